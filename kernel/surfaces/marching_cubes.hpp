// Marching cubes on a binary volume (level 1/2) or on grey values at a level (linear
// interpolation), topologically correct: the dual of the digital surface of an adjacency pair.
//
// Lachaud's topologically defined isosurfaces (DGCI 1996), tables derived, not typed: the
// vertices are the boundary surfels, one polygon per cycle of surfels around each pointel
// (kernel/surfaces/pointel_cycles.hpp); ambiguities follow the pair (6,26) ((6,18) is the same).
// The mesh is the dual of the primal surface mesh: a closed oriented 2-manifold, one component
// per digital surface, same Euler characteristic. Triangles: 4-cycles split on the shorter
// diagonal, longer cycles fanned around their mean; vertex i < surfels.size() is surfel i, then
// the centres. Grey positions interpolate linearly, clamped to [0, 1] (derivation and
// placement: docs/NOTES.md, "kernel/surfaces/marching_cubes.hpp").
// Cost: O(F log(row)) for F surfels, parallel, independent of the thread count; about 72 bytes
// per surfel.
#pragma once

#include <zdg/kernel/images/image.hpp>
#include <zdg/kernel/surfaces/digital_surface.hpp>
#include <zdg/kernel/surfaces/image_surfaces.hpp>
#include <zdg/kernel/surfaces/image_surfels.hpp>
#include <zdg/kernel/surfaces/mesh.hpp>

#include <cstdint>
#include <functional>

namespace zdg {

/// Grey values for the interpolated positions: value(v) for the voxel of linear index v
/// (C order of the image), and the level. value must be callable from several threads.
struct IsoLevel {
  std::function<double(std::int64_t)> value;
  double level = 0.5;
};

/// The marching-cubes mesh of the boundary of the nonzero voxels of image (surfels =
/// image_surfels(image)), ambiguities resolved by the convention's surfel adjacency; binary
/// positions when grey is null. face_size 3.
PolygonMesh marching_cubes(const Image<std::uint8_t>& image, const ImageSurfels& surfels,
                           const SurfaceConvention& convention, const VoxelPlacement& placement,
                           const IsoLevel* grey = nullptr, unsigned threads = 0);

/// The marching-cubes mesh ((6,26), binary positions) of the digitization {z in box :
/// inside(z)} on the grid of step h (voxel z at h z): the set rasterized to an image of the box
/// (one byte per voxel), its surfels, then the call above.
PolygonMesh marching_cubes(const VoxelPredicate& inside, const VoxelBox& box, double h,
                           unsigned threads = 0);

} // namespace zdg
