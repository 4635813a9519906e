// The 3D estimators of the registry and the Hausdorff estimators, through the driver.
#include <zdg/arith/error.hpp>
#include <zdg/convergence/digitized_3d.hpp>
#include <zdg/convergence/experiment.hpp>
#include <zdg/estimators/hausdorff.hpp>

#include "tests/support/experiments.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace {

// Under the sanitizers (about 15x slower in Debug) the loops below run on fewer shapes/steps.
const bool kSanitized = std::getenv("ZDG_SANITIZE") != nullptr;

zdg::ErrorStats run_once(const std::string& shape, const std::string& est, double h,
                         std::vector<double> t = {0.0, 0.0, 0.0}, double k = 3) {
  auto s = zdg::parse_shape(shape);
  auto box =
      s->bounding_box().value_or(std::vector<std::pair<double, double>>(t.size(), {-20.0, 20.0}));
  for (std::size_t a = 0; a < box.size(); ++a) {
    box[a].first += t[a] - 2 * h;
    box[a].second += t[a] + 2 * h;
  }
  zdg::RunInput in{*s, h, t, box, k, 1.0 / 3.0};
  return zdg::find_estimator(est).run(in);
}

TEST(Estimators3d, IISlopesOnTheSphereSmoke) {
  // Coarse steps only (the sweeps are in convergence_3d_slow_test.cpp): the l_inf slopes of
  // the mean and principal curvatures are at least 1/3 - 0.1 (CVIU 2014), the normal's at
  // least 2/3 - 0.1.
  zdg::ExperimentConfig c;
  c.shapes = {"sphere9"};
  // ii-gaussian is not in this smoke test: at these steps (R = 3 h^{1/3} >= 2.1 on a
  // sphere of radius 9) its error does not decrease yet.
  c.estimators = {"ii-mean", "ii-k1", "ii-k2", "ii-normal"};
  c.hs = {1.0, 0.7, 0.5, 0.35};
  c.translations = 2;
  c.seed = 5;
  c.threads = 2;
  auto r = zdg::run_experiment(c);
  ASSERT_EQ(r.runs.size(), 4u * 4 * 2);
  for (const auto& run : r.runs) {
    EXPECT_GT(run.errors.n, 1000);
    EXPECT_LT(run.errors.linf, 0.5) << run.estimator << " " << run.h;
  }
  for (const char* e : {"ii-mean", "ii-k1", "ii-k2"}) {
    const auto& f = zdg::test::linf_fit(r, e, "sphere9");
    EXPECT_NEAR(*f.expected, 1.0 / 3, 1e-12);
    EXPECT_TRUE(*f.pass) << e << " slope " << f.fit.slope;
  }
  EXPECT_NEAR(*zdg::test::linf_fit(r, "ii-normal", "sphere9").expected, 2.0 / 3, 1e-12);
  EXPECT_TRUE(r.all_pass);
}

TEST(Estimators3d, CoarseErrorsOnTorusAndGoursat) {
  // Torus (saddle points, k1 < 0 inside) and Goursat at h = 0.25 with R = 3 h^{1/3}: the
  // principal curvatures matched by value are within 0.2 everywhere; matching them by
  // position in a list instead would give errors of |1/r - cos v/(R + r cos v)| >= 0.375.
  for (const char* shape : {"torus", "goursat"}) {
    if (kSanitized && std::string(shape) == "goursat") continue;
    for (const char* e : {"ii-mean", "ii-k1", "ii-k2"}) {
      auto s = run_once(shape, e, 0.25, {0.01, -0.02, 0.03});
      EXPECT_LT(s.linf, 0.2) << shape << " " << e;
      EXPECT_GT(s.n, 5000);
    }
  }
  auto d = run_once("torus", "ii-directions", 0.25);
  EXPECT_GT(d.n, 5000);   // the torus has no umbilic
  EXPECT_LT(d.mean, 0.1); // radians
  auto sphere = run_once("sphere9", "ii-directions", 0.5);
  EXPECT_EQ(sphere.n, 0); // all umbilic: no direction to compare
  auto n = run_once("ellipsoid", "ii-normal", 0.25);
  EXPECT_LT(n.linf, 0.1);
}

TEST(Estimators3d, ClippedShapesIgnoreTheBoxFaces) {
  // The elliptic cylinder along y is cut by the box at y = +-10: the caps are not part of
  // the surface. Were their surfels counted, the Hausdorff ratio would reach about 10 / h
  // and the mean curvature error 1/R.
  auto ratio = run_once("cylinder", "hausdorff-rel", 0.5);
  EXPECT_LE(ratio.linf, 1.0);
  EXPECT_GT(ratio.n, 3000);
  auto mean = run_once("cylinder", "ii-mean", 0.5);
  EXPECT_LT(mean.linf, 0.3);
  auto shape = zdg::parse_shape("cylinder");
  zdg::RunInput in{*shape, 0.5, {0, 0, 0}, *shape->bounding_box(), 3, 1.0 / 3.0};
  auto d = zdg::detail::digitize_3d(in);
  EXPECT_TRUE(d.clipped[2] && d.clipped[3]);                  // -y, +y
  EXPECT_FALSE(d.clipped[0] || d.clipped[1] || d.clipped[4]); // x, z: inside the box
  EXPECT_LT(zdg::detail::evaluated_surfels(d, 0).size(), d.surfels.size());
}

TEST(Estimators3d, TrackedSurfacesHaveTheTopologyOfTheirShapes) {
  // Seeds from 64 lines, tracking, then the primal quad surface: V - E + F = 2 for the
  // sphere and the ellipsoid (translated), 0 for the torus; no surfel on the box.
  for (auto [shape, chi] : {std::pair{"sphere9", 2}, {"ellipsoid", 2}, {"torus", 0}}) {
    auto s = zdg::parse_shape(shape);
    auto box = *s->bounding_box();
    zdg::RunInput in{*s, 0.4, {0.11, -0.05, 0.17}, box, 3, 1.0 / 3.0};
    auto d = zdg::detail::digitize_3d(in);
    auto quads = zdg::primal_surface(d.surfels);
    EXPECT_EQ(zdg::euler_characteristic(quads), chi) << shape;
    EXPECT_EQ(zdg::detail::evaluated_surfels(d, 0).size(), d.surfels.size()) << shape;
    // Every tracked surfel separates an inside voxel from an outside one.
    for (std::size_t i = 0; i < d.surfels.size(); i += 97) {
      EXPECT_TRUE(d.inside(zdg::inner_voxel(d.surfels[i])));
      EXPECT_FALSE(d.inside(zdg::outer_voxel(d.surfels[i])));
    }
  }
}

TEST(Estimators3d, HausdorffBoundHoldsIn2dAnd3d) {
  // Lachaud-Thibert 2016: every boundary element centre lies within sqrt(d) h / 2 of the
  // true boundary once h < 2 rho / sqrt(d).
  for (const char* shape : {"sphere9", "torus", "ellipsoid"}) {
    for (double h : {0.5, 0.3}) {
      if (kSanitized && h < 0.5) continue;
      auto s = run_once(shape, "hausdorff-rel", h, {0.013, 0.21 * h, -0.37 * h});
      EXPECT_LE(s.linf, 1.0) << shape << " " << h;
      EXPECT_GT(s.linf, 0.2);
      auto d = run_once(shape, "hausdorff", h, {0.013, 0.21 * h, -0.37 * h});
      EXPECT_NEAR(d.linf, s.linf * zdg::hausdorff_bound(3, h), 1e-12);
    }
  }
  for (const char* shape : {"ellipse:20,7", "flower:20,7,6", "ball:5"}) {
    auto s = run_once(shape, "hausdorff-rel", kSanitized ? 0.3 : 0.1, {0.03, -0.01});
    EXPECT_LE(s.linf, 1.0) << shape;
    EXPECT_GT(s.n, 100);
  }
  EXPECT_DOUBLE_EQ(zdg::hausdorff_bound(2, 0.5), std::sqrt(2.0) / 4);
  EXPECT_THROW(zdg::hausdorff_bound(4, 0.5), zdg::InvalidArgument);
  EXPECT_THROW(zdg::hausdorff_bound(3, 0), zdg::InvalidArgument);
  std::vector<double> ds{0.1, 0.3, 0.2};
  auto c = zdg::check_hausdorff_bound(ds, 3, 0.5);
  EXPECT_DOUBLE_EQ(c.max_distance, 0.3);
  EXPECT_TRUE(c.holds());
}

TEST(Estimators3d, HausdorffSlopeSmokeAndGaussVolume) {
  zdg::ExperimentConfig c;
  c.shapes = {"sphere9", "ellipse:20,7"};
  c.estimators = {"hausdorff"};
  c.hs = {0.8, 0.55, 0.4, 0.3};
  c.translations = 3;
  c.threads = 2;
  auto r = zdg::run_experiment(c);
  EXPECT_NEAR(*zdg::test::linf_fit(r, "hausdorff", "sphere9").expected, 1.0, 1e-12);
  EXPECT_TRUE(r.all_pass);
  auto v = run_once("sphere9", "gauss-volume", 0.25, {0.1, 0.05, -0.07});
  EXPECT_LT(v.linf, 3.0); // of 3054
  EXPECT_EQ(v.n, 1);
  EXPECT_THROW(run_once("goursat", "gauss-volume", 0.5), zdg::InvalidArgument);
}

TEST(Estimators3d, DimensionsAndTheoryRows) {
  zdg::ExperimentConfig c;
  c.shapes = {"ellipse:20,7"};
  c.estimators = {"ii-mean"};
  c.hs = {0.5};
  EXPECT_THROW(zdg::run_experiment(c), zdg::InvalidArgument); // 3D estimator, 2D shape
  c.shapes = {"sphere9"};
  c.estimators = {"ii-curvature"};
  EXPECT_THROW(zdg::run_experiment(c), zdg::InvalidArgument);
  auto sphere = zdg::parse_shape("sphere9");
  auto goursat = zdg::parse_shape("goursat");
  auto heart = zdg::parse_shape("heart");
  EXPECT_NEAR(zdg::test::theory_rate("ii-k2", *goursat, 1.0 / 3)->slope, 1.0 / 3, 1e-12);
  EXPECT_NEAR(zdg::test::theory_rate("ii-normal", *goursat, 1.0 / 3)->slope, 2.0 / 3, 1e-12);
  EXPECT_FALSE(zdg::test::theory_rate("ii-mean", *goursat, 0.5).has_value());          // other law
  EXPECT_FALSE(zdg::test::theory_rate("ii-directions", *sphere, 1.0 / 3).has_value()); // umbilic
  EXPECT_FALSE(zdg::test::theory_rate("ii-mean", *heart, 1.0 / 3).has_value());        // cusps
  EXPECT_NEAR(zdg::test::theory_rate("gauss-volume", *sphere, 0)->slope, 243.0 / 158, 1e-12);
  EXPECT_NEAR(zdg::test::theory_rate("hausdorff", *zdg::parse_shape("ball:3"), 0)->slope, 1, 1e-12);
  EXPECT_FALSE(zdg::test::theory_rate("hausdorff-rel", *sphere, 0).has_value());
  // The ground truth at the surfel centre differs from the projected one by O(h): same rates.
  auto usphere = zdg::parse_shape("unprojected:sphere9");
  EXPECT_NEAR(zdg::test::theory_rate("ii-k1", *usphere, 1.0 / 3)->slope, 1.0 / 3, 1e-12);
  EXPECT_FALSE(zdg::test::theory_rate("ii-directions", *usphere, 1.0 / 3).has_value());
}

// The 3D integral invariants share one computation per (shape, h, translation, R), and
// run_plan runs them as one job: every run keeps its own record (entry, translation, k) and
// the errors of a run of its estimator alone, to the last bit, whatever the other entries and
// the thread count.
TEST(Estimators3d, SharedIIRunsKeepTheErrorsOfEachEstimatorAlone) {
  zdg::ExperimentConfig c;
  // Under the sanitizers: one shape and one step (a few seconds there).
  c.shapes = kSanitized ? std::vector<std::string>{"unprojected:sphere9"}
                        : std::vector<std::string>{"unprojected:sphere9", "rcube"};
  c.estimators = {"ii-mean", "gauss-volume", "ii-k1", "ii-k2:k=7"};
  c.hs = kSanitized ? std::vector<double>{0.6} : std::vector<double>{0.6, 0.45};
  c.translations = 2;
  c.k_text = "5";
  c.threads = 2;
  const auto together = zdg::run_experiment(c);
  ASSERT_EQ(together.runs.size(), c.shapes.size() * c.estimators.size() * c.hs.size() * 2);
  for (const auto& est : c.estimators) {
    zdg::ExperimentConfig alone = c;
    alone.estimators = {est};
    alone.threads = 1;
    const auto r = zdg::run_experiment(alone);
    for (const auto& a : r.runs) {
      const auto it = std::find_if(together.runs.begin(), together.runs.end(), [&](const auto& b) {
        return b.shape == a.shape && b.estimator == a.estimator && b.h == a.h &&
               b.translation == a.translation;
      });
      ASSERT_NE(it, together.runs.end()) << est << " " << a.shape;
      EXPECT_EQ(it->k, a.k);
      EXPECT_EQ(it->offset, a.offset);
      EXPECT_EQ(it->errors.n, a.errors.n);
      EXPECT_EQ(it->errors.linf, a.errors.linf) << est << " " << a.shape << " h = " << a.h;
      EXPECT_EQ(it->errors.l2, a.errors.l2);
    }
  }
}

} // namespace
