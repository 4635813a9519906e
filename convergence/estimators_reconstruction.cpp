// The reconstruction estimators of the registry (sampled: they run in samples sweeps, `zdg
// converge --samples`). A run samples N points uniformly on the area of the shape with their
// exact outward normals and noise sigma (convergence/surface_sampling.hpp, seeded by the run),
// reconstructs with `method` (estimators/implicit_reconstruction.hpp: hoppe, winding, poisson,
// rbf, imls; 10 neighbours, the other options at their defaults) on the grid of step
//   h = k sqrt(A / N),
// A the surface's area (so h is k times the mean spacing of the samples), and measures the
// marching-cubes mesh of the reconstruction against the exact surface:
//   recon-hausdorff  one error per mesh vertex v, |v - xi(v)| (xi: the nearest surface point),
//                    and one per sample x (noiseless, on the surface), its distance to the mesh
//                    as measured from its nearest mesh vertex w (kd-tree): the distance to the
//                    nearest of the triangles around w (an upper bound of the distance to the
//                    mesh, exact when the nearest triangle touches w). l_inf is the symmetric
//                    Hausdorff distance with the surface taken at the N samples. An empty mesh
//                    gives every sample the diagonal of the shape's bounding box.
//   recon-normal     one error per triangle: the angle (rad) between its normal (right-hand
//                    rule, outward for a correctly oriented reconstruction) and the exact normal
//                    at the projection of its centroid. An empty mesh: one error of pi.
//   recon-betti      one error: 0 when the Betti numbers ((6,26)) of the reconstruction's
//                    inside equal the shape's (those of its fine digitization, the sampling
//                    mesh), 1 otherwise; its mean over repetitions (--translations) is the
//                    fraction of samplings whose topology is wrong.
// The three share one reconstruction per (shape, N, seed, sigma, k, method): a cache of the
// last 16 (a run of each estimator reconstructs at most once).
//
// Rates (papers/THEORY.md, "Reconstruction from samples"): recon-hausdorff of hoppe and imls,
// exact normals, no noise, closed C^3 surface: O(N^{-1/2}) with high probability (the mesh
// within h plus the error of the field's zero set, O(eps^2) for Hoppe's planes, O(eps) for
// IMLS by Kolluri 2008, eps = O((log N / N)^{1/2}) the covering radius of N uniform random
// points). No rate for the other methods, the normal angles or the Betti numbers.
#include <zdg/arith/error.hpp>
#include <zdg/convergence/digitized_3d.hpp>
#include <zdg/convergence/estimator.hpp>
#include <zdg/convergence/number_text.hpp>
#include <zdg/convergence/surface_sampling.hpp>
#include <zdg/estimators/implicit_reconstruction.hpp>
#include <zdg/kernel/points/kd_tree.hpp>

#include <algorithm>
#include <cmath>
#include <list>
#include <memory>
#include <mutex>
#include <numbers>
#include <string>
#include <utility>

namespace zdg {

namespace {

using P3 = Point3<double>;

double length(const P3& v) {
  return std::sqrt(dot(v, v));
}

// The distance from p to the triangle abc (Ericson, Real-Time Collision Detection, 5.1.5: the
// closest point by the Voronoi regions of the vertices, edges and face).
double triangle_distance(const P3& p, const P3& a, const P3& b, const P3& c) {
  const P3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return length(p - a);
  const P3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return length(p - b);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return length(p - (a + ab * (d1 / (d1 - d3))));
  const P3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return length(p - c);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return length(p - (a + ac * (d2 / (d2 - d6))));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    return length(p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)))));
  }
  const double denom = 1 / (va + vb + vc);
  return length(p - (a + ab * (vb * denom) + ac * (vc * denom)));
}

struct ReconRun {
  SurfaceSamples samples;
  PolygonMesh mesh;
  BettiNumbers betti;
  double h = 0;
};

std::shared_ptr<const ReconRun> reconstruction_of(const RunInput& in) {
  const Shape3& shape = detail::as_3d(in.shape);
  const ReconstructionMethod method = reconstruction_method_of(in.choice);
  if (in.samples < 1) {
    throw InvalidArgument("the reconstruction estimators need a number of points (--samples)");
  }
  const std::string key = shape.spec() + "|" + std::to_string(in.samples) + "|" +
                          std::to_string(in.seed) + "|" + real_text(in.sigma) + "|" +
                          real_text(in.k) + "|" + in.choice;
  static std::mutex mutex;
  static std::list<std::pair<std::string, std::shared_ptr<const ReconRun>>> cache;
  {
    std::lock_guard<std::mutex> lock(mutex);
    for (auto it = cache.begin(); it != cache.end(); ++it) {
      if (it->first == key) {
        cache.splice(cache.begin(), cache, it);
        return cache.front().second;
      }
    }
  }
  auto run = std::make_shared<ReconRun>();
  run->samples = sample_surface(shape, in.samples, in.sigma, in.seed);
  run->h = in.k * std::sqrt(run->samples.area / double(in.samples));
  ReconstructionOptions options;
  options.method = method;
  options.threads = 1; // the driver runs the runs in parallel
  if (run->samples.cloud.size() <= options.k) {
    throw InvalidArgument("the reconstruction needs more than " + std::to_string(options.k) +
                          " points (N = " + std::to_string(in.samples) + ")");
  }
  Reconstruction r = reconstruct(run->samples.cloud, run->h, options);
  run->mesh = std::move(r.mesh);
  run->betti = r.betti;
  std::lock_guard<std::mutex> lock(mutex);
  cache.emplace_front(key, run);
  if (cache.size() > 16) cache.pop_back();
  return run;
}

double box_diagonal(const Shape& shape) {
  std::vector<std::pair<double, double>> box;
  if (auto bb = shape.bounding_box()) {
    box = *bb;
  } else {
    box.assign(3, shape.default_domain());
  }
  double s = 0;
  for (const auto& [lo, hi] : box) s += (hi - lo) * (hi - lo);
  return std::sqrt(s);
}

ErrorStats run_hausdorff(const RunInput& in) {
  const auto run = reconstruction_of(in);
  const Shape3& shape = detail::as_3d(in.shape);
  const PolygonMesh& m = run->mesh;
  ErrorAccumulator acc;
  for (const auto& v : m.vertices) acc.add(length(v - shape.project(v).point));
  if (m.vertices.empty()) {
    const double far = box_diagonal(in.shape);
    for (std::size_t i = 0; i < run->samples.exact.size(); ++i) acc.add(far);
    return acc.stats();
  }
  // The triangles around each vertex.
  std::vector<std::vector<std::int64_t>> around(m.vertices.size());
  for (std::int64_t f = 0; f < m.face_count(); ++f) {
    for (auto v : m.face(f)) around[std::size_t(v)].push_back(f);
  }
  const KdTree tree(m.vertices);
  std::vector<Neighbour> nearest;
  for (const auto& x : run->samples.exact) {
    tree.nearest(x, 1, nearest);
    const std::size_t w = nearest.front().index;
    double d = length(x - m.vertices[w]);
    for (auto f : around[w]) {
      const auto t = m.face(f);
      d = std::min(d,
                   triangle_distance(x, m.vertices[std::size_t(t[0])],
                                     m.vertices[std::size_t(t[1])], m.vertices[std::size_t(t[2])]));
    }
    acc.add(d);
  }
  return acc.stats();
}

ErrorStats run_normal(const RunInput& in) {
  const auto run = reconstruction_of(in);
  const Shape3& shape = detail::as_3d(in.shape);
  const PolygonMesh& m = run->mesh;
  ErrorAccumulator acc;
  if (m.face_count() == 0) {
    acc.add(std::numbers::pi);
    return acc.stats();
  }
  for (std::int64_t f = 0; f < m.face_count(); ++f) {
    const auto t = m.face(f);
    const P3 &a = m.vertices[std::size_t(t[0])], &b = m.vertices[std::size_t(t[1])],
             &c = m.vertices[std::size_t(t[2])];
    const P3 n = cross(b - a, c - a);
    const double l = length(n);
    if (l == 0) continue; // a degenerate triangle has no normal
    const SurfacePoint3 p = shape.project((a + b + c) * (1.0 / 3));
    const double cosine = dot(n, p.normal) / (l * length(p.normal));
    acc.add(std::acos(std::clamp(cosine, -1.0, 1.0)));
  }
  return acc.stats();
}

ErrorStats run_betti(const RunInput& in) {
  const auto run = reconstruction_of(in);
  const auto fine = sampling_mesh(detail::as_3d(in.shape));
  ErrorAccumulator acc;
  acc.add(run->betti == fine->betti ? 0.0 : 1.0);
  return acc.stats();
}

std::vector<EstimatorParameter> reconstruction_parameters() {
  EstimatorParameter method{"method", "hoppe", 0, 0,
                            "the reconstruction: hoppe, winding, poisson, rbf, imls "
                            "(estimators/implicit_reconstruction.hpp)"};
  method.check_text = [](const std::string& text) { reconstruction_method_of(text); };
  EstimatorParameter sigma{"sigma", "0", 0.0, 1e3,
                           "standard deviation of the isotropic Gaussian noise of the samples"};
  sigma.closed_below = true;
  return {{"k", "1", 0.0, 100.0, "grid factor: the reconstruction's grid step h = k sqrt(A / N)"},
          method,
          sigma};
}

// Hoppe and IMLS with exact normals and no noise on a closed C^3 surface (header).
std::optional<ProvenRate> hausdorff_rate(const ShapeClass& c, const EstimatorParameters& p) {
  if (!c.c3 || p.sigma != 0) return std::nullopt;
  if (p.choice == "hoppe") {
    return ProvenRate{-0.5, "O(N^{-1/2}) w.h.p.",
                      "closed C^3 surface, N uniform random samples, exact normals, no noise, "
                      "h = k sqrt(A / N)",
                      "derived from Hoppe et al. 1992 (papers/THEORY.md)"};
  }
  if (p.choice == "imls") {
    return ProvenRate{-0.5, "O(N^{-1/2}) w.h.p.",
                      "closed C^3 surface, N uniform random samples, exact normals, no noise, "
                      "rho ~ spacing, h = k sqrt(A / N)",
                      "Kolluri, ACM TALG 2008 (papers/THEORY.md)"};
  }
  return std::nullopt;
}

} // namespace

namespace detail {

void register_reconstruction_estimators(std::vector<Estimator>& out) {
  Estimator hausdorff{
      "recon-hausdorff",
      3,
      "symmetric Hausdorff distance between the mesh of a reconstruction from N sampled points "
      "(uniform on the area, exact normals, noise sigma) and the surface: mesh vertices to their "
      "projection, samples to the mesh; grid step h = k sqrt(A / N)",
      "length",
      reconstruction_parameters(),
      {"O(N^{-1/2}) w.h.p. for hoppe and imls with exact normals and no noise (h ~ N^{-1/2}; "
       "Hoppe et al. 1992, Kolluri 2008); none for winding, poisson, rbf",
       hausdorff_rate},
      run_hausdorff,
      "reconstruction"};
  hausdorff.sampled = true;
  out.push_back(hausdorff);
  Estimator normal{
      "recon-normal",
      3,
      "angle between each triangle's normal of the reconstruction's mesh and the exact normal "
      "at the projection of its centroid (N sampled points, as recon-hausdorff)",
      "angle (rad)",
      reconstruction_parameters(),
      {"none proven: reported without a verdict",
       [](const ShapeClass&, const EstimatorParameters&) -> std::optional<ProvenRate> {
         return std::nullopt;
       }},
      run_normal,
      "reconstruction"};
  normal.sampled = true;
  out.push_back(normal);
  Estimator betti{
      "recon-betti",
      3,
      "0 when the Betti numbers of the reconstruction's inside ((6,26)) equal the shape's, 1 "
      "otherwise (N sampled points, as recon-hausdorff)",
      "topology (0 right, 1 wrong)",
      reconstruction_parameters(),
      {"none: a 0/1 topology check (the mean over repetitions is the failure rate)",
       [](const ShapeClass&, const EstimatorParameters&) -> std::optional<ProvenRate> {
         return std::nullopt;
       }},
      run_betti,
      "reconstruction"};
  betti.sampled = true;
  out.push_back(betti);
}

} // namespace detail

} // namespace zdg
