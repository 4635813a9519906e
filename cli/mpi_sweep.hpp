// The runs of a convergence sweep on the ranks of an MPI job, for `zdg converge ... --mpi` and
// `zdg paper NAME --mpi` (issue #40): every rank plans the same experiment
// (convergence/experiment.hpp), the jobs (plan_jobs: one (level, shape, translation) of an
// entry, or of the entries that share a computation) are handed out largest first and
// dynamically, and rank 0 gathers the records.
//
// Schedule: rank 0 holds the next job's index. Its main thread serves the other ranks' requests
// (MPI messages; each request carries the records of the rank's previous job) while its other
// threads run jobs from the same index; every other rank runs `threads` workers that ask rank 0
// for their next job (one request at a time per rank). A job is never split: what its runs
// measure (errors, seconds) is what one process measures, and records are put in the one
// order of ExperimentResult::runs (sort_runs) whatever rank ran them, so that the gathered
// results are the single-process ones except the seconds. Cost: one message each way per
// job (40 bytes per record of the job back); rank 0 polls for requests every millisecond.
//
// Failures: a job that throws on any rank stops the hand-out (every rank then gets "no more
// work" and finishes the job it holds); rank 0 keeps the first failure, "what (rank r of P)".
// Records are gathered exactly (the doubles' bytes): the ranks are one binary on machines of
// one architecture.
#pragma once

#include <zdg/cli/mpi_session.hpp>
#include <zdg/convergence/experiment.hpp>

#include <string>
#include <vector>

namespace zdg::cli {

struct RankSweep {
  std::vector<RunRecord> runs; // rank 0: every run of the plan (any order) when none failed
  std::string failure;         // rank 0: the first failure of a rank (empty: none)
  unsigned threads = 1;        // the workers of this rank
};

/// The workers of each rank: `threads`, or for 0 the machine's cores shared among the ranks
/// on it (MpiSession::local_size), resolved by worker_count for `jobs` jobs.
unsigned sweep_threads(const MpiSession& mpi, unsigned threads, std::size_t jobs);

/// Runs the plan on every rank of the session (every rank calls it, with the same plan and
/// config). Rank 0 returns the records or the first failure; the other ranks return when rank 0
/// has no more work for them. Thread-safe only as MPI_THREAD_SERIALIZED allows: more than one
/// worker on a rank other than 0 needs MpiSession::serialized() (one worker otherwise).
/// `progress` is called on rank 0, one call at a time, for every record gathered.
RankSweep run_plan_on_ranks(MpiSession& mpi, const ExperimentPlan& plan,
                            const ExperimentConfig& config, const ProgressFn& progress = {});

/// The end of the job: rank 0 sends `status` (its exit status) to every other rank, which waits
/// for it; returns it on every rank.
int finish_on_ranks(MpiSession& mpi, int status);

} // namespace zdg::cli
