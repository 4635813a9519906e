// The Python module zdg._zdg, part 1: the exception mapping, the exact arithmetic on Python
// ints of any size (continued fractions, Christoffel words, floor sums, DSS recognition, DSL
// subsegments) and the convergence experiments. Part 2 (arrays.cpp): numpy arrays.
//
// Every exact entry point is "exact by escalation" (arith/escalate.hpp): it computes on int64,
// then int128, then BigInt, and says which type served ("integer_type"), so no OverflowError
// escapes it. zdg::InvalidArgument becomes ValueError, zdg::IoError OSError, and a remaining
// zdg::OverflowError (a fixed-width entry point) OverflowError, with the library's one-line
// message (the one the command line prints).
#include "python/common.hpp"

#include <zdg/arith/dsl_subsegment.hpp>
#include <zdg/arith/dss_recognizer.hpp>
#include <zdg/arith/error.hpp>
#include <zdg/arith/escalate.hpp>
#include <zdg/arith/rational.hpp>
#include <zdg/convergence/config.hpp>
#include <zdg/convergence/experiment.hpp>
#include <zdg/kernel/curves/maximal_segments.hpp>
#include <zdg/kernel/hulls/convex_body_hull.hpp>
#include <zdg/kernel/hulls/lattice_hull_2d.hpp>
#include <zdg/kernel/hulls/lattice_hull_3d.hpp>
#include <zdg/kernel/images/rigid_motion.hpp>
#include <zdg/kernel/io/output_files.hpp>
#include <zdg/kernel/surfaces/digital_plane_recognition.hpp>
#include <zdg/kernel/surfaces/plane_probing.hpp>
#include <zdg/operations/arith_operations.hpp>
#include <zdg/operations/convex_operations.hpp>
#include <zdg/operations/dss_operations.hpp>

#include <pybind11/stl.h>

#include <algorithm>
#include <initializer_list>
#include <string>
#include <vector>

namespace zdg::python {

namespace {

std::string served(IntKind k) {
  return std::string(to_string(k));
}

py::tuple fraction_to_py(const BigInt& p, const BigInt& q) {
  return py::make_tuple(bigint_to_py(p), bigint_to_py(q));
}

py::dict cf(py::handle p_obj, py::handle q_obj) {
  const Fraction<BigInt> f{py_to_bigint(p_obj, "cf: p"), py_to_bigint(q_obj, "cf: q")};
  const auto r = [&] {
    py::gil_scoped_release release;
    return continued_fraction_operation(f);
  }();
  py::list terms, conv;
  for (const auto& t : r.terms) terms.append(bigint_to_py(t));
  for (const auto& [a, b] : r.convergents) conv.append(fraction_to_py(a, b));
  py::dict d;
  d["terms"] = terms;
  d["convergents"] = conv;
  d["integer_type"] = served(r.served);
  return d;
}

py::dict christoffel(py::handle p_obj, py::handle q_obj, bool upper, bool word) {
  const ChristoffelOptions o{
      {py_to_bigint(p_obj, "christoffel: p"), py_to_bigint(q_obj, "christoffel: q")}, upper, word};
  const auto r = [&] {
    py::gil_scoped_release release;
    return christoffel_operation(o);
  }();
  py::dict d;
  d["p"] = bigint_to_py(r.p);
  d["q"] = bigint_to_py(r.q);
  d["word"] = word ? py::object(py::str(r.letters)) : py::object(py::none());
  d["standard_factorization"] =
      r.factorization ? py::object(py::make_tuple(r.factorization->first, r.factorization->second))
                      : py::object(py::none());
  d["parents"] =
      r.parents
          ? py::object(py::make_tuple(fraction_to_py(r.parents->first.p, r.parents->first.q),
                                      fraction_to_py(r.parents->second.p, r.parents->second.q)))
          : py::object(py::none());
  d["integer_type"] = served(r.served);
  return d;
}

// A Python int, fractions.Fraction (anything with numerator and denominator) or text such as
// "1000.5" or "-3/4" as a rational.
Rational<BigInt> py_to_rational(py::handle h, const char* what) {
  if (py::isinstance<py::str>(h)) return parse_rational<BigInt>(h.cast<std::string>());
  if (py::hasattr(h, "numerator") && py::hasattr(h, "denominator")) {
    const BigInt den = py_to_bigint(h.attr("denominator"), what);
    if (den == 0) throw InvalidArgument(std::string(what) + ": zero denominator");
    return Rational<BigInt>(py_to_bigint(h.attr("numerator"), what), den);
  }
  return Rational<BigInt>(py_to_bigint(h, what));
}

py::dict motion_check_py(py::handle a, py::handle b, py::handle c, py::object center,
                         py::object translation) {
  auto vec = [](py::object o, const char* what) {
    std::vector<Rational<BigInt>> v;
    if (o.is_none()) return std::vector<Rational<BigInt>>(2);
    for (auto x : o) v.push_back(py_to_rational(x, what));
    return v;
  };
  const RigidMotion m = motion_about(
      rotation_2d(py_to_bigint(a, "motion_check: a"), py_to_bigint(b, "motion_check: b"),
                  py_to_bigint(c, "motion_check: c")),
      vec(center, "motion_check: center"), vec(translation, "motion_check: translation"));
  const auto r = [&] {
    py::gil_scoped_release release;
    return lattice_bijectivity(m);
  }();
  auto pt = [](const std::array<BigInt, 2>& p) {
    return py::make_tuple(bigint_to_py(p[0]), bigint_to_py(p[1]));
  };
  py::dict d;
  d["bijective"] = r.bijective;
  d["method"] = r.method;
  d["period"] = bigint_to_py(r.period);
  d["collision"] = r.collision
                       ? py::object(py::make_tuple(pt((*r.collision)[0]), pt((*r.collision)[1])))
                       : py::object(py::none());
  d["image"] = r.collision_image ? py::object(pt(*r.collision_image)) : py::object(py::none());
  d["hole"] = r.hole ? py::object(pt(*r.hole)) : py::object(py::none());
  return d;
}

py::dict sturmian_py(py::handle a, py::handle b, py::handle d, py::handle c, std::uint64_t length) {
  SturmianOptions o{py_to_bigint(a, "sturmian: a"), py_to_bigint(b, "sturmian: b"),
                    py_to_bigint(d, "sturmian: d"), py_to_bigint(c, "sturmian: c")};
  o.length = length;
  const auto r = [&] {
    py::gil_scoped_release release;
    return sturmian_operation(o);
  }();
  auto ints = [](const std::vector<BigInt>& v) {
    py::list l;
    for (const auto& x : v) l.append(bigint_to_py(x));
    return l;
  };
  py::dict dd;
  dd["surd"] = py::make_tuple(bigint_to_py(r.P), bigint_to_py(r.D), bigint_to_py(r.Q));
  dd["preperiod"] = ints(r.preperiod);
  dd["period"] = ints(r.period);
  dd["floor"] = bigint_to_py(r.floor);
  dd["word"] = r.word;
  py::list conv;
  for (const auto& [p, q] : r.christoffel)
    conv.append(py::make_tuple(bigint_to_py(p), bigint_to_py(q)));
  dd["christoffel_convergents"] = conv;
  dd["integer_type"] = served(r.served);
  return dd;
}

py::dict floor_sum_py(py::handle n_obj, py::handle m_obj, py::handle a_obj, py::handle b_obj) {
  const FloorSumOptions o{py_to_bigint(n_obj, "floor_sum: n"), py_to_bigint(m_obj, "floor_sum: m"),
                          py_to_bigint(a_obj, "floor_sum: a"), py_to_bigint(b_obj, "floor_sum: b")};
  const auto r = [&] {
    py::gil_scoped_release release;
    return floor_sum_operation(o);
  }();
  py::dict d;
  d["value"] = bigint_to_py(r.value);
  d["integer_type"] = served(r.served);
  return d;
}

std::vector<Point2<BigInt>> points_of(py::handle seq, const char* what) {
  std::vector<Point2<BigInt>> pts;
  for (py::handle item : py::iter(seq)) {
    py::sequence s = py::reinterpret_borrow<py::sequence>(item);
    if (py::len(s) != 2)
      throw InvalidArgument(std::string(what) + ": a point is not a pair (x, y)");
    pts.push_back({py_to_bigint(s[0], what), py_to_bigint(s[1], what)});
  }
  return pts;
}

DssPathOptions path_of(py::handle points, int connectivity, const char* what) {
  DssPathOptions o;
  o.points = points_of(points, what);
  o.connectivity = connectivity;
  return o;
}

py::dict recognize_dss_py(py::handle points, int connectivity) {
  const DssPathOptions o = path_of(points, connectivity, "recognize_dss");
  const auto r = [&] {
    py::gil_scoped_release release;
    return dss_recognize_operation(o);
  }();
  const auto& ch = r.recognition.characteristics;
  py::dict d;
  d["is_dss"] = r.recognition.is_dss;
  d["longest_prefix"] = r.recognition.longest_prefix;
  d["connectivity"] = r.recognition.connectivity == Connectivity::four ? 4 : 8;
  d["a"] = bigint_to_py(ch.a);
  d["b"] = bigint_to_py(ch.b);
  d["mu"] = bigint_to_py(ch.mu);
  d["omega"] = bigint_to_py(ch.omega);
  d["integer_type"] = served(r.served);
  return d;
}

py::list tangential_cover(py::handle points, bool closed, int connectivity) {
  DssCoverOptions o{path_of(points, connectivity, "tangential_cover"), closed, false};
  const auto r = [&] {
    py::gil_scoped_release release;
    return dss_cover_operation(std::move(o));
  }();
  py::list out;
  for (const auto& s : r.segments) {
    py::dict d;
    d["begin"] = s.begin;
    d["end"] = s.end;
    d["length"] = s.length;
    d["a"] = s.a;
    d["b"] = s.b;
    d["mu"] = bigint_to_py(int_cast<BigInt>(Int128(s.mu)));
    d["omega"] = s.omega;
    out.append(d);
  }
  return out;
}

py::dict dsl_subsegment_py(py::handle a, py::handle b, py::handle mu, py::handle x0,
                           py::handle x1) {
  BigInt A = py_to_bigint(a, "dsl_subsegment: a"), B = py_to_bigint(b, "dsl_subsegment: b"),
         M = py_to_bigint(mu, "dsl_subsegment: mu"), X0 = py_to_bigint(x0, "dsl_subsegment: x0"),
         X1 = py_to_bigint(x1, "dsl_subsegment: x1");
  auto r = [&] {
    py::gil_scoped_release release;
    return dsl_subsegment_exact(A, B, M, X0, X1);
  }();
  py::dict d;
  d["a"] = bigint_to_py(r.value.a);
  d["b"] = bigint_to_py(r.value.b);
  d["mu"] = bigint_to_py(r.value.mu);
  d["integer_type"] = served(r.served);
  return d;
}

// Points as a list of 2D or 3D integer tuples (Python ints of any size); all the same
// dimension, one of `dims`.
struct PointsIn {
  int dim = 0;
  std::vector<BigInt> coords;
  std::size_t size() const { return dim == 0 ? 0 : coords.size() / static_cast<std::size_t>(dim); }
};

PointsIn points_nd(py::handle seq, const char* what, std::initializer_list<int> dims) {
  PointsIn out;
  for (py::handle item : py::iter(seq)) {
    py::sequence s = py::reinterpret_borrow<py::sequence>(item);
    const int n = static_cast<int>(py::len(s));
    if (out.dim == 0) {
      if (std::find(dims.begin(), dims.end(), n) == dims.end()) {
        throw InvalidArgument(std::string(what) + ": a point has " + std::to_string(n) +
                              " coordinates");
      }
      out.dim = n;
    } else if (n != out.dim) {
      throw InvalidArgument(std::string(what) + ": points of " + std::to_string(out.dim) +
                            " and of " + std::to_string(n) + " coordinates are mixed");
    }
    for (int k = 0; k < n; ++k)
      out.coords.push_back(py_to_bigint(s[static_cast<std::size_t>(k)], what));
  }
  if (out.dim == 0) throw InvalidArgument(std::string(what) + ": no point");
  return out;
}

py::tuple tuple3(const Point3<BigInt>& p) {
  return py::make_tuple(bigint_to_py(p.x), bigint_to_py(p.y), bigint_to_py(p.z));
}

py::dict convex_check_py(py::handle points, const std::string& definition,
                         std::uint64_t max_columns) {
  auto in = points_nd(points, "convex_check", {2, 3});
  ConvexCheckOptions o;
  o.dim = in.dim;
  o.coords = in.coords;
  o.definition = convexity_definition_from_name(definition, "convex_check: definition");
  o.max_columns = max_columns;
  const auto r = [&] {
    py::gil_scoped_release release;
    return convex_check_operation(o);
  }();
  py::dict d;
  d["convex"] = r.check.convex;
  d["definition"] = convexity_definition_name(r.definition);
  d["dimension"] = r.dim;
  d["points"] = r.points;
  d["integer_type"] = served(r.served);
  if (!r.check.convex) {
    py::dict w;
    py::list khalimsky, vertices;
    for (const auto& k : r.check.witness_khalimsky) khalimsky.append(bigint_to_py(k));
    for (const auto& v : r.check.witness_vertices) {
      py::list p;
      for (const auto& x : v) p.append(bigint_to_py(x));
      vertices.append(py::tuple(p));
    }
    w["dimension"] = r.check.witness_dimension;
    w["khalimsky"] = khalimsky;
    w["vertices"] = vertices;
    if (r.check.witness_dimension == 0) w["point"] = vertices[0];
    d["witness"] = w;
  }
  return d;
}

py::dict hull_py(py::handle points) {
  auto in = points_nd(points, "hull", {2, 3});
  py::dict d;
  if (in.dim == 2) {
    std::vector<Point2<BigInt>> pts;
    for (std::size_t i = 0; i < in.size(); ++i)
      pts.push_back({in.coords[2 * i], in.coords[2 * i + 1]});
    auto r = [&] {
      py::gil_scoped_release release;
      return lattice_hull_2d_exact<BigInt>(std::span<const Point2<BigInt>>(pts));
    }();
    py::list vertices;
    for (const auto& p : r.value)
      vertices.append(py::make_tuple(bigint_to_py(p.x), bigint_to_py(p.y)));
    d["vertices"] = vertices;
    d["integer_type"] = served(r.served);
    return d;
  }
  std::vector<Point3<BigInt>> pts;
  for (std::size_t i = 0; i < in.size(); ++i) {
    pts.push_back({in.coords[3 * i], in.coords[3 * i + 1], in.coords[3 * i + 2]});
  }
  auto r = [&] {
    py::gil_scoped_release release;
    return lattice_hull_3d_exact<BigInt>(std::span<const Point3<BigInt>>(pts));
  }();
  const auto& h = r.value;
  py::list vertices, facets, normals;
  for (const auto& p : h.vertices) vertices.append(tuple3(p));
  for (std::size_t f = 0; f < h.facets.size(); ++f) {
    facets.append(py::cast(h.facets[f]));
    normals.append(tuple3(h.normals[f]));
  }
  d["dimension"] = h.dimension;
  d["vertices"] = vertices;
  d["facets"] = facets;
  d["normals"] = normals;
  d["volume6"] = bigint_to_py(h.volume6);
  d["integer_type"] = served(r.served);
  return d;
}

// A rational from a Python int, a fractions.Fraction (numerator / denominator) or a str
// ("7", "-3/4", "1000.5": zdg's decimal rational syntax).
Rational<BigInt> rational_of(py::handle h, const std::string& what) {
  if (py::isinstance<py::str>(h)) {
    try {
      return parse_rational<BigInt>(std::string(py::str(h)));
    } catch (const InvalidArgument& e) {
      throw InvalidArgument(what + ": " + e.what());
    }
  }
  if (py::hasattr(h, "numerator") && py::hasattr(h, "denominator") && !PyFloat_Check(h.ptr())) {
    return Rational<BigInt>(py_to_bigint(h.attr("numerator"), what.c_str()),
                            py_to_bigint(h.attr("denominator"), what.c_str()));
  }
  if (PyFloat_Check(h.ptr())) {
    throw py::type_error(what + ": a float is not exact; pass an int, a Fraction or a str");
  }
  return Rational<BigInt>(py_to_bigint(h, what.c_str()));
}

py::dict body_hull_dict(const Escalated<BodyHull>& r) {
  py::list vertices;
  for (const auto& p : r.value.vertices)
    vertices.append(py::make_tuple(bigint_to_py(p.x), bigint_to_py(p.y)));
  py::dict d;
  d["vertices"] = vertices;
  d["integer_type"] = served(r.served);
  return d;
}

py::dict hull_disc_py(py::handle cx, py::handle cy, py::handle r, std::uint64_t max_vertices) {
  auto X = rational_of(cx, "hull_disc: cx"), Y = rational_of(cy, "hull_disc: cy"),
       R = rational_of(r, "hull_disc: r");
  if (R < Rational<BigInt>(0)) throw InvalidArgument("hull_disc: negative radius " + R.str());
  auto h = [&] {
    py::gil_scoped_release release;
    return disc_hull_exact(X, Y, R, max_vertices);
  }();
  return body_hull_dict(h);
}

py::dict hull_ellipse_py(py::handle cx, py::handle cy, py::handle a, py::handle b,
                         std::uint64_t max_vertices) {
  auto X = rational_of(cx, "hull_ellipse: cx"), Y = rational_of(cy, "hull_ellipse: cy"),
       A = rational_of(a, "hull_ellipse: a"), B = rational_of(b, "hull_ellipse: b");
  ellipse_body(X, Y, A, B); // a, b > 0
  auto h = [&] {
    py::gil_scoped_release release;
    return ellipse_hull_exact(X, Y, A, B, max_vertices);
  }();
  return body_hull_dict(h);
}

// The integer hull of the polygon of half-planes a x + b y <= c (rationals as for hull_disc).
py::dict hull_halfplanes_py(py::handle halfplanes) {
  std::vector<HalfPlane<BigInt>> hs;
  for (py::handle h : py::iter(halfplanes)) {
    const auto t = py::reinterpret_borrow<py::sequence>(h);
    if (!py::isinstance<py::sequence>(h) || py::len(t) != 3)
      throw InvalidArgument("hull_halfplanes: each half-plane is (a, b, c): a x + b y <= c");
    hs.push_back({rational_of(t[0], "hull_halfplanes: a"), rational_of(t[1], "hull_halfplanes: b"),
                  rational_of(t[2], "hull_halfplanes: c")});
  }
  if (hs.empty()) throw InvalidArgument("hull_halfplanes: no half-plane");
  auto h = [&] {
    py::gil_scoped_release release;
    return halfplane_hull_exact(std::span<const HalfPlane<BigInt>>(hs));
  }();
  py::dict d = body_hull_dict(h);
  d["region"] = to_string(h.value.region);
  return d;
}

py::dict recognize_plane_py(py::handle points) {
  auto in = points_nd(points, "recognize_plane", {3});
  std::vector<Point3<BigInt>> pts;
  for (std::size_t i = 0; i < in.size(); ++i) {
    pts.push_back({in.coords[3 * i], in.coords[3 * i + 1], in.coords[3 * i + 2]});
  }
  auto r = [&] {
    py::gil_scoped_release release;
    return recognize_naive_plane_exact(std::span<const Point3<BigInt>>(pts));
  }();
  py::dict d;
  d["is_plane"] = r.value.is_plane;
  if (r.value.is_plane) {
    d["normal"] = tuple3(r.value.normal);
    d["mu"] = bigint_to_py(r.value.mu);
    d["omega"] = bigint_to_py(r.value.omega);
  }
  d["integer_type"] = served(r.served);
  return d;
}

py::dict probe_plane_py(py::handle a, py::handle b, py::handle c, const std::string& algorithm,
                        std::uint64_t max_steps) {
  Point3<BigInt> n{py_to_bigint(a, "probe_plane: a"), py_to_bigint(b, "probe_plane: b"),
                   py_to_bigint(c, "probe_plane: c")};
  if (algorithm != "h" && algorithm != "r") {
    throw InvalidArgument("probe_plane: algorithm '" + algorithm + "' is not 'h' or 'r'");
  }
  auto r = [&] {
    py::gil_scoped_release release;
    return probe_standard_plane_exact(
        n, algorithm == "h" ? ProbingAlgorithm::h : ProbingAlgorithm::r, max_steps);
  }();
  py::dict d;
  d["normal"] = tuple3(r.value.normal);
  d["steps"] = r.value.steps;
  d["predicate_calls"] = r.value.predicate_calls;
  d["reduced_basis"] = r.value.reduced_basis;
  d["integer_type"] = served(r.served);
  return d;
}

// --- experiments --------------------------------------------------------------------------

std::optional<Setting> setting(const py::object& v, const std::string& name) {
  if (v.is_none()) return std::nullopt;
  return Setting{std::string(py::str(v)), "converge(" + name + "=...)"};
}

py::dict converge(const std::vector<std::string>& shapes,
                  const std::vector<std::string>& estimators, const py::object& h,
                  const py::object& k, const py::object& alpha, int translations,
                  std::uint64_t seed, int fit_levels, double tolerance, unsigned threads,
                  const py::object& box) {
  ExperimentSettings s;
  for (const auto& x : shapes) s.shapes.push_back({x, "converge(shapes=...)"});
  for (const auto& x : estimators) s.estimators.push_back({x, "converge(estimators=...)"});
  if (py::isinstance<py::str>(h)) {
    s.h = setting(h, "h");
  } else {
    std::string text;
    for (py::handle x : py::iter(h))
      text += (text.empty() ? "" : ",") + std::string(py::repr(py::float_(x.cast<double>())));
    s.h = Setting{text, "converge(h=...)"};
  }
  s.k = setting(k, "k");
  s.alpha = setting(alpha, "alpha");
  s.translations = Setting{std::to_string(translations), "converge(translations=...)"};
  s.seed = Setting{std::to_string(seed), "converge(seed=...)"};
  s.fit_levels = Setting{std::to_string(fit_levels), "converge(fit_levels=...)"};
  s.tolerance = Setting{std::string(py::repr(py::float_(tolerance))), "converge(tolerance=...)"};
  s.threads = Setting{std::to_string(threads), "converge(threads=...)"};
  if (!box.is_none()) {
    auto t = box.cast<std::pair<double, double>>();
    s.box = Setting{std::string(py::repr(py::float_(t.first))) + ":" +
                        std::string(py::repr(py::float_(t.second))),
                    "converge(box=...)"};
  }
  ExperimentConfig config = validate_experiment_settings(s);
  ExperimentResult r = [&] {
    py::gil_scoped_release release;
    return run_experiment(config);
  }();
  py::list runs, fits;
  for (const auto& x : r.runs) {
    py::dict d;
    d["shape"] = x.shape;
    d["estimator"] = x.estimator;
    d["h"] = x.h;
    d["translation"] = x.translation;
    d["offset"] = x.offset;
    d["k"] = x.k;
    d["alpha"] = x.alpha;
    d["linf"] = x.errors.linf;
    d["l2"] = x.errors.l2;
    d["mean"] = x.errors.mean;
    d["n"] = x.errors.n;
    d["seconds"] = x.seconds;
    runs.append(d);
  }
  for (const auto& f : r.fits) {
    py::dict d;
    d["shape"] = f.shape;
    d["estimator"] = f.estimator;
    d["norm"] = f.norm;
    d["slope"] = f.fit.slope;
    d["intercept"] = f.fit.intercept;
    d["stderr_slope"] = f.fit.stderr_slope;
    d["levels"] = f.fit.n;
    d["hs"] = f.hs;
    d["expected"] = f.expected ? py::object(py::float_(*f.expected)) : py::object(py::none());
    d["theory"] = f.theory;
    d["source"] = f.source;
    d["pass"] = f.pass ? py::object(py::bool_(*f.pass)) : py::object(py::none());
    d["reason"] = f.reason;
    fits.append(d);
  }
  py::dict d;
  d["runs"] = runs;
  d["fits"] = fits;
  d["all_pass"] = r.all_pass;
  d["threads"] = r.threads;
  return d;
}

} // namespace

} // namespace zdg::python

PYBIND11_MODULE(_zdg, m) {
  namespace py = pybind11;
  using namespace zdg::python;
  m.doc() = "zdg: exact digital geometry (the C++ library zdg, bound with pybind11)";

  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const zdg::InvalidArgument& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const zdg::IoError& e) {
      // A writer handed a staging file names it: the message names the user's file.
      PyErr_SetString(PyExc_OSError, zdg::name_outputs(e.what()).c_str());
    } catch (const zdg::OverflowError& e) {
      PyErr_SetString(PyExc_OverflowError, e.what());
    } catch (const zdg::Error& e) {
      PyErr_SetString(PyExc_RuntimeError, e.what());
    }
  });

  m.def("cf", &cf, py::arg("p"), py::arg("q"),
        "Continued fraction [a0; a1, ..., an] of p/q (q != 0) and its convergents, exact on "
        "Python ints of any size (Euclid's algorithm, O(log q) steps; escalates int64 -> "
        "int128 -> BigInt). Returns {'terms', 'convergents', 'integer_type'}.");
  m.def("christoffel", &christoffel, py::arg("p"), py::arg("q"), py::kw_only(),
        py::arg("upper") = false, py::arg("word") = true,
        "Christoffel word of slope p/q (p >= 0, q > 0; reduced first): q letters '0' and p "
        "letters '1', the prefix of length k holding floor(k p / (p + q)) ones (lower word; "
        "upper: its reverse), with the Stern-Brocot parents and the standard factorization "
        "(Borel-Laubie 1993). O(p + q) for the word (at most 2^30 letters; word=False for "
        "huge slopes), O(log q) for the parents. Returns {'p', 'q', 'word', "
        "'standard_factorization', 'parents', 'integer_type'}.");
  m.def("sturmian", &sturmian_py, py::arg("a"), py::arg("b"), py::arg("d"), py::arg("c"),
        py::kw_only(), py::arg("length") = 64,
        "The quadratic surd x = (a + b sqrt d) / c (b, c != 0, d > 0 not a square) as "
        "(P + sqrt D) / Q, its eventually periodic continued fraction (Lagrange), and the first "
        "`length` letters of the characteristic Sturmian word of its fractional part alpha "
        "(floor((n + 1) alpha) - floor(n alpha)) with the Christoffel convergents p/q whose "
        "words are 0 w 1, w a prefix of it. Exact; escalates int64 -> int128 -> BigInt. "
        "Returns {'surd': (P, D, Q), 'preperiod', 'period', 'floor', 'word', "
        "'christoffel_convergents', 'integer_type'}.");
  m.def("motion_check", &motion_check_py, py::arg("a"), py::arg("b"), py::arg("c"), py::kw_only(),
        py::arg("center") = py::none(), py::arg("translation") = py::none(),
        "Whether the digitized rotation of the Pythagorean triple a^2 + b^2 = c^2 (cos = a/c, "
        "sin = b/c) about `center` followed by `translation` (pairs of ints, Fractions or text; "
        "default 0), D(p) = floor(R (p - center) + center + translation + 1/2), is a bijection "
        "of Z^2: checked over one period of c points (c <= 2^28), past that by the theorem of "
        "Nouvel and Remila for a lattice centre. Returns {'bijective', 'method', 'period', "
        "'collision': ((x, y), (x, y)) two points with one image or None, 'image', 'hole': a "
        "point with no preimage or None}.");
  m.def("floor_sum", &floor_sum_py, py::arg("n"), py::arg("m"), py::arg("a"), py::arg("b"),
        "sum_{i=0}^{n-1} floor((a i + b) / m) for n >= 0, m != 0, exact, O(log m) (the "
        "Euclidean-like reduction). Returns {'value', 'integer_type'}.");
  m.def("recognize_dss", &recognize_dss_py, py::arg("points"), py::arg("connectivity") = 0,
        "Whether the 4- or 8-connected path (a sequence of (x, y) integer pairs; connectivity 0: "
        "4 when every step is an axis step, else 8) is a digital straight segment, and the "
        "minimal characteristics (a, b, mu, omega) of its longest DSS prefix: mu <= a x - b y "
        "< mu + omega. Incremental arithmetic recognition (Debled-Rennesson and Reveilles "
        "1995), O(1) amortized per point, exact by escalation. Returns {'is_dss', "
        "'longest_prefix', 'connectivity', 'a', 'b', 'mu', 'omega', 'integer_type'}.");
  m.def("tangential_cover", &tangential_cover, py::arg("points"), py::arg("closed") = true,
        py::arg("connectivity") = 0,
        "The maximal digital straight segments of a digital curve (int64 points; a closed "
        "curve may repeat its first point at the end), O(n) (Lachaud, Vialard, de Vieilleville "
        "2007). Returns a list of {'begin', 'end', 'length', 'a', 'b', 'mu', 'omega'} "
        "(inclusive indices; end < begin when a closed curve wraps).");
  m.def("dsl_subsegment", &dsl_subsegment_py, py::arg("a"), py::arg("b"), py::arg("mu"),
        py::arg("x0"), py::arg("x1"),
        "Minimal characteristics (a', b', mu') of the subsegment x0 <= x <= x1 of the naive "
        "digital straight line mu <= a x - b y < mu + b (0 <= a < b): reversed smart DSS "
        "(Said and Lachaud 2011), O(log(x1 - x0)), exact by escalation. Returns {'a', 'b', "
        "'mu', 'integer_type'}.");
  m.def("convex_check", &convex_check_py, py::arg("points"), py::arg("definition") = "full",
        py::arg("max_columns") = zdg::kConvexityMaxColumns,
        "Is a set of 2D or 3D integer points fully convex (definition 'full', Lachaud 2022: every "
        "cell of the grid whose closure meets the convex hull has a vertex in the set) or "
        "H-convex ('hull': Cvxh(X) cap Z^d = X)? Exact. Returns {'convex', 'definition', "
        "'dimension', 'points', 'integer_type'} and, when not, 'witness': {'dimension', "
        "'khalimsky', 'vertices', 'point' (a 0-cell)}, as zdg convex check --json.");
  m.def("hull", &hull_py, py::arg("points"),
        "Convex hull of 2D or 3D integer points (Python ints of any size), exact by "
        "escalation. 2D: its vertices counter-clockwise, without collinear points (Andrew's "
        "monotone chain, O(n log n)); returns {'vertices', 'integer_type'}. 3D: Quickhull with "
        "exact predicates and merged coplanar facets; returns {'dimension', 'vertices', "
        "'facets' (vertex indices, counter-clockwise from outside), 'normals' (primitive, "
        "outward), 'volume6' (6 x volume), 'integer_type'}.");
  m.def("hull_disc", &hull_disc_py, py::arg("cx"), py::arg("cy"), py::arg("r"),
        py::arg("max_vertices") = zdg::kHullMaxVertices,
        "Vertices of the convex hull of the lattice points of the closed disc of centre (cx, cy) "
        "and radius r (ints, fractions.Fraction or str rationals such as '1000.5'), counter-"
        "clockwise, exact (zdg hull disc). Refused when the proven vertex bound exceeds "
        "max_vertices. Returns {'vertices', 'integer_type'}.");
  m.def("hull_ellipse", &hull_ellipse_py, py::arg("cx"), py::arg("cy"), py::arg("a"), py::arg("b"),
        py::arg("max_vertices") = zdg::kHullMaxVertices,
        "Vertices of the convex hull of the lattice points of ((x - cx)/a)^2 + ((y - cy)/b)^2 "
        "<= 1 (rationals as for hull_disc; a, b > 0), exact. Returns {'vertices', "
        "'integer_type'}.");
  m.def("hull_halfplanes", &hull_halfplanes_py, py::arg("halfplanes"),
        "Vertices of the integer hull of the polygon {a x + b y <= c} of the half-planes "
        "[(a, b, c), ...] (rationals as for hull_disc), exact. Returns {'region' ('bounded', "
        "'unbounded' or 'empty'), 'vertices' (empty unless bounded), 'integer_type'}.");
  m.def("recognize_plane", &recognize_plane_py, py::arg("points"),
        "Is a set of 3D integer points a naive digital plane segment (mu <= N.x < mu + "
        "||N||_inf)? Exact, by the chord theorem (kernel/surfaces/digital_plane_recognition.hpp). "
        "Returns {'is_plane', 'normal', 'mu', 'omega', 'integer_type'} (normal, mu, omega "
        "when is_plane).");
  m.def("probe_plane", &probe_plane_py, py::arg("a"), py::arg("b"), py::arg("c"),
        py::arg("algorithm") = "r", py::arg("max_steps") = zdg::kPlaneProbingMaxSteps,
        "Plane probing (H or R algorithm, Lachaud-Provencal-Roussillon 2017) of the standard "
        "plane 0 <= a x + b y + c z < |a| + |b| + |c| from the origin: the normal found (the "
        "plane's own), steps, predicate calls, whether the final basis is reduced.");
  m.def("converge", &converge, py::arg("shapes"), py::arg("estimators"), py::kw_only(),
        py::arg("h"), py::arg("k") = py::none(), py::arg("alpha") = py::none(),
        py::arg("translations") = 0, py::arg("seed") = 0, py::arg("fit_levels") = 0,
        py::arg("tolerance") = 0.1, py::arg("threads") = 0, py::arg("box") = py::none(),
        "A multigrid convergence experiment (zdg converge): every shape x estimator entry x "
        "grid step h (a list of numbers, or the text 'HMAX:HMIN:N') x translation, the error "
        "statistics per run, then log-log fits of the error against h and the verdict against "
        "the proven rate (papers/THEORY.md). Returns {'runs': [records], 'fits': [records], "
        "'all_pass': bool}.");

  bind_arrays(m);
}
