#include <zdg/estimators/gauss_volume.hpp>

#include <zdg/arith/integer.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>

#include <atomic>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace zdg {

GaussVolume gauss_volume(const VoxelPredicate& inside, const VoxelBox& box, double h,
                         unsigned threads) {
  check_voxel_box(box);
  if (!(h > 0) || !std::isfinite(h))
    throw InvalidArgument("gauss_volume: grid step h = " + std::to_string(h) +
                          " is not a positive number");
  const int128_t n =
      int128_t(box.hi.x - box.lo.x + 1) * (box.hi.y - box.lo.y + 1) * (box.hi.z - box.lo.z + 1);
  if (n > std::numeric_limits<std::int64_t>::max())
    throw InvalidArgument("gauss_volume: the box has more than 2^63 voxels");
  std::atomic<std::int64_t> total{0};
  parallel_for(box.hi.z - box.lo.z + 1, unsigned(threads), [&](std::int64_t k) {
    const std::int64_t z = box.lo.z + k;
    std::int64_t count = 0;
    for (auto y = box.lo.y; y <= box.hi.y; ++y)
      for (auto x = box.lo.x; x <= box.hi.x; ++x) count += inside({x, y, z}) ? 1 : 0;
    total += count;
  });
  return {total.load(), h * h * h * double(total.load())};
}

} // namespace zdg
