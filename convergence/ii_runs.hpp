// The integral-invariant runs of the registry with an explicit radius (internal to
// convergence/): the fixed law R = k h^alpha (estimators_2d.cpp, estimators_3d.cpp) and the
// parameter-free radius R = k l^2 h (estimators_ii_auto.cpp, estimators/ii_auto_radius.hpp)
// share them.
#pragma once

#include <zdg/convergence/digitized_2d.hpp>
#include <zdg/convergence/digitized_3d.hpp>
#include <zdg/convergence/estimator.hpp>

namespace zdg::detail {

/// ii-curvature errors at every linel of the contours of d, ball radius R (shape units).
ErrorStats ii_curvature_errors(const Digitized2& d, double h, double radius);

enum class II3Quantity { mean, gaussian, k1, k2, normal, directions };

/// Errors of one 3D integral-invariant quantity with ball radius R, from the ball moments
/// shared by all quantities of one (shape, h, translation, R, box) (a cache). `digitized`,
/// when given, is the digitization of `in` (detail::digitize_3d(in)): used instead of
/// digitizing again when the moments are not cached.
ErrorStats ii_3d_errors(const RunInput& in, double radius, II3Quantity quantity,
                        const Digitized3* digitized = nullptr);

} // namespace zdg::detail
