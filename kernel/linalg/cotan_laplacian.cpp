#include <zdg/kernel/linalg/cotan_laplacian.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>

#include <cmath>
#include <string>

namespace zdg {

std::vector<double> CotanLaplacian::apply(std::span<const double> u, unsigned threads) const {
  auto y = stiffness.multiply(u, threads);
  for (std::size_t i = 0; i < y.size(); ++i) y[i] = mass[i] > 0 ? y[i] / mass[i] : 0.0;
  return y;
}

void check_triangle_indices(const std::array<std::int64_t, 3>& tri, std::int64_t n,
                            const std::string& who, std::size_t f) {
  for (auto v : tri)
    if (v < 0 || v >= n)
      throw InvalidArgument(who + ": triangle " + std::to_string(f) + " uses vertex " +
                            std::to_string(v) + " of " + std::to_string(n));
  if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
    throw InvalidArgument(who + ": triangle " + std::to_string(f) + " repeats a vertex");
}

CotanLaplacian cotan_laplacian(std::span<const Point3<double>> vertices,
                               std::span<const std::array<std::int64_t, 3>> triangles) {
  const auto n = static_cast<std::int64_t>(vertices.size());
  CotanLaplacian L;
  L.mass.assign(vertices.size(), 0.0);
  std::vector<SparseTriplet> t;
  t.reserve(12 * triangles.size());
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    const auto& tri = triangles[f];
    for (auto v : tri)
      if (v < 0 || v >= n)
        throw InvalidArgument("cotan Laplacian: triangle " + std::to_string(f) + " uses vertex " +
                              std::to_string(v) + " of " + std::to_string(n));
    const auto& p0 = vertices[std::size_t(tri[0])];
    const auto& p1 = vertices[std::size_t(tri[1])];
    const auto& p2 = vertices[std::size_t(tri[2])];
    const auto c = cross(p1 - p0, p2 - p0);
    const double twice_area = std::sqrt(dot(c, c));
    if (!(twice_area > 0))
      throw InvalidArgument("cotan Laplacian: triangle " + std::to_string(f) + " is degenerate");
    for (int k = 0; k < 3; ++k) {
      // The angle at corner k is opposite the edge (i, j).
      const auto i = tri[std::size_t((k + 1) % 3)], j = tri[std::size_t((k + 2) % 3)];
      const auto& pk = vertices[std::size_t(tri[std::size_t(k)])];
      const auto a = vertices[std::size_t(i)] - pk, b = vertices[std::size_t(j)] - pk;
      const double w = 0.5 * dot(a, b) / twice_area; // cot / 2 (|a x b| = twice the area)
      t.push_back({i, j, w});
      t.push_back({j, i, w});
      t.push_back({i, i, -w});
      t.push_back({j, j, -w});
      L.mass[std::size_t(tri[std::size_t(k)])] += twice_area / 6;
    }
  }
  L.stiffness = SparseMatrix::from_triplets(n, n, std::move(t));
  return L;
}

std::vector<std::array<std::int64_t, 3>>
triangulate_quads(std::span<const std::array<std::int64_t, 4>> quads) {
  std::vector<std::array<std::int64_t, 3>> t;
  t.reserve(2 * quads.size());
  for (const auto& q : quads) {
    t.push_back({q[0], q[1], q[2]});
    t.push_back({q[0], q[2], q[3]});
  }
  return t;
}

CotanLaplacian cotan_laplacian(const PolygonMesh& mesh) {
  if (mesh.face_size != 3 && mesh.face_size != 4)
    throw InvalidArgument("cotan_laplacian: faces of " + std::to_string(mesh.face_size) +
                          " vertices (triangles or quads only)");
  const auto nf = static_cast<std::size_t>(mesh.face_count());
  if (mesh.face_size == 4) { // split as triangulate_quads does
    std::vector<std::array<std::int64_t, 4>> q(nf);
    for (std::size_t f = 0; f < nf; ++f)
      for (std::size_t k = 0; k < 4; ++k) q[f][k] = mesh.indices[4 * f + k];
    return cotan_laplacian(mesh.vertices, triangulate_quads(q));
  }
  std::vector<std::array<std::int64_t, 3>> t(nf);
  for (std::size_t f = 0; f < nf; ++f)
    for (std::size_t k = 0; k < 3; ++k) t[f][k] = mesh.indices[3 * f + k];
  return cotan_laplacian(mesh.vertices, t);
}

SparseMatrix combinatorial_laplacian(const SurfelComplex& c) {
  const auto n = c.surfel_count();
  std::vector<SparseTriplet> t;
  t.reserve(std::size_t(5 * n));
  for (std::int64_t s = 0; s < n; ++s) {
    const double a = c.areas[std::size_t(s)];
    for (int i = 0; i < 4; ++i) {
      t.push_back({s, c.neighbour(s, i), 1 / a});
      t.push_back({s, s, -1 / a});
    }
  }
  return SparseMatrix::from_triplets(n, n, std::move(t));
}

} // namespace zdg
