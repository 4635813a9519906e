#include <zdg/kernel/transforms/distance_transform.hpp>
#include <zdg/kernel/transforms/separable_engine.hpp>

#include "tests/support/check_registry.hpp"
#include "tests/support/tower.hpp"
#include "tests/support/transform_oracle.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <algorithm>
#include <limits>
#include <random>
#include <type_traits>
#include <utility>
#include <vector>

namespace zdg {
namespace {

using test::brute_distance_transform;
using test::random_transform_case;

template <class I>
class DistanceTransformTyped : public ::testing::Test {};
TYPED_TEST_SUITE(DistanceTransformTyped, test::TowerTypes, test::TowerNames);

// Theorem (separability, Hirata 1996 / Meijster et al. 2000): the pass-by-pass lower
// envelopes give min over the background of d_p^p; oracle: every pair of points.
TYPED_TEST(DistanceTransformTyped, EqualsBruteForce) {
  test::check_property([] {
    auto c = random_transform_case();
    c.opt.min_engine_bits = test::engine_bits<TypeParam>();
    auto dt = distance_transform<std::int64_t>(c.shape, c.opt);
    auto oracle = brute_distance_transform<std::int64_t>(c.shape, c.opt);
    RC_ASSERT(dt.values() == oracle);
  });
}

TEST(DistanceTransform, DefaultWidthEqualsBruteForce) {
  test::check_property([] {
    auto c = random_transform_case();
    auto dt = distance_transform<std::uint64_t>(c.shape, c.opt);
    auto oracle = brute_distance_transform<std::int64_t>(c.shape, c.opt);
    for (std::size_t i = 0; i < oracle.size(); ++i) {
      RC_ASSERT(dt.values()[i] == static_cast<std::uint64_t>(oracle[i]));
    }
  });
}

// Large p: d^p exceeds int64 and __int128 (l_40 on a 20 x 13 domain: 19^40 ~ 1.4e51), so the
// engine runs on GMP integers; oracle in BigInt.
TEST(DistanceTransform, HugePowersUseBigIntegers) {
  Domain dom({20, 13}, {-3, 4});
  std::vector<std::uint8_t> v(static_cast<std::size_t>(dom.size()), 1);
  v[0] = 0;
  v[150] = 0;
  Image<std::uint8_t> shape(dom, v);
  TransformOptions opt;
  opt.metric = Metric::lp(40);
  EXPECT_GT(distance_transform_max_value(dom, opt), BigInt(1) << 160);
  auto dt = distance_transform<BigInt>(shape, opt);
  EXPECT_EQ(dt.values(), brute_distance_transform<BigInt>(shape, opt));
  EXPECT_THROW(distance_transform<std::uint64_t>(shape, opt), OverflowError);
}

TEST(DistanceTransform, WorkedExamples) {
  Image<std::uint8_t> line(Domain({7}), std::vector<std::uint8_t>{0, 1, 1, 1, 1, 0, 1});
  TransformOptions l2;
  EXPECT_EQ(distance_transform<std::uint32_t>(line, l2).values(),
            (std::vector<std::uint32_t>{0, 1, 4, 4, 1, 0, 1}));
  TransformOptions torus = l2;
  torus.torus = {true};
  // the last point is next to the first one on the circle
  EXPECT_EQ(distance_transform<std::uint32_t>(line, torus).values(),
            (std::vector<std::uint32_t>{0, 1, 4, 4, 1, 0, 1}));
  Image<std::uint8_t> ring(Domain({6}), std::vector<std::uint8_t>{1, 1, 1, 1, 0, 1});
  EXPECT_EQ(distance_transform<std::uint32_t>(ring, torus).values(),
            (std::vector<std::uint32_t>{4, 9, 4, 1, 0, 1}));
  // 3 x 3 with the background at the centre: l1, l2, linf rings.
  Image<std::uint8_t> sq(Domain({3, 3}), std::vector<std::uint8_t>{1, 1, 1, 1, 0, 1, 1, 1, 1});
  TransformOptions o;
  o.metric = Metric::l1();
  EXPECT_EQ(distance_transform<std::uint8_t>(sq, o).values(),
            (std::vector<std::uint8_t>{2, 1, 2, 1, 0, 1, 2, 1, 2}));
  o.metric = Metric::l2();
  EXPECT_EQ(distance_transform<std::uint8_t>(sq, o).values(),
            (std::vector<std::uint8_t>{2, 1, 2, 1, 0, 1, 2, 1, 2}));
  o.metric = Metric::linf();
  EXPECT_EQ(distance_transform<std::uint8_t>(sq, o).values(),
            (std::vector<std::uint8_t>{1, 1, 1, 1, 0, 1, 1, 1, 1}));
  o.metric = Metric::lp(3);
  EXPECT_EQ(distance_transform<std::uint8_t>(sq, o).values(),
            (std::vector<std::uint8_t>{2, 1, 2, 1, 0, 1, 2, 1, 2}));
}

// Results do not depend on the thread count (lines are independent): a 3D image large enough
// to be split (>= 2^15 points), every metric, with a torus axis.
TEST(DistanceTransform, ThreadCountIndependence) {
  Domain dom({33, 40, 29}, {-16, 0, 5});
  std::mt19937 rng(7);
  std::vector<std::uint8_t> v(static_cast<std::size_t>(dom.size()));
  for (auto& x : v) x = rng() % 50 == 0 ? 0 : 1;
  Image<std::uint8_t> shape(dom, v);
  for (int p : {1, 2, 3, 0}) {
    TransformOptions opt;
    opt.metric = Metric{p};
    opt.torus = {false, true, false};
    opt.threads = 1;
    auto ref = distance_transform<std::uint32_t>(shape, opt);
    for (unsigned t : {2u, 3u, 8u}) {
      opt.threads = t;
      EXPECT_EQ(distance_transform<std::uint32_t>(shape, opt), ref) << p << " " << t;
    }
  }
}

// The buffer form (what `zdg transform` runs on a mapped .npy): a mask of 1-, 2-, 4- or 8-byte
// items, an item background iff all its bytes are 0, gives the transform of the 0/1 mask, in
// every output type that holds it.
TEST(DistanceTransform, IntoBuffersReadsWideMaskItems) {
  test::check_property([] {
    auto c = random_transform_case();
    const int item = *rc::gen::element(1, 2, 4, 8);
    const auto n = static_cast<std::size_t>(c.shape.size());
    std::vector<std::uint8_t> wide(n * static_cast<std::size_t>(item), 0);
    for (std::size_t i = 0; i < n; ++i) {
      if (c.shape.values()[i] == 0) continue;
      // a foreground item: any nonzero byte pattern (one byte, several, a sign bit alone)
      const auto byte = *rc::gen::inRange<std::size_t>(0, static_cast<std::size_t>(item));
      wide[i * static_cast<std::size_t>(item) + byte] = *rc::gen::inRange<int>(1, 256);
    }
    const auto expect = distance_transform<std::uint64_t>(c.shape, c.opt);
    std::vector<std::uint64_t> out(n, 12345);
    // With a progress callback: called once per pass, (1, d) .. (d, d), the values unchanged.
    std::vector<std::pair<int, int>> calls;
    distance_transform_into<std::uint64_t>(
        c.shape.domain(), wide.data(), item, c.opt, out.data(),
        [&](int done, int total) { calls.emplace_back(done, total); });
    RC_ASSERT(out == expect.values());
    const int d = c.shape.domain().dim();
    RC_ASSERT(calls.size() == static_cast<std::size_t>(d));
    for (int k = 0; k < d; ++k)
      RC_ASSERT(calls[static_cast<std::size_t>(k)] == std::make_pair(k + 1, d));
    if (distance_transform_max_value(c.shape.domain(), c.opt) <= BigInt(4294967295ULL)) {
      std::vector<std::uint32_t> out32(n, 7);
      distance_transform_into<std::uint32_t>(c.shape.domain(), wide.data(), item, c.opt,
                                             out32.data());
      RC_ASSERT(std::equal(out32.begin(), out32.end(), expect.values().begin()));
    }
  });
  Image<std::uint8_t> img(Domain({3}), std::vector<std::uint8_t>{0, 1, 1});
  std::vector<std::uint32_t> out(3);
  EXPECT_THROW(
      distance_transform_into<std::uint32_t>(img.domain(), img.values().data(), 3, {}, out.data()),
      InvalidArgument);
}

TEST(DistanceTransform, Errors) {
  Image<std::uint8_t> full(Domain({4, 5}), std::uint8_t{1});
  EXPECT_THROW(distance_transform<std::uint32_t>(full, {}), InvalidArgument);
  TransformOptions torus;
  torus.torus = {true, true};
  try {
    distance_transform<std::uint32_t>(full, torus);
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("torus"), std::string::npos);
  }
  Image<std::uint8_t> img(Domain({20, 20}), std::uint8_t{0});
  EXPECT_THROW(distance_transform<std::uint8_t>(img, {}), OverflowError); // 2 * 19^2 > 255
  TransformOptions bad;
  bad.torus = {true};
  EXPECT_THROW(distance_transform<std::uint32_t>(img, bad), InvalidArgument);
  EXPECT_THROW(Metric::lp(0), InvalidArgument);
  EXPECT_THROW(parse_metric("l0"), InvalidArgument);
  EXPECT_THROW(parse_metric("l2.5"), InvalidArgument);
  EXPECT_EQ(parse_metric("l7").p, 7);
  EXPECT_TRUE(parse_metric("linf").is_inf());
}

// Allows the vectorized passes again when a test that compares them with the portable loop
// ends (passes or fails).
struct AllowSimdAtExit {
  ~AllowSimdAtExit() { detail::set_envelope_simd(true); }
};

// The vectorized passes (kernel/transforms/separable_engine.cpp: the mask pass from the sites'
// bits, the envelopes 16 lines per AVX-512 vector, peaks left out) give the values of the scalar
// sweep to the bit for every metric (l1, l2, l3, l4, linf), in mask mode (distance transforms) and
// in value mode (weighted sites, inf where none), on blocks of 16 columns and narrower ones, and
// torus axes (lines of three copies). Oracle: the portable loop of the same engine.
TEST(DistanceTransform, VectorizedEnvelopeEqualsPortable) {
  if (!detail::envelope_simd_available()) GTEST_SKIP() << "no AVX-512F on this CPU";
  const AllowSimdAtExit allow;
  test::check_property([] {
    std::mt19937 rng(*rc::gen::arbitrary<std::uint32_t>());
    auto pick = [&](int lo, int hi) {
      return lo + static_cast<int>(rng() % static_cast<unsigned>(hi - lo + 1));
    };
    const int d = pick(2, 3);
    std::vector<std::int64_t> ext;
    for (int k = 0; k < d; ++k) ext.push_back(pick(1, d == 2 ? 70 : 37));
    Domain dom(ext);
    TransformOptions opt;
    opt.metric = Metric{pick(0, 4)};
    for (int k = 0; k < d; ++k) opt.torus.push_back(pick(0, 2) == 0);
    opt.threads = static_cast<unsigned>(pick(1, 2));
    std::vector<std::uint8_t> v(static_cast<std::size_t>(dom.size()));
    if (pick(0, 2) == 0) {
      // Background boxes in the object: the first pass's values have long plateaus and ramps
      // (the peaks the vectorized envelopes leave out), where random masks have few.
      for (auto& x : v) x = 1;
      std::vector<std::int64_t> p(static_cast<std::size_t>(d));
      for (int box = pick(1, 4); box-- > 0;) {
        std::vector<std::int64_t> lo, hi;
        for (int k = 0; k < d; ++k) {
          lo.push_back(pick(0, static_cast<int>(ext[k]) - 1));
          hi.push_back(std::min<std::int64_t>(ext[k], lo.back() + pick(1, 6)));
        }
        for (std::int64_t i = 0; i < dom.size(); ++i) {
          dom.point(i, p);
          bool in = true;
          for (int k = 0; k < d; ++k)
            in = in && p[k] - dom.lower(k) >= lo[k] && p[k] - dom.lower(k) < hi[k];
          if (in) v[static_cast<std::size_t>(i)] = 0;
        }
      }
    } else {
      const int density = pick(0, 100);
      for (auto& x : v) x = pick(0, 99) < density ? 1 : 0;
    }
    v[rng() % v.size()] = 0;
    Image<std::uint8_t> shape(dom, v);
    detail::set_envelope_simd(false);
    auto ref = distance_transform<std::uint32_t>(shape, opt);
    detail::set_envelope_simd(true);
    RC_ASSERT(distance_transform<std::uint32_t>(shape, opt) == ref);

    RC_TAG(opt.metric.name());
    // Value mode: weights in [0, 1000] or no site, on the int32 engine.
    const auto bounds = detail::envelope_bounds(dom, opt, BigInt(1000));
    RC_PRE(bounds.width == detail::ValueWidth::I32);
    const auto inf = detail::envelope_infinity<std::int32_t>(bounds);
    std::vector<std::int32_t> f0(v.size());
    for (auto& x : f0) x = pick(0, 3) == 0 ? pick(0, 1000) : inf;
    std::vector<std::int32_t> a = f0, b = f0;
    detail::set_envelope_simd(false);
    detail::separable_envelope<std::int32_t>(dom, opt, nullptr, a.data(), inf, nullptr);
    detail::set_envelope_simd(true);
    detail::separable_envelope<std::int32_t>(dom, opt, nullptr, b.data(), inf, nullptr);
    RC_ASSERT(a == b);
  });
}

// The int64 engine's vectorized passes (kernel/transforms/separable_engine.cpp: 8 lines per
// AVX-512 vector, the mask pass widened from the int32 one, l2 and l_p separators by exact
// tests from a floating-point guess; in 3D the first two passes in int32 where the slices'
// bounds allow it, else in int64) give the values of the scalar sweep to the bit: distance
// transforms for l1, l2 .. l9 and linf forced onto the int64 engine (min_engine_bits = 64; l8
// and l9 on lines of 70 points reach 70^9 ~ 2^55), torus axes, and value mode with weights up
// to the largest the int64 engine takes on the domain (need just below 2^63: the sums and
// products of the separators at the width's limit), some at that limit. Oracle: the portable
// loop of the same engine.
TEST(DistanceTransform, VectorizedInt64EnvelopeEqualsPortable) {
  if (!detail::envelope_simd_available()) GTEST_SKIP() << "no AVX-512F on this CPU";
  const AllowSimdAtExit allow;
  test::check_property([] {
    std::mt19937_64 rng(*rc::gen::arbitrary<std::uint64_t>());
    auto pick = [&](std::int64_t lo, std::int64_t hi) {
      return lo + static_cast<std::int64_t>(rng() % static_cast<std::uint64_t>(hi - lo + 1));
    };
    const auto d = static_cast<int>(pick(2, 3));
    std::vector<std::int64_t> ext;
    for (int k = 0; k < d; ++k) ext.push_back(pick(1, d == 2 ? 70 : 30));
    Domain dom(ext);
    TransformOptions opt;
    opt.metric = Metric{static_cast<int>(pick(0, 9))};
    for (int k = 0; k < d; ++k) opt.torus.push_back(pick(0, 2) == 0);
    opt.threads = static_cast<unsigned>(pick(1, 2));
    opt.min_engine_bits = 64;
    RC_PRE(detail::envelope_bounds(dom, opt, BigInt(0)).width == detail::ValueWidth::I64);
    RC_TAG(opt.metric.name());
    std::vector<std::uint8_t> v(static_cast<std::size_t>(dom.size()));
    const auto density = pick(0, 100);
    for (auto& x : v) x = pick(0, 99) < density ? 1 : 0;
    v[rng() % v.size()] = 0;
    Image<std::uint8_t> shape(dom, v);
    detail::set_envelope_simd(false);
    auto ref = distance_transform<std::uint64_t>(shape, opt);
    detail::set_envelope_simd(true);
    RC_ASSERT(distance_transform<std::uint64_t>(shape, opt) == ref);

    // Value mode: the largest weight w with need = 2 (vmax + w + L^p) + 2 L < 2^63 - 1.
    const auto b0 = detail::envelope_bounds(dom, opt, BigInt(0));
    const BigInt limit(std::numeric_limits<std::int64_t>::max());
    const BigInt room = (limit - b0.need) / 2 - 1;
    RC_PRE(room > 0);
    const auto wmax = room.convert_to<std::int64_t>();
    RC_ASSERT(detail::envelope_bounds(dom, opt, BigInt(wmax)).width == detail::ValueWidth::I64);
    RC_ASSERT(detail::envelope_bounds(dom, opt, BigInt(wmax) + 3).width != detail::ValueWidth::I64);
    const auto bounds = detail::envelope_bounds(dom, opt, BigInt(wmax));
    const auto inf = detail::envelope_infinity<std::int64_t>(bounds);
    const auto scale = pick(0, 2); // weights small, anywhere, or near the limit
    std::vector<std::int64_t> f0(v.size());
    for (auto& x : f0) {
      if (pick(0, 3) != 0) {
        x = inf;
      } else if (scale == 0) {
        x = pick(0, 1000);
      } else if (scale == 1) {
        x = pick(0, wmax);
      } else {
        x = wmax - pick(0, 1000);
      }
    }
    std::vector<std::int64_t> a = f0, c = f0;
    detail::set_envelope_simd(false);
    detail::separable_envelope<std::int64_t>(dom, opt, nullptr, a.data(), inf, nullptr);
    detail::set_envelope_simd(true);
    detail::separable_envelope<std::int64_t>(dom, opt, nullptr, c.data(), inf, nullptr);
    RC_ASSERT(a == c);
  });
}

// distance_transform_into's max_value (taken by the last pass, unit by unit, while its lines
// are in cache; by a scan in 1D; by the conversion when the engine is wider than T) is the
// largest value of the output (oracle: std::max_element), on every engine path: vectorized and
// portable, int32 and int64 engines (min_engine_bits), uint32 and uint64 outputs, 1 to 3 axes,
// tori, 1 and 2 threads.
TEST(DistanceTransform, MaxValueIsTheLargestValueWritten) {
  const AllowSimdAtExit allow;
  test::check_property([] {
    std::mt19937 rng(*rc::gen::arbitrary<std::uint32_t>());
    auto pick = [&](int lo, int hi) {
      return lo + static_cast<int>(rng() % static_cast<unsigned>(hi - lo + 1));
    };
    const int d = pick(1, 3);
    std::vector<std::int64_t> ext;
    for (int k = 0; k < d; ++k) ext.push_back(pick(1, d == 1 ? 300 : d == 2 ? 70 : 30));
    const Domain dom(ext);
    TransformOptions opt;
    opt.metric = Metric{pick(0, 3)};
    for (int k = 0; k < d; ++k) opt.torus.push_back(pick(0, 2) == 0);
    opt.threads = static_cast<unsigned>(pick(1, 2));
    opt.min_engine_bits = pick(0, 1) == 0 ? 0 : 64;
    std::vector<std::uint8_t> v(static_cast<std::size_t>(dom.size()));
    const int density = pick(0, 100);
    for (auto& x : v) x = pick(0, 99) < density ? 1 : 0;
    v[rng() % v.size()] = 0;
    detail::set_envelope_simd(pick(0, 1) == 0);
    const auto check = [&]<class T>(std::type_identity<T>) {
      std::vector<T> out(v.size());
      std::uint64_t mx = 12345;
      distance_transform_into<T>(dom, v.data(), 1, opt, out.data(), {}, &mx);
      RC_ASSERT(mx == static_cast<std::uint64_t>(*std::max_element(out.begin(), out.end())));
    };
    if (distance_transform_max_value(dom, opt) <= BigInt(4294967295ULL)) {
      check(std::type_identity<std::uint32_t>{});
    }
    check(std::type_identity<std::uint64_t>{});
  });
}

// Lines of 2^15 points or more (l1 and linf only on the int32 engine): the vectorized envelope
// keeps sites and segment starts in separate tables instead of 16-bit halves of one.
TEST(DistanceTransform, VectorizedEnvelopeOnLongLines) {
  if (!detail::envelope_simd_available()) GTEST_SKIP() << "no AVX-512F on this CPU";
  const AllowSimdAtExit allow;
  Domain dom({40000, 19});
  std::mt19937 rng(11);
  std::vector<std::uint8_t> v(static_cast<std::size_t>(dom.size()));
  for (auto& x : v) x = rng() % 997 == 0 ? 0 : 1;
  Image<std::uint8_t> shape(dom, v);
  for (int p : {1, 0}) {
    for (bool torus : {false, true}) {
      TransformOptions opt;
      opt.metric = Metric{p};
      opt.torus = {torus, false};
      detail::set_envelope_simd(false);
      auto ref = distance_transform<std::uint32_t>(shape, opt);
      detail::set_envelope_simd(true);
      EXPECT_EQ(distance_transform<std::uint32_t>(shape, opt), ref) << p << " " << torus;
    }
  }
}

} // namespace
// The registered property dt.l2.brute_force (zdg check): 2D images of side <= 12 and 3D ones of
// side <= 6, against every pair of points.
TEST(DistanceTransform, RegisteredBruteForcePropertyHolds) {
  test::expect_registered_property("dt.l2.brute_force", IntKind::int64, 300);
}

} // namespace zdg
