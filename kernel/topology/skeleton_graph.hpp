// The graph of a curve skeleton: nodes (junctions, ends, loops) and the branches between them,
// with their lengths and radius profiles (the pore or strut network of a foam; skan's
// "skeleton analysis", Nunez-Iglesias et al., PeerJ 6, 2018, does the same on pixel graphs).
//
// Input: a thin set S of a 2D or 3D image (a curve skeleton, e.g. zdg topology skeleton), its
// points joined by 8-adjacency (2D) or 26-adjacency (3D), the object adjacencies of the default
// pairs (8,4) and (26,6). A point of S is regular when it has exactly two neighbours in S and
// these two are not neighbours of each other; the other points are node points (ends: one
// neighbour; junctions: three or more; the corners of the small triangles that 26-adjacency makes
// at staircases and crossings). Nodes are the connected components of the node points; branches
// are the connected components of the regular points, each a path whose two ends touch nodes
// (possibly the same node) or a cycle touching no node (a closed curve: its first point in C
// order becomes a node of kind "loop" and the rest its branch, from that node to itself).
// A branch's length is the Euclidean length of the polygonal line through its points, the
// steps to its nodes included (sqrt 1, 2 or 3 per step; > 0 for every branch); its radius
// profile the values of a squared-radius image (e.g. the squared distance transform of the
// object) along it, in order.
//
// Loops: b1 of S, as E - V + C + sum over the nodes of b1(node) (E branches, V nodes, C
// connected components; b1(node) the cycles inside a node's points, 0 on a thin skeleton, but
// not on the 2 x 2 x 2 blocks and small rings that critical kernels and junctions keep). Why:
// the union of the closed unit cubes (squares) centred on S is homotopy equivalent to the
// clique complex of the adjacency graph (nerve theorem: axis-parallel boxes that meet pairwise
// share a point); every triangle of that graph lies inside a node, so the complex is the nodes'
// complexes joined by arcs, and each arc either merges two components or adds one cycle.
// b1 is that of kernel/topology/betti_numbers.hpp under the pair (26,6) or (8,4) (tests check
// it on thinned shapes). Cost: O(N) to scan the image, O(|S| 3^d log |S|) for the graph, and
// the Betti numbers of each node of 4 points or more on its bounding box.
// Errors: InvalidArgument for an image of another dimension than 2 or 3, or a radius image of
// another domain.
#pragma once

#include <zdg/kernel/images/image.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace zdg {

enum class SkeletonNodeKind { junction, end, joint, isolated, loop };

/// "junction" (3 or more branch ends), "end" (1), "joint" (2), "isolated" (0), "loop".
std::string skeleton_node_kind_name(SkeletonNodeKind kind);

struct SkeletonNode {
  SkeletonNodeKind kind = SkeletonNodeKind::isolated;
  /// The node's points (linear indices, increasing).
  std::vector<std::int64_t> points;
  /// Branch ends at the node (a branch from the node to itself counts twice).
  int degree = 0;
  /// b1 of the node's points (cycles inside the node).
  std::int64_t loops = 0;
};

struct SkeletonBranch {
  /// The nodes at its two ends (equal for a loop through one node).
  std::int64_t from = 0, to = 0;
  /// Its regular points in order along it, from `from` to `to` (linear indices).
  std::vector<std::int64_t> points;
  /// Euclidean length of the polygonal line from the node point at `from` through `points` to
  /// the node point at `to`.
  double length = 0;
  /// The squared-radius image's values at `points` (empty when none was given).
  std::vector<std::int64_t> squared_radii;
};

struct SkeletonGraph {
  std::vector<SkeletonNode> nodes;
  std::vector<SkeletonBranch> branches;
  std::int64_t components = 0; ///< C: connected components of the graph (= of S)
  std::int64_t loops = 0;      ///< b1 of S: E - V + C + the nodes' own loops
};

/// The graph of the nonzero points of `skeleton`. squared_radius (optional, same domain): the
/// values reported along the branches.
SkeletonGraph skeleton_graph(const Image<std::uint8_t>& skeleton,
                             const Image<std::int64_t>* squared_radius = nullptr);

} // namespace zdg
