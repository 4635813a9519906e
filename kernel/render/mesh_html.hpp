// A self-contained HTML page that shows a mesh in the browser (WebGL written here, no
// library, no server, no network at viewing time): the mesh coloured by any of its per-face
// scalars (a field menu, a colour map and range control, a colour bar), picking (a click on a
// face shows its index, its centre, its vertices and every value it carries), and layers
// with a toggle (the surface, the face normals as glyphs when the mesh has them).
//
// The geometry is embedded as binary (base64): positions float32 (x, y, z per vertex), the
// faces' vertex indices uint32, each scalar field float32 per face, the face normals as int8
// triples (unit vectors times 127). For a closed quad mesh of F faces with k fields the page
// is about (31 + 4k) F * 4/3 bytes, against (41 + 4k) F for the binary PLY of the same mesh
// (kernel/io/mesh_io.hpp): at most 1.05 times the PLY for k <= 1 and below it for k >= 3.
// The browser expands the faces to triangles (about 60 bytes of GPU memory per triangle).
//
// Limits: at most `max_faces` faces (default 2,000,000) and 2^24 - 2 faces whatever the
// option (the picking pass encodes a face in 24 bits): a larger mesh is refused
// (InvalidArgument naming both counts), never written as a page a browser cannot open. The
// mesh is validated first (PolygonMesh::validate). O(V + F) time and memory.
//
// The page exposes `window.zdgViewer` (ready, faces, pick(x, y) in canvas pixels, info(f),
// faceColor(f), setField(name), setColorMap(name), setRange(lo, hi), setLayer(name, on)) for
// scripted checks (tests/python/test_viewer.py drives it in headless Chromium).
#pragma once

#include <zdg/kernel/surfaces/mesh.hpp>

#include <cstdint>
#include <string>

namespace zdg {

struct MeshHtmlOptions {
  std::string title = "zdg view"; ///< the page's title (e.g. the input's name)
  std::string field;              ///< the scalar shown first ("" = the first one, if any)
  std::int64_t max_faces = 2'000'000;
  std::string note = {}; ///< a line the page shows under its title (e.g. what a face stands for)
  bool top_view = false; ///< first seen from +z, x to the right (a flat mesh: contours)
};

/// The page's text.
std::string mesh_html(const PolygonMesh& mesh, const MeshHtmlOptions& options = {});

/// Writes the page to `path` (IoError when it cannot be written).
void write_mesh_html(const std::string& path, const PolygonMesh& mesh,
                     const MeshHtmlOptions& options = {});

/// Standard base64 (RFC 4648, with padding) of n bytes.
std::string base64(const void* data, std::size_t n);

} // namespace zdg
