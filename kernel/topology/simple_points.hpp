// Simple points of binary images of Z^2 and Z^3 under an adjacency pair (k, kbar)
// (kernel/topology/adjacency.hpp): the definition-level test and the look-up tables built from it.
//
// x in X is simple when the analog of X \ {x} is a deformation retract of that of X (Kong and
// Rosenfeld, CVGIP 48, 1989, sec. 7): every Betti number of object and background is kept.
// 3D: T_k(x, X) = T_kbar(x, complement of X) = 1, topological numbers on geodesic
// neighbourhoods (Bertrand and Malandain, PRL 15, 1994; 6 is "6+" with 18); 2D: Rosenfeld's
// numbers (JACM 17, 1970). O(1) per configuration (bit-parallel flood fill). Bit j of a
// configuration is the neighbour at p = sum_k (d_k + 1) 3^(d - 1 - k), j = p below the centre,
// p - 1 above; outside the image is background. SimplePointTable::of(pair): one bit per
// configuration (8 MiB in 3D), built once per pair on first use, thread-safe; tests check every
// entry (definitions: docs/NOTES.md, "kernel/topology/simple_points.hpp").
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

/// The simple points of the object (value != 0) of a 2D or 3D image under the pair: 1 on
/// them, 0 elsewhere, each tested on its own 3^d neighbourhood by the definition (the object is
/// not changed between tests; zdg topology simple). O(N 3^d); their number in `count` when
/// given.
Image<std::uint8_t> simple_point_mask(const Image<std::uint8_t>& image, const AdjacencyPair& pair,
                                      std::int64_t* count = nullptr);

} // namespace zdg
