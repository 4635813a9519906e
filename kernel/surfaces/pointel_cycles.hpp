// The sheets of a digital surface at a pointel: the boundary surfels around a pointel p,
// partitioned into cycles by the surfel adjacency through the six linels of p.
//
// Local frame. The 8 voxels around p form a 2x2x2 block; the local voxel (bx, by, bz) in
// {0,1}^3 has bit b = bx + 2 by + 4 bz of the configuration byte (bit set = voxel in X). For a
// pointel of index q = (i, j, k) in a voxel grid (the corner shared by the voxels q - 1 and q
// along each axis) the local voxel (bx, by, bz) is the voxel (i - 1 + bx, j - 1 + by,
// k - 1 + bz). The block has 12 inner faces, the local faces f = 4 a + u + 2 w: the face
// orthogonal to axis a between the local voxels with bit a = 0 and 1, whose bits along the
// axes (a + 1) % 3 and (a + 2) % 3 are u and w. A local face is a boundary face when exactly
// one of its voxels is in X (the inner one).
//
// Cycles. Every boundary face at p has two linels at p; through each, the surfel adjacency of
// kernel/surfaces/digital_surface.hpp (interior: X is joined across an edge where two of its voxels
// meet along a linel only; exterior: they are separated) gives exactly one other boundary
// face at p. So the boundary faces at p form disjoint cycles: one sheet of the surface
// through p each. `next[f]` is the face met across the linel of f that ENTERS p when the quad
// of f is run counterclockwise seen from outside (kernel/surfaces/cubical_cells.hpp,
// surfel_pointels): following `next` turns counterclockwise around p seen from outside, so
// the polygon through the face centres in this order is the dual face of the vertex (p,
// cycle), oriented outwards (marching cubes, kernel/surfaces/marching_cubes.hpp). Cycles are
// numbered by increasing smallest face; the smallest face of a cycle is its owner.
//
// Pinched linels. A linel whose four voxels are two diagonal pairs has four boundary faces,
// paired in two by the adjacency: two passages of the surface along the linel. When at BOTH
// ends of the linel the two passages lie on the same cycle, the two passages join the same
// two vertices: a quad mesh whose edges are vertex pairs sees that edge in four faces, though
// the surface itself (edges = adjacent surfel pairs) is a 2-manifold. The surface is a tube
// squeezed onto the linel (a neck of the object under interior adjacency, of the background
// under exterior); no vertex copies can open it. entering_joined / leaving_joined find them.
//
// Pinches. Which cycles one sheet would need to join, and cannot with quads: for an object
// taken 26-connected, the configuration where X is exactly two opposite voxels of the block
// (two sheets meeting at p only, but X connected through p); for a background taken
// 26-connected, the configuration where the complement is exactly two opposite voxels. See
// kernel/surfaces/image_surfaces.hpp for what this does to the Euler characteristic.
//
// Source: the bel-adjacency of Herman ("Discrete multidimensional Jordan surfaces", CVGIP
// 1992) and Udupa; the local analysis at pointels is the one of Lachaud, "Topologically
// defined isosurfaces" (DGCI 1996) and Lachaud and Montanvert (Graphical Models 62, 2000).
// The 2 x 256 tables are derived at first use from adjacent_surfel() itself (never typed by
// hand), O(1) each afterwards.
#pragma once

#include <zdg/kernel/surfaces/digital_surface.hpp>
#include <zdg/kernel/surfaces/image_surfels.hpp>

#include <array>
#include <cstdint>

namespace zdg {

/// The boundary faces at a pointel and their cycles, for one configuration and adjacency.
struct PointelStar {
  std::uint16_t faces = 0;              ///< bit f: local face f is a boundary face
  int cycles = 0;                       ///< number of cycles (sheets through the pointel)
  std::array<std::int8_t, 12> next{};   ///< next face of the cycle (-1: not a boundary face)
  std::array<std::int8_t, 12> cycle{};  ///< cycle of the face (-1: not a boundary face)
  std::array<std::int8_t, 12> owner{};  ///< smallest face of the face's cycle (-1: none)
  std::array<std::int8_t, 12> length{}; ///< number of faces of the face's cycle (0: none)
  /// The linel of face f that enters (resp. leaves) the pointel is a "joined" linel here: its
  /// four voxels are two diagonal pairs (four boundary faces around it) and both pairs of
  /// faces at it lie on the same cycle at this pointel.
  std::array<bool, 12> entering_joined{}, leaving_joined{};
};

/// The star of the configuration byte under the surfel adjacency (tables built once).
const PointelStar& pointel_star(std::uint8_t configuration, SurfelAdjacency adjacency);
/// The 256 stars of an adjacency, indexed by the configuration byte (for inner loops).
const PointelStar* pointel_stars(SurfelAdjacency adjacency);

/// The local face f = 4 a + u + 2 w (see above).
constexpr int local_face(int axis, int u, int w) {
  return 4 * axis + u + 2 * w;
}
/// The local voxel (bit index) on side s (0 or 1 along the face's axis) of the local face f.
constexpr int local_face_voxel(int f, int side) {
  const int a = f / 4, u = f & 1, w = (f >> 1) & 1;
  const int b = (a + 1) % 3, c = (a + 2) % 3;
  return (side << a) | (u << b) | (w << c);
}

/// True when exactly two voxels of the configuration are set and they are opposite corners
/// of the block (the 26-pinch of the set; use ~configuration for the complement).
constexpr bool is_opposite_pair(std::uint8_t configuration) {
  return configuration == 0x81 || configuration == 0x42 || configuration == 0x24 ||
         configuration == 0x18;
}

/// The configuration byte of the pointel of index q = (i, j, k) (0 <= i <= nx, ...): bit b
/// set when the local voxel b is in the grid and nonzero.
inline std::uint8_t pointel_configuration(const VoxelGrid& g, const std::uint8_t* data,
                                          std::int64_t i, std::int64_t j, std::int64_t k) {
  std::uint8_t c = 0;
  if (i >= 1 && j >= 1 && k >= 1 && i < g.nx && j < g.ny && k < g.nz) {
    const std::uint8_t* p = data + g.index(i - 1, j - 1, k - 1);
    const std::int64_t sy = g.nx, sz = g.nx * g.ny;
    c = static_cast<std::uint8_t>((p[0] != 0) | (p[1] != 0) << 1 | (p[sy] != 0) << 2 |
                                  (p[sy + 1] != 0) << 3 | (p[sz] != 0) << 4 |
                                  (p[sz + 1] != 0) << 5 | (p[sz + sy] != 0) << 6 |
                                  (p[sz + sy + 1] != 0) << 7);
    return c;
  }
  for (int b = 0; b < 8; ++b) {
    const std::int64_t x = i - 1 + (b & 1), y = j - 1 + ((b >> 1) & 1), z = k - 1 + (b >> 2);
    if (x >= 0 && y >= 0 && z >= 0 && x < g.nx && y < g.ny && z < g.nz &&
        data[g.index(x, y, z)] != 0)
      c = static_cast<std::uint8_t>(c | (1 << b));
  }
  return c;
}

/// A corner of a boundary surfel seen from its pointel: the pointel index q and the local
/// face of the surfel there.
struct SurfelCorner {
  std::int64_t q[3];
  int face;
};

namespace detail {
struct CornerStep {
  std::int8_t dq[3];
  std::int8_t face;
};
// The corners of the surfels of each direction d = 2 a + (outer voxel at +e_a): the pointel
// index minus the inner voxel's indices, and the local face of the surfel there.
constexpr std::array<std::array<CornerStep, 4>, 6> corner_steps() {
  constexpr int du[4] = {-1, 1, 1, -1}, dv[4] = {-1, -1, 1, 1};
  std::array<std::array<CornerStep, 4>, 6> t{};
  for (int d = 0; d < 6; ++d)
    for (int n = 0; n < 4; ++n) {
      const int a = d / 2, b = (a + 1) % 3, cc = (a + 2) % 3;
      const bool pos = (d & 1) != 0;
      const int jn = pos ? n : 3 - n;
      auto& k = t[std::size_t(d)][std::size_t(n)];
      k.dq[a] = pos ? 1 : 0;
      k.dq[b] = du[jn] > 0 ? 1 : 0;
      k.dq[cc] = dv[jn] > 0 ? 1 : 0;
      k.face = static_cast<std::int8_t>(local_face(a, du[jn] < 0 ? 1 : 0, dv[jn] < 0 ? 1 : 0));
    }
  return t;
}
inline constexpr auto kCornerSteps = corner_steps();
} // namespace detail

/// Corner n (0..3) of the surfel of code `code` whose inner voxel has the grid indices c, in
/// the counterclockwise order seen from outside of surfel_pointels().
inline SurfelCorner surfel_corner(const std::int64_t c[3], std::uint64_t code, int n) {
  const auto& k = detail::kCornerSteps[code & 7][static_cast<std::size_t>(n)];
  return {{c[0] + k.dq[0], c[1] + k.dq[1], c[2] + k.dq[2]}, k.face};
}

/// Which corner (0..3) of the surfel of code `code`, inner voxel of grid indices c, is the
/// pointel q (which must be one of them).
inline int corner_index(const std::int64_t c[3], std::uint64_t code, const std::int64_t q[3]) {
  const int a = code_axis(code), b = (a + 1) % 3, cc = (a + 2) % 3;
  const bool ub = q[b] > c[b], uc = q[cc] > c[cc];
  const int jn = ub ? (uc ? 2 : 1) : (uc ? 3 : 0);
  return code_positive(code) ? jn : 3 - jn;
}

/// The boundary surfel of local face f at the pointel q, for the configuration byte of q (f
/// must be a boundary face of it): its code, the row of its inner voxel and the grid indices
/// of that voxel.
struct LocalSurfel {
  std::uint64_t code;
  std::int64_t row;
  std::int64_t c[3];
};
inline LocalSurfel local_face_surfel(const VoxelGrid& g, const std::int64_t q[3], int f,
                                     std::uint8_t configuration) {
  const int a = f / 4;
  const int low = local_face_voxel(f, 0);
  const bool low_inside = ((configuration >> low) & 1) != 0;
  const int inner = low_inside ? low : local_face_voxel(f, 1);
  LocalSurfel s{};
  s.c[0] = q[0] - 1 + (inner & 1);
  s.c[1] = q[1] - 1 + ((inner >> 1) & 1);
  s.c[2] = q[2] - 1 + (inner >> 2);
  s.row = s.c[2] * g.ny + s.c[1];
  s.code = surfel_code(s.row * g.nx + s.c[0], a, low_inside);
  return s;
}

} // namespace zdg
