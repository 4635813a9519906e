// A team of P ranks as P threads of one process, for testing the distributed transforms
// (kernel/transforms/distributed_transform.hpp) without an MPI launcher: the collective operations
// of RankExchange through shared memory and a barrier.
//
//   zdg::test::run_team(3, [&](zdg::RankExchange& ex) { ... ex.rank() ... });
#pragma once

#include <zdg/kernel/transforms/distributed_transform.hpp>

#include <algorithm>
#include <atomic>
#include <barrier>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <functional>
#include <stdexcept>
#include <thread>
#include <vector>

namespace zdg::test {

class ThreadTeam {
public:
  explicit ThreadTeam(int ranks)
      : ranks_(ranks), sync_(ranks), posts_(static_cast<std::size_t>(ranks * ranks)),
        values_(static_cast<std::size_t>(ranks)) {}

  class Member final : public RankExchange {
  public:
    Member(ThreadTeam& team, int rank) : team_(team), rank_(rank) {}
    int rank() const override { return rank_; }
    int size() const override { return team_.ranks_; }
    void sendrecv(int to, const void* send, std::uint64_t send_bytes, int from, void* recv,
                  std::uint64_t recv_bytes) override {
      team_.posts_[static_cast<std::size_t>(rank_ * team_.ranks_ + to)] = {send, send_bytes};
      team_.wait();
      const Post& p = team_.posts_[static_cast<std::size_t>(from * team_.ranks_ + rank_)];
      if (p.bytes != recv_bytes) {
        std::fprintf(stderr, "ThreadTeam: rank %d expects %llu bytes from %d, which sends %llu\n",
                     rank_, static_cast<unsigned long long>(recv_bytes), from,
                     static_cast<unsigned long long>(p.bytes));
        std::abort();
      }
      if (recv_bytes > 0) std::memcpy(recv, p.data, recv_bytes);
      team_.wait(); // the senders' buffers stay alive until every copy is made
    }
    std::uint64_t max_over_ranks(std::uint64_t value) override {
      team_.values_[static_cast<std::size_t>(rank_)] = value;
      team_.wait();
      const std::uint64_t m = *std::max_element(team_.values_.begin(), team_.values_.end());
      team_.wait();
      return m;
    }

  private:
    ThreadTeam& team_;
    int rank_;
  };

  /// A rank threw while others still wait in a collective step: they throw this, as MPI_Abort ends
  /// an MPI job, instead of waiting forever.
  struct Aborted : std::runtime_error {
    Aborted() : std::runtime_error("ThreadTeam: a rank left while others were in a collective") {}
  };

  /// Runs fn on every rank, each on its own thread; rethrows the exception of the lowest rank
  /// that threw one of its own (the distributed transforms throw, if at all, on every rank at
  /// the same collective step; a rank that throws alone makes the others throw Aborted).
  void run(const std::function<void(RankExchange&)>& fn) {
    std::vector<std::exception_ptr> errors(static_cast<std::size_t>(ranks_));
    std::vector<std::thread> threads;
    for (int r = 0; r < ranks_; ++r) {
      threads.emplace_back([&, r] {
        Member m(*this, r);
        try {
          fn(m);
        } catch (...) {
          errors[static_cast<std::size_t>(r)] = std::current_exception();
          left_ = true;
        }
        sync_.arrive_and_drop();
      });
    }
    for (auto& t : threads) t.join();
    std::exception_ptr aborted;
    for (auto& e : errors) {
      if (!e) continue;
      try {
        std::rethrow_exception(e);
      } catch (const Aborted&) {
        aborted = e;
      } catch (...) {
        throw;
      }
    }
    if (aborted) std::rethrow_exception(aborted);
  }

private:
  void wait() {
    sync_.arrive_and_wait();
    if (left_) throw Aborted();
  }
  struct Post {
    const void* data = nullptr;
    std::uint64_t bytes = 0;
  };
  int ranks_;
  std::barrier<> sync_;
  std::atomic<bool> left_{false};
  std::vector<Post> posts_;
  std::vector<std::uint64_t> values_;
};

inline void run_team(int ranks, const std::function<void(RankExchange&)>& fn) {
  ThreadTeam team(ranks);
  team.run(fn);
}

} // namespace zdg::test
