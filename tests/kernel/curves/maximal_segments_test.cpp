// Tangential cover and greedy segmentation against brute force (every run of the curve tested
// afresh with the recognizer, itself checked against the exhaustive oracle in
// tests/arith/dss_recognizer_test.cpp), on open paths and closed contours of digital discs;
// the structure of the cover on convex curves; huge translations.
#include <zdg/kernel/curves/maximal_segments.hpp>

#include "tests/support/check_registry.hpp"
#include "tests/support/contours.hpp"
#include "tests/support/dss_oracle.hpp"
#include "tests/support/tower.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace {

using namespace zdg;
using Curve = std::vector<Point2<std::int64_t>>;

// Characteristics of p_i .. p_j (indices modulo n), or nullopt when not a DSS.
std::optional<MaximalSegment> fresh(const Curve& c, std::int64_t i, std::int64_t j,
                                    Connectivity conn) {
  const std::int64_t n = static_cast<std::int64_t>(c.size());
  auto at = [&](std::int64_t k) {
    const auto& p = c[static_cast<std::size_t>(((k % n) + n) % n)];
    return Point2<BigInt>{BigInt(p.x), BigInt(p.y)};
  };
  DssRecognizer<BigInt> rec(at(i), conn);
  for (std::int64_t k = i + 1; k <= j; ++k) {
    if (!rec.extend_front(at(k))) return std::nullopt;
  }
  auto ch = rec.characteristics();
  MaximalSegment s;
  s.begin = static_cast<std::size_t>(((i % n) + n) % n);
  s.end = static_cast<std::size_t>(((j % n) + n) % n);
  s.length = static_cast<std::size_t>(j - i + 1);
  s.a = ch.a.convert_to<std::int64_t>();
  s.b = ch.b.convert_to<std::int64_t>();
  s.omega = ch.omega.convert_to<std::int64_t>();
  s.mu = int_cast<Int128>(ch.mu).value();
  return s;
}

// Brute force: for each start i, the longest DSS i..e(i) (shorter than the curve when closed);
// i..e(i) is maximal when i-1..e(i) is not a DSS (or i = 0 on an open curve).
std::vector<MaximalSegment> brute_force_cover(const Curve& c, bool closed, Connectivity conn) {
  const std::int64_t n = static_cast<std::int64_t>(c.size());
  std::vector<MaximalSegment> out;
  for (std::int64_t i = 0; i < n; ++i) {
    std::int64_t e = i;
    while (e - i + 1 < n && (closed || e + 1 < n) && fresh(c, i, e + 1, conn)) ++e;
    bool left_blocked = closed ? (e - i + 1 == n || !fresh(c, i - 1, e, conn))
                               : (i == 0 || !fresh(c, i - 1, e, conn));
    if (left_blocked) out.push_back(*fresh(c, i, e, conn));
  }
  return out;
}

// Random open path from a cone of steps (same generator idea as the recognizer tests).
Curve random_open_path(Connectivity c, int n) {
  auto steps = test::all_steps(c);
  const int m = static_cast<int>(steps.size());
  Curve p{{0, 0}};
  int k = *rc::gen::inRange(0, m);
  for (int i = 1; i < n; ++i) {
    int j = *rc::gen::weightedElement<int>({{10, 0}, {10, 1}, {3, 2}});
    auto [sx, sy] = steps[static_cast<std::size_t>((k + j) % m)];
    p.push_back({p.back().x + sx, p.back().y + sy});
  }
  return p;
}

// Rotates a closed curve so that it starts at index s.
Curve rotate(const Curve& c, std::size_t s) {
  Curve r(c.begin() + static_cast<long>(s), c.end());
  r.insert(r.end(), c.begin(), c.begin() + static_cast<long>(s));
  return r;
}

void sort_by_begin(std::vector<MaximalSegment>& v) {
  std::sort(v.begin(), v.end(), [](const auto& x, const auto& y) { return x.begin < y.begin; });
}

TEST(MaximalSegments, OpenPathsAgreeWithBruteForce) {
  test::check_property([] {
    Connectivity c = *rc::gen::element(Connectivity::four, Connectivity::eight);
    Curve p = random_open_path(c, *rc::gen::inRange(1, 40));
    auto got = maximal_segments<Int64>(p, false, c);
    auto want = brute_force_cover(p, false, c);
    RC_ASSERT(got == want);
    // Every tower type computes the same cover; the exact entry point is served by Int64.
    RC_ASSERT(maximal_segments<Int128>(p, false, c) == want);
    RC_ASSERT(maximal_segments<BigInt>(p, false, c) == want);
    auto e = maximal_segments_exact(p, false, c);
    RC_ASSERT(e.value == want);
    RC_ASSERT(e.served == IntKind::int64);
    RC_ASSERT(greedy_segmentation<BigInt>(p, false, c) == greedy_segmentation<Int64>(p, false, c));
    RC_ASSERT(greedy_segmentation_exact(p, false, c).value ==
              greedy_segmentation<Int64>(p, false, c));
  });
}

// Closed contours of digital discs (random centre, radius and starting point).
TEST(MaximalSegments, ClosedDiscContoursAgreeWithBruteForce) {
  test::check_property([] {
    std::int64_t r2 = *rc::gen::inRange<std::int64_t>(1, 200);
    Curve c = test::disc_contour(*rc::gen::inRange(-5, 6), *rc::gen::inRange(-5, 6), r2);
    c = rotate(c, static_cast<std::size_t>(*rc::gen::inRange<std::size_t>(0, c.size())));
    auto got = maximal_segments<Int64>(c, true);
    auto want = brute_force_cover(c, true, Connectivity::four);
    sort_by_begin(got);
    RC_ASSERT(got == want);
  });
}

// Closed 8-connected curves: disc contours with every other staircase corner cut (the points
// whose neighbours are diagonal), so that both axis and diagonal steps occur.
TEST(MaximalSegments, Closed8ConnectedCurvesAgreeWithBruteForce) {
  test::check_property([] {
    std::int64_t r2 = *rc::gen::inRange<std::int64_t>(2, 200);
    Curve c4 = test::disc_contour(0, 0, r2), c;
    const std::size_t n4 = c4.size();
    bool dropped = true; // never drop p_0
    for (std::size_t k = 0; k < n4; ++k) {
      const auto &p = c4[(k + n4 - 1) % n4], &q = c4[(k + 1) % n4];
      bool diagonal = std::abs(q.x - p.x) == 1 && std::abs(q.y - p.y) == 1;
      if (!dropped && diagonal && k + 1 < n4) {
        dropped = true;
        continue;
      }
      dropped = false;
      c.push_back(c4[k]);
    }
    c = rotate(c, static_cast<std::size_t>(*rc::gen::inRange<std::size_t>(0, c.size())));
    auto got = maximal_segments<Int64>(c, true, Connectivity::eight);
    auto want = brute_force_cover(c, true, Connectivity::eight);
    sort_by_begin(got);
    RC_ASSERT(got == want);
  });
}

// Convexity: on the counter-clockwise contour of a convex digital set the directions of the
// maximal segments turn monotonically (Doerksen-Lachaud-de Vieilleville; a curve is convex iff
// its maximal segments' slopes are monotone), every point is covered, and begins and ends
// increase strictly around the curve (one wrap each, the first segment goes through p_0).
TEST(MaximalSegments, CoverStructureOnConvexContours) {
  test::check_property([] {
    std::int64_t r2 = *rc::gen::inRange<std::int64_t>(2, 5000);
    Curve c = test::disc_contour(0, 0, r2);
    auto segs = maximal_segments<Int64>(c, true);
    const std::size_t n = c.size(), m = segs.size();
    RC_ASSERT(m >= 4u);
    std::vector<int> covered(n, 0);
    int begin_wraps = 0, end_wraps = 0;
    for (std::size_t k = 0; k < m; ++k) {
      const auto& s = segs[k];
      const auto& t = segs[(k + 1) % m];
      for (std::size_t q = 0; q < s.length; ++q) covered[(s.begin + q) % n] = 1;
      RC_ASSERT(std::int64_t{s.b} * t.a - std::int64_t{s.a} * t.b >= 0);
      if (t.begin <= s.begin) ++begin_wraps;
      if (t.end <= s.end) ++end_wraps;
      // omega of a standard DSS; mu tight on the segment
      RC_ASSERT(s.omega == std::abs(s.a) + std::abs(s.b));
    }
    for (int v : covered) RC_ASSERT(v == 1);
    RC_ASSERT(begin_wraps == 1 && end_wraps == 1);
    RC_ASSERT(segs[0].begin + segs[0].length > n || segs[0].begin == 0);
  });
}

TEST(MaximalSegments, GreedySegmentationIsAChainOfLongestDss) {
  test::check_property([] {
    bool closed = *rc::gen::arbitrary<bool>();
    Connectivity conn = Connectivity::four;
    Curve c =
        closed ? test::disc_contour(0, 0, *rc::gen::inRange<std::int64_t>(1, 300))
               : random_open_path(conn = *rc::gen::element(Connectivity::four, Connectivity::eight),
                                  *rc::gen::inRange(1, 40));
    auto segs = greedy_segmentation<Int64>(c, closed, conn);
    const std::int64_t n = static_cast<std::int64_t>(c.size());
    std::int64_t i = 0;
    for (const auto& s : segs) {
      RC_ASSERT(static_cast<std::int64_t>(s.begin) == i % n);
      std::int64_t j = i + static_cast<std::int64_t>(s.length) - 1;
      RC_ASSERT(fresh(c, i, j, conn) == std::optional<MaximalSegment>(s));
      std::int64_t last = closed ? n : n - 1;
      if (j < last) RC_ASSERT(!fresh(c, i, j + 1, conn));
      i = j;
    }
    RC_ASSERT(i == (closed ? n : n - 1));
  });
}

// Translating the curve by t leaves begin, end, a, b, omega and shifts mu by a t.x - b t.y,
// for offsets up to 2^62 (mu then needs 128 bits).
TEST(MaximalSegments, TranslationByHugeOffsets) {
  test::check_property([] {
    Curve c = test::disc_contour(0, 0, *rc::gen::inRange<std::int64_t>(1, 2000));
    std::int64_t tx = *test::int64_in(-(std::int64_t{1} << 62), std::int64_t{1} << 62);
    std::int64_t ty = *test::int64_in(-(std::int64_t{1} << 62), std::int64_t{1} << 62);
    Curve t = c;
    for (auto& p : t) {
      p.x += tx;
      p.y += ty;
    }
    auto s0 = maximal_segments<Int64>(c, true), s1 = maximal_segments<Int64>(t, true);
    RC_ASSERT(s0.size() == s1.size());
    for (std::size_t k = 0; k < s0.size(); ++k) {
      auto e = s0[k];
      e.mu += int128_t(e.a) * tx - int128_t(e.b) * ty;
      RC_ASSERT(s1[k] == e);
    }
  });
}

TEST(MaximalSegments, WorkedExamples) {
  // The boundary of a 3x2 rectangle of pointels, codes 0001122233: the maximal segments are
  // the balanced factors 233, 330, 3000, 0001, 011, 112, 1222, 2223; the first one goes
  // through p_0 (found by extending backwards first).
  Curve rect{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
  auto segs = maximal_segments<Int64>(rect, true);
  std::vector<std::pair<std::size_t, std::size_t>> got,
      want{{7, 4}, {8, 4}, {9, 5}, {0, 5}, {2, 4}, {3, 4}, {4, 5}, {5, 5}};
  for (const auto& s : segs) got.emplace_back(s.begin, s.length);
  EXPECT_EQ(got, want);
  EXPECT_EQ(segs[0], (MaximalSegment{7, 0, 4, -2, -1, 0, 3}));
  auto one = maximal_segments<Int64>(Curve{{4, 7}}, false);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0], (MaximalSegment{0, 0, 1, 0, 1, -7, 1}));
  EXPECT_TRUE(maximal_segments<Int64>(Curve{}, true).empty());
}

TEST(MaximalSegments, RejectsCurvesThatAreNotPaths) {
  EXPECT_THROW(maximal_segments<Int64>(Curve{{0, 0}, {2, 0}}, false), InvalidArgument);
  EXPECT_THROW(maximal_segments<Int64>(Curve{{0, 0}, {1, 0}, {2, 0}}, true), InvalidArgument);
  EXPECT_THROW(maximal_segments<Int64>(Curve{{0, 0}, {1, 1}}, false, Connectivity::four),
               InvalidArgument);
  EXPECT_THROW(greedy_segmentation<Int64>(Curve{{0, 0}, {0, 0}}, false), InvalidArgument);
}

// The registered property dss.cover.maximal (zdg check): open paths of <= 12 points against the
// longest DSS from every point by brute force, on every integer type of the tower.
template <class I>
class MaximalSegmentsTyped : public ::testing::Test {};
TYPED_TEST_SUITE(MaximalSegmentsTyped, zdg::test::TowerTypes, zdg::test::TowerNames);

TYPED_TEST(MaximalSegmentsTyped, RegisteredCoverPropertyHolds) {
  zdg::test::expect_registered_property("dss.cover.maximal", zdg::int_kind<TypeParam>(), 200);
}

} // namespace
