// Euler characteristic and Betti numbers of the object of a binary image of Z^2 or Z^3 under
// an adjacency pair (k, kbar) (kernel/topology/adjacency.hpp).
//
// X stands for a cubical complex per pair, its continuous analog (Kong and Rosenfeld, CVGIP 48,
// 1989; Lee, Poston and Rosenfeld, CVGIP: GMIP 53, 1991): (8,4), (26,6) the union of the closed
// squares / cubes of X; (4,8), (6,26) the cells on full blocks; (18,6) and (6,18) (Bertrand's
// "6+") variants of these (definitions: docs/NOTES.md, "kernel/topology/betti_numbers.hpp").
// chi: a 2^{2^d}-entry table summed over the blocks of the padded image, O(N), multi-threaded.
// Betti numbers by Alexander duality, O(N): b0 = the k-components of X, b2 = the bounded
// kbar-components of the background (3D), b1 = b0 + b2 - chi (3D) or b0 - chi (2D).
// Width: int64 sums; OverflowError when 64 (N + 1) 8 would not fit (never in memory).
#pragma once

#include <zdg/kernel/images/image.hpp>
#include <zdg/kernel/topology/adjacency.hpp>

#include <array>
#include <cstdint>

namespace zdg {

struct BettiNumbers {
  int dim = 3;
  /// chi = b0 - b1 + b2.
  std::int64_t euler = 0;
  /// b0, b1, b2 (b2 = 0 in 2D).
  std::array<std::int64_t, 3> b{};
  friend bool operator==(const BettiNumbers&, const BettiNumbers&) = default;
};

/// The Euler characteristic of the object under the pair (its dim must be the image's).
std::int64_t euler_characteristic(const Image<std::uint8_t>& image, const AdjacencyPair& pair,
                                  unsigned threads = 0);

/// Euler characteristic and Betti numbers of the object under the pair.
BettiNumbers betti_numbers(const Image<std::uint8_t>& image, const AdjacencyPair& pair,
                           unsigned threads = 0);

/// The table behind euler_characteristic(): 2^d (2D: 4, 3D: 8) times the share of the block
/// whose points in X are the bits of `config` (bit a*4 + b*2 + c for the point (a, b, c) of
/// the block in 3D, bit a*2 + b in 2D). The sum over all blocks is 2^d chi.
int euler_block_weight(const AdjacencyPair& pair, unsigned config);

} // namespace zdg
