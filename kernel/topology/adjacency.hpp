// Adjacencies and adjacency pairs of digital topology in Z^2 and Z^3.
//
// Two distinct points p, q of Z^d are k-adjacent when |p - q|_inf = 1 and |p - q|_1 <= m(k):
//   2D: k = 4 (m = 1, edge neighbours), k = 8 (m = 2, all eight);
//   3D: k = 6 (m = 1, face neighbours), k = 18 (m = 2, face and edge), k = 26 (m = 3, all).
// A k-path is a sequence of points, each k-adjacent to the next; a k-component of a set is a
// maximal k-path-connected subset.
//
// An adjacency pair (k, kbar) gives the object of a binary image (the points of nonzero value)
// the k-adjacency and the background (the points of value 0, and every point outside the
// image's domain) the kbar-adjacency. zdg accepts the pairs for which the object has a
// polyhedral "continuous analog" whose complement is an analog of the background, so that
// the Jordan theorem, Euler characteristic, Betti numbers and simple points behave as in R^d
// (Kong and Rosenfeld, "Digital topology: introduction and survey", CVGIP 48, 1989, sec. 5;
// Kong and Roscoe, "Continuous analogs of axiomatized digital surfaces", CVGIP 29, 1985):
//   2D: (8,4), (4,8);   3D: (26,6), (6,26), (18,6), (6,18).
// kernel/topology/betti_numbers.hpp says which cell complex stands for the object under each pair.
//
// Everything here is O(1) (neighbour_offsets: O(3^d)); no integer width concerns.
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
