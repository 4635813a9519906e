// Adjacencies and adjacency pairs of digital topology in Z^2 and Z^3.
//
// p, q are k-adjacent when |p - q|_inf = 1 and |p - q|_1 <= m(k). A pair (k, kbar) gives the
// object (nonzero points) k and the background (zeros, and outside the domain) kbar; the
// admissible pairs (8,4), (4,8), (26,6), (6,26), (18,6), (6,18) have a polyhedral continuous
// analog (Kong and Rosenfeld, CVGIP 48, 1989, sec. 5; kernel/topology/betti_numbers.hpp).
// All O(1) (neighbour_offsets: O(3^d)); no integer width concerns.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace zdg {

/// An adjacency pair (object k, background kbar) in dimension 2 or 3.
struct AdjacencyPair {
  int dim = 3;
  int object = 26;
  int background = 6;

  /// The pair seen from the background: (kbar, k). The complement of an admissible pair is
  /// admissible.
  AdjacencyPair complement() const { return {dim, background, object}; }
  /// "26,6".
  std::string name() const { return std::to_string(object) + "," + std::to_string(background); }
  friend bool operator==(const AdjacencyPair&, const AdjacencyPair&) = default;
};

/// True for k = 4, 8 (dim 2) and k = 6, 18, 26 (dim 3).
bool is_adjacency(int dim, int k);

/// m(k): the largest l1 norm of a k-neighbour offset (4, 6: 1; 8, 18: 2; 26: 3).
/// InvalidArgument when k is not an adjacency of dimension dim.
int adjacency_max_l1(int dim, int k);

/// True when (object, background) is one of the admissible pairs listed above.
bool is_adjacency_pair(int dim, int object, int background);

/// The admissible pair; InvalidArgument naming the pair otherwise.
AdjacencyPair make_adjacency_pair(int dim, int object, int background);

/// The default pair: (8,4) in 2D, (26,6) in 3D (the object gets the larger adjacency).
AdjacencyPair default_adjacency_pair(int dim);

/// Parses "K,KBAR" (spaces allowed around the numbers, e.g. "26,6", "6, 26") into an
/// admissible pair of dimension dim; InvalidArgument with the text otherwise.
AdjacencyPair parse_adjacency_pair(const std::string& text, int dim);

/// The k-neighbour offsets of the origin (axis order of the image: entry 0 is axis 0), in
/// lexicographic order; in 2D the third entry is 0. 4, 8, 6, 18 or 26 offsets.
std::vector<std::array<int, 3>> neighbour_offsets(int dim, int k);

} // namespace zdg
