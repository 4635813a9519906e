// The 3D estimators of the registry: digitize the translated shape, track its boundary
// surfels, run the estimator of estimators/, and compare with the shape's ground truth at
// the projection xi of each surfel centre (errors per surfel; see papers/THEORY.md).
//
// The integral-invariant estimators (ii-mean, ii-gaussian, ii-k1, ii-k2, ii-normal,
// ii-directions) share one computation per (shape, h, translation, R, box): the ball
// moments at every surfel (estimators/ii_3d.hpp) and the ground truth, kept in a small
// cache (at most 512 MiB) so that a driver running several of them on the same
// digitization counts the balls once.
#include <zdg/arith/error.hpp>
#include <zdg/convergence/digitized_3d.hpp>
#include <zdg/convergence/estimator.hpp>
#include <zdg/convergence/ii_runs.hpp>
#include <zdg/estimators/gauss_volume.hpp>
#include <zdg/estimators/hausdorff.hpp>
#include <zdg/estimators/ii_3d.hpp>

#include <algorithm>
#include <cmath>
#include <list>
#include <memory>
#include <mutex>
#include <numbers>
#include <sstream>
#include <tuple>

namespace zdg {

namespace detail {

const Shape3& as_3d(const Shape& s) {
  const auto* p = dynamic_cast<const Shape3*>(&s);
  if (p == nullptr) throw InvalidArgument("shape '" + s.spec() + "' is not a 3D shape");
  return *p;
}

VoxelBox voxel_box(const std::vector<std::pair<double, double>>& box, double h) {
  if (box.size() != 3) throw InvalidArgument("a 3D run needs a box with 3 axes");
  double far = 0;
  for (const auto& [lo, hi] : box) far = std::max({far, std::abs(lo), std::abs(hi)});
  if (!(far / h < 1e9)) {
    std::ostringstream msg;
    msg << "grid step h = " << h << " is too small for the box";
    throw InvalidArgument(msg.str());
  }
  auto lo = [&](double v) { return static_cast<std::int64_t>(std::floor(v / h)) - 1; };
  auto hi = [&](double v) { return static_cast<std::int64_t>(std::ceil(v / h)) + 1; };
  VoxelBox b{{lo(box[0].first), lo(box[1].first), lo(box[2].first)},
             {hi(box[0].second), hi(box[1].second), hi(box[2].second)}};
  check_voxel_box(b);
  return b;
}

Digitized3 digitize_3d(const RunInput& in) {
  Digitized3 d;
  d.shape = &as_3d(in.shape);
  d.t = {in.translation.at(0), in.translation.at(1), in.translation.at(2)};
  d.h = in.h;
  d.box = voxel_box(in.box, in.h);
  d.inside = d.shape->digitize(in.h, d.t);
  // Seeds on 8 x 8 lines along x (the axes y = 0, z = 0 and 7 evenly spread rows each).
  std::vector<std::int64_t> ys{0}, zs{0};
  for (int i = 1; i <= 7; ++i) {
    ys.push_back(d.box.lo.y + (d.box.hi.y - d.box.lo.y) * i / 8);
    zs.push_back(d.box.lo.z + (d.box.hi.z - d.box.lo.z) * i / 8);
  }
  std::vector<Surfel> seeds;
  for (auto y : ys) {
    for (auto z : zs) {
      auto line = line_boundary_surfels(d.inside, d.box, y, z);
      seeds.insert(seeds.end(), line.begin(), line.end());
    }
  }
  d.surfels = track_surfaces(d.inside, d.box, seeds);
  for (const auto& s : d.surfels) {
    if (!d.box.contains(outer_voxel(s)))
      d.clipped[2 * orthogonal_axis(s) + (s.direct ? 1 : 0)] = true;
  }
  return d;
}

std::vector<Surfel> evaluated_surfels(const Digitized3& d, double margin) {
  // Face planes at the surfels between the extreme voxels of the box and the outside.
  const double lo[3] = {d.h * (double(d.box.lo.x) - 0.5), d.h * (double(d.box.lo.y) - 0.5),
                        d.h * (double(d.box.lo.z) - 0.5)};
  const double hi[3] = {d.h * (double(d.box.hi.x) + 0.5), d.h * (double(d.box.hi.y) + 0.5),
                        d.h * (double(d.box.hi.z) + 0.5)};
  std::vector<Surfel> out;
  out.reserve(d.surfels.size());
  for (const auto& s : d.surfels) {
    if (!d.box.contains(outer_voxel(s))) continue;
    const auto c = surfel_centre(s, d.h);
    const double x[3] = {c.x, c.y, c.z};
    bool near = false;
    for (int a = 0; a < 3; ++a) {
      near = near || (d.clipped[std::size_t(2 * a)] && x[a] - lo[a] < margin) ||
             (d.clipped[std::size_t(2 * a + 1)] && hi[a] - x[a] < margin);
    }
    if (!near) out.push_back(s);
  }
  return out;
}

} // namespace detail

namespace {

using detail::Digitized3;
using P3 = Point3<double>;

double angle(P3 a, P3 b) {
  const double cx = a.y * b.z - a.z * b.y, cy = a.z * b.x - a.x * b.z, cz = a.x * b.y - a.y * b.x;
  return std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), a.x * b.x + a.y * b.y + a.z * b.z);
}

// Angle between two lines (directions without orientation), in [0, pi/2].
double line_angle(P3 a, P3 b) {
  const double t = angle(a, b);
  return std::min(t, std::numbers::pi - t);
}

SurfacePoint3 truth_at(const Digitized3& d, const Surfel& s) {
  const auto c = surfel_centre(s, d.h);
  return d.shape->project({c.x - d.t.x, c.y - d.t.y, c.z - d.t.z});
}

ErrorStats run_gauss_volume(const RunInput& in) {
  const auto& shape = detail::as_3d(in.shape);
  auto volume = shape.volume();
  if (!volume) throw InvalidArgument("the volume of '" + in.shape.spec() + "' is not known");
  const VoxelBox box = detail::voxel_box(in.box, in.h);
  const P3 t{in.translation.at(0), in.translation.at(1), in.translation.at(2)};
  ErrorAccumulator acc;
  acc.add(gauss_volume(shape.digitize(in.h, t), box, in.h, 1).volume - *volume);
  return acc.stats();
}

// --- integral invariants, one computation shared by the six estimators ---------------------

struct IIRun {
  std::vector<Surfel> surfels;
  std::vector<SurfelBallMoments> moments;
  std::vector<SurfacePoint3> truth;
  double h = 0, R = 0;
  std::size_t bytes() const {
    return surfels.size() * (sizeof(Surfel) + sizeof(SurfelBallMoments) + sizeof(SurfacePoint3));
  }
};

using IIKey = std::tuple<std::string, double, std::vector<double>, double,
                         std::vector<std::pair<double, double>>>;

class IICache {
public:
  std::shared_ptr<const IIRun> get(const RunInput& in, double R, const Digitized3* digitized) {
    IIKey key{in.shape.spec(), in.h, in.translation, R, in.box};
    // The last run this thread used, even if other threads' runs evicted it since: run_plan
    // runs the estimators sharing it one after the other on one thread (a computation of the
    // finest levels of the CVIU 2014 sweep is up to 420 MB, most of the budget). Held
    // until the thread asks for another run or ends.
    thread_local IIKey last_key;
    thread_local std::shared_ptr<const IIRun> last;
    if (last && last_key == key) return last;
    auto keep = [&](std::shared_ptr<const IIRun> run) {
      last_key = key;
      last = run;
      return run;
    };
    {
      std::lock_guard<std::mutex> lock(mutex_);
      for (auto it = entries_.begin(); it != entries_.end(); ++it) {
        if (it->first == key) {
          entries_.splice(entries_.begin(), entries_, it);
          return keep(entries_.front().second);
        }
      }
    }
    last.reset(); // not held while computing the next one
    auto run = compute(in, R, digitized);
    std::lock_guard<std::mutex> lock(mutex_);
    entries_.emplace_front(key, run);
    std::size_t total = 0;
    for (auto it = entries_.begin(); it != entries_.end();) {
      total += it->second->bytes();
      if (total > kBudget && it != entries_.begin()) {
        it = entries_.erase(it);
      } else {
        ++it;
      }
    }
    return keep(run);
  }

private:
  static constexpr std::size_t kBudget = std::size_t{512} << 20;
  std::mutex mutex_;
  std::list<std::pair<IIKey, std::shared_ptr<const IIRun>>> entries_;

  static std::shared_ptr<const IIRun> compute(const RunInput& in, double R,
                                              const Digitized3* digitized) {
    const std::int64_t r2 = ii_digital_radius2(R, in.h);
    Digitized3 own;
    if (digitized == nullptr) own = detail::digitize_3d(in);
    const Digitized3& d = digitized != nullptr ? *digitized : own;
    auto run = std::make_shared<IIRun>();
    run->h = in.h;
    run->R = R;
    // The ball of radius R around a surfel must not reach a clipped face.
    run->surfels = detail::evaluated_surfels(d, R + 2 * in.h);
    run->moments = ii_surfel_moments(d.inside, d.box, run->surfels, r2, 1, true).moments;
    run->truth.reserve(run->surfels.size());
    for (const auto& s : run->surfels) run->truth.push_back(truth_at(d, s));
    return run;
  }
};

IICache& ii_cache() {
  static IICache cache;
  return cache;
}

using IIQuantity = detail::II3Quantity;

// Principal directions are compared where the true curvatures differ by at least this
// fraction of the larger one and by kDirectionGapAbsolute (curvature units, about a tenth
// of the curvature of the [-10,10]^3 shapes: their flat umbilics, like the face centres of
// rcube, have k1 = k2 = 0). Near umbilics the directions are undefined: the proven rate
// is O(h^{1/3}) / |k1 - k2|.
constexpr double kDirectionGap = 0.25, kDirectionGapAbsolute = 0.02;

template <IIQuantity Q>
ErrorStats ii_errors(const RunInput& in, double R, const Digitized3* digitized) {
  auto run = ii_cache().get(in, R, digitized);
  ErrorAccumulator acc;
  for (std::size_t i = 0; i < run->surfels.size(); ++i) {
    const SurfacePoint3& t = run->truth[i];
    const SurfelBallMoments& m = run->moments[i];
    if constexpr (Q == IIQuantity::mean) {
      acc.add(ii_mean_curvature_from_moments(m, run->h, run->R) - t.mean);
    } else {
      const auto pc = ii_principal_curvatures_from_moments(m, run->surfels[i], run->h, run->R);
      if constexpr (Q == IIQuantity::gaussian) acc.add(pc.gaussian() - t.gaussian);
      if constexpr (Q == IIQuantity::k1) acc.add(pc.k1 - t.k1);
      if constexpr (Q == IIQuantity::k2) acc.add(pc.k2 - t.k2);
      if constexpr (Q == IIQuantity::normal) acc.add(line_angle(pc.normal, t.normal));
      if constexpr (Q == IIQuantity::directions) {
        const double gap = t.k2 - t.k1;
        if (gap >= kDirectionGap * std::max(std::abs(t.k1), std::abs(t.k2)) &&
            gap >= kDirectionGapAbsolute) {
          // Matched by value: the direction of the smaller estimated curvature against the
          // true direction of the smaller curvature, and likewise for the larger.
          acc.add(std::max(line_angle(pc.d1, t.d1), line_angle(pc.d2, t.d2)));
        }
      }
    }
  }
  return acc.stats();
}

template <IIQuantity Q>
ErrorStats run_ii(const RunInput& in) {
  return ii_errors<Q>(in, in.k * std::pow(in.h, in.alpha), nullptr);
}

// --- theory (papers/THEORY.md, "Rates") -----------------------------------------------------

const char* const kCLL = "Coeurjolly, Lachaud, Levallois, CVIU 2014";
const char* const kLCL = "Lachaud, Coeurjolly, Levallois 2017";

// The integral-invariant rates: slope with R = k h^{1/3} on C^3 surfaces with positive reach
// (and away from umbilics for the principal directions).
EstimatorTheory ii_theory(double slope, const std::string& statement, const std::string& source,
                          bool needs_non_umbilic) {
  const std::string hypotheses =
      std::string("C^3 surface with positive reach, R = k h^{1/3} (R below half the reach)") +
      (needs_non_umbilic ? ", away from umbilics (k1 != k2)" : "");
  return {statement + " with R = k h^{1/3} on C^3 surfaces with positive reach (" + source + ")",
          [=](const ShapeClass& c, const EstimatorParameters& p) -> std::optional<ProvenRate> {
            if (c.c3 && detail::is_one_third(p.alpha) && !(needs_non_umbilic && c.umbilic)) {
              return ProvenRate{slope, statement, hypotheses, source};
            }
            return std::nullopt;
          }};
}

} // namespace

namespace detail {

ErrorStats ii_3d_errors(const RunInput& in, double radius, II3Quantity quantity,
                        const Digitized3* digitized) {
  switch (quantity) {
  case II3Quantity::mean:
    return ii_errors<IIQuantity::mean>(in, radius, digitized);
  case II3Quantity::gaussian:
    return ii_errors<IIQuantity::gaussian>(in, radius, digitized);
  case II3Quantity::k1:
    return ii_errors<IIQuantity::k1>(in, radius, digitized);
  case II3Quantity::k2:
    return ii_errors<IIQuantity::k2>(in, radius, digitized);
  case II3Quantity::normal:
    return ii_errors<IIQuantity::normal>(in, radius, digitized);
  case II3Quantity::directions:
    return ii_errors<IIQuantity::directions>(in, radius, digitized);
  }
  throw Error("ii_3d_errors: unknown quantity");
}

void register_3d_estimators(std::vector<Estimator>& out) {
  out.push_back(
      {"gauss-volume",
       3,
       "h^3 times the number of digitized voxels (counted in the box)",
       "volume",
       {},
       {"O(h^{243/158}) on C^3 strictly convex bodies (Kraetzel; Guo), O(h) on convex bodies",
        [](const ShapeClass& c, const EstimatorParameters&) -> std::optional<ProvenRate> {
          if (c.c3 && c.convex && c.positive_curvature) {
            return ProvenRate{243.0 / 158.0, "O(h^{243/158})",
                              "X convex with C^3 boundary of positive Gaussian curvature",
                              "Kraetzel; Guo (lattice points in smooth convex bodies)"};
          }
          if (c.convex) return ProvenRate{1.0, "O(h)", "X convex", "lattice-point theory"};
          return std::nullopt;
        }},
       run_gauss_volume});
  out.push_back({"ii-mean", 3,
                 "integral-invariant mean curvature 8/(3R) - 4V/(pi R^4) at every surfel "
                 "(inner/outer voxel average)",
                 "curvature", radius_law_parameters(),
                 ii_theory(1.0 / 3.0, "O(h^{1/3})", kCLL, false), run_ii<IIQuantity::mean>});
  out.push_back({"ii-gaussian", 3, "integral-invariant Gaussian curvature k1 k2 at every surfel",
                 "curvature^2", radius_law_parameters(),
                 ii_theory(1.0 / 3.0, "O(h^{1/3})", std::string(kCLL) + ", Thm 6", false),
                 run_ii<IIQuantity::gaussian>});
  out.push_back({"ii-k1", 3,
                 "integral-invariant smaller principal curvature k1 (covariance eigenvalues)",
                 "curvature", radius_law_parameters(),
                 ii_theory(1.0 / 3.0, "O(h^{1/3})", std::string(kCLL) + ", Thm 6", false),
                 run_ii<IIQuantity::k1>});
  out.push_back({"ii-k2", 3,
                 "integral-invariant larger principal curvature k2 (covariance eigenvalues)",
                 "curvature", radius_law_parameters(),
                 ii_theory(1.0 / 3.0, "O(h^{1/3})", std::string(kCLL) + ", Thm 6", false),
                 run_ii<IIQuantity::k2>});
  out.push_back({"ii-normal", 3, "integral-invariant normal (smallest covariance eigenvector)",
                 "angle (rad)", radius_law_parameters(),
                 ii_theory(2.0 / 3.0, "O(h^{2/3})", kLCL, false), run_ii<IIQuantity::normal>});
  out.push_back({"ii-directions", 3,
                 "integral-invariant principal directions matched by value (max of the two "
                 "line angles; surfels where k2 - k1 < max(0.1 max |k|, 0.01) are skipped)",
                 "angle (rad)", radius_law_parameters(),
                 ii_theory(1.0 / 3.0, "O(h^{1/3}) / |k1 - k2|", kLCL, true),
                 run_ii<IIQuantity::directions>});
  for (auto& e : out) {
    if (e.name.rfind("ii-", 0) == 0 && e.dimension == 3) e.shared_computation = "ii-3d";
  }
}

} // namespace detail

} // namespace zdg
