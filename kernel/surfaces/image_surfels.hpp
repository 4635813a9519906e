// The boundary surfels of a binary image of Z^3, all of them, as sorted 64-bit codes.
//
// The object is X = { voxels of nonzero value } of a 3D Image<uint8_t> (axes (z, y, x) in C
// order, x contiguous; voxel (i, j, k) of index (k ny + j) nx + i stands for the point
// lower + (i, j, k) of Z^3). Voxels outside the domain are outside X, so the boundary is
// closed. A boundary surfel is a pair (inner voxel v in X, 6-neighbour v + s e_a not in X);
// their number is the number of such (inside, outside) pairs.
//
// Code of a surfel: 8 (linear index of its inner voxel) + d, with the direction
// d = 2 a + (1 if the outer voxel is at +e_a, else 0), a = 0 (x), 1 (y), 2 (z). Sorted codes
// list the surfels voxel after voxel in the image's order. The surfel of code c is the
// oriented Khalimsky surfel of kernel/surfaces/cubical_cells.hpp (direct iff its outer voxel is at
// +e_a), in the coordinates of Z^3 (lower bounds included).
//
// Row index: row_start[r] is the position of the first surfel whose inner voxel lies in the
// row r = k ny + j (row_start has ny nz + 1 entries), so finding a code is a binary search
// among the few surfels of one row.
//
// Algorithm: two passes over the rows, split into contiguous chunks over the workers
// (parallel_chunks): count the surfels of each row, prefix sums, then write them in place.
// O(N) time for N voxels, memory 8 bytes per surfel plus 8 per row; the result does not
// depend on the number of threads.
//
// Width: the domain has at most 2^60 voxels (checked: InvalidArgument past it), so codes fit
// 64 bits; voxel coordinates are those of the Domain (int64, and at most 2^40 in absolute
// value for the Khalimsky conversions: checked when the surfels are built).
#pragma once

#include <zdg/kernel/images/image.hpp>
#include <zdg/kernel/surfaces/cubical_cells.hpp>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace zdg {

/// The code of the surfel between the inner voxel of linear index v and its neighbour along
/// axis a (0 x, 1 y, 2 z) on the positive (outer voxel at +e_a) or negative side.
constexpr std::uint64_t surfel_code(std::int64_t v, int axis, bool positive) {
  return (static_cast<std::uint64_t>(v) << 3) |
         static_cast<std::uint64_t>(2 * axis + (positive ? 1 : 0));
}
constexpr std::int64_t code_voxel(std::uint64_t code) {
  return static_cast<std::int64_t>(code >> 3);
}
constexpr int code_axis(std::uint64_t code) {
  return static_cast<int>((code & 7) >> 1);
}
constexpr bool code_positive(std::uint64_t code) {
  return (code & 1) != 0;
}

/// The sizes of a 3D binary image seen as a voxel grid: nx (contiguous), ny, nz, and the point
/// of Z^3 of voxel (0, 0, 0).
struct VoxelGrid {
  std::int64_t nx = 0, ny = 0, nz = 0;
  Voxel lower{0, 0, 0};

  /// The grid of a 3D image; InvalidArgument for another dimension, for more than 2^60 voxels,
  /// or coordinates beyond 2^40 in absolute value (the Khalimsky range).
  static VoxelGrid of(const Domain& domain);
  std::int64_t size() const { return nx * ny * nz; }
  std::int64_t rows() const { return ny * nz; }
  std::int64_t index(std::int64_t i, std::int64_t j, std::int64_t k) const {
    return (k * ny + j) * nx + i;
  }
  /// The voxel box of the grid in Z^3 coordinates.
  VoxelBox box() const { return {lower, {lower.x + nx - 1, lower.y + ny - 1, lower.z + nz - 1}}; }
  /// The point of Z^3 of the voxel of linear index v.
  Voxel voxel(std::int64_t v) const {
    return {lower.x + v % nx, lower.y + (v / nx) % ny, lower.z + v / (nx * ny)};
  }
};

/// Where a voxel grid sits in physical space: the centre of voxel (i, j, k) (indices from 0)
/// is origin + (sx i, sy j, sz k). The default puts the voxels at their points of Z^3
/// (lattice(grid)); a file's voxel size and position give another.
struct VoxelPlacement {
  Point3<double> spacing{1, 1, 1};
  Point3<double> origin{0, 0, 0};

  static VoxelPlacement lattice(const VoxelGrid& g) {
    return {{1, 1, 1}, {double(g.lower.x), double(g.lower.y), double(g.lower.z)}};
  }
  /// The physical point of the grid point (i, j, k) (fractional indices allowed: the pointel
  /// of index q is at q - 1/2).
  Point3<double> at(double i, double j, double k) const {
    return {origin.x + spacing.x * i, origin.y + spacing.y * j, origin.z + spacing.z * k};
  }
};

/// All boundary surfels of a binary image, sorted by code, with the row index.
struct ImageSurfels {
  VoxelGrid grid;
  std::vector<std::uint64_t> codes;
  std::vector<std::int64_t> row_start; ///< grid.rows() + 1 entries

  std::int64_t size() const { return static_cast<std::int64_t>(codes.size()); }
  /// Position of the code in `codes`, or -1 when it is not a boundary surfel.
  std::int64_t find(std::uint64_t code) const;
  /// The same when the row of the code's inner voxel (k ny + j) is known (0 <= row < rows):
  /// a branch-free binary search among the surfels of that row.
  std::int64_t find_in_row(std::int64_t row, std::uint64_t code) const {
    const std::int64_t b = row_start[static_cast<std::size_t>(row)];
    std::int64_t len = row_start[static_cast<std::size_t>(row) + 1] - b;
    if (len == 0) return -1;
    const std::uint64_t* base = codes.data() + b;
    while (len > 1) {
      const std::int64_t half = len / 2;
      base += static_cast<std::int64_t>(base[half - 1] < code) * half; // no branch to mispredict
      len -= half;
    }
    return *base == code ? base - codes.data() : -1;
  }
  /// The Khalimsky surfel of code c (Z^3 coordinates, direct iff the outer voxel is at +e_a).
  Surfel surfel_of(std::uint64_t code) const;
  Surfel surfel(std::int64_t i) const { return surfel_of(codes[static_cast<std::size_t>(i)]); }
  /// The Khalimsky surfels of all the codes, in the same order.
  std::vector<Surfel> surfels(unsigned threads = 0) const;
};

/// Calls f(i, code, c) for the surfels of positions b <= i < e in order, c = {i, j, k} the grid
/// indices of the inner voxel (an std::int64_t[3]); the row index gives j and k, so there is
/// no division per surfel.
template <class F>
void for_each_surfel(const ImageSurfels& s, std::int64_t b, std::int64_t e, F&& f) {
  if (b >= e) return;
  const auto& rs = s.row_start;
  std::int64_t r = std::int64_t(std::upper_bound(rs.begin(), rs.end(), b) - rs.begin()) - 1;
  std::int64_t c[3] = {0, r % s.grid.ny, r / s.grid.ny};
  for (std::int64_t i = b; i < e; ++i) {
    while (rs[static_cast<std::size_t>(r) + 1] <= i) {
      ++r;
      if (++c[1] == s.grid.ny) {
        c[1] = 0;
        ++c[2];
      }
    }
    const std::uint64_t code = s.codes[static_cast<std::size_t>(i)];
    c[0] = code_voxel(code) - r * s.grid.nx;
    f(i, code, c);
  }
}

/// The boundary surfels of the nonzero voxels of a 3D image (threads: 0 = all cores).
/// InvalidArgument when the image is not 3D (see VoxelGrid::of).
ImageSurfels image_surfels(const Image<std::uint8_t>& image, unsigned threads = 0);

/// One interface of a labelled image: the surfels between a voxel of label a and a 6-neighbour
/// (4-neighbour in 2D) of label b, a < b.
struct LabelInterface {
  std::int64_t a = 0, b = 0;
  std::int64_t surfels = 0;
  friend bool operator==(const LabelInterface&, const LabelInterface&) = default;
};

/// The interfaces between the labels of an image of any dimension (the seeds' multi-label
/// partitions): for every unordered pair of distinct labels {a, b} that touch, the number of
/// (d-1)-cells between a voxel of label a and an axis neighbour of label b; outside the domain
/// every voxel has the label `outside` (the background's value), so the interfaces close. For a
/// label L != outside, the interfaces holding L add up to the boundary surfels of {label == L}
/// (image_surfels). Sorted by (a, b). O(N d) time for N voxels, memory per interface, one
/// thread.
std::vector<LabelInterface> label_interfaces(const Image<std::int64_t>& labels,
                                             std::int64_t outside = 0);

} // namespace zdg
