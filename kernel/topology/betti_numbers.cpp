#include <zdg/arith/error.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>
#include <zdg/kernel/topology/betti_numbers.hpp>
#include <zdg/kernel/topology/connected_components.hpp>

#include <array>
#include <bit>
#include <vector>

namespace zdg {
namespace {

// Point (a, b, c) of a 2x2x2 block: bit a*4 + b*2 + c (so axis 0 is bit 2).

// 8 times the share of one 2x2x2 block (centred on a vertex p of the cubical grid of the
// voxel boundaries) in the Euler characteristic of the 3D analog of the pair.
int block_weight_3d(int object, int background, unsigned config) {
  const int points = std::popcount(config);
  if (object == 26 || object == 18) {
    // Union of closed cubes: the vertex p (1 block), the 6 half-edges from p (2 blocks each),
    // the 12 quarter-squares around p (4 blocks each), the 8 cubes (8 blocks each).
    int edges = 0, squares = 0;
    for (int axis = 0; axis < 3; ++axis) {
      for (int side = 0; side < 2; ++side) {
        bool any = false; // the edge from p along axis, on side: the 4 cubes with that side
        for (unsigned v = 0; v < 8; ++v) {
          const int bit = static_cast<int>((v >> (2 - axis)) & 1u);
          if (bit == side && ((config >> v) & 1u)) any = true;
        }
        edges += any ? 1 : 0;
      }
    }
    for (unsigned v = 0; v < 8; ++v) {
      for (int axis = 0; axis < 3; ++axis) {
        const unsigned w = v ^ (1u << (2 - axis));
        if (w < v) continue; // the square between cubes v and w (they differ along axis)
        if (((config >> v) & 1u) || ((config >> w) & 1u)) ++squares;
      }
    }
    int weight = 8 * (config != 0 ? 1 : 0) - 4 * edges + 2 * squares - points;
    if (object == 18 && points == 2) {
      // Two opposite corners alone: the vertex is split in two (+1 vertex).
      for (unsigned v = 0; v < 4; ++v) { // the 4 main diagonals {v, 7 - v}
        if (config == ((1u << v) | (1u << (7 - v)))) weight += 8;
      }
    }
    (void)background;
    return weight;
  }
  // object 6: the cubical complex on the points (vertex: 8 blocks, edge: 4, square: 2, cube: 1).
  int edges = 0, squares = 0;
  for (unsigned v = 0; v < 8; ++v) {
    for (int axis = 0; axis < 3; ++axis) {
      const unsigned w = v ^ (1u << (2 - axis));
      if (w > v && ((config >> v) & 1u) && ((config >> w) & 1u)) ++edges;
    }
  }
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      bool all = true; // the face of the block where the coordinate along axis is side
      for (unsigned v = 0; v < 8; ++v) {
        const int bit = static_cast<int>((v >> (2 - axis)) & 1u);
        if (bit == side && !((config >> v) & 1u)) all = false;
      }
      squares += all ? 1 : 0;
    }
  }
  int weight = points - 2 * edges + 4 * squares - 8 * (config == 255u ? 1 : 0);
  if (background == 18 && points == 6) {
    // The hexagon around a main diagonal whose two ends are background: one more 2-cell.
    for (unsigned v = 0; v < 4; ++v) {
      if (config == (255u & ~((1u << v) | (1u << (7 - v))))) weight += 8;
    }
  }
  return weight;
}

// 2D: 4 times the share of one 2x2 block (bit a*2 + b).
int block_weight_2d(int object, unsigned config) {
  const int points = std::popcount(config);
  if (object == 8) {
    // Union of closed squares: vertex (1 block), 4 half-edges (2 blocks), 4 squares (4 blocks).
    int edges = 0;
    const unsigned sides[4] = {0b0011u, 0b1100u, 0b0101u, 0b1010u};
    for (unsigned s : sides) edges += (config & s) != 0 ? 1 : 0;
    return 4 * (config != 0 ? 1 : 0) - 2 * edges + points;
  }
  // object 4: vertices (4 blocks), edges (2 blocks), squares (1 block).
  int edges = 0;
  const unsigned pairs[4] = {0b0011u, 0b1100u, 0b0101u, 0b1010u};
  for (unsigned s : pairs) edges += (config & s) == s ? 1 : 0;
  return points - 2 * edges + 4 * (config == 15u ? 1 : 0);
}

void check_pair(const Image<std::uint8_t>& image, const AdjacencyPair& pair) {
  if (image.dim() != pair.dim) {
    throw InvalidArgument("adjacency pair " + pair.name() + " is for dimension " +
                          std::to_string(pair.dim) + ", the image has dimension " +
                          std::to_string(image.dim()));
  }
  make_adjacency_pair(pair.dim, pair.object, pair.background); // admissible, or throws
}

} // namespace

int euler_block_weight(const AdjacencyPair& pair, unsigned config) {
  make_adjacency_pair(pair.dim, pair.object, pair.background);
  if (pair.dim == 2) {
    if (config >= 16u) throw InvalidArgument("euler block weight: 2D configuration >= 16");
    return block_weight_2d(pair.object, config);
  }
  if (config >= 256u) throw InvalidArgument("euler block weight: 3D configuration >= 256");
  return block_weight_3d(pair.object, pair.background, config);
}

std::int64_t euler_characteristic(const Image<std::uint8_t>& image, const AdjacencyPair& pair,
                                  unsigned threads) {
  check_pair(image, pair);
  const Domain& d = image.domain();
  const bool three_d = d.dim() == 3;
  // A 2D image is the slab n0 = 1 of 3D; (8,4) and (4,8) give it the same complexes as
  // (26,6) and (6,26) (a cube of the slab over each square).
  const std::int64_t n0 = three_d ? d.extent(0) : 1, n1 = d.extent(d.dim() - 2),
                     n2 = d.extent(d.dim() - 1);
  if (d.size() >= (std::int64_t{1} << 53)) {
    throw OverflowError("euler characteristic: 2^53 points or more (int64 sums)");
  }
  const int object = three_d ? pair.object : (pair.object == 8 ? 26 : 6);
  const int background = three_d ? pair.background : (pair.object == 8 ? 6 : 26);
  std::array<int, 256> weight{};
  for (unsigned c = 0; c < 256; ++c) weight[c] = block_weight_3d(object, background, c);
  // spread[col]: the column bits (a*2 + b) at the block positions (a*4 + b*2 + 0).
  std::array<unsigned, 16> spread{};
  for (unsigned col = 0; col < 16; ++col) {
    for (unsigned a = 0; a < 2; ++a) {
      for (unsigned b = 0; b < 2; ++b) {
        if ((col >> (a * 2 + b)) & 1u) spread[col] |= 1u << (a * 4 + b * 2);
      }
    }
  }
  const std::uint8_t* data = image.values().data();
  const std::int64_t block_rows = (n0 + 1) * (n1 + 1);
  const unsigned w = worker_count(threads, block_rows);
  std::vector<std::int64_t> partial(w, 0);
  parallel_for(w, w, [&](std::int64_t k) {
    const std::int64_t rb = block_rows / w * k + block_rows % w * k / w;
    const std::int64_t re = block_rows / w * (k + 1) + block_rows % w * (k + 1) / w;
    std::int64_t sum = 0;
    for (std::int64_t r = rb; r < re; ++r) {
      const std::int64_t p = r / (n1 + 1), q = r % (n1 + 1);
      // The four rows (p - 1 + a, q - 1 + b) of the block row, null outside the image.
      const std::uint8_t* rows[4];
      for (int a = 0; a < 2; ++a) {
        for (int b = 0; b < 2; ++b) {
          const std::int64_t i0 = p - 1 + a, i1 = q - 1 + b;
          rows[a * 2 + b] =
              (i0 >= 0 && i0 < n0 && i1 >= 0 && i1 < n1) ? data + (i0 * n1 + i1) * n2 : nullptr;
        }
      }
      auto column = [&](std::int64_t x) {
        unsigned col = 0;
        for (unsigned j = 0; j < 4; ++j) {
          if (rows[j] != nullptr && rows[j][x] != 0) col |= 1u << j;
        }
        return col;
      };
      unsigned left = 0;
      for (std::int64_t x = 0; x <= n2; ++x) {
        const unsigned right = x < n2 ? column(x) : 0u;
        sum += weight[spread[left] | (spread[right] << 1)];
        left = right;
      }
    }
    partial[static_cast<std::size_t>(k)] = sum;
  });
  std::int64_t total = 0;
  for (std::int64_t s : partial) total += s;
  return total / 8; // exact: the weights sum to 8 chi
}

BettiNumbers betti_numbers(const Image<std::uint8_t>& image, const AdjacencyPair& pair,
                           unsigned threads) {
  BettiNumbers out;
  out.dim = pair.dim;
  out.euler = euler_characteristic(image, pair, threads);
  out.b[0] = count_components(image, pair.object, Phase::object, threads).components;
  if (pair.dim == 3) {
    out.b[2] = count_components(image, pair.background, Phase::background, threads).bounded;
  }
  out.b[1] = out.b[0] + out.b[2] - out.euler;
  return out;
}

} // namespace zdg
