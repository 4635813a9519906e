// The scale of the parameter-free integral invariants (DGCI 2014):
// - 2D: the mean maximal-segment length of a digital disc contour equals the brute-force one
//   (every run of the closed pointel curve tested as a standard DSS by the exhaustive oracle;
//   the maximal segments are the runs [i, i + L(i) - 1], L(i) the longest DSS from i, with
//   L(i - 1) <= L(i)); the segments themselves are the same (begin, length) pairs;
// - 3D: the mean over the slice contours of a digital ball, found by tracking from the
//   surfels, equals the mean over the contours of every section x_a = c of the box, found by
//   scanning all rows (each section contour once), with their tangential covers;
// - invariance: the 2D mean is invariant under the 8 symmetries of Z^2 and the 3D mean under
//   the 48 of Z^3 (off-centre discs and balls, so that the symmetries move them);
// - R = k l^2 h; bad input (no segment, k or h not positive) is refused.
#include <zdg/arith/error.hpp>
#include <zdg/estimators/ii_auto_radius.hpp>
#include <zdg/kernel/curves/maximal_segments.hpp>

#include "tests/support/dss_oracle.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

namespace {

using namespace zdg;

// The disc (q x - a)^2 + (q y - b)^2 <= r2 after the lattice symmetry (swap, sx, sy).
class Disc final : public GaussDigitization2 {
public:
  Disc(std::int64_t q, std::int64_t a, std::int64_t b, std::int64_t r2, int sym = 0)
      : GaussDigitization2(Box2{{-200, -200}, {200, 200}}), q_(q), a_(a), b_(b), r2_(r2),
        sym_(sym) {}

protected:
  bool inside(const Pixel& z) const override {
    // Undo the symmetry: sym bit 0 negates x, bit 1 negates y, bit 2 swaps.
    Pixel p = z;
    if ((sym_ & 4) != 0) std::swap(p.x, p.y);
    if ((sym_ & 1) != 0) p.x = -p.x;
    if ((sym_ & 2) != 0) p.y = -p.y;
    const auto dx = q_ * p.x - a_, dy = q_ * p.y - b_;
    return dx * dx + dy * dy <= r2_;
  }

private:
  std::int64_t q_, a_, b_, r2_;
  int sym_;
};

bool is_standard_dss(const std::vector<Pixel>& pts, std::size_t begin, std::size_t len) {
  std::vector<Point2<BigInt>> run;
  for (std::size_t k = 0; k < len; ++k) {
    const auto& p = pts[(begin + k) % pts.size()];
    run.push_back({BigInt(p.x), BigInt(p.y)});
  }
  return test::oracle_dss(run, Connectivity::four).has_value();
}

// (begin, number of points) of every maximal segment of the closed curve, by brute force.
std::set<std::pair<std::size_t, std::size_t>>
brute_maximal_segments(const std::vector<Pixel>& pts) {
  const std::size_t n = pts.size();
  std::vector<std::size_t> longest(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t len = 1;
    while (len < n && is_standard_dss(pts, i, len + 1)) ++len;
    longest[i] = len;
  }
  std::set<std::pair<std::size_t, std::size_t>> out;
  for (std::size_t i = 0; i < n; ++i) {
    if (longest[(i + n - 1) % n] <= longest[i]) out.insert({i, longest[i]});
  }
  return out;
}

struct BruteSum {
  std::int64_t total = 0, segments = 0;
  void add(const DigitalContour& c) {
    for (const auto& [b, len] : brute_maximal_segments(c.pointels())) {
      total += static_cast<std::int64_t>(len) - 1;
      ++segments;
    }
  }
  // The same sums from the tangential cover (kernel/curves/maximal_segments.hpp, checked against
  // the brute force above).
  void add_cover(const DigitalContour& c) {
    for (const auto& s : maximal_segments_exact(c.pointels(), true, Connectivity::four).value) {
      total += static_cast<std::int64_t>(s.length) - 1;
      ++segments;
    }
  }
};

DigitalContour disc_contour(const GaussDigitization2& set) {
  std::vector<std::int64_t> rows;
  for (std::int64_t y = -200; y <= 200; ++y) rows.push_back(y);
  auto cs = digital_contours(set, rows, {});
  RC_ASSERT(cs.size() == 1u);
  return cs.front();
}

RC_GTEST_PROP(IIAutoRadius, DiscMeanLengthEqualsBruteForce, ()) {
  const std::int64_t q = *rc::gen::inRange<std::int64_t>(1, 3);
  const std::int64_t a = *rc::gen::inRange<std::int64_t>(-q, q + 1);
  const std::int64_t b = *rc::gen::inRange<std::int64_t>(-q, q + 1);
  const std::int64_t r = *rc::gen::inRange<std::int64_t>(3, 10);
  const std::int64_t r2 = q * q * r * r + *rc::gen::inRange<std::int64_t>(0, q * q);
  const Disc disc(q, a, b, r2);
  const DigitalContour c = disc_contour(disc);
  const std::vector<DigitalContour> cs{c};
  const auto got = mean_maximal_segment_length(cs);
  BruteSum brute;
  brute.add(c);
  RC_ASSERT(got.contours == 1u);
  RC_ASSERT(static_cast<std::int64_t>(got.segments) == brute.segments);
  RC_ASSERT(got.mean == static_cast<double>(brute.total) / static_cast<double>(brute.segments));
  // The segments themselves.
  std::set<std::pair<std::size_t, std::size_t>> fast;
  for (const auto& s : maximal_segments_exact(c.pointels(), true, Connectivity::four).value) {
    fast.insert({s.begin, s.length});
  }
  RC_ASSERT(fast == brute_maximal_segments(c.pointels()));
}

TEST(IIAutoRadius, DiscMeanLengthIsInvariantUnderTheEightSymmetries) {
  const std::vector<DigitalContour> ref{disc_contour(Disc(3, 1, -2, 9 * 40 * 40 + 5))};
  const auto m0 = mean_maximal_segment_length(ref);
  for (int sym = 1; sym < 8; ++sym) {
    const std::vector<DigitalContour> cs{disc_contour(Disc(3, 1, -2, 9 * 40 * 40 + 5, sym))};
    const auto m = mean_maximal_segment_length(cs);
    EXPECT_EQ(m.segments, m0.segments) << sym;
    EXPECT_DOUBLE_EQ(m.mean, m0.mean) << sym;
  }
}

// The ball |q z - c|^2 <= r2 after a symmetry of Z^3 (permutation perm, then signs).
VoxelPredicate ball(std::int64_t q, Voxel c, std::int64_t r2, std::array<int, 3> perm = {0, 1, 2},
                    std::array<int, 3> sign = {1, 1, 1}) {
  return [=](const Voxel& z) {
    // z = S P p: p_{perm[i]} = sign[i] z_i.
    Voxel p{0, 0, 0};
    for (int i = 0; i < 3; ++i) coord(p, perm[std::size_t(i)]) = sign[std::size_t(i)] * coord(z, i);
    const auto dx = q * p.x - c.x, dy = q * p.y - c.y, dz = q * p.z - c.z;
    return dx * dx + dy * dy + dz * dz <= r2;
  };
}

// A section of the box as a 2D set, axes (a + 1, a + 2).
class Section final : public GaussDigitization2 {
public:
  Section(const VoxelPredicate& inside, const VoxelBox& box, int a, std::int64_t level)
      : GaussDigitization2(Box2{{coord(box.lo, (a + 1) % 3), coord(box.lo, (a + 2) % 3)},
                                {coord(box.hi, (a + 1) % 3), coord(box.hi, (a + 2) % 3)}}),
        inside_(inside), a_(a), level_(level) {}

protected:
  bool inside(const Pixel& z) const override {
    Voxel v{0, 0, 0};
    coord(v, a_) = level_;
    coord(v, (a_ + 1) % 3) = z.x;
    coord(v, (a_ + 2) % 3) = z.y;
    return inside_(v);
  }

private:
  const VoxelPredicate& inside_;
  int a_;
  std::int64_t level_;
};

TEST(IIAutoRadius, BallSliceMeanLengthEqualsTheSectionsBruteForce) {
  for (const auto& [q, c, r2] : {std::tuple<std::int64_t, Voxel, std::int64_t>{1, {0, 0, 0}, 30},
                                 {2, {1, -1, 1}, 4 * 36 + 3},
                                 {3, {1, 2, -1}, 9 * 49 + 7}}) {
    const VoxelPredicate inside = ball(q, c, r2);
    const VoxelBox box{{-12, -12, -12}, {12, 12, 12}};
    const auto surfels = boundary_surfels(inside, box);
    const auto got = mean_slice_maximal_segment_length(inside, box, surfels);
    BruteSum brute;
    std::size_t contours = 0;
    for (int a = 0; a < 3; ++a) {
      for (std::int64_t level = -12; level <= 12; ++level) {
        Section s(inside, box, a, level);
        std::vector<std::int64_t> rows;
        for (std::int64_t y = -12; y <= 12; ++y) rows.push_back(y);
        for (const auto& contour : digital_contours(s, rows, {})) {
          brute.add_cover(contour);
          ++contours;
        }
      }
    }
    EXPECT_EQ(got.contours, contours) << r2;
    EXPECT_EQ(static_cast<std::int64_t>(got.segments), brute.segments) << r2;
    EXPECT_EQ(got.mean, static_cast<double>(brute.total) / static_cast<double>(brute.segments));
  }
}

TEST(IIAutoRadius, BallSliceMeanLengthIsInvariantUnderThe48Symmetries) {
  const VoxelBox box{{-20, -20, -20}, {20, 20, 20}};
  const Voxel c{2, -1, 3};
  const std::int64_t q = 3, r2 = 9 * 15 * 15 + 4;
  const auto inside0 = ball(q, c, r2);
  const auto m0 = mean_slice_maximal_segment_length(inside0, box, boundary_surfels(inside0, box));
  std::array<int, 3> perm = {0, 1, 2};
  int count = 0;
  do {
    for (int signs = 0; signs < 8; ++signs) {
      const std::array<int, 3> sign = {(signs & 1) ? -1 : 1, (signs & 2) ? -1 : 1,
                                       (signs & 4) ? -1 : 1};
      const auto inside = ball(q, c, r2, perm, sign);
      const auto m = mean_slice_maximal_segment_length(inside, box, boundary_surfels(inside, box));
      EXPECT_EQ(m.segments, m0.segments);
      EXPECT_DOUBLE_EQ(m.mean, m0.mean);
      ++count;
    }
  } while (std::next_permutation(perm.begin(), perm.end()));
  EXPECT_EQ(count, 48);
}

TEST(IIAutoRadius, RadiusLawAndBadInput) {
  MaximalSegmentLengths l;
  l.mean = 6;
  l.segments = 10;
  EXPECT_DOUBLE_EQ(ii_auto_radius(l, 0.5, 0.01), 0.5 * 36 * 0.01);
  EXPECT_THROW(ii_auto_radius(l, 0, 0.01), InvalidArgument);
  EXPECT_THROW(ii_auto_radius(l, 1, -1), InvalidArgument);
  EXPECT_THROW(ii_auto_radius(MaximalSegmentLengths{}, 1, 0.01), InvalidArgument);
  EXPECT_EQ(mean_maximal_segment_length({}).segments, 0u);
}

} // namespace
