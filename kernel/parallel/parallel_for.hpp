// The one parallel loop of zdg: every multi-threaded algorithm goes through it.
//
//   parallel_for(n, threads, fn)     fn(i) for i in [0, n), items handed out one at a time
//                                    from a shared counter (dynamic schedule: uneven work)
//   parallel_chunks(n, threads, fn)  fn(begin, end) on `threads` contiguous chunks of [0, n)
//                                    (static schedule: uniform work, locality kept)
//   parallel_team(threads, fn)       fn(rank, size, sync) on one team of `size` workers for
//                                    the whole call, sync() a barrier of the team (iterative
//                                    solvers: one thread start per solve, not per sweep)
//
// `threads` = 0 means the hardware's concurrency; the count is clamped to [1, n]. The caller's
// thread works too. Exceptions: the first exception thrown by fn stops the hand-out of new
// items, every worker finishes its current item, and the exception is rethrown in the caller
// (later ones are dropped); nothing escapes a worker thread. When the system refuses to start
// a thread, the loop runs on the workers it has (at least the caller), so a request for more
// threads than the system allows costs time, never a crash.
//
// Cost: one thread start per worker and one atomic increment per item (parallel_for) or per
// chunk (parallel_chunks).
#pragma once

#include <atomic>
#include <cstdint>
#include <exception>
#include <functional>

namespace zdg {

/// The one threads rule of zdg: every `threads` parameter is an `unsigned`, 0 means all the
/// hardware's cores, and this function resolves it. Returns the number of workers used for
/// `requested` threads and `items` work items: in [1, max(1, items)]; 1 when items <
/// serial_below (work too small for a thread to pay). Results never depend on the count; a
/// report of "threads" gives this value.
unsigned worker_count(unsigned requested, std::int64_t items, std::int64_t serial_below = 0);

namespace detail {

/// Runs body() on `workers` threads, the caller's included, and returns when all returned.
/// body must not throw. Starts fewer threads when the system refuses more.
void run_on_workers(unsigned workers, const std::function<void()>& body);

/// The first exception of a parallel loop (thread-safe capture, rethrown after the join).
class FirstError {
public:
  bool failed() const { return failed_.load(std::memory_order_relaxed); }
  void capture() noexcept {
    if (!failed_.exchange(true)) error_ = std::current_exception();
  }
  void rethrow() const {
    if (error_) std::rethrow_exception(error_);
  }

private:
  std::atomic<bool> failed_{false};
  std::exception_ptr error_;
};

} // namespace detail

template <class Fn>
void parallel_for(std::int64_t n, unsigned threads, Fn&& fn) {
  if (n <= 0) return;
  const unsigned w = worker_count(threads, n);
  if (w == 1) {
    for (std::int64_t i = 0; i < n; ++i) fn(i);
    return;
  }
  std::atomic<std::int64_t> next{0};
  detail::FirstError error;
  detail::run_on_workers(w, [&] {
    while (!error.failed()) {
      const std::int64_t i = next.fetch_add(1, std::memory_order_relaxed);
      if (i >= n) return;
      try {
        fn(i);
      } catch (...) {
        error.capture();
        return;
      }
    }
  });
  error.rethrow();
}

/// Runs fn(rank, size, sync) once on each of `size` workers (ranks 0 .. size - 1, the caller is
/// rank 0; size = worker_count(threads, max), fewer when the system refuses threads), sync()
/// blocking until every worker of the team has called it. fn must not throw, and every worker
/// must call sync() the same number of times (decisions that end a loop are taken on values
/// all ranks share).
void parallel_team(
    unsigned threads, std::int64_t max,
    const std::function<void(unsigned rank, unsigned size, const std::function<void()>& sync)>& fn);

template <class Fn>
void parallel_chunks(std::int64_t n, unsigned threads, Fn&& fn) {
  if (n <= 0) return;
  const std::int64_t t = worker_count(threads, n);
  parallel_for(t, static_cast<unsigned>(t), [&](std::int64_t k) {
    // floor(n k / t) without forming n k: n = q t + r gives q k + floor(r k / t), r k < t^2.
    const std::int64_t q = n / t, r = n % t;
    fn(q * k + r * k / t, q * (k + 1) + r * (k + 1) / t);
  });
}

} // namespace zdg
