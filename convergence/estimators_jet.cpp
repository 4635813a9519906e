// Jet-fitting estimators of the registry (jet-normal, jet-mean, jet-k1, jet-k2): CGAL's
// osculating jets (estimators/jet_fitting.hpp) fitted to the surfel centres of the digitized
// shape in a ball of radius R = k h^alpha around each surfel, compared with the shape's
// ground truth at the projection of the surfel centre. The four share one fit per (shape, h,
// translation, R, degree, box), kept for the thread that runs them one after the other.
#include <zdg/arith/error.hpp>
#include <zdg/convergence/digitized_3d.hpp>
#include <zdg/convergence/estimator.hpp>
#include <zdg/estimators/jet_fitting.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <tuple>

namespace zdg {

namespace {

using detail::Digitized3;
using P3 = Point3<double>;

struct JetRun {
  std::vector<JetEstimate> estimates;
  std::vector<SurfacePoint3> truth;
};

using JetKey = std::tuple<std::string, double, std::vector<double>, double, double,
                          std::vector<std::pair<double, double>>>;

std::shared_ptr<const JetRun> jet_run(const RunInput& in) {
  const double R = in.k * std::pow(in.h, in.alpha);
  const double dg = in.degree > 0 ? in.degree : 2.0;
  if (dg != std::round(dg)) {
    throw InvalidArgument("jet fitting: the degree must be an integer from 1 to 4");
  }
  const int degree = static_cast<int>(dg);
  JetKey key{in.shape.spec(), in.h, in.translation, R, double(degree), in.box};
  thread_local JetKey last_key;
  thread_local std::shared_ptr<const JetRun> last;
  if (last && last_key == key) return last;
  last.reset();
  Digitized3 d = detail::digitize_3d(in);
  // The ball around an evaluated surfel stays clear of clipped box faces.
  const auto evaluated = detail::evaluated_surfels(d, R + 2 * in.h);
  std::vector<P3> centres;
  centres.reserve(d.surfels.size());
  for (const auto& s : d.surfels) centres.push_back(surfel_centre(s, in.h));
  // evaluated_surfels keeps the order of d.surfels: match the two sequences.
  std::vector<std::size_t> queries;
  std::vector<P3> outward;
  queries.reserve(evaluated.size());
  for (std::size_t i = 0, j = 0; i < d.surfels.size() && j < evaluated.size(); ++i) {
    if (d.surfels[i] == evaluated[j]) {
      queries.push_back(i);
      const auto n = trivial_normal(d.surfels[i]);
      outward.push_back({double(n.x), double(n.y), double(n.z)});
      ++j;
    }
  }
  auto run = std::make_shared<JetRun>();
  run->estimates = jet_fitting(centres, queries, outward, R, degree, 0);
  run->truth.reserve(queries.size());
  for (auto i : queries) {
    const auto c = centres[i];
    run->truth.push_back(d.shape->project({c.x - d.t.x, c.y - d.t.y, c.z - d.t.z}));
  }
  last_key = key;
  last = run;
  return run;
}

double line_angle(P3 a, P3 b) {
  const double cx = a.y * b.z - a.z * b.y, cy = a.z * b.x - a.x * b.z, cz = a.x * b.y - a.y * b.x;
  const double t =
      std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), a.x * b.x + a.y * b.y + a.z * b.z);
  return std::min(t, std::numbers::pi - t);
}

enum class JetQuantity { normal, mean, k1, k2 };

template <JetQuantity Q>
ErrorStats run_jet(const RunInput& in) {
  auto run = jet_run(in);
  ErrorAccumulator acc;
  std::size_t skipped = 0;
  for (std::size_t i = 0; i < run->estimates.size(); ++i) {
    const auto& e = run->estimates[i];
    const auto& t = run->truth[i];
    if (!e.ok) {
      ++skipped;
      continue;
    }
    if constexpr (Q == JetQuantity::normal) acc.add(line_angle(e.normal, t.normal));
    if constexpr (Q == JetQuantity::mean) acc.add(e.mean() - t.mean);
    if constexpr (Q == JetQuantity::k1) acc.add(e.k1 - t.k1);
    if constexpr (Q == JetQuantity::k2) acc.add(e.k2 - t.k2);
  }
  if (skipped > 0) {
    throw InvalidArgument("jet fitting: " + std::to_string(skipped) +
                          " surfels have fewer neighbours than the jet's coefficients at h = " +
                          std::to_string(in.h) + " (raise k or lower the degree)");
  }
  return acc.stats();
}

std::vector<EstimatorParameter> jet_parameters() {
  auto p = detail::radius_law_parameters();
  p.push_back({"degree", "2", 0.0, 4.0, "degree d of the fitted jet (1 to 4; Monge degree 2)"});
  return p;
}

EstimatorTheory no_proven_rate() {
  return {"no proven rate on digital surfaces (O(r^{d-k+1}) on exact samples at spacing r: "
          "Cazals, Pouget, CAGD 2005)",
          {}};
}

} // namespace

namespace detail {

void register_jet_estimators(std::vector<Estimator>& out) {
  out.push_back({"jet-normal", 3,
                 "normal of the osculating jet (CGAL Monge_via_jet_fitting) fitted to the surfel "
                 "centres in the ball of radius R = k h^alpha",
                 "angle (rad)", jet_parameters(), no_proven_rate(), run_jet<JetQuantity::normal>});
  out.push_back({"jet-mean", 3, "mean curvature of the osculating jet's Monge form", "curvature",
                 jet_parameters(), no_proven_rate(), run_jet<JetQuantity::mean>});
  out.push_back({"jet-k1", 3, "smaller principal curvature of the osculating jet", "curvature",
                 jet_parameters(), no_proven_rate(), run_jet<JetQuantity::k1>});
  out.push_back({"jet-k2", 3, "larger principal curvature of the osculating jet", "curvature",
                 jet_parameters(), no_proven_rate(), run_jet<JetQuantity::k2>});
  for (auto& e : out) {
    if (e.name.rfind("jet-", 0) == 0) e.shared_computation = "jet-3d";
  }
}

} // namespace detail

} // namespace zdg
