#include <zdg/kernel/parallel/parallel_for.hpp>
#include <zdg/kernel/render/dag_render.hpp>

#include <algorithm>
#include <cmath>

namespace zdg {

Rgb dag_background() {
  return {31, 31, 38};
}

Rgb dag_face_color(int axis, const std::array<std::int64_t, 3>& d) {
  const double x = double(d[0]), y = double(d[1]), z = double(d[2]);
  const double norm = std::sqrt(x * x + y * y + z * z);
  const double lambert = norm > 0 ? std::abs(double(d[std::size_t(axis)])) / norm : 0.0;
  const double shade = 0.25 + 0.75 * lambert;
  const double base[3] = {0.92, 0.78, 0.58};
  auto to8 = [](double c) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(c, 0.0, 1.0) * 255.0));
  };
  return {to8(base[0] * shade), to8(base[1] * shade), to8(base[2] * shade)};
}

DagRendering render_dag(const VoxelDag& dag, const VolumeRenderOptions& o) {
  o.validate();
  DagRendering out;
  out.picture = RgbImage(o.width, o.height, dag_background());
  out.faces.assign(std::size_t(o.width) * std::size_t(o.height), -1);
  std::vector<std::int64_t> hits(static_cast<std::size_t>(o.height), 0);
  const auto& e = dag.extent();
  const std::array<double, 3> spacing{1, 1, 1};
  parallel_for(o.height, o.threads, [&](std::int64_t py) {
    for (int px = 0; px < o.width; ++px) {
      const DigitalRay r = volume_camera_ray(e, spacing, o, px, static_cast<int>(py));
      const auto h = dag.first_hit(r);
      if (!h) continue;
      ++hits[std::size_t(py)];
      out.faces[std::size_t(py) * std::size_t(o.width) + std::size_t(px)] =
          static_cast<std::int8_t>(h->axis);
      out.picture.set(px, static_cast<int>(py), dag_face_color(h->axis, r.direction));
    }
  });
  out.rays = std::int64_t(o.width) * o.height;
  for (auto k : hits) out.hits += k;
  return out;
}

} // namespace zdg
