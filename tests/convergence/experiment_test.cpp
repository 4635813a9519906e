#include <zdg/convergence/experiment.hpp>

#include "tests/support/experiments.hpp"
#include "tests/support/tower.hpp"
#include <zdg/arith/error.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <tuple>

namespace {

using zdg::test::linf_fit;

TEST(Fit, ExactPowerLawHasItsSlopeAndNoError) {
  std::vector<double> h{0.1, 0.05, 0.02, 0.01}, e;
  for (double x : h) e.push_back(3 * std::pow(x, 1.5));
  auto f = zdg::fit_loglog(h, e);
  EXPECT_NEAR(f.slope, 1.5, 1e-12);
  EXPECT_NEAR(f.stderr_slope, 0, 1e-9);
  EXPECT_EQ(f.n, 4);
  auto g = zdg::fit_loglog({0.1}, {1.0});
  EXPECT_TRUE(std::isnan(g.slope));
}

TEST(Experiment, GridStepSyntaxes) {
  auto a = zdg::parse_grid_steps("0.1:0.001:3");
  ASSERT_EQ(a.size(), 3u);
  EXPECT_NEAR(a[1], 0.01, 1e-15);
  auto b = zdg::parse_grid_steps("exp:0:87");
  ASSERT_EQ(b.size(), 88u);
  EXPECT_NEAR(b.back(), std::exp(-8.7), 1e-18);
  auto c = zdg::parse_grid_steps("1/2,0.25");
  EXPECT_EQ(c, (std::vector<double>{0.5, 0.25}));
  EXPECT_THROW(zdg::parse_grid_steps("0.1:x:3"), zdg::InvalidArgument);
  EXPECT_THROW(zdg::parse_grid_steps("0.001:0.1:3"), zdg::InvalidArgument);
  EXPECT_THROW(zdg::parse_grid_steps("-1"), zdg::InvalidArgument);
  EXPECT_THROW(zdg::parse_box("3:1"), zdg::InvalidArgument);
}

// k is one value for every shape or one per shape, in the order of the shapes.
TEST(Experiment, ParameterKPerShape) {
  EXPECT_EQ(zdg::parse_k_per_shape("5", 3), (std::vector<double>{5, 5, 5}));
  EXPECT_EQ(zdg::parse_k_per_shape("5,5,3", 3), (std::vector<double>{5, 5, 3}));
  EXPECT_EQ(zdg::parse_k_per_shape("1/2,8.9", 2), (std::vector<double>{0.5, 8.9}));
  EXPECT_THROW(zdg::parse_k_per_shape("5,3", 3), zdg::InvalidArgument);
  EXPECT_THROW(zdg::parse_k_per_shape("5,-3", 2), zdg::InvalidArgument);
  zdg::ExperimentConfig c;
  c.shapes = {"ball:10", "ellipse:20,7"};
  c.estimators = {"ii-curvature"};
  c.hs = {0.5};
  c.k_text = "3,5";
  auto r = zdg::run_experiment(c);
  ASSERT_EQ(r.runs.size(), 2u);
  for (const auto& run : r.runs) EXPECT_EQ(run.k, run.shape == "ball:10" ? 3.0 : 5.0);
  c.k_text = "3,5,7";
  EXPECT_THROW(zdg::run_experiment(c), zdg::InvalidArgument);
}

TEST(Experiment, GaussAreaOfAGridAlignedLatticePolygonIsPicksCount) {
  // Exact case: at h = 1 the Gauss count of a lattice polygon is A + B/2 + 1 (Pick).
  auto shape = zdg::parse_shape("polygon:0,0,10,0,10,7,0,7");
  const auto& est = zdg::find_estimator("gauss-area");
  zdg::RunInput in{*shape, 1.0, {0.0, 0.0}, {{-1, 11}, {-1, 8}}, 0, 0};
  auto s = est.run(in);
  EXPECT_DOUBLE_EQ(s.linf, (70 + 34 / 2 + 1) - 70.0);
  auto tri = zdg::parse_shape("polygon:0,0,12,0,0,8");
  zdg::RunInput in2{*tri, 0.5, {0.0, 0.0}, {{-1, 13}, {-1, 9}}, 0, 0};
  // At h = 1/2 the triangle is the lattice triangle (0,0), (24,0), (0,16): A = 192,
  // B = 24 + 16 + gcd(24, 16) = 48, count = 192 + 24 + 1 = 217, area 217 / 4.
  EXPECT_DOUBLE_EQ(est.run(in2).linf, 217 / 4.0 - 48);
}

TEST(Experiment, IICurvatureSlopeOnTheEllipseSmoke) {
  zdg::ExperimentConfig c;
  c.shapes = {"ellipse:20,7"};
  c.estimators = {"ii-curvature"};
  c.hs = zdg::parse_grid_steps("0.5:0.05:5");
  c.k_text = "5";
  c.threads = 2;
  auto r = zdg::run_experiment(c);
  ASSERT_EQ(r.runs.size(), 5u);
  const auto& f = linf_fit(r, "ii-curvature");
  EXPECT_NEAR(*f.expected, 1.0 / 3, 1e-12);
  EXPECT_GT(f.fit.slope, 1.0 / 3 - 0.1);
  EXPECT_TRUE(*f.pass);
  EXPECT_TRUE(r.all_pass);
  std::ostringstream csv;
  zdg::write_results_csv(r, csv);
  EXPECT_NE(csv.str().find("\"ellipse:20,7\",\"ii-curvature\",0.5,0"), std::string::npos);
}

TEST(Experiment, MomentsAndTangentSlopesSmoke) {
  zdg::ExperimentConfig c;
  c.shapes = {"ellipse:20,7"};
  c.estimators = {"moments", "bc-tangent", "mlp-length"};
  c.hs = zdg::parse_grid_steps("0.4:0.05:4");
  c.translations = 2;
  c.seed = 3;
  auto r = zdg::run_experiment(c);
  EXPECT_EQ(r.runs.size(), 24u);
  EXPECT_GT(linf_fit(r, "mlp-length").fit.slope, 0.9);
  EXPECT_GT(linf_fit(r, "moments").fit.slope, 0.9);
  EXPECT_GT(linf_fit(r, "bc-tangent").fit.slope, 2.0 / 3 - 0.2);
}

// The estimators built on maximal segments: DSS length converges at O(h) on a convex
// polygon, the lambda-MST tangent at least at its proven h^{1/3} on the ellipse.
TEST(Experiment, MaximalSegmentEstimatorsSmoke) {
  zdg::ExperimentConfig c;
  c.shapes = {"polygon:-9,-7,10,-8,6,9,-5,6"};
  c.estimators = {"dss-length"};
  c.hs = {0.2, 0.1, 0.05, 0.025};
  c.translations = 2;
  c.seed = 7;
  c.threads = 2;
  auto r = zdg::run_experiment(c);
  EXPECT_GT(linf_fit(r, "dss-length").fit.slope, 0.8);
  ASSERT_TRUE(linf_fit(r, "dss-length").pass.has_value());
  EXPECT_TRUE(*linf_fit(r, "dss-length").pass);
  c.shapes = {"ellipse:20,7"};
  c.estimators = {"lmst-tangent", "mdss-curvature"};
  c.hs = {0.4, 0.2, 0.1, 0.05};
  auto t = zdg::run_experiment(c);
  EXPECT_GT(linf_fit(t, "lmst-tangent").fit.slope, 1.0 / 3.0 - 0.1);
  EXPECT_TRUE(linf_fit(t, "lmst-tangent").pass.value_or(false));
  // The negative control gets no verdict: theory proves no rate.
  EXPECT_FALSE(linf_fit(t, "mdss-curvature").pass.has_value());
}

TEST(Experiment, RejectsMismatchedInput) {
  zdg::ExperimentConfig c;
  c.shapes = {"ellipse:20,7"};
  c.estimators = {"no-such"};
  c.hs = {0.1};
  EXPECT_THROW(zdg::run_experiment(c), zdg::InvalidArgument);
  c.estimators = {"gauss-area"};
  c.shapes = {"poly:x^2+y^2-4"};
  EXPECT_THROW(zdg::run_experiment(c), zdg::InvalidArgument); // area unknown
}

// Theorem checked: aggregate_levels (sort, then one pass: O(n log n)) equals the definition,
// a quadratic scan that takes, for every (shape, entry, h), the maximum of l_inf and the
// averages of l_2 and of the mean over its translations; levels ordered by shape, entry and
// decreasing h; records in any order.
TEST(Experiment, AggregationEqualsTheQuadraticScan) {
  zdg::test::check_property([] {
    const int shapes = *rc::gen::inRange(1, 4), entries = *rc::gen::inRange(1, 4),
              levels = *rc::gen::inRange(1, 6), translations = *rc::gen::inRange(1, 5);
    std::vector<zdg::RunRecord> runs;
    for (int s = 0; s < shapes; ++s) {
      for (int e = 0; e < entries; ++e) {
        for (int l = 0; l < levels; ++l) {
          for (int t = 0; t < translations; ++t) {
            zdg::RunRecord r;
            r.shape_index = std::size_t(s);
            r.entry_index = std::size_t(e);
            r.h = std::ldexp(1.0, -l);
            r.translation = t;
            r.errors.linf = *rc::gen::inRange(0, 1000) / 7.0;
            r.errors.l2 = *rc::gen::inRange(0, 1000) / 11.0;
            r.errors.mean = *rc::gen::inRange(0, 1000) / 13.0;
            runs.push_back(r);
          }
        }
      }
    }
    const auto order =
        *rc::gen::container<std::vector<int>>(runs.size(), rc::gen::arbitrary<int>());
    std::vector<std::size_t> perm(runs.size());
    std::iota(perm.begin(), perm.end(), 0);
    std::sort(perm.begin(), perm.end(), [&](std::size_t a, std::size_t b) {
      return std::pair(order[a], a) < std::pair(order[b], b);
    });
    std::vector<zdg::RunRecord> shuffled;
    for (auto k : perm) shuffled.push_back(runs[k]);
    const auto got = zdg::aggregate_levels(shuffled);
    RC_ASSERT(got.size() == std::size_t(shapes * entries * levels));
    std::size_t k = 0;
    for (int s = 0; s < shapes; ++s) {
      for (int e = 0; e < entries; ++e) {
        for (int l = 0; l < levels; ++l, ++k) {
          const double h = std::ldexp(1.0, -l);
          double linf = 0, l2 = 0, mean = 0;
          int n = 0;
          for (const auto& r : runs) { // the quadratic scan
            if (r.shape_index != std::size_t(s) || r.entry_index != std::size_t(e) || r.h != h)
              continue;
            linf = std::max(linf, r.errors.linf);
            l2 += r.errors.l2;
            mean += r.errors.mean;
            ++n;
          }
          RC_ASSERT(got[k].shape_index == std::size_t(s));
          RC_ASSERT(got[k].entry_index == std::size_t(e));
          RC_ASSERT(got[k].h == h);
          RC_ASSERT(got[k].runs == n);
          RC_ASSERT(got[k].linf == linf);
          RC_ASSERT(std::abs(got[k].l2 - l2 / n) <= 1e-12 * (1 + l2));
          RC_ASSERT(std::abs(got[k].mean - mean / n) <= 1e-12 * (1 + mean));
        }
      }
    }
  });
}

// Two entries of one estimator with different parameters are two curves: their own rows in
// results.csv (quoted labels), their own fits, their own parameters.
TEST(Experiment, EntriesOfOneEstimatorStayApart) {
  zdg::ExperimentConfig c;
  c.shapes = {"ellipse:20,7"};
  c.estimators = {"ii-curvature:k=5", "ii-curvature:k=3", "bc-curvature:alpha=4/3"};
  c.hs = {0.5, 0.35, 0.25};
  c.threads = 2;
  auto r = zdg::run_experiment(c);
  ASSERT_EQ(r.entries.size(), 3u);
  EXPECT_EQ(r.entries[0].label, "ii-curvature:k=5");
  EXPECT_EQ(r.entries[0].parameters.k, 5.0);
  EXPECT_EQ(r.entries[1].parameters.k, 3.0);
  EXPECT_EQ(r.entries[2].parameters.alpha, 4.0 / 3);
  EXPECT_EQ(r.runs.size(), 9u);
  EXPECT_EQ(r.fits.size(), 9u);
  const auto& f5 = linf_fit(r, "ii-curvature:k=5");
  const auto& f3 = linf_fit(r, "ii-curvature:k=3");
  EXPECT_NE(f5.fit.slope, f3.fit.slope);
  // The rate follows the entry's own exponent: bc-curvature at a = 4/3 proves only h^{1/3}.
  EXPECT_NEAR(*linf_fit(r, "bc-curvature:alpha=4/3").expected, 1.0 / 3, 1e-12);
  std::ostringstream csv;
  zdg::write_results_csv(r, csv);
  EXPECT_NE(csv.str().find("\"ellipse:20,7\",\"ii-curvature:k=5\",0.5,0,\"0 0\",5,"),
            std::string::npos)
      << csv.str();
  EXPECT_NE(csv.str().find("\"ii-curvature:k=3\",0.5,0,\"0 0\",3,"), std::string::npos);
  // The same label twice is refused.
  c.estimators = {"ii-curvature:k=5", "ii-curvature:k=5"};
  EXPECT_THROW(zdg::run_experiment(c), zdg::InvalidArgument);
}

} // namespace

// Issue #34, one threads rule: 0 means all cores, the result reports the workers used
// (worker_count: never more than the jobs), and the records do not depend on the count.
TEST(Experiment, ThreadsZeroIsAllCoresAndTheCountUsedIsReported) {
  zdg::ExperimentConfig c;
  c.shapes = {"ellipse:20,7"};
  c.estimators = {"gauss-area"};
  c.hs = zdg::parse_grid_steps("0.5,0.25");
  EXPECT_EQ(c.threads, 0u);
  const auto all = zdg::run_experiment(c);
  EXPECT_EQ(all.threads, zdg::worker_count(0, 2));
  EXPECT_LE(all.threads, 2u);
  c.threads = 1;
  const auto one = zdg::run_experiment(c);
  EXPECT_EQ(one.threads, 1u);
  ASSERT_EQ(one.runs.size(), all.runs.size());
  for (std::size_t i = 0; i < one.runs.size(); ++i) {
    EXPECT_EQ(one.runs[i].errors.linf, all.runs[i].errors.linf);
    EXPECT_EQ(one.runs[i].errors.l2, all.runs[i].errors.l2);
  }
  c.threads = 1025;
  EXPECT_THROW(zdg::run_experiment(c), zdg::InvalidArgument);
}

// Issue #40, the jobs a scheduler hands out (threads or MPI ranks): every run of the plan is in
// exactly one job, the jobs come largest first (their size estimate non-increasing), and the
// entries that share a computation (the 3D integral invariants) are one job per (level, shape,
// translation).
TEST(Experiment, JobsHoldEveryRunOnceLargestFirst) {
  zdg::test::check_property([] {
    const std::vector<std::string> shapes = {"ellipse:20,7", "ball:5", "flower:20,7,6"};
    const std::vector<std::string> estimators = {"gauss-area", "ii-curvature", "mlp-length"};
    zdg::ExperimentConfig c;
    for (const auto& s : shapes) {
      if (*rc::gen::arbitrary<bool>()) c.shapes.push_back(s);
    }
    for (const auto& e : estimators) {
      if (*rc::gen::arbitrary<bool>()) c.estimators.push_back(e);
    }
    if (c.shapes.empty()) c.shapes.push_back(shapes[0]);
    if (c.estimators.empty()) c.estimators.push_back(estimators[0]);
    const int levels = *rc::gen::inRange(1, 5);
    for (int l = 0; l < levels; ++l) c.hs.push_back(1.0 / (1 + *rc::gen::inRange(0, 40)));
    c.translations = *rc::gen::inRange(0, 4);
    const auto plan = zdg::plan_experiment(c);
    const auto jobs = zdg::plan_jobs(plan, c);
    std::vector<std::tuple<std::size_t, std::size_t, double, int>> got, want;
    for (std::size_t j = 0; j < jobs.size(); ++j) {
      if (j > 0) RC_ASSERT(jobs[j - 1].size >= jobs[j].size);
      RC_ASSERT(jobs[j].size > 0);
      RC_ASSERT(jobs[j].entries.size() == 1u); // none of these estimators shares a computation
      for (const auto e : jobs[j].entries)
        got.emplace_back(jobs[j].shape, e, jobs[j].h, jobs[j].translation);
    }
    for (std::size_t s = 0; s < plan.shapes.size(); ++s)
      for (std::size_t e = 0; e < plan.entries.size(); ++e)
        for (const double h : plan.hs)
          for (int t = 0; t < plan.runs_per_level; ++t) want.emplace_back(s, e, h, t);
    std::sort(got.begin(), got.end());
    std::sort(want.begin(), want.end());
    RC_ASSERT(got == want);
  });
}

// The jobs run one by one (run_job), in any order, give run_plan's records to the last bit but
// the seconds (what a rank of `zdg converge --mpi` runs and sends), and experiment_result
// gives run_experiment's fits; the shared 3D integral invariants are one job.
TEST(Experiment, JobsRunAloneInAnyOrderGiveTheSweep) {
  zdg::ExperimentConfig c;
  c.shapes = {"sphere1"};
  c.estimators = {"ii-mean", "gauss-volume", "ii-k1"};
  c.hs = {0.5, 0.35};
  c.k_text = "1";
  c.translations = 2;
  c.seed = 40;
  c.threads = 2;
  const auto plan = zdg::plan_experiment(c);
  const auto jobs = zdg::plan_jobs(plan, c);
  ASSERT_EQ(jobs.size(), 8u); // 2 levels x 2 translations x {ii-mean + ii-k1, gauss-volume}
  EXPECT_EQ(jobs[0].h, 0.35); // the finer level first
  std::vector<zdg::RunRecord> runs;
  for (std::size_t j = jobs.size(); j-- > 0;) { // smallest first: another order
    const auto records = zdg::run_job(plan, c, jobs[j]);
    ASSERT_EQ(records.size(), jobs[j].entries.size());
    if (records.size() == 2) {
      EXPECT_EQ(records[0].estimator, "ii-mean");
      EXPECT_EQ(records[1].estimator, "ii-k1");
    }
    const auto bare = zdg::job_records(plan, c, jobs[j]);
    for (std::size_t i = 0; i < records.size(); ++i) {
      EXPECT_EQ(bare[i].offset, records[i].offset);
      EXPECT_EQ(bare[i].errors.n, 0);
    }
    runs.insert(runs.end(), records.begin(), records.end());
  }
  const auto alone = zdg::experiment_result(plan, c, runs, 1);
  const auto sweep = zdg::run_experiment(c);
  ASSERT_EQ(alone.runs.size(), sweep.runs.size());
  for (std::size_t i = 0; i < sweep.runs.size(); ++i) {
    const auto &a = alone.runs[i], &b = sweep.runs[i];
    EXPECT_EQ(a.shape, b.shape);
    EXPECT_EQ(a.estimator, b.estimator);
    EXPECT_EQ(a.h, b.h);
    EXPECT_EQ(a.translation, b.translation);
    EXPECT_EQ(a.offset, b.offset);
    EXPECT_EQ(a.errors.linf, b.errors.linf);
    EXPECT_EQ(a.errors.l2, b.errors.l2);
    EXPECT_EQ(a.errors.mean, b.errors.mean);
    EXPECT_EQ(a.errors.n, b.errors.n);
  }
  ASSERT_EQ(alone.fits.size(), sweep.fits.size());
  for (std::size_t i = 0; i < sweep.fits.size(); ++i) {
    EXPECT_EQ(alone.fits[i].fit.slope, sweep.fits[i].fit.slope);
    EXPECT_EQ(alone.fits[i].pass, sweep.fits[i].pass);
  }
}
