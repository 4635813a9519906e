#include <zdg/kernel/transforms/reduced_medial_axis.hpp>

#include <zdg/kernel/transforms/distance_transform.hpp>
#include <zdg/kernel/transforms/linf_covering.hpp>
#include <zdg/kernel/transforms/power_map.hpp>
#include <zdg/kernel/transforms/separable_engine.hpp>

#include <algorithm>

namespace zdg {

std::vector<MedialBall> reduced_medial_axis(const Image<std::uint8_t>& shape,
                                            const TransformOptions& opt) {
  return reduced_medial_axis(shape.domain(), shape.values().data(), opt);
}

std::vector<MedialBall> reduced_medial_axis(const Domain& dom, const std::uint8_t* mask,
                                            const TransformOptions& opt, int mask_item_bytes) {
  auto dt_bounds = detail::envelope_bounds(dom, opt, BigInt(0));
  require_background(dom, mask, opt, mask_item_bytes);
  const auto item = static_cast<std::size_t>(mask_item_bytes);
  auto object = [&](std::size_t i) {
    const std::uint8_t* p = mask + i * item;
    return std::any_of(p, p + item, [](std::uint8_t b) { return b != 0; });
  };
  auto bounds = detail::envelope_bounds(dom, opt, dt_bounds.value_max);
  std::vector<MedialBall> balls;
  detail::with_value_type(bounds.width, [&]<class V>(std::type_identity<V>) {
    V inf = detail::envelope_infinity<V>(bounds);
    std::vector<V> dt(static_cast<std::size_t>(dom.size()));
    detail::separable_envelope<V>(dom, opt, mask, dt.data(), inf, nullptr, mask_item_bytes);
    std::vector<std::int64_t> site;
    if (opt.metric.is_inf()) {
      // l_inf: the centre of the largest cube covering each point (DT values fit int64:
      // they are at most the largest extent).
      std::vector<std::int64_t> r(dt.size());
      for (std::size_t i = 0; i < r.size(); ++i) {
        if constexpr (std::is_same_v<V, BigInt>) {
          r[i] = dt[i].template convert_to<std::int64_t>();
        } else {
          r[i] = static_cast<std::int64_t>(dt[i]);
        }
      }
      detail::linf_covering(dom, opt, r, &site);
    } else {
      std::vector<V> f(dt.size());
      for (std::size_t i = 0; i < f.size(); ++i) f[i] = dt[i] > V(0) ? V(-dt[i]) : inf;
      detail::separable_envelope<V>(dom, opt, nullptr, f.data(), inf, &site);
    }
    std::vector<std::uint8_t> kept(dt.size(), 0);
    for (std::size_t i = 0; i < dt.size(); ++i) {
      if (object(i)) kept[static_cast<std::size_t>(site[i])] = 1;
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
