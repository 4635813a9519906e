#include <zdg/estimators/mdca_curvature.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/curves/digital_circular_arc.hpp>

#include <algorithm>
#include <string>

namespace zdg {

std::vector<double> mdca_curvature(const DigitalContour& contour, double h) {
  if (!(h > 0)) throw InvalidArgument("mdca_curvature: grid step h = " + std::to_string(h));
  const std::size_t n = contour.size();
  if (n < 4) {
    throw InvalidArgument("mdca_curvature: a closed contour has at least 4 linels, got " +
                          std::to_string(n));
  }
  const LinelPairs pairs = linel_pairs(contour);
  const auto arcs = maximal_circular_arcs_exact(pairs.inner, pairs.outer, true).value;
  std::vector<double> kappa(n, 0.0);
  std::vector<std::size_t> best(n, 0);
  std::vector<bool> seen(n, false);
  for (const auto& a : arcs) {
    for (std::size_t t = 0; t < a.length; ++t) {
      const std::size_t l = (a.begin + t) % n;
      const std::size_t centrality = std::min(t, a.length - 1 - t);
      if (!seen[l] || centrality > best[l]) {
        seen[l] = true;
        best[l] = centrality;
        kappa[l] = a.curvature / h;
      }
    }
  }
  return kappa;
}

} // namespace zdg
