#include <zdg/arith/error.hpp>
#include <zdg/kernel/images/digital_ray.hpp>

#include <string>
#include <utility>

namespace zdg {

namespace {
constexpr std::int64_t kMaxRayTerm = std::int64_t{1} << 42;
constexpr std::int64_t kMaxExtent = std::int64_t{1} << 20;
} // namespace

void ray_detail::entry_outside() {
  throw Error("digital ray: entry voxel outside the box");
}

void check_digital_ray(const DigitalRay& r, const std::array<std::int64_t, 3>& extent) {
  if (r.denominator <= 0 || r.denominator > kMaxRayTerm)
    throw InvalidArgument("digital ray: the denominator must lie in [1, 2^42]");
  bool moving = false;
  for (std::size_t a = 0; a < 3; ++a) {
    if (r.origin[a] < -kMaxRayTerm || r.origin[a] > kMaxRayTerm || r.direction[a] < -kMaxRayTerm ||
        r.direction[a] > kMaxRayTerm)
      throw InvalidArgument("digital ray: origin and direction numerators must lie in "
                            "[-2^42, 2^42]");
    if (extent[a] < 1 || extent[a] > kMaxExtent)
      throw InvalidArgument("digital ray: box extents must lie in [1, 2^20] (got " +
                            std::to_string(extent[a]) + ")");
    moving = moving || r.direction[a] != 0;
  }
  if (!moving) throw InvalidArgument("digital ray: the direction is zero");
}

RayChord digital_ray_chord(const DigitalRay& r, const std::array<std::int64_t, 3>& extent) {
  using ray_detail::i128;
  const i128 den = r.denominator;
  RayChord c;
  bool first = true;
  for (std::size_t a = 0; a < 3; ++a) {
    if (r.direction[a] == 0) {
      const i128 o2 = 2 * static_cast<i128>(r.origin[a]);
      if (o2 < -den || o2 >= (2 * static_cast<i128>(extent[a]) - 1) * den) return c;
      continue;
    }
    RayTime t1 = ray_plane_time(r, int(a), 0), t2 = ray_plane_time(r, int(a), extent[a]);
    if (t2 < t1) std::swap(t1, t2);
    if (first || c.in < t1) {
      c.in = t1;
      c.in_axis = int(a);
    }
    if (first || t2 < c.out) c.out = t2;
    first = false;
  }
  c.hit = c.in < c.out;
  return c;
}

std::vector<std::array<std::int64_t, 3>>
digital_ray_voxels(const DigitalRay& ray, const std::array<std::int64_t, 3>& extent) {
  check_digital_ray(ray, extent);
  std::vector<std::array<std::int64_t, 3>> out;
  for_each_ray_voxel(ray, extent, [&](const std::array<std::int64_t, 3>& v) { out.push_back(v); });
  return out;
}

} // namespace zdg
