// Persistent homology of the sublevel filtration of a 2D or 3D cubical complex whose
// top-dimensional cells are the pixels / voxels of an image, in GUDHI's convention for
// `CubicalComplex(top_dimensional_cells=...)`: the complex is the closed box of the image, cut
// into unit squares / cubes (in Khalimsky coordinates, shape 2 n_k + 1), a pixel / voxel gets its
// value and every lower-dimensional cell the minimum of the values of its top-dimensional cofaces
// (it enters with its first coface). The sublevel set at t is the union of the closed voxels of
// value <= t (the (8,4) / (26,6) analog of kernel/topology/betti_numbers.hpp), and the diagram
// in dimension k is the multiset of pairs (birth, death) of its k-homology classes over Z/2
// (equal to GUDHI's Z/11 result: a cubical complex of R^3 has no torsion), zero-length pairs
// dropped, death = +infinity for an essential class. The box is contractible: the one essential
// class is the component born at the minimum value, and dimension d has no pair.
//
// Algorithm (Kaczynski, Mischaikow, Mrozek, "Computational Homology", Springer 2004, for the
// cubical complex and its boundary; Edelsbrunner, Letscher, Zomorodian 2002 for the pairing).
// The cells are totally ordered by (entering voxel's rank, dimension, Khalimsky index), the voxels
// ranked by (value, linear index): a filtration compatible with the values, so the diagram (of
// values) is the one of any other tie-break. A 2D image is the slab of one voxel's thickness
// over it (the same homotopy type at each level, the same diagram).
//   dimension 0: union-find on the vertices over the edges in filtration order (elder rule);
//   dimension d-1 (2 in 3D, 1 in 2D): Alexander duality, union-find on the voxels plus the
//     outside over the (d-1)-cells in reverse filtration order (Kaji, Sudo, Ahara, "Cubical
//     Ripser: software for computing persistent homology of image and volume data",
//     arXiv:2005.12692, 2020);
//   dimension 1 in 3D: column reduction of the boundary matrix of the 2-cells that duality
//     left unpaired (clearing: Chen, Kerber, "Persistence algorithm with twist", EuroCG
//     2011), rows restricted to the edges not paired in dimension 0 (compression: Bauer,
//     Kerber, Reininghaus, "Clear and compress: computing persistent homology in chunks",
//     2014); a column whose pivot is free is an apparent pair and is not stored.
// Complexity: O(N log N) for the ranking (N voxels) and for the union-finds (path halving,
// linking by age), O(N) columns of at most four entries plus their reductions (cubic in the
// worst case, near linear on images); memory about 60 N bytes. Width: cell indices in int64;
// N < 2^32 voxels and a cell count times N below 2^64 (InvalidArgument beyond).
// Errors: InvalidArgument for a dimension other than 2 or 3 or a value that is not finite (NaN,
// +-infinity: an infinite death would read as an essential class).
#pragma once

#include <zdg/kernel/images/image.hpp>

#include <cstdint>
#include <limits>
#include <vector>

namespace zdg {

struct PersistencePair {
  double birth = 0;
  /// +infinity for an essential class.
  double death = std::numeric_limits<double>::infinity();
  friend bool operator==(const PersistencePair&, const PersistencePair&) = default;
};

struct PersistenceDiagrams {
  /// diagrams[k]: the pairs of dimension k = 0 .. d-1, sorted by (birth, death).
  std::vector<std::vector<PersistencePair>> diagrams;
};

/// The diagrams of the sublevel filtration of `values` (2D or 3D), as above.
PersistenceDiagrams cubical_persistence(const Image<double>& values);

/// The filtration `--filtration dt` of a binary image (nonzero = object): the signed squared
/// Euclidean distance, -DT(object) on the object (minus the squared distance to the nearest
/// background point) and +DT(background) on the background (the squared distance to the
/// nearest object point), exact integers (kernel/transforms/distance_transform.hpp). Its
/// sublevel sets grow from the object's deepest points to the object (at -1) and then into the
/// background: dimension 0 sees the object's grains, the top dimension its pores. The mask must
/// hold object and background (InvalidArgument otherwise). 64-bit squared distances; they are
/// below 2^53 for every volume that fits memory, so the double values are exact (checked).
Image<double> signed_squared_distance(const Image<std::uint8_t>& mask, unsigned threads = 0);

} // namespace zdg
