// Test support: brute-force homology over Z/2 of the cell complex that stands for the object
// of a small binary image under an adjacency pair (kernel/topology/betti_numbers.hpp lists them;
// Kong and Rosenfeld, CVGIP 48, 1989, sec. 5):
//   (8,4), (26,6): the union of the closed unit squares / cubes centred at the object points,
//                  as a cubical complex in Khalimsky coordinates (a cell k belongs to it when
//                  one of the pixels / voxels whose closure contains it is in the object);
//   (18,6):        the same with every vertex whose block meets the object in exactly two
//                  opposite corners split into two vertices, one per cube;
//   (4,8), (6,26): the cubical complex on the object points (a cell on every lattice square /
//                  cube whose corners are all in the object);
//   (6,18):        the same plus a hexagonal 2-cell on each 2x2x2 block whose object points
//                  are the six off a main diagonal.
// Betti numbers b_i = n_i - rank d_i - rank d_{i+1}, ranks by Gaussian elimination over Z/2
// on bit columns. Cubic in the number of cells: meant for images of a few hundred points.
#pragma once

#include <zdg/kernel/images/image.hpp>
#include <zdg/kernel/topology/adjacency.hpp>

#include <array>
#include <bit>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <vector>

namespace zdg::test {

struct CellComplexHomology {
  /// Number of cells of each dimension 0..3.
  std::array<std::int64_t, 4> cells{};
  /// Betti numbers over Z/2, b_0..b_3.
  std::array<std::int64_t, 4> betti{};
  std::int64_t euler() const { return cells[0] - cells[1] + cells[2] - cells[3]; }
};

namespace detail {

/// Rank over Z/2 of a matrix given by its columns (lists of row indices; repeated indices
/// cancel).
inline std::int64_t rank_mod2(const std::vector<std::vector<std::int64_t>>& columns,
                              std::int64_t rows) {
  const std::size_t words = static_cast<std::size_t>((rows + 63) / 64);
  std::vector<std::vector<std::uint64_t>> pivots_by_row(static_cast<std::size_t>(rows));
  std::vector<bool> has_pivot(static_cast<std::size_t>(rows), false);
  std::int64_t rank = 0;
  for (const auto& col : columns) {
    std::vector<std::uint64_t> v(words, 0);
    for (std::int64_t r : col) v[static_cast<std::size_t>(r / 64)] ^= std::uint64_t{1} << (r % 64);
    for (;;) {
      std::int64_t lead = -1;
      for (std::size_t w = words; w-- > 0;) {
        if (v[w] != 0) {
          lead = static_cast<std::int64_t>(w * 64 + 63 -
                                           static_cast<std::size_t>(__builtin_clzll(v[w])));
          break;
        }
      }
      if (lead < 0) break;
      if (!has_pivot[static_cast<std::size_t>(lead)]) {
        has_pivot[static_cast<std::size_t>(lead)] = true;
        pivots_by_row[static_cast<std::size_t>(lead)] = v;
        ++rank;
        break;
      }
      const auto& p = pivots_by_row[static_cast<std::size_t>(lead)];
      for (std::size_t w = 0; w < words; ++w) v[w] ^= p[w];
    }
  }
  return rank;
}

/// Homology of a complex given cell by cell: dims[c] and faces[c] (indices of its facets).
inline CellComplexHomology homology(const std::vector<int>& dims,
                                    const std::vector<std::vector<std::int64_t>>& faces) {
  CellComplexHomology h;
  std::vector<std::int64_t> local(dims.size());
  for (std::size_t c = 0; c < dims.size(); ++c) {
    local[c] = h.cells[static_cast<std::size_t>(dims[c])]++;
  }
  std::array<std::int64_t, 5> rank{};
  for (int i = 1; i <= 3; ++i) {
    std::vector<std::vector<std::int64_t>> cols;
    for (std::size_t c = 0; c < dims.size(); ++c) {
      if (dims[c] != i) continue;
      std::vector<std::int64_t> col;
      for (std::int64_t f : faces[c]) col.push_back(local[static_cast<std::size_t>(f)]);
      cols.push_back(std::move(col));
    }
    rank[static_cast<std::size_t>(i)] = rank_mod2(cols, h.cells[static_cast<std::size_t>(i - 1)]);
  }
  for (std::size_t i = 0; i < 4; ++i) h.betti[i] = h.cells[i] - rank[i] - rank[i + 1];
  return h;
}

} // namespace detail

/// The homology of the complex of the object of `image` (2D or 3D, any extents) under `pair`.
inline CellComplexHomology object_homology(const Image<std::uint8_t>& image,
                                           const AdjacencyPair& pair) {
  const Domain& dom = image.domain();
  const int d = dom.dim();
  // Coordinates are 3D; a 2D image is the layer 0 of a first axis of extent 1 along which
  // no cell extends (its cells are those of the plane).
  std::array<std::int64_t, 3> n{1, 1, 1};
  for (int k = 0; k < d; ++k) n[static_cast<std::size_t>(3 - d + k)] = dom.extent(k);
  auto in_x = [&](std::int64_t i0, std::int64_t i1, std::int64_t i2) {
    if (i0 < 0 || i1 < 0 || i2 < 0 || i0 >= n[0] || i1 >= n[1] || i2 >= n[2]) return false;
    return image[(i0 * n[1] + i1) * n[2] + i2] != 0;
  };
  std::vector<int> dims;
  std::vector<std::vector<std::int64_t>> faces;
  const bool union_of_cubes = pair.object == 8 || pair.object == 26 || pair.object == 18;
  // Axes along which cells may extend: the last d axes.
  const int first_axis = 3 - d;
  if (union_of_cubes) {
    // Khalimsky cells k in [0, 2n]; in 2D axis 0 is fixed at k = 1 (the slab's only voxel
    // layer, not extended: cells are those of the plane).
    std::map<std::array<std::int64_t, 4>, std::int64_t> id; // (k0, k1, k2, copy) -> cell
    // Incident object voxels of a cell.
    auto incident = [&](const std::array<std::int64_t, 3>& k) {
      std::vector<std::array<std::int64_t, 3>> vox;
      std::array<std::vector<std::int64_t>, 3> choices;
      for (std::size_t a = 0; a < 3; ++a) {
        if (k[a] % 2 != 0) {
          choices[a] = {(k[a] - 1) / 2};
        } else {
          choices[a] = {k[a] / 2 - 1, k[a] / 2};
        }
      }
      for (auto x : choices[0]) {
        for (auto y : choices[1]) {
          for (auto z : choices[2]) {
            if (in_x(x, y, z)) vox.push_back({x, y, z});
          }
        }
      }
      return vox;
    };
    // A vertex to split: its object voxels are exactly two opposite corners of its block.
    auto split_vertex = [&](const std::array<std::int64_t, 3>& k,
                            const std::vector<std::array<std::int64_t, 3>>& vox) {
      if (pair.object != 18 || vox.size() != 2) return false;
      (void)k;
      return std::abs(vox[0][0] - vox[1][0]) == 1 && std::abs(vox[0][1] - vox[1][1]) == 1 &&
             std::abs(vox[0][2] - vox[1][2]) == 1;
    };
    std::array<std::int64_t, 3> lo{}, hi{};
    for (int a = 0; a < 3; ++a) {
      lo[static_cast<std::size_t>(a)] = a < first_axis ? 1 : 0;
      hi[static_cast<std::size_t>(a)] = a < first_axis ? 1 : 2 * n[static_cast<std::size_t>(a)];
    }
    // Cells in increasing dimension so that faces exist before the cells that use them.
    for (int dim = 0; dim <= d; ++dim) {
      for (std::int64_t k0 = lo[0]; k0 <= hi[0]; ++k0) {
        for (std::int64_t k1 = lo[1]; k1 <= hi[1]; ++k1) {
          for (std::int64_t k2 = lo[2]; k2 <= hi[2]; ++k2) {
            const std::array<std::int64_t, 3> k{k0, k1, k2};
            int cd = 0;
            for (int a = first_axis; a < 3; ++a) cd += k[static_cast<std::size_t>(a)] % 2 != 0;
            if (cd != dim) continue;
            const auto vox = incident(k);
            if (vox.empty()) continue;
            if (dim == 0) {
              const int copies = split_vertex(k, vox) ? 2 : 1;
              for (int c = 0; c < copies; ++c) {
                id[{k0, k1, k2, c}] = static_cast<std::int64_t>(dims.size());
                dims.push_back(0);
                faces.emplace_back();
              }
              continue;
            }
            std::vector<std::int64_t> f;
            for (int a = first_axis; a < 3; ++a) {
              if (k[static_cast<std::size_t>(a)] % 2 == 0) continue;
              for (int s = -1; s <= 1; s += 2) {
                auto kf = k;
                kf[static_cast<std::size_t>(a)] += s;
                int copy = 0;
                if (dim == 1) {
                  const auto fv = incident(kf);
                  if (split_vertex(kf, fv)) {
                    // The copy of the corner voxel whose closure holds this edge.
                    copy = -1;
                    for (int c = 0; c < 2; ++c) {
                      for (const auto& v : vox) {
                        if (v == fv[static_cast<std::size_t>(c)]) copy = c;
                      }
                    }
                  }
                }
                f.push_back(id.at({kf[0], kf[1], kf[2], copy}));
              }
            }
            id[{k0, k1, k2, 0}] = static_cast<std::int64_t>(dims.size());
            dims.push_back(dim);
            faces.push_back(std::move(f));
          }
        }
      }
    }
    return detail::homology(dims, faces);
  }
  // The cubical complex on the object points: cell (v, S) = the block v + {0,1}^S.
  std::map<std::array<std::int64_t, 4>, std::int64_t> id; // (v0, v1, v2, S) -> cell
  for (int dim = 0; dim <= d; ++dim) {
    for (std::int64_t v0 = 0; v0 < n[0]; ++v0) {
      for (std::int64_t v1 = 0; v1 < n[1]; ++v1) {
        for (std::int64_t v2 = 0; v2 < n[2]; ++v2) {
          for (int s = 0; s < 8; ++s) {
            if (std::popcount(static_cast<unsigned>(s)) != dim) continue;
            bool ok = true;
            for (int a = 0; a < first_axis; ++a) ok = ok && ((s >> a) & 1) == 0;
            for (int t = 0; t < 8 && ok; ++t) {
              if ((t & ~s) != 0) continue;
              ok = in_x(v0 + (t & 1), v1 + ((t >> 1) & 1), v2 + ((t >> 2) & 1));
            }
            if (!ok) continue;
            std::vector<std::int64_t> f;
            for (int a = 0; a < 3; ++a) {
              if (((s >> a) & 1) == 0) continue;
              const int sf = s & ~(1 << a);
              f.push_back(id.at({v0, v1, v2, sf}));
              f.push_back(id.at({v0 + (a == 0), v1 + (a == 1), v2 + (a == 2), sf}));
            }
            id[{v0, v1, v2, s}] = static_cast<std::int64_t>(dims.size());
            dims.push_back(dim);
            faces.push_back(std::move(f));
          }
        }
      }
    }
  }
  if (pair.object == 6 && pair.background == 18) {
    // Hexagons: blocks whose object points are all but two opposite corners.
    for (std::int64_t v0 = 0; v0 + 1 < n[0]; ++v0) {
      for (std::int64_t v1 = 0; v1 + 1 < n[1]; ++v1) {
        for (std::int64_t v2 = 0; v2 + 1 < n[2]; ++v2) {
          int missing = 0, first_missing = -1;
          for (int t = 0; t < 8; ++t) {
            if (!in_x(v0 + (t & 1), v1 + ((t >> 1) & 1), v2 + ((t >> 2) & 1))) {
              ++missing;
              if (first_missing < 0) first_missing = t;
            }
          }
          if (missing != 2 ||
              in_x(v0 + ((7 - first_missing) & 1), v1 + (((7 - first_missing) >> 1) & 1),
                   v2 + (((7 - first_missing) >> 2) & 1))) {
            continue;
          }
          // Its boundary: the 6 edges of the block between two object points.
          std::vector<std::int64_t> f;
          for (int t = 0; t < 8; ++t) {
            for (int a = 0; a < 3; ++a) {
              if ((t >> a) & 1) continue;
              const int u = t | (1 << a);
              const std::int64_t x0 = v0 + (t & 1), x1 = v1 + ((t >> 1) & 1),
                                 x2 = v2 + ((t >> 2) & 1);
              if (!in_x(x0, x1, x2) ||
                  !in_x(v0 + (u & 1), v1 + ((u >> 1) & 1), v2 + ((u >> 2) & 1))) {
                continue;
              }
              f.push_back(id.at({x0, x1, x2, 1 << a}));
            }
          }
          dims.push_back(2);
          faces.push_back(std::move(f));
        }
      }
    }
  }
  return detail::homology(dims, faces);
}

} // namespace zdg::test
