// The cell complex of the boundary of a small binary volume under an adjacency pair, with its
// closed surfaces (Euler characteristic, genus), for the exterior-calculus tests: the primal
// mesh (kernel/surfaces/primal_surface_mesh.hpp, one face per surfel in code order) as a
// SurfelComplex at the lattice placement, and image_surfaces on the same surfels.
#pragma once

#include <zdg/kernel/surfaces/image_surfaces.hpp>
#include <zdg/kernel/surfaces/primal_surface_mesh.hpp>
#include <zdg/kernel/surfaces/surfel_complex.hpp>

#include "tests/support/volumes.hpp"

#include <functional>

namespace zdg::test {

struct ImageComplex {
  SurfelComplex complex;
  ImageSurfaces surfaces;
};

inline ImageComplex image_complex(const SmallVolume& v, int k = 6, int kbar = 26) {
  const auto img = to_image(v);
  const auto sf = image_surfels(img, 1);
  const auto conv = SurfaceConvention::of(k, kbar);
  ImageComplex c;
  c.complex =
      surfel_complex(primal_surface_mesh(img, sf, conv, VoxelPlacement::lattice(sf.grid), 1));
  c.surfaces = image_surfaces(img, sf, conv, 1);
  return c;
}

/// The volume of nx x ny x nz voxels where inside(x, y, z) holds.
inline SmallVolume volume_of(int nx, int ny, int nz,
                             const std::function<bool(int, int, int)>& inside) {
  SmallVolume v;
  v.nx = nx;
  v.ny = ny;
  v.nz = nz;
  for (int z = 0; z < nz; ++z)
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) v.data.push_back(inside(x, y, z) ? 1 : 0);
  return v;
}

/// A solid torus: the square ring [1, 5]^2 minus [2, 4]^2 of the slice z = 1 (genus 1).
inline SmallVolume ring_torus() {
  return volume_of(7, 7, 3, [](int x, int y, int z) {
    return z == 1 && x >= 1 && x <= 5 && y >= 1 && y <= 5 &&
           !(x >= 2 && x <= 4 && y >= 2 && y <= 4);
  });
}

/// A solid of genus 2: the slab [1, 9] x [1, 5] of z = 1 with two square holes.
inline SmallVolume double_ring() {
  return volume_of(11, 7, 3, [](int x, int y, int z) {
    const bool hole = y >= 2 && y <= 4 && ((x >= 2 && x <= 4) || (x >= 6 && x <= 8));
    return z == 1 && x >= 1 && x <= 9 && y >= 1 && y <= 5 && !hole;
  });
}

/// A 5^3 cube with a one-voxel cavity at its centre (two spheres: outer and inner).
inline SmallVolume hollow_cube() {
  return volume_of(7, 7, 7, [](int x, int y, int z) {
    const bool in = x >= 1 && x <= 5 && y >= 1 && y <= 5 && z >= 1 && z <= 5;
    return in && !(x == 3 && y == 3 && z == 3);
  });
}

} // namespace zdg::test
