// kernel/parallel/parallel_rounds.hpp: every item runs once; no item of round k starts before every
// item of the earlier rounds has finished (checked by the finish counts each item sees); empty
// rounds; the first exception is rethrown without leaving a worker waiting.
#include <zdg/kernel/parallel/parallel_rounds.hpp>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <atomic>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace {

using zdg::parallel_rounds;

// Rounds of random sizes (some empty), on 1 to 4 threads: each item runs once, and when it
// starts, the number of finished items is at least the start of its round.
RC_GTEST_PROP(ParallelRounds, EveryItemOnceAndRoundsInOrder, ()) {
  const auto sizes = *rc::gen::container<std::vector<int>>(rc::gen::inRange(0, 40));
  const auto threads = *rc::gen::inRange(1, 5);
  std::vector<std::int64_t> start{0};
  for (const int s : sizes) start.push_back(start.back() + s);
  const auto n = start.back();
  std::vector<std::atomic<int>> runs(static_cast<std::size_t>(n));
  std::vector<std::int64_t> seen(static_cast<std::size_t>(n), -1);
  std::atomic<std::int64_t> done{0};
  parallel_rounds(start, unsigned(threads), [&](std::int64_t i) {
    seen[static_cast<std::size_t>(i)] = done.load();
    ++runs[static_cast<std::size_t>(i)];
    ++done;
  });
  for (std::size_t r = 0; r + 1 < start.size(); ++r)
    for (auto i = start[r]; i < start[r + 1]; ++i) {
      RC_ASSERT(runs[static_cast<std::size_t>(i)].load() == 1);
      RC_ASSERT(seen[static_cast<std::size_t>(i)] >= start[r]);
    }
}

TEST(ParallelRounds, RethrowsTheFirstExceptionWithoutHanging) {
  // Round 0 throws in one item while other workers wait to start round 1.
  const std::vector<std::int64_t> start{0, 4, 100, 200};
  std::atomic<int> later{0};
  EXPECT_THROW(parallel_rounds(start, 3,
                               [&](std::int64_t i) {
                                 if (i == 2) throw std::runtime_error("item 2");
                                 if (i >= 4) ++later;
                               }),
               std::runtime_error);
  EXPECT_EQ(later.load(), 0); // no item of a later round started after the failure
  parallel_rounds(std::vector<std::int64_t>{}, 2, [](std::int64_t) { FAIL(); });
  parallel_rounds(std::vector<std::int64_t>{5, 5, 5}, 2, [](std::int64_t) { FAIL(); });
}

} // namespace
