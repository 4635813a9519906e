// Test support: small binary volumes for the surface tests (a volume with an at(x, y, z)
// accessor), a RapidCheck generator, conversion to zdg images (axes (z, y, x), x contiguous),
// and the Betti numbers of the brute-force homology oracle (tests/support/cubical_homology.hpp).
#pragma once

#include <zdg/kernel/images/image.hpp>

#include <zdg/kernel/topology/adjacency.hpp>

#include "tests/support/cubical_homology.hpp"

#include <rapidcheck.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace zdg::test {

/// A small binary volume, x fastest: at(x, y, z) = data[(z ny + y) nx + x]; outside is 0.
struct SmallVolume {
  int nx = 0, ny = 0, nz = 0;
  std::vector<std::uint8_t> data;
  bool at(int x, int y, int z) const {
    return x >= 0 && y >= 0 && z >= 0 && x < nx && y < ny && z < nz &&
           data[std::size_t((z * ny + y) * nx + x)] != 0;
  }
};

/// A random volume of at most max_side^3 voxels; the density of its voxels is itself random
/// (sparse, dense and balanced volumes all occur).
inline rc::Gen<SmallVolume> small_volume(int max_side) {
  return rc::gen::exec([max_side] {
    SmallVolume v;
    v.nx = *rc::gen::inRange(1, max_side + 1);
    v.ny = *rc::gen::inRange(1, max_side + 1);
    v.nz = *rc::gen::inRange(1, max_side + 1);
    const int density = *rc::gen::inRange(1, 10); // out of 10
    v.data = *rc::gen::container<std::vector<std::uint8_t>>(
        std::size_t(v.nx * v.ny * v.nz), rc::gen::map(rc::gen::inRange(0, 10), [density](int r) {
          return std::uint8_t(r < density);
        }));
    return v;
  });
}

/// The volume as a 3D image with these lower bounds (x, y, z).
inline Image<std::uint8_t> to_image(const SmallVolume& v, std::int64_t lx = 0, std::int64_t ly = 0,
                                    std::int64_t lz = 0) {
  return Image<std::uint8_t>(Domain({v.nz, v.ny, v.nx}, {lz, ly, lx}), v.data);
}

/// A volume drawn as rows of x: one string per row, rows in (z, y) order with ny rows per
/// slice, '#' inside and '.' outside.
inline SmallVolume volume_from_rows(int ny, const std::vector<const char*>& rows) {
  SmallVolume v;
  v.ny = ny;
  v.nx = int(std::string(rows.at(0)).size());
  v.nz = int(rows.size()) / ny;
  for (const char* r : rows)
    for (const char* c = r; *c; ++c) v.data.push_back(*c == '#' ? 1 : 0);
  return v;
}

/// (b0, b1, b2) of the object of v under the pair (k, kbar), by brute-force homology.
inline std::array<std::int64_t, 3> object_betti(const SmallVolume& v, int k, int kbar) {
  const auto h = object_homology(to_image(v), make_adjacency_pair(3, k, kbar));
  return {h.betti[0], h.betti[1], h.betti[2]};
}

} // namespace zdg::test
