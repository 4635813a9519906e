#include <zdg/kernel/transforms/voronoi_map.hpp>

#include "tests/support/check_registry.hpp"
#include "tests/support/tower.hpp"
#include "tests/support/transform_oracle.hpp"
#include <zdg/kernel/transforms/distance_transform.hpp>
#include <zdg/kernel/transforms/reduced_medial_axis.hpp>

#include <gtest/gtest.h>

namespace zdg {
namespace {

template <class I>
class VoronoiMapTyped : public ::testing::Test {};
TYPED_TEST_SUITE(VoronoiMapTyped, test::TowerTypes, test::TowerNames);

// Every site is a background point and attains the distance transform (oracle: brute force).
TYPED_TEST(VoronoiMapTyped, SitesAttainTheDistance) {
  test::check_property([] {
    auto c = test::random_transform_case();
    c.opt.min_engine_bits = test::engine_bits<TypeParam>();
    auto map = voronoi_map(c.shape, c.opt);
    auto oracle = test::brute_distance_transform<std::int64_t>(c.shape, c.opt);
    const Domain& dom = c.shape.domain();
    for (std::int64_t i = 0; i < dom.size(); ++i) {
      std::int64_t s = map.site[static_cast<std::size_t>(i)];
      RC_ASSERT(s >= 0);
      RC_ASSERT(s < dom.size());
      RC_ASSERT(c.shape[s] == 0);
      RC_ASSERT(test::metric_length<std::int64_t>(dom, c.opt, i, s) ==
                oracle[static_cast<std::size_t>(i)]);
    }
  });
}

TEST(VoronoiMap, BackgroundIsItsOwnSite) {
  Image<std::uint8_t> img(Domain({3, 4}, {-1, 2}),
                          std::vector<std::uint8_t>{1, 0, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0});
  auto map = voronoi_map(img, {});
  EXPECT_EQ(map.site[1], 1);
  EXPECT_EQ(map.site[11], 11);
  EXPECT_EQ(map.site_point(0), (std::vector<std::int64_t>{-1, 3}));
  EXPECT_EQ(map.site_point(10), (std::vector<std::int64_t>{1, 5}));
}

TEST(VoronoiMap, ThreadCountIndependence) {
  Domain dom({180, 201});
  std::mt19937 rng(3);
  std::vector<std::uint8_t> v(static_cast<std::size_t>(dom.size()));
  for (auto& x : v) x = rng() % 300 == 0 ? 0 : 1;
  Image<std::uint8_t> shape(dom, v);
  for (int p : {1, 2, 5, 0}) {
    TransformOptions opt;
    opt.metric = Metric{p};
    opt.torus = {true, false};
    opt.threads = 1;
    auto ref = voronoi_map(shape, opt).site;
    opt.threads = 3;
    EXPECT_EQ(voronoi_map(shape, opt).site, ref) << p;
  }
}

// The in-place overload (what the Python module calls) reads any nonzero byte as object and
// agrees with the Image overload; the reduced medial axis likewise.
TEST(VoronoiMap, InPlaceMaskOfAnyNonzeroBytesAgrees) {
  Domain dom({23, 31});
  std::mt19937 rng(11);
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(dom.size())), binary(bytes.size());
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    bytes[i] = rng() % 9 == 0 ? 0 : static_cast<std::uint8_t>(1 + rng() % 255);
    binary[i] = bytes[i] != 0 ? 1 : 0;
  }
  const Image<std::uint8_t> shape(dom, binary);
  for (int p : {1, 2, 0}) {
    TransformOptions opt;
    opt.metric = Metric{p};
    EXPECT_EQ(voronoi_map(dom, bytes.data(), opt).site, voronoi_map(shape, opt).site) << p;
    EXPECT_EQ(reduced_medial_axis(dom, bytes.data(), opt), reduced_medial_axis(shape, opt)) << p;
  }
  std::vector<std::uint8_t> full(bytes.size(), 3);
  EXPECT_THROW(voronoi_map(dom, full.data(), {}), InvalidArgument);
}

// Masks of wider items (2, 4, 8 bytes a point, as numpy's integer arrays) are read in place:
// a point is background when all its bytes are 0, so a value whose low byte is 0 (256, 2^24,
// 2^40) is object. Oracle: the byte mask of the same points.
TEST(VoronoiMap, WideMaskItemsAgreeWithTheByteMask) {
  Domain dom({19, 27});
  std::mt19937 rng(5);
  std::vector<std::uint8_t> binary(static_cast<std::size_t>(dom.size()));
  for (auto& b : binary) b = rng() % 7 == 0 ? 0 : 1;
  const Image<std::uint8_t> shape(dom, binary);
  auto check = [&]<class T>(T big) {
    std::vector<T> wide(binary.size());
    for (std::size_t i = 0; i < wide.size(); ++i) wide[i] = binary[i] ? big : T(0);
    const auto* bytes = reinterpret_cast<const std::uint8_t*>(wide.data());
    for (int p : {1, 2, 0}) {
      TransformOptions opt;
      opt.metric = Metric{p};
      opt.torus = {false, true};
      EXPECT_EQ(voronoi_map(dom, bytes, opt, int(sizeof(T))).site, voronoi_map(shape, opt).site)
          << sizeof(T) << " " << p;
      EXPECT_EQ(reduced_medial_axis(dom, bytes, opt, int(sizeof(T))),
                reduced_medial_axis(shape, opt))
          << sizeof(T) << " " << p;
    }
  };
  check(std::uint16_t{256});
  check(std::int32_t{1} << 24);
  check(std::int64_t{1} << 40);
  std::vector<std::uint8_t> bytes(3 * binary.size(), 1);
  EXPECT_THROW(voronoi_map(dom, bytes.data(), {}, 3), InvalidArgument);
}

TEST(VoronoiMap, NoBackgroundIsAnError) {
  Image<std::uint8_t> full(Domain({2, 2, 2}), std::uint8_t{7});
  EXPECT_THROW(voronoi_map(full, {}), InvalidArgument);
}

} // namespace
// The registered property voronoi.l2.nearest (zdg check): every site is a nearest background
// point, against every pair of points.
TEST(VoronoiMap, RegisteredNearestSitePropertyHolds) {
  test::expect_registered_property("voronoi.l2.nearest", IntKind::int64, 300);
}

} // namespace zdg
