#include <zdg/kernel/parallel/parallel_for.hpp>

#include <algorithm>
#include <barrier>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <system_error>
#include <thread>
#include <vector>

namespace zdg {

unsigned worker_count(unsigned requested, std::int64_t items, std::int64_t serial_below) {
  unsigned t = requested == 0 ? std::max(1u, std::thread::hardware_concurrency()) : requested;
  if (items < 1 || items < serial_below) return 1;
  if (static_cast<std::int64_t>(t) > items) t = static_cast<unsigned>(items);
  return std::max(1u, t);
}

namespace detail {

void run_on_workers(unsigned workers, const std::function<void()>& body) {
  std::vector<std::thread> pool;
  for (unsigned k = 1; k < workers; ++k) {
    try {
      pool.emplace_back(body);
    } catch (const std::system_error&) {
      break; // the system refuses more threads: run on those we have
    }
  }
  body();
  for (auto& th : pool) th.join();
}

} // namespace detail

void parallel_team(
    unsigned threads, std::int64_t max,
    const std::function<void(unsigned, unsigned, const std::function<void()>&)>& fn) {
  const unsigned want = worker_count(threads, max);
  std::mutex m;
  std::condition_variable cv;
  bool go = false;
  unsigned size = 1;
  std::optional<std::barrier<>> barrier;
  const std::function<void()> sync = [&] {
    if (size > 1) barrier->arrive_and_wait();
  };
  // The workers wait for the team's size (known once the system has started what it allows).
  const auto worker = [&](unsigned rank) {
    {
      std::unique_lock<std::mutex> lock(m);
      cv.wait(lock, [&] { return go; });
    }
    fn(rank, size, sync);
  };
  std::vector<std::thread> pool;
  for (unsigned k = 1; k < want; ++k) {
    try {
      pool.emplace_back(worker, k);
    } catch (const std::system_error&) {
      break;
    }
  }
  {
    const std::lock_guard<std::mutex> lock(m);
    size = static_cast<unsigned>(pool.size()) + 1;
    barrier.emplace(static_cast<std::ptrdiff_t>(size));
    go = true;
  }
  cv.notify_all();
  fn(0, size, sync);
  for (auto& th : pool) th.join();
}

} // namespace zdg
