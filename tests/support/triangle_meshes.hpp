// Triangle meshes for the tests and benchmarks of the mesh estimators (Ambrosio-Tortorelli on
// meshes): a triangulated grid on a plane (with a boundary), the closed cube [-1, 1]^3 whose
// faces are n x n grids of squares cut into two triangles each (12 n^2 triangles, 6 n^2 + 2
// vertices, consistently oriented outwards), the same mesh projected onto the unit sphere, and
// a vertex noise. Each face records the cube face it lies on (0..5: -x, +x, -y, +y, -z, +z).
#pragma once

#include <zdg/arith/point.hpp>
#include <zdg/kernel/surfaces/mesh.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <vector>

namespace zdg::test {

struct LabelledMesh {
  PolygonMesh mesh;
  std::vector<int> side; ///< per face: the cube face (0..5), or 0 on the plane
};

/// The plane z = 0 over [0, n]^2, unit squares cut along a diagonal (2 n^2 triangles, normal
/// +z), with its boundary.
inline LabelledMesh plane_mesh(int n) {
  LabelledMesh m;
  m.mesh.face_size = 3;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.mesh.vertices.push_back({double(i), double(j), 0.0});
  const auto at = [n](int i, int j) { return std::int64_t(j) * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      for (const auto v : {at(i, j), at(i + 1, j), at(i + 1, j + 1)}) m.mesh.indices.push_back(v);
      for (const auto v : {at(i, j), at(i + 1, j + 1), at(i, j + 1)}) m.mesh.indices.push_back(v);
      m.side.insert(m.side.end(), {0, 0});
    }
  return m;
}

/// The closed cube [-1, 1]^3, each face an n x n grid (see above).
inline LabelledMesh cube_mesh(int n) {
  LabelledMesh m;
  m.mesh.face_size = 3;
  std::map<std::array<int, 3>, std::int64_t> index;
  const auto vertex = [&](std::array<int, 3> k) {
    const auto [it, added] = index.emplace(k, std::int64_t(m.mesh.vertices.size()));
    if (added)
      m.mesh.vertices.push_back({2.0 * k[0] / n - 1, 2.0 * k[1] / n - 1, 2.0 * k[2] / n - 1});
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int sign = 0; sign < 2; ++sign) {
      const int u = (axis + 1) % 3, w = (axis + 2) % 3;
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
          std::array<std::array<int, 3>, 4> q{};
          const int corner[4][2] = {{a, b}, {a + 1, b}, {a + 1, b + 1}, {a, b + 1}};
          for (int c = 0; c < 4; ++c) {
            q[c][axis] = sign * n;
            q[c][u] = corner[c][0];
            q[c][w] = corner[c][1];
          }
          // (u, w, axis) is right-handed: the corners run counterclockwise seen from +axis.
          std::array<std::int64_t, 4> v{};
          for (int c = 0; c < 4; ++c) v[c] = vertex(q[sign == 1 ? c : 3 - c]);
          for (const auto t : {v[0], v[1], v[2], v[0], v[2], v[3]}) m.mesh.indices.push_back(t);
          m.side.insert(m.side.end(), {2 * axis + sign, 2 * axis + sign});
        }
    }
  return m;
}

/// The cube mesh projected onto the unit sphere (a smooth closed mesh of 12 n^2 triangles).
inline LabelledMesh sphere_mesh(int n) {
  LabelledMesh m = cube_mesh(n);
  for (auto& p : m.mesh.vertices) p = (1 / std::sqrt(dot(p, p))) * p;
  return m;
}

/// Moves every vertex by a Gaussian vector of standard deviation sigma per coordinate.
inline void add_vertex_noise(PolygonMesh& mesh, double sigma, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> d(0.0, sigma);
  for (auto& p : mesh.vertices) p = p + Point3<double>{d(rng), d(rng), d(rng)};
}

/// The outward normal of cube face `side` (0..5: -x, +x, -y, +y, -z, +z).
inline Point3<double> side_normal(int side) {
  Point3<double> n{0, 0, 0};
  const double s = side % 2 == 1 ? 1.0 : -1.0;
  (side / 2 == 0 ? n.x : side / 2 == 1 ? n.y : n.z) = s;
  return n;
}

} // namespace zdg::test
