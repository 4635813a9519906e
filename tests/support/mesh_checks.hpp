// Test support: combinatorial and geometric checks of a PolygonMesh.
//
//   manifold_defect(mesh)   "" when the mesh is a closed oriented 2-manifold (no face repeats
//                           a vertex; every directed edge is in exactly one face and its
//                           reverse in exactly one other; the faces around every vertex form
//                           a single fan; every vertex is used), else what is wrong
//   mesh_components(mesh)   V, E, F of each connected component (by shared vertices)
//   enclosed_volume(mesh)   the signed volume (divergence theorem over a fan triangulation)
//   edge_uses(mesh)         for each undirected vertex pair {u < v} of a face edge: how many
//                           faces run it u -> v and how many v -> u
#pragma once

#include <zdg/kernel/surfaces/mesh.hpp>

#include <cstdint>
#include <map>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

namespace zdg::test {

inline std::string manifold_defect(const PolygonMesh& m) {
  const std::int64_t F = m.face_count(), k = m.face_size;
  std::map<std::pair<std::int64_t, std::int64_t>, std::int64_t> directed;
  // around[v]: for each face (.. u v w ..), the pair (u, w).
  std::vector<std::vector<std::pair<std::int64_t, std::int64_t>>> around(
      static_cast<std::size_t>(m.vertex_count()));
  for (std::int64_t f = 0; f < F; ++f) {
    const auto face = m.face(f);
    for (std::int64_t i = 0; i < k; ++i) {
      const auto u = face[std::size_t((i + k - 1) % k)], v = face[std::size_t(i)],
                 w = face[std::size_t((i + 1) % k)];
      if (u == v || v == w || u == w) return "face " + std::to_string(f) + " repeats a vertex";
      if (++directed[{v, w}] > 1)
        return "directed edge " + std::to_string(v) + "->" + std::to_string(w) + " twice";
      around[std::size_t(v)].emplace_back(u, w);
    }
  }
  for (const auto& [e, n] : directed)
    if (!directed.count({e.second, e.first}))
      return "edge " + std::to_string(e.first) + "->" + std::to_string(e.second) +
             " has no opposite (open or inconsistently oriented)";
  for (std::size_t v = 0; v < around.size(); ++v) {
    const auto& a = around[v];
    if (a.empty()) return "vertex " + std::to_string(v) + " is in no face";
    std::map<std::int64_t, std::int64_t> next; // u -> w
    for (const auto& [u, w] : a) next[u] = w;
    std::int64_t x = a[0].first, steps = 0;
    do {
      auto it = next.find(x);
      if (it == next.end()) return "vertex " + std::to_string(v) + ": open fan";
      x = it->second;
      ++steps;
    } while (x != a[0].first && steps <= std::int64_t(a.size()));
    if (steps != std::int64_t(a.size()))
      return "vertex " + std::to_string(v) + ": " + std::to_string(a.size()) +
             " faces in more than one fan (non-manifold vertex)";
  }
  return "";
}

struct MeshComponent {
  std::int64_t vertices = 0, edges = 0, faces = 0;
  std::int64_t euler() const { return vertices - edges + faces; }
};

inline std::vector<MeshComponent> mesh_components(const PolygonMesh& m) {
  std::vector<std::int64_t> parent(static_cast<std::size_t>(m.vertex_count()));
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](std::int64_t x) {
    while (parent[std::size_t(x)] != x)
      x = parent[std::size_t(x)] = parent[std::size_t(parent[std::size_t(x)])];
    return x;
  };
  for (std::int64_t f = 0; f < m.face_count(); ++f) {
    const auto face = m.face(f);
    for (std::size_t i = 1; i < face.size(); ++i) {
      const auto a = find(face[0]), b = find(face[i]);
      if (a != b) parent[std::size_t(std::max(a, b))] = std::min(a, b);
    }
  }
  std::map<std::int64_t, MeshComponent> comp;
  for (std::int64_t v = 0; v < m.vertex_count(); ++v) comp[find(v)].vertices++;
  std::map<std::pair<std::int64_t, std::int64_t>, bool> edges;
  for (std::int64_t f = 0; f < m.face_count(); ++f) {
    const auto face = m.face(f);
    comp[find(face[0])].faces++;
    for (std::size_t i = 0; i < face.size(); ++i) {
      const auto u = face[i], w = face[(i + 1) % face.size()];
      if (edges.emplace(std::pair{std::min(u, w), std::max(u, w)}, true).second)
        comp[find(u)].edges++;
    }
  }
  std::vector<MeshComponent> out;
  for (const auto& [r, c] : comp) out.push_back(c);
  return out;
}

inline std::map<std::pair<std::int64_t, std::int64_t>, std::pair<int, int>>
edge_uses(const PolygonMesh& m) {
  std::map<std::pair<std::int64_t, std::int64_t>, std::pair<int, int>> uses;
  for (std::int64_t f = 0; f < m.face_count(); ++f) {
    const auto face = m.face(f);
    for (std::size_t i = 0; i < face.size(); ++i) {
      const auto u = face[i], w = face[(i + 1) % face.size()];
      auto& e = uses[{std::min(u, w), std::max(u, w)}];
      (u < w ? e.first : e.second) += 1;
    }
  }
  return uses;
}

inline double enclosed_volume(const PolygonMesh& m) {
  double v = 0;
  for (std::int64_t f = 0; f < m.face_count(); ++f) {
    const auto face = m.face(f);
    const auto& a = m.vertices[std::size_t(face[0])];
    for (std::size_t i = 1; i + 1 < face.size(); ++i) {
      const auto& b = m.vertices[std::size_t(face[i])];
      const auto& c = m.vertices[std::size_t(face[i + 1])];
      v += a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) +
           a.z * (b.x * c.y - b.y * c.x);
    }
  }
  return v / 6;
}

} // namespace zdg::test
