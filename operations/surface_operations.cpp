#include <zdg/operations/surface_operations.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/estimators/ambrosio_tortorelli_mesh.hpp>
#include <zdg/estimators/digital_integration.hpp>
#include <zdg/estimators/heat_geodesics.hpp>
#include <zdg/kernel/calculus/harmonic_dimension.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>
#include <zdg/kernel/surfaces/marching_cubes.hpp>
#include <zdg/kernel/surfaces/primal_surface_mesh.hpp>
#include <zdg/kernel/surfaces/surfel_complex.hpp>
#include <zdg/kernel/topology/connected_components.hpp>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>

namespace zdg {

namespace {

std::string str(std::int64_t v) {
  return std::to_string(v);
}

std::string component_text(std::int64_t which) {
  return which == 0 ? "all" : (which == 1 ? "largest" : str(which));
}

std::string radius_text(const EstimatorRadius& r) {
  return r.text.empty() ? "5v (the default)" : r.text;
}

// Components of the object under k, and the mask of the selected ones.
struct ComponentSelection {
  std::int64_t count = 0;                     // components of the object
  std::vector<std::int64_t> chosen;           // their labels (1-based, by decreasing size)
  std::vector<std::int64_t> sizes;            // sizes of all components
  std::optional<Image<std::uint32_t>> labels; // kept when every component is selected
};

ComponentSelection select_components(Image<std::uint8_t>& mask, int k, std::int64_t which,
                                     unsigned threads, const std::string& name) {
  if (which < 0)
    throw InvalidArgument("component rank " + str(which) + ": expected 0 (all) or K >= 1");
  ComponentOptions opt;
  opt.order = ComponentOrder::by_size;
  opt.threads = threads;
  Components c = connected_components(mask, k, opt);
  ComponentSelection s;
  s.count = c.count();
  s.sizes = c.sizes;
  if (which == 0) {
    for (std::int64_t l = 1; l <= s.count; ++l) s.chosen.push_back(l);
    s.labels = std::move(c.labels);
    return s;
  }
  if (which > s.count)
    throw InvalidArgument(name + ": --component " + str(which) + " but the object has " +
                          str(s.count) + " component" + (s.count == 1 ? "" : "s") + " under " +
                          str(k) + "-adjacency");
  s.chosen = {which};
  const auto& lab = c.labels.values();
  parallel_chunks(mask.size(), threads, [&](std::int64_t b, std::int64_t e) {
    for (auto i = b; i < e; ++i) mask[i] = lab[std::size_t(i)] == std::uint32_t(which) ? 1 : 0;
  });
  return s;
}

// The radius in physical units at grid step h.
double physical_radius(const EstimatorRadius& radius, double h) {
  return radius.voxels ? radius.value * h : radius.value;
}

// The radius an estimator reads: positive, and at most the image's largest extent (in voxels
// or pixels, `unit`; `shape` names the image's size in messages).
void check_radius(const EstimatorRadius& radius, double h, std::int64_t extent,
                  const std::string& name, const std::string& shape, const char* unit) {
  if (!(radius.value > 0) || !std::isfinite(radius.value))
    throw InvalidArgument("--radius " + radius_text(radius) + ": a positive number is needed");
  const double rv = physical_radius(radius, h) / h;
  if (rv > double(extent))
    throw InvalidArgument(name + ": --radius " + radius_text(radius) + " is " +
                          fmt::format("{}", rv) + " " + unit + ", larger than the " + shape);
}

// The object's components under the pair's object adjacency (the mask keeps the selected
// ones: select_components) and its Betti numbers, reported as two steps.
ComponentSelection components_and_betti(Image<std::uint8_t>& mask, const AdjacencyPair& pair,
                                        std::int64_t component, unsigned threads,
                                        const std::string& name, OperationProgress& progress,
                                        BettiNumbers& betti) {
  progress.start("components");
  ComponentSelection comps = select_components(mask, pair.object, component, threads, name);
  progress.done("components", str(comps.count) + " component(s)");
  progress.start("Betti numbers");
  betti = betti_numbers(mask, pair, threads);
  progress.done("betti");
  return comps;
}

const ImageEstimator* find(const std::vector<ImageEstimator>& reg, const std::string& n) {
  for (const auto& e : reg)
    if (e.name == n) return &e;
  return nullptr;
}

// --- surface estimates: what each one adds per surfel ---------------------------------------

// A column of per-surfel values: its CSV header, its name as a mesh field ("" = not a mesh
// field), and its value at surfel i.
struct SurfelColumn {
  const char* csv;
  const char* field;
  double (*value)(const SurfaceEstimates&, std::size_t);
};

// The columns of each surface estimator, in the registry's order.
const std::vector<std::pair<std::string, std::vector<SurfelColumn>>>& surface_columns() {
  using E = SurfaceEstimates;
  static const std::vector<std::pair<std::string, std::vector<SurfelColumn>>> cols = {
      {"ii-mean", {{"ii_mean", "ii-mean", [](const E& e, std::size_t i) { return e.mean[i]; }}}},
      {"ii-gaussian",
       {{"ii_gaussian", "ii-gaussian",
         [](const E& e, std::size_t i) { return e.principal[i].gaussian(); }}}},
      {"ii-k1", {{"ii_k1", "ii-k1", [](const E& e, std::size_t i) { return e.principal[i].k1; }}}},
      {"ii-k2", {{"ii_k2", "ii-k2", [](const E& e, std::size_t i) { return e.principal[i].k2; }}}},
      {"ii-normal",
       {{"nx", "", [](const E& e, std::size_t i) { return e.principal[i].normal.x; }},
        {"ny", "", [](const E& e, std::size_t i) { return e.principal[i].normal.y; }},
        {"nz", "", [](const E& e, std::size_t i) { return e.principal[i].normal.z; }}}},
      {"ii-directions",
       {{"d1x", "", [](const E& e, std::size_t i) { return e.principal[i].d1.x; }},
        {"d1y", "", [](const E& e, std::size_t i) { return e.principal[i].d1.y; }},
        {"d1z", "", [](const E& e, std::size_t i) { return e.principal[i].d1.z; }},
        {"d2x", "", [](const E& e, std::size_t i) { return e.principal[i].d2.x; }},
        {"d2y", "", [](const E& e, std::size_t i) { return e.principal[i].d2.y; }},
        {"d2z", "", [](const E& e, std::size_t i) { return e.principal[i].d2.z; }}}},
      {"geodesic",
       {{"geodesic", "geodesic", [](const E& e, std::size_t i) { return e.geodesic[i]; }}}},
      {"at-normal",
       {{"at_nx", "at-nx", [](const E& e, std::size_t i) { return e.at_normal[i].x; }},
        {"at_ny", "at-ny", [](const E& e, std::size_t i) { return e.at_normal[i].y; }},
        {"at_nz", "at-nz", [](const E& e, std::size_t i) { return e.at_normal[i].z; }},
        {"at_v", "at-v", [](const E& e, std::size_t i) { return e.at_v[i]; }}}},
  };
  return cols;
}

// The columns of the estimates computed, in order.
std::vector<SurfelColumn> computed_columns(const SurfaceEstimates& est) {
  std::vector<SurfelColumn> out;
  for (const auto& [name, cols] : surface_columns())
    if (est.names.count(name) != 0) out.insert(out.end(), cols.begin(), cols.end());
  return out;
}

std::vector<double> field_values(const SurfaceEstimates& est, const SurfelColumn& c,
                                 std::size_t n) {
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = c.value(est, i);
  return v;
}

// The heat-method distance on the primal surface's surfels (estimators/heat_geodesics.hpp),
// with the II normals and the surfel measure; surfels on other closed surfaces than the
// source's get NaN.
void compute_geodesic(SurfaceEstimates& est, const SurfelComplex& cx,
                      const std::vector<Point3<double>>& normals, const ImageSurfaces& ss,
                      const GeodesicSource& source, const std::string& name) {
  const auto w = surfel_weights(surfel_measure(normals, cx.normals), cx.areas);
  std::int64_t s = 0;
  if (source.surfel) {
    s = *source.surfel;
    if (s < 0 || s >= cx.surfel_count())
      throw InvalidArgument("--source " + str(s) + ": the surface has " + str(cx.surfel_count()) +
                            " surfels (0.." + str(cx.surfel_count() - 1) + ")");
  } else {
    const auto [nearest, gap] = nearest_surfel(cx, source.point);
    if (gap > 2 * est.h)
      throw InvalidArgument(fmt::format("--source {},{},{}: {:.6g} from the nearest surfel centre "
                                        "of {}, more than two voxels: not on the surface",
                                        source.point.x, source.point.y, source.point.z, gap, name));
    s = nearest;
  }
  const HeatGeodesics geo(cx, normals, w);
  est.geodesic = geo.distance(s);
  est.source = s;
  est.geodesic_time = geo.time();
  est.geodesic_solver = spd_backend_name(geo.backend());
  const auto own = ss.surface_of[std::size_t(s)];
  for (std::size_t i = 0; i < est.geodesic.size(); ++i)
    if (ss.surface_of[i] != own) est.geodesic[i] = std::numeric_limits<double>::quiet_NaN();
}

// The Ambrosio-Tortorelli piecewise-smooth normals from the II normals on the primal surface's
// surfels, and v brought to the surfels (the minimum over their four sides, or their four
// corners with v on the pointels: 0 on a sharp edge).
void compute_at_normals(SurfaceEstimates& est, const SurfelComplex& cx,
                        const std::vector<Point3<double>>& normals, unsigned threads) {
  if (est.at_discretization == ATDiscretization::pointel) {
    const ATMesh mesh = at_mesh(cx);
    ATMeshOptions o;
    o.threads = threads;
    const ATMeshResult r = at_mesh_normals(mesh, normals, est.at, o);
    est.at_normal = r.normals;
    est.at_v = at_face_values(mesh, r.v, ATSurfelPolicy::minimum);
    est.at_solver = r.solver;
    est.at_iterations = r.iterations;
    return;
  }
  const ATResult r = at_normals(cx, normals, est.at);
  est.at_normal = r.normals;
  est.at_v = at_surfel_v(cx, r.v, ATSurfelPolicy::minimum);
  est.at_solver = r.backend;
  est.at_iterations = r.iterations;
}

// The per-face fields and the normals of the mesh from the surfels' estimates (primal: face =
// surfel; marching cubes: the mean over the triangle's surfel vertices, and the vertex normals).
void attach_estimates(PolygonMesh& mesh, SurfaceMesh kind, const ImageSurfels& sf,
                      const SurfaceEstimates& est, unsigned threads) {
  std::vector<std::pair<std::string, std::vector<double>>> fields;
  for (const auto& c : computed_columns(est))
    if (*c.field != '\0')
      fields.emplace_back(c.field, field_values(est, c, std::size_t(sf.size())));
  // The surfels' normals (II, or the elementary ones), written where the mesh keeps them:
  // the face normals of the primal mesh, the first vertex normals of marching cubes.
  auto surfel_normals = [&](Point3<double>* out) {
    parallel_chunks(sf.size(), threads, [&](std::int64_t b, std::int64_t e) {
      for (std::int64_t i = b; i < e; ++i) {
        if (!est.principal.empty()) {
          out[i] = est.principal[std::size_t(i)].normal;
        } else {
          const auto t = trivial_normal(sf.surfel(i));
          out[i] = {double(t.x), double(t.y), double(t.z)};
        }
      }
    });
  };
  if (kind == SurfaceMesh::primal) {
    mesh.face_scalars = std::move(fields);
    mesh.face_normals.resize(static_cast<std::size_t>(sf.size()));
    surfel_normals(mesh.face_normals.data());
    return;
  }
  const std::int64_t n = sf.size();
  // (no structured binding: clang 14, the fuzzers' compiler, cannot capture one in a lambda)
  for (auto& field : fields) {
    const std::vector<double>& values = field.second;
    std::vector<double> per_face(static_cast<std::size_t>(mesh.face_count()));
    parallel_chunks(mesh.face_count(), threads, [&](std::int64_t b, std::int64_t e) {
      for (std::int64_t f = b; f < e; ++f) {
        double s = 0;
        int k = 0;
        for (auto v : mesh.face(f))
          if (v < n) {
            s += values[std::size_t(v)];
            ++k;
          }
        per_face[std::size_t(f)] = s / k;
      }
    });
    mesh.face_scalars.emplace_back(field.first, std::move(per_face));
  }
  // Vertex normals: the surfels' (vertices 0 .. n - 1), the centres' the mean of their surfel
  // neighbours' (the surfel normals are not changed while the centres sum them).
  auto& vn = mesh.vertex_normals;
  vn.assign(mesh.vertices.size(), Point3<double>{0, 0, 0});
  surfel_normals(vn.data());
  for (std::int64_t f = 0; f < mesh.face_count(); ++f) {
    const auto t = mesh.face(f);
    for (std::size_t c = 0; c < 3; ++c)
      if (t[c] >= n)
        for (std::size_t d = 0; d < 3; ++d)
          if (t[d] < n) vn[std::size_t(t[c])] = vn[std::size_t(t[c])] + vn[std::size_t(t[d])];
  }
  parallel_chunks(std::int64_t(vn.size()), threads, [&](std::int64_t b, std::int64_t e) {
    for (std::int64_t i = b; i < e; ++i) {
      auto& v = vn[std::size_t(i)];
      const double l = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
      if (l > 0) v = {v.x / l, v.y / l, v.z / l};
    }
  });
}

nlohmann::json timings(const std::map<std::string, double>& m) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [k, v] : m) j[k] = v;
  return j;
}

} // namespace

// --- registry ------------------------------------------------------------------------------

const std::vector<ImageEstimator>& surface_estimators() {
  static const std::vector<ImageEstimator> r = {
      {"ii-mean", "integral-invariant mean curvature (Coeurjolly et al. 2013)"},
      {"ii-gaussian", "integral-invariant Gaussian curvature k1 k2"},
      {"ii-k1", "integral-invariant first principal curvature"},
      {"ii-k2", "integral-invariant second principal curvature"},
      {"ii-normal", "integral-invariant normal (covariance of the ball's intersection)"},
      {"ii-directions", "integral-invariant principal directions"},
      {"geodesic", "heat-method distance to --source on the surfels, with the II normals"},
      {"at-normal", "Ambrosio-Tortorelli piecewise-smooth normals from the II normals, and "
                    "their discontinuity field at-v"},
  };
  return r;
}

const std::vector<ImageEstimator>& contour_estimators() {
  static const std::vector<ImageEstimator> r = {
      {"ii-curvature", "integral-invariant curvature per linel"},
      {"bc-tangent", "binomial-convolution tangent per pointel"},
      {"lmst-tangent", "lambda-MST tangent per pointel"},
      {"mlp-length", "length of the minimum-length polygon per contour"},
      {"gauss-area", "the object's area (pixel count times h^2)"},
  };
  return r;
}

const std::vector<std::pair<std::string, std::string>>& surface_color_fields() {
  static const std::vector<std::pair<std::string, std::string>> f = {
      {"ii-mean", "ii-mean"}, {"ii-gaussian", "ii-gaussian"}, {"ii-k1", "ii-k1"},
      {"ii-k2", "ii-k2"},     {"geodesic", "geodesic"},       {"at-v", "at-normal"}};
  return f;
}

const std::vector<std::pair<std::string, std::string>>& contour_color_fields() {
  static const std::vector<std::pair<std::string, std::string>> f = {
      {"ii-curvature", "ii-curvature"}};
  return f;
}

std::string estimator_names(const std::vector<ImageEstimator>& registry) {
  std::string out;
  for (const auto& e : registry) {
    if (!out.empty()) out += ", ";
    out += e.name;
  }
  return out;
}

std::set<std::string> check_estimator_names(const std::vector<std::string>& names,
                                            const std::vector<ImageEstimator>& registry) {
  std::set<std::string> out;
  for (const auto& n : names) {
    if (find(registry, n) == nullptr)
      throw InvalidArgument("--estimate: unknown estimator '" + n + "' (" +
                            estimator_names(registry) + ")");
    out.insert(n);
  }
  return out;
}

EstimatorRadius parse_estimator_radius(const std::string& text) {
  EstimatorRadius r;
  r.text = text;
  if (text.empty()) return r;
  std::string t = text;
  r.voxels = t.back() == 'v';
  if (r.voxels) t.pop_back();
  double v = 0;
  const auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (t.empty() || ec != std::errc() || p != t.data() + t.size() || !std::isfinite(v) || v <= 0)
    throw InvalidArgument("--radius '" + text +
                          "': expected a positive number, in physical units (R) or in voxels "
                          "(Rv, e.g. 5v)");
  r.value = v;
  return r;
}

double isotropic_step(const std::vector<double>& spacing, const std::string& name) {
  const double h = spacing.at(0);
  for (double s : spacing) {
    if (std::abs(s - h) > 1e-9 * std::max(std::abs(s), std::abs(h))) {
      std::string all;
      for (double x : spacing) {
        if (!all.empty()) all += ',';
        all += fmt::format("{}", x);
      }
      throw InvalidArgument(name + ": the estimators need isotropic voxels (spacing " + all +
                            "); resample, or give --spacing");
    }
  }
  return h;
}

const char* at_discretization_name(ATDiscretization d) {
  return d == ATDiscretization::pointel ? "pointel" : "linel";
}

const char* surface_mesh_name(SurfaceMesh m) {
  switch (m) {
  case SurfaceMesh::primal:
    return "primal";
  case SurfaceMesh::marching_cubes:
    return "marching-cubes";
  case SurfaceMesh::none:
    break;
  }
  return "";
}

nlohmann::json value_stats(const std::vector<double>& v) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo, sum = 0;
  std::int64_t n = 0;
  for (double x : v) {
    if (!std::isfinite(x)) continue;
    lo = std::min(lo, x);
    hi = std::max(hi, x);
    sum += x;
    ++n;
  }
  if (n == 0) return {{"count", "0"}};
  return {{"min", lo}, {"max", hi}, {"mean", sum / double(n)}, {"count", str(n)}};
}

// --- zdg surface ---------------------------------------------------------------------------

std::set<std::string> check_surface_options(const SurfaceOptions& o) {
  auto names = check_estimator_names(o.estimates, surface_estimators());
  if (names.count("geodesic") != 0 && !o.source)
    throw InvalidArgument("--estimate geodesic needs --source SURFEL or --source X,Y,Z");
  if (o.source && names.count("geodesic") == 0)
    throw InvalidArgument("--source is only read by --estimate geodesic");
  if (o.regularize && o.mesh == SurfaceMesh::marching_cubes)
    throw InvalidArgument("--regularize moves the primal mesh's vertices (one per pointel); it "
                          "does not apply to --mesh marching-cubes");
  if (o.regularize) {
    // The parameters' checks (alpha, beta, gamma > 0) before any input is read.
    const PolygonMesh empty;
    check_regularization_input(empty, {}, 1.0, *o.regularize);
  }
  return names;
}

SurfaceResult surface_operation(ObjectImage image, const SurfaceOptions& o) {
  if (image.mask.dim() != 3) throw InvalidArgument(image.name + ": the surface needs a 3D image");
  make_adjacency_pair(3, o.adjacency.object, o.adjacency.background);
  SurfaceResult r;
  auto& est = r.estimates;
  est.names = check_surface_options(o);
  if (o.regularize) est.names.insert("ii-normal"); // the normals the quads align with
  est.at = o.at;
  est.at_discretization = o.at_v;
  const SurfaceConvention conv = SurfaceConvention::of(o.adjacency);
  OperationProgress progress(o.progress);
  r.adjacency = o.adjacency;
  r.component = o.component;
  r.mesh_kind = o.regularize ? SurfaceMesh::primal : o.mesh;
  r.threads = worker_count(o.threads, std::int64_t{1} << 30);
  Image<std::uint8_t> mask = std::move(image.mask);
  const auto& sp = image.spacing;
  const auto& org = image.origin;
  if (sp.size() != 3 || org.size() != 3)
    throw InvalidArgument(image.name + ": spacing and origin need three values (z, y, x)");
  r.place = VoxelPlacement{{sp[2], sp[1], sp[0]}, {org[2], org[1], org[0]}};
  const auto& dom = mask.domain();
  if (!est.names.empty()) {
    est.h = o.step ? *o.step : isotropic_step(sp, image.name);
    if (!(est.h > 0) || !std::isfinite(est.h))
      throw InvalidArgument(image.name + ": the grid step h must be a positive number");
    const std::int64_t extent = std::max({dom.extent(0), dom.extent(1), dom.extent(2)});
    check_radius(o.radius, est.h, extent, image.name,
                 "volume (" + str(dom.extent(2)) + " x " + str(dom.extent(1)) + " x " +
                     str(dom.extent(0)) + " voxels)",
                 "voxels");
    est.R = physical_radius(o.radius, est.h);
    const double rv = est.R / est.h;
    if (rv > 256)
      throw InvalidArgument("--radius " + radius_text(o.radius) + " is " + fmt::format("{}", rv) +
                            " voxels; the integral invariants take at most 256");
  }
  if (o.mesh != SurfaceMesh::marching_cubes) image.grey.reset();

  ComponentSelection comps = components_and_betti(mask, o.adjacency, o.component, o.threads,
                                                  image.name, progress, r.betti);
  r.object_components = comps.count;

  progress.start("boundary surfels");
  ImageSurfels sf = image_surfels(mask, o.threads);
  progress.done("surfels", str(sf.size()) + " surfels");
  progress.start("closed surfaces");
  ImageSurfaces ss = image_surfaces(mask, sf, conv, o.threads);
  progress.done("surfaces", str(std::int64_t(ss.surfaces.size())) + " surfaces");
  if (ss.object_euler() != r.betti.euler)
    throw Error("internal: the surfaces give chi = " + str(ss.object_euler()) +
                " but the block table gives " + str(r.betti.euler));
  r.surfels = sf.size();
  r.surfaces = std::int64_t(ss.surfaces.size());
  r.pinched_pointels = ss.pinched_pointels;
  r.pinched_linels = ss.pinched_linels;

  // With harmonic: each closed surface's harmonic dimension from its exterior derivatives
  // (the primal complex: face f is surfel f, as surface_of).
  std::vector<HarmonicDimension> harmonic;
  if (o.harmonic) {
    progress.start("harmonic dimensions (exact ranks of d0, d1)");
    harmonic =
        harmonic_dimensions(surfel_complex(primal_surface_mesh(mask, sf, conv, r.place, o.threads)),
                            ss.surface_of, std::int64_t(ss.surfaces.size()));
    progress.done("harmonic");
  }
  // Per selected component: voxels, surfels, surfaces, Euler characteristic and genus of its
  // boundary (the genus is the sum of its surfaces' genera), likewise the harmonic dimension.
  std::map<std::int64_t, SurfaceComponent> per;
  for (auto l : comps.chosen) {
    per[l].voxels = comps.sizes[std::size_t(l - 1)];
    if (o.harmonic) per[l].harmonic_dim = 0;
  }
  for (std::size_t k = 0; k < ss.surfaces.size(); ++k) {
    const auto& s = ss.surfaces[k];
    std::int64_t l = comps.chosen.front();
    if (comps.labels) l = (*comps.labels)[code_voxel(sf.codes[std::size_t(s.first)])];
    auto& c = per[l];
    c.surfels += s.surfels;
    c.surfaces += 1;
    c.euler += s.euler;
    c.genus += s.genus;
    if (o.harmonic)
      c.harmonic_dim = std::max<std::int64_t>(c.harmonic_dim, 0) + harmonic[k].dimension;
  }
  comps.labels.reset();
  for (auto& [l, c] : per) {
    c.rank = l;
    r.components.push_back(c);
  }

  if (!est.names.empty()) {
    progress.start("estimates");
    const bool principal = est.names.size() > (est.names.count("ii-mean") ? 1u : 0u);
    if (est.names.count("ii-mean"))
      est.mean = volume_ii_mean_curvature(mask, sf, est.h, est.R, o.threads);
    if (principal)
      est.principal = volume_ii_principal_curvatures(mask, sf, est.h, est.R, o.threads);
    progress.done("estimates");
  }
  if (est.names.count("geodesic") || est.names.count("at-normal")) {
    // The cell complex of the primal surface (one surfel per face, in the order of the
    // surfels) and the II normals: what the calculus estimates start from, built once.
    const SurfelComplex cx =
        surfel_complex(primal_surface_mesh(mask, sf, conv, r.place, o.threads));
    std::vector<Point3<double>> normals;
    normals.reserve(est.principal.size());
    for (const auto& p : est.principal) normals.push_back(p.normal);
    if (est.names.count("geodesic")) {
      progress.start("geodesic distance (heat method)");
      compute_geodesic(est, cx, normals, ss, *o.source, image.name);
      progress.done("geodesic");
    }
    if (est.names.count("at-normal")) {
      progress.start("Ambrosio-Tortorelli normals");
      compute_at_normals(est, cx, normals, o.threads);
      progress.done("at-normal");
    }
  }
  if (o.keep_surfels) r.surface_of = std::move(ss.surface_of);
  std::vector<std::uint64_t>().swap(ss.surface_of);

  if (r.mesh_kind != SurfaceMesh::none) {
    const std::string kind = surface_mesh_name(r.mesh_kind);
    progress.start(kind + " mesh");
    PolygonMesh mesh;
    if (r.mesh_kind == SurfaceMesh::primal) {
      mesh = primal_surface_mesh(mask, sf, conv, r.place, o.threads);
      r.mesh_edges = 2 * mesh.face_count() - ss.pinched_linels;
      if (o.regularize) {
        progress.done("mesh", str(mesh.face_count()) + " faces");
        progress.start("regularization");
        std::vector<Point3<double>> normals;
        normals.reserve(est.principal.size());
        for (const auto& q : est.principal) normals.push_back(q.normal);
        RegularizationParameters rp = *o.regularize;
        rp.threads = o.threads;
        // The bound is the voxel's: the cube of side h (the isotropic spacing) at each pointel.
        RegularizationResult reg =
            regularize_surface(mesh, normals, isotropic_step(sp, image.name), rp);
        mesh.vertices = std::move(reg.positions);
        reg.positions = {};
        r.regularization_parameters = rp;
        r.regularization = std::move(reg);
        progress.done("regularization");
        progress.start("mesh fields");
      }
    } else {
      std::optional<IsoLevel> level;
      if (image.grey) {
        level.emplace();
        const ScalarVolume* v = &*image.grey;
        level->value = [v](std::int64_t i) { return v->value(i); };
        level->level = image.grey_level;
      }
      mesh = marching_cubes(mask, sf, conv, r.place, level ? &*level : nullptr, o.threads);
      r.mesh_edges = 3 * mesh.face_count() / 2;
      image.grey.reset(); // the grey values
    }
    { const Image<std::uint8_t> freed = std::move(mask); } // no later step reads the mask
    attach_estimates(mesh, r.mesh_kind, sf, est, o.threads);
    progress.done("mesh", str(mesh.face_count()) + " faces");
    r.mesh = std::move(mesh);
  }
  if (o.keep_surfels) r.surfels_kept = std::move(sf);
  r.seconds = std::move(progress.seconds);
  r.cpu_seconds = std::move(progress.cpu_seconds);
  return r;
}

nlohmann::json to_json(const SurfaceResult& r) {
  const auto& est = r.estimates;
  nlohmann::json components = nlohmann::json::array();
  for (const auto& c : r.components) {
    components.push_back({{"rank", str(c.rank)},
                          {"voxels", str(c.voxels)},
                          {"surfels", str(c.surfels)},
                          {"surfaces", str(c.surfaces)},
                          {"euler", str(c.euler)},
                          {"genus", str(c.genus)}});
    if (c.harmonic_dim >= 0) components.back()["harmonic_dim"] = str(c.harmonic_dim);
  }
  nlohmann::json estimates = nlohmann::json::object();
  const std::size_t n = std::size_t(r.surfels);
  for (const auto& [name, cols] : surface_columns()) {
    if (est.names.count(name) == 0) continue;
    if (name == "ii-normal" || name == "ii-directions") {
      estimates[name] = {{"count", str(std::int64_t(est.principal.size()))}};
    } else if (name == "at-normal") {
      estimates["at-normal"] = {{"count", str(std::int64_t(est.at_normal.size()))},
                                {"alpha", est.at.alpha},
                                {"lambda", est.at.lambda},
                                {"epsilon1", est.at.epsilon1},
                                {"epsilon2", est.at.epsilon2},
                                {"v", at_discretization_name(est.at_discretization)},
                                {"iterations", est.at_iterations},
                                {"solver", est.at_solver}};
      estimates["at-v"] = value_stats(est.at_v);
    } else {
      estimates[name] = value_stats(field_values(est, cols.front(), n));
    }
  }
  if (est.names.count("geodesic")) {
    estimates["geodesic"]["source"] = str(est.source);
    estimates["geodesic"]["time"] = est.geodesic_time;
    estimates["geodesic"]["solver"] = est.geodesic_solver;
  }
  if (!est.names.empty()) {
    estimates["radius"] = est.R;
    estimates["radius_voxels"] = est.R / est.h;
  }
  nlohmann::json j = {{"adjacency", r.adjacency.name()},
                      {"component", component_text(r.component)},
                      {"object_components", str(r.object_components)},
                      {"components", components},
                      {"surfaces", str(r.surfaces)},
                      {"surfels", str(r.surfels)},
                      {"euler", str(r.betti.euler)},
                      {"betti", {str(r.betti.b[0]), str(r.betti.b[1]), str(r.betti.b[2])}},
                      {"pinched_pointels", str(r.pinched_pointels)},
                      {"pinched_linels", str(r.pinched_linels)},
                      {"estimates", estimates},
                      {"seconds", timings(r.seconds)},
                      {"cpu_seconds", timings(r.cpu_seconds)},
                      {"threads", r.threads}};
  if (r.mesh) {
    const auto& m = *r.mesh;
    j["mesh"] = {{"kind", surface_mesh_name(r.mesh_kind)},
                 {"vertices", str(m.vertex_count())},
                 {"faces", str(m.face_count())},
                 {"edges", str(r.mesh_edges)},
                 {"euler", str(m.vertex_count() - r.mesh_edges + m.face_count())}};
  }
  if (r.regularization) {
    const auto& g = *r.regularization;
    const auto& p = *r.regularization_parameters;
    auto energy = [](const RegularizationEnergy& e) {
      return nlohmann::json{{"data", e.data},
                            {"alignment", e.alignment},
                            {"fairness", e.fairness},
                            {"total", e.total()}};
    };
    j["regularization"] = {{"alpha", p.alpha},
                           {"beta", p.beta},
                           {"gamma", p.gamma},
                           {"energy_before", energy(g.before)},
                           {"energy_after", energy(g.after)},
                           {"max_displacement_h", g.max_displacement},
                           {"iterations", g.iterations},
                           {"converged", g.converged},
                           {"kkt_residual", g.kkt_residual},
                           {"solver", g.solver}};
  }
  return j;
}

void write_surface_csv(const std::string& path, const SurfaceResult& r) {
  if (!r.surfels_kept) throw InvalidArgument("write_surface_csv: the surfels were not kept");
  const ImageSurfels& sf = *r.surfels_kept;
  const auto& est = r.estimates;
  const auto columns = computed_columns(est);
  std::ofstream f(path);
  if (!f) throw IoError(path + ": cannot be written");
  std::string out = "surfel,surface,x,y,z,voxel_x,voxel_y,voxel_z,direction";
  for (const auto& c : columns) {
    out += ',';
    out += c.csv;
  }
  out += "\n";
  static const char* dirs[6] = {"-x", "+x", "-y", "+y", "-z", "+z"};
  const VoxelGrid& gr = sf.grid;
  for (std::int64_t i = 0; i < sf.size(); ++i) {
    const auto code = sf.codes[std::size_t(i)];
    const std::int64_t v = code_voxel(code);
    const std::int64_t c[3] = {v % gr.nx, (v / gr.nx) % gr.ny, v / (gr.nx * gr.ny)};
    double p[3] = {double(c[0]), double(c[1]), double(c[2])};
    p[code_axis(code)] += code_positive(code) ? 0.5 : -0.5;
    const auto x = r.place.at(p[0], p[1], p[2]);
    fmt::format_to(std::back_inserter(out), "{},{},{},{},{},{},{},{},{}", i,
                   r.surface_of[std::size_t(i)], x.x, x.y, x.z, c[0] + gr.lower.x,
                   c[1] + gr.lower.y, c[2] + gr.lower.z, dirs[code & 7]);
    for (const auto& col : columns)
      fmt::format_to(std::back_inserter(out), ",{}", col.value(est, std::size_t(i)));
    out += "\n";
    if (out.size() > (std::size_t{1} << 22)) {
      f << out;
      out.clear();
    }
  }
  f << out;
  if (!f) throw IoError(path + ": write failed");
}

// --- zdg contour ---------------------------------------------------------------------------

ContourResult contour_operation(ObjectImage image, const ContourOptions& o) {
  if (image.mask.dim() != 2) throw InvalidArgument(image.name + ": contours need a 2D image");
  make_adjacency_pair(2, o.adjacency.object, o.adjacency.background);
  ContourResult r;
  const auto names = check_estimator_names(o.estimates, contour_estimators());
  auto& req = r.request;
  req.ii_curvature = names.count("ii-curvature") != 0;
  req.bc_tangent = names.count("bc-tangent") != 0;
  req.lmst_tangent = names.count("lmst-tangent") != 0;
  req.mlp_length = names.count("mlp-length") != 0;
  req.gauss_area = names.count("gauss-area") != 0;
  r.adjacency = o.adjacency;
  r.component = o.component;
  r.threads = worker_count(o.threads, std::int64_t{1} << 30);
  OperationProgress progress(o.progress);
  Image<std::uint8_t> mask = std::move(image.mask);
  const auto& dom = mask.domain();
  if (image.spacing.size() != 2 || image.origin.size() != 2)
    throw InvalidArgument(image.name + ": spacing and origin need two values (y, x)");
  r.h = isotropic_step(image.spacing, image.name);
  if (req.ii_curvature || req.bc_tangent)
    check_radius(o.radius, r.h, std::max(dom.extent(0), dom.extent(1)), image.name,
                 "image (" + str(dom.extent(1)) + " x " + str(dom.extent(0)) + " pixels)",
                 "pixels");
  r.R = physical_radius(o.radius, r.h);
  r.origin_pixel = Pixel{dom.lower(1), dom.lower(0)};
  r.origin = Point2<double>{image.origin[1], image.origin[0]};

  r.object_components =
      components_and_betti(mask, o.adjacency, o.component, o.threads, image.name, progress, r.betti)
          .count;
  progress.start("contours");
  r.contours = image_contours(mask, o.adjacency.object, o.adjacency.background);
  progress.done("contours", str(std::int64_t(r.contours.contours.size())) + " contours");
  if (r.contours.b0 != r.betti.b[0] || r.contours.b1 != r.betti.b[1])
    throw Error("internal: the contours give b0, b1 = " + str(r.contours.b0) + ", " +
                str(r.contours.b1) + " but the components give " + str(r.betti.b[0]) + ", " +
                str(r.betti.b[1]));
  if (!names.empty()) {
    progress.start("estimates");
    r.estimates = contour_estimates(mask, r.contours, req, r.h, r.R, o.threads);
    progress.done("estimates");
  }
  if (o.interpolated) {
    progress.start("marching squares");
    std::optional<GreyLevel2> grey;
    if (image.grey) {
      const ScalarVolume* v = &*image.grey;
      const Domain* d = &dom;
      grey.emplace();
      grey->value = [v, d](const Pixel& z) {
        const std::array<std::int64_t, 2> p{z.y, z.x};
        return v->value(d->index(p));
      };
      grey->level = image.grey_level;
      r.interpolated_grey = true;
      r.interpolated_level = image.grey_level;
    }
    r.interpolated = marching_squares(r.contours, dom, grey ? &*grey : nullptr);
    progress.done("marching squares");
  }
  r.mask = std::move(mask);
  r.seconds = std::move(progress.seconds);
  r.cpu_seconds = std::move(progress.cpu_seconds);
  return r;
}

nlohmann::json to_json(const ContourResult& r) {
  const auto& req = r.request;
  const auto& e = r.estimates;
  const auto& cs = r.contours;
  nlohmann::json contours = nlohmann::json::array();
  for (std::size_t c = 0; c < cs.contours.size(); ++c) {
    const auto area2 = cs.contours[c].twice_signed_area();
    nlohmann::json k = {{"linels", str(std::int64_t(cs.contours[c].size()))},
                        {"pixels", str(area2 / 2)},
                        {"kind", area2 > 0 ? "outer" : "hole"}};
    if (req.mlp_length) k["mlp-length"] = e.mlp_length[c];
    if (c < r.interpolated.size())
      k["interpolated"] = {{"length", r.h * r.interpolated[c].length()},
                           {"area", r.h * r.h * r.interpolated[c].signed_area()}};
    contours.push_back(k);
  }
  nlohmann::json estimates = nlohmann::json::object();
  if (req.ii_curvature) {
    std::vector<double> all;
    for (const auto& v : e.ii_curvature) all.insert(all.end(), v.begin(), v.end());
    estimates["ii-curvature"] = value_stats(all);
  }
  if (req.bc_tangent)
    estimates["bc-tangent"] = {{"mask_order", str(e.bc_mask_order)},
                               {"lowered", str(e.bc_lowered)},
                               {"skipped", str(e.bc_skipped)}};
  if (req.lmst_tangent) estimates["lmst-tangent"] = {{"count", str(cs.linels())}};
  if (req.mlp_length) {
    double total = 0;
    for (double l : e.mlp_length) total += l;
    estimates["mlp-length"] = {{"total", total}};
  }
  if (req.gauss_area) estimates["gauss-area"] = {{"area", e.gauss_area}};
  if (req.ii_curvature || req.bc_tangent) {
    estimates["radius"] = r.R;
    estimates["radius_pixels"] = r.R / r.h;
  }
  nlohmann::json out = {{"adjacency", r.adjacency.name()},
                        {"component", component_text(r.component)},
                        {"object_components", str(r.object_components)},
                        {"contours", contours},
                        {"linels", str(cs.linels())},
                        {"euler", str(r.betti.euler)},
                        {"betti", {str(r.betti.b[0]), str(r.betti.b[1])}},
                        {"estimates", estimates},
                        {"seconds", timings(r.seconds)},
                        {"cpu_seconds", timings(r.cpu_seconds)},
                        {"threads", r.threads}};
  if (!r.interpolated.empty() || (cs.contours.empty() && r.interpolated_grey)) {
    double length = 0, area = 0;
    for (const auto& c : r.interpolated) {
      length += c.length();
      area += c.signed_area();
    }
    out["interpolated"] = {{"level", r.interpolated_grey ? nlohmann::json(r.interpolated_level)
                                                         : nlohmann::json(nullptr)},
                           {"length", r.h * length},
                           {"area", r.h * r.h * area}};
  }
  return out;
}

void write_contour_csv(const std::string& path, const ContourResult& r) {
  const auto& cs = r.contours;
  const auto& req = r.request;
  const auto& e = r.estimates;
  const double h = r.h;
  std::ofstream f(path);
  if (!f) throw IoError(path + ": cannot be written");
  std::string out = "contour,linel,pointel_x,pointel_y,code,midpoint_x,midpoint_y,inner_x,inner_y";
  if (req.ii_curvature) out += ",ii_curvature";
  if (req.bc_tangent) out += ",bc_tx,bc_ty";
  if (req.lmst_tangent) out += ",lmst_tx,lmst_ty";
  const bool ms = !r.interpolated.empty();
  if (ms) out += ",interpolated_x,interpolated_y";
  out += "\n";
  for (std::size_t c = 0; c < cs.contours.size(); ++c) {
    const auto& k = cs.contours[c];
    Pixel p = k.start;
    for (std::size_t i = 0; i < k.size(); ++i) {
      const int code = k.codes[i];
      const Pixel d = freeman_step(code);
      const Pixel in = DigitalContour::inner_pixel(p, code);
      // Physical position of the lattice point q: origin + h (q - origin_pixel).
      const double mx = r.origin.x + h * (double(p.x - r.origin_pixel.x) + 0.5 * double(d.x) - 0.5);
      const double my = r.origin.y + h * (double(p.y - r.origin_pixel.y) + 0.5 * double(d.y) - 0.5);
      fmt::format_to(std::back_inserter(out), "{},{},{},{},{},{},{},{},{}", c, i, p.x, p.y, code,
                     mx, my, in.x, in.y);
      if (req.ii_curvature) fmt::format_to(std::back_inserter(out), ",{}", e.ii_curvature[c][i]);
      if (req.bc_tangent)
        fmt::format_to(std::back_inserter(out), ",{},{}", e.bc_tangent[c][i].x,
                       e.bc_tangent[c][i].y);
      if (req.lmst_tangent)
        fmt::format_to(std::back_inserter(out), ",{},{}", e.lmst_tangent[c][i].x,
                       e.lmst_tangent[c][i].y);
      if (ms) {
        const auto& v = r.interpolated[c].vertices[i];
        fmt::format_to(std::back_inserter(out), ",{},{}",
                       r.origin.x + h * (v.x - double(r.origin_pixel.x)),
                       r.origin.y + h * (v.y - double(r.origin_pixel.y)));
      }
      out += "\n";
      p = p + d;
      if (out.size() > (std::size_t{1} << 22)) {
        f << out;
        out.clear();
      }
    }
  }
  f << out;
  if (!f) throw IoError(path + ": write failed");
}

PolygonMesh contour_mesh(const ContourResult& r) {
  const auto& cs = r.contours;
  const auto& req = r.request;
  const auto& e = r.estimates;
  const double h = r.h, w = h / 6;
  PolygonMesh m;
  m.face_size = 4;
  std::vector<double> contour, ii, bx, by, lx, ly;
  for (std::size_t c = 0; c < cs.contours.size(); ++c) {
    const auto& k = cs.contours[c];
    Pixel p = k.start;
    for (std::size_t i = 0; i < k.size(); ++i) {
      const Pixel d = freeman_step(k.codes[i]);
      // The pointel q at origin + h (q - origin_pixel - 1/2), as in write_contour_csv.
      const double ax = r.origin.x + h * (double(p.x - r.origin_pixel.x) - 0.5);
      const double ay = r.origin.y + h * (double(p.y - r.origin_pixel.y) - 0.5);
      const double bx_ = ax + h * double(d.x), by_ = ay + h * double(d.y);
      // The left normal of the step (-dy, dx): the ribbon's corners a - wn, b - wn, b + wn,
      // a + wn turn counterclockwise.
      const double nx = -double(d.y) * w, ny = double(d.x) * w;
      const auto v = m.vertex_count();
      m.vertices.push_back({ax - nx, ay - ny, 0});
      m.vertices.push_back({bx_ - nx, by_ - ny, 0});
      m.vertices.push_back({bx_ + nx, by_ + ny, 0});
      m.vertices.push_back({ax + nx, ay + ny, 0});
      m.indices.insert(m.indices.end(), {v, v + 1, v + 2, v + 3});
      contour.push_back(double(c));
      if (req.ii_curvature) ii.push_back(e.ii_curvature[c][i]);
      if (req.bc_tangent) {
        bx.push_back(e.bc_tangent[c][i].x);
        by.push_back(e.bc_tangent[c][i].y);
      }
      if (req.lmst_tangent) {
        lx.push_back(e.lmst_tangent[c][i].x);
        ly.push_back(e.lmst_tangent[c][i].y);
      }
      p = p + d;
    }
  }
  if (req.ii_curvature) m.face_scalars.emplace_back("ii-curvature", std::move(ii));
  if (req.bc_tangent) {
    m.face_scalars.emplace_back("bc-tangent x", std::move(bx));
    m.face_scalars.emplace_back("bc-tangent y", std::move(by));
  }
  if (req.lmst_tangent) {
    m.face_scalars.emplace_back("lmst-tangent x", std::move(lx));
    m.face_scalars.emplace_back("lmst-tangent y", std::move(ly));
  }
  m.face_scalars.emplace_back("contour", std::move(contour));
  return m;
}

void write_contour_svg(const std::string& path, const ContourResult& r) {
  const auto& dom = r.mask.domain();
  ContourDrawing drawing;
  drawing.box = Box2{{dom.lower(1), dom.lower(0)}, {dom.upper(1), dom.upper(0)}};
  if (r.request.ii_curvature) {
    drawing.field_name = "ii-curvature";
    drawing.field = &r.estimates.ii_curvature;
  }
  write_contour_svg(path, r.contours.contours, drawing);
}

std::vector<ContourPolyline> contour_polylines(const ContourResult& r, const std::string& field) {
  const auto& cs = r.contours;
  if (!field.empty() && (field != "ii-curvature" || !r.request.ii_curvature))
    throw InvalidArgument("contour picture: the field '" + field + "' was not estimated");
  std::vector<ContourPolyline> lines(cs.contours.size());
  const ContourEmbedding lattice{1.0};
  for (std::size_t c = 0; c < cs.contours.size(); ++c) {
    const auto& k = cs.contours[c];
    auto& line = lines[c];
    const std::size_t n = k.size();
    const std::vector<double>* v = field.empty() ? nullptr : &r.estimates.ii_curvature[c];
    Pixel p = k.start;
    for (std::size_t i = 0; i < n; ++i) {
      line.points.push_back(lattice.pointel(p));
      line.points.push_back(lattice.linel_midpoint(p, k.codes[i]));
      if (v != nullptr) {
        const double before = (*v)[(i + n - 1) % n], here = (*v)[i];
        line.values.push_back(std::isnan(before) ? here
                              : std::isnan(here) ? before
                                                 : (before + here) / 2);
        line.values.push_back(here);
      }
      p = p + freeman_step(k.codes[i]);
    }
  }
  return lines;
}

} // namespace zdg
