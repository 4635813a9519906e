// The parameter-free integral invariants of the registry (Levallois, Coeurjolly, Lachaud,
// "Parameter-free and multigrid convergent digital curvature estimators", DGCI 2014; Levallois,
// PhD thesis 2015): the II estimators of estimators_2d.cpp (ii-curvature) and
// estimators_3d.cpp (ii-mean, ii-k1, ii-k2) with the ball radius read from the digitization,
// R = k l^2 h, l the mean digital length of the maximal segments of its contours (2D) or of
// the contours of its axis slices (3D) (estimators/ii_auto_radius.hpp), instead of k h^alpha.
//
// Theory. 2D (DGCI 2014, the convergence theorem of the parameter-free curvature estimator;
// thesis, Theorem "Convergence asymptotique de l'estimateur digital de courbure sans
// parametre"): X convex with C^3 boundary of bounded positive curvature: error O(h^{1/3}
// log^2(1/h)) (from Theta(h^{-1/3}) <= l <= Theta(h^{-1/3} log(1/h)), Lachaud 2006, de
// Vieilleville 2007, and the II theorem with R between Theta(h^{1/3}) and Theta(h^{1/3}
// log^2(1/h))); registered with slope 1/3, the log factor left to the statement. 3D: the same
// bound only under a conjecture on the lengths of the slice maximal segments (thesis, Conj.
// "slice-mdss-3d", Obs. for H, k1, k2): no proven rate.
#include <zdg/arith/error.hpp>
#include <zdg/convergence/digitized_2d.hpp>
#include <zdg/convergence/digitized_3d.hpp>
#include <zdg/convergence/estimator.hpp>
#include <zdg/convergence/ii_runs.hpp>
#include <zdg/estimators/ii_auto_radius.hpp>

#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace zdg {

namespace {

const char* const kLCL14 = "Levallois, Coeurjolly, Lachaud, DGCI 2014";

std::vector<EstimatorParameter> auto_radius_parameters() {
  return {{"k", "1/10", 0.0, 1e6,
           "radius factor: R = k l^2 h, l the mean digital length of the maximal segments"}};
}

// R/h above the II counters' limit, named with the mean length that gave it.
void check_radius(const std::string& name, double R, double h, const MaximalSegmentLengths& l) {
  if (R / h > 256) {
    std::ostringstream msg;
    msg << name << ": the parameter-free radius k l^2 h = " << R << " is " << R / h
        << " voxels (mean maximal-segment length l = " << l.mean
        << "), over the 256 the II counters accept; lower k or coarsen h";
    throw InvalidArgument(msg.str());
  }
}

ErrorStats run_ii_curvature_auto(const RunInput& in) {
  const detail::Digitized2 d = detail::digitize_2d(in);
  const auto lengths = mean_maximal_segment_length(d.contours);
  return detail::ii_curvature_errors(d, in.h, ii_auto_radius(lengths, in.k, in.h));
}

// The radius of the last digitization this thread saw: ii-mean-auto, ii-k1-auto and
// ii-k2-auto run one after the other on one thread (shared_computation), the first one
// digitizes and counts, the next ones find the radius here and the moments in the II cache.
using AutoKey = std::tuple<std::string, double, std::vector<double>,
                           std::vector<std::pair<double, double>>, double>;

template <detail::II3Quantity Q>
ErrorStats run_ii_3d_auto(const RunInput& in) {
  thread_local AutoKey last_key;
  thread_local double last_radius = 0;
  AutoKey key{in.shape.spec(), in.h, in.translation, in.box, in.k};
  if (last_radius > 0 && key == last_key) {
    return detail::ii_3d_errors(in, last_radius, Q, nullptr);
  }
  const detail::Digitized3 d = detail::digitize_3d(in);
  const auto lengths = mean_slice_maximal_segment_length(d.inside, d.box, d.surfels);
  const double R = ii_auto_radius(lengths, in.k, in.h);
  check_radius(Q == detail::II3Quantity::mean ? "ii-mean-auto"
               : Q == detail::II3Quantity::k1 ? "ii-k1-auto"
                                              : "ii-k2-auto",
               R, in.h, lengths);
  last_key = std::move(key);
  last_radius = R;
  return detail::ii_3d_errors(in, R, Q, &d);
}

EstimatorTheory auto_3d_theory() {
  return {"none proven: O(h^{1/3} log^2(1/h)) on convex C^3 surfaces only under a conjecture on "
          "the slice maximal-segment lengths (Levallois PhD 2015; " +
              std::string(kLCL14) + ")",
          {}};
}

} // namespace

namespace detail {

void register_ii_auto_estimators(std::vector<Estimator>& out) {
  out.push_back(
      {"ii-curvature-auto",
       2,
       "parameter-free integral-invariant curvature: ii-curvature with R = k l^2 h, l the mean "
       "length of the maximal segments of the contours",
       "curvature",
       auto_radius_parameters(),
       {"O(h^{1/3} log^2(1/h)) on convex C^3 shapes of positive curvature, parameter-free (" +
            std::string(kLCL14) + ")",
        [](const ShapeClass& c, const EstimatorParameters&) -> std::optional<ProvenRate> {
          if (c.c3 && c.convex && c.positive_curvature) {
            return ProvenRate{1.0 / 3.0, "O(h^{1/3} log^2(1/h))",
                              "X convex with C^3 boundary of bounded positive curvature, "
                              "R = k l^2 h (l the mean maximal-segment length)",
                              kLCL14};
          }
          return std::nullopt;
        }},
       run_ii_curvature_auto});
  const std::string tail = " with R = k l^2 h, l the mean length of the maximal segments of "
                           "the axis slices of the digital surface";
  out.push_back({"ii-mean-auto", 3,
                 "parameter-free integral-invariant mean curvature: ii-mean" + tail, "curvature",
                 auto_radius_parameters(), auto_3d_theory(), run_ii_3d_auto<II3Quantity::mean>,
                 "ii-3d-auto"});
  out.push_back({"ii-k1-auto", 3,
                 "parameter-free integral-invariant smaller principal curvature: ii-k1" + tail,
                 "curvature", auto_radius_parameters(), auto_3d_theory(),
                 run_ii_3d_auto<II3Quantity::k1>, "ii-3d-auto"});
  out.push_back({"ii-k2-auto", 3,
                 "parameter-free integral-invariant larger principal curvature: ii-k2" + tail,
                 "curvature", auto_radius_parameters(), auto_3d_theory(),
                 run_ii_3d_auto<II3Quantity::k2>, "ii-3d-auto"});
}

} // namespace detail

} // namespace zdg
