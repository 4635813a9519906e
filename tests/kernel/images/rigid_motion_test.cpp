#include <zdg/kernel/images/rigid_motion.hpp>

#include "tests/support/tower.hpp"
#include <zdg/arith/error.hpp>
#include <zdg/kernel/topology/betti_numbers.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <vector>

namespace zdg {
namespace {

using Q = Rational<BigInt>;
using P2 = std::vector<BigInt>;

// The primitive Pythagorean triples (m^2 - n^2, 2mn, m^2 + n^2) with c < limit (Euclid).
std::vector<std::array<long, 3>> primitive_triples(long limit) {
  std::vector<std::array<long, 3>> t;
  for (long m = 2; m * m < limit; ++m) {
    for (long n = 1; n < m; ++n) {
      if ((m - n) % 2 == 0 || std::gcd(m, n) != 1) continue;
      const long c = m * m + n * n;
      if (c < limit) t.push_back({m * m - n * n, 2 * m * n, c});
    }
  }
  return t;
}

// Every point p whose image may be q: D(p) = q puts R p within sqrt(2)/2 of q - v, so p is
// within 1 of R^-1 (q - v); the box of radius 2 around its rounding holds them all.
std::vector<P2> preimages(const RigidMotion& m, const P2& q) {
  double y[3] = {0, 0, 0};
  const double n = to_double(m.n);
  for (int j = 0; j < m.dim; ++j) {
    for (int k = 0; k < m.dim; ++k) {
      const auto ku = static_cast<std::size_t>(k);
      y[j] += to_double(m.m[ku][static_cast<std::size_t>(j)]) / n *
              (to_double(q[ku]) - to_double(m.v[ku].num()) / to_double(m.v[ku].den()));
    }
  }
  std::vector<P2> out;
  const int span = 5, total = m.dim == 2 ? 25 : 125;
  for (int c = 0; c < total; ++c) {
    int rest = c;
    P2 p(static_cast<std::size_t>(m.dim));
    for (int j = 0; j < m.dim; ++j) {
      p[static_cast<std::size_t>(j)] =
          BigInt(static_cast<long>(std::floor(y[j])) - 2 + rest % span);
      rest /= span;
    }
    if (digitized_image(m, p) == q) out.push_back(p);
  }
  return out;
}

TEST(RigidMotion, RotationOfATripleIsValidatedAndReduced) {
  EXPECT_THROW(rotation_2d(3, 4, 6), InvalidArgument);
  EXPECT_THROW(rotation_2d(-3, -4, -5), InvalidArgument);
  EXPECT_THROW(rotation_3d(0, 0, 0, 0), InvalidArgument);
  const RigidMotion a = rotation_2d(6, 8, 10), b = rotation_2d(3, 4, 5);
  EXPECT_EQ(a.m, b.m);
  EXPECT_EQ(a.n, BigInt(5));
  // Near 2^62: the check is exact (a^2 would overflow int64 and int128 is not enough past
  // 2^63): the triple (2k+1, 2k^2+2k, 2k^2+2k+1) with k = 2^30.
  const BigInt k = BigInt(1) << 30;
  EXPECT_NO_THROW(rotation_2d(2 * k + 1, 2 * k * k + 2 * k, 2 * k * k + 2 * k + 1));
  EXPECT_THROW(rotation_2d(2 * k + 1, 2 * k * k + 2 * k, 2 * k * k + 2 * k + 2), InvalidArgument);
}

TEST(RigidMotion, QuaternionRotationIsOrthogonal) {
  // M M^T = n^2 I and det M = n^3 for the reduced matrix of any quaternion.
  std::mt19937 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    auto r = [&] { return BigInt(static_cast<long>(rng() % 11) - 5); };
    const BigInt w = r(), x = r(), y = r(), z = r();
    if (w == 0 && x == 0 && y == 0 && z == 0) continue;
    const RigidMotion m = rotation_3d(w, x, y, z);
    for (std::size_t i = 0; i < 3; ++i) {
      for (std::size_t j = 0; j < 3; ++j) {
        BigInt s = 0;
        for (std::size_t k = 0; k < 3; ++k) s += m.m[i][k] * m.m[j][k];
        EXPECT_EQ(s, i == j ? BigInt(m.n * m.n) : BigInt(0));
      }
    }
    const auto& a = m.m;
    const BigInt det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                       a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                       a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    EXPECT_EQ(det, m.n * m.n * m.n);
  }
}

// Nouvel and Remila (IWCIA 2004), Roussillon and Coeurjolly (2016): the digitized rotation of a
// primitive triple is a bijection of Z^2 iff max(|a|, |b|) = c - 1; the period certificate
// agrees on every primitive triple with c < 3000, in all four quadrants and both orders.
TEST(RigidMotion, PeriodCertificateProvesTheTwinTripleTheorem) {
  int bijective = 0, total = 0;
  for (const auto& [a0, b0, c] : primitive_triples(3000)) {
    for (int variant = 0; variant < 4; ++variant) {
      long a = a0, b = b0;
      if (variant & 1) std::swap(a, b);
      if (variant & 2) a = -a;
      const LatticeBijectivity r = lattice_bijectivity(rotation_2d(a, b, c));
      EXPECT_EQ(r.method, "period");
      EXPECT_EQ(r.bijective, std::max(std::abs(a), std::abs(b)) == c - 1)
          << a << "," << b << "," << c;
      bijective += r.bijective;
      ++total;
    }
  }
  EXPECT_GT(bijective, 0);
  EXPECT_GT(total - bijective, 0);
  // Quarter turns are bijections.
  for (const auto& t :
       std::vector<std::array<long, 3>>{{1, 0, 1}, {0, 1, 1}, {-1, 0, 1}, {0, -1, 1}}) {
    EXPECT_TRUE(lattice_bijectivity(rotation_2d(t[0], t[1], t[2])).bijective);
  }
}

// The witness of a non-bijective motion is checked by evaluating D: two distinct points with
// the stated image, and a point with no preimage at all (every candidate within distance 1 of
// R^-1 (q - v) examined). A bijective one is injective on a window and onto its inner part.
TEST(RigidMotion, LatticeCertificateAgainstBruteForce) {
  const auto triples = primitive_triples(400);
  test::check_property([&] {
    const auto& t = triples[*rc::gen::inRange<std::size_t>(0, triples.size())];
    const long sa = *rc::gen::element(1L, -1L), sb = *rc::gen::element(1L, -1L);
    const bool swap = *rc::gen::arbitrary<bool>();
    const long a = sa * (swap ? t[1] : t[0]), b = sb * (swap ? t[0] : t[1]);
    const long den = *rc::gen::inRange(1L, 7L);
    const std::vector<Q> center = {Q(*rc::gen::inRange(-20L, 20L), den),
                                   Q(*rc::gen::inRange(-20L, 20L), den)};
    const std::vector<Q> shift = {Q(*rc::gen::inRange(-9L, 9L), 3), Q(0)};
    const RigidMotion m = motion_about(rotation_2d(a, b, t[2]), center, shift);
    const LatticeBijectivity r = lattice_bijectivity(m);
    RC_ASSERT(r.period == BigInt(t[2]));
    if (!r.bijective) {
      RC_ASSERT(r.collision.has_value() && r.hole.has_value());
      const P2 p1 = {(*r.collision)[0][0], (*r.collision)[0][1]};
      const P2 p2 = {(*r.collision)[1][0], (*r.collision)[1][1]};
      const P2 q = {(*r.collision_image)[0], (*r.collision_image)[1]};
      RC_ASSERT(p1 != p2);
      RC_ASSERT(digitized_image(m, p1) == q);
      RC_ASSERT(digitized_image(m, p2) == q);
      RC_ASSERT(preimages(m, {(*r.hole)[0], (*r.hole)[1]}).empty());
    } else {
      RC_ASSERT(!r.collision.has_value());
      const long w = 24;
      std::set<P2> images;
      for (long y = -w; y <= w; ++y) {
        for (long x = -w; x <= w; ++x) RC_ASSERT(images.insert(digitized_image(m, {x, y})).second);
      }
      for (long y = -w / 2; y <= w / 2; ++y) {
        for (long x = -w / 2; x <= w / 2; ++x) RC_ASSERT(preimages(m, {x, y}).size() == 1u);
      }
    }
  });
}

// Past 2^28 the answer is the theorem's; the witness search, when it finds a pair, is checked.
TEST(RigidMotion, LargePeriodsAnswerByTheTheorem) {
  const BigInt k = BigInt(1) << 30;
  const LatticeBijectivity twin =
      lattice_bijectivity(rotation_2d(2 * k + 1, 2 * k * k + 2 * k, 2 * k * k + 2 * k + 1));
  EXPECT_TRUE(twin.bijective);
  EXPECT_EQ(twin.method, "theorem");
  // m = 5 2^28 + 1, n = 2^29 (coprime, opposite parity): the angle of (21, 20, 29), no twin
  // triple, whose collisions start next to the origin (a triple near (3, 4, 5) would hide them
  // past the search's reach).
  const BigInt mm = 5 * (k / 4) + 1, nn = k / 2;
  const RigidMotion m = rotation_2d(mm * mm - nn * nn, 2 * mm * nn, mm * mm + nn * nn);
  const LatticeBijectivity r = lattice_bijectivity(m);
  EXPECT_FALSE(r.bijective);
  EXPECT_EQ(r.method, "theorem");
  ASSERT_TRUE(r.collision.has_value());
  const P2 p1 = {(*r.collision)[0][0], (*r.collision)[0][1]};
  const P2 p2 = {(*r.collision)[1][0], (*r.collision)[1][1]};
  EXPECT_NE(p1, p2);
  EXPECT_EQ(digitized_image(m, p1), digitized_image(m, p2));
  ASSERT_TRUE(r.hole.has_value());
  EXPECT_TRUE(preimages(m, {(*r.hole)[0], (*r.hole)[1]}).empty());
  // A non-integral offset is beyond both the certificate and the theorem.
  EXPECT_THROW(lattice_bijectivity(motion_about(m, {Q(1, 2), Q(0)}, {Q(0), Q(0)})),
               InvalidArgument);
}

// apply_motion equals the image of every object point computed one by one in BigInt, with the
// count of distinct images and a verified colliding pair, in 2D and 3D.
TEST(RigidMotion, ApplyEqualsPointwiseImages) {
  const auto triples = primitive_triples(60);
  test::check_property([&] {
    const int dim = *rc::gen::inRange(2, 4);
    std::vector<std::int64_t> ext, low;
    for (int k = 0; k < dim; ++k) {
      ext.push_back(*rc::gen::inRange<std::int64_t>(1, dim == 2 ? 14 : 7));
      low.push_back(*rc::gen::inRange<std::int64_t>(-4, 4));
    }
    Image<std::uint8_t> img{Domain(ext, low)};
    for (auto& v : img.values()) v = *rc::gen::inRange(0, 3) == 0 ? 1 : 0;
    RigidMotion rot;
    if (dim == 2) {
      const auto& t = triples[*rc::gen::inRange<std::size_t>(0, triples.size())];
      rot = rotation_2d(t[0] * *rc::gen::element(1L, -1L), t[1], t[2]);
    } else {
      auto c = [] { return BigInt(*rc::gen::inRange(-3L, 4L)); };
      BigInt w = c(), x = c(), y = c(), z = c();
      if (w == 0 && x == 0 && y == 0 && z == 0) w = 1;
      rot = rotation_3d(w, x, y, z);
    }
    std::vector<Q> center, shift;
    for (int k = 0; k < dim; ++k) {
      center.emplace_back(*rc::gen::inRange(-8L, 8L), 2);
      shift.emplace_back(*rc::gen::inRange(-4L, 4L), *rc::gen::inRange(1L, 4L));
    }
    const RigidMotion m = motion_about(rot, center, shift);
    const MotionOnImage r = apply_motion(img, m, true);
    std::set<std::vector<std::int64_t>> expected;
    std::int64_t points = 0;
    const Domain& d = img.domain();
    std::vector<std::int64_t> p(static_cast<std::size_t>(dim));
    for (std::int64_t i = 0; i < d.size(); ++i) {
      if (img[i] == 0) continue;
      ++points;
      d.point(i, p);
      P2 gb;
      for (auto it = p.rbegin(); it != p.rend(); ++it) gb.emplace_back(*it);
      const P2 q = digitized_image(m, gb);
      std::vector<std::int64_t> qa;
      for (auto it = q.rbegin(); it != q.rend(); ++it) qa.push_back(static_cast<std::int64_t>(*it));
      expected.insert(qa);
    }
    RC_ASSERT(r.points == points);
    RC_ASSERT(r.images == static_cast<std::int64_t>(expected.size()));
    std::int64_t ones = 0;
    for (std::int64_t i = 0; i < r.image.size(); ++i) {
      if (r.image[i] == 0) continue;
      ++ones;
      RC_ASSERT(expected.count(r.image.domain().point(i)) == 1u);
    }
    RC_ASSERT(ones == r.images);
    RC_ASSERT(r.collision.has_value() == (r.images < r.points));
    if (r.collision) {
      P2 a, b, q;
      for (auto v : (*r.collision)[0]) a.emplace_back(v);
      for (auto v : (*r.collision)[1]) b.emplace_back(v);
      for (auto v : r.collision_image) q.emplace_back(v);
      RC_ASSERT(a != b);
      RC_ASSERT(digitized_image(m, a) == q && digitized_image(m, b) == q);
      std::vector<std::int64_t> ia((*r.collision)[0].rbegin(), (*r.collision)[0].rend());
      std::vector<std::int64_t> ib((*r.collision)[1].rbegin(), (*r.collision)[1].rend());
      RC_ASSERT(img.at(ia) != 0 && img.at(ib) != 0);
    }
    // The domain holds the input's and the images.
    for (int k = 0; k < dim; ++k) {
      RC_ASSERT(r.image.domain().lower(k) <= d.lower(k));
      RC_ASSERT(r.image.domain().upper(k) >= d.upper(k));
    }
  });
}

TEST(RigidMotion, QuarterTurnsMoveImagesExactly) {
  // (0, 1, 1): the quarter turn about the centre of a 5 x 5 box moves a row of three points
  // onto a column of three.
  Image<std::uint8_t> img{Domain({5, 5})};
  img.at(std::vector<std::int64_t>{1, 1}) = 1;
  img.at(std::vector<std::int64_t>{1, 2}) = 1;
  img.at(std::vector<std::int64_t>{1, 3}) = 1;
  const RigidMotion m = motion_about(rotation_2d(0, 1, 1), {Q(2), Q(2)}, {Q(0), Q(0)});
  const MotionOnImage r = apply_motion(img, m, false);
  EXPECT_EQ(r.images, 3);
  // (x, y) -> (2 - (y - 2), 2 + (x - 2)) = (4 - y, x): (1,1) (2,1) (3,1) -> (3,1) (3,2) (3,3).
  EXPECT_EQ(r.image.at(std::vector<std::int64_t>{1, 3}), 1);
  EXPECT_EQ(r.image.at(std::vector<std::int64_t>{2, 3}), 1);
  EXPECT_EQ(r.image.at(std::vector<std::int64_t>{3, 3}), 1);
  // The quaternion (1, 1, 0, 0) is the quarter turn about x: (x, y, z) -> (x, -z, y).
  const RigidMotion q = rotation_3d(1, 1, 0, 0);
  EXPECT_EQ(q.n, BigInt(1));
  EXPECT_EQ(digitized_image(q, {3, 5, 7}), (P2{3, -7, 5}));
}

TEST(RigidMotion, LeavingTheDomainIsAnErrorWithoutExpand) {
  Image<std::uint8_t> img{Domain({4, 4})};
  img.at(std::vector<std::int64_t>{3, 3}) = 1;
  const RigidMotion m = motion_about(rotation_2d(3, 4, 5), {Q(0), Q(0)}, {Q(0), Q(0)});
  EXPECT_THROW(apply_motion(img, m, false), InvalidArgument);
  const MotionOnImage r = apply_motion(img, m, true);
  // (3, 3) -> (-3/5, 21/5) rounds to (-1, 4).
  EXPECT_EQ(r.image.domain().lower(1), -1);
  EXPECT_EQ(r.image.domain().upper(0), 4);
  EXPECT_EQ(r.image.at(std::vector<std::int64_t>{4, -1}), 1);
  EXPECT_THROW(apply_motion(Image<std::uint8_t>{Domain({2, 2, 2})}, m, true), InvalidArgument);
}

// Ties round up: the rotation by a quarter turn about (1/2, 0) sends (0, 0) to (1/2, -1/2),
// digitized to (1, 0).
TEST(RigidMotion, HalfIntegersRoundUp) {
  const RigidMotion m = motion_about(rotation_2d(0, 1, 1), {Q(1, 2), Q(0)}, {Q(0), Q(0)});
  EXPECT_EQ(digitized_image(m, {0, 0}), (P2{1, 0}));
}

} // namespace
} // namespace zdg
