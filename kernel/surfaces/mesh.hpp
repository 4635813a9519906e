// A polygon surface mesh, the common currency of the surface extractors (primal surfel mesh,
// marching cubes), the mesh writers (PLY, OBJ, OFF) and the renderer.
//
//   vertices  points of R^3 (physical units: voxel index times spacing, plus an origin)
//   faces     cycles of face_size vertex indices (3: triangles, 4: quads), in
//             indices[face_size * f .. face_size * f + face_size - 1], ordered
//             counterclockwise seen from outside (the outward normal is given by the
//             right-hand rule), so that a closed mesh is consistently oriented
//   fields    named per-face scalars (estimates: "ii-mean", ...), optional per-face and
//             per-vertex normals (empty, or one per face / vertex)
//
// Indices are int64 (a 2048^3 volume can have more than 2^32 surfel corners).
#pragma once

#include <zdg/arith/error.hpp>
#include <zdg/arith/point.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace zdg {

struct PolygonMesh {
  int face_size = 4;
  std::vector<Point3<double>> vertices;
  std::vector<std::int64_t> indices;
  std::vector<std::pair<std::string, std::vector<double>>> face_scalars;
  std::vector<Point3<double>> face_normals;
  std::vector<Point3<double>> vertex_normals;

  std::int64_t vertex_count() const { return static_cast<std::int64_t>(vertices.size()); }
  std::int64_t face_count() const {
    return face_size > 0 ? static_cast<std::int64_t>(indices.size()) / face_size : 0;
  }
  /// The vertex indices of face f.
  std::span<const std::int64_t> face(std::int64_t f) const {
    return std::span<const std::int64_t>(indices).subspan(static_cast<std::size_t>(f * face_size),
                                                          static_cast<std::size_t>(face_size));
  }
  /// Checks the invariants (face_size >= 3, indices in range, field sizes); InvalidArgument
  /// naming the first violation.
  void validate() const {
    if (face_size < 3)
      throw InvalidArgument("mesh: faces of " + std::to_string(face_size) +
                            " vertices (at least 3 needed)");
    if (indices.size() % static_cast<std::size_t>(face_size) != 0)
      throw InvalidArgument("mesh: " + std::to_string(indices.size()) +
                            " indices is not a whole number of faces of " +
                            std::to_string(face_size));
    for (std::size_t i = 0; i < indices.size(); ++i) {
      if (indices[i] < 0 || indices[i] >= vertex_count())
        throw InvalidArgument("mesh: face " + std::to_string(i / std::size_t(face_size)) +
                              " uses vertex " + std::to_string(indices[i]) + " of " +
                              std::to_string(vertex_count()));
    }
    for (const auto& [name, values] : face_scalars) {
      if (static_cast<std::int64_t>(values.size()) != face_count())
        throw InvalidArgument("mesh: field '" + name + "' has " + std::to_string(values.size()) +
                              " values for " + std::to_string(face_count()) + " faces");
    }
    if (!face_normals.empty() && static_cast<std::int64_t>(face_normals.size()) != face_count())
      throw InvalidArgument("mesh: face normals do not match the faces");
    if (!vertex_normals.empty() &&
        static_cast<std::int64_t>(vertex_normals.size()) != vertex_count())
      throw InvalidArgument("mesh: vertex normals do not match the vertices");
  }
};

} // namespace zdg
