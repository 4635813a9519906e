#include <zdg/estimators/contour_estimators.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/estimators/binomial_convolver.hpp>
#include <zdg/estimators/contour_ball_count.hpp>
#include <zdg/estimators/gauss_area.hpp>
#include <zdg/estimators/ii_curvature.hpp>
#include <zdg/estimators/lambda_mst.hpp>
#include <zdg/estimators/mlp_length.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <string>

namespace zdg {

namespace {

Box2 image_box(const Image<std::uint8_t>& image) {
  if (image.dim() != 2)
    throw InvalidArgument("a 2D image is needed (got " + std::to_string(image.dim()) + "-D)");
  const auto& d = image.domain();
  return Box2{{d.lower(1), d.lower(0)}, {d.upper(1), d.upper(0)}};
}

// Whether the binomial mask of order n fits a contour of N linels (binomial_convolver's own
// condition).
bool mask_fits(long n, long N) {
  const long reach = std::min(n / 2, static_cast<long>(5.0 * std::sqrt(double(n))) + 2);
  return 2 * reach + 2 < N;
}

} // namespace

BinaryImageSet2::BinaryImageSet2(const Image<std::uint8_t>& image)
    : GaussDigitization2(image_box(image)), data_(image.values().data()),
      nx_(image.domain().extent(1)), lower_{image.domain().lower(1), image.domain().lower(0)} {}

bool BinaryImageSet2::inside(const Pixel& z) const {
  return data_[(z.y - lower_.y) * nx_ + (z.x - lower_.x)] != 0;
}

ContourEstimates contour_estimates(const Image<std::uint8_t>& image, const ImageContours& contours,
                                   const ContourEstimateRequest& request, double h, double R,
                                   unsigned threads) {
  if (!(h > 0)) throw InvalidArgument("contour estimators: grid step h must be > 0");
  if ((request.ii_curvature || request.bc_tangent) && !(R > 0))
    throw InvalidArgument("contour estimators: radius R must be > 0");
  const BinaryImageSet2 set(image);
  const auto& cs = contours.contours;
  const auto n = static_cast<std::int64_t>(cs.size());
  ContourEstimates out;
  if (request.gauss_area) out.gauss_area = gauss_area(cs, h);
  if (request.ii_curvature) out.ii_curvature.resize(cs.size());
  if (request.bc_tangent) {
    out.bc_tangent.resize(cs.size());
    const double r = R / h;
    if (!(r * r < 1e9)) throw InvalidArgument("contour estimators: R / h too large for bc-tangent");
    long m = std::max(2L, static_cast<long>(std::lround(r * r)));
    out.bc_mask_order = m % 2 == 0 ? m : m + 1;
  }
  if (request.lmst_tangent) out.lmst_tangent.resize(cs.size());
  if (request.mlp_length) out.mlp_length.resize(cs.size());
  std::atomic<std::int64_t> lowered{0}, skipped{0};
  const unsigned workers = worker_count(threads, n);
  // Ball counters are not thread-safe: a task borrows one from a pool (built on demand, at
  // most one per worker) and gives it back.
  std::mutex pool_mutex;
  std::vector<std::unique_ptr<ContourBallCounter>> pool;
  parallel_for(n, workers, [&](std::int64_t c) {
    const DigitalContour& contour = cs[static_cast<std::size_t>(c)];
    if (request.ii_curvature) {
      std::unique_ptr<ContourBallCounter> counter;
      {
        std::lock_guard<std::mutex> lock(pool_mutex);
        if (!pool.empty()) {
          counter = std::move(pool.back());
          pool.pop_back();
        }
      }
      if (!counter) counter = std::make_unique<ContourBallCounter>(set, cs, R / h);
      out.ii_curvature[std::size_t(c)] = ii_curvature(*counter, contour, h, R);
      std::lock_guard<std::mutex> lock(pool_mutex);
      pool.push_back(std::move(counter));
    }
    if (request.bc_tangent) {
      long order = out.bc_mask_order;
      const long N = static_cast<long>(contour.size());
      while (order > 2 && !mask_fits(order, N)) order -= 2;
      if (mask_fits(order, N)) {
        if (order != out.bc_mask_order) ++lowered;
        out.bc_tangent[std::size_t(c)] = binomial_convolver(contour, h, order).tangent;
      } else {
        ++skipped;
        const double nan = std::numeric_limits<double>::quiet_NaN();
        out.bc_tangent[std::size_t(c)].assign(contour.size(), Point2<double>{nan, nan});
      }
    }
    if (request.lmst_tangent)
      out.lmst_tangent[std::size_t(c)] = lambda_mst_tangents(contour.pointels(), true);
    if (request.mlp_length) out.mlp_length[std::size_t(c)] = mlp_length(contour, h);
  });
  out.bc_lowered = lowered;
  out.bc_skipped = skipped;
  return out;
}

} // namespace zdg
