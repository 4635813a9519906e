// The radius of the parameter-free integral invariants: the scale of a digital shape read from
// the mean length of its maximal digital straight segments (Levallois, Coeurjolly, Lachaud,
// "Parameter-free and multigrid convergent digital curvature estimators", DGCI 2014, LNCS
// 8668, pp. 162-175; Levallois, PhD thesis, Lyon / Chambery 2015, Sect. "Estimation sans
// parametre de la courbure").
//
//   l = mean over the maximal segments of the digital length of each segment, the length of a
//       segment (p_i .. p_j) of a 4-connected curve being ||p_j - p_i||_1 = j - i (its number
//       of unit steps: the number of points minus one), as in the reference experiments
//       (DGtalTools fork of Levallois, estimators/2dLocalEstimatorsRadius.cpp: norm1 of
//       back - front of every segment of the tangential cover);
//   R = k l^2 h (shape units), i.e. k l^2 pixels/voxels.
// On a convex shape with C^3 boundary of bounded positive curvature, Theta(h^{-1/3}) <= l <=
// Theta(h^{-1/3} log(1/h)) (Lachaud 2006, de Vieilleville 2007), so R lies between
// Theta(h^{1/3}) and Theta(h^{1/3} log^2(1/h)): the law of the II theorems up to a log, without
// a parameter to tune. The thesis defines rho = l^2 (k = 1); the reference experiments use
// k = 1/10 (their default constant), the default of the registry.
//
// 2D (mean_maximal_segment_length): the maximal segments of the tangential cover
//   (kernel/curves/maximal_segments.hpp, standard DSS) of the pointels of every given contour.
// 3D (mean_slice_maximal_segment_length): each boundary surfel is orthogonal to one axis and
//   lies in the two slices of the digital surface by the planes x_a = const through voxel
//   centres, a one of the two other axes; such a slice is a closed 4-connected contour of the
//   2D section of the set (the linels of the contour are the surfels). l is the mean over the
//   maximal segments of every slice contour through the given surfels, each contour once
//   (thesis, Def. "rho'(Z)": the mean of the lengths of the maximal segments of all slices).
//   Slice contours that run along a face of the box (a surfel whose outer voxel is outside
//   the box: the set was clipped) are left out: they follow the box, not the shape.
//   (The reference experiments average per-surfel pencils instead, which weights each
//   segment by its length; this follows the thesis' definition.)
//
// Complexity: O(n) for n pointels in 2D (maximal segments are linear); in 3D O(n) predicate
// calls and hash operations for n surfels (each surfel is a linel of two slice contours).
// Width: coordinates int64; the maximal segments escalate (maximal_segments_exact).
#pragma once

#include <zdg/kernel/curves/digital_contour.hpp>
#include <zdg/kernel/surfaces/digital_surface.hpp>

#include <cstddef>
#include <span>

namespace zdg {

struct MaximalSegmentLengths {
  double mean = 0;          ///< mean digital length (unit steps) of the maximal segments
  std::size_t segments = 0; ///< number of maximal segments
  std::size_t contours = 0; ///< number of contours (2D) or slice contours (3D) they come from
};

/// Mean length of the maximal segments of the contours (all segments of all contours).
MaximalSegmentLengths mean_maximal_segment_length(std::span<const DigitalContour> contours);

/// Mean length of the maximal segments of the slice contours through the surfels (boundary
/// surfels of {z in box : inside(z)}).
MaximalSegmentLengths mean_slice_maximal_segment_length(const VoxelPredicate& inside,
                                                        const VoxelBox& box,
                                                        std::span<const Surfel> surfels);

/// R = k l^2 h. Throws InvalidArgument unless k > 0, h > 0 and l > 0 (no maximal segment).
double ii_auto_radius(const MaximalSegmentLengths& lengths, double k, double h);

} // namespace zdg
