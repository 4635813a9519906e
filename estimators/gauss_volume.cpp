#include "estimators/gauss_volume.hpp"

#include "arith/integer.hpp"

#include <atomic>
#include <cmath>
#include <exception>
#include <limits>
#include <string>
#include <thread>
#include <vector>

namespace zdg {

GaussVolume gauss_volume(const VoxelPredicate& inside, const VoxelBox& box, double h, int threads) {
  check_voxel_box(box);
  if (!(h > 0) || !std::isfinite(h))
    throw InvalidArgument("gauss_volume: grid step h = " + std::to_string(h) +
                          " is not a positive number");
  if (threads < 0) throw InvalidArgument("gauss_volume: threads = " + std::to_string(threads));
  if (threads == 0) threads = int(std::max(1u, std::thread::hardware_concurrency()));
  const int128_t n =
      int128_t(box.hi.x - box.lo.x + 1) * (box.hi.y - box.lo.y + 1) * (box.hi.z - box.lo.z + 1);
  if (n > std::numeric_limits<std::int64_t>::max())
    throw InvalidArgument("gauss_volume: the box has more than 2^63 voxels");
  std::atomic<std::int64_t> next_z{box.lo.z}, total{0};
  std::exception_ptr error;
  std::atomic<bool> failed{false};
  auto work = [&] {
    std::int64_t count = 0;
    try {
      for (auto z = next_z++; z <= box.hi.z && !failed; z = next_z++)
        for (auto y = box.lo.y; y <= box.hi.y; ++y)
          for (auto x = box.lo.x; x <= box.hi.x; ++x) count += inside({x, y, z}) ? 1 : 0;
    } catch (...) {
      if (!failed.exchange(true)) error = std::current_exception();
    }
    total += count;
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
  return {total.load(), h * h * h * double(total.load())};
}

} // namespace zdg
