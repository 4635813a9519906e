#include <zdg/kernel/transforms/power_map.hpp>

#include <zdg/kernel/transforms/separable_engine.hpp>

#include <string>

namespace zdg {

namespace detail {

void require_finite_p(const TransformOptions& opt, const char* what) {
  if (opt.metric.is_inf()) {
    throw InvalidArgument(std::string(what) +
                          ": linf is not supported (the l_inf power distance is not "
                          "separable); use l1, l2 or lP");
  }
}

std::int64_t check_weights(const Image<std::int64_t>& weights) {
  return check_weights(weights.domain(), weights.values().data());
}

std::int64_t check_weights(const Domain& dom, const std::int64_t* weights) {
  std::int64_t wmax = 0;
  for (std::int64_t i = 0; i < dom.size(); ++i) {
    std::int64_t w = weights[i];
    if (w < 0) {
      auto p = dom.point(i);
      std::string at;
      for (auto c : p) {
        if (!at.empty()) at.push_back(',');
        at.append(std::to_string(c));
      }
      throw InvalidArgument("weight " + std::to_string(w) + " at (" + at +
                            ") is negative (radii to the power p must be >= 0)");
    }
    wmax = std::max(wmax, w);
  }
  if (wmax == 0) throw InvalidArgument("no site: every weight is 0");
  return wmax;
}

} // namespace detail

PowerMap power_map(const Image<std::int64_t>& weights, const TransformOptions& opt) {
  return power_map(weights.domain(), weights.values().data(), opt);
}

PowerMap power_map(const Domain& dom, const std::int64_t* weights, const TransformOptions& opt) {
  detail::require_finite_p(opt, "power map");
  std::int64_t wmax = detail::check_weights(dom, weights);
  auto bounds = detail::envelope_bounds(dom, opt, BigInt(wmax));
  PowerMap map{dom, {}, std::vector<std::uint8_t>(static_cast<std::size_t>(dom.size()), 0)};
  detail::with_value_type(bounds.width, [&]<class V>(std::type_identity<V>) {
    V inf = detail::envelope_infinity<V>(bounds);
    std::vector<V> f(static_cast<std::size_t>(dom.size()));
    for (std::int64_t i = 0; i < dom.size(); ++i) {
      std::int64_t w = weights[i];
      f[static_cast<std::size_t>(i)] = w > 0 ? V(-V(w)) : inf;
    }
    detail::separable_envelope<V>(dom, opt, nullptr, f.data(), inf, &map.site);
    for (std::size_t i = 0; i < f.size(); ++i) map.negative[i] = f[i] < V(0) ? 1 : 0;
  });
  return map;
}

} // namespace zdg
