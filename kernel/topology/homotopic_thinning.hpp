// Sequential homotopic thinning of a binary image of Z^2 or Z^3, ordered by a priority:
// skeletons that keep the topology of the object exactly.
//
// Algorithm (distance-ordered homotopic thinning, Pudney, CVIU 72, 1998; Davies and Plummer
// 1981): the border points (object points with a kbar-neighbour in the background) wait in a
// priority queue, smallest priority first, ties by linear index. A point taken from the queue
// is deleted when it is simple (kernel/topology/simple_points.hpp), not an anchor, and does not
// meet the condition of the skeleton kind (kernel/topology/skeleton_constraints.hpp; a point that
// meets it becomes an anchor). Deleting a point puts its object neighbours that are not waiting
// back into the queue. Since simplicity and the skeleton conditions depend only on the 3^d - 1
// neighbours, a point left unexamined since its last neighbour's deletion keeps its verdict:
// when the queue is empty no point can be deleted (the result is a fixed point, and thinning
// it again deletes nothing). The default priority is the exact squared Euclidean distance to
// the background (kernel/transforms/distance_transform.hpp), so points go in layers from the
// boundary inwards and the skeleton is centred.
//
// Guarantees (tests/kernel/topology/homotopic_thinning_test.cpp): the result is a subset of the
// object; every deleted point was simple when it was deleted, so the object and the background keep
// all their Betti numbers; no deletable point remains; a digital ball thins to one point
// (ultimate), a solid torus to a closed curve, a hollow sphere to a closed surface.
//
// Cost: O(N) for the padded copy and the distance transform, O(M log M) to rank the M object
// priorities (int64 comparisons: exact, no overflow possible), then O(1) per examination (a
// table look-up in 3D when the object has at least 2^22 points, where building the 2^26 table
// pays; the definition-level test otherwise, with the same verdicts) and per queue operation
// (one bucket per rank): O(N + M log M + E), E the examinations (a few per point).
// Sequential by nature: only the distance transform and the table build use threads.
#pragma once

#include <zdg/kernel/topology/skeleton_constraints.hpp>

namespace zdg {

/// Thins the object (nonzero points) of a 2D or 3D image. InvalidArgument for another
/// dimension, a pair that does not fit the image, or anchors / priority of another domain.
ThinningResult homotopic_thinning(const Image<std::uint8_t>& image,
                                  const ThinningOptions& options = {});

} // namespace zdg
