// A parallel loop in rounds: the items [round_start[k], round_start[k + 1]) of round k run in
// parallel, and an item of round k starts only when every item of rounds 0 .. k-1 has finished.
// For schedules where the items of one round write disjoint data and a later round reads or
// adds to what an earlier one wrote (e.g. the pairs of blocks of a symmetric sum, coloured so
// that no block appears twice in a round): every datum is then updated in round order, the same
// for any number of threads.
//
//   parallel_rounds(round_start, threads, fn)   fn(i) for i in [round_start[0], round_start.back())
//
// The workers are started once for all the rounds (kernel/parallel/parallel_for.hpp's
// run_on_workers) and take the items in order from one counter; a worker that takes the first items
// of a round waits (yielding) for the stragglers of the previous one. The wait always ends: the
// items of a round are all handed out before any of the next, and each is finished by the worker
// that took it. Exceptions as parallel_for: the first one stops the hand-out, a waiting worker
// gives up, and it is rethrown in the caller. `threads` = 0: the hardware's concurrency.
//
// Cost: one atomic increment and one binary search over the rounds per item, one thread start
// per worker.
#pragma once

#include <zdg/kernel/parallel/parallel_for.hpp>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <span>
#include <thread>

namespace zdg {

template <class Fn>
void parallel_rounds(std::span<const std::int64_t> round_start, unsigned threads, Fn&& fn) {
  if (round_start.size() < 2) return;
  const std::int64_t first = round_start.front(), last = round_start.back();
  if (last <= first) return;
  const unsigned w = worker_count(threads, last - first);
  if (w == 1) {
    for (std::int64_t i = first; i < last; ++i) fn(i);
    return;
  }
  std::atomic<std::int64_t> next{first}, finished{first};
  detail::FirstError error;
  detail::run_on_workers(w, [&] {
    while (!error.failed()) {
      const std::int64_t i = next.fetch_add(1, std::memory_order_relaxed);
      if (i >= last) return;
      // The first item of i's round: every item before it must be finished.
      const auto k = std::upper_bound(round_start.begin(), round_start.end(), i) - 1;
      while (finished.load(std::memory_order_acquire) < *k) {
        if (error.failed()) return;
        std::this_thread::yield();
      }
      try {
        fn(i);
      } catch (...) {
        error.capture();
        return;
      }
      finished.fetch_add(1, std::memory_order_release);
    }
  });
  error.rethrow();
}

} // namespace zdg
