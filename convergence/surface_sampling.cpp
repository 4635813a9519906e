#include <zdg/convergence/surface_sampling.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/images/image.hpp>
#include <zdg/kernel/surfaces/image_surfels.hpp>
#include <zdg/kernel/surfaces/marching_cubes.hpp>
#include <zdg/kernel/topology/adjacency.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>
#include <random>
#include <string>

namespace zdg {

namespace {

using P3 = Point3<double>;

constexpr double kDivisions = 80; // h_f = largest side / kDivisions
constexpr double kJacobianMax = 2;

double length(const P3& v) {
  return std::sqrt(dot(v, v));
}

// The area element of the surface per area of the triangle of normal nt at q (header).
double jacobian(const Shape3& shape, const P3& q, const P3& nt, SurfacePoint3& p) {
  p = shape.project(q);
  const double d = dot(q - p.point, p.normal);
  const double parallel = (1 + d * p.k1) * (1 + d * p.k2);
  if (!(parallel > 0)) {
    throw InvalidArgument("sampling shape '" + shape.spec() +
                          "': the fine mesh is not within the reach of the surface");
  }
  return std::abs(dot(nt, p.normal)) / parallel;
}

std::shared_ptr<const SamplingMesh> make_mesh(const Shape3& shape) {
  std::vector<std::pair<double, double>> box;
  if (auto bb = shape.bounding_box()) {
    box = *bb;
  } else {
    box.assign(3, shape.default_domain());
  }
  double side = 0;
  for (const auto& [lo, hi] : box) side = std::max(side, hi - lo);
  auto out = std::make_shared<SamplingMesh>();
  const double h = side / kDivisions;
  out->h = h;
  const VoxelBox b{{static_cast<std::int64_t>(std::floor(box[0].first / h)) - 2,
                    static_cast<std::int64_t>(std::floor(box[1].first / h)) - 2,
                    static_cast<std::int64_t>(std::floor(box[2].first / h)) - 2},
                   {static_cast<std::int64_t>(std::ceil(box[0].second / h)) + 2,
                    static_cast<std::int64_t>(std::ceil(box[1].second / h)) + 2,
                    static_cast<std::int64_t>(std::ceil(box[2].second / h)) + 2}};
  check_voxel_box(b);
  const VoxelPredicate inside = shape.digitize(h, P3{0, 0, 0});
  const std::int64_t nx = b.hi.x - b.lo.x + 1, ny = b.hi.y - b.lo.y + 1, nz = b.hi.z - b.lo.z + 1;
  Image<std::uint8_t> mask(Domain({nz, ny, nx}, {b.lo.z, b.lo.y, b.lo.x}));
  auto& v = mask.values();
  for (std::int64_t z = 0, i = 0; z < nz; ++z)
    for (std::int64_t y = 0; y < ny; ++y)
      for (std::int64_t x = 0; x < nx; ++x, ++i)
        v[std::size_t(i)] = inside({b.lo.x + x, b.lo.y + y, b.lo.z + z}) ? 1 : 0;
  out->betti = betti_numbers(mask, make_adjacency_pair(3, 6, 26));
  const VoxelPlacement place{{h, h, h},
                             {h * double(b.lo.x), h * double(b.lo.y), h * double(b.lo.z)}};
  out->mesh = marching_cubes(mask, image_surfels(mask), SurfaceConvention::of(6, 26), place);
  const PolygonMesh& m = out->mesh;
  if (m.face_count() == 0 || m.face_size != 3) {
    throw InvalidArgument("sampling shape '" + shape.spec() + "': no surface in its box");
  }
  double total = 0, estimate = 0;
  out->cumulative.reserve(std::size_t(m.face_count()));
  for (std::int64_t f = 0; f < m.face_count(); ++f) {
    const auto t = m.face(f);
    const P3 &a = m.vertices[std::size_t(t[0])], &b1 = m.vertices[std::size_t(t[1])],
             &c = m.vertices[std::size_t(t[2])];
    const P3 n = cross(b1 - a, c - a);
    const double area = length(n) / 2;
    total += area;
    out->cumulative.push_back(total);
    if (area == 0) continue;
    const P3 centroid = (a + b1 + c) * (1.0 / 3);
    SurfacePoint3 p;
    const double j = jacobian(shape, centroid, n * (1 / (2 * area)), p);
    if (length(centroid - p.point) > 2 * h) {
      throw InvalidArgument("sampling shape '" + shape.spec() +
                            "': its fine mesh leaves the surface (a shape cut by its box?)");
    }
    estimate += area * j;
  }
  out->area_exact = shape.area().has_value();
  out->area = out->area_exact ? *shape.area() : estimate;
  return out;
}

double uniform01(std::mt19937_64& rng) {
  return double(rng() >> 11) * 0x1.0p-53;
}

} // namespace

std::shared_ptr<const SamplingMesh> sampling_mesh(const Shape3& shape) {
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<const SamplingMesh>> cache;
  {
    std::lock_guard<std::mutex> lock(mutex);
    auto it = cache.find(shape.spec());
    if (it != cache.end()) return it->second;
  }
  auto mesh = make_mesh(shape); // outside the lock: another thread may make it too, same result
  std::lock_guard<std::mutex> lock(mutex);
  return cache.emplace(shape.spec(), std::move(mesh)).first->second;
}

SurfaceSamples sample_surface(const Shape3& shape, std::int64_t n, double sigma,
                              std::uint64_t seed) {
  if (n < 1 || n > 100000000) {
    throw InvalidArgument("sampling: the number of points " + std::to_string(n) +
                          " must be in 1..10^8");
  }
  if (!(sigma >= 0 && std::isfinite(sigma))) {
    throw InvalidArgument("sampling: the noise sigma must be finite and >= 0");
  }
  const auto fine = sampling_mesh(shape);
  const PolygonMesh& m = fine->mesh;
  const double total = fine->cumulative.back();
  std::mt19937_64 rng(seed);
  SurfaceSamples out;
  out.area = fine->area;
  out.cloud.points.reserve(std::size_t(n));
  out.cloud.normals.reserve(std::size_t(n));
  out.exact.reserve(std::size_t(n));
  while (static_cast<std::int64_t>(out.exact.size()) < n) {
    ++out.candidates;
    const double pick = uniform01(rng) * total;
    const auto f = std::min<std::size_t>(
        std::size_t(std::upper_bound(fine->cumulative.begin(), fine->cumulative.end(), pick) -
                    fine->cumulative.begin()),
        fine->cumulative.size() - 1);
    const auto t = m.face(std::int64_t(f));
    const P3 &a = m.vertices[std::size_t(t[0])], &b = m.vertices[std::size_t(t[1])],
             &c = m.vertices[std::size_t(t[2])];
    const P3 nt = cross(b - a, c - a);
    const double nl = length(nt);
    const double r1 = std::sqrt(uniform01(rng)), r2 = uniform01(rng);
    const P3 q = a * (1 - r1) + b * (r1 * (1 - r2)) + c * (r1 * r2);
    const double accept = uniform01(rng);
    if (nl == 0) continue; // a degenerate triangle has probability 0
    SurfacePoint3 p;
    const double j = jacobian(shape, q, nt * (1 / nl), p);
    if (j > kJacobianMax) {
      throw Error("sampling shape '" + shape.spec() +
                  "': an area factor above the rejection bound (the fine mesh is too coarse)");
    }
    if (accept * kJacobianMax >= j) continue;
    P3 x = p.point;
    if (sigma > 0) {
      // Box-Muller: two uniforms give two independent standard Gaussians.
      const double u1 = 1 - uniform01(rng), u2 = uniform01(rng), u3 = 1 - uniform01(rng),
                   u4 = uniform01(rng);
      const double g1 = std::sqrt(-2 * std::log(u1)), g2 = std::sqrt(-2 * std::log(u3));
      const double tau = 2 * std::numbers::pi;
      x = x + P3{g1 * std::cos(tau * u2), g1 * std::sin(tau * u2), g2 * std::cos(tau * u4)} * sigma;
    }
    out.cloud.points.push_back(x);
    out.cloud.normals.push_back(p.normal * (1 / length(p.normal)));
    out.exact.push_back(p.point);
  }
  return out;
}

} // namespace zdg
