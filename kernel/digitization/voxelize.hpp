// Exact voxelization of a triangle mesh on the grid of step h and origin o.
//
// Grid. Voxel (i, j, k), 0 <= i < nx, 0 <= j < ny, 0 <= k < nz, is the closed cube
// o + h [i, i+1] x [j, j+1] x [k, k+1]; it stands for its centre o + h (i + 1/2, j + 1/2, k + 1/2)
// (zdg's convention that a digital point stands for one continuous point: here the centre, so
// the voxelization of a mesh is the digitization G_h of the mesh translated by -(o + h/2)).
// The result is an Image<uint8_t> of extents (nz, ny, nx) (C order, x fastest), 1 = in.
// Voxels outside the grid are not represented (the mesh is clipped to it).
//
// Modes (each face of the mesh is fanned into triangles (v0, vi, vi+1); T a triangle, c the
// voxel's centre, all in exact arithmetic):
//   conservative  the closed cube meets T (triangle-box overlap by the separating axis
//                 theorem, Akenine-Moller, "Fast 3D triangle-box overlap testing", JGT 2001:
//                 the 3 box normals, T's normal and the 9 products of box and triangle edges).
//                 Theorem: the set is 26-separating (a 26-path of voxels outside it joins two
//                 centres on the same side of a closed surface: the segment between 26-adjacent
//                 centres lies in the union of their closed cubes).
//   six           Huang, Yagel, Filippov, Kurzion, "An accurate method for voxelizing polygon
//                 meshes", IEEE VolVis 1998, 6-separating form: c within the slab
//                 |n.(c - v0)| <= (h/2) ||n||_inf (n the unit normal) and projecting into T, or
//                 within distance h/2 of an edge or vertex of T. Theorem: 6-separating (the set
//                 contains every voxel whose diamond, the l1 ball of radius h/2 about c, meets
//                 the surface, and the segment between 6-adjacent centres lies in their two
//                 diamonds). Contained in the conservative set.
//   twenty_six    Huang et al.'s 26-separating form: slab half-width (h/2) ||n||_1, distance
//                 sqrt(3) h / 2 to edges and vertices. Contains the conservative set.
//   solid         the centres inside a closed mesh: nonzero winding number, counted as the
//                 signed crossings of the ray from c in direction +x. A centre on the surface
//                 is decided by symbolic perturbation (Edelsbrunner, Mucke, "Simulation of
//                 simplicity", TOG 1990): c is moved to c + (d, e, e^2) with 0 < e^2 << e << d
//                 infinitesimal, so that of two solids sharing a face each centre on it goes to
//                 exactly one (the cube [0.5, 3.5]^3 in grid units gets 3^3 voxels, not 4^3).
//                 The mesh must be closed: after merging vertices of equal coordinates, every
//                 directed edge (a, b) of a triangle with three distinct vertices appears once and
//                 (b, a) once; InvalidArgument naming the first edge otherwise (for other
//                 meshes, voxelize_winding below).
// Hence six <= conservative <= twenty_six (as sets), each decided exactly.
//
// Exactness. Coordinates, o and h are doubles, i.e. dyadic rationals, and every predicate is
// the sign of a polynomial of degree <= 4 in the grid coordinates 2 (p - o) / h and the voxel
// indices. It is evaluated in double with a running bound on its error (error-free
// transformations TwoSum and FMA for each operation, Ogita, Rump, Oishi, SISC 2005); a sign the
// bound does not certify is recomputed in Rational<BigInt>. No voxel is lost or added by
// rounding: a cube with faces on voxel boundaries or centres at h = 0.1 gets the voxels of its
// rational coordinates.
//
// Cost. Surface modes: per triangle, the rows of its bounding box along the dominant axis of
// its normal, each cut to the voxels within distance h sqrt(3) of its plane: O(F + V') exact
// tests, V' the voxels near the surface. Solid: per row of centres, the triangles whose
// projection contains it, then one sweep: O(F + nx ny nz). Parallel over z-slabs
// (kernel/parallel), the result independent of `threads`. Memory: the volume (one byte per
// voxel) plus O(F) for the slab lists. Identical triangles are voxelized once in the surface
// modes, so millions of copies of one face cost one sort.
//
// Errors (InvalidArgument): a face with a repeated vertex index, a non-finite coordinate, h not
// positive and finite, a non-finite origin, a grid of more than `max_voxels` voxels (checked
// before allocating), a non-closed mesh in solid mode.
#pragma once

#include <zdg/arith/point.hpp>
#include <zdg/kernel/images/image.hpp>
#include <zdg/kernel/surfaces/mesh.hpp>

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace zdg {

enum class VoxelizationMode { conservative, six, twenty_six, solid };

/// "conservative", "6", "26", "solid".
std::string voxelization_mode_name(VoxelizationMode mode);
/// The mode of a name above (InvalidArgument naming the text otherwise).
VoxelizationMode parse_voxelization_mode(const std::string& text);

struct VoxelizationGrid {
  Point3<double> origin{0, 0, 0};
  double h = 1;
  std::array<std::int64_t, 3> extents{1, 1, 1}; ///< nx, ny, nz
};

/// The grid of step h covering the mesh: origin as given, or h (floor(min / h) - 2) per axis;
/// extents floor(max (p - o) / h) + 3 per axis (at least 1): with the default origin no
/// surface voxel lies on the grid's border (a margin of more than one voxel each side). Checks the
/// mesh (finite coordinates, face indices in range and distinct), h and the origin, and that
/// the grid has at most max_voxels voxels; InvalidArgument otherwise.
VoxelizationGrid voxel_grid_for(const PolygonMesh& mesh, double h,
                                const std::optional<Point3<double>>& origin = std::nullopt,
                                std::int64_t max_voxels = std::int64_t(1) << 32);

/// The voxelization of the mesh in the given mode on the grid (see above).
Image<std::uint8_t> voxelize(const PolygonMesh& mesh, const VoxelizationGrid& grid,
                             VoxelizationMode mode, unsigned threads = 0);

/// The same voxels, slab by slab: slab(z0, depth, data) for z0 = 0, depth, 2 depth, ... with
/// data the bytes [z][y][x] of the layers [z0, z0 + depth) (the last slab may be thinner), in
/// order, so that a grid larger than memory can be streamed (kernel/images/voxel_dag.hpp).
/// Memory: one slab plus O(F). InvalidArgument for a depth that is not a positive multiple of 4,
/// and as voxelize().
void voxelize_by_slabs(
    const PolygonMesh& mesh, const VoxelizationGrid& grid, VoxelizationMode mode,
    std::int64_t depth,
    const std::function<void(std::int64_t, std::int64_t, const std::uint8_t*)>& slab,
    unsigned threads = 0);

/// The exact test of one voxel against one triangle in a surface mode (conservative, six,
/// twenty_six): the predicate voxelize() applies, for oracles and tests.
bool triangle_voxel_test(const std::array<Point3<double>, 3>& triangle,
                         const VoxelizationGrid& grid, const std::array<std::int64_t, 3>& voxel,
                         VoxelizationMode mode);

/// The solid of a mesh that need not be closed (Jacobson, Kavan, Sorkine-Hornung, "Robust
/// inside-outside segmentation using generalized winding numbers", SIGGRAPH 2013): the voxels
/// whose centre c has w(c) >= threshold, w(c) = sum over the (fanned) triangles of their solid
/// angle at c (Van Oosterom, Strackee, IEEE TBME 1983) over 4 pi, in double: not exact (w is
/// transcendental), and a centre on the surface or within rounding of a threshold crossing may go
/// either way. w = 1 inside and 0 outside a closed outward mesh. Cost O(F N) for F triangles and
/// N voxels, checked first: InvalidArgument when F N > max_work (default 10^9).
Image<std::uint8_t> voxelize_winding(const PolygonMesh& mesh, const VoxelizationGrid& grid,
                                     double threshold, unsigned threads = 0, double max_work = 1e9);

/// Checks that the mesh is closed and consistently oriented (see solid above); InvalidArgument
/// naming the first edge that is not otherwise.
void check_closed_mesh(const PolygonMesh& mesh);

} // namespace zdg
