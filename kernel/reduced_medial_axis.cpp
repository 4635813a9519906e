#include "kernel/reduced_medial_axis.hpp"

#include "kernel/distance_transform.hpp"
#include "kernel/power_map.hpp"
#include "kernel/separable_engine.hpp"

namespace zdg {

std::vector<MedialBall> reduced_medial_axis(const Image<std::uint8_t>& shape,
                                            const TransformOptions& opt) {
  detail::require_finite_p(opt, "reduced medial axis");
  const Domain& dom = shape.domain();
  auto dt_bounds = detail::envelope_bounds(dom, opt, BigInt(0));
  require_background(shape, opt);
  auto bounds = detail::envelope_bounds(dom, opt, dt_bounds.value_max);
  std::vector<MedialBall> balls;
  detail::with_value_type(bounds.width, [&]<class V>(std::type_identity<V>) {
    V inf = detail::envelope_infinity<V>(bounds);
    std::vector<V> dt;
    detail::separable_envelope<V>(dom, opt, shape.values().data(), dt, inf, nullptr);
    std::vector<V> f(dt.size());
    for (std::size_t i = 0; i < f.size(); ++i) f[i] = dt[i] > V(0) ? V(-dt[i]) : inf;
    std::vector<std::int64_t> site;
    detail::separable_envelope<V>(dom, opt, nullptr, f, inf, &site);
    std::vector<std::uint8_t> kept(dt.size(), 0);
    for (std::size_t i = 0; i < f.size(); ++i) {
      if (shape.values()[i] != 0) kept[static_cast<std::size_t>(site[i])] = 1;
    }
    for (std::size_t i = 0; i < kept.size(); ++i) {
      if (kept[i] == 0) continue;
      BigInt v = detail::engine_to_bigint(dt[i]);
      if (v > BigInt(std::numeric_limits<std::int64_t>::max())) {
        throw OverflowError("reduced medial axis: ball value " + v.str() + " exceeds int64");
      }
      balls.push_back(
          {dom.point(static_cast<std::int64_t>(i)), v.template convert_to<std::int64_t>()});
    }
  });
  return balls;
}

} // namespace zdg
