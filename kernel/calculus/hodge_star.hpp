// Diagonal Hodge stars of the cell complex of a digital surface (kernel/surfaces/
// surfel_complex.hpp): star_k maps primal k-forms to dual (2 - k)-forms by the ratio of the
// dual cell's measure to the primal cell's (Desbrun, Hirani, Leok, Marsden 2005, 4.2):
//     star0(p) = |*p|,  star1(e) = |*e| / |e|,  star2(s) = 1 / |s|.
//
// Measures (CellMeasure):
//   cubical            every measure 1 (all stars 1): the combinatorial calculus, exact
//                      integer operators (Laplacians d^T d with integer entries).
//   corrected_clamped  the corrected measures of digital integration
//   corrected_absolute (estimators/digital_integration.hpp; Lachaud, Thibert, JMIV 2016;
//                      Coeurjolly, Lachaud, DGMM 2022), from an estimated unit normal n_est(s)
//                      per surfel and its elementary normal n(s):
//                        |s|  = area(s) m(s),  m(s) = max(0, n_est . n) (clamped) or
//                               |n_est . n| (absolute): the weight w(s) of digital integration;
//                        |*p| = the sum of |s| / 4 over the surfel corners at the pointel p;
//                        |e|  = the length of the linel, |*e| = (|f0| + |f1|) / (2 |e|) for its
//                               two surfels f0, f1,
//                      so that the surfels, the dual faces of the pointels and the diamonds
//                      |e| |*e| / 2 of the linels each sum to the corrected area sum_s w(s).
//                      On a flat square grid of step h with n_est = n every measure is the
//                      Euclidean one (|s| = h^2, |e| = |*e| = h).
// A surfel of measure 0 (a clamped estimate pointing inwards) has star2 = +infinity and makes
// the adjacent stars smaller; solvers that need positive stars check them
// (kernel/calculus/hodge_decomposition.hpp).
//
// O(F) for F surfels; doubles. InvalidArgument when the corrected measures get a number of
// normals other than one per surfel, or a normal that is not finite.
#pragma once

#include <zdg/arith/point.hpp>
#include <zdg/kernel/surfaces/surfel_complex.hpp>

#include <span>
#include <vector>

namespace zdg {

enum class CellMeasure { cubical, corrected_clamped, corrected_absolute };

struct HodgeStars {
  CellMeasure measure = CellMeasure::cubical;
  std::vector<double> surfel_measure;       ///< |s|
  std::vector<double> linel_measure;        ///< |e|
  std::vector<double> dual_linel_measure;   ///< |*e|
  std::vector<double> dual_pointel_measure; ///< |*p|
  std::vector<double> star0, star1, star2;
};

/// The stars of the complex under the measure; `normals` (one unit n_est per surfel) is read
/// by the corrected measures only.
HodgeStars hodge_stars(const SurfelComplex& c, CellMeasure measure,
                       std::span<const Point3<double>> normals = {});

} // namespace zdg
