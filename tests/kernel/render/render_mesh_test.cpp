// The mesh picture: decoded with libpng's simplified reader (not zdg's writer code), and
// checked for what a person must see: the shape on a white background, the colour of the
// field where it is high and where it is low, the colour bar.
#include <zdg/kernel/render/render_mesh.hpp>

#include "tests/support/cli.hpp"
#include "tests/support/png.hpp"
#include "tests/support/voxel_mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace zdg {
namespace {

namespace fs = std::filesystem;

using test::decode_png;

PolygonMesh ball(std::int64_t r) {
  return test::voxel_primal_mesh([r](std::int64_t x, std::int64_t y,
                                     std::int64_t z) { return x * x + y * y + z * z <= r * r; },
                                 -r - 1, r + 1);
}

bool is_white(Rgb c) {
  return c.r == 255 && c.g == 255 && c.b == 255;
}

TEST(RenderMesh, PngRoundTripIsLossless) {
  const auto dir = test::scratch_dir("render");
  RgbImage img(7, 5);
  for (std::size_t i = 0; i < img.rgb.size(); ++i) img.rgb[i] = static_cast<std::uint8_t>(i * 37);
  write_png((dir / "a.png").string(), img);
  EXPECT_EQ(decode_png(dir / "a.png").rgb, img.rgb);
  EXPECT_THROW(write_png((dir / "missing" / "a.png").string(), img), IoError);
  fs::remove_all(dir);
}

// A ball coloured by z (viridis): the top of the ball is yellow-green (green > blue), the
// bottom purple (blue > green), whatever the Lambert factor (a common factor of r, g, b).
TEST(RenderMesh, BallColouredByHeight) {
  const auto dir = test::scratch_dir("render");
  PolygonMesh m = ball(12);
  std::vector<double> height = m.face_scalars[0].second;
  for (auto& h : height) h += 100; // positive values: the sequential map
  m.face_scalars.emplace_back("height", height);
  MeshRenderOptions opt;
  opt.width = 600;
  opt.height = 450;
  const auto report = render_mesh_png((dir / "ball.png").string(), m, "height", opt);
  EXPECT_EQ(report.color_map, ColorMap::viridis);
  const RgbImage img = decode_png(dir / "ball.png");
  ASSERT_EQ(img.width, 600);
  ASSERT_EQ(img.height, 450);
  EXPECT_TRUE(is_white(img.at(1, img.height - 2)));
  // The centre column of the drawing area, from the top of the shape to its bottom.
  int first = -1, last = -1;
  const int cx = (opt.width - 180) / 2;
  for (int y = 0; y < img.height; ++y) {
    const Rgb c = img.at(cx, y);
    if (!is_white(c) && y > 40) {
      if (first < 0) first = y;
      last = y;
    }
  }
  ASSERT_GT(last - first, 200) << "the ball should fill the picture's height";
  const Rgb top = img.at(cx, first + (last - first) / 10);
  const Rgb bottom = img.at(cx, last - (last - first) / 10);
  EXPECT_GT(top.g, top.b) << int(top.r) << "," << int(top.g) << "," << int(top.b);
  EXPECT_GT(bottom.b, bottom.g) << int(bottom.r) << "," << int(bottom.g) << "," << int(bottom.b);
  fs::remove_all(dir);
}

// A signed field (3 z): coolwarm, symmetric range, red on top,
// blue below; no field: grey, no colour bar; unknown field: an error.
TEST(RenderMesh, SignedFieldsDivergeAndErrors) {
  PolygonMesh m = ball(6);
  std::vector<double> signed_z = m.face_scalars[0].second;
  for (auto& v : signed_z) v = v * 3;
  m.face_scalars.emplace_back("signed", signed_z);
  MeshRenderOptions opt;
  opt.width = 400;
  opt.height = 300;
  opt.clip_percent = 0;
  MeshRenderReport rep;
  const RgbImage img = render_mesh(m, "signed", opt, &rep);
  EXPECT_EQ(rep.color_map, ColorMap::coolwarm);
  EXPECT_EQ(rep.value_min, -rep.value_max);
  EXPECT_EQ(rep.value_max, 3 * 6.5);
  EXPECT_EQ(rep.faces, m.face_count());
  EXPECT_GT(rep.samples, 1000);
  const int cx = (opt.width - 180) / 2;
  int first = -1, last = -1;
  for (int y = 40; y < img.height; ++y) {
    if (!is_white(img.at(cx, y))) {
      if (first < 0) first = y;
      last = y;
    }
  }
  ASSERT_GT(last, first);
  const Rgb top = img.at(cx, first + (last - first) / 10),
            bottom = img.at(cx, last - (last - first) / 10);
  EXPECT_GT(top.r, top.b);
  EXPECT_GT(bottom.b, bottom.r);
  // No field: grey surface, the right part (colour bar area) stays white.
  const RgbImage grey = render_mesh(m, "", opt);
  const Rgb g = grey.at(opt.width / 2, (first + last) / 2);
  EXPECT_LE(std::abs(int(g.r) - int(g.g)), 3);
  EXPECT_THROW(render_mesh(m, "ii-mean", opt), InvalidArgument);
  PolygonMesh nan_mesh = m;
  nan_mesh.vertices[0].x = std::nan("");
  EXPECT_THROW(render_mesh(nan_mesh, "", opt), InvalidArgument);
  opt.width = 10;
  EXPECT_THROW(render_mesh(m, "", opt), InvalidArgument);
}

TEST(RenderMesh, ColorScaleChoices) {
  const std::vector<double> v = {1, 2, 3, 4, 5, 6, 7, 8, 9, 1000};
  auto s = choose_color_scale(v, std::nullopt, std::nullopt, 0, std::nullopt);
  EXPECT_EQ(s.lo, 1);
  EXPECT_EQ(s.hi, 1000);
  EXPECT_EQ(s.map, ColorMap::viridis);
  s = choose_color_scale(v, std::nullopt, std::nullopt, 10, std::nullopt); // drops the outlier
  EXPECT_EQ(s.hi, 9);
  s = choose_color_scale(v, -1.0, 2.0, 0, std::nullopt);
  EXPECT_EQ(s.map, ColorMap::coolwarm);
  EXPECT_EQ(s.lo, -1); // a given range is kept as given
  s = choose_color_scale(std::vector<double>{5, 5, NAN}, std::nullopt, std::nullopt, 1,
                         std::nullopt);
  EXPECT_EQ(s.lo, 4.5);
  EXPECT_EQ(s.hi, 5.5);
  EXPECT_EQ(map_color(ColorMap::viridis, 0), (Rgb{68, 1, 84}));
  EXPECT_EQ(map_color(ColorMap::viridis, 1), (Rgb{253, 231, 37}));
  EXPECT_EQ(map_color(ColorMap::coolwarm, 0.5), (Rgb{221, 220, 220}));
  EXPECT_EQ(map_color(ColorMap::viridis, NAN), (Rgb{150, 150, 150}));
  EXPECT_THROW(choose_color_scale(v, 3.0, 1.0, 0, std::nullopt), InvalidArgument);
  EXPECT_EQ(short_number(0.000123456), "0.0001235");
  EXPECT_EQ(text_width("ab", 2), 22);
}

} // namespace
} // namespace zdg
