// Test oracle: Betti numbers over Z/2 of small digital objects of Z^3 under the four adjacency
// pairs, by brute force (ranks of the boundary matrices of a cubical complex).
//
//   (26,6): the closed cubical complex of X (the union of its closed unit cubes).
//   (18,6): the same, with every pointel around which X is exactly two opposite voxels of the
//           2x2x2 block split into two copies (one per voxel): the two cubes no longer touch.
//   (6,26) and (6,18): Alexander duality in S^3 from the background. With K the complex of the
//           complement of X in the box grown by one voxel, under (26,6) resp. (18,6), the
//           object has b0 = b2(K), b1 = b1(K), b2 = b0(K) - 1 (the outer layer of K is a
//           sphere around X, coned off by the point at infinity).
//   dual_cubical_betti: (6,26) directly, as the cubical complex on the voxel centres whose
//           cells are the unit lattice cubes (points, edges, squares, cubes) with all their
//           voxels in X: an independent cross-check of the duality.
//
// Cells are Khalimsky points k (dimension = number of odd coordinates; the faces of k are the
// k +- e_a for its odd axes a). Dense Z/2 elimination: fine up to a few thousand cells.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
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

using Betti3 = std::array<std::int64_t, 3>;

namespace detail {

inline std::int64_t rank_z2(std::vector<std::vector<std::uint64_t>> rows) {
  std::map<std::size_t, std::vector<std::uint64_t>> pivots; // lowest set bit -> row
  std::int64_t rank = 0;
  for (auto& row : rows) {
    while (true) {
      std::size_t w = 0;
      while (w < row.size() && row[w] == 0) ++w;
      if (w == row.size()) break;
      const std::size_t col = w * 64 + std::size_t(__builtin_ctzll(row[w]));
      auto it = pivots.find(col);
      if (it == pivots.end()) {
        pivots.emplace(col, row);
        ++rank;
        break;
      }
      for (std::size_t i = 0; i < row.size(); ++i) row[i] ^= it->second[i];
    }
  }
  return rank;
}

struct Cell {
  int k[3];
  int dim() const { return (k[0] & 1) + (k[1] & 1) + (k[2] & 1); }
};

/// Betti numbers of the complex of the cells k in [0, 2n]^3 (Khalimsky, n = (nx, ny, nz)) for
/// which `in(k)` holds (closed under faces); `copies(k)` gives, for a 0-cell k, the copy of k
/// that a 1-cell's endpoint uses (vertex_copy(linel, pointel) -> index 0 or 1), so that
/// pointels may be split.
inline Betti3 betti(int nx, int ny, int nz, const std::function<bool(const int*)>& in,
                    const std::function<int(const int*, const int*)>& vertex_copy,
                    const std::function<int(const int*)>& copies) {
  std::map<std::array<int, 4>, std::size_t> index[4];
  std::vector<Cell> cells[4];
  for (int z = 0; z <= 2 * nz; ++z)
    for (int y = 0; y <= 2 * ny; ++y)
      for (int x = 0; x <= 2 * nx; ++x) {
        const int k[3] = {x, y, z};
        if (!in(k)) continue;
        Cell c{{x, y, z}};
        const int d = c.dim();
        const int m = d == 0 ? copies(k) : 1;
        for (int i = 0; i < m; ++i) {
          index[d].emplace(std::array<int, 4>{x, y, z, i}, cells[d].size());
          if (i == 0) cells[d].push_back(c);
        }
        if (d == 0 && m == 2) cells[0].push_back(c);
      }
  std::int64_t rank[5] = {0, 0, 0, 0, 0};
  for (int d = 1; d <= 3; ++d) {
    const std::size_t cols = index[d - 1].size();
    std::vector<std::vector<std::uint64_t>> rows;
    for (const Cell& c : cells[d]) {
      std::vector<std::uint64_t> row((cols + 63) / 64, 0);
      for (int a = 0; a < 3; ++a) {
        if ((c.k[a] & 1) == 0) continue;
        for (int s : {-1, 1}) {
          int f[3] = {c.k[0], c.k[1], c.k[2]};
          f[a] += s;
          const int copy = d == 1 ? vertex_copy(c.k, f) : 0;
          const auto col = index[d - 1].at({f[0], f[1], f[2], copy});
          row[col / 64] ^= std::uint64_t{1} << (col % 64);
        }
      }
      rows.push_back(std::move(row));
    }
    rank[d] = rank_z2(std::move(rows));
  }
  Betti3 b{};
  for (int d = 0; d < 3; ++d)
    b[std::size_t(d)] = std::int64_t(index[d].size()) - rank[d] - rank[d + 1];
  return b;
}

inline bool opposite_pair(const SmallVolume& v, const int* p, int* first) {
  // p: Khalimsky pointel (all even); the block voxels are p/2 - 1 + {0,1}^3.
  int count = 0, bits = 0;
  for (int b = 0; b < 8; ++b)
    if (v.at(p[0] / 2 - 1 + (b & 1), p[1] / 2 - 1 + ((b >> 1) & 1), p[2] / 2 - 1 + (b >> 2))) {
      ++count;
      bits |= 1 << b;
    }
  if (count != 2) return false;
  for (int b = 0; b < 8; ++b)
    if (bits == ((1 << b) | (1 << (7 - b)))) {
      *first = b;
      return true;
    }
  return false;
}

/// Closed cubical complex of v (pointels of opposite pairs split when split_pinches).
inline Betti3 closed_complex_betti(const SmallVolume& v, bool split_pinches) {
  auto in = [&](const int* k) {
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      if (k[a] & 1) {
        lo[a] = hi[a] = (k[a] - 1) / 2;
      } else {
        lo[a] = k[a] / 2 - 1;
        hi[a] = k[a] / 2;
      }
    }
    for (int z = lo[2]; z <= hi[2]; ++z)
      for (int y = lo[1]; y <= hi[1]; ++y)
        for (int x = lo[0]; x <= hi[0]; ++x)
          if (v.at(x, y, z)) return true;
    return false;
  };
  auto copies = [&](const int* p) {
    int b = 0;
    return split_pinches && opposite_pair(v, p, &b) ? 2 : 1;
  };
  auto vertex_copy = [&](const int* linel, const int* p) {
    int b = 0;
    if (!split_pinches || !opposite_pair(v, p, &b)) return 0;
    // The linel lies on the side of the voxel b (bits (bx, by, bz)) or of 7 - b: along its
    // axis it points into that voxel's half.
    for (int a = 0; a < 3; ++a)
      if (linel[a] & 1) return ((linel[a] > p[a]) == (((b >> a) & 1) != 0)) ? 0 : 1;
    return 0;
  };
  return betti(v.nx, v.ny, v.nz, in, vertex_copy, copies);
}

/// The complement of v in its box grown by one voxel on every side.
inline SmallVolume padded_complement(const SmallVolume& v) {
  SmallVolume c;
  c.nx = v.nx + 2;
  c.ny = v.ny + 2;
  c.nz = v.nz + 2;
  c.data.resize(std::size_t(c.nx * c.ny * c.nz));
  for (int z = 0; z < c.nz; ++z)
    for (int y = 0; y < c.ny; ++y)
      for (int x = 0; x < c.nx; ++x)
        c.data[std::size_t((z * c.ny + y) * c.nx + x)] = v.at(x - 1, y - 1, z - 1) ? 0 : 1;
  return c;
}

} // namespace detail

/// Betti numbers (b0, b1, b2) over Z/2 of the object of v under the pair (k, kbar) in
/// {(26,6), (18,6), (6,26), (6,18)}.
inline Betti3 object_betti(const SmallVolume& v, int k, int kbar) {
  if (k == 26 || k == 18) return detail::closed_complex_betti(v, k == 18);
  const auto bg = detail::closed_complex_betti(detail::padded_complement(v), kbar == 18);
  return {bg[2], bg[1], bg[0] - 1};
}

/// (6,26) directly: the cubical complex of the lattice cubes with all voxels in v.
inline Betti3 dual_cubical_betti(const SmallVolume& v) {
  auto in = [&](const int* k) {
    // Dual cell k: voxels k/2 (even) or (k-1)/2 and (k+1)/2 (odd) along each axis.
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      lo[a] = (k[a] & 1) ? (k[a] - 1) / 2 : k[a] / 2;
      hi[a] = (k[a] & 1) ? (k[a] + 1) / 2 : k[a] / 2;
    }
    for (int z = lo[2]; z <= hi[2]; ++z)
      for (int y = lo[1]; y <= hi[1]; ++y)
        for (int x = lo[0]; x <= hi[0]; ++x)
          if (!v.at(x, y, z)) return false;
    return true;
  };
  return detail::betti(
      v.nx, v.ny, v.nz, in, [](const int*, const int*) { return 0; }, [](const int*) { return 1; });
}

} // namespace zdg::test
