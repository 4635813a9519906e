// The Hodge decomposition of a primal 1-form on the cell complex of a closed digital surface
// (kernel/surfaces/surfel_complex.hpp), under diagonal Hodge stars (kernel/calculus/
// hodge_star.hpp):
//     omega = d0 alpha + delta1 beta + h,   delta1 = star1^{-1} d1^T star2,
// orthogonal in the inner product <a, b> = sum_e star1(e) a(e) b(e), with h harmonic:
// d1 h = 0 and d0^T star1 h = 0, i.e. in the kernel of the 1-form Laplacian
// Delta1 = d0 star0^{-1} d0^T star1 + star1^{-1} d1^T star2 d1 (Desbrun, Hirani, Leok, Marsden
// 2005, 6; Desbrun, Kanso, Tong 2008, 4.3). A tangent vector field enters as its flat
// (kernel/calculus/sharp_flat.hpp). The harmonic part has the dimension of
// kernel/calculus/harmonic_dimension.hpp (2g on a closed surface of genus g).
//
// Algorithm: two sparse SPD solves (kernel/linalg/sparse_spd_solver.hpp):
//   d0^T star1 d0 alpha = d0^T star1 omega              (pointels)
//   d1 star1^{-1} d1^T gamma = d1 omega, beta = gamma / star2 (surfels)
// each with one unknown per connected component set to 0 (the kernels are the constants per
// component; the right-hand sides sum to zero on each, so the grounded systems are SPD and
// exact). Cost: two sparse Cholesky factorizations (about n^{3/2}) and solves; doubles.
// Errors: InvalidArgument when omega does not have one value per linel, when the stars do not
// match the complex, or when a star1 is not positive and finite or a surfel measure is 0
// (star2 infinite: a clamped corrected measure); the solver's errors otherwise.
#pragma once

#include <zdg/kernel/calculus/hodge_star.hpp>
#include <zdg/kernel/linalg/sparse_spd_solver.hpp>
#include <zdg/kernel/surfaces/surfel_complex.hpp>

#include <span>
#include <string>
#include <vector>

namespace zdg {

struct HodgeDecomposition {
  std::vector<double> alpha;   ///< primal 0-form (one per pointel), 0 at one pointel per component
  std::vector<double> beta;    ///< primal 2-form (one per surfel)
  std::vector<double> exact;   ///< d0 alpha
  std::vector<double> coexact; ///< delta1 beta
  std::vector<double> harmonic;
  std::string solver; ///< the backend of the two solves
};

HodgeDecomposition hodge_decomposition(const SurfelComplex& c, const HodgeStars& stars,
                                       std::span<const double> omega,
                                       SpdBackend backend = SpdBackend::automatic);

} // namespace zdg
