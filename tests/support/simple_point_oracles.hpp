// Test support: characterizations of simple points written independently of
// kernel/topology/simple_points.cpp (no bit tricks, no shared code beyond the configuration
// layout).
//
// - geodesic_topological_numbers: Bertrand's definition ("Simple points, topological numbers
//   and geodesic neighborhoods in cubic grids", PRL 15, 1994) by explicit breadth-first
//   search: G_6(x, Y) = N^2_6(x, Y) with N^1_6 = N*_6 cap Y and
//   N^k_6 = U_{y in N^{k-1}_6} N_6(y) cap N*_18(x) cap Y; G_6+ = N^3_6 with N*_26 in place of
//   N*_18 (the 6-adjacency paired with 18); G_18(x, Y) = N^2_18(x, Y) with
//   N^1_18 = N*_18 cap Y and N^k_18 = U N_18(y) cap N*_26(x) cap Y; G_26 = N*_26 cap Y;
//   T_n(x, Y) = the number of n-components of G_n(x, Y).
// - attachment_is_contractible (3D pairs (26,6) and (6,26)): x is simple iff the attachment
//   of x (the cells of the boundary of x's closed cube covered by the other cubes of the
//   object, for 26; the link of the vertex x in the cubical complex on the object, for 6) is
//   contractible (Kong, "Topology-preserving deletion of 1's from 2-, 3- and 4-dimensional
//   binary images", DGCI 1997). Both live on a 2-sphere and are not all of it unless x is
//   interior, so contractible = connected and Euler characteristic 1.
// - yokoi_connectivity_number (2D; Yokoi, Toriwaki and Fukumura, "An analysis of topological
//   properties of digitized binary pictures using local features", CGIP 4, 1975):
//   N_c^4 = sum_{k odd} (x_k - x_k x_{k+1} x_{k+2}), N_c^8 the same on complemented values,
//   x_1..x_8 the neighbours counter-clockwise from the east; x is simple iff N_c = 1.
#pragma once

#include <array>
#include <bit>
#include <cstdint>
#include <cstdlib>

namespace zdg::test {

/// The offset of bit j of a configuration (3D: 26 bits; 2D: 8 bits, third entry 0).
inline std::array<int, 3> configuration_offset(int dim, int j) {
  const int centre = dim == 3 ? 13 : 4;
  const int p = j < centre ? j : j + 1;
  if (dim == 3) return {p / 9 - 1, (p / 3) % 3 - 1, p % 3 - 1};
  return {p / 3 - 1, p % 3 - 1, 0};
}

inline int offset_l1(const std::array<int, 3>& o) {
  return std::abs(o[0]) + std::abs(o[1]) + std::abs(o[2]);
}

inline bool n_adjacent(int n, const std::array<int, 3>& a, const std::array<int, 3>& b) {
  std::array<int, 3> d{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  for (int v : d) {
    if (std::abs(v) > 1) return false;
  }
  const int l1 = offset_l1(d);
  const int m = (n == 4 || n == 6) ? 1 : ((n == 8 || n == 18) ? 2 : 3);
  return l1 >= 1 && l1 <= m;
}

/// The neighbours (bit masks over configuration bits) of each neighbour position and of x
/// (index count) under n-adjacency, from the definition (n_adjacent); built once.
struct AdjacencyMasks {
  std::array<std::array<std::uint32_t, 27>, 27> of{}; // of[n][j]
  std::array<std::uint32_t, 4> region{};              // neighbours of l1 norm <= m
  explicit AdjacencyMasks(int dim) {
    const int count = dim == 3 ? 26 : 8;
    for (int m = 1; m <= 3; ++m) {
      for (int j = 0; j < count; ++j) {
        if (offset_l1(configuration_offset(dim, j)) <= m)
          region[static_cast<std::size_t>(m)] |= std::uint32_t{1} << j;
      }
    }
    const std::array<int, 3> origin{0, 0, 0};
    for (int n : {4, 6, 8, 18, 26}) {
      for (int j = 0; j <= count; ++j) {
        const auto pj = j == count ? origin : configuration_offset(dim, j);
        std::uint32_t m = 0;
        for (int i = 0; i < count; ++i) {
          if (n_adjacent(n, pj, configuration_offset(dim, i))) m |= std::uint32_t{1} << i;
        }
        of[static_cast<std::size_t>(n)][static_cast<std::size_t>(j)] = m;
      }
    }
  }
  static const AdjacencyMasks& get(int dim) {
    static const AdjacencyMasks d2(2), d3(3);
    return dim == 3 ? d3 : d2;
  }
};

/// T_n(x, Y) for Y a set of neighbours given as configuration bits (3D: n = 6, 18, 26, and 6+
/// when plus; 2D: 4, 8 with G_4 = N^2_4 inside N*_8 and G_8 = N*_8).
inline int geodesic_topological_number(int dim, int n, bool plus, std::uint32_t y) {
  const int count = dim == 3 ? 26 : 8;
  const auto& adj = AdjacencyMasks::get(dim).of[static_cast<std::size_t>(n)];
  // Order and region (largest l1 norm of its offsets) of the geodesic neighbourhood.
  int order = 1, region_m = 3;
  if (n == 6 || n == 4) order = 2, region_m = 2;
  if (n == 6 && plus) order = 3, region_m = 3;
  if (n == 18) order = 2, region_m = 3;
  const std::uint32_t region = AdjacencyMasks::get(dim).region[static_cast<std::size_t>(region_m)];
  // N^1: the points of Y n-adjacent to x; N^k: N^{k-1} and the points of Y in the region
  // n-adjacent to a point of N^{k-1}.
  std::uint32_t g = y & adj[static_cast<std::size_t>(count)];
  for (int k = 2; k <= order; ++k) {
    std::uint32_t next = g;
    for (std::uint32_t rest = y & region & ~g; rest != 0; rest &= rest - 1) {
      const int j = std::countr_zero(rest);
      if ((adj[static_cast<std::size_t>(j)] & g) != 0) next |= std::uint32_t{1} << j;
    }
    g = next;
  }
  // n-components of G by depth-first search.
  std::uint32_t seen = 0;
  int components = 0;
  for (std::uint32_t starts = g; starts != 0; starts &= ~seen) {
    const int s = std::countr_zero(starts);
    ++components;
    std::array<int, 27> stack{};
    int top = 0;
    stack[static_cast<std::size_t>(top++)] = s;
    seen |= std::uint32_t{1} << s;
    while (top > 0) {
      const int a = stack[static_cast<std::size_t>(--top)];
      for (std::uint32_t nb = g & ~seen & adj[static_cast<std::size_t>(a)]; nb != 0; nb &= nb - 1) {
        const int b = std::countr_zero(nb);
        seen |= std::uint32_t{1} << b;
        stack[static_cast<std::size_t>(top++)] = b;
      }
    }
  }
  return components;
}

/// Simple by Bertrand's geodesic topological numbers (6 is 6+ in the pairs with 18).
inline bool geodesic_simple(int dim, int k, int kbar, std::uint32_t config) {
  const std::uint32_t all = dim == 3 ? 0x3FFFFFFu : 0xFFu;
  return geodesic_topological_number(dim, k, kbar == 18, config) == 1 &&
         geodesic_topological_number(dim, kbar, k == 18, ~config & all) == 1;
}

namespace detail {
inline int find(std::array<int, 8>& parent, int a) {
  while (parent[static_cast<std::size_t>(a)] != a) a = parent[static_cast<std::size_t>(a)];
  return a;
}
} // namespace detail

/// Kong's attachment criterion for the pairs (26,6) (object 26) and (6,26) (object 6).
inline bool attachment_is_contractible(int object, std::uint32_t config) {
  auto in_x = [&](int a, int b, int c) {
    if (a == 0 && b == 0 && c == 0) return false;
    const int p = (a + 1) * 9 + (b + 1) * 3 + (c + 1);
    const int j = p < 13 ? p : p - 1;
    return ((config >> j) & 1u) != 0;
  };
  // Vertices: the 8 corners s in {-1, 1}^3 (26) or the 6 face neighbours (6).
  std::array<int, 8> parent{0, 1, 2, 3, 4, 5, 6, 7};
  std::array<bool, 8> vertex{};
  int v = 0, e = 0, f = 0;
  if (object == 26) {
    auto corner_id = [](int a, int b, int c) { return (a > 0) * 4 + (b > 0) * 2 + (c > 0); };
    for (int a : {-1, 1}) {
      for (int b : {-1, 1}) {
        for (int c : {-1, 1}) {
          bool covered = false; // one of the 7 neighbours around the corner
          for (int da : {0, a}) {
            for (int db : {0, b}) {
              for (int dc : {0, c}) covered = covered || in_x(da, db, dc);
            }
          }
          vertex[static_cast<std::size_t>(corner_id(a, b, c))] = covered;
          v += covered;
        }
      }
    }
    // Edges: along axis t, at signs of the two other axes; covered by the 3 neighbours around.
    for (int t = 0; t < 3; ++t) {
      for (int s1 : {-1, 1}) {
        for (int s2 : {-1, 1}) {
          std::array<int, 3> d{0, 0, 0};
          const int u = (t + 1) % 3, w = (t + 2) % 3;
          bool covered = false;
          for (int a : {0, s1}) {
            for (int b : {0, s2}) {
              d[static_cast<std::size_t>(u)] = a;
              d[static_cast<std::size_t>(w)] = b;
              d[static_cast<std::size_t>(t)] = 0;
              covered = covered || in_x(d[0], d[1], d[2]);
            }
          }
          if (!covered) continue;
          ++e;
          std::array<int, 3> p{0, 0, 0}, q{0, 0, 0};
          p[static_cast<std::size_t>(u)] = q[static_cast<std::size_t>(u)] = s1;
          p[static_cast<std::size_t>(w)] = q[static_cast<std::size_t>(w)] = s2;
          p[static_cast<std::size_t>(t)] = -1;
          q[static_cast<std::size_t>(t)] = 1;
          const int ra = detail::find(parent, corner_id(p[0], p[1], p[2]));
          const int rb = detail::find(parent, corner_id(q[0], q[1], q[2]));
          parent[static_cast<std::size_t>(ra)] = rb;
        }
      }
    }
    for (int t = 0; t < 3; ++t) {
      for (int s : {-1, 1}) {
        std::array<int, 3> d{0, 0, 0};
        d[static_cast<std::size_t>(t)] = s;
        f += in_x(d[0], d[1], d[2]);
      }
    }
  } else {
    // Link of x in the cubical complex on the object: vertices = face neighbours (id 2t + side),
    // edges = full quadrant squares, triangles = full octant cubes.
    auto face = [](int t, int s) { return 2 * t + (s > 0); };
    auto unit = [](int t, int s) {
      std::array<int, 3> d{0, 0, 0};
      d[static_cast<std::size_t>(t)] = s;
      return d;
    };
    for (int t = 0; t < 3; ++t) {
      for (int s : {-1, 1}) {
        const auto d = unit(t, s);
        vertex[static_cast<std::size_t>(face(t, s))] = in_x(d[0], d[1], d[2]);
        v += vertex[static_cast<std::size_t>(face(t, s))];
      }
    }
    for (int t = 0; t < 3; ++t) {
      for (int u = t + 1; u < 3; ++u) {
        for (int st : {-1, 1}) {
          for (int su : {-1, 1}) {
            auto a = unit(t, st), b = unit(u, su);
            const std::array<int, 3> c{a[0] + b[0], a[1] + b[1], a[2] + b[2]};
            if (!in_x(a[0], a[1], a[2]) || !in_x(b[0], b[1], b[2]) || !in_x(c[0], c[1], c[2])) {
              continue;
            }
            ++e;
            const int ra = detail::find(parent, face(t, st)),
                      rb = detail::find(parent, face(u, su));
            parent[static_cast<std::size_t>(ra)] = rb;
          }
        }
      }
    }
    for (int a : {-1, 1}) {
      for (int b : {-1, 1}) {
        for (int c : {-1, 1}) {
          bool full = true;
          for (int da : {0, a}) {
            for (int db : {0, b}) {
              for (int dc : {0, c})
                full = full && (in_x(da, db, dc) || (da == 0 && db == 0 && dc == 0));
            }
          }
          f += full;
        }
      }
    }
  }
  int components = 0;
  for (int i = 0; i < 8; ++i) {
    if (vertex[static_cast<std::size_t>(i)] && detail::find(parent, i) == i) ++components;
  }
  return components == 1 && v - e + f == 1;
}

/// The Yokoi connectivity number of the centre for the object adjacency k (4 or 8).
inline int yokoi_connectivity_number(int k, std::uint32_t config) {
  // x_1..x_8 counter-clockwise from the east, with axis 0 = rows (up = -1), axis 1 = columns.
  const int rows[8] = {0, -1, -1, -1, 0, 1, 1, 1}, cols[8] = {1, 1, 0, -1, -1, -1, 0, 1};
  int x[9];
  for (int i = 0; i < 8; ++i) {
    const int p = (rows[i] + 1) * 3 + (cols[i] + 1);
    const int j = p < 4 ? p : p - 1;
    const int v = static_cast<int>((config >> j) & 1u);
    x[i] = k == 4 ? v : 1 - v;
  }
  x[8] = x[0];
  int n = 0;
  for (int i = 0; i < 8; i += 2) n += x[i] - x[i] * x[i + 1] * x[(i + 2) % 8];
  return n;
}

} // namespace zdg::test
