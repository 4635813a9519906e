// Representative cycles of the homology over Z/2 of the object of a binary image of Z^2 or Z^3,
// as the cubical complex of the union of its closed pixels / voxels (the (8,4) / (26,6) analog
// of kernel/topology/betti_numbers.hpp; Kaczynski, Mischaikow, Mrozek, "Computational
// Homology", Springer 2004, ch. 2 and 3).
//
// Cells are in Khalimsky coordinates (2 p_k + 1 on the open extent of the voxel p along axis k,
// the even values on its boundary; the image's lower bounds are not added). For each k = 0 ..
// d-1, generators[k] holds b_k chains of k-cells (lists of cells, each once): each is a cycle
// (its boundary is zero mod 2) and their classes form a basis of H_k (none is a boundary, nor
// is any sum of them).
//
// Algorithm: the standard reduction of the boundary matrix over Z/2 with the reduction matrix V
// kept (Edelsbrunner, Letscher, Zomorodian 2002; Zomorodian, Carlsson 2005), the cells in the
// order (dimension, index), with clearing (Chen, Kerber 2011); a k-cell j whose column reduces
// to zero and that is no pivot is essential, and the chain V_j is its generator. Complexity:
// cubic in the number of cells in the worst case (the columns of R and the chains of V can
// grow; on images both stay short); memory: the chains of V kept for every negative cell.
// Width: cell indices in int64; the image's point count must fit int64 (Domain checks it).
// Errors: InvalidArgument for a dimension other than 2 or 3.
#pragma once

#include <zdg/kernel/images/image.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace zdg {

struct HomologyGenerators {
  int dim = 3;
  /// generators[k][g]: the k-cells of the g-th cycle of dimension k, each a point of
  /// Khalimsky coordinates (d of them; the third is 0 in 2D).
  std::vector<std::vector<std::vector<std::array<std::int64_t, 3>>>> generators;
};

/// Generators of H_0 .. H_{d-1} of the union of the closed voxels of the object (nonzero).
HomologyGenerators homology_generators(const Image<std::uint8_t>& image);

} // namespace zdg
