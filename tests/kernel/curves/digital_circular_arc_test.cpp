#include <zdg/kernel/curves/digital_circular_arc.hpp>

#include "tests/support/tower.hpp"

#include "tests/support/predicate_contour.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

namespace {

using zdg::test::contour_of;

using zdg::Pixel;

// --- Oracle: Gordan's alternative by circuit enumeration ------------------------------------
//
// The strict system w.v > 0 (v = u(P) = (|P|^2, P.x, P.y, 1) for inner points, -u(Q) for outer
// points) has no solution iff 0 is a non-negative, non-zero combination of the v (Gordan).
// A minimal-support such combination lives on a circuit: at most 5 vectors of rank |S| - 1,
// whose dependency is given by the signed maximal minors of |S| - 1 of their coordinates.
// So the points are separable iff no subset S (|S| <= 5) and coordinate set T (|T| = |S| - 1)
// give minors lambda, all non-zero and of one sign, with sum lambda_s v_s = 0. Independent of
// the recognizer (no linear programming, no elimination order).
template <class N>
using Vec4 = std::array<N, 4>;

// Determinant of the k x k submatrix of m on the given rows and columns (Laplace expansion
// along the first row; k <= 4, no allocation).
template <class N>
N minor_det(const N (&m)[4][5], int k, const int* rows, const int* cols) {
  if (k == 1) return m[rows[0]][cols[0]];
  N s = 0;
  int sub[4];
  for (int c = 0; c < k; ++c) {
    int t = 0;
    for (int cc = 0; cc < k; ++cc) {
      if (cc != c) sub[t++] = cols[cc];
    }
    const N term = m[rows[0]][cols[c]] * minor_det(m, k - 1, rows + 1, sub);
    s = c % 2 == 0 ? N(s + term) : N(s - term);
  }
  return s;
}

template <class N>
bool has_positive_dependency(const std::vector<Vec4<N>>& v, const std::vector<std::size_t>& s) {
  const int k = static_cast<int>(s.size());
  N m[4][5]; // m[r][q] = coordinate t_r of v_{s_q}
  // Coordinate subsets T of size k - 1.
  for (unsigned mask = 0; mask < 16; ++mask) {
    if (__builtin_popcount(mask) != k - 1) continue;
    int r = 0;
    for (int c = 0; c < 4; ++c) {
      if (!(mask & (1u << c))) continue;
      for (int q = 0; q < k; ++q)
        m[r][q] = v[s[static_cast<std::size_t>(q)]][static_cast<std::size_t>(c)];
      ++r;
    }
    const int rows[4] = {0, 1, 2, 3};
    N lambda[5];
    int sgn = 0;
    bool ok = true;
    for (int drop = 0; drop < k && ok; ++drop) {
      int cols[4], t = 0;
      for (int q = 0; q < k; ++q) {
        if (q != drop) cols[t++] = q;
      }
      const N d = minor_det(m, k - 1, rows, cols);
      lambda[drop] = drop % 2 == 0 ? d : N(-d);
      const int sd = lambda[drop] > 0 ? 1 : (lambda[drop] < 0 ? -1 : 0);
      if (sd == 0 || (sgn != 0 && sd != sgn)) ok = false;
      sgn = sd;
    }
    if (!ok) continue;
    for (std::size_t c = 0; c < 4 && ok; ++c) {
      N sum = 0;
      for (int q = 0; q < k; ++q) sum += lambda[q] * v[s[static_cast<std::size_t>(q)]][c];
      ok = sum == 0;
    }
    if (ok) return true;
  }
  return false;
}

template <class N>
bool oracle_separable(std::span<const Pixel> inner, std::span<const Pixel> outer) {
  std::vector<Vec4<N>> v;
  for (const auto& p : inner) v.push_back({N(p.x * p.x + p.y * p.y), N(p.x), N(p.y), N(1)});
  for (const auto& q : outer) v.push_back({N(-(q.x * q.x + q.y * q.y)), N(-q.x), N(-q.y), N(-1)});
  std::vector<std::size_t> s;
  std::function<bool(std::size_t)> rec = [&](std::size_t from) -> bool {
    if (s.size() >= 2 && has_positive_dependency(v, s)) return true;
    if (s.size() == 5) return false;
    for (std::size_t q = from; q < v.size(); ++q) {
      s.push_back(q);
      if (rec(q + 1)) return true;
      s.pop_back();
    }
    return false;
  };
  return !rec(0);
}

// Shifts the points so that the oracle's lifted coordinates stay small (separability is
// invariant under translation).
std::vector<Pixel> shifted(std::span<const Pixel> pts, Pixel o) {
  std::vector<Pixel> out;
  for (const auto& p : pts) out.push_back(Pixel{p.x - o.x, p.y - o.y});
  return out;
}

template <class I>
class CircularArcTest : public ::testing::Test {};
TYPED_TEST_SUITE(CircularArcTest, zdg::test::TowerTypes, zdg::test::TowerNames);

// Theorem checked: is_digital_circular_arc<I> finds a strictly separating circle exactly when
// Gordan's alternative (circuit enumeration above) says one exists; the circle it returns
// separates (checked exactly).
TYPED_TEST(CircularArcTest, RecognitionAgreesWithGordanOracle) {
  using I = TypeParam;
  zdg::test::check_property([] {
    const auto ni = *rc::gen::inRange<std::size_t>(1, 6);
    const auto no = *rc::gen::inRange<std::size_t>(1, 6);
    const auto range = *rc::gen::element<std::int64_t>(2, 4, 8);
    auto coord = rc::gen::inRange<std::int64_t>(-range, range + 1);
    const auto offset = *rc::gen::element<std::int64_t>(0, 1 << 20, -(1 << 20) + 7);
    std::vector<Pixel> inner, outer;
    for (std::size_t k = 0; k < ni; ++k) inner.push_back({*coord + offset, *coord - offset});
    for (std::size_t k = 0; k < no; ++k) outer.push_back({*coord + offset, *coord - offset});
    const bool expected = oracle_separable<zdg::Int128>(shifted(inner, {offset, -offset}),
                                                        shifted(outer, {offset, -offset}));
    RC_CLASSIFY(expected, "separable");
    auto c = zdg::is_digital_circular_arc<I>(inner, outer);
    RC_ASSERT(c.has_value() == expected);
    if (c) RC_ASSERT(c->separates(inner, outer));
  });
}

TEST(CircularArc, KnownCases) {
  // A square's corners split along a diagonal are cocircular: not strictly separable.
  std::vector<Pixel> in{{0, 0}, {1, 1}}, out{{1, 0}, {0, 1}};
  EXPECT_FALSE(zdg::is_digital_circular_arc_exact(in, out).value);
  // The same with one point moved off the circle: a line separates.
  std::vector<Pixel> in2{{0, 0}, {1, 1}}, out2{{2, 0}, {3, 1}};
  auto c = zdg::is_digital_circular_arc_exact(in2, out2).value;
  ASSERT_TRUE(c);
  EXPECT_TRUE(c->separates(in2, out2));
  // The centre inside, a ring of points outside: a circle with the inner point inside (d < 0,
  // curvature > 0); swapped roles: curvature < 0.
  std::vector<Pixel> centre{{0, 0}}, ring{{3, 0}, {0, 3}, {-3, 0}, {0, -3}, {2, 2}, {-2, -2}};
  auto inside = zdg::is_digital_circular_arc_exact(centre, ring).value;
  ASSERT_TRUE(inside);
  EXPECT_LT(inside->d, 0);
  EXPECT_GT(inside->curvature(), 0);
  auto outside = zdg::is_digital_circular_arc_exact(ring, centre).value;
  ASSERT_TRUE(outside);
  EXPECT_GT(outside->d, 0);
  EXPECT_LT(outside->curvature(), 0);
  // A point both inner and outer: never separable.
  std::vector<Pixel> a{{5, 5}, {1, 2}}, b{{7, 7}, {5, 5}};
  EXPECT_FALSE(zdg::is_digital_circular_arc_exact(a, b).value);
}

TEST(CircularArc, BadInputAndWidth) {
  std::vector<Pixel> none, one{{0, 0}}, two{{1, 0}};
  EXPECT_THROW((void)zdg::is_digital_circular_arc_exact(none, one), zdg::InvalidArgument);
  EXPECT_THROW((void)zdg::is_digital_circular_arc_exact(one, none), zdg::InvalidArgument);
  EXPECT_THROW((void)zdg::maximal_circular_arcs_exact(none, none, true), zdg::InvalidArgument);
  EXPECT_THROW((void)zdg::maximal_circular_arcs_exact(one, none, true), zdg::InvalidArgument);
  std::vector<Pixel> far{{3, 0}};
  EXPECT_THROW((void)zdg::maximal_circular_arcs_exact(one, far, false), zdg::InvalidArgument);
  // Points 2^40 apart: the lifted coordinates exceed 64 bits. Int64 reports the overflow, the
  // exact entry point escalates and still answers exactly.
  const std::int64_t big = std::int64_t(1) << 40;
  std::vector<Pixel> in{{0, 0}, {big, 1}}, out{{0, 1}, {big, 2}};
  EXPECT_THROW((void)zdg::is_digital_circular_arc<zdg::Int64>(in, out), zdg::OverflowError);
  auto r = zdg::is_digital_circular_arc_exact(in, out);
  EXPECT_NE(r.served, zdg::IntKind::int64);
  ASSERT_TRUE(r.value);
  EXPECT_TRUE(r.value->separates(in, out));
}

// --- contours ---------------------------------------------------------------------------------

std::vector<Pixel> run(const std::vector<Pixel>& v, std::size_t begin, std::size_t length) {
  std::vector<Pixel> out;
  for (std::size_t t = 0; t < length; ++t) out.push_back(v[(begin + t) % v.size()]);
  return out;
}

// Theorem checked: every arc of the cover is a DCA (its circle separates its pairs, exactly),
// and is maximal: adding the pair before or after it is not separable by Gordan's oracle; the
// arcs go once around in increasing order of their first pair.
TEST(CircularArc, CoverArcsAreMaximal) {
  zdg::test::check_property([] {
    // A random star-shaped blob: radius r(theta) from a few harmonics.
    const auto r0 = *rc::gen::inRange<int>(2, 5);
    const auto a1 = *rc::gen::inRange<int>(0, 20);
    const auto k = *rc::gen::inRange<int>(1, 4);
    const double amp = 0.1 * a1 * r0 / 20.0 * 3.0;
    auto f = [=](const Pixel& z) {
      const double x = double(z.x) + 0.23, y = double(z.y) - 0.17;
      const double t = std::atan2(y, x);
      const double r = r0 + amp * std::cos(k * t);
      return x * x + y * y <= r * r;
    };
    auto c = contour_of(f, r0 + 4);
    auto pairs = zdg::linel_pairs(c);
    const auto arcs = zdg::maximal_circular_arcs<zdg::Int64>(pairs.inner, pairs.outer, true);
    const std::size_t n = pairs.inner.size();
    RC_ASSERT(!arcs.empty());
    for (std::size_t q = 0; q < arcs.size(); ++q) {
      const auto& a = arcs[q];
      auto in = run(pairs.inner, a.begin, a.length), out = run(pairs.outer, a.begin, a.length);
      RC_ASSERT(a.circle.separates(in, out));
      RC_ASSERT(std::abs(a.curvature - a.circle.curvature()) < 1e-12);
      if (a.length >= n) continue;
      // The run itself is separable, so a certificate of the extension uses the added pair:
      // list it first, where the oracle's enumeration starts.
      auto in_f = run(pairs.inner, a.begin + a.length, 1),
           out_f = run(pairs.outer, a.begin + a.length, 1);
      auto in_b = run(pairs.inner, a.begin + n - 1, 1),
           out_b = run(pairs.outer, a.begin + n - 1, 1);
      for (std::size_t t = 0; t < a.length; ++t) {
        for (auto* v : {&in_f, &in_b}) v->push_back(in[t]);
        for (auto* v : {&out_f, &out_b}) v->push_back(out[t]);
      }
      RC_ASSERT(!oracle_separable<zdg::Int128>(in_f, out_f));
      RC_ASSERT(!oracle_separable<zdg::Int128>(in_b, out_b));
      if (q > 0) RC_ASSERT(a.begin != arcs[q - 1].begin);
    }
    // Every pair is covered.
    std::vector<bool> covered(n, false);
    for (const auto& a : arcs) {
      for (std::size_t t = 0; t < a.length; ++t) covered[(a.begin + t) % n] = true;
    }
    for (bool b : covered) RC_ASSERT(b);
  });
}

// The cover is computed on every tower type with the same result.
TYPED_TEST(CircularArcTest, CoverIsTheSameOnEveryType) {
  using I = TypeParam;
  auto c = contour_of([](const Pixel& z) { return z.x * z.x + 2 * z.y * z.y <= 40; }, 8);
  auto pairs = zdg::linel_pairs(c);
  const auto ref = zdg::maximal_circular_arcs<zdg::Int64>(pairs.inner, pairs.outer, true);
  const auto got = zdg::maximal_circular_arcs<I>(pairs.inner, pairs.outer, true);
  ASSERT_EQ(ref.size(), got.size());
  for (std::size_t q = 0; q < ref.size(); ++q) {
    EXPECT_EQ(ref[q].begin, got[q].begin);
    EXPECT_EQ(ref[q].length, got[q].length);
    EXPECT_EQ(ref[q].circle, got[q].circle);
  }
}

// A cover on a wide type solves the runs of small extent on Int64 and the others on its own type:
// a digital ellipse of half-axes 1100 and 50 has both (its flat sides give arcs over 2^9 pixels
// long, its ends short ones), and the two wide types, which take the same steps, give the same
// arcs and circles; every circle separates its run (checked exactly, on BigInt).
TEST(CircularArc, WideAndNarrowSolvesAgree) {
  auto c = contour_of(
      [](const Pixel& z) {
        return z.x * z.x * 2500 + z.y * z.y * 1210000 <= std::int64_t(1210000) * 2500;
      },
      1104);
  auto pairs = zdg::linel_pairs(c);
  const auto a128 = zdg::maximal_circular_arcs<zdg::Int128>(pairs.inner, pairs.outer, true);
  const auto abig = zdg::maximal_circular_arcs<zdg::BigInt>(pairs.inner, pairs.outer, true);
  ASSERT_EQ(a128.size(), abig.size());
  std::int64_t widest = 0, narrowest = std::numeric_limits<std::int64_t>::max();
  for (std::size_t q = 0; q < a128.size(); ++q) {
    EXPECT_EQ(a128[q].begin, abig[q].begin);
    EXPECT_EQ(a128[q].length, abig[q].length);
    EXPECT_EQ(a128[q].circle, abig[q].circle);
    auto in = run(pairs.inner, a128[q].begin, a128[q].length);
    auto out = run(pairs.outer, a128[q].begin, a128[q].length);
    EXPECT_TRUE(a128[q].circle.separates(in, out)) << "arc " << q;
    // The extent of the run from its first inner point, as the cover measures it.
    std::int64_t extent = 0;
    for (const auto* side : {&in, &out})
      for (const Pixel& p : *side)
        extent = std::max({extent, std::abs(p.x - in[0].x), std::abs(p.y - in[0].y)});
    widest = std::max(widest, extent);
    narrowest = std::min(narrowest, extent);
  }
  EXPECT_GE(widest, 512);    // runs beyond the 2^9 extent of the Int64 solves
  EXPECT_LT(narrowest, 512); // and runs within it
}

// A digital disc is one digital circular arc: a closed contour gives a single arc covering it,
// whose circle separates the disc from its complement with curvature close to 1/r.
TEST(CircularArc, DigitalDiscIsOneArc) {
  for (std::int64_t r2 : {2, 5, 10, 50, 200, 1000, 5000}) {
    auto c = contour_of([=](const Pixel& z) { return z.x * z.x + z.y * z.y <= r2; },
                        static_cast<std::int64_t>(std::sqrt(double(r2))) + 1);
    auto pairs = zdg::linel_pairs(c);
    const auto arcs = zdg::maximal_circular_arcs_exact(pairs.inner, pairs.outer, true).value;
    ASSERT_EQ(arcs.size(), 1u) << "r2 = " << r2;
    EXPECT_EQ(arcs[0].length, pairs.inner.size());
    EXPECT_TRUE(arcs[0].circle.separates(pairs.inner, pairs.outer));
    // Every separating circle lies between the inner and outer pixels: radius within
    // [sqrt(r2) - 1, sqrt(r2) + 1].
    const double r = std::sqrt(double(r2));
    EXPECT_GT(arcs[0].curvature, 1.0 / (r + 1.0));
    EXPECT_LT(arcs[0].curvature, 1.0 / (r - 1.0 + 1e-9) + (r2 == 2 ? 10.0 : 0.0));
  }
}

// The 8 lattice symmetries map the cover onto the cover of the transformed contour: the same
// runs of linels (mapped; a mirror reverses the contour), and each arc's circle separates the
// image of the original run it corresponds to (the circles themselves may differ: any element
// of the separating set is a valid answer).
TEST(CircularArc, CoverIsInvariantUnderLatticeSymmetries) {
  auto f = [](const Pixel& z) {
    const double x = double(z.x) + 0.31, y = double(z.y) - 0.12;
    const double t = std::atan2(y, x);
    const double r = 9 + 3 * std::cos(3 * t);
    return x * x + y * y <= r * r;
  };
  auto c = contour_of(f, 14);
  auto pairs = zdg::linel_pairs(c);
  const std::size_t n = pairs.inner.size();
  const auto ref = zdg::maximal_circular_arcs_exact(pairs.inner, pairs.outer, true).value;
  auto as_set =
      [n](const std::vector<zdg::MaximalArc>& arcs,
          const std::function<std::pair<std::size_t, std::size_t>(std::size_t, std::size_t)>& map) {
        std::vector<std::pair<std::size_t, std::size_t>> s;
        for (const auto& a : arcs) s.push_back(map(a.begin, a.length));
        std::sort(s.begin(), s.end());
        (void)n;
        return s;
      };
  for (int sym = 0; sym < 8; ++sym) {
    auto g = [sym](const Pixel& p) {
      Pixel q = sym & 1 ? Pixel{p.y, p.x} : p;
      if (sym & 2) q.x = -q.x;
      if (sym & 4) q.y = -q.y;
      return q;
    };
    const bool mirror = __builtin_popcount(static_cast<unsigned>(sym)) % 2 == 1;
    std::vector<Pixel> in, out;
    for (std::size_t l = 0; l < n; ++l) {
      // A mirror reverses the orientation: walk the mapped pairs backwards so that the inner
      // pixels stay on the left; the runs are the same sets of linels.
      const std::size_t s = mirror ? (n - l) % n : l;
      in.push_back(g(pairs.inner[s]));
      out.push_back(g(pairs.outer[s]));
    }
    const auto got = zdg::maximal_circular_arcs_exact(in, out, true).value;
    // Map each arc of `got` to (first linel index in the original numbering, length).
    auto back = [&](std::size_t b, std::size_t len) {
      if (!mirror) return std::make_pair(b, len);
      const std::size_t last = b + len - 1;
      return std::make_pair((n - last % n) % n, len);
    };
    auto id = [](std::size_t b, std::size_t len) { return std::make_pair(b, len); };
    EXPECT_EQ(as_set(got, back), as_set(ref, id)) << "symmetry " << sym;
    for (const auto& a : got) {
      auto [b, len] = back(a.begin, a.length);
      // The circle of `a` in the transformed plane; pull the original run through g and check.
      std::vector<Pixel> gi, go;
      for (std::size_t t = 0; t < len; ++t) {
        gi.push_back(g(pairs.inner[(b + t) % n]));
        go.push_back(g(pairs.outer[(b + t) % n]));
      }
      EXPECT_TRUE(a.circle.separates(gi, go)) << "symmetry " << sym;
    }
  }
}

} // namespace
