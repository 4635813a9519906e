// Marching cubes on a binary volume (level 1/2) or on grey values at a level (linear
// interpolation), topologically correct: the dual of the digital surface of an adjacency pair.
//
// Lorensen and Cline ("Marching cubes", SIGGRAPH 1987) cut every cube of 8 voxel centres by a
// few triangles chosen by a table indexed by the 8 signs; their table leaves holes where two
// cubes disagree on an ambiguous face (two diagonal corners in, two out), and it fixes one
// choice for the ambiguous cube (two opposite corners). Topologically correct variants choose
// by a rule: Chernyaev's MC33 (1995) by the trilinear interpolant, Lachaud ("Topologically
// defined isosurfaces", DGCI 1996; Lachaud-Montanvert 2000) by the adjacency pair of digital
// topology, which makes the isosurface the continuous analog of the digital boundary.
//
// Derivation used here (the tables are derived, not typed): the cube of marching cubes whose
// corners are the 8 voxel centres around a pointel p is the dual cell of p; its edges are
// dual to the 12 faces of the 2x2x2 block, and an edge crosses the isosurface exactly when
// the face is a boundary surfel. So the vertices of the isosurface are the boundary surfels
// (one per cut edge: the surfel centre at level 1/2 on binary input, the interpolated point
// on grey input), and in each cube the isosurface is one polygon per cycle of surfels around
// p (kernel/surfaces/pointel_cycles.hpp), through the surfels in cycle order, which is
// counterclockwise seen from outside. The ambiguities are resolved by the surfel adjacency of the
// pair: with (6,26) (the default; (6,18) gives the same surface) two object corners diagonal on a
// face or opposite in the cube are separated, and so are two opposite background corners. The mesh
// is the dual of the primal surface mesh (kernel/surfaces/primal_surface_mesh.hpp): a closed
// oriented 2-manifold with one component per digital surface of image_surfaces and the same
// Euler characteristic, surface by surface -- also at the pinched linels of the primal mesh
// (its two passages are two distinct dual edges, a thin tube).
//
// Triangles: a polygon of 3 surfels is one triangle, of 4 two triangles along the shorter
// diagonal (two surfels opposite in a 4-cycle share no linel, so a diagonal is never an edge
// elsewhere), of 5 or more (saddles) a fan around an added centre vertex (their mean). Vertex
// i < surfels.size() is surfel i of image_surfels (sorted code order), then the centres.
//
// Positions: on a cut edge from the inner voxel centre u (in X) to the outer one w, the
// vertex is u + t (w - u), t = 1/2 on binary input; on grey input t = (level - f(u)) /
// (f(w) - f(u)) clamped to [0, 1] (1/2 where f(u) = f(w) or w is outside the domain), where
// the object must be the voxels on one side of the level (value >= level, or < with --invert).
// Placement as in kernel/surfaces/image_surfels.hpp.
//
// Cost: O(F log(row)) for F surfels, three passes over contiguous chunks (parallel_for);
// the mesh takes about 24 bytes per surfel for the vertices and 48 per surfel for the
// triangles (about two per surfel). The result does not depend on the number of threads.
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
