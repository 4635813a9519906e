// Test support: small binary volumes for the surface tests: RapidCheck generators, conversion
// to zdg images (axes (z, y, x), x contiguous), and digitized balls as images.
#pragma once

#include <zdg/kernel/image.hpp>

#include "tests/support/cubical_homology.hpp"

#include <rapidcheck.h>

#include <cstdint>
#include <string>
#include <vector>

namespace zdg::test {

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

/// The digital ball |z - c|^2 <= r2 (c = the centre of the box) in a box of side n.
inline Image<std::uint8_t> ball_image(std::int64_t n, std::int64_t r2) {
  Image<std::uint8_t> img(Domain({n, n, n}));
  const std::int64_t c = n / 2;
  std::int64_t i = 0;
  for (std::int64_t z = 0; z < n; ++z)
    for (std::int64_t y = 0; y < n; ++y)
      for (std::int64_t x = 0; x < n; ++x, ++i)
        img[i] = (x - c) * (x - c) + (y - c) * (y - c) + (z - c) * (z - c) <= r2 ? 1 : 0;
  return img;
}

} // namespace zdg::test
