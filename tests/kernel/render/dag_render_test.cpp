#include <zdg/arith/error.hpp>
#include <zdg/kernel/render/dag_render.hpp>

#include "tests/support/tower.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>

namespace zdg {
namespace {

// Each pixel is the first set voxel of its camera ray among digital_ray_voxels (the dense
// oracle), shaded by the face it is entered by; the background where there is none.
TEST(DagRender, PixelsAreTheDenseFirstHits) {
  test::check_property([] {
    const std::int64_t nx = *rc::gen::inRange(1, 12), ny = *rc::gen::inRange(1, 12),
                       nz = *rc::gen::inRange(1, 12);
    Image<std::uint8_t> img(Domain({nz, ny, nx}));
    const int pct = *rc::gen::inRange(0, 30);
    for (auto& x : img.values()) x = *rc::gen::inRange(0, 100) < pct ? 1 : 0;
    VolumeRenderOptions o;
    o.width = 200;
    o.height = 150;
    o.azimuth = *rc::gen::inRange(-180, 181);
    o.elevation = *rc::gen::inRange(-89, 90);
    o.threads = 2;
    const auto kind = *rc::gen::elementOf(
        std::vector<VoxelDagKind>{VoxelDagKind::svo, VoxelDagKind::dag, VoxelDagKind::ssvdag});
    const DagRendering r = render_dag(build_voxel_dag(img, kind), o);
    const std::array<std::int64_t, 3> e{nx, ny, nz};
    std::int64_t hits = 0;
    // A sample of pixels (every 7th): the oracle walks every voxel of the ray.
    for (int py = 0; py < o.height; py += 7)
      for (int px = 0; px < o.width; px += 7) {
        const DigitalRay ray = volume_camera_ray(e, {1, 1, 1}, o, px, py);
        std::optional<std::array<std::int64_t, 3>> first;
        for (const auto& v : digital_ray_voxels(ray, e))
          if (img.values()[std::size_t((v[2] * ny + v[1]) * nx + v[0])] != 0) {
            first = v;
            break;
          }
        const auto face = r.faces[std::size_t(py) * std::size_t(o.width) + std::size_t(px)];
        RC_ASSERT((face >= 0) == first.has_value());
        if (first) {
          DigitalRay s = ray;
          for (std::size_t a = 0; a < 3; ++a) s.origin[a] -= (*first)[a] * ray.denominator;
          RC_ASSERT(face == digital_ray_chord(s, {1, 1, 1}).in_axis);
          RC_ASSERT(r.picture.at(px, py) == dag_face_color(face, ray.direction));
        } else {
          RC_ASSERT(r.picture.at(px, py) == dag_background());
        }
      }
    for (auto f : r.faces) hits += f >= 0;
    RC_ASSERT(r.hits == hits);
    RC_ASSERT(r.rays == std::int64_t(o.width) * o.height);
  });
}

TEST(DagRender, ThreadsDoNotChangeThePicture) {
  Image<std::uint8_t> img(Domain({9, 9, 9}));
  for (std::size_t i = 0; i < img.values().size(); i += 3) img.values()[i] = 1;
  const VoxelDag g = build_voxel_dag(img, VoxelDagKind::ssvdag);
  VolumeRenderOptions a, b;
  a.width = b.width = 300;
  a.height = b.height = 200;
  a.threads = 1;
  b.threads = 3;
  EXPECT_EQ(render_dag(g, a).picture.rgb, render_dag(g, b).picture.rgb);
  a.width = 10;
  EXPECT_THROW(render_dag(g, a), InvalidArgument);
}

} // namespace
} // namespace zdg
