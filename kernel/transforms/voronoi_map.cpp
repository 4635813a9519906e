#include <zdg/kernel/transforms/voronoi_map.hpp>

#include <zdg/kernel/transforms/distance_transform.hpp>
#include <zdg/kernel/transforms/separable_engine.hpp>

namespace zdg {

VoronoiMap voronoi_map(const Image<std::uint8_t>& shape, const TransformOptions& opt) {
  return voronoi_map(shape.domain(), shape.values().data(), opt);
}

VoronoiMap voronoi_map(const Domain& dom, const std::uint8_t* mask, const TransformOptions& opt,
                       int mask_item_bytes) {
  auto bounds = detail::envelope_bounds(dom, opt, BigInt(0));
  require_background(dom, mask, opt, mask_item_bytes);
  VoronoiMap map{dom, {}};
  detail::with_value_type(bounds.width, [&]<class V>(std::type_identity<V>) {
    std::vector<V> f(static_cast<std::size_t>(dom.size()));
    V inf = detail::envelope_infinity<V>(bounds);
    detail::separable_envelope<V>(dom, opt, mask, f.data(), inf, &map.site, mask_item_bytes);
  });
  return map;
}

} // namespace zdg
