#include <zdg/kernel/calculus/hodge_star.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/estimators/digital_integration.hpp>

#include "tests/support/image_complex.hpp"
#include "tests/support/tower.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <cmath>
#include <numeric>

namespace {

using zdg::CellMeasure;
using zdg::Point3;

double total(const std::vector<double>& v) {
  return std::accumulate(v.begin(), v.end(), 0.0);
}

TEST(HodgeStar, CubicalIsAllOnes) {
  const auto c = zdg::test::image_complex(zdg::test::ring_torus()).complex;
  const auto h = zdg::hodge_stars(c, CellMeasure::cubical);
  for (const auto* v : {&h.star0, &h.star1, &h.star2})
    for (double x : *v) EXPECT_EQ(x, 1.0);
  EXPECT_EQ(h.star0.size(), std::size_t(c.pointel_count()));
  EXPECT_EQ(h.star1.size(), std::size_t(c.linel_count()));
  EXPECT_EQ(h.star2.size(), std::size_t(c.surfel_count()));
}

// With the elementary normals as estimates every measure is Euclidean (lattice: h = 1).
TEST(HodgeStar, ElementaryNormalsGiveTheEuclideanMeasures) {
  const auto c = zdg::test::image_complex(zdg::test::double_ring()).complex;
  const auto h = zdg::hodge_stars(c, CellMeasure::corrected_clamped, c.normals);
  for (double x : h.star1) EXPECT_DOUBLE_EQ(x, 1.0);
  for (double x : h.star2) EXPECT_DOUBLE_EQ(x, 1.0);
  for (std::size_t p = 0; p < h.star0.size(); ++p) EXPECT_GT(h.star0[p], 0.0);
  EXPECT_DOUBLE_EQ(total(h.star0), double(c.surfel_count()));
}

// Random unit normals: |s| is the weight of digital integration (estimators/
// digital_integration.hpp), clamped at 0 or absolute; the surfels, the dual faces of the
// pointels and the diamonds of the linels each sum to the corrected area.
TEST(HodgeStar, CorrectedMeasuresAreTheDigitalIntegrationWeights) {
  zdg::test::check_property([] {
    const auto v = *zdg::test::small_volume(4);
    const auto c = zdg::test::image_complex(v).complex;
    std::vector<Point3<double>> n;
    for (std::int64_t s = 0; s < c.surfel_count(); ++s) {
      const double a = *rc::gen::inRange(-1000, 1000), b = *rc::gen::inRange(-1000, 1000),
                   d = *rc::gen::inRange(1, 1000);
      const double l = std::sqrt(a * a + b * b + d * d);
      n.push_back({a / l, b / l, d / l});
    }
    const auto w = zdg::surfel_weights(zdg::surfel_measure(n, c.normals), c.areas);
    for (const auto m : {CellMeasure::corrected_clamped, CellMeasure::corrected_absolute}) {
      const auto h = zdg::hodge_stars(c, m, n);
      double area = 0;
      for (std::size_t s = 0; s < w.size(); ++s) {
        const double want =
            m == CellMeasure::corrected_clamped ? std::max(0.0, w[s]) : std::abs(w[s]);
        RC_ASSERT(h.surfel_measure[s] == want);
        const bool star_ok = want > 0 ? h.star2[s] == 1 / want : std::isinf(h.star2[s]);
        RC_ASSERT(star_ok);
        area += want;
      }
      RC_ASSERT(std::abs(total(h.star0) - area) <= 1e-9 * (1 + area));
      double diamonds = 0;
      for (std::size_t e = 0; e < h.star1.size(); ++e)
        diamonds += h.star1[e] * h.linel_measure[e] * h.linel_measure[e] / 2;
      RC_ASSERT(std::abs(diamonds - area) <= 1e-9 * (1 + area));
    }
  });
}

TEST(HodgeStar, BadNormals) {
  const auto c = zdg::test::image_complex(zdg::test::ring_torus()).complex;
  EXPECT_THROW(zdg::hodge_stars(c, CellMeasure::corrected_absolute, {}), zdg::InvalidArgument);
  auto n = c.normals;
  n[3].x = std::nan("");
  EXPECT_THROW(zdg::hodge_stars(c, CellMeasure::corrected_absolute, n), zdg::InvalidArgument);
}

} // namespace
