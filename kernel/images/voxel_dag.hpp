// Sparse voxel octrees and DAGs of binary volumes, with exact ray queries.
//
// The scene: the voxels (x, y, z), 0 <= x < nx, 0 <= y < ny, 0 <= z < nz, set or not, in the
// cube [0, S)^3 with S = 2^depth the least power of two >= max(nx, ny, nz, 4); voxels of the
// cube outside the extent are empty. The octree: level 0 is a voxel, level l a cube of 2^l a
// side, the root level `depth`; a node at level l >= 3 has a child mask (8 bits, slot
// s = x + 2 y + 4 z of its sub-cubes) and a reference per non-empty child; a leaf is a level-2
// cube of 4^3 voxels as a 64-bit mask (bit x + 4 y + 16 z). Empty cubes have no node.
//   svo     the tree: every non-empty cube its own node.
//   dag     identical subtrees stored once (Kampe, Sintorn, Assarsson, "High resolution sparse
//           voxel DAGs", ACM TOG 32(4), 2013): bottom-up hashing of each level's nodes.
//   ssvdag  subtrees equal up to a reflection stored once (Villanueva, Marton, Gobbetti,
//           "SSVDAGs: symmetry-aware sparse voxel DAGs", I3D 2016): each reference carries 3
//           bits m (reflect x, y, z within the cube), the canonical form is the least of the 8
//           reflections (a reference's bits taken modulo the symmetries of the subtree it
//           names, so that the form is canonical), and a traversal composes the bits (xor) on
//           the way down. (Their
//           cross-level leaf merging and variable-width pointers are not done: nodes and
//           pointers are counted in the encoding below.)
// Encoding (the byte counts of stats()): a node is a 32-bit header (the mask) and one 32-bit
// reference per child (29 bits of index, 3 of reflection); a leaf is 64 bits. The tree's own
// figures (svo_*) are counted during any build: a node header and a pointer per non-root node.
//
// Building, bottom-up by slabs (VoxelDagBuilder): z-slices arrive in order and are folded into
// 4-deep layers of leaves, then two layers of level l into one of level l + 1 (a binary
// counter), so that only one layer per level is held: O(S^2 / 16) references plus the nodes.
// A scene of 2048^3 never exists as a dense array (the voxelizer streams its slabs). Cost:
// O(nx ny nz / 8) byte tests (8 voxels a word) plus O(1) expected hashing per tree node.
//
// Queries, exact: contains(v) in O(depth); ray_hits(ray) the set voxels of the digital ray
// (kernel/images/digital_ray.hpp: the voxels the line crosses over a positive length, in its
// order) in the box of the extent, each with the axis of the face the line enters it by. The
// traversal cuts the chord (t_in, t_out) of each node at the parameters of its three
// mid-planes (Revelles, Urena, Lastra, "An efficient parametric algorithm for octree
// traversal", WSCG 2000), compared exactly as fractions of 128-bit integers, and descends only
// into non-empty children: O(depth + visited nodes) per hit; first_hit stops at the first.
//
// Errors (InvalidArgument): a non-3D volume, an extent outside [1, 2^20], slices past nz, a
// node store past 2^29 references (about 2 GiB); the ray's bounds as in digital_ray.hpp.
#pragma once

#include <zdg/kernel/images/digital_ray.hpp>
#include <zdg/kernel/images/image.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace zdg {

enum class VoxelDagKind { svo, dag, ssvdag };

/// "svo", "dag", "ssvdag".
std::string voxel_dag_kind_name(VoxelDagKind kind);
/// The kind of a name above (InvalidArgument listing them otherwise).
VoxelDagKind parse_voxel_dag_kind(const std::string& text);

struct VoxelDagStats {
  VoxelDagKind kind = VoxelDagKind::dag;
  int depth = 2;
  std::int64_t voxels = 0;      ///< set voxels
  std::int64_t inner_nodes = 0; ///< stored nodes of levels >= 3
  std::int64_t leaves = 0;      ///< stored 4^3 leaves
  std::int64_t pointers = 0;    ///< stored child references
  std::int64_t bytes = 0;       ///< 4 (inner_nodes + pointers) + 8 leaves
  std::int64_t svo_inner_nodes = 0, svo_leaves = 0, svo_pointers = 0, svo_bytes = 0; ///< the tree's
  std::vector<std::int64_t> nodes_per_level; ///< stored nodes of levels depth, depth - 1, ..., 2
  /// 8 bytes / voxels (0 for an empty scene).
  double bits_per_voxel() const;
};

struct DagRayHit {
  std::array<std::int64_t, 3> voxel{};
  int axis = 0; ///< the axis of the face the line enters the voxel by
  friend bool operator==(const DagRayHit&, const DagRayHit&) = default;
};

class VoxelDag {
public:
  VoxelDag() = default;
  const std::array<std::int64_t, 3>& extent() const { return extent_; }
  int depth() const { return depth_; }
  std::int64_t side() const { return std::int64_t{1} << depth_; }
  VoxelDagKind kind() const { return kind_; }
  /// Whether voxel v (x, y, z) is set (false outside the extent).
  bool contains(const std::array<std::int64_t, 3>& v) const;
  /// The set voxels the ray crosses, in its order, at most max_hits of them.
  std::vector<DagRayHit>
  ray_hits(const DigitalRay& ray,
           std::size_t max_hits = std::numeric_limits<std::size_t>::max()) const;
  /// The first of them.
  std::optional<DagRayHit> first_hit(const DigitalRay& ray) const;
  VoxelDagStats stats() const;
  /// The scene as a volume of domain {nz, ny, nx} (1 where set).
  Image<std::uint8_t> to_image() const;

private:
  friend class VoxelDagBuilder;
  std::array<std::int64_t, 3> extent_{1, 1, 1};
  int depth_ = 2;
  VoxelDagKind kind_ = VoxelDagKind::dag;
  std::uint32_t root_ = 0xFFFFFFFFu;    ///< reference (index << 3 | reflection); all ones: empty
  std::vector<std::uint32_t> words_;    ///< nodes: header, then references
  std::vector<std::uint64_t> leaves_;   ///< 4^3 masks
  std::vector<std::int64_t> per_level_; ///< stored nodes, levels depth .. 2
  std::int64_t voxels_ = 0, svo_inner_ = 0, svo_leaves_ = 0;
};

/// Streams z-slices into a VoxelDag (see above).
class VoxelDagBuilder {
public:
  /// extent (nx, ny, nz).
  VoxelDagBuilder(const std::array<std::int64_t, 3>& extent, VoxelDagKind kind);
  ~VoxelDagBuilder();
  VoxelDagBuilder(const VoxelDagBuilder&) = delete;
  VoxelDagBuilder& operator=(const VoxelDagBuilder&) = delete;
  /// The next `slices` z-slices, nx * ny * slices bytes in [z][y][x] order (nonzero: set).
  void add_slices(const std::uint8_t* data, std::int64_t slices);
  /// The DAG (the slices not given are empty).
  VoxelDag finish();

private:
  struct State;
  std::unique_ptr<State> s_;
};

/// The DAG of a 3D volume (axes z, y, x: extent (nx, ny, nz); its lower bounds are not used).
VoxelDag build_voxel_dag(const Image<std::uint8_t>& volume, VoxelDagKind kind);

} // namespace zdg
