// Online DSS recognition (Debled-Rennesson and Reveilles 1995) against the brute-force oracle
// of tests/support/dss_oracle.hpp, on every tower type: front and back extension, retraction
// at both ends, translation invariance (huge offsets), octant symmetries, escalation.
#include <zdg/arith/dss_recognizer.hpp>

#include <zdg/arith/christoffel.hpp>

#include "tests/support/check_registry.hpp"
#include "tests/support/dss_oracle.hpp"
#include "tests/support/tower.hpp"

#include <cstdint>
#include <limits>
#include <numeric>
#include <vector>

namespace {

using namespace zdg;
using test::check_property;
using BigPath = std::vector<Point2<BigInt>>;

struct RandomPath {
  Connectivity c;
  BigPath pts;
};

// Paths whose steps come from a cone of two neighbouring steps (plus, rarely, a third one):
// many are DSS, many are not.
RandomPath random_path(std::int64_t offset_x, std::int64_t offset_y, int max_len = 14) {
  Connectivity c = *rc::gen::element(Connectivity::four, Connectivity::eight);
  auto steps = test::all_steps(c);
  const int m = static_cast<int>(steps.size());
  int n = *rc::gen::inRange(1, max_len + 1);
  int k = *rc::gen::inRange(0, m);
  RandomPath p{c, {}};
  BigInt x(offset_x), y(offset_y);
  p.pts.push_back({x, y});
  for (int i = 1; i < n; ++i) {
    int j = *rc::gen::weightedElement<int>({{12, 0}, {12, 1}, {1, 2}});
    auto [sx, sy] = steps[static_cast<std::size_t>((k + j) % m)];
    x += sx;
    y += sy;
    p.pts.push_back({x, y});
  }
  return p;
}

// A piece of a random line of small period: always a DSS.
RandomPath random_dss(std::int64_t offset_x, std::int64_t offset_y) {
  Connectivity c = *rc::gen::element(Connectivity::four, Connectivity::eight);
  long a = *rc::gen::inRange(-9, 10), b = *rc::gen::inRange(-9, 10);
  if (std::gcd(a, b) != 1) {
    a = 1;
    b = *rc::gen::element(-1L, 1L) * 5;
  }
  DslKind kind = c == Connectivity::eight ? DslKind::naive : DslKind::standard;
  BigInt mu(*rc::gen::inRange(-20, 21));
  DigitalStraightLine<BigInt> line(BigInt(a), BigInt(b), mu, kind);
  auto start = line.point_with_remainder(mu + BigInt(*rc::gen::inRange(0, 9)) % line.omega());
  std::size_t n = static_cast<std::size_t>(*rc::gen::inRange(1, 40));
  auto pts = line.points(start, n);
  for (auto& p : pts) {
    p.x += offset_x;
    p.y += offset_y;
  }
  return {c, pts};
}

template <TowerInt I>
Point2<I> to(const Point2<BigInt>& p) {
  return {int_cast<I>(p.x), int_cast<I>(p.y)};
}

template <TowerInt I>
void expect_matches(const DssRecognizer<I>& rec, const BigPath& pts, Connectivity c) {
  auto o = test::oracle_dss(pts, c);
  RC_ASSERT(o.has_value());
  RC_ASSERT(o->candidates == 1); // the minimal line is unique once oriented
  RC_ASSERT(o->tight);           // and mu is determined
  auto ch = rec.characteristics();
  RC_ASSERT(ch == (DssCharacteristics{o->a, o->b, o->mu, o->omega}));
  RC_ASSERT(rec.size() == pts.size());
}

std::int64_t offset() {
  return *rc::gen::oneOf(rc::gen::inRange<std::int64_t>(-50, 51),
                         test::int64_in(-(std::int64_t{1} << 62), std::int64_t{1} << 62));
}

template <class I>
class DssRecognizerTest : public ::testing::Test {};
TYPED_TEST_SUITE(DssRecognizerTest, zdg::test::TowerTypes, zdg::test::TowerNames);

// Oracle: every prefix is a DSS exactly when brute force finds a line, with the same minimal
// characteristics; the first failure is the longest prefix and leaves the state unchanged.
TYPED_TEST(DssRecognizerTest, FrontExtensionAgreesWithBruteForce) {
  using I = TypeParam;
  check_property([] {
    auto p = *rc::gen::weightedElement<int>({{3, 0}, {1, 1}}) == 0 ? random_path(offset(), offset())
                                                                   : random_dss(offset(), offset());
    DssRecognizer<I> rec(to<I>(p.pts[0]), p.c);
    BigPath prefix{p.pts[0]};
    expect_matches(rec, prefix, p.c);
    for (std::size_t k = 1; k < p.pts.size(); ++k) {
      prefix.push_back(p.pts[k]);
      auto before = rec.characteristics();
      bool ok = rec.extend_front(to<I>(p.pts[k]));
      RC_ASSERT(ok == test::oracle_dss(prefix, p.c).has_value());
      if (!ok) {
        RC_ASSERT(rec.characteristics() == before);
        RC_ASSERT(rec.size() == k);
        break;
      }
      expect_matches(rec, prefix, p.c);
    }
  });
}

// Oracle again, feeding the path from its last point backwards with extend_back.
TYPED_TEST(DssRecognizerTest, BackExtensionAgreesWithBruteForce) {
  using I = TypeParam;
  check_property([] {
    auto p = *rc::gen::weightedElement<int>({{3, 0}, {1, 1}}) == 0 ? random_path(offset(), offset())
                                                                   : random_dss(offset(), offset());
    DssRecognizer<I> rec(to<I>(p.pts.back()), p.c);
    BigPath suffix{p.pts.back()};
    for (std::size_t k = p.pts.size() - 1; k-- > 0;) {
      suffix.insert(suffix.begin(), p.pts[k]);
      bool ok = rec.extend_back(to<I>(p.pts[k]));
      RC_ASSERT(ok == test::oracle_dss(suffix, p.c).has_value());
      if (!ok) break;
      expect_matches(rec, suffix, p.c);
      RC_ASSERT(rec.back() == to<I>(p.pts[k]));
    }
  });
}

// Retraction: removing points at either end of a DSS gives the characteristics of what is
// left (oracle), down to one point; extending then retracting restores the state.
TYPED_TEST(DssRecognizerTest, RetractionAgreesWithBruteForce) {
  using I = TypeParam;
  check_property([] {
    auto p = random_dss(offset(), offset());
    DssRecognizer<I> rec(to<I>(p.pts[0]), p.c);
    for (std::size_t k = 1; k < p.pts.size(); ++k) RC_ASSERT(rec.extend_front(to<I>(p.pts[k])));
    std::size_t lo = 0, hi = p.pts.size(); // rec holds [lo, hi)
    while (hi - lo > 1) {
      bool back = *rc::gen::arbitrary<bool>();
      if (back) {
        RC_ASSERT(rec.retract_back());
        ++lo;
      } else {
        RC_ASSERT(rec.retract_front());
        --hi;
      }
      BigPath part(p.pts.begin() + static_cast<long>(lo), p.pts.begin() + static_cast<long>(hi));
      expect_matches(rec, part, p.c);
      RC_ASSERT(rec.back() == to<I>(p.pts[lo]));
      RC_ASSERT(rec.front() == to<I>(p.pts[hi - 1]));
    }
    RC_ASSERT(!rec.retract_back());
    RC_ASSERT(!rec.retract_front());
  });
}

// A window sliding along an arbitrary path, as in the tangential cover: extend at the front
// while possible, else retract at the back; every state matches the oracle.
TYPED_TEST(DssRecognizerTest, SlidingWindowAgreesWithBruteForce) {
  using I = TypeParam;
  check_property([] {
    auto p = random_path(offset(), offset(), 30);
    DssRecognizer<I> rec(to<I>(p.pts[0]), p.c);
    std::size_t lo = 0, hi = 1;
    while (hi < p.pts.size()) {
      if (rec.extend_front(to<I>(p.pts[hi]))) {
        ++hi;
      } else {
        RC_ASSERT(rec.retract_back());
        ++lo;
      }
      BigPath part(p.pts.begin() + static_cast<long>(lo), p.pts.begin() + static_cast<long>(hi));
      expect_matches(rec, part, p.c);
    }
  });
}

TYPED_TEST(DssRecognizerTest, ExtendThenRetractRestoresTheState) {
  using I = TypeParam;
  check_property([] {
    auto p = random_dss(offset(), offset());
    RC_PRE(p.pts.size() >= 3);
    DssRecognizer<I> rec(to<I>(p.pts[1]), p.c);
    for (std::size_t k = 2; k + 1 < p.pts.size(); ++k) RC_ASSERT(rec.extend_front(to<I>(p.pts[k])));
    auto ch = rec.characteristics();
    auto leaning =
        std::vector{rec.first_upper(), rec.last_upper(), rec.first_lower(), rec.last_lower()};
    RC_ASSERT(rec.extend_front(to<I>(p.pts.back())));
    RC_ASSERT(rec.retract_front());
    RC_ASSERT(rec.characteristics() == ch);
    RC_ASSERT(rec.extend_back(to<I>(p.pts[0])));
    RC_ASSERT(rec.retract_back());
    RC_ASSERT(rec.characteristics() == ch);
    auto after =
        std::vector{rec.first_upper(), rec.last_upper(), rec.first_lower(), rec.last_lower()};
    RC_ASSERT(after == leaning);
  });
}

// Translating the path by t changes mu into mu + a t.x - b t.y and nothing else.
TYPED_TEST(DssRecognizerTest, CharacteristicsAreTranslationInvariant) {
  using I = TypeParam;
  check_property([] {
    auto p = random_dss(0, 0);
    RC_PRE(p.pts.size() >= 2);
    std::int64_t tx = offset(), ty = offset();
    DssRecognizer<I> r0(to<I>(p.pts[0]), p.c), r1(to<I>({p.pts[0].x + tx, p.pts[0].y + ty}), p.c);
    for (std::size_t k = 1; k < p.pts.size(); ++k) {
      RC_ASSERT(r0.extend_front(to<I>(p.pts[k])));
      RC_ASSERT(r1.extend_front(to<I>({p.pts[k].x + tx, p.pts[k].y + ty})));
    }
    auto c0 = r0.characteristics(), c1 = r1.characteristics();
    RC_ASSERT(c1.a == c0.a && c1.b == c0.b && c1.omega == c0.omega);
    RC_ASSERT(c1.mu == c0.mu + c0.a * tx - c0.b * ty);
  });
}

// The 8 symmetries M of the square map D(a, b, mu) to the line of normal M (a, -b) and the same
// mu for rotations; a reflection reverses the orientation of the normal relative to the path,
// so the oriented normal is -M (a, -b) and mu becomes -mu - omega + 1.
TYPED_TEST(DssRecognizerTest, CharacteristicsFollowTheOctantSymmetries) {
  using I = TypeParam;
  check_property([] {
    auto p = random_dss(offset() / 4, offset() / 4);
    RC_PRE(p.pts.size() >= 2);
    DssRecognizer<I> r0(to<I>(p.pts[0]), p.c);
    for (std::size_t k = 1; k < p.pts.size(); ++k) RC_ASSERT(r0.extend_front(to<I>(p.pts[k])));
    auto c0 = r0.characteristics();
    for (int sym = 0; sym < 8; ++sym) {
      auto map = [sym](BigInt x, BigInt y) {
        if (sym & 4) std::swap(x, y);
        if (sym & 1) x = -x;
        if (sym & 2) y = -y;
        return Point2<BigInt>{x, y};
      };
      DssRecognizer<I> r(to<I>(map(p.pts[0].x, p.pts[0].y)), p.c);
      for (std::size_t k = 1; k < p.pts.size(); ++k) {
        RC_ASSERT(r.extend_front(to<I>(map(p.pts[k].x, p.pts[k].y))));
      }
      auto c = r.characteristics();
      auto n = map(c0.a, BigInt(-c0.b)); // the normal (a, -b) transforms like a point
      bool reflection = (((sym >> 2) ^ (sym >> 1) ^ sym) & 1) != 0;
      if (reflection) {
        RC_ASSERT(c.a == -n.x && c.b == n.y && c.mu == -c0.mu - c0.omega + 1);
      } else {
        RC_ASSERT(c.a == n.x && c.b == -n.y && c.mu == c0.mu);
      }
      RC_ASSERT(c.omega == c0.omega);
    }
  });
}

TEST(DssRecognizer, WorkedExampleSlopeThreeSevenths) {
  // y = floor(3 x / 7) for x = 0..19: the naive line 0 <= 3x - 7y < 7.
  std::vector<Point2<std::int64_t>> pts;
  for (std::int64_t x = 0; x < 20; ++x) pts.push_back({x, (3 * x) / 7});
  auto r = recognize_dss_exact(pts, Connectivity::eight).value;
  EXPECT_TRUE(r.is_dss);
  EXPECT_EQ(r.characteristics, (DssCharacteristics{3, 7, 0, 7}));
  // One more point above the line breaks it after 20 points.
  pts.push_back({20, 9});
  r = recognize_dss_exact(pts, Connectivity::eight).value;
  EXPECT_FALSE(r.is_dss);
  EXPECT_EQ(r.longest_prefix, 20u);
}

TEST(DssRecognizer, StandardStaircase) {
  // Two periods of the lower Christoffel path of 2/5: the standard line 0 <= 2x - 5y < 7.
  std::vector<Point2<std::int64_t>> pts{{0, 0}};
  for (char ch :
       lower_christoffel_word(Int64(2), Int64(5)) + lower_christoffel_word(Int64(2), Int64(5))) {
    auto p = pts.back();
    pts.push_back(ch == '0' ? Point2<std::int64_t>{p.x + 1, p.y}
                            : Point2<std::int64_t>{p.x, p.y + 1});
  }
  EXPECT_EQ(path_connectivity(pts), Connectivity::four);
  auto r = recognize_dss_exact(pts, Connectivity::four).value;
  EXPECT_TRUE(r.is_dss);
  EXPECT_EQ(r.characteristics, (DssCharacteristics{2, 5, 0, 7}));
}

TEST(DssRecognizer, NonAdjacentPointsAreRejected) {
  DssRecognizer<Int64> rec({0, 0});
  EXPECT_THROW(rec.extend_front({2, 0}), InvalidArgument);
  EXPECT_THROW(rec.extend_front({0, 0}), InvalidArgument);
  DssRecognizer<Int64> four({0, 0}, Connectivity::four);
  EXPECT_THROW(four.extend_front({1, 1}), InvalidArgument);
  EXPECT_EQ(four.size(), 1u);
  std::vector<Point2<std::int64_t>> bad{{0, 0}, {1, 0}, {3, 0}};
  EXPECT_THROW(path_connectivity(bad), InvalidArgument);
}

// Coordinates near 2^62 stay on int64 (local coordinates); mu itself needs 128 bits.
TEST(DssRecognizer, HugeCoordinatesServeOnInt64) {
  const std::int64_t big = std::int64_t{1} << 62;
  std::vector<Point2<std::int64_t>> pts;
  for (std::int64_t x = 0; x < 50; ++x) pts.push_back({big + x, big - 3 + (5 * x) / 11});
  auto e = recognize_dss_exact(pts, Connectivity::eight);
  const auto& r = e.value;
  EXPECT_TRUE(r.is_dss);
  EXPECT_EQ(e.served, IntKind::int64);
  EXPECT_EQ(r.characteristics.a, 5);
  EXPECT_EQ(r.characteristics.b, 11);
  // 5 (big + x) - 11 (big - 3 + y) = 5x - 11y - 6 big + 33, and min over the points of
  // 5x - 11y is 0.
  EXPECT_EQ(r.characteristics.mu, BigInt(-6) * BigInt(big) + 33);
  // Points beyond int64 escalate.
  std::vector<Point2<BigInt>> huge;
  BigInt h = BigInt(1) << 100;
  for (int x = 0; x < 10; ++x) huge.push_back({h + x, -h + x / 3});
  auto rh = recognize_dss_exact(huge, Connectivity::eight);
  EXPECT_TRUE(rh.value.is_dss);
  EXPECT_NE(rh.served, IntKind::int64);
  EXPECT_EQ(rh.value.characteristics, (DssCharacteristics{1, 3, BigInt(h - 3 * (-h)), 3}));
  // recognize_dss<I> computes on I: the points do not fit int64, the BigInt run agrees.
  const std::vector<Point2<Int64>> none;
  EXPECT_THROW(recognize_dss<Int64>(std::span<const Point2<Int64>>(none), Connectivity::eight),
               InvalidArgument);
  EXPECT_EQ(recognize_dss<BigInt>(std::span<const Point2<BigInt>>(huge), Connectivity::eight)
                .characteristics,
            rh.value.characteristics);
}

// recognize_dss<I> on each tower type agrees with the escalating entry point (the same
// minimal characteristics whichever type computes them).
TYPED_TEST(DssRecognizerTest, RecognizeOnEveryTypeAgreesWithExact) {
  using I = TypeParam;
  std::vector<Point2<std::int64_t>> pts;
  for (std::int64_t x = 0; x < 30; ++x) pts.push_back({x - 7, (5 * x) / 13 + 2});
  std::vector<Point2<I>> q;
  for (const auto& p : pts) q.push_back({I(p.x), I(p.y)});
  auto r = recognize_dss<I>(std::span<const Point2<I>>(q), Connectivity::eight);
  auto e = recognize_dss_exact(pts, Connectivity::eight);
  EXPECT_EQ(e.served, IntKind::int64);
  EXPECT_TRUE(r.is_dss);
  EXPECT_EQ(r.characteristics, e.value.characteristics);
}

// The registered property dss.recognize.minimal (zdg check): 4- and 8-connected paths in every
// octant, far from the origin (up to 64, 128, 256-bit coordinates), against the brute-force
// minimal line.
TYPED_TEST(DssRecognizerTest, RegisteredMinimalCharacteristicsHold) {
  test::expect_registered_property("dss.recognize.minimal", int_kind<TypeParam>(), 300);
}

} // namespace
