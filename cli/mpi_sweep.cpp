// See cli/mpi_sweep.hpp.
#include <zdg/arith/error.hpp>
#include <zdg/cli/mpi_sweep.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <exception>
#include <iostream>
#include <mutex>
#include <new>
#include <thread>

namespace zdg::cli {

namespace {

// Message tags. A request carries the records of the sender's previous job (empty: none);
// its reply is the next job's index, -1 for no more work. A failure carries its line; done
// says that every worker of the sender has finished; final carries the job's exit status.
constexpr int kRequest = 40, kReply = 41, kFailure = 42, kDone = 43, kFinal = 44;

template <class T>
void put(std::string& out, T v) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  out.append(b, sizeof(T));
}

template <class T>
T get(const std::string& in, std::size_t& at) {
  T v;
  std::memcpy(&v, in.data() + at, sizeof(T));
  at += sizeof(T);
  return v;
}

// The records of job j: its index, then per record linf, l2, mean, seconds and n (the bytes of
// each value: exact).
std::string encode(std::int64_t j, const std::vector<RunRecord>& records) {
  std::string out;
  put(out, j);
  for (const auto& r : records) {
    put(out, r.errors.linf);
    put(out, r.errors.l2);
    put(out, r.errors.mean);
    put(out, r.seconds);
    put(out, r.errors.n);
  }
  return out;
}

constexpr std::size_t kRecordBytes = 4 * sizeof(double) + sizeof(std::int64_t);

std::string failure_text(const MpiSession& mpi, const std::string& what) {
  return (what.empty() ? std::string("unknown error") : what) + " (rank " +
         std::to_string(mpi.rank()) + " of " + std::to_string(mpi.size()) + ")";
}

// What the running of a job threw, as a line.
std::string caught() {
  try {
    throw;
  } catch (const std::bad_alloc&) {
    return "out of memory";
  } catch (const std::exception& e) {
    return e.what();
  } catch (...) {
    return "unknown error";
  }
}

RankSweep sweep_on_rank0(MpiSession& mpi, const ExperimentPlan& plan,
                         const ExperimentConfig& config, const std::vector<ExperimentJob>& jobs,
                         unsigned workers, const ProgressFn& progress) {
  const auto n = static_cast<std::int64_t>(jobs.size());
  std::size_t total = 0;
  for (const auto& job : jobs) total += job.entries.size();
  std::vector<std::vector<RunRecord>> results(jobs.size());
  std::atomic<std::int64_t> next{0};
  std::atomic<bool> failed{false};
  std::mutex mutex; // results' progress, the failure
  std::string failure;
  std::size_t runs_done = 0, jobs_done = 0;

  const auto take = [&]() -> std::int64_t {
    if (failed.load()) return -1;
    const std::int64_t j = next.fetch_add(1);
    return j < n ? j : -1;
  };
  const auto fail = [&](const std::string& what) {
    std::lock_guard<std::mutex> lock(mutex);
    if (failure.empty()) failure = what;
    failed.store(true);
  };
  const auto store = [&](std::int64_t j, std::vector<RunRecord> records) {
    std::lock_guard<std::mutex> lock(mutex);
    for (const auto& r : records) {
      ++runs_done;
      if (progress) progress(runs_done, total, r);
    }
    results[static_cast<std::size_t>(j)] = std::move(records);
    ++jobs_done;
  };
  const auto run_local = [&](std::int64_t j) {
    try {
      store(j, run_job(plan, config, jobs[static_cast<std::size_t>(j)]));
    } catch (...) {
      fail(failure_text(mpi, caught()));
    }
  };
  // The records another rank sent with its request (checked: the sender runs this binary).
  const auto gather = [&](const std::string& bytes) {
    if (bytes.empty()) return;
    std::size_t at = 0;
    const auto j = bytes.size() >= sizeof(std::int64_t) ? get<std::int64_t>(bytes, at) : -1;
    if (j < 0 || j >= n ||
        bytes.size() != at + jobs[static_cast<std::size_t>(j)].entries.size() * kRecordBytes) {
      fail("internal error: a malformed result message (" + std::to_string(bytes.size()) +
           " bytes)");
      return;
    }
    std::vector<RunRecord> records = job_records(plan, config, jobs[static_cast<std::size_t>(j)]);
    for (auto& r : records) {
      r.errors.linf = get<double>(bytes, at);
      r.errors.l2 = get<double>(bytes, at);
      r.errors.mean = get<double>(bytes, at);
      r.seconds = get<double>(bytes, at);
      r.errors.n = get<std::int64_t>(bytes, at);
    }
    store(j, std::move(records));
  };

  // Team member 0 (this thread) serves the other ranks; members 1.. run jobs. When the system
  // grants no second thread, this one runs the jobs too, between its rounds of requests.
  parallel_team(workers + 1, workers + 1,
                [&](unsigned member, unsigned size, const std::function<void()>&) {
                  if (member > 0) {
                    for (std::int64_t j; (j = take()) >= 0;) run_local(j);
                    return;
                  }
                  int ranks_left = mpi.size() - 1;
                  try {
                    while (ranks_left > 0 || (size == 1 && !failed.load() && next.load() < n)) {
                      auto m = mpi.try_receive(-1, -1);
                      if (!m) {
                        if (size == 1) {
                          if (const std::int64_t j = take(); j >= 0) run_local(j);
                        } else {
                          std::this_thread::sleep_for(std::chrono::milliseconds(1));
                        }
                        continue;
                      }
                      if (m->tag == kRequest) {
                        gather(m->bytes);
                        std::string reply;
                        put(reply, take());
                        mpi.send(m->source, kReply, reply);
                      } else if (m->tag == kFailure) {
                        fail(m->bytes);
                      } else if (m->tag == kDone) {
                        --ranks_left;
                      }
                    }
                  } catch (...) {
                    // The messages themselves failed: the other ranks cannot be told; end the
                    // whole job (what mpiexec prints follows this line).
                    std::cerr << "zdg: " << failure_text(mpi, caught()) << std::endl;
                    mpi.abort(2);
                  }
                });
  RankSweep out;
  out.threads = workers;
  out.failure = failure;
  if (out.failure.empty() && jobs_done != jobs.size()) {
    out.failure = "internal error: " + std::to_string(jobs_done) + " of " +
                  std::to_string(jobs.size()) + " jobs gathered";
  }
  if (!out.failure.empty()) return out;
  out.runs.reserve(total);
  for (auto& records : results) {
    for (auto& r : records) out.runs.push_back(std::move(r));
  }
  return out;
}

RankSweep sweep_on_rank(MpiSession& mpi, const ExperimentPlan& plan, const ExperimentConfig& config,
                        const std::vector<ExperimentJob>& jobs, unsigned workers) {
  std::mutex mpi_mutex; // one thread at a time calls MPI (MPI_THREAD_SERIALIZED)
  bool failed = false;  // guarded by mpi_mutex
  parallel_team(workers, workers, [&](unsigned, unsigned, const std::function<void()>&) {
    std::string previous; // the records of this worker's previous job
    for (;;) {
      std::int64_t j = -1;
      try {
        std::lock_guard<std::mutex> lock(mpi_mutex);
        if (failed) return;
        mpi.send(0, kRequest, previous);
        const auto reply = mpi.receive(0, kReply);
        std::size_t at = 0;
        if (reply.bytes.size() == sizeof(std::int64_t)) j = get<std::int64_t>(reply.bytes, at);
      } catch (...) {
        std::cerr << "zdg: " << failure_text(mpi, caught()) << std::endl;
        mpi.abort(2);
      }
      if (j < 0 || j >= static_cast<std::int64_t>(jobs.size())) return;
      try {
        previous = encode(j, run_job(plan, config, jobs[static_cast<std::size_t>(j)]));
      } catch (...) {
        const std::string what = failure_text(mpi, caught());
        std::lock_guard<std::mutex> lock(mpi_mutex);
        if (!failed) {
          failed = true;
          try {
            mpi.send(0, kFailure, what);
          } catch (...) {
            std::cerr << "zdg: " << what << std::endl;
            mpi.abort(2);
          }
        }
        return;
      }
    }
  });
  mpi.send(0, kDone, std::string());
  RankSweep out;
  out.threads = workers;
  return out;
}

} // namespace

unsigned sweep_threads(const MpiSession& mpi, unsigned threads, std::size_t jobs) {
  if (threads == 0) {
    threads = std::max(1u, std::thread::hardware_concurrency() /
                               static_cast<unsigned>(std::max(1, mpi.local_size())));
  }
  return worker_count(threads, static_cast<std::int64_t>(jobs));
}

RankSweep run_plan_on_ranks(MpiSession& mpi, const ExperimentPlan& plan,
                            const ExperimentConfig& config, const ProgressFn& progress) {
  const std::vector<ExperimentJob> jobs = plan_jobs(plan, config);
  unsigned workers = sweep_threads(mpi, config.threads, jobs.size());
  if (mpi.rank() == 0) return sweep_on_rank0(mpi, plan, config, jobs, workers, progress);
  if (!mpi.serialized()) workers = 1;
  return sweep_on_rank(mpi, plan, config, jobs, workers);
}

int finish_on_ranks(MpiSession& mpi, int status) {
  if (mpi.rank() == 0) {
    std::string bytes;
    put(bytes, static_cast<std::int32_t>(status));
    for (int r = 1; r < mpi.size(); ++r) mpi.send(r, kFinal, bytes);
    return status;
  }
  const auto m = mpi.receive(0, kFinal);
  std::size_t at = 0;
  return m.bytes.size() == sizeof(std::int32_t) ? get<std::int32_t>(m.bytes, at) : 2;
}

} // namespace zdg::cli
