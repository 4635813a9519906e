// The reconstruction estimators (convergence/estimators_reconstruction.cpp) and the samples
// sweeps of the driver (convergence/experiment.hpp). Oracles: the exact surface (projection),
// the Betti numbers of the solids (ball (1, 0, 0), solid torus (1, 1, 0)), power laws for
// the rate check in N, and the counts of the sweep syntaxes computed by hand.
#include <zdg/arith/error.hpp>
#include <zdg/convergence/estimator.hpp>
#include <zdg/convergence/experiment.hpp>
#include <zdg/convergence/fit.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>

namespace zdg {
namespace {

ErrorStats run_once(const std::string& shape_spec, const std::string& spec, std::int64_t n,
                    std::uint64_t seed = 1) {
  const auto shape = parse_shape(shape_spec);
  const EstimatorSpec es = parse_estimator_spec(spec);
  const EstimatorParameters p = resolve_parameters(es, std::nullopt, std::nullopt);
  RunInput in{*shape, 0, {0, 0, 0}, *shape->bounding_box(), p.k, p.alpha};
  in.choice = p.choice;
  in.samples = n;
  in.seed = seed;
  in.sigma = p.sigma;
  return find_estimator(es.name).run(in);
}

// Hoppe's planes from exact normals: the Hausdorff distance falls as N grows (h = sqrt(A / N)
// falls with it), and it stays below the grid step at each level.
TEST(ReconstructionEstimators, HausdorffFallsWithTheNumberOfSamplesOnTheSphere) {
  double previous = 1e9;
  for (std::int64_t n : {300, 1200, 4800}) {
    const ErrorStats e = run_once("sphere1", "recon-hausdorff:method=hoppe", n);
    const double h = std::sqrt(4 * std::numbers::pi / double(n));
    EXPECT_GT(e.n, n) << "one error per sample and per mesh vertex";
    EXPECT_LT(e.linf, h) << "N = " << n;
    EXPECT_LT(e.linf, previous) << "N = " << n;
    previous = e.linf;
  }
}

// Past a density every method gets the topology of the sphere and of the torus right.
TEST(ReconstructionEstimators, BettiNumbersRightOnSphereAndTorusPastADensity) {
  for (const char* method : {"hoppe", "imls", "winding"}) {
    EXPECT_EQ(run_once("sphere1", std::string("recon-betti:method=") + method, 2000).linf, 0)
        << method;
    EXPECT_EQ(run_once("torus", std::string("recon-betti:method=") + method, 3000).linf, 0)
        << method;
  }
}

// The mesh normals of a dense reconstruction point outward along the exact normals.
TEST(ReconstructionEstimators, NormalAnglesAreSmallOnADenseSphere) {
  const ErrorStats e = run_once("sphere1", "recon-normal:method=imls", 4000);
  EXPECT_GT(e.n, 100);
  EXPECT_LT(e.mean, 0.2);
  EXPECT_LT(e.linf, std::numbers::pi / 2) << "every triangle oriented outward";
}

TEST(ReconstructionEstimators, ParametersAndBadInput) {
  EXPECT_THROW(parse_estimator_spec("recon-hausdorff:method=marching"), InvalidArgument);
  EXPECT_THROW(parse_estimator_spec("recon-hausdorff:sigma=-1"), InvalidArgument);
  EXPECT_NO_THROW(parse_estimator_spec("recon-hausdorff:sigma=0"));
  EXPECT_EQ(parse_estimator_spec("recon-betti:sigma=0.1,method=imls").label(),
            "recon-betti:method=imls,sigma=0.1");
  EXPECT_THROW(run_once("sphere1", "recon-hausdorff", 5), InvalidArgument) << "too few points";
  EXPECT_THROW(run_once("cylinder", "recon-hausdorff", 500), InvalidArgument) << "cut by its box";
  // Rates: hoppe and imls without noise on a C^3 shape; none for the others or with noise.
  const auto sphere = parse_shape("sphere1");
  auto rate = [&](const std::string& spec) {
    const auto es = parse_estimator_spec(spec);
    return find_estimator(es.name).proven_rate(*sphere,
                                               resolve_parameters(es, std::nullopt, std::nullopt));
  };
  ASSERT_TRUE(rate("recon-hausdorff:method=imls"));
  EXPECT_EQ(rate("recon-hausdorff:method=hoppe")->slope, -0.5);
  EXPECT_FALSE(rate("recon-hausdorff:method=poisson"));
  EXPECT_FALSE(rate("recon-hausdorff:method=hoppe,sigma=0.01"));
  EXPECT_FALSE(rate("recon-betti"));
}

// The sweep syntaxes: exp:I0:I1:STEP gives round(exp(i / 10)); NMIN:NMAX:COUNT geometric.
TEST(SampleCounts, SyntaxesGiveTheStatedCounts) {
  EXPECT_EQ(parse_sample_counts("exp:60:70:5"), (std::vector<std::int64_t>{403, 665, 1097}));
  EXPECT_EQ(parse_sample_counts("100:1000:3"), (std::vector<std::int64_t>{100, 316, 1000}));
  EXPECT_EQ(parse_sample_counts("5,3,5"), (std::vector<std::int64_t>{3, 5}));
  EXPECT_EQ(parse_sample_counts("exp:0:3"), (std::vector<std::int64_t>{1}));
  for (const char* bad :
       {"0", "1.5", "exp:0:200", "exp:5:4", "1:2:3:4", "abc", "10:5:2", "200000000", ""}) {
    EXPECT_THROW(parse_sample_counts(bad), InvalidArgument) << bad;
  }
}

// The rate check in N: error = N^-a passes for a >= rate - tolerance in absolute value.
TEST(SampleCounts, RateCheckInSamplesIsSlopeAtMostTheRate) {
  std::vector<FitLevel> levels;
  for (double n : {100.0, 400.0, 1600.0}) levels.push_back({n, 3 / std::sqrt(n), 100});
  auto v = check_rate_in_samples(levels, -0.5, 0.1);
  EXPECT_TRUE(v.pass) << v.reason;
  EXPECT_NEAR(v.fit.slope, -0.5, 1e-12);
  v = check_rate_in_samples(levels, -1.0, 0.1);
  EXPECT_FALSE(v.pass);
  EXPECT_NE(v.reason.find("> expected -1 + tolerance 0.1"), std::string::npos) << v.reason;
  levels[1].h = 0;
  EXPECT_NE(check_rate_in_samples(levels, -0.5, 0.1).reason.find("N = 0"), std::string::npos);
}

// The driver over sample counts: the records carry N, results.csv gains the column `samples`
// (h empty), the fit is against log(N) with the verdict of the proven rate.
TEST(SampleCounts, DriverSweepsOverNAndWritesTheSamplesColumn) {
  ExperimentConfig c;
  c.shapes = {"sphere1"};
  c.estimators = {"recon-hausdorff:method=hoppe", "recon-betti:method=hoppe"};
  c.samples = parse_sample_counts("300,1200,4800");
  c.translations = 2;
  c.seed = 5;
  c.threads = 2;
  const auto r = run_experiment(c);
  ASSERT_EQ(r.runs.size(), 12u);
  EXPECT_EQ(r.runs.front().samples, 300);
  EXPECT_EQ(r.runs.front().h, 0);
  const FitRecord* hausdorff = nullptr;
  for (const auto& f : r.fits) {
    if (f.estimator == "recon-hausdorff:method=hoppe" && f.norm == "linf") hausdorff = &f;
  }
  ASSERT_NE(hausdorff, nullptr);
  EXPECT_EQ(hausdorff->hs, (std::vector<double>{300, 1200, 4800}));
  EXPECT_LT(hausdorff->fit.slope, -0.4);
  ASSERT_TRUE(hausdorff->pass.has_value());
  EXPECT_TRUE(*hausdorff->pass) << hausdorff->reason;
  std::ostringstream csv;
  write_results_csv(r, csv);
  const std::string text = csv.str();
  EXPECT_EQ(text.substr(0, text.find('\n')),
            "shape,estimator,h,translation,offset,k,alpha,linf,l2,mean,n,seconds,samples");
  EXPECT_NE(text.find("\"sphere1\",\"recon-betti:method=hoppe\",,1,\"0 0 0\",1,0,0,0,0,1,"),
            std::string::npos)
      << text;
  // Distinct repetitions are distinct samplings.
  EXPECT_NE(r.runs[0].errors.linf, r.runs[1].errors.linf);
}

TEST(SampleCounts, SweepsAreOverGridStepsOrSampleCounts) {
  ExperimentConfig c;
  c.shapes = {"sphere1"};
  c.estimators = {"recon-hausdorff"};
  c.hs = {0.5};
  EXPECT_THROW(plan_experiment(c), InvalidArgument) << "a sampled estimator with --h";
  c.samples = {100};
  EXPECT_THROW(plan_experiment(c), InvalidArgument) << "both";
  c.hs.clear();
  EXPECT_NO_THROW(plan_experiment(c));
  c.estimators = {"hausdorff"};
  EXPECT_THROW(plan_experiment(c), InvalidArgument) << "a digitization estimator with --samples";
}

} // namespace
} // namespace zdg
