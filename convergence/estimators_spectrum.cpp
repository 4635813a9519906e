// The estimator lb-spectrum of the registry: the first n non-zero eigenvalues of a discrete
// Laplace-Beltrami operator on the digitized sphere (convergence/laplacian_spectrum.hpp) against
// the closed form l(l+1)/r^2 with multiplicity 2l+1; the error of a run is the relative error
// |lambda_i - lambda_i^exact| / lambda_i^exact of each eigenvalue (linf: the largest of the n).
#include <zdg/arith/error.hpp>
#include <zdg/convergence/estimator.hpp>
#include <zdg/convergence/laplacian_spectrum.hpp>
#include <zdg/convergence/number_text.hpp>

#include <cmath>

namespace zdg {

namespace {

ErrorStats run_lb_spectrum(const RunInput& in) {
  const double r = sphere_radius(in.shape, "lb-spectrum");
  if (in.count != std::floor(in.count) || in.count < 1) {
    throw InvalidArgument("lb-spectrum: n = " + real_text(in.count) +
                          " must be a positive integer");
  }
  const auto n = static_cast<std::int64_t>(in.count);
  const SurfaceSpectrum s = surface_spectrum(in, parse_spectrum_operator(in.choice), n + 1);
  const auto exact = sphere_laplacian_eigenvalues(r, n);
  ErrorAccumulator acc;
  for (std::int64_t i = 0; i < n; ++i) {
    acc.add((s.values[std::size_t(i + 1)] - exact[std::size_t(i)]) / exact[std::size_t(i)]);
  }
  return acc.stats();
}

} // namespace

namespace detail {

void register_spectrum_estimators(std::vector<Estimator>& out) {
  EstimatorParameter op{"operator", "cotan", 0, 0,
                        "the Laplacian: cotan (primal surface), cotan-mc (marching cubes), heat "
                        "(heat kernel, t = h^{2/5})"};
  op.check_text = [](const std::string& text) { parse_spectrum_operator(text); };
  out.push_back(
      {"lb-spectrum",
       3,
       "the first n non-zero eigenvalues of a Laplace-Beltrami operator with its mass matrix "
       "(generalized problem, Spectra shift-invert) on the digitized sphere, relative errors "
       "against l(l+1)/r^2 with multiplicity 2l+1",
       "relative eigenvalue error",
       {{"n", "3", 0.0, 400.0, "the number of non-zero eigenvalues compared (an integer)"}, op},
       {"eigenvalues of the cotangent Laplacian converge on meshes whose normals converge "
        "(Hildebrandt, Polthier, Wardetzky 2006; Dodziuk 1976); not on the digital staircase, "
        "whose normals do not (papers/lb-spectrum/README.md); no rate is proven here",
        [](const ShapeClass&, const EstimatorParameters&) -> std::optional<ProvenRate> {
          return std::nullopt;
        }},
       run_lb_spectrum});
}

} // namespace detail

} // namespace zdg
