// The boundary-distance estimators of the registry, in 2D and 3D (dimension 0: the shape's):
//   hausdorff      d_i = max |p - xi(p)| over the sampled points p of the boundary element i
//                  of the digitization: a linel's midpoint and its two pointels in 2D, a
//                  surfel's centre and its four pointels in 3D (xi: nearest point of the true
//                  boundary). l_inf is the one-sided Hausdorff distance from dX_h to dX sampled
//                  at the cell vertices and centres, O(h) (Lachaud-Thibert 2016). The centres
//                  alone stay within h / 2 (the surface crosses the segment between the inner
//                  and the outer voxel); the pointels reach farther.
//   hausdorff-rel  d_i / (sqrt(d) h / 2): l_inf <= 1 is the bound of the same theorem
//                  (for h < 2 rho / sqrt(d), rho the reach).
// Boundary elements on the box (outer pixel or voxel outside it, for shapes the box clips)
// carry no error. The 2D contours are found as in estimators_2d.cpp (9 rows and columns).
#include <zdg/arith/error.hpp>
#include <zdg/convergence/digitized_2d.hpp>
#include <zdg/convergence/digitized_3d.hpp>
#include <zdg/convergence/estimator.hpp>
#include <zdg/estimators/hausdorff.hpp>
#include <zdg/kernel/curves/digital_contour.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace zdg {

namespace {

std::vector<double> distances_2d(const RunInput& in) {
  const detail::Digitized2 d = detail::digitize_2d(in);
  const auto* shape = d.shape;
  const Box2& box = d.box;
  const Point2<double> t = d.t;
  const ContourEmbedding& embed = d.embed;
  std::vector<Point2<double>> centres;
  for (const auto& c : d.contours) {
    Pixel p = c.start;
    for (auto code : c.codes) {
      Pixel s = freeman_step(code);
      const Pixel next{p.x + s.x, p.y + s.y};
      if (box.contains(DigitalContour::outer_pixel(p, code))) {
        for (auto m : {embed.linel_midpoint(p, code), embed.pointel(p), embed.pointel(next)}) {
          centres.push_back({m.x - t.x, m.y - t.y});
        }
      }
      p = next;
    }
  }
  return projection_distances(centres, [&](Point2<double> q) { return shape->project(q).point; });
}

std::vector<double> distances_3d(const RunInput& in) {
  detail::Digitized3 d = detail::digitize_3d(in);
  std::vector<Point3<double>> centres;
  for (const auto& s : detail::evaluated_surfels(d, 0.0)) {
    const auto c = surfel_centre(s, in.h);
    centres.push_back({c.x - d.t.x, c.y - d.t.y, c.z - d.t.z});
    for (const auto& k : surfel_pointels(s)) {
      const auto q = embed_cell(k, in.h);
      centres.push_back({q.x - d.t.x, q.y - d.t.y, q.z - d.t.z});
    }
  }
  return projection_distances(centres, [&](Point3<double> q) { return d.shape->project(q).point; });
}

template <bool Ratio>
ErrorStats run_hausdorff(const RunInput& in) {
  const int dim = in.shape.dimension();
  auto dist = dim == 2 ? distances_2d(in) : distances_3d(in);
  const double scale = Ratio ? 1.0 / hausdorff_bound(dim, in.h) : 1.0;
  // One error per boundary element: the largest distance of its sampled points.
  const std::size_t per = dim == 2 ? 3 : 5;
  ErrorAccumulator acc;
  for (std::size_t i = 0; i + per <= dist.size(); i += per) {
    acc.add(*std::max_element(dist.begin() + std::ptrdiff_t(i),
                              dist.begin() + std::ptrdiff_t(i + per)) *
            scale);
  }
  return acc.stats();
}

} // namespace

namespace detail {

void register_hausdorff_estimators(std::vector<Estimator>& out) {
  out.push_back(
      {"hausdorff",
       0,
       "largest distance of the centre and the pointels of each boundary element (linel / "
       "surfel) to the true boundary, 2D or 3D; l_inf <= sqrt(d) h / 2 (Lachaud-Thibert 2016)",
       "length",
       {},
       {"O(h): at most sqrt(d) h / 2 for h < 2 rho / sqrt(d) when the reach exceeds rho "
        "(Lachaud, Thibert, JMIV 2016)",
        [](const ShapeClass& c, const EstimatorParameters&) -> std::optional<ProvenRate> {
          if (c.c3) {
            return ProvenRate{1.0, "O(h): at most sqrt(d) h / 2",
                              "reach > rho (C^3 boundary), h < 2 rho / sqrt(d)",
                              "Lachaud, Thibert, JMIV 2016"};
          }
          return std::nullopt;
        }},
       run_hausdorff<false>});
  out.push_back(
      {"hausdorff-rel",
       0,
       "the same distances divided by the bound sqrt(d) h / 2 (the bound holds when "
       "l_inf <= 1), 2D or 3D",
       "ratio",
       {},
       {"none: a ratio to the Lachaud-Thibert bound, read as l_inf <= 1, not a slope", {}},
       run_hausdorff<true>});
}

} // namespace detail

} // namespace zdg
