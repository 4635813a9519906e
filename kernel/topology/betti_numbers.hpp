// Euler characteristic and Betti numbers of the object of a binary image of Z^2 or Z^3 under
// an adjacency pair (k, kbar) (kernel/topology/adjacency.hpp).
//
// The object X (points of nonzero value) stands for a polyhedron, its continuous analog,
// whose complement in R^d is an analog of the background under kbar (Kong and Rosenfeld,
// "Digital topology: introduction and survey", CVGIP 48, 1989, sec. 5; Kong and Roscoe,
// CVGIP 29, 1985; Lee, Poston and Rosenfeld, "Winding and Euler numbers for 2D and 3D
// digital images", CVGIP: GMIP 53, 1991). Up to homotopy it is this cell complex:
//   (8,4), (26,6): the union of the closed unit squares / cubes centred at the points of X;
//   (4,8), (6,26): the cubical complex with a vertex at every point of X and a cell on every
//                  unit square / cube of the lattice whose corners all lie in X (edges:
//                  4/6-adjacent pairs; squares: full 2x2 blocks; cubes: full 2x2x2 blocks);
//                  it is a deformation retract of the open set of the points of R^d all of
//                  whose nearest lattice points lie in X, the complement of the (8,4) /
//                  (26,6) analog of the background;
//   (18,6):        the (26,6) complex in which every vertex shared by exactly two closed cubes,
//                  opposite corners of its 2x2x2 block, is split into one vertex per cube
//                  (those two points are 26- but not 18-adjacent);
//   (6,18):        the (6,26) complex plus a hexagonal 2-cell on every 2x2x2 block whose
//                  points in X are the six off one main diagonal (the block's two background
//                  corners are not 18-adjacent, so no background path crosses that hexagon).
// The 6-adjacency paired with 18 is the literature's "6+" (Bertrand 1994): a closed 6-path
// inside one 2x2x2 block bounds a disc, which the hexagonal cells above say.
// tests/kernel/topology/betti_numbers_test.cpp computes the homology of exactly these complexes by
// brute force (ranks of boundary matrices over Z/2) and checks the results below against it;
// tests/kernel/topology/simple_points_test.cpp checks that deleting a simple point
// (Bertrand-Malandain) keeps the homology of these complexes for the object and for the background.
//
// Euler characteristic: chi = sum over the (n_0 + 1) ... (n_{d-1} + 1) 2^d-blocks of the image
// padded with background of a local contribution read in a 2^{2^d}-entry table (every cell of
// the complex is shared by the blocks around it: a vertex of the union of cubes sits in one
// block, an edge in two, a square in four, a cube in eight; the table holds 8 (3D) or 4 (2D)
// times the block's share, so the sum is exact). O(N), multi-threaded.
// Betti numbers (Alexander duality in S^d; the analog is a compact polyhedron up to homotopy):
//   b0 = the number of k-components of X;
//   b2 (3D) = the number of bounded kbar-components of the background (cavities);
//   b1 = b0 + b2 - chi in 3D (b3 = 0), b1 = b0 - chi in 2D (the bounded kbar-components of
//   the background, the holes). O(N) (kernel/topology/connected_components.hpp for b0 and b2).
//
// Width: every value is at most 8 N in absolute value and N fits int64 (Domain); the sums are
// int64, checked at entry (OverflowError when 64 (N + 1) 8 would not fit, i.e. never for an
// image that fits in memory).
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
