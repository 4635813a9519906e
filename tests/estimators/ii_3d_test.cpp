#include <zdg/estimators/ii_3d.hpp>

#include "tests/support/tower.hpp"

#include "tests/support/digital_sets.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace {

using zdg::Surfel;
using zdg::Voxel;
using zdg::VoxelBox;

zdg::VoxelPredicate ball(Voxel c, std::int64_t r2) {
  return zdg::test::ball_predicate(c, r2);
}

bool sanitized() {
  return std::getenv("ZDG_SANITIZE") != nullptr;
}

// Incremental evaluation (walk, unit moves, chunks, threads) equals the brute-force count
// and moments of the ball at every inner and outer voxel.
TEST(IntegralInvariants3D, IncrementalMomentsEqualDirectMoments) {
  zdg::test::check_property([] {
    const auto r2 = *rc::gen::inRange<std::int64_t>(0, 30);
    const auto s1 = *rc::gen::inRange<std::int64_t>(0, 20);
    const auto s2 = *rc::gen::inRange<std::int64_t>(0, 12);
    const int threads = *rc::gen::inRange(1, 4);
    const bool second = *rc::gen::arbitrary<bool>();
    // Two balls (a jump between the components), clipped by a box with odd lower bounds.
    const auto b1 = ball({-3, 2, 1}, s1), b2 = ball({6, 3, -1}, s2);
    const zdg::VoxelPredicate in = [&](const Voxel& z) { return b1(z) || b2(z); };
    const VoxelBox box{{-8, -3, -4}, {10, 7, 4}};
    const auto surfels = zdg::boundary_surfels(in, box);
    const bool shared = *rc::gen::arbitrary<bool>();
    const auto m = zdg::detail::ii_surfel_moments_incremental(in, box, surfels, r2, threads, second,
                                                              shared ? std::size_t{1} << 29 : 0);
    RC_ASSERT(m.stats.shared_cache == shared);
    RC_ASSERT(m.moments.size() == surfels.size());
    for (std::size_t i = 0; i < surfels.size(); ++i) {
      const auto di = zdg::direct_ball_moments(in, box, zdg::inner_voxel(surfels[i]), r2);
      const auto dout = zdg::direct_ball_moments(in, box, zdg::outer_voxel(surfels[i]), r2);
      if (second) {
        RC_ASSERT(m.moments[i].inner == di);
        RC_ASSERT(m.moments[i].outer == dout);
      } else {
        RC_ASSERT(m.moments[i].inner.m0 == di.m0);
        RC_ASSERT(m.moments[i].outer.m0 == dout.m0);
      }
    }
    RC_ASSERT(m.stats.full_counts >= m.stats.chunks);
  });
}

// The column counter (the default) and the incremental walk give the same integers at every
// inner and outer voxel, on random unions of balls with random radii.
TEST(IntegralInvariants3D, ColumnCounterEqualsIncrementalCounter) {
  zdg::test::check_property([] {
    const auto r2 = *rc::gen::inRange<std::int64_t>(0, 40);
    const auto c1 =
        Voxel{*rc::gen::inRange<std::int64_t>(-4, 4), *rc::gen::inRange<std::int64_t>(-4, 4),
              *rc::gen::inRange<std::int64_t>(-4, 4)};
    const auto c2 =
        Voxel{*rc::gen::inRange<std::int64_t>(-4, 8), *rc::gen::inRange<std::int64_t>(-4, 4),
              *rc::gen::inRange<std::int64_t>(-6, 4)};
    const auto b1 = ball(c1, *rc::gen::inRange<std::int64_t>(0, 30));
    const auto b2 = ball(c2, *rc::gen::inRange<std::int64_t>(0, 20));
    const zdg::VoxelPredicate in = [&](const Voxel& z) { return b1(z) != b2(z); };
    const VoxelBox box{{-9, -7, -8}, {11, 8, 7}};
    const auto surfels = zdg::boundary_surfels(in, box);
    const bool second = *rc::gen::arbitrary<bool>();
    const int threads = *rc::gen::inRange(1, 4);
    const auto fast = zdg::ii_surfel_moments(in, box, surfels, r2, threads, second);
    const auto walk = zdg::ii_surfel_moments_incremental(in, box, surfels, r2, threads, second);
    RC_ASSERT(fast.moments.size() == walk.moments.size());
    RC_ASSERT(fast.stats.voxels == walk.stats.voxels);
    for (std::size_t i = 0; i < surfels.size(); ++i) {
      RC_ASSERT(fast.moments[i].inner == walk.moments[i].inner);
      RC_ASSERT(fast.moments[i].outer == walk.moments[i].outer);
    }
  });
}

// The principal curvatures come from the average of the covariance matrices of the inner and
// outer kernels, each about its own centroid (DGtal's convention behind CVIU 2014): oracle =
// the two matrices summed voxel by voxel, in long double.
TEST(IntegralInvariants3D, PrincipalCurvaturesAverageTheTwoCovarianceMatrices) {
  zdg::test::check_property([] {
    const auto r2 = *rc::gen::inRange<std::int64_t>(4, 40);
    const auto b1 = ball({0, 0, 0}, *rc::gen::inRange<std::int64_t>(9, 40));
    const auto b2 = ball({4, 1, -2}, *rc::gen::inRange<std::int64_t>(0, 20));
    const zdg::VoxelPredicate in = [&](const Voxel& z) { return b1(z) || b2(z); };
    const VoxelBox box{{-10, -10, -10}, {10, 10, 10}};
    const auto surfels = zdg::boundary_surfels(in, box);
    const auto s = surfels[*rc::gen::inRange<std::size_t>(0, surfels.size())];
    const double h = 0.1, R = 0.1 * std::sqrt(double(r2)) + 0.01;
    const auto m = zdg::ii_surfel_moments(in, box, std::vector<Surfel>{s}, r2, 1, true);
    const auto pc = zdg::ii_principal_curvatures_from_moments(m.moments[0], s, h, R);
    Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
    const std::int64_t r = std::int64_t(std::sqrt(double(r2))) + 1;
    for (const Voxel c : {zdg::inner_voxel(s), zdg::outer_voxel(s)}) {
      std::vector<Eigen::Vector3d> pts;
      for (std::int64_t z = -r; z <= r; ++z)
        for (std::int64_t y = -r; y <= r; ++y)
          for (std::int64_t x = -r; x <= r; ++x) {
            const Voxel p{c.x + x, c.y + y, c.z + z};
            if (x * x + y * y + z * z <= r2 && box.contains(p) && in(p))
              pts.emplace_back(double(x), double(y), double(z));
          }
      if (pts.empty()) continue;
      Eigen::Vector3d g = Eigen::Vector3d::Zero();
      for (const auto& q : pts) g += q;
      g /= double(pts.size());
      for (const auto& q : pts) J += 0.5 * (q - g) * (q - g).transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(J);
    const double h5 = std::pow(h, 5), c6 = 6.0 / (M_PI * std::pow(R, 6));
    const double l1 = h5 * es.eigenvalues()(2), l2 = h5 * es.eigenvalues()(1);
    const double k1 = c6 * (l2 - 3 * l1) + 8.0 / (5.0 * R),
                 k2 = c6 * (l1 - 3 * l2) + 8.0 / (5.0 * R);
    RC_ASSERT(std::abs(pc.k1 - k1) <= 1e-9 * (1 + std::abs(k1)));
    RC_ASSERT(std::abs(pc.k2 - k2) <= 1e-9 * (1 + std::abs(k2)));
  });
}

// A closed surface is walked mostly by unit moves: few full counts.
TEST(IntegralInvariants3D, WalkUsesUnitMoves) {
  const auto in = ball({0, 0, 0}, 15 * 15);
  const VoxelBox box{{-20, -20, -20}, {20, 20, 20}};
  const auto surfels = zdg::boundary_surfels(in, box);
  const auto m = zdg::ii_surfel_moments_incremental(in, box, surfels, 16, 2, false);
  EXPECT_LT(m.stats.full_counts, m.stats.voxels / 10);
  EXPECT_LT(m.stats.unit_moves, 2 * m.stats.voxels);
}

struct BallCase {
  std::int64_t n; // digital radius rho / h with rho = 1
  double R;
};

// On the unit ball digitized by the integer predicate |z|^2 <= n^2 (h = 1/n): the II mean
// and principal curvatures are close to 1, k1 <= k2, the normal is radial, and the
// principal directions are tangent.
TEST(IntegralInvariants3D, UnitBallCurvatures) {
  const BallCase c = sanitized() ? BallCase{16, 0.8} : BallCase{20, 0.8};
  const double h = 1.0 / double(c.n);
  const auto in = ball({0, 0, 0}, c.n * c.n);
  const VoxelBox box{{-c.n - 2, -c.n - 2, -c.n - 2}, {c.n + 2, c.n + 2, c.n + 2}};
  const auto seed = zdg::find_boundary_surfel(in, box, {0, 0, 0});
  const auto surfels = zdg::track_surface(in, box, seed);
  const auto H = zdg::ii_mean_curvature(in, box, surfels, h, c.R, 2);
  const auto P = zdg::ii_principal_curvatures(in, box, surfels, h, c.R, 2);
  ASSERT_EQ(H.size(), surfels.size());
  double errH = 0, errK = 0, errN = 0, meanH = 0;
  for (std::size_t i = 0; i < surfels.size(); ++i) {
    const auto p = zdg::surfel_centre(surfels[i], h);
    const double norm = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
    const zdg::Point3<double> u{p.x / norm, p.y / norm, p.z / norm};
    errH = std::max(errH, std::abs(H[i] - 1.0));
    meanH += H[i];
    EXPECT_LE(P[i].k1, P[i].k2);
    errK = std::max({errK, std::abs(P[i].k1 - 1.0), std::abs(P[i].k2 - 1.0)});
    const auto& n = P[i].normal;
    errN = std::max(errN, std::acos(std::min(1.0, n.x * u.x + n.y * u.y + n.z * u.z)));
    const auto dot = [](const zdg::Point3<double>& a, const zdg::Point3<double>& b) {
      return a.x * b.x + a.y * b.y + a.z * b.z;
    };
    EXPECT_NEAR(dot(P[i].d1, n), 0.0, 1e-9);
    EXPECT_NEAR(dot(P[i].d2, n), 0.0, 1e-9);
    EXPECT_NEAR(dot(P[i].d1, P[i].d2), 0.0, 1e-9);
    EXPECT_NEAR(P[i].mean(), H[i], 0.35); // two estimators of the same H
  }
  meanH /= double(surfels.size());
  RecordProperty("errH", std::to_string(errH));
  std::printf("n=%lld R=%.2f surfels=%zu: max|H-1|=%.4f mean H=%.4f max|k-1|=%.4f max angle=%.4f\n",
              static_cast<long long>(c.n), c.R, surfels.size(), errH, meanH, errK, errN);
  // A surfel centre lies up to delta = sqrt(3) h / 2 off the sphere; moving the kernel by
  // delta changes V by about pi R^2 delta, that is H by 4 delta / R^2 (0.11 at n = 24), plus
  // the lattice-count error of the digital ball: the tolerances follow.
  const double delta = std::sqrt(3.0) * h / 2;
  EXPECT_LT(errH, 4 * delta / (c.R * c.R) + 0.05);
  EXPECT_NEAR(meanH, 1.0, 0.04);
  EXPECT_LT(errK, 4 * delta / (c.R * c.R) + 0.05);
  EXPECT_LT(errN, 0.05);
}

// A cylinder of radius 1 along z has curvatures 0 and 1: k1 ~ 0 with d1 along the axis and
// k2 ~ 1 with d2 around it. Matched by value, the classic swap of the formulas shows here.
TEST(IntegralInvariants3D, CylinderCurvaturesMatchedByValue) {
  const std::int64_t n = sanitized() ? 12 : 20, L = 3 * n;
  const double h = 1.0 / double(n), R = 0.6;
  const zdg::VoxelPredicate in = [&](const Voxel& z) {
    return z.x * z.x + z.y * z.y <= n * n && std::abs(z.z) <= L;
  };
  const VoxelBox box{{-n - 2, -n - 2, -L - 2}, {n + 2, n + 2, L + 2}};
  std::vector<Surfel> side;
  for (const Surfel& s : zdg::boundary_surfels(in, box))
    if (std::abs(s.k.z) < 2 * (L - n) && zdg::orthogonal_axis(s) != 2) side.push_back(s);
  const auto P = zdg::ii_principal_curvatures(in, box, side, h, R, 2);
  double e1 = 0, e2 = 0, axis = 1;
  for (const auto& p : P) {
    e1 = std::max(e1, std::abs(p.k1 - 0.0));
    e2 = std::max(e2, std::abs(p.k2 - 1.0));
    axis = std::min(axis, std::abs(p.d1.z));
  }
  std::printf("cylinder: max|k1|=%.4f max|k2-1|=%.4f min|d1.z|=%.4f\n", e1, e2, axis);
  // Same positional tolerance as for the sphere (4 delta / R^2 = 0.48 here).
  const double tol = 4 * (std::sqrt(3.0) * h / 2) / (R * R);
  EXPECT_LT(e1, tol);
  EXPECT_LT(e2, tol);
  EXPECT_GT(axis, 0.95);
}

TEST(IntegralInvariants3D, RadiusAndArguments) {
  EXPECT_EQ(zdg::ii_digital_radius2(3.0, 1.0), 9);
  EXPECT_EQ(zdg::ii_digital_radius2(1.5, 0.5), 9);
  EXPECT_EQ(zdg::ii_digital_radius2(0.99, 0.1), 98);
  EXPECT_THROW(zdg::ii_digital_radius2(300.0, 1.0), zdg::InvalidArgument);
  EXPECT_THROW(zdg::ii_digital_radius2(-1.0, 1.0), zdg::InvalidArgument);
  EXPECT_THROW(zdg::ii_digital_radius2(1.0, 0.0), zdg::InvalidArgument);
  const auto in = ball({0, 0, 0}, 4);
  const VoxelBox box{{-3, -3, -3}, {3, 3, 3}};
  const std::vector<Surfel> bad{{{1, 1, 1}, true}};
  EXPECT_THROW(zdg::ii_surfel_moments(in, box, bad, 4), zdg::InvalidArgument);
  EXPECT_THROW(zdg::ii_surfel_moments(in, box, {}, -1), zdg::InvalidArgument);
  EXPECT_TRUE(zdg::ii_surfel_moments(in, box, {}, 4).moments.empty());
  // A surfel of the complement has empty kernels once the set is empty.
  const std::vector<Surfel> lone{zdg::surfel_between({0, 0, 0}, 0, 1)};
  const zdg::VoxelPredicate none = [](const Voxel&) { return false; };
  EXPECT_THROW(zdg::ii_principal_curvatures(none, box, lone, 1.0, 0.5), zdg::InvalidArgument);
  // Counts alone cannot give principal curvatures.
  const auto counts = zdg::ii_surfel_moments(in, box, lone, 4, 1, false);
  EXPECT_THROW(zdg::ii_principal_curvatures_from_moments(counts.moments[0], lone[0], 1.0, 2.0),
               zdg::InvalidArgument);
}

// An error raised by the predicate (exact digitization overflowing, say) in a worker thread
// reaches the caller.
TEST(IntegralInvariants3D, PredicateErrorsPropagate) {
  const auto b = ball({0, 0, 0}, 25);
  const VoxelBox box{{-8, -8, -8}, {8, 8, 8}};
  const auto surfels = zdg::boundary_surfels(b, box);
  const zdg::VoxelPredicate bad = [&](const Voxel& z) {
    if (z.x == 7) throw zdg::OverflowError("predicate overflow at x = 7");
    return b(z);
  };
  EXPECT_THROW(zdg::ii_mean_curvature(bad, box, surfels, 0.1, 0.4, 3), zdg::OverflowError);
}

} // namespace
