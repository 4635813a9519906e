#include <zdg/estimators/point_normals.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/estimators/jet_fitting.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numeric>
#include <queue>
#include <tuple>
#include <utility>

namespace zdg {

namespace {

Point3<double> unit(const Point3<double>& v) {
  const double l = std::sqrt(dot(v, v));
  return {v.x / l, v.y / l, v.z / l};
}

// The normal turned into the half-space z > 0 (y > 0 when z = 0, then x > 0).
Point3<double> canonical_sign(const Point3<double>& n) {
  const bool flip = n.z < 0 || (n.z == 0 && (n.y < 0 || (n.y == 0 && n.x < 0)));
  return flip ? -n : n;
}

void check_k(std::size_t k, std::size_t n, PointNormalMethod method) {
  if (k < 3)
    throw InvalidArgument("point normals: k = " + std::to_string(k) +
                          " neighbours are too few (at least 3)");
  if (method == PointNormalMethod::jet && k < 5)
    throw InvalidArgument("point normals: the jet needs k >= 5 neighbours (the 6 coefficients "
                          "of a quadric), got k = " +
                          std::to_string(k));
  if (n == 0 || k > n - 1)
    throw InvalidArgument("point normals: too few neighbours: k = " + std::to_string(k) +
                          " needs at least " + std::to_string(k + 1) + " points, the cloud has " +
                          std::to_string(n));
}

// The bits of x (21 of them) spread to every third bit: a Morton code's one coordinate.
std::uint64_t spread_bits(std::uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffff;
  x = (x | x << 16) & 0x1f0000ff0000ff;
  x = (x | x << 8) & 0x100f00f00f00f00f;
  x = (x | x << 4) & 0x10c30c30c30c30c3;
  x = (x | x << 2) & 0x1249249249249249;
  return x;
}

// The tree's points in Morton order (21 bits per axis over their bounding box, ties by index):
// the order in which the queries run, so that consecutive queries visit the same part of the
// tree and of the points (bench/README.md). The results do not depend on it.
std::vector<std::size_t> spatial_order(const KdTree& tree) {
  const std::size_t n = tree.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  if (n == 0) return order;
  Point3<double> lo = tree.point(0), hi = lo;
  for (std::size_t i = 1; i < n; ++i) {
    const auto& p = tree.point(i);
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  const auto cell = [](double v, double a, double b) {
    if (!(b > a)) return std::uint64_t{0};
    const double t = std::clamp((v - a) / (b - a), 0.0, 1.0);
    return static_cast<std::uint64_t>(t * 2097151.0);
  };
  std::vector<std::pair<std::uint64_t, std::size_t>> key(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& p = tree.point(i);
    key[i] = {spread_bits(cell(p.x, lo.x, hi.x)) | spread_bits(cell(p.y, lo.y, hi.y)) << 1 |
                  spread_bits(cell(p.z, lo.z, hi.z)) << 2,
              i};
  }
  std::sort(key.begin(), key.end());
  for (std::size_t i = 0; i < n; ++i) order[i] = key[i].second;
  return order;
}

// The k nearest other points of every tree point, row i at [i k, i k + k) (the point itself
// left out: it is the first of its own k + 1 nearest when the points are distinct).
std::vector<std::size_t> knn_lists(const KdTree& tree, std::size_t k, unsigned threads,
                                   const std::vector<std::size_t>& order) {
  const std::size_t n = tree.size();
  std::vector<std::size_t> out(n * k);
  parallel_chunks(static_cast<std::int64_t>(n), threads, [&](std::int64_t b, std::int64_t e) {
    std::vector<Neighbour> nb;
    for (auto at = static_cast<std::size_t>(b); at < static_cast<std::size_t>(e); ++at) {
      const std::size_t i = order[at];
      tree.nearest(tree.point(i), k + 1, nb);
      std::size_t m = 0;
      for (const auto& x : nb)
        if (x.index != i && m < k) out[i * k + m++] = x.index;
    }
  });
  return out;
}

// The symmetrized graph of the lists, as sorted rows without repeats (CSR).
struct Graph {
  std::vector<std::size_t> start, adj;
};

Graph riemannian_graph(const std::vector<std::size_t>& knn, std::size_t n, std::size_t k) {
  Graph g;
  std::vector<std::size_t> degree(n, k);
  for (const std::size_t j : knn) ++degree[j];
  g.start.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) g.start[i + 1] = g.start[i] + degree[i];
  g.adj.resize(g.start[n]);
  std::vector<std::size_t> fill(g.start.begin(), g.start.end() - 1);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t m = 0; m < k; ++m) {
      const std::size_t j = knn[i * k + m];
      g.adj[fill[i]++] = j;
      g.adj[fill[j]++] = i;
    }
  // Sort and compact each row.
  std::size_t w = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto b = g.adj.begin() + static_cast<std::ptrdiff_t>(g.start[i]);
    const auto e = g.adj.begin() + static_cast<std::ptrdiff_t>(g.start[i + 1]);
    std::sort(b, e);
    const auto u = std::unique(b, e);
    g.start[i] = w;
    for (auto it = b; it != u; ++it) g.adj[w++] = *it;
  }
  g.start[n] = w;
  g.adj.resize(w);
  return g;
}

std::size_t orient(const KdTree& tree, const std::vector<std::size_t>& knn, std::size_t k,
                   std::vector<Point3<double>>& normals) {
  const std::size_t n = tree.size();
  const Graph g = riemannian_graph(knn, n, k);
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const double za = tree.point(a).z, zb = tree.point(b).z;
    return za != zb ? za > zb : a < b;
  });
  std::vector<char> done(n, 0);
  using Edge = std::tuple<double, std::size_t, std::size_t>; // (weight, to, from)
  std::priority_queue<Edge, std::vector<Edge>, std::greater<Edge>> heap;
  std::size_t components = 0;
  const auto push_edges = [&](std::size_t i) {
    for (std::size_t a = g.start[i]; a < g.start[i + 1]; ++a) {
      const std::size_t j = g.adj[a];
      if (!done[j]) heap.emplace(1 - std::abs(dot(normals[i], normals[j])), j, i);
    }
  };
  for (const std::size_t seed : order) {
    if (done[seed]) continue;
    ++components;
    if (normals[seed].z < 0) normals[seed] = -normals[seed];
    done[seed] = 1;
    push_edges(seed);
    while (!heap.empty()) {
      const auto [w, to, from] = heap.top();
      heap.pop();
      if (done[to]) continue;
      if (dot(normals[from], normals[to]) < 0) normals[to] = -normals[to];
      done[to] = 1;
      push_edges(to);
    }
  }
  return components;
}

void check_normals(const std::vector<Point3<double>>& normals, std::size_t n) {
  if (normals.size() != n)
    throw InvalidArgument("orient normals: " + std::to_string(normals.size()) + " normals for " +
                          std::to_string(n) + " points");
  for (std::size_t i = 0; i < n; ++i) {
    const auto& v = normals[i];
    if (!(std::isfinite(dot(v, v)) && dot(v, v) > 0))
      throw InvalidArgument("orient normals: the normal of point " + std::to_string(i) +
                            " is zero or not finite");
  }
}

} // namespace

std::string point_normal_method_name(PointNormalMethod m) {
  return m == PointNormalMethod::pca ? "pca" : "jet";
}

PointNormalMethod point_normal_method_from_name(const std::string& name) {
  if (name == "pca") return PointNormalMethod::pca;
  if (name == "jet") return PointNormalMethod::jet;
  throw InvalidArgument("normal method '" + name + "': expected pca or jet");
}

std::string point_normal_orientation_name(PointNormalOrientation o) {
  return o == PointNormalOrientation::mst ? "mst" : "none";
}

PointNormalOrientation point_normal_orientation_from_name(const std::string& name) {
  if (name == "mst") return PointNormalOrientation::mst;
  if (name == "none") return PointNormalOrientation::none;
  throw InvalidArgument("normal orientation '" + name + "': expected mst or none");
}

Point3<double> pca_normal(std::span<const Point3<double>> nb) {
  if (nb.size() < 3)
    throw InvalidArgument("pca normal: " + std::to_string(nb.size()) +
                          " points (at least 3 needed)");
  Point3<double> c{0, 0, 0};
  for (const auto& p : nb) c += p;
  c = (1.0 / static_cast<double>(nb.size())) * c;
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
  for (const auto& p : nb) {
    const Eigen::Vector3d d(p.x - c.x, p.y - c.y, p.z - c.z);
    m += d * d.transpose();
  }
  const double scale = m.cwiseAbs().maxCoeff();
  if (scale > 0) m /= scale;
  // The iterative solver: the closed form (computeDirect) loses up to 1e-7 on thin
  // neighbourhoods far from the origin, the QR iteration stays near the rounding of C.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(m);
  const Eigen::Vector3d v = solver.eigenvectors().col(0); // eigenvalues in increasing order
  return unit({v.x(), v.y(), v.z()});
}

PointNormals point_normals(const KdTree& tree, const PointNormalsOptions& options) {
  const std::size_t n = tree.size(), k = options.k;
  check_k(k, n, options.method);
  PointNormals out;
  out.normals.resize(n);
  const bool orienting = options.orientation == PointNormalOrientation::mst;
  // The lists are kept for the orientation; without it each chunk queries as it goes.
  const std::vector<std::size_t> order = spatial_order(tree);
  std::vector<std::size_t> knn;
  if (orienting) knn = knn_lists(tree, k, options.threads, order);
  parallel_chunks(
      static_cast<std::int64_t>(n), options.threads, [&](std::int64_t b, std::int64_t e) {
        std::vector<Neighbour> found;
        std::vector<Point3<double>> nb;
        nb.reserve(k + 1);
        for (auto at = static_cast<std::size_t>(b); at < static_cast<std::size_t>(e); ++at) {
          const std::size_t i = order[at];
          nb.clear();
          nb.push_back(tree.point(i));
          if (orienting) {
            for (std::size_t m = 0; m < k; ++m) nb.push_back(tree.point(knn[i * k + m]));
          } else {
            tree.nearest(tree.point(i), k + 1, found);
            for (const auto& x : found)
              if (x.index != i && nb.size() < k + 1) nb.push_back(tree.point(x.index));
          }
          Point3<double> v = options.method == PointNormalMethod::pca
                                 ? pca_normal(nb)
                                 : jet_fit(nb, Point3<double>{0, 0, 1}, 2).normal;
          out.normals[i] = canonical_sign(v);
        }
      });
  if (options.method == PointNormalMethod::jet) {
    for (std::size_t i = 0; i < n; ++i) {
      const auto& v = out.normals[i];
      if (!(std::isfinite(dot(v, v)) && dot(v, v) > 0))
        throw InvalidArgument("point normals: the jet fit at point " + std::to_string(i) +
                              " failed (its neighbours are degenerate)");
    }
  }
  if (orienting) {
    out.components = orient(tree, knn, k, out.normals);
    out.oriented = true;
  }
  return out;
}

PointNormals point_normals(const PointCloud& cloud, const PointNormalsOptions& options,
                           const std::string& source) {
  validate_point_cloud(cloud, source);
  check_k(options.k, cloud.size(), options.method);
  const KdTree tree(cloud.points);
  return point_normals(tree, options);
}

std::size_t orient_normals_mst(const KdTree& tree, std::size_t k,
                               std::vector<Point3<double>>& normals, unsigned threads) {
  check_k(k, tree.size(), PointNormalMethod::pca);
  check_normals(normals, tree.size());
  std::vector<Point3<double>> units(normals.size());
  for (std::size_t i = 0; i < normals.size(); ++i) units[i] = unit(normals[i]);
  const std::size_t components =
      orient(tree, knn_lists(tree, k, threads, spatial_order(tree)), k, units);
  // The given normals keep their lengths; only their signs change.
  for (std::size_t i = 0; i < normals.size(); ++i)
    if (dot(units[i], normals[i]) < 0) normals[i] = -normals[i];
  return components;
}

} // namespace zdg
