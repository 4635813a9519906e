// Reading a PLY mesh (Turk's polygon file format, PLY 1.0), the input of `zdg view` and of the
// commands that take a triangle or quad mesh: the files zdg writes (kernel/io/mesh_io.hpp) and
// those of MeshLab, Blender, CGAL, Open3D and the like.
//
//   formats   ascii, binary_little_endian and binary_big_endian; the scalar types char/int8,
//             uchar/uint8, short/int16, ushort/uint16, int/int32, uint/uint32, float/float32,
//             double/float64; lists with an integer count type
//   vertex    x, y, z (required, any numeric type); nx, ny, nz as vertex normals; every other
//             scalar property as a per-vertex scalar
//   face      a list named vertex_indices or vertex_index (required); nx, ny, nz as face
//             normals; every other scalar property as a per-face scalar (the estimates). When
//             the header has zdg's "comment face fields: NAME ..." with as many names as such
//             properties, the fields take those names ("ii-mean"), otherwise the property's
//   other     elements (edge, material, ...) and list properties other than the indices are
//             read past and ignored
//
// A PolygonMesh has one face size: when the faces do not all have the same number of
// vertices, each face of k vertices becomes the fan of k - 2 triangles (v0, vi, vi+1), which
// carries the face's scalars and normal, and `triangulated` says so.
//
// Errors: IoError "SOURCE: what was wrong" naming the element and record ("face 12: vertex
// index 40 out of range (36 vertices)"), for a bad header, a truncated or overlong body, a
// coordinate that is not finite, a face of fewer than 3 vertices or a count beyond what the
// rest of the file can hold. Memory is taken as records are read, never for a header's claim
// alone. Cost: O(size of the file); memory: the mesh plus the file's bytes (read_ply).
#pragma once

#include <zdg/kernel/surfaces/mesh.hpp>

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace zdg {

struct PlyMesh {
  PolygonMesh mesh;
  /// Per-vertex scalars (the vertex element's properties other than x, y, z, nx, ny, nz).
  std::vector<std::pair<std::string, std::vector<double>>> vertex_scalars;
  std::string format;             ///< "ascii", "binary_little_endian" or "binary_big_endian"
  std::int64_t file_faces = 0;    ///< faces in the file (before triangulation)
  bool triangulated = false;      ///< faces of several sizes were split into triangles
  std::vector<std::string> other; ///< ignored elements and properties ("edge", "face.texcoord")
};

/// Parses the bytes of a PLY file; `source` names it in errors.
PlyMesh parse_ply(std::string_view bytes, const std::string& source);

/// As parse_ply, but a file without a face element is accepted: a point cloud (the mesh then
/// has its vertices, their normals when given, and no faces). A face element, when present, is
/// read and checked as parse_ply does. The reader of kernel/io/point_cloud_io.hpp.
PlyMesh parse_ply_points(std::string_view bytes, const std::string& source);

/// Reads and parses the file at path (kernel/io/input_file.hpp's checks).
PlyMesh read_ply(const std::string& path);

} // namespace zdg
