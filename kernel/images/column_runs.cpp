#include <zdg/kernel/images/column_runs.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/digitization/polynomial_sign.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>

#include <algorithm>
#include <atomic>
#include <string>

namespace zdg {

namespace {

struct RowRun {
  std::int64_t x; // index in the row
  std::int32_t b, e;
};

} // namespace

std::vector<std::pair<std::int64_t, std::int64_t>> ColumnRuns::runs(std::int64_t x,
                                                                    std::int64_t y) const {
  std::vector<std::pair<std::int64_t, std::int64_t>> out;
  const std::size_t c = column(x, y);
  for (int k = 0; k < layers(); ++k) {
    const auto b = begin[std::size_t(k)][c], e = end[std::size_t(k)][c];
    if (b <= e) out.push_back({region.lo.z + b, region.lo.z + e});
  }
  return out;
}

std::pair<std::int64_t, std::int64_t>
ColumnRuns::deeper_range(int layer, std::int64_t y, std::int64_t x0, std::int64_t x1) const {
  // d[i] = number of columns before index i of the row with more than `layer` runs.
  const auto& dv = deeper[std::size_t(layer - 1)];
  const std::int32_t* d = dv.data() + std::size_t(y - region.lo.y) * std::size_t(nx + 1);
  const std::int64_t i0 = x0 - region.lo.x, i1 = x1 - region.lo.x;
  const std::int32_t before = d[i0], total = d[i1 + 1];
  if (before == total) return {x1 + 1, x1};
  // The columns of ranks before and total - 1 among the row's deeper columns.
  const std::int32_t* xs = deeper_x[std::size_t(layer - 1)].data() +
                           deeper_start[std::size_t(layer - 1)][std::size_t(y - region.lo.y)];
  return {region.lo.x + xs[before], region.lo.x + xs[total - 1]};
}

ColumnRuns column_runs(const VoxelPredicate& inside, const VoxelBox& box, const VoxelBox& region,
                       unsigned threads, const BlockMask* needed) {
  check_voxel_box(box);
  check_voxel_box(region);
  ColumnRuns out;
  out.region = region;
  out.nx = region.hi.x - region.lo.x + 1;
  out.ny = region.hi.y - region.lo.y + 1;
  out.nz = region.hi.z - region.lo.z + 1;
  if (out.nz >= (std::int64_t{1} << 28))
    throw InvalidArgument("column runs: the region spans " + std::to_string(out.nz) +
                          " voxels along z (at most 2^28)");
  if (double(out.nx) * double(out.ny) >= double(std::int64_t{1} << 31))
    throw InvalidArgument("column runs: the region has more than 2^31 columns");
  const std::int64_t B = ColumnRuns::kBlock;
  if (needed) {
    const auto blocks = [&](std::int64_t n) { return (n + B - 1) / B; };
    if (needed->bx != blocks(out.nx) || needed->by != blocks(out.ny) ||
        needed->bz != blocks(out.nz) ||
        needed->needed.size() != std::size_t(needed->bx * needed->by * needed->bz))
      throw InvalidArgument("column runs: the block mask does not match the region");
  }
  const std::int64_t z0 = std::max(region.lo.z, box.lo.z), z1 = std::min(region.hi.z, box.hi.z);
  std::vector<std::vector<RowRun>> rows(std::size_t(out.ny));
  std::atomic<std::size_t> evaluations{0};
  parallel_for(out.ny, threads, [&](std::int64_t j) {
    const std::int64_t y = region.lo.y + j;
    if (y < box.lo.y || y > box.hi.y || z0 > z1) return;
    std::vector<RowRun>& row = rows[std::size_t(j)];
    std::size_t evals = 0;
    // A polynomial digitization answers whole stretches of a column at once (the x and y
    // parts of F once per column: the same answers, a third of the time per voxel).
    const auto* column = inside.target<PolynomialDigitization>();
    std::vector<std::uint8_t> status(column ? std::size_t(B) : 0);
    for (std::int64_t i = 0; i < out.nx; ++i) {
      const std::int64_t x = region.lo.x + i;
      if (x < box.lo.x || x > box.hi.x) continue;
      bool in = false;
      std::int64_t start = 0;
      std::int64_t z = z0;
      while (z <= z1) {
        const std::int64_t kz = (z - region.lo.z) / B;
        const std::int64_t block_end = std::min(z1, region.lo.z + (kz + 1) * B - 1);
        if (needed && !needed->at(i / B, j / B, kz)) {
          z = block_end + 1; // unneeded: the status of the last evaluated voxel continues
          continue;
        }
        if (column) column->column(x, y, z, block_end, status.data());
        for (const std::int64_t zb = z; z <= block_end; ++z) {
          ++evals;
          const bool v = column ? status[std::size_t(z - zb)] != 0 : inside(Voxel{x, y, z});
          if (v != in) {
            if (v) {
              start = z;
            } else {
              row.push_back(
                  {i, std::int32_t(start - region.lo.z), std::int32_t(z - 1 - region.lo.z)});
            }
            in = v;
          }
        }
      }
      if (in) row.push_back({i, std::int32_t(start - region.lo.z), std::int32_t(z1 - region.lo.z)});
    }
    evaluations += evals;
  });
  out.evaluations = evaluations.load();

  int layers = 0;
  for (const auto& row : rows) {
    std::size_t k = 0;
    while (k < row.size()) {
      std::size_t m = k;
      while (m < row.size() && row[m].x == row[k].x) ++m;
      layers = std::max(layers, int(m - k));
      k = m;
    }
  }
  const std::size_t ncol = std::size_t(out.nx * out.ny);
  out.begin.assign(std::size_t(layers), std::vector<std::int32_t>(ncol, ColumnRuns::kEmptyBegin));
  out.end.assign(std::size_t(layers), std::vector<std::int32_t>(ncol, ColumnRuns::kEmptyEnd));
  out.deeper.assign(std::size_t(std::max(0, layers - 1)),
                    std::vector<std::int32_t>(std::size_t(out.ny * (out.nx + 1)), 0));
  out.deeper_x.assign(out.deeper.size(), {});
  out.deeper_start.assign(out.deeper.size(), std::vector<std::int64_t>(std::size_t(out.ny), 0));
  for (std::int64_t j = 0; j < out.ny; ++j) {
    const auto& row = rows[std::size_t(j)];
    std::size_t k = 0;
    while (k < row.size()) {
      std::size_t m = k;
      while (m < row.size() && row[m].x == row[k].x) ++m;
      const std::size_t c = std::size_t(j * out.nx + row[k].x);
      for (std::size_t l = k; l < m; ++l) {
        out.begin[l - k][c] = row[l].b;
        out.end[l - k][c] = row[l].e;
      }
      for (std::size_t l = 1; l < m - k; ++l)
        out.deeper[l - 1][std::size_t(j * (out.nx + 1) + row[k].x + 1)] = 1;
      k = m;
    }
    for (std::size_t l = 0; l < out.deeper.size(); ++l) {
      std::int32_t* p = out.deeper[l].data() + j * (out.nx + 1);
      out.deeper_start[l][std::size_t(j)] = std::int64_t(out.deeper_x[l].size());
      for (std::int64_t i = 1; i <= out.nx; ++i) {
        if (p[i]) out.deeper_x[l].push_back(std::int32_t(i - 1));
        p[i] += p[i - 1];
      }
    }
  }
  return out;
}

} // namespace zdg
