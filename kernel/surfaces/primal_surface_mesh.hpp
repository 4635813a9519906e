// The primal surface mesh of a binary volume: one quad per boundary surfel, each boundary
// surface a closed oriented 2-manifold.
//
// Faces: the boundary surfels in sorted code order (face f is surfel f of image_surfels), each
// the quad of its four pointels, counterclockwise seen from outside (the outward normal
// points from the inner to the outer voxel; kernel/surfaces/cubical_cells.hpp, surfel_pointels).
// Vertices: one per sheet through a pointel (kernel/surfaces/pointel_cycles.hpp): where several
// sheets of the boundary meet at a pointel (two voxels meeting along a linel, or at a corner only)
// each sheet gets its own copy of the vertex, at the same position. With the surfel adjacency
// of the adjacency pair (kernel/surfaces/image_surfaces.hpp), every edge is then in exactly two
// faces run in opposite directions, the faces around every vertex form one fan, and the connected
// components of the mesh are the closed surfaces of image_surfaces, with the same V - E + F.
// Positions: the pointel of index q (the corner of the voxels q - 1 and q) is at
// placement.at(q - 1/2).
//
// Algorithm: each (surfel, corner) whose face is the owner of its sheet (the smallest face of
// the cycle) creates the vertex; the other corners find the owner's surfel (table lookup,
// binary search in its row) and take its vertex. Three passes over the surfels in contiguous
// chunks (parallel_for): count the owners per chunk, number them in chunk order, then resolve
// the other corners. O(F log(row)) time; the mesh takes 32 bytes per face and 24 per vertex,
// plus nothing else. The result does not depend on the number of threads. Indices are int64.
#pragma once

#include <zdg/kernel/images/image.hpp>
#include <zdg/kernel/surfaces/image_surfaces.hpp>
#include <zdg/kernel/surfaces/image_surfels.hpp>
#include <zdg/kernel/surfaces/mesh.hpp>

#include <cstdint>

namespace zdg {

/// The primal mesh of the boundary surfels (surfels = image_surfels(image)) under the surfel
/// adjacency of the convention (threads: 0 = all cores). face_size 4, no fields.
PolygonMesh primal_surface_mesh(const Image<std::uint8_t>& image, const ImageSurfels& surfels,
                                const SurfaceConvention& convention,
                                const VoxelPlacement& placement, unsigned threads = 0);

/// The mesh of the interfaces of a labelled 3D image (the seeds' multi-label partitions; the
/// surfels of label_interfaces, kernel/surfaces/image_surfels.hpp): one quad per pair of
/// 6-neighbours with labels a != b (outside the domain every voxel has the label `outside`),
/// counterclockwise seen from the larger label, so its normal points from the smaller label to
/// the larger; face scalars "label_a" and "label_b" (a < b, as doubles: InvalidArgument for a
/// label past 2^24 in magnitude, which a PLY float would round). Vertices: one per pointel,
/// shared by every interface through it (where three labels meet the mesh is not a manifold),
/// the pointel of index q (0-based in the domain) at placement.at(q - 1/2). Faces in the order
/// (axis of the normal, z, y, x). O(N) time, memory O(faces). InvalidArgument when the image is not
/// 3D.
PolygonMesh label_interface_mesh(const Image<std::int64_t>& labels, std::int64_t outside,
                                 const VoxelPlacement& placement);

} // namespace zdg
