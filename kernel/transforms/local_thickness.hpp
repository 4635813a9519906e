// Local thickness of a binary shape (Hildebrand and Ruegsegger, "A new method for the
// model-independent assessment of thickness in three-dimensional images", J. Microscopy 185(1),
// 1997), exact, in the Euclidean metric.
//
// Definitions. X is the object (nonzero points) of an image on a box domain D of Z^d. For a
// centre c in X and an integer s >= 1, the open lattice ball is B(c, s) = { y in Z^d :
// |y - c|^2 < s }; it is inscribed when B(c, s) meets no background point of D (points outside
// D are neither object nor background, as in the distance transform's convention). The
// largest inscribed squared radius at c is then exactly DT(c), the squared Euclidean distance
// transform (kernel/transforms/distance_transform.hpp): B(c, DT(c)) holds no background point
// and any larger s takes in the nearest one. The local squared radius of y in X is
//   R2(y) = max { s : B(c, s) inscribed, y in B(c, s) } = max { DT(c) : c in X, |y - c|^2 < DT(c) }
// (c = y itself qualifies, so R2(y) >= DT(y) >= 1), and 0 off the object. The local thickness
// is the diameter of that ball, 2 sqrt(R2(y)), in voxel units (the diameter of the
// continuous ball whose open interior has the lattice points of B(c, R2)); 0 off the object.
// Examples (tests pin them): in a digital ball B(c, s) (with a margin of background) R2 = DT(c)
// = the smallest sum of d squares >= s at every point; in a slab of w layers between two
// background layers R2 = floor((w + 1) / 2)^2 everywhere (thickness w + 1 for odd w, w for
// even w: the centres are lattice points).
//
// Algorithm: the distance transform; then a centre c is dropped when the ball of a neighbour
// c + e (e in {-1, 0, 1}^d) with DT(c + e) >= DT(c) contains its ball; dropping changes no
// maximum, since containment of distinct lattice balls is a strict order. Containment is
// decided exactly: B(c) lies in B(c + e) iff DT(c + e) > M(DT(c), e) = max { |p - e|^2 :
// |p|^2 < DT(c) }, read from tables when d <= 3 and DT < 2^16 (M depends on the sorted |e_i|
// only; the tables enumerate the lattice points p_1 >= ... >= p_d >= 0), otherwise by the
// sufficient test sqrt(DT(c + e)) > sqrt(DT(c) - 1) + |e|, in integers. The kept balls are
// painted in decreasing DT, slice by slice of axis 0 and line
// by line of the last axis: each ball covers an interval of each line it meets, and a
// union-find of the unpainted points of the line gives every point the first (largest) value
// that covers it. In 3D a ball skips the lines that lie in the ball of its neighbour of
// largest DT > its own (those points have a larger R2, painted by the ball that realises it).
// Cost: O(N 3^d) for the selection (the tables O(sqrt(max DT)^d / d!)), then O(1) per line
// of each kept ball, about pi r^2 per ball of radius r in 3D, plus one union-find step per
// line painted and O(N alpha): Theta(N r) on shapes of inscribed radius r (bench/README.md).
// Threads: the selection by slices, the painting by groups of 8 slices of axis 0; the result
// does not depend on the thread count. Memory: the values (4 or 8 bytes a point, the narrowest
// unsigned type holding the largest possible DT), the kept centres (24 to 32 bytes each), one
// union-find line set of one slice per thread.
//
// Width: values are squared distances, at most sum_k (n_k - 1)^2 (the distance transform's
// bound); R2 is one of them, so it fits int64 for every domain whose DT fits (OverflowError
// otherwise). Errors: InvalidArgument for a metric other than l2, a torus axis, a dimension
// above 6, an image with no background point (the distance transform's message) or a line
// (last axis) of 2^31 - 1 points or more.
#pragma once

#include <zdg/kernel/images/image.hpp>
#include <zdg/kernel/transforms/lp_metric.hpp>

#include <cstdint>

namespace zdg {

/// R2(y) above: the largest squared radius of an inscribed open ball containing y, 0 off the
/// object. opt: l2 only, no torus axis; threads as usual.
Image<std::int64_t> local_thickness_squared_radius(const Image<std::uint8_t>& shape,
                                                   const TransformOptions& opt = {});

/// The local thickness 2 sqrt(R2(y)) in voxel units as float32 (the square root of the exact
/// integer taken in double, then rounded to float), 0 off the object.
Image<float> local_thickness(const Image<std::uint8_t>& shape, const TransformOptions& opt = {});

} // namespace zdg
