// Reading a polygon mesh from OBJ or OFF text, and any mesh file by its extension (.ply through
// kernel/io/ply_read.hpp): the input of `zdg voxelize`.
//
//   .obj  "v x y z [w]" vertices (w ignored), "f a b c ..." faces whose tokens are "i", "i/t",
//         "i/t/n" or "i//n" with 1-based indices, negative ones counted back from the last
//         vertex read (-1: the last); every other line (vn, vt, o, g, s, usemtl, mtllib, l, ...)
//         is ignored; '#' starts a comment
//   .off  a first data line "OFF" (the counts "V F E" may follow on it), then V vertex lines
//         "x y z" (further fields, colours, ignored) and F face lines "n i1 .. in" (0-based,
//         further fields ignored); '#' starts a comment
// As for PLY, a mesh whose faces do not all have the same number of vertices has each face of
// k vertices fanned into k - 2 triangles (v0, vi, vi+1).
//
// Errors: IoError "SOURCE:LINE: what was wrong" for a number that is not one or not finite, an
// index out of range or not an integer, a face of fewer than 3 vertices, a count beyond what
// the file holds; memory is taken as lines are read, never for a header's count alone. The
// result satisfies PolygonMesh::validate(). Cost: O(size of the file).
#pragma once

#include <zdg/kernel/surfaces/mesh.hpp>

#include <string>
#include <string_view>

namespace zdg {

PolygonMesh parse_obj_mesh(std::string_view text, const std::string& source);
PolygonMesh parse_off_mesh(std::string_view text, const std::string& source);

/// The mesh of a .ply, .obj or .off file (by the extension, any case; IoError otherwise).
PolygonMesh read_mesh(const std::string& path);

} // namespace zdg
