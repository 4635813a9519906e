// The II estimators on a user's volume (estimators/volume_ii.hpp) give the same numbers as the
// synthetic driver (the registry's ii-* estimators of convergence/) on the same digitization:
// the shape digitized by the driver is written into an image, estimated through the image
// path, compared with the shape's ground truth exactly as the driver does, and the error
// statistics are equal to the last bit.
#include <zdg/convergence/digitized_3d.hpp>
#include <zdg/convergence/estimator.hpp>
#include <zdg/convergence/shapes_3d.hpp>
#include <zdg/estimators/volume_ii.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace {

TEST(VolumeIIDriver, SameErrorsAsTheSyntheticDriverOnTheSameDigitization) {
  const auto shape = zdg::parse_shape("sphere9");
  const double h = 0.5;
  std::vector<double> t{0.123, -0.31, 0.05};
  auto box = *shape->bounding_box();
  for (std::size_t a = 0; a < 3; ++a) {
    box[a].first += t[a] - 2 * h;
    box[a].second += t[a] + 2 * h;
  }
  const zdg::RunInput in{*shape, h, t, box, 3.0, 1.0 / 3.0};
  const double R = in.k * std::pow(h, in.alpha);
  const auto mean_stats = zdg::find_estimator("ii-mean").run(in);
  const auto k2_stats = zdg::find_estimator("ii-k2").run(in);

  // The same digitization as an image.
  const auto d = zdg::detail::digitize_3d(in);
  const auto nx = d.box.hi.x - d.box.lo.x + 1, ny = d.box.hi.y - d.box.lo.y + 1,
             nz = d.box.hi.z - d.box.lo.z + 1;
  zdg::Image<std::uint8_t> img(zdg::Domain({nz, ny, nx}, {d.box.lo.z, d.box.lo.y, d.box.lo.x}));
  std::int64_t i = 0;
  for (auto z = d.box.lo.z; z <= d.box.hi.z; ++z)
    for (auto y = d.box.lo.y; y <= d.box.hi.y; ++y)
      for (auto x = d.box.lo.x; x <= d.box.hi.x; ++x) img[i++] = d.inside({x, y, z}) ? 1 : 0;
  const auto sf = zdg::image_surfels(img, 2);
  ASSERT_EQ(sf.size(), std::int64_t(d.surfels.size()));
  const auto H = zdg::volume_ii_mean_curvature(img, sf, h, R, 2);
  const auto P = zdg::volume_ii_principal_curvatures(img, sf, h, R, 2);

  // Errors against the truth at the projection of each surfel centre, in the driver's order.
  zdg::ErrorAccumulator mean_acc, k2_acc;
  const auto& s3 = dynamic_cast<const zdg::Shape3&>(*shape);
  for (const auto& s : zdg::detail::evaluated_surfels(d, R + 2 * h)) {
    const auto v = zdg::inner_voxel(s);
    const auto j = sf.find(
        zdg::surfel_code(sf.grid.index(v.x - d.box.lo.x, v.y - d.box.lo.y, v.z - d.box.lo.z),
                         zdg::orthogonal_axis(s), s.direct));
    ASSERT_GE(j, 0);
    const auto c = zdg::surfel_centre(s, h);
    const auto truth = s3.project({c.x - d.t.x, c.y - d.t.y, c.z - d.t.z});
    mean_acc.add(H[std::size_t(j)] - truth.mean);
    k2_acc.add(P[std::size_t(j)].k2 - truth.k2);
  }
  const auto m = mean_acc.stats(), k = k2_acc.stats();
  EXPECT_EQ(m.n, mean_stats.n);
  EXPECT_EQ(m.linf, mean_stats.linf);
  EXPECT_EQ(m.l2, mean_stats.l2);
  EXPECT_EQ(m.mean, mean_stats.mean);
  EXPECT_EQ(k.n, k2_stats.n);
  EXPECT_EQ(k.linf, k2_stats.linf);
  EXPECT_EQ(k.l2, k2_stats.l2);
  EXPECT_GT(m.n, 1000);
}

} // namespace
