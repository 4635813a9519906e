#include <zdg/arith/error.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <stdexcept>
#include <thread>
#include <vector>

namespace {

using zdg::parallel_chunks;
using zdg::parallel_for;

// Every index is visited exactly once, whatever the thread count and the size.
RC_GTEST_PROP(ParallelFor, VisitsEveryIndexOnce, ()) {
  const auto n = *rc::gen::inRange<std::int64_t>(0, 2000);
  const auto threads = *rc::gen::inRange<unsigned>(0, 9);
  std::vector<std::atomic<int>> seen(static_cast<std::size_t>(n));
  parallel_for(n, threads, [&](std::int64_t i) { seen[static_cast<std::size_t>(i)]++; });
  for (const auto& s : seen) RC_ASSERT(s.load() == 1);
}

// The one threads rule: 0 is every core, a request is clamped to the items, and work below
// serial_below runs on one worker.
RC_GTEST_PROP(WorkerCount, OneRuleForEveryThreadsParameter, ()) {
  const auto items = *rc::gen::inRange<std::int64_t>(-2, 100000);
  const auto threads = *rc::gen::inRange<unsigned>(0, 65);
  const auto serial_below = *rc::gen::inRange<std::int64_t>(0, 70000);
  const unsigned all = std::max(1u, std::thread::hardware_concurrency());
  const unsigned w = zdg::worker_count(threads, items, serial_below);
  if (items < 1 || items < serial_below) {
    RC_ASSERT(w == 1u);
  } else {
    RC_ASSERT(w ==
              static_cast<unsigned>(std::min<std::int64_t>(threads == 0 ? all : threads, items)));
  }
}

// The chunks are contiguous, disjoint, in order and cover [0, n).
RC_GTEST_PROP(ParallelChunks, PartitionTheRange, ()) {
  const auto n = *rc::gen::inRange<std::int64_t>(0, 5000);
  const auto threads = *rc::gen::inRange<unsigned>(0, 17);
  std::vector<std::atomic<int>> seen(static_cast<std::size_t>(n));
  std::atomic<int> chunks{0};
  parallel_chunks(n, threads, [&](std::int64_t b, std::int64_t e) {
    RC_ASSERT(b < e);
    ++chunks;
    for (auto i = b; i < e; ++i) seen[static_cast<std::size_t>(i)]++;
  });
  for (const auto& s : seen) RC_ASSERT(s.load() == 1);
  if (n > 0) RC_ASSERT(chunks.load() == static_cast<int>(zdg::worker_count(threads, n)));
}

TEST(ParallelFor, ChunkBoundsExactForHugeRanges) {
  // floor(n k / t) without overflow for n near 2^63.
  const std::int64_t n = INT64_MAX - 5;
  std::atomic<std::int64_t> covered{0};
  std::vector<std::pair<std::int64_t, std::int64_t>> got(3);
  parallel_chunks(n, 3, [&](std::int64_t b, std::int64_t e) {
    covered += e - b;
    got[static_cast<std::size_t>(b == 0 ? 0 : (e == n ? 2 : 1))] = {b, e};
  });
  EXPECT_EQ(covered.load(), n);
  EXPECT_EQ(got[0].second, got[1].first);
  EXPECT_EQ(got[1].second, got[2].first);
}

// A worker's exception reaches the caller (it used to terminate the process), and it is the
// zdg error type that was thrown, with its message.
TEST(ParallelFor, RethrowsTheWorkerExceptionInTheCaller) {
  for (unsigned threads : {1u, 2u, 4u}) {
    try {
      parallel_for(1000, threads, [](std::int64_t i) {
        if (i == 617) throw zdg::InvalidArgument("item 617 is bad");
      });
      FAIL() << "no exception with " << threads << " threads";
    } catch (const zdg::InvalidArgument& e) {
      EXPECT_STREQ(e.what(), "item 617 is bad");
    }
  }
  EXPECT_THROW(parallel_chunks(100, 4,
                               [](std::int64_t b, std::int64_t) {
                                 if (b > 0) throw std::runtime_error("chunk");
                               }),
               std::runtime_error);
}

TEST(ParallelFor, StopsHandingOutWorkAfterAFailure) {
  std::atomic<std::int64_t> ran{0};
  EXPECT_THROW(parallel_for(1'000'000, 4,
                            [&](std::int64_t i) {
                              ++ran;
                              if (i == 0) throw std::runtime_error("first");
                            }),
               std::runtime_error);
  EXPECT_LT(ran.load(), 1'000'000);
}

// parallel_team: ranks 0 .. size - 1 once each, size as worker_count says, and sync() a
// barrier: after it every rank sees every rank's write of the phase before.
TEST(ParallelTeam, RanksAndBarrier) {
  for (const unsigned threads : {1u, 2u, 3u, 4u}) {
    std::vector<std::int64_t> slot(threads, -1);
    std::atomic<int> failures{0};
    std::atomic<unsigned> seen_size{0};
    zdg::parallel_team(threads, 1000, [&](unsigned rank, unsigned size, const auto& sync) {
      seen_size = size;
      for (std::int64_t phase = 0; phase < 200; ++phase) {
        slot[rank] = phase;
        sync();
        for (unsigned r = 0; r < size; ++r)
          if (slot[r] != phase) ++failures;
        sync();
      }
    });
    EXPECT_EQ(seen_size.load(), zdg::worker_count(threads, 1000));
    EXPECT_EQ(failures.load(), 0);
    for (unsigned r = 0; r < seen_size.load(); ++r) EXPECT_EQ(slot[r], 199);
  }
  // no more workers than the items
  unsigned size_for_one = 0;
  zdg::parallel_team(4, 1, [&](unsigned, unsigned size, const auto&) { size_for_one = size; });
  EXPECT_EQ(size_for_one, 1u);
}

TEST(ParallelFor, WorkerCountIsClampedToTheItems) {
  EXPECT_EQ(zdg::worker_count(8, 3), 3u);
  EXPECT_EQ(zdg::worker_count(8, 0), 1u);
  EXPECT_GE(zdg::worker_count(0, 1000), 1u);
  EXPECT_EQ(zdg::worker_count(5, 1000), 5u);
}

} // namespace
