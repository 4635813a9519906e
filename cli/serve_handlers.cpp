// The request handlers of zdg serve (cli/serve.hpp): the line-JSON protocol of
// `zdg check --against` answered by zdg's own implementations (so that zdg itself is a valid
// COMMAND). Kept apart from the command line (no CLI11) so that a fuzz target can call them.
// Requests carry the operation's arguments under the lowercase names of `zdg OPERATION --help`
// (integers as decimal strings or JSON integers, images as nested lists); answers carry the fields
// of `zdg OPERATION --json`. A request zdg refuses gets
// {"error": "..."} and the loop goes on; the program ends at the end of its input.
#include <zdg/arith/christoffel.hpp>
#include <zdg/arith/continued_fraction.hpp>
#include <zdg/arith/dsl_subsegment.hpp>
#include <zdg/arith/dss_recognizer.hpp>
#include <zdg/arith/error.hpp>
#include <zdg/arith/escalate.hpp>
#include <zdg/arith/floor_sum.hpp>
#include <zdg/arith/rational.hpp>
#include <zdg/arith/stern_brocot.hpp>
#include <zdg/cli/external_command.hpp>
#include <zdg/cli/serve.hpp>
#include <zdg/kernel/curves/maximal_segments.hpp>
#include <zdg/kernel/hulls/convex_body_hull.hpp>
#include <zdg/kernel/hulls/lattice_hull_2d.hpp>
#include <zdg/kernel/hulls/lattice_polygon.hpp>
#include <zdg/kernel/surfaces/digital_plane_recognition.hpp>
#include <zdg/kernel/surfaces/image_surfaces.hpp>
#include <zdg/kernel/surfaces/image_surfels.hpp>
#include <zdg/kernel/surfaces/plane_probing.hpp>
#include <zdg/kernel/topology/adjacency.hpp>
#include <zdg/kernel/topology/betti_numbers.hpp>
#include <zdg/kernel/topology/connected_components.hpp>
#include <zdg/kernel/topology/homotopic_thinning.hpp>
#include <zdg/kernel/topology/simple_points.hpp>
#include <zdg/kernel/transforms/chamfer_transform.hpp>
#include <zdg/kernel/transforms/distance_transform.hpp>
#include <zdg/kernel/transforms/voronoi_map.hpp>
#include <zdg/operations/arith_operations.hpp>
#include <zdg/operations/convex_operations.hpp>
#include <zdg/operations/dss_operations.hpp>
#include <zdg/operations/surface_operations.hpp>

#include <algorithm>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <new>
#include <string>
#include <vector>

namespace zdg::cli {

namespace {

using json = nlohmann::json;

BigInt integer_field(const json& j, const std::string& name) {
  if (!j.contains(name)) throw InvalidArgument("request: no field '" + name + "'");
  auto v = json_integer(j.at(name));
  if (!v) throw InvalidArgument("request: field '" + name + "' is not an integer");
  return *v;
}

// An optional bound (max_vertices, max_steps): a non-negative integer below 2^64, or the
// library's default when the field is absent.
std::uint64_t bound_field(const json& j, const std::string& name, std::uint64_t fallback) {
  if (!j.contains(name)) return fallback;
  const BigInt v = integer_field(j, name);
  if (v < 0 || v > BigInt(UINT64_MAX)) {
    throw InvalidArgument("request: field '" + name + "' = " + v.str().substr(0, 40) +
                          " is not in 0..18446744073709551615");
  }
  return v.convert_to<std::uint64_t>();
}

std::string text_field(const json& j, const std::string& name) {
  if (!j.contains(name)) throw InvalidArgument("request: no field '" + name + "'");
  const auto& v = j.at(name);
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number_integer()) return v.dump();
  throw InvalidArgument("request: field '" + name + "' is not a string");
}

// "P/Q" or "P", Q != 0.
std::pair<BigInt, BigInt> fraction_field(const json& j, const std::string& name) {
  const std::string t = text_field(j, name);
  const auto slash = t.find('/');
  if (slash == std::string::npos) return {parse_integer<BigInt>(t), BigInt(1)};
  BigInt p = parse_integer<BigInt>(t.substr(0, slash)),
         q = parse_integer<BigInt>(t.substr(slash + 1));
  if (q == 0) throw InvalidArgument("request: zero denominator in '" + t + "'");
  return {p, q};
}

std::vector<Point2<BigInt>> points_field(const json& j) {
  if (!j.contains("points") || !j.at("points").is_array()) {
    throw InvalidArgument("request: 'points' is not a list of [x, y]");
  }
  std::vector<Point2<BigInt>> pts;
  for (const auto& e : j.at("points")) {
    if (!e.is_array() || e.size() != 2) throw InvalidArgument("request: a point is not [x, y]");
    auto x = json_integer(e[0]), y = json_integer(e[1]);
    if (!x || !y) throw InvalidArgument("request: a coordinate is not an integer");
    pts.push_back({*x, *y});
  }
  if (pts.empty()) throw InvalidArgument("request: no points");
  return pts;
}

// A nested list of rank 2 or 3 of integers (nonzero = object).
Image<std::uint8_t> image_field(const json& j) {
  if (!j.contains("image")) throw InvalidArgument("request: no field 'image'");
  std::vector<std::int64_t> ext;
  const json* v = &j.at("image");
  while (v->is_array()) {
    if (v->empty()) throw InvalidArgument("request: 'image' has an empty axis");
    ext.push_back(static_cast<std::int64_t>(v->size()));
    v = &(*v)[0];
  }
  if (ext.size() != 2 && ext.size() != 3) throw InvalidArgument("request: 'image' is not 2D or 3D");
  Domain d(ext);
  if (d.size() > (std::int64_t{1} << 24)) throw InvalidArgument("request: 'image' is too large");
  std::vector<std::uint8_t> vals;
  std::function<void(const json&, std::size_t)> walk = [&](const json& a, std::size_t axis) {
    if (!a.is_array() || static_cast<std::int64_t>(a.size()) != ext[axis]) {
      throw InvalidArgument("request: 'image' is not a rectangular nested list");
    }
    for (const auto& e : a) {
      if (axis + 1 < ext.size()) {
        walk(e, axis + 1);
      } else {
        auto x = json_integer(e);
        if (!x) throw InvalidArgument("request: an 'image' value is not an integer");
        vals.push_back(*x != 0 ? 1 : 0);
      }
    }
  };
  walk(j.at("image"), 0);
  return Image<std::uint8_t>(d, std::move(vals));
}

// The request's "adjacency" pair for an image of that dimension, or the default pair.
AdjacencyPair adjacency_field(const json& j, int dim) {
  return j.contains("adjacency") ? parse_adjacency_pair(text_field(j, "adjacency"), dim)
                                 : default_adjacency_pair(dim);
}

// The transform options of a request ("metric", default l2; one thread), checked against the
// image (a background point is needed).
TransformOptions transform_field(const json& j, const Image<std::uint8_t>& img) {
  TransformOptions opt;
  opt.metric = j.contains("metric") ? parse_metric(text_field(j, "metric")) : Metric::l2();
  opt.threads = 1;
  require_background(img, opt);
  return opt;
}

json nested(const std::vector<json>& flat, const Domain& d) {
  std::function<json(int, std::size_t&)> build = [&](int axis, std::size_t& pos) {
    json a = json::array();
    for (std::int64_t k = 0; k < d.extent(axis); ++k) {
      if (axis + 1 < d.dim()) {
        a.push_back(build(axis + 1, pos));
      } else {
        a.push_back(flat[pos++]);
      }
    }
    return a;
  };
  std::size_t pos = 0;
  return build(0, pos);
}

json polygon_json(const std::vector<Point2<BigInt>>& v, IntKind served) {
  auto m = lattice_polygon_measures_exact(std::span<const Point2<BigInt>>(v)).value;
  json verts = json::array();
  for (const auto& p : v) verts.push_back({p.x.str(), p.y.str()});
  return {{"vertices", verts},
          {"area2", m.area2.str()},
          {"boundary_points", m.boundary.str()},
          {"interior_points", m.interior.str()},
          {"integer_type", std::string(to_string(served))}};
}

bool flag_field(const json& j, const std::string& name, bool otherwise) {
  if (!j.contains(name)) return otherwise;
  if (!j.at(name).is_boolean())
    throw InvalidArgument("request: field '" + name + "' is not a boolean");
  return j.at(name).get<bool>();
}

json serve_floor_sum(const json& j) {
  return to_json(floor_sum_operation({integer_field(j, "n"), integer_field(j, "m"),
                                      integer_field(j, "a"), integer_field(j, "b")}));
}

json serve_cf(const json& j) {
  const auto [p, q] = fraction_field(j, "fraction");
  return to_json(continued_fraction_operation({p, q}));
}

json serve_christoffel(const json& j) {
  const auto [p, q] = fraction_field(j, "slope");
  return to_json(
      christoffel_operation({{p, q}, flag_field(j, "upper", false), flag_field(j, "word", true)}));
}

// sturmian: {"a": A, "b": B, "d": D, "c": C, "length": N} (length optional, default 64).
json serve_sturmian(const json& j) {
  SturmianOptions o{integer_field(j, "a"), integer_field(j, "b"), integer_field(j, "d"),
                    integer_field(j, "c")};
  o.length = bound_field(j, "length", o.length);
  return to_json(sturmian_operation(o));
}

// The path of a dss request: its points and the asked connectivity (0 when absent).
DssPathOptions path_field(const json& j) {
  DssPathOptions o;
  o.points = points_field(j);
  if (j.contains("connectivity")) {
    auto c = json_integer(j.at("connectivity"));
    if (!c || (*c != 4 && *c != 8)) throw InvalidArgument("request: connectivity is 4 or 8");
    o.connectivity = static_cast<int>(c->convert_to<long>());
  }
  return o;
}

json serve_dss_recognize(const json& j) {
  return to_json(dss_recognize_operation(path_field(j)));
}

json serve_dss_subsegment(const json& j) {
  BigInt a = integer_field(j, "a"), b = integer_field(j, "b"), mu = integer_field(j, "mu"),
         x0 = integer_field(j, "x0"), x1 = integer_field(j, "x1");
  if (b <= 0 || a < 0 || a >= b) throw InvalidArgument("dss subsegment: needs 0 <= a < b");
  if (x1 < x0) throw InvalidArgument("dss subsegment: needs x0 <= x1");
  auto r = dsl_subsegment_exact(a, b, mu, x0, x1);
  return {{"a", r.value.a.str()},
          {"b", r.value.b.str()},
          {"mu", r.value.mu.str()},
          {"integer_type", std::string(to_string(r.served))}};
}

json serve_hull_points(const json& j) {
  auto pts = points_field(j);
  auto r = lattice_hull_2d_exact<BigInt>(std::span<const Point2<BigInt>>(pts));
  return polygon_json(r.value, r.served);
}

json serve_hull_disc(const json& j) {
  auto cx = parse_rational<BigInt>(text_field(j, "cx"));
  auto cy = parse_rational<BigInt>(text_field(j, "cy"));
  auto r = parse_rational<BigInt>(text_field(j, "r"));
  if (r <= Rational<BigInt>(0)) throw InvalidArgument("hull disc: r must be > 0");
  auto h = disc_hull_exact(cx, cy, r, bound_field(j, "max_vertices", kHullMaxVertices));
  return polygon_json(h.value.vertices, h.served);
}

// The values of a transform as nested arrays of the image's shape: numbers up to 2^53 (exact in
// a JSON double), decimal strings past it.
json distances_json(const Image<BigInt>& values) {
  std::vector<json> flat;
  for (const auto& v : values.values()) {
    if (v <= BigInt(std::int64_t{1} << 53)) {
      flat.push_back(v.convert_to<std::int64_t>());
    } else {
      flat.push_back(v.str());
    }
  }
  return nested(flat, values.domain());
}

json serve_transform_dt(const json& j) {
  const auto img = image_field(j);
  const TransformOptions opt = transform_field(j, img);
  return {{"distances", distances_json(distance_transform<BigInt>(img, opt))},
          {"metric", opt.metric.name()}};
}

// transform chamfer: {"image": [[...]], "mask": [5, 7, 11]} (mask optional: <3,4> / <3,4,5>).
json serve_transform_chamfer(const json& j) {
  const auto img = image_field(j);
  if (img.dim() != 2 && img.dim() != 3) {
    throw InvalidArgument("transform chamfer: a " + std::to_string(img.dim()) +
                          "-D image (the masks are 2D or 3D)");
  }
  std::vector<std::int64_t> w;
  if (j.contains("mask")) {
    const json& m = j.at("mask");
    if (!m.is_array()) throw InvalidArgument("request: 'mask' is a list of weights");
    for (const auto& e : m) {
      const auto v = json_integer(e);
      if (!v || *v < 1 || *v > BigInt(std::numeric_limits<std::int64_t>::max())) {
        throw InvalidArgument("request: a 'mask' weight is not an integer in 1..2^63-1");
      }
      w.push_back(v->convert_to<std::int64_t>());
    }
  }
  const ChamferMask mask =
      w.empty() ? ChamferMask::borgefors(img.dim()) : ChamferMask(img.dim(), w);
  return {{"distances", distances_json(chamfer_transform<BigInt>(img, mask))},
          {"mask", mask.weights()},
          {"metric", "chamfer " + mask.name()}};
}

json serve_topology_betti(const json& j) {
  const auto img = image_field(j);
  const AdjacencyPair pair = adjacency_field(j, img.dim());
  const BettiNumbers b = betti_numbers(img, pair, 1);
  json betti = json::array();
  for (int k = 0; k < pair.dim; ++k)
    betti.push_back(std::to_string(b.b[static_cast<std::size_t>(k)]));
  return {{"adjacency", pair.name()},
          {"components", std::to_string(b.b[0])},
          {"euler", std::to_string(b.euler)},
          {"betti", betti}};
}

json serve_dss_cover(const json& j) {
  return to_json(dss_cover_operation(
      {path_field(j), flag_field(j, "closed", false), flag_field(j, "greedy", false)}));
}

json serve_transform_voronoi(const json& j) {
  const auto img = image_field(j);
  const TransformOptions opt = transform_field(j, img);
  const VoronoiMap v = voronoi_map(img, opt);
  std::vector<json> flat;
  for (std::int64_t i = 0; i < img.size(); ++i) flat.push_back(v.site_point(i));
  return {{"sites", nested(flat, img.domain())}, {"metric", opt.metric.name()}};
}

json serve_topology_skeleton(const json& j) {
  const auto img = image_field(j);
  ThinningOptions opt;
  opt.pair = adjacency_field(j, img.dim());
  opt.skeleton = parse_skeleton_kind(j.contains("skeleton") ? text_field(j, "skeleton") : "curve");
  opt.threads = 1;
  const ThinningResult t = homotopic_thinning(img, opt);
  const BettiNumbers b = betti_numbers(t.skeleton, opt.pair, 1);
  json betti = json::array();
  for (int k = 0; k < opt.pair.dim; ++k)
    betti.push_back(std::to_string(b.b[static_cast<std::size_t>(k)]));
  std::vector<json> flat(t.skeleton.values().begin(), t.skeleton.values().end());
  std::int64_t voxels = 0;
  for (auto x : t.skeleton.values()) voxels += x != 0 ? 1 : 0;
  return {{"skeleton", nested(flat, img.domain())},
          {"adjacency", opt.pair.name()},
          {"voxels", std::to_string(voxels)},
          {"betti", betti},
          {"deleted", std::to_string(t.deleted)}};
}

// zdg surface on a whole 3D object (--component all; operations/surface_operations.hpp):
// counts, Betti numbers and one row per object component (by decreasing size) with its
// surfaces' totals.
// The request's image as the object of an operation on `dim`-dimensional images (named `op`
// in messages): unit spacing, origin at 0; an image of another dimension or without object
// is refused.
ObjectImage object_field(const json& j, int dim, const std::string& op) {
  ObjectImage im;
  im.mask = image_field(j);
  if (im.mask.dim() != dim)
    throw InvalidArgument(op + ": the image is not " + std::to_string(dim) + "D");
  const auto& v = im.mask.values();
  if (std::all_of(v.begin(), v.end(), [](std::uint8_t x) { return x == 0; }))
    throw InvalidArgument(op + ": the object is empty");
  im.spacing.assign(std::size_t(dim), 1.0);
  im.origin.assign(std::size_t(dim), 0.0);
  im.name = op;
  return im;
}

// An operation's JSON without what describes the run rather than the answer.
json answer_of(json r) {
  for (const char* k : {"component", "seconds", "cpu_seconds", "threads"}) r.erase(k);
  return r;
}

json serve_surface(const json& j) {
  ObjectImage im = object_field(j, 3, "surface");
  SurfaceOptions o;
  o.adjacency = adjacency_field(j, 3);
  o.threads = 1;
  json r = answer_of(to_json(surface_operation(std::move(im), o)));
  r.erase("estimates"); // none are asked for
  return r;
}

json serve_plane_probe(const json& j) {
  const Point3<BigInt> n{integer_field(j, "a"), integer_field(j, "b"), integer_field(j, "c")};
  const std::string alg = j.contains("algorithm") ? text_field(j, "algorithm") : "r";
  if (alg != "h" && alg != "r") throw InvalidArgument("plane probe: algorithm is h or r");
  auto r = probe_standard_plane_exact(n, alg == "h" ? ProbingAlgorithm::h : ProbingAlgorithm::r,
                                      bound_field(j, "max_steps", kPlaneProbingMaxSteps));
  const auto& p = r.value;
  auto point = [](const Point3<BigInt>& q) {
    return json::array({q.x.str(), q.y.str(), q.z.str()});
  };
  json frame = json::array();
  for (const auto& m : p.frame) frame.push_back(point(m));
  return {{"normal", point(p.normal)},
          {"algorithm", alg},
          {"steps", p.steps},
          {"predicate_calls", p.predicate_calls},
          {"frame", frame},
          {"apex", point(p.apex)},
          {"integer_type", std::string(to_string(r.served))}};
}

json serve_hull_ellipse(const json& j) {
  auto cx = parse_rational<BigInt>(text_field(j, "cx"));
  auto cy = parse_rational<BigInt>(text_field(j, "cy"));
  auto a = parse_rational<BigInt>(text_field(j, "a"));
  auto b = parse_rational<BigInt>(text_field(j, "b"));
  ellipse_body(cx, cy, a, b); // InvalidArgument unless a, b > 0
  auto h = ellipse_hull_exact(cx, cy, a, b, bound_field(j, "max_vertices", kHullMaxVertices));
  return polygon_json(h.value.vertices, h.served);
}

// "points": a list of [x, y, z] integers.
std::vector<Point3<BigInt>> points3_field(const json& j) {
  if (!j.contains("points") || !j.at("points").is_array())
    throw InvalidArgument("request: 'points' is not a list of [x, y, z]");
  std::vector<Point3<BigInt>> pts;
  for (const auto& e : j.at("points")) {
    if (!e.is_array() || e.size() != 3) throw InvalidArgument("request: a point is not [x, y, z]");
    auto x = json_integer(e[0]), y = json_integer(e[1]), z = json_integer(e[2]);
    if (!x || !y || !z) throw InvalidArgument("request: a coordinate is not an integer");
    pts.push_back({*x, *y, *z});
  }
  if (pts.empty()) throw InvalidArgument("request: no points");
  return pts;
}

// The keys of zdg plane recognize --json.
json serve_plane_recognize(const json& j) {
  const auto pts = points3_field(j);
  auto r = recognize_naive_plane_exact(std::span<const Point3<BigInt>>(pts));
  const auto& p = r.value;
  json out{{"is_plane", p.is_plane},
           {"points", pts.size()},
           {"served", std::string(to_string(r.served))}};
  if (p.is_plane) {
    out["normal"] = json::array({p.normal.x.str(), p.normal.y.str(), p.normal.z.str()});
    out["mu"] = p.mu.str();
    out["omega"] = p.omega.str();
  }
  return out;
}

// The labels (1 = the largest component, 0 off the object) and the sizes, by decreasing size.
json serve_topology_components(const json& j) {
  const auto img = image_field(j);
  const AdjacencyPair pair = adjacency_field(j, img.dim());
  ComponentOptions opt;
  opt.threads = 1;
  const Components c = connected_components(img, pair.object, opt);
  std::vector<json> flat(c.labels.values().begin(), c.labels.values().end());
  json sizes = json::array();
  for (auto s : c.sizes) sizes.push_back(std::to_string(s));
  return {{"labels", nested(flat, img.domain())},
          {"adjacency", pair.name()},
          {"components", std::to_string(c.count())},
          {"sizes", sizes}};
}

// zdg contour on a whole 2D object (operations/surface_operations.hpp): the contours, Betti
// numbers and the estimates asked for ("estimates": a list of names, "radius": "R" or "Rv").
json serve_contour(const json& j) {
  ObjectImage im = object_field(j, 2, "contour");
  ContourOptions o;
  if (j.contains("adjacency")) o.adjacency = parse_adjacency_pair(text_field(j, "adjacency"), 2);
  if (j.contains("estimates")) {
    if (!j.at("estimates").is_array())
      throw InvalidArgument("request: 'estimates' is not a list of names");
    for (const auto& e : j.at("estimates")) {
      if (!e.is_string()) throw InvalidArgument("request: an estimate is not a name");
      o.estimates.push_back(e.get<std::string>());
    }
  }
  o.radius = parse_estimator_radius(j.contains("radius") ? text_field(j, "radius") : "");
  o.threads = 1;
  return answer_of(to_json(contour_operation(std::move(im), o)));
}

// "halfplanes": a list of [a, b, c] (a x + b y <= c), each an integer or a rational as text.
json serve_hull_halfplanes(const json& j) {
  if (!j.contains("halfplanes") || !j.at("halfplanes").is_array() || j.at("halfplanes").empty())
    throw InvalidArgument("request: 'halfplanes' is not a list of [a, b, c]");
  std::vector<HalfPlane<BigInt>> hs;
  for (const auto& e : j.at("halfplanes")) {
    if (!e.is_array() || e.size() != 3)
      throw InvalidArgument("request: a half-plane is not [a, b, c]");
    Rational<BigInt> c[3];
    for (std::size_t k = 0; k < 3; ++k) {
      if (e[k].is_string()) {
        c[k] = parse_rational<BigInt>(e[k].get<std::string>());
      } else if (const auto v = json_integer(e[k])) {
        c[k] = Rational<BigInt>(*v);
      } else {
        throw InvalidArgument("request: a coefficient is not an integer or a rational text");
      }
    }
    hs.push_back({c[0], c[1], c[2]});
  }
  auto r = halfplane_hull_exact(std::span<const HalfPlane<BigInt>>(hs));
  if (r.value.region != RegionKind::bounded) return {{"region", to_string(r.value.region)}};
  json out = polygon_json(r.value.vertices, r.served);
  out["region"] = "bounded";
  return out;
}

// The simple points of the object (a mask) and their count.
json serve_topology_simple(const json& j) {
  const auto img = image_field(j);
  const AdjacencyPair pair = adjacency_field(j, img.dim());
  std::int64_t count = 0;
  const Image<std::uint8_t> simple = simple_point_mask(img, pair, &count);
  std::vector<json> flat(simple.values().begin(), simple.values().end());
  return {{"simple", nested(flat, img.domain())},
          {"adjacency", pair.name()},
          {"count", std::to_string(count)}};
}

// "convex check": {"points": [[x, y] or [x, y, z], ...], "definition": "full" | "hull",
// "max_columns": N}, answered with the --json form of zdg convex check.
json serve_convex_check(const json& j) {
  if (!j.contains("points") || !j.at("points").is_array() || j.at("points").empty()) {
    throw InvalidArgument("request: 'points' is not a non-empty list of [x, y] or [x, y, z]");
  }
  ConvexCheckOptions o;
  o.dim = 0;
  for (const auto& e : j.at("points")) {
    if (!e.is_array() || (e.size() != 2 && e.size() != 3) ||
        (o.dim != 0 && static_cast<int>(e.size()) != o.dim)) {
      throw InvalidArgument("request: a point is not [x, y] or [x, y, z] like the first");
    }
    o.dim = static_cast<int>(e.size());
    for (const auto& c : e) {
      auto v = json_integer(c);
      if (!v) throw InvalidArgument("request: a coordinate is not an integer");
      o.coords.push_back(*v);
    }
  }
  if (j.contains("definition"))
    o.definition =
        convexity_definition_from_name(text_field(j, "definition"), "request: definition");
  o.max_columns = bound_field(j, "max_columns", kConvexityMaxColumns);
  return to_json(convex_check_operation(o));
}

using Handler = json (*)(const json&);

const std::map<std::string, Handler>& handlers() {
  static const std::map<std::string, Handler> h = {
      {"floor-sum", serve_floor_sum},
      {"cf", serve_cf},
      {"christoffel", serve_christoffel},
      {"sturmian", serve_sturmian},
      {"dss recognize", serve_dss_recognize},
      {"dss subsegment", serve_dss_subsegment},
      {"hull points", serve_hull_points},
      {"hull disc", serve_hull_disc},
      {"transform dt", serve_transform_dt},
      {"transform chamfer", serve_transform_chamfer},
      {"topology betti", serve_topology_betti},
      {"dss cover", serve_dss_cover},
      {"transform voronoi", serve_transform_voronoi},
      {"topology skeleton", serve_topology_skeleton},
      {"plane probe", serve_plane_probe},
      {"surface", serve_surface},
      {"contour", serve_contour},
      {"hull ellipse", serve_hull_ellipse},
      {"hull halfplanes", serve_hull_halfplanes},
      {"topology simple", serve_topology_simple},
      {"plane recognize", serve_plane_recognize},
      {"topology components", serve_topology_components},
      {"convex check", serve_convex_check}};
  return h;
}

} // namespace

std::vector<std::string> serve_operations() {
  std::vector<std::string> ops;
  for (const auto& [k, v] : handlers()) ops.push_back(k);
  return ops;
}

std::string serve_answer(const std::string& operation, const std::string& line) {
  auto it = handlers().find(operation);
  if (it == handlers().end()) {
    std::string known;
    for (const auto& [k, v] : handlers()) known += (known.empty() ? "" : ", ") + k;
    throw InvalidArgument("serve: unknown operation '" + operation.substr(0, 60) +
                          "' (known: " + known + ")");
  }
  json answer;
  try {
    const json request = json::parse(line);
    if (!request.is_object()) throw InvalidArgument("request: not a JSON object");
    answer = it->second(request);
  } catch (const Error& e) {
    answer = {{"error", e.what()}};
  } catch (const std::bad_alloc&) {
    // GMP's allocations included (arith/integer.cpp): the request is refused, the server goes on.
    answer = {{"error", "out of memory"}};
  } catch (const json::exception& e) {
    answer = {{"error", std::string("request: ") + e.what()}};
  }
  // An error message may quote the request's bytes, which need not be UTF-8: replaced by
  // U+FFFD rather than thrown at (dump's default), so that every answer is one line of JSON.
  return answer.dump(-1, ' ', false, json::error_handler_t::replace);
}

} // namespace zdg::cli
