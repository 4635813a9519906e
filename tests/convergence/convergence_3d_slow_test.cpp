// Slow sweeps (label "slow"): the fitted l_inf slopes of the 3D estimators and of the
// Hausdorff distance over finer grid steps and random translations meet their proven rates
// (papers/THEORY.md) on the finest levels, and the Lachaud-Thibert bound holds at every level.
#include "tests/support/experiments.hpp"
#include <zdg/convergence/experiment.hpp>

#include <gtest/gtest.h>

namespace {

using zdg::test::expect_all_linf_pass;
using zdg::test::sweep;

TEST(Convergence3dSlow, IntegralInvariantCurvaturesSphereAndGoursat) {
  expect_all_linf_pass(sweep({"sphere9", "goursat"}, {"ii-mean", "ii-k1", "ii-k2", "ii-normal"},
                             "exp:8:22:2", 2, 6, "3"));
}

TEST(Convergence3dSlow, HausdorffBoundIn2dAnd3d) {
  auto r = sweep({"sphere9", "torus", "ellipse:20,7", "flower:20,7,6"},
                 {"hausdorff", "hausdorff-rel"}, "exp:5:25:2", 3, 0);
  expect_all_linf_pass(r);
  for (const auto& run : r.runs) {
    if (run.estimator == "hausdorff-rel") {
      EXPECT_LE(run.errors.linf, 1.0) << run.shape << " h = " << run.h;
    }
  }
}

} // namespace
