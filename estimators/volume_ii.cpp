#include <zdg/estimators/volume_ii.hpp>

#include <zdg/kernel/parallel/parallel_for.hpp>

#include <algorithm>

namespace zdg {

namespace {

constexpr std::int64_t kBatch = std::int64_t{1} << 18;

unsigned thread_count(unsigned threads) {
  return worker_count(threads, std::int64_t{1} << 30);
}

template <class Result, class Estimate>
std::vector<Result> in_batches(const ImageSurfels& surfels, Estimate&& estimate) {
  std::vector<Result> out;
  out.reserve(static_cast<std::size_t>(surfels.size()));
  std::vector<Surfel> batch;
  for (std::int64_t b = 0; b < surfels.size(); b += kBatch) {
    const std::int64_t e = std::min(surfels.size(), b + kBatch);
    batch.resize(static_cast<std::size_t>(e - b));
    for (std::int64_t i = b; i < e; ++i) batch[static_cast<std::size_t>(i - b)] = surfels.surfel(i);
    const auto r = estimate(batch);
    out.insert(out.end(), r.begin(), r.end());
  }
  return out;
}

} // namespace

VoxelPredicate volume_predicate(const Image<std::uint8_t>& image) {
  const VoxelGrid g = VoxelGrid::of(image.domain());
  const std::uint8_t* data = image.values().data();
  return [g, data](const Voxel& z) {
    const std::int64_t i = z.x - g.lower.x, j = z.y - g.lower.y, k = z.z - g.lower.z;
    return i >= 0 && j >= 0 && k >= 0 && i < g.nx && j < g.ny && k < g.nz &&
           data[g.index(i, j, k)] != 0;
  };
}

std::vector<double> volume_ii_mean_curvature(const Image<std::uint8_t>& image,
                                             const ImageSurfels& surfels, double h, double R,
                                             unsigned threads) {
  ii_digital_radius2(R, h); // checks R and h first
  const VoxelPredicate inside = volume_predicate(image);
  const VoxelBox box = surfels.grid.box();
  return in_batches<double>(surfels, [&](const std::vector<Surfel>& batch) {
    return ii_mean_curvature(inside, box, batch, h, R, thread_count(threads));
  });
}

std::vector<IIPrincipalCurvatures> volume_ii_principal_curvatures(const Image<std::uint8_t>& image,
                                                                  const ImageSurfels& surfels,
                                                                  double h, double R,
                                                                  unsigned threads) {
  ii_digital_radius2(R, h);
  const VoxelPredicate inside = volume_predicate(image);
  const VoxelBox box = surfels.grid.box();
  return in_batches<IIPrincipalCurvatures>(surfels, [&](const std::vector<Surfel>& batch) {
    return ii_principal_curvatures(inside, box, batch, h, R, thread_count(threads));
  });
}

} // namespace zdg
