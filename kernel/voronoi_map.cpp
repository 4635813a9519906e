#include <zdg/kernel/voronoi_map.hpp>

#include <zdg/kernel/distance_transform.hpp>
#include <zdg/kernel/separable_engine.hpp>

namespace zdg {

VoronoiMap voronoi_map(const Image<std::uint8_t>& shape, const TransformOptions& opt) {
  const Domain& dom = shape.domain();
  auto bounds = detail::envelope_bounds(dom, opt, BigInt(0));
  require_background(shape, opt);
  VoronoiMap map{dom, {}};
  detail::with_value_type(bounds.width, [&]<class V>(std::type_identity<V>) {
    std::vector<V> f(static_cast<std::size_t>(dom.size()));
    V inf = detail::envelope_infinity<V>(bounds);
    detail::separable_envelope<V>(dom, opt, shape.values().data(), f.data(), inf, &map.site);
  });
  return map;
}

} // namespace zdg
