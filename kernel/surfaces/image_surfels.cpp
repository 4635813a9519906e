#include <zdg/kernel/surfaces/image_surfels.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>

#include <algorithm>
#include <map>
#include <string>
#include <utility>

namespace zdg {

VoxelGrid VoxelGrid::of(const Domain& domain) {
  if (domain.dim() != 3)
    throw InvalidArgument("a volume needs a 3D image (got " + std::to_string(domain.dim()) + "-D)");
  if (domain.size() > (std::int64_t{1} << 60))
    throw InvalidArgument("volume of " + std::to_string(domain.size()) + " voxels: more than 2^60");
  for (int k = 0; k < 3; ++k) {
    if (domain.lower(k) < -kMaxVoxelCoordinate || domain.upper(k) > kMaxVoxelCoordinate)
      throw InvalidArgument("volume axis " + std::to_string(k) +
                            " leaves the coordinate range [-2^40, 2^40]");
  }
  VoxelGrid g;
  g.nz = domain.extent(0);
  g.ny = domain.extent(1);
  g.nx = domain.extent(2);
  g.lower = {domain.lower(2), domain.lower(1), domain.lower(0)};
  return g;
}

std::int64_t ImageSurfels::find(std::uint64_t code) const {
  const std::int64_t r = code_voxel(code) / grid.nx;
  if (r < 0 || r >= grid.rows()) return -1;
  return find_in_row(r, code);
}

Surfel ImageSurfels::surfel_of(std::uint64_t code) const {
  const int a = code_axis(code);
  const bool positive = code_positive(code);
  return surfel_between(grid.voxel(code_voxel(code)), a, positive ? 1 : -1);
}

std::vector<Surfel> ImageSurfels::surfels(unsigned threads) const {
  std::vector<Surfel> out(codes.size());
  parallel_chunks(size(), threads, [&](std::int64_t b, std::int64_t e) {
    for (auto i = b; i < e; ++i) out[static_cast<std::size_t>(i)] = surfel(i);
  });
  return out;
}

namespace {

// Visits the boundary surfels of row r (j, k) in code order: emit(code).
template <class Emit>
void row_surfels(const VoxelGrid& g, const std::uint8_t* data, std::int64_t r, Emit&& emit) {
  const std::int64_t j = r % g.ny, k = r / g.ny, nx = g.nx;
  const std::uint8_t* cur = data + r * nx;
  const std::uint8_t* ym = j > 0 ? cur - nx : nullptr;
  const std::uint8_t* yp = j + 1 < g.ny ? cur + nx : nullptr;
  const std::uint8_t* zm = k > 0 ? cur - nx * g.ny : nullptr;
  const std::uint8_t* zp = k + 1 < g.nz ? cur + nx * g.ny : nullptr;
  const std::int64_t base = r * nx;
  for (std::int64_t i = 0; i < nx; ++i) {
    if (cur[i] == 0) continue;
    const std::int64_t v = base + i;
    if (i == 0 || cur[i - 1] == 0) emit(surfel_code(v, 0, false));
    if (i + 1 == nx || cur[i + 1] == 0) emit(surfel_code(v, 0, true));
    if (ym == nullptr || ym[i] == 0) emit(surfel_code(v, 1, false));
    if (yp == nullptr || yp[i] == 0) emit(surfel_code(v, 1, true));
    if (zm == nullptr || zm[i] == 0) emit(surfel_code(v, 2, false));
    if (zp == nullptr || zp[i] == 0) emit(surfel_code(v, 2, true));
  }
}

} // namespace

ImageSurfels image_surfels(const Image<std::uint8_t>& image, unsigned threads) {
  ImageSurfels out;
  out.grid = VoxelGrid::of(image.domain());
  const VoxelGrid& g = out.grid;
  const std::uint8_t* data = image.values().data();
  const std::int64_t rows = g.rows();
  std::vector<std::int64_t> count(static_cast<std::size_t>(rows) + 1, 0);
  parallel_chunks(rows, threads, [&](std::int64_t b, std::int64_t e) {
    for (auto r = b; r < e; ++r) {
      std::int64_t n = 0;
      row_surfels(g, data, r, [&](std::uint64_t) { ++n; });
      count[static_cast<std::size_t>(r) + 1] = n;
    }
  });
  for (std::size_t r = 0; r < static_cast<std::size_t>(rows); ++r) count[r + 1] += count[r];
  out.codes.resize(static_cast<std::size_t>(count.back()));
  parallel_chunks(rows, threads, [&](std::int64_t b, std::int64_t e) {
    for (auto r = b; r < e; ++r) {
      auto* dst = out.codes.data() + count[static_cast<std::size_t>(r)];
      row_surfels(g, data, r, [&](std::uint64_t c) { *dst++ = c; });
    }
  });
  out.row_start = std::move(count);
  return out;
}

std::vector<LabelInterface> label_interfaces(const Image<std::int64_t>& labels,
                                             std::int64_t outside) {
  const Domain& dom = labels.domain();
  const int d = dom.dim();
  std::map<std::pair<std::int64_t, std::int64_t>, std::int64_t> count;
  auto add = [&](std::int64_t x, std::int64_t y) {
    if (x == y) return;
    ++count[x < y ? std::pair{x, y} : std::pair{y, x}];
  };
  const auto& v = labels.values();
  std::vector<std::int64_t> p(static_cast<std::size_t>(d));
  for (std::int64_t i = 0; i < dom.size(); ++i) {
    dom.point(i, p);
    const std::int64_t here = v[static_cast<std::size_t>(i)];
    for (int k = 0; k < d; ++k) {
      const std::int64_t c = p[static_cast<std::size_t>(k)] - dom.lower(k);
      if (c == 0) add(outside, here); // the face towards -e_k on the domain's side
      if (c + 1 < dom.extent(k)) {
        add(here, v[static_cast<std::size_t>(i + dom.stride(k))]);
      } else {
        add(here, outside);
      }
    }
  }
  std::vector<LabelInterface> out;
  out.reserve(count.size());
  for (const auto& [ab, n] : count) out.push_back({ab.first, ab.second, n});
  return out;
}

} // namespace zdg
