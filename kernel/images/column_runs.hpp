// The runs of a digital set along z, column by column: for every column (x, y) of a region,
// the maximal intervals [b, e] of z such that (x, y, z) is in X for b <= z <= e, clipped to
// the region's z-range. A digital ball is a union of such column segments, so the count and
// the moments of X in a ball follow from these runs in O(1) per column of the ball
// (estimators/ii_3d.hpp), without touching the voxels.
//
// Layout: run k of every column is stored in layer k (two int32 arrays, begin and end,
// relative to region.lo.z, x fastest then y); a column with fewer runs holds the empty run
// (kEmptyBegin, kEmptyEnd) there. layers() is the largest number of runs of a column.
// covering(k, y, x0, x1) says in O(1) whether some column of row y with x0 <= x <= x1 has
// more than k runs (prefix counts per row), and deeper_range gives the first and the last
// such column (their ranks in the list of such columns), so a consumer reads layer k only
// there.
//
// Which voxels are evaluated: every voxel of region, or, when a `needed` mask of
// blocks is given, only the voxels of the needed blocks (blocks of kBlock^3 voxels aligned
// on region.lo). A run then is exact inside the needed blocks; across a stretch of unneeded
// blocks the status of the last evaluated voxel is continued, so a consumer must read a
// column only over needed z (the balls of estimators/ii_3d.cpp mark the blocks they cover).
// Voxels outside `box` are outside X (never evaluated).
//
// Cost: one predicate evaluation per evaluated voxel (threads share the columns, rows of y
// handed out dynamically); memory 8 bytes per column and layer plus 4 per column and
// layer > 0 for the prefix counts and the lists of deeper columns. Requirements: region non-empty
// with fewer than 2^28 voxels along z and 2^31 columns; coordinates within kMaxVoxelCoordinate; the
// predicate callable from several threads at once. InvalidArgument otherwise.
#pragma once

#include <zdg/kernel/surfaces/digital_surface.hpp>

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace zdg {

struct ColumnRuns {
  static constexpr std::int32_t kEmptyBegin = 0x3fffffff;
  static constexpr std::int32_t kEmptyEnd = -0x3fffffff;
  static constexpr std::int64_t kBlock = 16;

  VoxelBox region;
  std::int64_t nx = 0, ny = 0, nz = 0;
  std::vector<std::vector<std::int32_t>> begin, end; ///< [layer][column]
  /// [layer - 1][y * (nx + 1) + x + 1]: columns x' <= x of row y with more than `layer` runs.
  std::vector<std::vector<std::int32_t>> deeper;
  /// [layer - 1]: the x (relative to region.lo.x) of the columns with more than `layer` runs,
  /// row after row; deeper_start[layer - 1][y] is the index of row y's first one.
  std::vector<std::vector<std::int32_t>> deeper_x;
  std::vector<std::vector<std::int64_t>> deeper_start;
  std::size_t evaluations = 0; ///< predicate evaluations made to build the runs

  int layers() const { return int(begin.size()); }
  /// Index of column (x, y) of the region (absolute coordinates).
  std::size_t column(std::int64_t x, std::int64_t y) const {
    return std::size_t((y - region.lo.y) * nx + (x - region.lo.x));
  }
  /// Whether a column of row y (absolute) with x0 <= x <= x1 (absolute, inside the region)
  /// has more than `layer` runs (layer >= 1).
  bool covering(int layer, std::int64_t y, std::int64_t x0, std::int64_t x1) const {
    const auto& d = deeper[std::size_t(layer - 1)];
    const std::size_t row = std::size_t(y - region.lo.y) * std::size_t(nx + 1);
    return d[row + std::size_t(x1 - region.lo.x + 1)] != d[row + std::size_t(x0 - region.lo.x)];
  }
  /// The first and the last x in [x0, x1] (absolute, inside the region) of row y whose
  /// column has more than `layer` runs (layer >= 1); first > last when there is none.
  /// O(1): the prefix counts give the ranks of the first and the last one in deeper_x.
  std::pair<std::int64_t, std::int64_t> deeper_range(int layer, std::int64_t y, std::int64_t x0,
                                                     std::int64_t x1) const;
  /// The runs of column (x, y) in absolute z (for tests and diagnostics).
  std::vector<std::pair<std::int64_t, std::int64_t>> runs(std::int64_t x, std::int64_t y) const;
};

/// Blocks of ColumnRuns::kBlock^3 voxels of a region (aligned on region.lo), x fastest.
struct BlockMask {
  std::int64_t bx = 0, by = 0, bz = 0;
  std::vector<std::uint8_t> needed;
  bool at(std::int64_t i, std::int64_t j, std::int64_t k) const {
    return needed[std::size_t((k * by + j) * bx + i)] != 0;
  }
};

/// The runs of { z in box : inside(z) } over the columns of region, evaluating the voxels of
/// region (or of the needed blocks only, when `needed` is given). threads: 0 = hardware.
ColumnRuns column_runs(const VoxelPredicate& inside, const VoxelBox& box, const VoxelBox& region,
                       unsigned threads = 1, const BlockMask* needed = nullptr);

} // namespace zdg
