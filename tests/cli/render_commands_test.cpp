// zdg render volume (cli/render_commands.cpp): the maximum intensity projection of a ball and a
// brighter cube shows both at their values (grey preset: a ramp over the volume's range);
// compositing through a transfer function file paints what it makes opaque and nothing where
// it is transparent; the JSON summary, and an existing output kept without --force.
#include <zdg/kernel/io/npy_io.hpp>

#include "tests/support/cli.hpp"
#include "tests/support/png.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

namespace zdg {
namespace {

namespace fs = std::filesystem;

// 32^3 uint8: a ball of radius 10 at value 200, a 4^3 cube at 254 outside it, 0 elsewhere.
void write_scene(const fs::path& path) {
  const std::int64_t n = 32;
  NpyArray a;
  a.dtype = DType::U8;
  a.shape = {n, n, n};
  a.bytes.assign(static_cast<std::size_t>(n * n * n), 0);
  for (std::int64_t z = 0; z < n; ++z)
    for (std::int64_t y = 0; y < n; ++y)
      for (std::int64_t x = 0; x < n; ++x) {
        auto& v = a.bytes[static_cast<std::size_t>((z * n + y) * n + x)];
        if ((x - 12) * (x - 12) + (y - 12) * (y - 12) + (z - 16) * (z - 16) <= 100) v = 200;
        if (x >= 26 && x < 30 && y >= 26 && y < 30 && z >= 14 && z < 18) v = 254;
      }
  write_npy(path.string(), a);
}

std::map<int, int> grey_levels(const RgbImage& img) {
  std::map<int, int> count;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const Rgb c = img.at(x, y);
      EXPECT_TRUE(c.r == c.g && c.g == c.b);
      ++count[c.r];
    }
  return count;
}

TEST(RenderVolume, MipShowsEachObjectAtItsValue) {
  const fs::path dir = test::scratch_dir("render_mip");
  write_scene(dir / "s.npy");
  const auto r = test::run_zdg("render volume " + (dir / "s.npy").string() + " --mip --view 0,90 " +
                               "--png-size 300x200 -o " + (dir / "m.png").string() + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["mode"], "mip");
  EXPECT_EQ(j["size"], nlohmann::json({300, 200}));
  EXPECT_EQ(j["values"], nlohmann::json({0.0, 254.0}));
  EXPECT_GT(j["rays"].get<std::int64_t>(), 0);
  const RgbImage img = test::decode_png(dir / "m.png");
  ASSERT_EQ(img.width, 300);
  ASSERT_EQ(img.height, 200);
  const auto levels = grey_levels(img);
  EXPECT_EQ(levels.size(), 3u); // background, ball, cube: nothing in between
  // The grey preset spans the values 0..254: 200 -> round(255 * 200 / 254), 254 -> 255.
  const int ball = static_cast<int>(std::lround(255.0 * 200 / 254)), cube = 255;
  ASSERT_GT(levels.count(ball), 0u);
  ASSERT_GT(levels.count(cube), 0u);
  // From above, the ball's disc of radius 10 voxels and the cube's 4 x 4 square: the disc is
  // about 314 / 16 times larger in pixels.
  const double ratio = double(levels.at(ball)) / levels.at(cube);
  EXPECT_NEAR(ratio, 3.14159 * 100 / 16, 3.0);
}

TEST(RenderVolume, TransferFunctionFilePaintsOnlyWhatItMakesOpaque) {
  const fs::path dir = test::scratch_dir("render_tf");
  write_scene(dir / "s.npy");
  // Red and opaque from 240 on: the cube only.
  std::ofstream(dir / "tf.txt")
      << "# cube only\n0 0 0 0 0\n239 0 0 0 0\n240 1 0 0 1\n255 1 0 0 1\n";
  const std::string out = (dir / "c.png").string();
  const auto r = test::run_zdg("render volume " + (dir / "s.npy").string() + " --tf " +
                               (dir / "tf.txt").string() + " -o " + out + " --json --threads 2");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["mode"], "composite");
  EXPECT_EQ(j["transfer_function"]["points"].size(), 4u);
  const RgbImage img = test::decode_png(out);
  int red = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const Rgb c = img.at(x, y);
      EXPECT_EQ(c.g, 0);
      EXPECT_EQ(c.b, 0);
      red += c.r > 0;
    }
  EXPECT_GT(red, 0);
  EXPECT_LT(red, img.width * img.height / 20); // a small cube of the 32^3 box
  // An existing output is kept without --force, replaced with it.
  const auto again = test::run_zdg("render volume " + (dir / "s.npy").string() + " -o " + out);
  EXPECT_EQ(again.status, 2);
  EXPECT_NE(again.err.find("--force"), std::string::npos) << again.err;
  EXPECT_EQ(
      test::run_zdg("render volume " + (dir / "s.npy").string() + " -o " + out + " --force").status,
      0);
}

} // namespace
} // namespace zdg
