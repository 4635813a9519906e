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
#include <zdg/kernel/surfaces/image_surfaces.hpp>
#include <zdg/kernel/surfaces/image_surfels.hpp>
#include <zdg/kernel/surfaces/plane_probing.hpp>
#include <zdg/kernel/topology/adjacency.hpp>
#include <zdg/kernel/topology/betti_numbers.hpp>
#include <zdg/kernel/topology/connected_components.hpp>
#include <zdg/kernel/topology/homotopic_thinning.hpp>
#include <zdg/kernel/transforms/distance_transform.hpp>
#include <zdg/kernel/transforms/voronoi_map.hpp>

#include <functional>
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

std::vector<std::string> strings(const std::vector<BigInt>& v) {
  std::vector<std::string> out;
  for (const auto& x : v) out.push_back(x.str());
  return out;
}

json serve_floor_sum(const json& j) {
  BigInt n = integer_field(j, "n"), m = integer_field(j, "m");
  if (n < 0) throw InvalidArgument("floor-sum: n must be >= 0");
  if (m == 0) throw InvalidArgument("floor-sum: m must not be 0");
  auto r = floor_sum_exact(n, m, integer_field(j, "a"), integer_field(j, "b"));
  return {{"value", r.value.str()}, {"integer_type", std::string(to_string(r.served))}};
}

json serve_cf(const json& j) {
  // Named copies, not structured bindings: clang 14 (the fuzz build) cannot capture those.
  const auto pq = fraction_field(j, "fraction");
  const BigInt p = pq.first, q = pq.second;
  struct Out {
    std::vector<BigInt> terms;
    json conv = json::array();
  };
  auto r = escalate([&]<class I>(std::type_identity<I>) {
    auto terms = continued_fraction<I>(int_cast<I>(p), int_cast<I>(q));
    Out o;
    for (const auto& t : terms) o.terms.push_back(to_bigint(t));
    for (const auto& [a, b] : convergents<I>(std::span<const I>(terms))) {
      o.conv.push_back({to_string(a), to_string(b)});
    }
    return o;
  });
  return {{"p", p.str()},
          {"q", q.str()},
          {"terms", strings(r.value.terms)},
          {"convergents", r.value.conv},
          {"integer_type", std::string(to_string(r.served))}};
}

json serve_christoffel(const json& j) {
  auto [p0, q0] = fraction_field(j, "slope");
  if (p0 < 0 || q0 <= 0) throw InvalidArgument("christoffel: the slope must have P >= 0, Q > 0");
  const BigInt g = gcd(p0, q0);
  const BigInt p = p0 / g, q = q0 / g;
  auto r = escalate([&]<class I>(std::type_identity<I>) {
    I pi = int_cast<I>(p), qi = int_cast<I>(q);
    json o{{"p", p.str()}, {"q", q.str()}, {"upper", false}};
    o["word"] = lower_christoffel_word(pi, qi);
    o["standard_factorization"] = json::array();
    o["parents"] = json::array();
    if (pi > 0) {
      auto sf = standard_factorization(pi, qi);
      o["standard_factorization"] = json::array({sf.u, sf.v});
      auto par = stern_brocot_parents(pi, qi);
      o["parents"] = json::array({json::array({to_string(par.left.p), to_string(par.left.q)}),
                                  json::array({to_string(par.right.p), to_string(par.right.q)})});
    }
    return o;
  });
  r.value["integer_type"] = std::string(to_string(r.served));
  return r.value;
}

// Connectivity of a path: the request's "connectivity" (4 or 8) or, absent, 4 when every step
// is an axis step, else 8 (as zdg dss recognize and zdg dss cover choose).
Connectivity path_connectivity(const json& j, const std::vector<Point2<BigInt>>& pts,
                               const char* op) {
  int forced = 0;
  if (j.contains("connectivity")) {
    auto c = json_integer(j.at("connectivity"));
    if (!c || (*c != 4 && *c != 8))
      throw InvalidArgument(std::string(op) + ": connectivity is 4 or 8");
    forced = static_cast<int>(c->convert_to<long>());
  }
  Connectivity c = Connectivity::four;
  for (std::size_t k = 1; k < pts.size(); ++k) {
    if (abs(BigInt(pts[k].x - pts[k - 1].x)) == 1 && abs(BigInt(pts[k].y - pts[k - 1].y)) == 1) {
      if (forced == 4)
        throw InvalidArgument(std::string(op) + ": a diagonal step in a 4-connected path");
      c = Connectivity::eight;
    }
  }
  if (forced == 8) c = Connectivity::eight;
  return c;
}

json serve_dss_recognize(const json& j) {
  auto pts = points_field(j);
  const Connectivity c = path_connectivity(j, pts, "dss recognize");
  auto r = recognize_dss_exact(std::span<const Point2<BigInt>>(pts), c);
  json o{{"is_dss", r.value.is_dss}, {"connectivity", c == Connectivity::four ? 4 : 8}};
  if (r.value.is_dss) {
    const auto& ch = r.value.characteristics;
    o["a"] = ch.a.str();
    o["b"] = ch.b.str();
    o["mu"] = ch.mu.str();
    o["omega"] = ch.omega.str();
  } else {
    o["longest_prefix"] = r.value.longest_prefix;
  }
  o["integer_type"] = std::string(to_string(r.served));
  return o;
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

json serve_transform_dt(const json& j) {
  const auto img = image_field(j);
  const TransformOptions opt = transform_field(j, img);
  const auto dt = distance_transform<BigInt>(img, opt);
  std::vector<json> flat;
  for (const auto& v : dt.values()) {
    if (v <= BigInt(std::int64_t{1} << 53)) {
      flat.push_back(v.convert_to<std::int64_t>());
    } else {
      flat.push_back(v.str());
    }
  }
  return {{"distances", nested(flat, img.domain())}, {"metric", opt.metric.name()}};
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
  const auto big = points_field(j);
  const Connectivity c = path_connectivity(j, big, "dss cover");
  const bool closed =
      j.contains("closed") && j.at("closed").is_boolean() && j.at("closed").get<bool>();
  const bool greedy =
      j.contains("greedy") && j.at("greedy").is_boolean() && j.at("greedy").get<bool>();
  std::vector<Point2<std::int64_t>> pts;
  for (const auto& p : big) {
    try {
      pts.push_back({int_cast<Int64>(p.x).value(), int_cast<Int64>(p.y).value()});
    } catch (const OverflowError&) {
      throw InvalidArgument("dss cover: a coordinate beyond 64 bits (cover works on int64 points)");
    }
  }
  auto segs = greedy ? greedy_segmentation_exact(pts, closed, c).value
                     : maximal_segments_exact(pts, closed, c).value;
  return cover_json(segs, closed, c, greedy);
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

// zdg surface on a whole 3D object (--component all): counts, Betti numbers and one row per
// object component (by decreasing size) with its surfaces' totals.
json serve_surface(const json& j) {
  const auto img = image_field(j);
  if (img.dim() != 3) throw InvalidArgument("surface: the image is not 3D");
  const AdjacencyPair pair = adjacency_field(j, 3);
  ComponentOptions copt;
  copt.threads = 1;
  const Components comps = connected_components(img, pair.object, copt);
  if (comps.count() == 0) throw InvalidArgument("surface: the object is empty");
  const BettiNumbers b = betti_numbers(img, pair, 1);
  const ImageSurfels sf = image_surfels(img, 1);
  const ImageSurfaces ss = image_surfaces(img, sf, SurfaceConvention::of(pair), 1);
  struct Stats {
    std::int64_t voxels = 0, surfels = 0, surfaces = 0, euler = 0, genus = 0;
  };
  std::vector<Stats> per(static_cast<std::size_t>(comps.count()));
  for (std::size_t l = 0; l < per.size(); ++l) per[l].voxels = comps.sizes[l];
  for (const auto& s : ss.surfaces) {
    auto& c = per[comps.labels[code_voxel(sf.codes[static_cast<std::size_t>(s.first)])] - 1];
    c.surfels += s.surfels;
    c.surfaces += 1;
    c.euler += s.euler;
    c.genus += s.genus;
  }
  json rows = json::array();
  for (std::size_t l = 0; l < per.size(); ++l) {
    rows.push_back({{"rank", std::to_string(l + 1)},
                    {"voxels", std::to_string(per[l].voxels)},
                    {"surfels", std::to_string(per[l].surfels)},
                    {"surfaces", std::to_string(per[l].surfaces)},
                    {"euler", std::to_string(per[l].euler)},
                    {"genus", std::to_string(per[l].genus)}});
  }
  json betti = json::array();
  for (int k = 0; k < 3; ++k) betti.push_back(std::to_string(b.b[static_cast<std::size_t>(k)]));
  return {{"adjacency", pair.name()},
          {"object_components", std::to_string(comps.count())},
          {"components", rows},
          {"surfels", std::to_string(sf.codes.size())},
          {"surfaces", std::to_string(ss.surfaces.size())},
          {"euler", std::to_string(b.euler)},
          {"betti", betti},
          {"pinched_pointels", std::to_string(ss.pinched_pointels)},
          {"pinched_linels", std::to_string(ss.pinched_linels)}};
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

using Handler = json (*)(const json&);

const std::map<std::string, Handler>& handlers() {
  static const std::map<std::string, Handler> h = {{"floor-sum", serve_floor_sum},
                                                   {"cf", serve_cf},
                                                   {"christoffel", serve_christoffel},
                                                   {"dss recognize", serve_dss_recognize},
                                                   {"dss subsegment", serve_dss_subsegment},
                                                   {"hull points", serve_hull_points},
                                                   {"hull disc", serve_hull_disc},
                                                   {"transform dt", serve_transform_dt},
                                                   {"topology betti", serve_topology_betti},
                                                   {"dss cover", serve_dss_cover},
                                                   {"transform voronoi", serve_transform_voronoi},
                                                   {"topology skeleton", serve_topology_skeleton},
                                                   {"plane probe", serve_plane_probe},
                                                   {"surface", serve_surface}};
  return h;
}

} // namespace

nlohmann::json cover_json(const std::vector<MaximalSegment>& segments, bool closed,
                          Connectivity connectivity, bool greedy) {
  json arr = json::array();
  for (const auto& s : segments) {
    arr.push_back({{"begin", s.begin},
                   {"end", s.end},
                   {"a", std::to_string(s.a)},
                   {"b", std::to_string(s.b)},
                   {"mu", to_string(Int128(s.mu))}});
  }
  return {{"closed", closed},
          {"connectivity", connectivity == Connectivity::four ? 4 : 8},
          {"greedy", greedy},
          {"segments", arr}};
}

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
