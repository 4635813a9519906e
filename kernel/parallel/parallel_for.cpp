#include <zdg/kernel/parallel/parallel_for.hpp>

#include <algorithm>
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

} // namespace zdg
