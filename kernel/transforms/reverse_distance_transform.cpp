#include <zdg/kernel/transforms/reverse_distance_transform.hpp>

#include <zdg/kernel/transforms/linf_covering.hpp>
#include <zdg/kernel/transforms/power_map.hpp>
#include <zdg/kernel/transforms/separable_engine.hpp>

#include <algorithm>

namespace zdg {

Image<std::uint8_t> reverse_distance_transform(const Image<std::int64_t>& values,
                                               const TransformOptions& opt) {
  return reverse_distance_transform(values.domain(), values.values().data(), opt);
}

Image<std::uint8_t> reverse_distance_transform(const Domain& dom, const std::int64_t* v,
                                               const TransformOptions& opt) {
  Image<std::uint8_t> out(dom, std::uint8_t{0});
  const std::int64_t* end = v + dom.size();
  if (std::all_of(v, end, [](std::int64_t x) { return x == 0; })) {
    detail::envelope_bounds(dom, opt, BigInt(0)); // validates the options
    return out;
  }
  std::int64_t wmax = detail::check_weights(dom, v);
  if (opt.metric.is_inf()) {
    detail::envelope_bounds(dom, opt, BigInt(0)); // validates the options
    std::vector<std::int64_t> r(v, end);
    detail::linf_covering(dom, opt, r, nullptr);
    for (std::size_t i = 0; i < r.size(); ++i) out.values()[i] = r[i] > 0 ? 1 : 0;
    return out;
  }
  auto bounds = detail::envelope_bounds(dom, opt, BigInt(wmax));
  detail::with_value_type(bounds.width, [&]<class V>(std::type_identity<V>) {
    V inf = detail::envelope_infinity<V>(bounds);
    std::vector<V> f(static_cast<std::size_t>(dom.size()));
    for (std::size_t i = 0; i < f.size(); ++i) f[i] = v[i] > 0 ? V(-V(v[i])) : inf;
    detail::separable_envelope<V>(dom, opt, nullptr, f.data(), inf, nullptr);
    for (std::size_t i = 0; i < f.size(); ++i) out.values()[i] = f[i] < V(0) ? 1 : 0;
  });
  return out;
}

} // namespace zdg
