// The 48 symmetries of the lattice Z^3 (signed permutations of the axes) acting on voxels,
// surfels, vectors and voxel predicates, for the invariance tests of the surface estimators.
#pragma once

#include <zdg/kernel/surfaces/cubical_cells.hpp>
#include <zdg/kernel/surfaces/digital_surface.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace zdg::test {

/// (g z)_i = sign[i] z_{perm[i]}.
struct LatticeSymmetry {
  std::array<int, 3> perm{0, 1, 2};
  std::array<int, 3> sign{1, 1, 1};

  template <class T>
  Point3<T> apply(const Point3<T>& v) const {
    const T c[3] = {v.x, v.y, v.z};
    return {T(sign[0]) * c[perm[0]], T(sign[1]) * c[perm[1]], T(sign[2]) * c[perm[2]]};
  }
  template <class T>
  Point3<T> inverse(const Point3<T>& v) const {
    const T c[3] = {v.x, v.y, v.z};
    T w[3]{};
    for (int i = 0; i < 3; ++i) w[perm[std::size_t(i)]] = T(sign[std::size_t(i)]) * c[i];
    return {w[0], w[1], w[2]};
  }
  /// The image of the boundary surfel s: the surfel between the images of its voxels.
  Surfel apply(const Surfel& s) const {
    const Voxel i = apply(inner_voxel(s)), o = apply(outer_voxel(s));
    const Voxel d = o - i;
    const int axis = d.x != 0 ? 0 : (d.y != 0 ? 1 : 2);
    const auto step = d.x + d.y + d.z;
    return surfel_between(i, axis, step > 0 ? 1 : -1);
  }
  /// The predicate of the image set g(X).
  VoxelPredicate apply(const VoxelPredicate& inside) const {
    const LatticeSymmetry g = *this;
    return [g, inside](const Voxel& z) { return inside(g.inverse(z)); };
  }
  /// The box containing the image of the box.
  VoxelBox apply(const VoxelBox& b) const {
    const Voxel p = apply(b.lo), q = apply(b.hi);
    return {{std::min(p.x, q.x), std::min(p.y, q.y), std::min(p.z, q.z)},
            {std::max(p.x, q.x), std::max(p.y, q.y), std::max(p.z, q.z)}};
  }
};

/// All 48 signed permutations.
inline std::vector<LatticeSymmetry> lattice_symmetries() {
  std::vector<LatticeSymmetry> out;
  const std::array<std::array<int, 3>, 6> perms{
      {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  for (const auto& p : perms)
    for (int m = 0; m < 8; ++m)
      out.push_back({p, {(m & 1) ? -1 : 1, (m & 2) ? -1 : 1, (m & 4) ? -1 : 1}});
  return out;
}

} // namespace zdg::test
