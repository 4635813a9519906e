#include <zdg/convergence/estimator.hpp>

#include <zdg/arith/error.hpp>

#include <cmath>

namespace zdg {

ErrorStats ErrorAccumulator::stats() const {
  ErrorStats s;
  s.n = n_;
  s.linf = linf_;
  if (n_ > 0) {
    s.mean = sum_ / static_cast<double>(n_);
    s.l2 = std::sqrt(sum2_ / static_cast<double>(n_));
  }
  return s;
}

const std::vector<Estimator>& estimators() {
  static const std::vector<Estimator> all = [] {
    std::vector<Estimator> v;
    detail::register_2d_estimators(v);
    detail::register_3d_estimators(v);
    detail::register_hausdorff_estimators(v);
    return v;
  }();
  return all;
}

const Estimator& find_estimator(const std::string& name) {
  std::string names;
  for (const auto& e : estimators()) {
    if (e.name == name) return e;
    names += (names.empty() ? "" : ", ") + e.name;
  }
  throw InvalidArgument("unknown estimator '" + name + "' (known: " + names + ")");
}

} // namespace zdg
