#include <zdg/arith/error.hpp>
#include <zdg/kernel/render/volume_render.hpp>

#include "tests/support/tower.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <set>

namespace zdg {
namespace {

using Voxel = std::array<std::int64_t, 3>;

// Exact fractions of small integers (the oracle's rays have |numerators| below 2^12).
struct F {
  std::int64_t n, d; // d > 0
};
F fr(std::int64_t n, std::int64_t d) {
  return d < 0 ? F{-n, -d} : F{n, d};
}
bool operator<(const F& a, const F& b) {
  return a.n * b.d < b.n * a.d;
}
bool operator==(const F& a, const F& b) {
  return a.n * b.d == b.n * a.d;
}
std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  return a / b - ((a % b != 0) && ((a < 0) != (b < 0)) ? 1 : 0);
}

// The oracle: every parameter where the line crosses a plane of voxel faces, the chord of the
// box, and the voxel of the midpoint of each piece between consecutive parameters.
std::vector<Voxel> crossed_voxels(const DigitalRay& r, const Voxel& n) {
  const std::int64_t den = r.denominator;
  std::vector<F> ts;
  bool have = false;
  F lo{0, 1}, hi{0, 1};
  for (int a = 0; a < 3; ++a) {
    const std::int64_t o2 = 2 * r.origin[a];
    if (r.direction[a] == 0) {
      if (o2 < -den || o2 >= (2 * n[a] - 1) * den) return {};
      continue;
    }
    for (std::int64_t k = -1; k < n[a]; ++k)
      ts.push_back(fr((2 * k + 1) * den - o2, 2 * r.direction[a]));
    F t1 = fr(-den - o2, 2 * r.direction[a]),
      t2 = fr((2 * n[a] - 1) * den - o2, 2 * r.direction[a]);
    if (t2 < t1) std::swap(t1, t2);
    if (!have || lo < t1) lo = t1;
    if (!have || t2 < hi) hi = t2;
    have = true;
  }
  if (!(lo < hi)) return {};
  std::vector<F> cut{lo, hi};
  for (const F& t : ts)
    if (lo < t && t < hi) cut.push_back(t);
  std::sort(cut.begin(), cut.end());
  cut.erase(std::unique(cut.begin(), cut.end()), cut.end());
  std::vector<Voxel> out;
  for (std::size_t i = 0; i + 1 < cut.size(); ++i) {
    const F mid{cut[i].n * cut[i + 1].d + cut[i + 1].n * cut[i].d, 2 * cut[i].d * cut[i + 1].d};
    Voxel v{};
    for (int a = 0; a < 3; ++a) // floor(P + 1/2), P = (O + t D) / den
      v[a] = floor_div(2 * (r.origin[a] * mid.d + mid.n * r.direction[a]) + den * mid.d,
                       2 * den * mid.d);
    out.push_back(v);
  }
  // Oriented along the direction: t increases.
  return out;
}

DigitalRay random_ray(Voxel& extent) {
  for (auto& e : extent) e = *rc::gen::inRange<std::int64_t>(1, 7);
  DigitalRay r;
  r.denominator = *rc::gen::inRange<std::int64_t>(1, 9);
  // Coarse origins and directions make rays through edges and corners, and in face planes.
  for (int a = 0; a < 3; ++a) {
    r.origin[a] = *rc::gen::inRange<std::int64_t>(-4 * r.denominator, 10 * r.denominator);
    r.direction[a] = *rc::gen::inRange<std::int64_t>(-4, 5);
  }
  if (r.direction == Voxel{0, 0, 0}) r.direction[*rc::gen::inRange(0, 3)] = 1;
  return r;
}

// Amanatides & Woo in exact arithmetic: the traversal is the set of voxels the line crosses
// over a positive length, in the line's order, each step to a 26-neighbour in the
// direction's orthant.
TEST(DigitalRay, VisitsTheVoxelsCrossedOverAPositiveLength) {
  test::check_property([] {
    Voxel n{};
    const DigitalRay r = random_ray(n);
    const auto got = digital_ray_voxels(r, n);
    RC_ASSERT(got == crossed_voxels(r, n));
    for (std::size_t i = 0; i + 1 < got.size(); ++i)
      for (int a = 0; a < 3; ++a) {
        const std::int64_t step = got[i + 1][a] - got[i][a];
        RC_ASSERT(step == 0 || step == (r.direction[a] > 0 ? 1 : -1));
      }
  });
}

// The same line in other numerators (O, D, den times k, up to 2^42): the same voxels, so the
// 128-bit comparisons hold at the contract's bounds.
TEST(DigitalRay, TheLineNotItsNumeratorsDecides) {
  test::check_property([] {
    Voxel n{};
    const DigitalRay r = random_ray(n);
    const std::int64_t k = *rc::gen::inRange<std::int64_t>(1, (std::int64_t{1} << 38) / 9);
    DigitalRay s = r;
    s.denominator *= k;
    for (int a = 0; a < 3; ++a) {
      s.origin[a] *= k;
      s.direction[a] *= (std::int64_t{1} << 38) / 8;
    }
    RC_ASSERT(digital_ray_voxels(s, n) == digital_ray_voxels(r, n));
  });
}

TEST(DigitalRay, WorkedExamples) {
  // Along +x at y = 1, z = 2 in a 4 x 3 x 3 box.
  EXPECT_EQ(digital_ray_voxels({{-10, 1, 2}, {1, 0, 0}, 1}, {4, 3, 3}),
            (std::vector<Voxel>{{0, 1, 2}, {1, 1, 2}, {2, 1, 2}, {3, 1, 2}}));
  // Backwards: the same voxels in reverse order.
  EXPECT_EQ(digital_ray_voxels({{10, 1, 2}, {-3, 0, 0}, 1}, {4, 3, 3}),
            (std::vector<Voxel>{{3, 1, 2}, {2, 1, 2}, {1, 1, 2}, {0, 1, 2}}));
  // The diagonal through the corners (k + 1/2, k + 1/2): the corners' neighbours are met in a
  // point only, so the ray steps diagonally.
  EXPECT_EQ(digital_ray_voxels({{-1, -1, 0}, {1, 1, 0}, 2}, {3, 3, 1}),
            (std::vector<Voxel>{{0, 0, 0}, {1, 1, 0}, {2, 2, 0}}));
  // In the face plane y = 1/2: the voxel above (half-open cubes).
  EXPECT_EQ(digital_ray_voxels({{-2, 1, 0}, {2, 0, 0}, 2}, {2, 2, 1}),
            (std::vector<Voxel>{{0, 1, 0}, {1, 1, 0}}));
  // Slope 1/2 through the centre of voxel (0, 0) (y = x / 2): the faces x = 1/2, y = 1/2 (at
  // x = 1), x = 3/2, x = 5/2, y = 3/2 (at x = 3) are crossed in that order.
  EXPECT_EQ(digital_ray_voxels({{0, 0, 0}, {2, 1, 0}, 1}, {4, 3, 1}),
            (std::vector<Voxel>{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {2, 1, 0}, {3, 1, 0}, {3, 2, 0}}));
  // A miss, and a line in the plane of the box's far face (outside the half-open box).
  EXPECT_TRUE(digital_ray_voxels({{-10, 5, 0}, {1, 0, 0}, 1}, {4, 3, 1}).empty());
  EXPECT_TRUE(digital_ray_voxels({{-2, 3, 0}, {1, 0, 0}, 2}, {4, 2, 1}).empty());
}

TEST(DigitalRay, BadRaysAreErrors) {
  EXPECT_THROW(digital_ray_voxels({{0, 0, 0}, {0, 0, 0}, 1}, {2, 2, 2}), InvalidArgument);
  EXPECT_THROW(digital_ray_voxels({{0, 0, 0}, {1, 0, 0}, 0}, {2, 2, 2}), InvalidArgument);
  EXPECT_THROW(digital_ray_voxels({{(std::int64_t{1} << 42) + 1, 0, 0}, {1, 0, 0}, 1}, {2, 2, 2}),
               InvalidArgument);
  EXPECT_THROW(digital_ray_voxels({{0, 0, 0}, {1, 0, 0}, 1}, {2, (std::int64_t{1} << 20) + 1, 2}),
               InvalidArgument);
}

// ---- transfer functions ----

TEST(TransferFunction, TextAndJsonFormsAgreeAndInterpolateLinearly) {
  const auto a =
      parse_transfer_function("# bone\n0 0 0 0 0\n\n100 1 0.5 0.25 0.8  # end\n", "a.txt");
  const auto b = parse_transfer_function(
      R"({"points": [[0, 0, 0, 0, 0], [100, 1, 0.5, 0.25, 0.8]]})", "b.json");
  EXPECT_EQ(a.points, b.points);
  const Rgba m = a(25);
  EXPECT_DOUBLE_EQ(m.r, 0.25);
  EXPECT_DOUBLE_EQ(m.g, 0.125);
  EXPECT_DOUBLE_EQ(m.b, 0.0625);
  EXPECT_DOUBLE_EQ(m.a, 0.2);
  EXPECT_DOUBLE_EQ(a(-5).a, 0.0); // clamped below and above
  EXPECT_DOUBLE_EQ(a(1e9).r, 1.0);
  EXPECT_DOUBLE_EQ(a(std::nan("")).a, 0.0);
}

TEST(TransferFunction, BadFilesAreOneLineErrorsNamingTheLine) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"", "needs a control point"},
      {"0 0 0 0\n", "t.txt:1: expected 'value r g b alpha'"},
      {"0 0 0 0 0\n1 0 0 0 0 7\n", "t.txt:2: expected"},
      {"0 0 0 0 0\n0 1 1 1 1\n", "control point 2: value 0 does not increase"},
      {"0 0 0 0 1.5\n", "must lie in [0, 1]"},
      {"nan 0 0 0 0\n", "t.txt:1"},
      {"{\"points\": [[0, 0, 0, 0]]}", "point 1: expected [value, r, g, b, alpha]"},
      {"{\"points\": [[0, 0, \"x\", 0, 0]]}", "entry 3 is not a number"},
      {"{\"points\": ", "not valid JSON"},
      {"{\"colours\": []}", "expected {\"points\""},
      {"0 0 0 0 0\x01\n", "control character"},
  };
  for (const auto& [text, why] : cases) {
    try {
      parse_transfer_function(text, "t.txt");
      ADD_FAILURE() << why << ": no error";
    } catch (const IoError& e) {
      const std::string w = e.what();
      EXPECT_NE(w.find(why), std::string::npos) << w;
      EXPECT_EQ(w.find('\n'), std::string::npos) << w;
    }
  }
  EXPECT_THROW(transfer_function_preset("bone", 0, 1), InvalidArgument);
  for (const auto& name : transfer_function_presets())
    EXPECT_NO_THROW(transfer_function_preset(name, -1000, 3000).validate(name));
}

// ---- rendering ----

template <class T>
ScalarVolume volume_of(DType t, const std::vector<std::int64_t>& shape, const std::vector<T>& v) {
  NpyArray a;
  a.dtype = t;
  a.shape = shape;
  a.bytes.resize(v.size() * sizeof(T));
  std::memcpy(a.bytes.data(), v.data(), a.bytes.size());
  return make_scalar_volume(std::move(a));
}

VolumeRenderOptions small(double az, double el) {
  VolumeRenderOptions o;
  o.width = 200;
  o.height = 150;
  o.azimuth = az;
  o.elevation = el;
  return o;
}

// MIP: each pixel's value is the maximum over the voxels of its digital ray (the brute-force
// maximum over digital_ray_voxels of volume_camera_ray), NaN where the ray misses the box.
TEST(VolumeRender, MipIsTheMaximumOverEachPixelsDigitalRay) {
  test::check_property([] {
    const std::int64_t nz = *rc::gen::inRange(1, 5), ny = *rc::gen::inRange(1, 6),
                       nx = *rc::gen::inRange(1, 6);
    std::vector<std::int16_t> v(static_cast<std::size_t>(nx * ny * nz));
    for (auto& x : v) x = static_cast<std::int16_t>(*rc::gen::inRange(-1000, 1000));
    ScalarVolume vol = volume_of(DType::I16, {nz, ny, nx}, v);
    vol.spacing = {*rc::gen::element(0.5, 1.0, 2.0), 1.0, *rc::gen::element(1.0, 1.5)};
    VolumeRenderOptions o = small(*rc::gen::inRange(-180, 180), *rc::gen::inRange(-90, 91));
    o.mip = true;
    o.threads = 2;
    const auto r = render_volume(vol, transfer_function_preset("grey", -1000, 1000), o);
    const std::array<double, 3> sp{vol.spacing[2], vol.spacing[1], vol.spacing[0]};
    std::int64_t hits = 0;
    for (int py = 0; py < o.height; py += 7)
      for (int px = 0; px < o.width; px += 5) {
        const auto voxels =
            digital_ray_voxels(volume_camera_ray({nx, ny, nz}, sp, o, px, py), {nx, ny, nz});
        const double got = r.values[std::size_t(py) * std::size_t(o.width) + std::size_t(px)];
        if (voxels.empty()) {
          RC_ASSERT(std::isnan(got));
          continue;
        }
        ++hits;
        double best = -1e300;
        for (const auto& q : voxels)
          best = std::max(best, double(v[std::size_t((q[2] * ny + q[1]) * nx + q[0])]));
        RC_ASSERT(got == best);
      }
    RC_ASSERT(hits > 0); // the framed box covers the middle of the picture
  });
}

// Looking down (elevation 90): every ray is a column of voxels, so the MIP is the maximum of
// each column.
TEST(VolumeRender, MipFromAboveIsTheColumnMaximum) {
  const std::int64_t n = 6;
  std::vector<std::uint8_t> v(static_cast<std::size_t>(n * n * n));
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = static_cast<std::uint8_t>((i * 37) % 251);
  VolumeRenderOptions o = small(0, 90);
  o.mip = true;
  const auto r = render_volume(volume_of(DType::U8, {n, n, n}, v),
                               transfer_function_preset("grey", 0, 250), o);
  std::set<double> column_max;
  for (std::int64_t y = 0; y < n; ++y)
    for (std::int64_t x = 0; x < n; ++x) {
      int m = 0;
      for (std::int64_t z = 0; z < n; ++z)
        m = std::max<int>(m, v[std::size_t((z * n + y) * n + x)]);
      column_max.insert(m);
    }
  std::set<double> seen;
  for (double x : r.values)
    if (!std::isnan(x)) seen.insert(x);
  EXPECT_EQ(seen, column_max);
}

// Compositing a constant material seen along an axis: every ray crosses n voxel lengths, so
// its opacity is 1 - (1 - alpha)^n and its colour the material's times that (Max 1995),
// whatever the step (opacity correction).
TEST(VolumeRender, ConstantSlabHasTheClosedFormOpacity) {
  const std::int64_t n = 5;
  const std::vector<float> v(static_cast<std::size_t>(n * n * n), 3.0f);
  TransferFunction tf;
  tf.points = {{0, 0.2, 0.6, 1.0, 0.3}, {10, 0.2, 0.6, 1.0, 0.3}};
  const double expected = 1 - std::pow(1 - 0.3, double(n));
  for (double step : {0.5, 0.3, 1.7}) {
    VolumeRenderOptions o = small(0, 0);
    o.shading = false;
    o.early_termination = 1.0;
    o.step = step;
    const auto r = render_volume(volume_of(DType::F32, {n, n, n}, v), tf, o);
    ASSERT_GT(r.rays, 0);
    for (int py = 0; py < o.height; ++py)
      for (int px = 0; px < o.width; ++px) {
        const double a = r.values[std::size_t(py) * std::size_t(o.width) + std::size_t(px)];
        if (std::isnan(a)) continue;
        ASSERT_NEAR(a, expected, 1e-12) << "step " << step;
        const Rgb c = r.picture.at(px, py);
        EXPECT_EQ(c.b, std::lround(255 * expected));
        EXPECT_EQ(c.g, std::lround(255 * 0.6 * expected));
      }
  }
}

// Early termination at A stops a ray whose remaining transmittance is at most 1 - A: the
// opacity and every channel move by at most that.
TEST(VolumeRender, EarlyTerminationChangesAtMostTheRemainingTransmittance) {
  const std::int64_t n = 8;
  std::vector<std::uint16_t> v(static_cast<std::size_t>(n * n * n));
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = static_cast<std::uint16_t>((i * 7919) % 1000);
  const auto vol = volume_of(DType::U16, {n, n, n}, v);
  const auto tf = transfer_function_preset("grey", 0, 400);
  VolumeRenderOptions o = small(-60, 30);
  o.early_termination = 1.0;
  const auto full = render_volume(vol, tf, o);
  o.early_termination = 0.9;
  const auto early = render_volume(vol, tf, o);
  EXPECT_LT(early.samples, full.samples);
  for (std::size_t i = 0; i < full.values.size(); ++i) {
    if (std::isnan(full.values[i])) continue;
    ASSERT_LE(full.values[i] - early.values[i], 0.1 + 1e-12);
    ASSERT_GE(full.values[i] - early.values[i], 0.0);
  }
  for (std::size_t i = 0; i < full.picture.rgb.size(); ++i)
    ASSERT_LE(std::abs(int(full.picture.rgb[i]) - int(early.picture.rgb[i])), 26);
}

// The same values stored as uint8, int16 or float64 (or as int8 with a slope and intercept),
// and any thread count: the same picture, byte for byte.
TEST(VolumeRender, IndependentOfTheDtypeAndTheThreads) {
  const std::int64_t n = 7;
  std::vector<std::uint8_t> u(static_cast<std::size_t>(n * n * n));
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = static_cast<std::uint8_t>((i * i * 13) % 200);
  std::vector<std::int16_t> s(u.begin(), u.end());
  std::vector<double> d(u.begin(), u.end());
  std::vector<std::int8_t> h(u.size());
  for (std::size_t i = 0; i < u.size(); ++i) h[i] = static_cast<std::int8_t>(u[i] / 2 - 50);
  ScalarVolume scaled = volume_of(DType::I8, {n, n, n}, h);
  scaled.slope = 2;
  scaled.inter = 100;
  const auto tf = transfer_function_preset("grey", 0, 199);
  for (bool mip : {false, true}) {
    VolumeRenderOptions o = small(35, -20);
    o.mip = mip;
    o.threads = 1;
    const auto ref = render_volume(volume_of(DType::U8, {n, n, n}, u), tf, o);
    o.threads = 3;
    EXPECT_EQ(render_volume(volume_of(DType::U8, {n, n, n}, u), tf, o).picture.rgb,
              ref.picture.rgb);
    EXPECT_EQ(render_volume(volume_of(DType::I16, {n, n, n}, s), tf, o).picture.rgb,
              ref.picture.rgb);
    EXPECT_EQ(render_volume(volume_of(DType::F64, {n, n, n}, d), tf, o).picture.rgb,
              ref.picture.rgb);
    if (mip) { // even values only: the MIP of the scaled volume takes even maxima
      const auto r = render_volume(scaled, tf, o);
      for (double x : r.values)
        if (!std::isnan(x)) {
          EXPECT_EQ(std::fmod(x, 2.0), 0.0);
        }
    }
  }
}

TEST(VolumeRender, BadOptionsAreErrors) {
  const auto vol = volume_of(DType::U8, {2, 2, 2}, std::vector<std::uint8_t>(8, 1));
  const auto tf = transfer_function_preset("grey", 0, 1);
  VolumeRenderOptions o = small(0, 0);
  o.step = 0;
  EXPECT_THROW(render_volume(vol, tf, o), InvalidArgument);
  o = small(0, 0);
  o.early_termination = 0;
  EXPECT_THROW(render_volume(vol, tf, o), InvalidArgument);
  o = small(0, 0);
  o.width = 10;
  EXPECT_THROW(render_volume(vol, tf, o), InvalidArgument);
  o = small(std::nan(""), 0);
  EXPECT_THROW(render_volume(vol, tf, o), InvalidArgument);
  // A huge angle is taken modulo 360 degrees (exactly), not overflowed into radians.
  EXPECT_EQ(render_volume(vol, tf, small(1e308, 5)).picture.rgb,
            render_volume(vol, tf, small(std::fmod(1e308, 360.0), 5)).picture.rgb);
  EXPECT_THROW(render_volume(vol, TransferFunction{}, small(0, 0)), InvalidArgument);
}

} // namespace
} // namespace zdg
