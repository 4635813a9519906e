// The radius of the parameter-free integral invariants: the scale of a digital shape read from
// the mean length of its maximal digital straight segments (Levallois, Coeurjolly, Lachaud,
// "Parameter-free and multigrid convergent digital curvature estimators", DGCI 2014, LNCS
// 8668, pp. 162-175; Levallois, PhD thesis, Lyon / Chambery 2015, Sect. "Estimation sans
// parametre de la courbure").
//
// l = the mean digital length (||p_j - p_i||_1) of the maximal segments, R = k l^2 h (default
// k = 1/10, the reference experiments'; the thesis has k = 1). On a convex C^3 shape l lies
// between Theta(h^{-1/3}) and Theta(h^{-1/3} log(1/h)), so R follows the II law up to a log.
// 2D: the tangential covers of the given contours (kernel/curves/maximal_segments.hpp). 3D: the
// slice contours through the surfels, each once, those along a face of the box left out
// (details and the difference with the reference code: docs/NOTES.md,
// "estimators/ii_auto_radius.hpp").
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
