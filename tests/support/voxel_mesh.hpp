// Test and benchmark support: a trivial primal quad mesh of a voxel set (one quad per
// boundary surfel, corners shared, counterclockwise seen from outside) and a parametric torus
// mesh of any size, to feed the mesh writers and the renderer. (The real surface extractors
// live in kernel/; these are deliberately naive and independent of them.)
#pragma once

#include <zdg/kernel/surfaces/mesh.hpp>

#include <cmath>
#include <cstdint>
#include <functional>
#include <numbers>
#include <unordered_map>

namespace zdg::test {

/// Voxel (x, y, z) is the unit cube centred at (x, y, z); the set is inside(x, y, z) over
/// [lo, hi]^3. A field "z" holds each face's centre height.
inline PolygonMesh
voxel_primal_mesh(const std::function<bool(std::int64_t, std::int64_t, std::int64_t)>& inside,
                  std::int64_t lo, std::int64_t hi) {
  PolygonMesh m;
  m.face_size = 4;
  std::unordered_map<std::int64_t, std::int64_t> corner;
  std::vector<double> zs;
  const std::int64_t span = 2 * (hi - lo) + 8;
  auto vertex = [&](std::int64_t x2, std::int64_t y2, std::int64_t z2) { // doubled coordinates
    const std::int64_t key =
        ((x2 - 2 * lo + 2) * span + (y2 - 2 * lo + 2)) * span + (z2 - 2 * lo + 2);
    auto [it, fresh] = corner.emplace(key, m.vertex_count());
    if (fresh) m.vertices.push_back({x2 / 2.0, y2 / 2.0, z2 / 2.0});
    return it->second;
  };
  auto in = [&](std::int64_t x, std::int64_t y, std::int64_t z) {
    return x >= lo && x <= hi && y >= lo && y <= hi && z >= lo && z <= hi && inside(x, y, z);
  };
  for (std::int64_t z = lo; z <= hi; ++z)
    for (std::int64_t y = lo; y <= hi; ++y)
      for (std::int64_t x = lo; x <= hi; ++x) {
        if (!in(x, y, z)) continue;
        const std::int64_t X = 2 * x, Y = 2 * y, Z = 2 * z;
        auto quad = [&](std::int64_t a, std::int64_t b, std::int64_t c, std::int64_t d, double zc) {
          for (auto v : {a, b, c, d}) m.indices.push_back(v);
          zs.push_back(zc);
        };
        if (!in(x + 1, y, z))
          quad(vertex(X + 1, Y - 1, Z - 1), vertex(X + 1, Y + 1, Z - 1),
               vertex(X + 1, Y + 1, Z + 1), vertex(X + 1, Y - 1, Z + 1), double(z));
        if (!in(x - 1, y, z))
          quad(vertex(X - 1, Y - 1, Z - 1), vertex(X - 1, Y - 1, Z + 1),
               vertex(X - 1, Y + 1, Z + 1), vertex(X - 1, Y + 1, Z - 1), double(z));
        if (!in(x, y + 1, z))
          quad(vertex(X - 1, Y + 1, Z - 1), vertex(X - 1, Y + 1, Z + 1),
               vertex(X + 1, Y + 1, Z + 1), vertex(X + 1, Y + 1, Z - 1), double(z));
        if (!in(x, y - 1, z))
          quad(vertex(X - 1, Y - 1, Z - 1), vertex(X + 1, Y - 1, Z - 1),
               vertex(X + 1, Y - 1, Z + 1), vertex(X - 1, Y - 1, Z + 1), double(z));
        if (!in(x, y, z + 1))
          quad(vertex(X - 1, Y - 1, Z + 1), vertex(X + 1, Y - 1, Z + 1),
               vertex(X + 1, Y + 1, Z + 1), vertex(X - 1, Y + 1, Z + 1), z + 0.5);
        if (!in(x, y, z - 1))
          quad(vertex(X - 1, Y - 1, Z - 1), vertex(X - 1, Y + 1, Z - 1),
               vertex(X + 1, Y + 1, Z - 1), vertex(X + 1, Y - 1, Z - 1), z - 0.5);
      }
  m.face_scalars.emplace_back("z", std::move(zs));
  return m;
}

/// A torus of radii R > r around the z axis as an nu x nv grid of quads (outward, closed),
/// with the field "mean-curvature" (exact: (R + 2 r cos v) / (2 r (R + r cos v))).
inline PolygonMesh torus_mesh(double R, double r, std::int64_t nu, std::int64_t nv) {
  PolygonMesh m;
  m.face_size = 4;
  m.vertices.reserve(static_cast<std::size_t>(nu * nv));
  for (std::int64_t i = 0; i < nu; ++i)
    for (std::int64_t j = 0; j < nv; ++j) {
      const double u = 2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(nu);
      const double v = 2 * std::numbers::pi * static_cast<double>(j) / static_cast<double>(nv);
      m.vertices.push_back({(R + r * std::cos(v)) * std::cos(u),
                            (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)});
    }
  std::vector<double> h;
  h.reserve(static_cast<std::size_t>(nu * nv));
  m.indices.reserve(static_cast<std::size_t>(4 * nu * nv));
  for (std::int64_t i = 0; i < nu; ++i)
    for (std::int64_t j = 0; j < nv; ++j) {
      const std::int64_t i1 = (i + 1) % nu, j1 = (j + 1) % nv;
      // (u, v) increasing: d/du x d/dv points outward for this parametrization.
      for (auto k : {i * nv + j, i1 * nv + j, i1 * nv + j1, i * nv + j1}) m.indices.push_back(k);
      const double v =
          2 * std::numbers::pi * (static_cast<double>(j) + 0.5) / static_cast<double>(nv);
      h.push_back((R + 2 * r * std::cos(v)) / (2 * r * (R + r * std::cos(v))));
    }
  m.face_scalars.emplace_back("mean-curvature", std::move(h));
  return m;
}

} // namespace zdg::test
