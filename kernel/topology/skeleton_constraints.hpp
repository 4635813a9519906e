// What a homotopic thinning keeps besides topology: the kinds of skeleton, their local
// conditions, and the options and result shared by the sequential
// (kernel/topology/homotopic_thinning.hpp) and the parallel
// (kernel/topology/critical_kernel_thinning.hpp) thinnings of binary images of Z^2 and Z^3.
//
// A thinning deletes simple points (kernel/topology/simple_points.hpp) only, so the result is a
// subset of the object with the same topology (every Betti number of object and background kept).
// Points are never deleted when they are anchors (a user mask, or the centres of the reduced
// discrete medial axis, kernel/transforms/reduced_medial_axis.hpp) or when they satisfy the
// condition of the skeleton kind at the moment they are examined (they then stay anchored):
//   ultimate     no condition: the result is a homotopy kernel (no simple point is left);
//   curve        end points: points with exactly one object point among their 3^d - 1
//                neighbours (curve extremities; Pudney, "Distance-ordered homotopic
//                thinning", CVIU 72, 1998); counting all neighbours, not only the
//                k-neighbours, keeps a 6-object from growing hairs on its staircases;
//   surface      isthmuses: points where the object is locally a curve or a surface,
//                T_k(x, X) >= 2 or T_kbar(x, complement) >= 2 (1- and 2-isthmuses of
//                Bertrand and Couprie, "Isthmus based parallel and symmetric 3D thinning
//                algorithms", Graphical Models 80, 2015; DGtal's volSkeleton "isthmus").
//                Isthmus persistence: a point found to be an isthmus stays, even if it is no
//                longer one later, so thinning the result again may still delete points at
//                the rims (in 2D this keeps curves: there the isthmuses are curve points);
//   medial-axis  the reduced medial axis (l2, Coeurjolly and Montanvert 2007) as anchors,
//                then ultimate thinning: the union of the medial balls centred on the
//                result is the object (DGtal's volSkeleton does this).
// Points outside the domain are background: the thinnings work on a copy padded with one
// layer of background (detail::PaddedVolume below), and a 2D image is the one-layer slab of
// 3D, where (8,4) and (4,8) are (26,6) and (6,26) restricted to the plane.
#pragma once

#include <zdg/kernel/images/image.hpp>
#include <zdg/kernel/topology/adjacency.hpp>

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace zdg {

enum class SkeletonKind { ultimate, curve, surface, medial_axis };

/// "ultimate", "curve", "surface", "medial-axis"; InvalidArgument otherwise.
SkeletonKind parse_skeleton_kind(const std::string& text);
std::string skeleton_kind_name(SkeletonKind kind);

/// Reported during a thinning (every pass of the parallel one, every few hundred thousand
/// deletions of the sequential one, and at the end).
struct ThinningProgress {
  std::int64_t remaining = 0; ///< points of the object left
  std::int64_t deleted = 0;   ///< points deleted so far
  std::int64_t passes = 0;    ///< parallel passes (sequential: 1)
};

struct ThinningOptions {
  /// The adjacency pair; dim 0 (default) picks the default pair of the image's dimension.
  AdjacencyPair pair{0, 0, 0};
  SkeletonKind skeleton = SkeletonKind::ultimate;
  /// Points never deleted (nonzero), on the image's domain; not owned, may be null.
  const Image<std::uint8_t>* anchors = nullptr;
  /// Sequential thinning only: the order of deletion (smaller first, ties by index); null:
  /// the exact squared Euclidean distance to the background (so the result is centred).
  /// Same domain as the image; not owned.
  const Image<std::int64_t>* priority = nullptr;
  /// Worker threads (0: all cores); the result never depends on it.
  unsigned threads = 0;
  /// When set, receives the deleted points (linear indices in the image) in deletion order
  /// (the parallel thinning appends each pass's deletions in increasing index).
  std::vector<std::int64_t>* deletions = nullptr;
  std::function<void(const ThinningProgress&)> progress;
};

struct ThinningResult {
  /// The thinned object: 1 on kept points, 0 elsewhere (same domain).
  Image<std::uint8_t> skeleton;
  std::int64_t deleted = 0;
  std::int64_t passes = 0;
};

namespace detail {

/// The image padded with one layer of background, as flags per point (bit 0: object; the
/// thinnings use the other bits), with the linear offsets of the 26 (2D: 8) neighbours.
/// A 2D image is stored as a slab with one layer (n0 = 1).
class PaddedVolume {
public:
  explicit PaddedVolume(const Image<std::uint8_t>& image);

  int dim() const { return dim_; }
  std::int64_t size() const { return static_cast<std::int64_t>(flags.size()); }
  /// Padded index of the image point of linear index i, and back.
  std::int64_t padded_index(std::int64_t i) const;
  std::int64_t image_index(std::int64_t p) const;
  /// The configuration of the neighbours of p (kernel/topology/simple_points.hpp layout: 26 bits in
  /// 3D, 8 in 2D).
  std::uint32_t configuration(std::int64_t p) const {
    std::uint32_t c = 0;
    for (int j = 0; j < neighbours_; ++j) {
      c |= static_cast<std::uint32_t>(
               flags[static_cast<std::size_t>(p + offset[static_cast<std::size_t>(j)])] & 1u)
           << j;
    }
    return c;
  }
  /// The object as an image of the original domain (1 = object).
  Image<std::uint8_t> object(const Domain& domain) const;

  std::vector<std::uint8_t> flags;
  /// Offsets of the neighbours in configuration-bit order (26 or 8 entries used).
  std::array<std::int64_t, 26> offset{};
  /// Extents of the padded box (n0 + 2, n1 + 2, n2 + 2; 2D: 3, n0 + 2, n1 + 2).
  std::array<std::int64_t, 3> extent{};

private:
  int dim_ = 3;
  int neighbours_ = 26;
};

/// The skeleton condition of `kind` (curve: end point; surface: isthmus) for a point of the
/// object whose neighbours are `config`; false for ultimate and medial-axis.
bool is_skeleton_point(SkeletonKind kind, const AdjacencyPair& pair, std::uint32_t config);

/// Simplicity of a configuration by the pair's table (2D, or 3D when `use_table`) or by the
/// definition.
class SimplicityTest {
public:
  SimplicityTest(const AdjacencyPair& pair, bool use_table);
  bool operator()(std::uint32_t config) const;

private:
  AdjacencyPair pair_;
  const class SimplePointTable* table_ = nullptr;
};

/// The pair of the options, checked against the image; the anchors (user anchors and, for
/// medial-axis, the reduced medial axis) as padded-index flags set in bit 2 of `volume`.
AdjacencyPair resolve_pair(const Image<std::uint8_t>& image, const ThinningOptions& options);
void mark_anchors(const Image<std::uint8_t>& image, const ThinningOptions& options,
                  PaddedVolume& volume);

} // namespace detail

} // namespace zdg
