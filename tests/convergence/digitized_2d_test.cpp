#include <zdg/convergence/digitized_2d.hpp>

#include <zdg/convergence/shape.hpp>
#include <zdg/estimators/ii_curvature.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace {

struct Digitized {
  std::unique_ptr<zdg::Shape> shape;
  zdg::detail::Digitized2 d;
};

Digitized digitize(const std::string& spec, double h, std::vector<double> t = {0.0, 0.0}) {
  Digitized r;
  r.shape = zdg::parse_shape(spec);
  auto box = r.shape->bounding_box().value_or(
      std::vector<std::pair<double, double>>{{-3.0, 3.0}, {-3.0, 3.0}});
  for (std::size_t a = 0; a < 2; ++a) {
    box[a].first += t[a] - 2 * h;
    box[a].second += t[a] + 2 * h;
  }
  zdg::RunInput in{*r.shape, h, t, box, 5.0, 1.0 / 3.0};
  r.d = zdg::detail::digitize_2d(in);
  return r;
}

// Pixels of the digitization, by enumeration of the box.
std::int64_t brute_pixels(const zdg::GaussDigitization2& set) {
  std::int64_t n = 0;
  for (std::int64_t y = set.box().lo.y; y <= set.box().hi.y; ++y) {
    for (std::int64_t x = set.box().lo.x; x <= set.box().hi.x; ++x) {
      n += set.contains(zdg::Pixel{x, y}) ? 1 : 0;
    }
  }
  return n;
}

TEST(Digitized2d, CertifiedBoundaryIsTheWholeBoundary) {
  // Topological faithfulness (Latecki-Conrad-Gross; Stelldinger-Koethe) at h <= reach / 2:
  // the one certified contour encloses every pixel of the digitization (oracle: enumeration).
  struct Case {
    const char* spec;
    double h;
  };
  for (Case c : {Case{"ellipse:3,2", 0.05}, Case{"ball:2", 0.37}, Case{"flower:3,1,5", 0.04},
                 Case{"accflower:3,1/2,1.0132118364233778", 0.004}}) {
    Digitized r = digitize(c.spec, c.h, {0.3 * c.h, -0.2 * c.h});
    ASSERT_TRUE(r.d.complete) << c.spec;
    EXPECT_EQ(r.d.contours.front().twice_signed_area(), 2 * brute_pixels(*r.d.set)) << c.spec;
  }
}

TEST(Digitized2d, NoCertificateOutsideTheTheorem) {
  EXPECT_FALSE(digitize("ellipse:20,7", 2.0).d.complete); // h > reach / 2 = 1.225
  EXPECT_TRUE(digitize("ellipse:20,7", 1.2).d.complete);
  EXPECT_FALSE(digitize("polygon:0,0,4,0,0,3", 0.1).d.complete); // corners: reach 0
  EXPECT_FALSE(digitize("accflower:20,5,5", 0.01).d.complete);   // corner at t = +-pi
  EXPECT_FALSE(digitize("poly:x^2+y^2-4", 0.1).d.complete);      // reach unknown
}

TEST(Digitized2d, CertifiedIiCurvatureEqualsTheIncrementalCounts) {
  // Flower at h = 0.02 (certified): Green counts over the contour and symmetric-difference
  // counts with the predicate give identical curvatures.
  Digitized r = digitize("flower:20,7,6", 0.02, {0.004, -0.007});
  ASSERT_TRUE(r.d.complete);
  const double h = 0.02, radius = 5 * std::cbrt(h);
  zdg::ContourBallCounter counter(*r.d.set, r.d.contours, radius / h);
  EXPECT_EQ(zdg::ii_curvature(counter, r.d.contours.front(), h, radius),
            zdg::ii_curvature(*r.d.set, r.d.contours.front(), h, radius));
}

} // namespace
