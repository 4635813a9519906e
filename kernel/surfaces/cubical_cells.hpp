// Cells of the cubical complex of R^3 in Khalimsky coordinates, and boxes of voxels.
//
// Convention (the one of Khalimsky spaces, as in DGtal's KhalimskySpaceND):
// - the digital point z in Z^3 is the voxel, the closed unit cube centred at z; its Khalimsky
//   point is k = 2 z + 1 (all coordinates odd);
// - a cell is any k in Z^3; its dimension is the number of odd coordinates: voxel (3),
//   surfel (2: exactly one EVEN coordinate, the orthogonal axis), linel (1: exactly one odd
//   coordinate, the axis it runs along), pointel (0: all even);
// - the cell k stands for the point (k - 1) / 2 of R^3 in voxel units, so its embedding at
//   grid step h is h (k - 1) / 2 (a voxel 2z+1 embeds at h z, the pointel 2z at h (z - 1/2)).
//
// A boundary surfel is a surfel together with an orientation. With a the orthogonal axis of
// the surfel k, its two incident voxels are k - e_a and k + e_a (Khalimsky). The surfel is
// DIRECT when its inner voxel is k - e_a (so its outward elementary normal is +e_a), and
// INDIRECT when its inner voxel is k + e_a (outward elementary normal -e_a). The elementary
// ("trivial") normal of a boundary surfel always points from the inner to the outer voxel.
//
// All functions are O(1). Coordinates are int64; the algorithms that create cells check at
// entry that the Khalimsky coordinates of their box fit (|z| <= kMaxVoxelCoordinate).
#pragma once

#include <zdg/arith/error.hpp>
#include <zdg/kernel/images/box.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

namespace zdg {

/// A point of Z^3 in Khalimsky coordinates (a cell of any dimension).
using KPoint = Point3<std::int64_t>;
/// A digital point of Z^3 (a voxel in ordinary coordinates).

/// Largest absolute voxel coordinate accepted by the cell algorithms (2 z + 1 and the
/// offsets added to it then stay far inside int64).
inline constexpr std::int64_t kMaxVoxelCoordinate = std::int64_t{1} << 40;

inline std::int64_t coord(const Point3<std::int64_t>& p, int axis) {
  return axis == 0 ? p.x : (axis == 1 ? p.y : p.z);
}
inline std::int64_t& coord(Point3<std::int64_t>& p, int axis) {
  return axis == 0 ? p.x : (axis == 1 ? p.y : p.z);
}

/// Number of odd Khalimsky coordinates: 3 voxel, 2 surfel, 1 linel, 0 pointel.
inline int cell_dimension(const KPoint& k) {
  return int(k.x & 1) + int(k.y & 1) + int(k.z & 1);
}

/// Khalimsky point of the voxel z: 2 z + 1.
inline KPoint voxel_cell(const Voxel& z) {
  return {2 * z.x + 1, 2 * z.y + 1, 2 * z.z + 1};
}

/// Voxel of a Khalimsky point with all coordinates odd: (k - 1) / 2.
inline Voxel cell_voxel(const KPoint& k) {
  return {(k.x - 1) / 2, (k.y - 1) / 2, (k.z - 1) / 2};
}

/// The point of R^3 the cell k stands for at grid step h: h (k - 1) / 2.
inline Point3<double> embed_cell(const KPoint& k, double h) {
  return {h * 0.5 * double(k.x - 1), h * 0.5 * double(k.y - 1), h * 0.5 * double(k.z - 1)};
}

/// An oriented surfel of a digital boundary (see the convention above).
struct Surfel {
  KPoint k;           ///< Khalimsky point: exactly one even coordinate
  bool direct = true; ///< direct: inner voxel k - e_a, outward normal +e_a
  friend bool operator==(const Surfel&, const Surfel&) = default;
  friend auto operator<=>(const Surfel&, const Surfel&) = default;
};

/// The axis of the even coordinate of a surfel (the axis of its elementary normal).
inline int orthogonal_axis(const Surfel& s) {
  return (s.k.x & 1) == 0 ? 0 : ((s.k.y & 1) == 0 ? 1 : 2);
}

/// The boundary surfel between the inside voxel z and its neighbour z + sign e_axis.
inline Surfel surfel_between(const Voxel& inner, int axis, int sign) {
  KPoint k = voxel_cell(inner);
  coord(k, axis) += sign > 0 ? 1 : -1;
  return {k, sign > 0};
}

/// The voxel incident to s on its inner side (k - e_a if direct, k + e_a otherwise).
inline Voxel inner_voxel(const Surfel& s) {
  KPoint k = s.k;
  coord(k, orthogonal_axis(s)) += s.direct ? -1 : 1;
  return cell_voxel(k);
}

/// The voxel incident to s on its outer side.
inline Voxel outer_voxel(const Surfel& s) {
  KPoint k = s.k;
  coord(k, orthogonal_axis(s)) += s.direct ? 1 : -1;
  return cell_voxel(k);
}

/// The elementary (trivial) outward normal of s: +-e_a, from the inner to the outer voxel.
inline Point3<int> trivial_normal(const Surfel& s) {
  Point3<int> n{0, 0, 0};
  const int v = s.direct ? 1 : -1;
  const int a = orthogonal_axis(s);
  (a == 0 ? n.x : (a == 1 ? n.y : n.z)) = v;
  return n;
}

/// Centre of the surfel s at grid step h (the midpoint of its inner and outer voxel).
inline Point3<double> surfel_centre(const Surfel& s, double h) {
  return embed_cell(s.k, h);
}

/// The four pointels of the surfel s, counterclockwise when seen from the tip of its outward
/// normal: with a the orthogonal axis and (a, b, c) a cyclic permutation of (0, 1, 2), the
/// corners k + (-1,-1), (+1,-1), (+1,+1), (-1,+1) along (b, c), reversed for an indirect s.
inline std::array<KPoint, 4> surfel_pointels(const Surfel& s) {
  const int a = orthogonal_axis(s), b = (a + 1) % 3, c = (a + 2) % 3;
  static constexpr int du[4] = {-1, 1, 1, -1}, dv[4] = {-1, -1, 1, 1};
  std::array<KPoint, 4> p;
  for (int i = 0; i < 4; ++i) {
    const int j = s.direct ? i : 3 - i;
    p[std::size_t(i)] = s.k;
    coord(p[std::size_t(i)], b) += du[j];
    coord(p[std::size_t(i)], c) += dv[j];
  }
  return p;
}

/// The four linels of the surfel s (k +- e_b, k +- e_c for its tangent axes b, c).
inline std::array<KPoint, 4> surfel_linels(const Surfel& s) {
  const int a = orthogonal_axis(s), b = (a + 1) % 3, c = (a + 2) % 3;
  std::array<KPoint, 4> l{s.k, s.k, s.k, s.k};
  coord(l[0], b) -= 1;
  coord(l[1], b) += 1;
  coord(l[2], c) -= 1;
  coord(l[3], c) += 1;
  return l;
}

/// A box of voxels lo <= z <= hi (inclusive, coordinatewise; any lower bounds).
struct VoxelBox {
  Voxel lo, hi;
  bool contains(const Voxel& z) const {
    return lo.x <= z.x && z.x <= hi.x && lo.y <= z.y && z.y <= hi.y && lo.z <= z.z && z.z <= hi.z;
  }
  bool empty() const { return hi.x < lo.x || hi.y < lo.y || hi.z < lo.z; }
  friend bool operator==(const VoxelBox&, const VoxelBox&) = default;
};

/// Throws InvalidArgument unless the box is non-empty and its coordinates are at most
/// kMaxVoxelCoordinate in absolute value.
inline void check_voxel_box(const VoxelBox& box) {
  auto ok = [](std::int64_t v) { return v >= -kMaxVoxelCoordinate && v <= kMaxVoxelCoordinate; };
  if (box.empty())
    throw InvalidArgument("empty voxel box: lo (" + std::to_string(box.lo.x) + ", " +
                          std::to_string(box.lo.y) + ", " + std::to_string(box.lo.z) + ") > hi (" +
                          std::to_string(box.hi.x) + ", " + std::to_string(box.hi.y) + ", " +
                          std::to_string(box.hi.z) + ")");
  for (const auto v : {box.lo.x, box.lo.y, box.lo.z, box.hi.x, box.hi.y, box.hi.z})
    if (!ok(v))
      throw InvalidArgument("voxel box coordinate " + std::to_string(v) +
                            " exceeds 2^40 in absolute value");
}

/// Hash of a Khalimsky point (for unordered containers of cells and voxels).
struct KPointHash {
  std::size_t operator()(const KPoint& k) const noexcept {
    std::uint64_t h = std::uint64_t(k.x) * 0x9E3779B97F4A7C15ULL;
    h ^= std::uint64_t(k.y) + 0x7F4A7C159E3779B9ULL + (h << 6) + (h >> 2);
    h ^= std::uint64_t(k.z) * 0xC2B2AE3D27D4EB4FULL + (h << 6) + (h >> 2);
    return std::size_t(h ^ (h >> 29));
  }
};

/// Hash of a surfel (its orientation included).
struct SurfelHash {
  std::size_t operator()(const Surfel& s) const noexcept {
    return KPointHash{}(s.k) ^ std::size_t(s.direct);
  }
};

} // namespace zdg
