#include <zdg/kernel/linalg/mean_value_laplacian.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/linalg/cotan_laplacian.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>

namespace zdg {

std::vector<double> MeanValueLaplacian::apply(std::span<const double> u, unsigned threads) const {
  auto y = weights.multiply(u, threads);
  for (std::size_t i = 0; i < y.size(); ++i) y[i] = mass[i] > 0 ? y[i] / mass[i] : 0.0;
  return y;
}

namespace {

// tan(a / 2) of the angle a between p and q: sin a / (1 + cos a) = |p x q| / (|p| |q| + p . q).
double half_angle_tangent(Point3<double> p, Point3<double> q) {
  const auto c = cross(p, q);
  return std::sqrt(dot(c, c)) / (std::sqrt(dot(p, p)) * std::sqrt(dot(q, q)) + dot(p, q));
}

} // namespace

MeanValueLaplacian mean_value_laplacian(std::span<const Point3<double>> vertices,
                                        std::span<const std::array<std::int64_t, 3>> triangles) {
  const auto n = static_cast<std::int64_t>(vertices.size());
  const auto where = [](std::size_t f) {
    return "mean-value Laplacian: triangle " + std::to_string(f);
  };
  // Edge -> number of triangles, for the manifold check.
  std::unordered_map<std::uint64_t, int> edges;
  edges.reserve(3 * triangles.size());
  MeanValueLaplacian L;
  L.mass.assign(vertices.size(), 0.0);
  std::vector<SparseTriplet> t;
  t.reserve(12 * triangles.size());
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    const auto& tri = triangles[f];
    check_triangle_indices(tri, n, "mean-value Laplacian", f);
    const auto& p0 = vertices[std::size_t(tri[0])];
    const auto& p1 = vertices[std::size_t(tri[1])];
    const auto& p2 = vertices[std::size_t(tri[2])];
    const auto c = cross(p1 - p0, p2 - p0);
    if (!(dot(c, c) > 0)) throw InvalidArgument(where(f) + " is degenerate");
    for (int k = 0; k < 3; ++k) {
      const auto a = tri[std::size_t(k)], b = tri[std::size_t((k + 1) % 3)];
      const auto lo = std::uint64_t(std::min(a, b)), hi = std::uint64_t(std::max(a, b));
      // n < 2^32 for any mesh that fits in memory with 12 entries per triangle; checked anyway.
      if (hi >= (std::uint64_t(1) << 32))
        throw InvalidArgument("mean-value Laplacian: more than 2^32 vertices");
      if (++edges[(lo << 32) | hi] > 2)
        throw InvalidArgument("mean-value Laplacian: the edge (" + std::to_string(lo) + ", " +
                              std::to_string(hi) + ") of triangle " + std::to_string(f) +
                              " has more than two triangles (not a manifold)");
    }
    for (int k = 0; k < 3; ++k) {
      // At corner i = tri[k], the angle between the edges to j and to l: tan(a / 2) / |e| goes
      // to w_ij and w_il.
      const auto i = tri[std::size_t(k)], j = tri[std::size_t((k + 1) % 3)],
                 l = tri[std::size_t((k + 2) % 3)];
      const auto& pi = vertices[std::size_t(i)];
      const auto ej = vertices[std::size_t(j)] - pi, el = vertices[std::size_t(l)] - pi;
      const double tn = half_angle_tangent(ej, el);
      for (auto [v, e] : {std::pair{j, ej}, std::pair{l, el}}) {
        const double len = std::sqrt(dot(e, e));
        const double w = tn / len;
        t.push_back({i, v, w});
        t.push_back({i, i, -w});
        L.mass[std::size_t(i)] += 0.25 * w * len * len;
      }
    }
  }
  L.weights = SparseMatrix::from_triplets(n, n, std::move(t));
  return L;
}

} // namespace zdg
