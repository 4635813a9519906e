// A picture of a surface mesh coloured by a per-face field: headless software rendering.
//
// Camera: orthographic, looking at the centre of the mesh's bounding box from the direction
// (cos e cos a, cos e sin a, sin e) (azimuth a around +z, elevation e above the xy plane;
// the default a = -60, e = 30 degrees is matplotlib's 3/4 view), +z up in the picture; the
// projection is framed to fill the drawing area. Rasterization: each face is split into a
// fan of triangles and scan-converted at `supersample`^2 samples per pixel with a z-buffer
// that keeps the nearest face per sample (faces of either orientation are drawn); each
// sample is then shaded once (deferred shading): colour of the face's value (colour map over
// the value range) times Lambert's cosine of a light near the camera (two-sided, 30%
// ambient); samples are averaged into pixels. A colour bar with the value range and the
// field name sits on the right, a title on top. Without a field the surface is grey.
// Value range: the given one, else the clip_percent and 100 - clip_percent percentiles of
// the finite values (so that a few outliers do not wash out the picture; 0 gives min and
// max); a range with both signs uses the diverging coolwarm map, symmetric about 0 (white =
// 0, the sign of a curvature reads at once), otherwise viridis. NaN values are grey.
// Cost: O(V + F + pixels) per band of rows; the picture is split into bands, one per thread
// (threads = 0: all cores); every band scans the faces' bounding boxes. Memory: 3 floats per
// vertex and 8 bytes per sample.
#pragma once

#include <zdg/kernel/render/picture.hpp>
#include <zdg/kernel/surfaces/mesh.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace zdg {

struct MeshRenderOptions {
  int width = 1200, height = 900;
  double azimuth = -60.0, elevation = 30.0;   ///< degrees
  int supersample = 2;                        ///< samples per pixel along each axis (1..4)
  std::optional<ColorMap> color_map;          ///< default: coolwarm for signed ranges, viridis
  std::optional<double> value_min, value_max; ///< the colour range (default: percentiles)
  double clip_percent = 1.0;                  ///< percentile clipping of the default range
  std::string title;                          ///< default: the field name and the face count
  unsigned threads = 0;
};

struct MeshRenderReport {
  double value_min = 0, value_max = 0; ///< the colour range used
  ColorMap color_map = ColorMap::viridis;
  std::int64_t faces = 0;   ///< faces in the mesh
  std::int64_t samples = 0; ///< samples covered by the surface
};

/// Renders the mesh coloured by its face field `field` ("" for none; InvalidArgument when the
/// mesh has no such field).
RgbImage render_mesh(const PolygonMesh& mesh, const std::string& field,
                     const MeshRenderOptions& options = {}, MeshRenderReport* report = nullptr);

/// render_mesh, written as a PNG file (atomically).
MeshRenderReport render_mesh_png(const std::string& path, const PolygonMesh& mesh,
                                 const std::string& field, const MeshRenderOptions& options = {});

} // namespace zdg
