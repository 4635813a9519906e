// Writing a PolygonMesh (kernel/surfaces/mesh.hpp) for ParaView, MeshLab, Blender and the like.
//
//   .ply  binary little-endian (PLY 1.0): element vertex with float x, y, z (and float nx, ny,
//         nz when the mesh has vertex normals); element face with "list uchar int
//         vertex_indices" ("list uchar uint" past 2^31 - 1 vertices), float nx, ny, nz when it
//         has face normals, and one float property per face scalar (the estimates), named as
//         the field with every character outside [A-Za-z0-9_] replaced by '_' ("ii-mean" ->
//         "ii_mean"); a comment line lists the original names
//   .obj  text: "v x y z", "vn" for vertex normals, "f i j k l" with 1-based indices
//         ("f i//i ..." with vertex normals); the face scalars are not stored (OBJ has no
//         per-face values)
//   .off  text: "OFF", "V F 0", vertices, faces "n i j k l" 0-based; no scalars
//
// Coordinates and values are written as float32 (PLY; the shortest decimal text that reads
// back to that float in OBJ and OFF). The mesh is validated first (InvalidArgument); a PLY
// needs at most 2^32 - 1 vertices and faces of at most 255 vertices. Files are written
// through a staging file and renamed (kernel/io/output_files.hpp): an error leaves nothing.
// Cost: O(V + F) time, memory O(V + F) only for the blocks being formatted (text formats in
// parallel blocks of 2^18 items, PLY in two alternating blocks of 2^18 records, on `threads`
// threads, 0 = all cores).
#pragma once

#include <zdg/kernel/surfaces/mesh.hpp>

#include <optional>
#include <string>

namespace zdg {

enum class MeshFormat { ply, obj, off };

/// The format of a file name by its extension (.ply, .obj, .off; IoError otherwise).
MeshFormat mesh_format_of(const std::string& path);

void write_ply(const std::string& path, const PolygonMesh& mesh, unsigned threads = 0);
void write_obj(const std::string& path, const PolygonMesh& mesh, unsigned threads = 0);
void write_off(const std::string& path, const PolygonMesh& mesh, unsigned threads = 0);

/// Writes in `format`, or in the format of the file name when none is given (give it when
/// writing to an OutputSet staging file).
void write_mesh(const std::string& path, const PolygonMesh& mesh,
                std::optional<MeshFormat> format = std::nullopt, unsigned threads = 0);

/// The PLY property name of a field ("ii-mean" -> "ii_mean").
std::string ply_property_name(const std::string& field);

} // namespace zdg
