// Pictures of sparse voxel DAGs by exact ray casting.
//
// Each pixel casts the camera ray of render volume (volume_render.hpp: orthographic, the view
// convention of render_mesh.hpp, the scene's box framed, each ray a digital ray of denominator
// 2^20 in voxel coordinates, spacing 1) and takes its first set voxel in the DAG
// (VoxelDag::first_hit: exact, Revelles et al.'s parametric traversal). The voxel's face that
// the ray enters by is shaded by Lambert's law under a headlight, 25% ambient, over a dark
// background: the picture shows the voxels as cubes, with no rounding in what is hit.
// Cost: O(pixels x (depth + visited nodes)) on `threads` threads (0: all cores); the result
// does not depend on the thread count. Errors: the options as VolumeRenderOptions::validate
// (only width, height, angles and threads are used), InvalidArgument for an empty scene box.
#pragma once

#include <zdg/kernel/images/voxel_dag.hpp>
#include <zdg/kernel/render/picture.hpp>
#include <zdg/kernel/render/volume_render.hpp>

#include <cstdint>
#include <vector>

namespace zdg {

struct DagRendering {
  RgbImage picture;
  /// Per pixel (row-major, row 0 at the top): the axis of the face hit (0, 1, 2), -1 for none.
  std::vector<std::int8_t> faces;
  std::int64_t rays = 0; ///< pixels
  std::int64_t hits = 0; ///< pixels whose ray hits a voxel
};

/// The colour of a face of `axis` seen along a ray of direction d (the shading above).
Rgb dag_face_color(int axis, const std::array<std::int64_t, 3>& d);
/// The background colour.
Rgb dag_background();

DagRendering render_dag(const VoxelDag& dag, const VolumeRenderOptions& options = {});

} // namespace zdg
