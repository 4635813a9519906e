// Simple points of binary images of Z^2 and Z^3 under an adjacency pair (k, kbar)
// (kernel/topology/adjacency.hpp): the definition-level test and the look-up tables built from it.
//
// A point x of the object X is simple when removing it does not change the topology: the
// continuous analog of X \ {x} is a deformation retract of that of X
// (kernel/topology/betti_numbers.hpp lists the analogs), so every Betti number of the object and of
// the background is kept (Kong and Rosenfeld, CVGIP 48, 1989, sec. 7). Simplicity is local: it
// depends only on the configuration of X in the 3^d - 1 neighbours of x.
//
// Definition-level test, 3D (Bertrand and Malandain, "A new characterization of
// three-dimensional simple points", Pattern Recognition Letters 15, 1994; Bertrand, "Simple
// points, topological numbers and geodesic neighborhoods in cubic grids", PRL 15, 1994):
// with N*_n(x) the n-neighbours of x and the geodesic neighbourhoods of order k
// N^1_n(x, Y) = N*_n(x) cap Y, N^k_n(x, Y) = U_{y in N^{k-1}_n} N_n(y) cap N*_m(x) cap Y,
//   G_6(x, Y)  = N^2_6 with m = 18,       G_6+(x, Y) = N^3_6 with m = 26,
//   G_18(x, Y) = N^2_18 with m = 26,      G_26(x, Y) = N*_26(x) cap Y,
// the topological number T_n(x, Y) is the number of n-components of G_n(x, Y), and x is
// (k, kbar)-simple iff T_k(x, X) = 1 and T_kbar(x, complement of X) = 1. The 6-adjacency of
// the pairs (6,18) and (18,6) is the literature's "6+" (order 3: a closed 6-path inside a
// 2x2x2 block bounds a disc when the background is 18-connected); with 26 it is plain 6.
// 2D (Rosenfeld, "Connectivity in digital pictures", JACM 17, 1970; the crossing / Yokoi
// number is the same count): T_8(x, Y) = the number of 8-components of N*_8(x) cap Y,
// T_4(x, Y) = the number of 4-components of N*_8(x) cap Y 4-adjacent to x; x is simple iff
// both numbers of the pair are 1.
// Components are found by bit-parallel flood filling in the 27-bit (9-bit) mask of the
// neighbourhood; a configuration costs O(1) (a few dozen word operations).
//
// Configurations: bit j of a configuration is the neighbour at position
// p = sum_k (d_k + 1) 3^(d - 1 - k) of the offset d (axis order of the image; p = 13 in 3D,
// 4 in 2D is x itself), with j = p below the centre and j = p - 1 above: 26 bits in 3D, 8 in
// 2D. Bit set = the neighbour is in the object; points outside the image are background.
//
// Tables: SimplePointTable::of(pair) holds one bit per configuration (2^26 bits = 8 MiB in 3D,
// 256 bits in 2D), built from the definition-level test on first use (multi-threaded,
// std::call_once: thread-safe, built once per pair for the life of the program).
// tests/kernel/topology/simple_points_slow_test.cpp checks every entry of every table against the
// definition and against an independent breadth-first search over geodesic neighbourhoods.
#pragma once

#include <zdg/kernel/images/image.hpp>
#include <zdg/kernel/topology/adjacency.hpp>

#include <cstdint>
#include <vector>

namespace zdg {

/// The bit of the neighbour at offset (d0, d1, d2) (entries in {-1, 0, 1}, not all 0; in 2D
/// d2 is ignored and the offset is (d0, d1)).
int neighbour_bit(int dim, int d0, int d1, int d2 = 0);

/// Number of configurations: 2^8 (dim 2) or 2^26 (dim 3).
std::uint32_t configuration_count(int dim);

/// The configuration of the point of linear index i of a 2D or 3D image (neighbours outside
/// the domain are background).
std::uint32_t neighbourhood_configuration(const Image<std::uint8_t>& image, std::int64_t i);

struct TopologicalNumbers {
  /// T_k(x, X) and T_kbar(x, complement of X) (6 read as 6+ in the pairs with 18).
  int object = 0;
  int background = 0;
  friend bool operator==(const TopologicalNumbers&, const TopologicalNumbers&) = default;
};

/// The topological numbers of the centre of the configuration under the pair.
TopologicalNumbers topological_numbers(const AdjacencyPair& pair, std::uint32_t config);

/// The definition-level test: both topological numbers equal 1.
bool is_simple_by_definition(const AdjacencyPair& pair, std::uint32_t config);

/// One bit per configuration: simple or not, for one pair.
class SimplePointTable {
public:
  /// The table of the pair, built on first use (thread-safe); InvalidArgument for a pair
  /// that is not admissible.
  static const SimplePointTable& of(const AdjacencyPair& pair);

  bool simple(std::uint32_t config) const {
    return ((bits_[config >> 6] >> (config & 63u)) & 1u) != 0;
  }
  const AdjacencyPair& pair() const { return pair_; }

  /// Builds a table (what of() does once per pair); threads = 0: all cores.
  explicit SimplePointTable(const AdjacencyPair& pair, unsigned threads = 0);

private:
  AdjacencyPair pair_;
  std::vector<std::uint64_t> bits_;
};

/// Is the point of linear index i simple for the object of the image (it must be in the
/// object: InvalidArgument otherwise)? One query: the table in 2D, the definition in 3D.
bool is_simple_point(const Image<std::uint8_t>& image, std::int64_t i, const AdjacencyPair& pair);

} // namespace zdg
