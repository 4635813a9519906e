// zdg converge --mpi and zdg paper NAME --mpi under mpiexec with 1 to 4 ranks (issue #40): the
// runs handed out to the ranks and gathered by rank 0 give the single-process command's
// results.csv (every column but the seconds), summary.json and printed table byte for byte,
// rows in the same order, for sweeps with more jobs than ranks (dynamic hand-out), fewer jobs
// than ranks (ranks with no work), jobs of estimators that share a computation, and several
// workers per rank. A run that fails on any rank fails the job: one line of zdg, exit 2, no
// output (a folder the run created removed, existing outputs kept). The jobs themselves are
// checked by tests/convergence/experiment_test.cpp (JobsHoldEveryRunOnceLargestFirst,
// JobsRunAloneInAnyOrderGiveTheSweep).
#include "tests/support/cli.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace zdg {
namespace {

namespace fs = std::filesystem;

// results.csv without its column `seconds` (the 12th; fields may be quoted and hold commas);
// each removed value checked to be a time in seconds.
std::string without_seconds(const std::string& csv) {
  std::string out;
  std::size_t line_start = 0;
  while (line_start < csv.size()) {
    std::size_t end = csv.find('\n', line_start);
    if (end == std::string::npos) end = csv.size();
    const std::string line = csv.substr(line_start, end - line_start);
    std::size_t field = 0, begin = 0;
    bool quoted = false;
    std::string kept;
    for (std::size_t i = 0; i <= line.size(); ++i) {
      if (i < line.size() && line[i] == '"') quoted = !quoted;
      if (i == line.size() || (line[i] == ',' && !quoted)) {
        const std::string value = line.substr(begin, i - begin);
        if (field == 11) {
          if (line_start > 0) {
            EXPECT_GE(std::stod(value), 0.0) << line;
          }
          kept += "<seconds>";
        } else {
          kept += value;
        }
        if (i < line.size()) kept += ',';
        ++field;
        begin = i + 1;
      }
    }
    out += kept + '\n';
    line_start = end + 1;
  }
  return out;
}

// A path as a shell word (not "'" + ... + "'": a false -Wstringop-overflow of GCC 12).
std::string quoted(const fs::path& p) {
  std::string q(1, '\'');
  q.append(p.string());
  q.push_back('\'');
  return q;
}

struct Outputs {
  int status = -1;
  std::string csv, summary, out;
};

Outputs read_outputs(const test::CliResult& r, const fs::path& dir) {
  return {r.status, without_seconds(test::read_file(dir / "results.csv")),
          test::read_file(dir / "summary.json"), r.out};
}

// Theorem: the distributed sweep's outputs are the single-process command's, but the seconds.
TEST(ConvergeMpi, OutputsEqualTheSingleProcessSweep) {
  if (!test::mpi_built()) GTEST_SKIP() << "zdg was built without MPI";
  const fs::path dir = test::scratch_dir("converge_mpi");
  const std::string out = quoted(dir / "out");
  struct Case {
    std::string args;
    std::vector<int> ranks;
  };
  const std::vector<Case> cases = {
      // 24 jobs: more than the ranks; two theory checks fail (exit status 1 on every path).
      {"converge --shape ellipse:20,7 --shape flower:20,7,6 --estimator ii-curvature "
       "--estimator bc-curvature --h 1:0.3:3 --translations 2 --seed 5 --threads 1",
       {1, 2, 3, 4}},
      // 2 jobs (ii-mean and ii-k1 share their computation): ranks 2 and 3 get no work.
      {"converge --shape sphere1 --estimator ii-mean --estimator ii-k1 --h 0.5,0.25 --k 1 "
       "--translations 0 --threads 1",
       {1, 2, 3, 4}},
      // Two workers per rank (requests from two threads of one rank).
      {"converge --shape ellipse:20,7 --estimator gauss-area --estimator mlp-length "
       "--h 1:0.2:4 --translations 3 --seed 2 --threads 2",
       {2, 3}},
      // A paper's configuration (flags override its file).
      {"paper gauss-area --quick --threads 1", {2}},
  };
  for (const auto& c : cases) {
    const std::string args = c.args + " -o " + out + " --force --no-plot --quiet";
    const auto ref = read_outputs(test::run_zdg(args), dir / "out");
    ASSERT_TRUE(ref.status == 0 || ref.status == 1) << c.args;
    ASSERT_NE(ref.csv.find("<seconds>"), std::string::npos) << c.args;
    for (const int P : c.ranks) {
      const auto r = test::run_mpi(P, args + " --mpi");
      const auto got = read_outputs(r, dir / "out");
      EXPECT_EQ(got.status, ref.status) << c.args << ", P = " << P << ": " << r.err;
      EXPECT_EQ(test::zdg_lines(r.err), 0) << c.args << ", P = " << P << ": " << r.err;
      EXPECT_EQ(got.csv, ref.csv) << c.args << ", P = " << P;
      EXPECT_EQ(got.summary, ref.summary) << c.args << ", P = " << P;
      EXPECT_EQ(got.out, ref.out) << c.args << ", P = " << P; // the table, printed once
    }
  }
  // --json: the runs and fits printed once, by rank 0; the same but the seconds.
  const std::string args = cases[0].args + " --json --quiet";
  auto strip = [](const std::string& text) {
    auto j = nlohmann::json::parse(text);
    for (auto& run : j["runs"]) {
      EXPECT_GE(run["seconds"].get<double>(), 0.0);
      run.erase("seconds");
    }
    return j;
  };
  const auto ref = test::run_zdg(args);
  const auto r = test::run_mpi(3, args + " --mpi");
  EXPECT_EQ(r.status, ref.status) << r.err;
  EXPECT_EQ(strip(r.out), strip(ref.out));
  // The figures: drawn by rank 0 from the gathered results.csv and summary.json (by the script
  // that draws the single process's; they differ only in the panel of the seconds per run).
  if (fs::exists("/usr/bin/python3")) {
    const auto plotted = test::run_mpi(
        2, "paper gauss-area --quick --threads 1 --quiet --force --mpi -o " + quoted(dir / "fig"));
    EXPECT_EQ(plotted.status, 0) << plotted.err;
    if (plotted.out.find("plot:") != std::string::npos) { // matplotlib is there
      for (const char* name : {"convergence.png", "convergence.svg", "convergence.html"}) {
        EXPECT_GT(fs::file_size(dir / "fig" / name), 0u) << name;
      }
    } else {
      EXPECT_NE(plotted.err.find("the plot could not be drawn"), std::string::npos) << plotted.err;
    }
  }
  fs::remove_all(dir);
}

// Errors: a run that throws on whichever rank holds it (jet fitting with too few neighbours at
// the coarsest step: 3 of 6 jobs, handed out last), bad input met by every rank, an existing
// output without --force. One line of zdg (whatever mpiexec adds), exit 2; the folder the run
// would create is not left behind, an existing output is kept, no staged file is left.
TEST(ConvergeMpi, AFailureIsOneLineAndNoOutput) {
  const fs::path dir = test::scratch_dir("converge_mpi");
  const std::string q = quoted(dir);
  // Outside mpiexec (or in a zdg built without MPI), --mpi is refused.
  const auto single = test::run_zdg("converge --shape ball:5 --estimator gauss-area --h 0.5 -o " +
                                    q + "/single --mpi");
  EXPECT_EQ(single.status, 2);
  EXPECT_EQ(test::zdg_lines(single.err), 1) << single.err;
  EXPECT_NE(single.err.find(test::mpi_built() ? "MPI launcher" : "without MPI"), std::string::npos)
      << single.err;
  EXPECT_FALSE(fs::exists(dir / "single"));
  if (!test::mpi_built()) return;

  const std::string failing = "converge --shape sphere1 --estimator jet-mean:k=1,degree=4 "
                              "--h 0.5,0.25 --translations 3 --threads 1 --quiet";
  for (int P = 1; P <= 4; ++P) {
    const auto r = test::run_mpi(P, failing + " -o " + q + "/new/out --mpi");
    EXPECT_EQ(r.status, 2) << "P = " << P << ": " << r.err;
    EXPECT_EQ(test::zdg_lines(r.err), 1) << "P = " << P << ": " << r.err;
    EXPECT_NE(r.err.find("zdg: jet fitting: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(" of " + std::to_string(P) + ")"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_FALSE(fs::exists(dir / "new")) << "P = " << P;
  }
  // Existing outputs: kept as they were when the run fails, and refused without --force.
  fs::create_directories(dir / "old");
  for (const char* name : {"results.csv", "summary.json"}) {
    std::ofstream(dir / "old" / name) << "keep\n";
  }
  const auto kept = test::run_mpi(3, failing + " -o " + q + "/old --force --no-plot --mpi");
  EXPECT_EQ(kept.status, 2) << kept.err;
  EXPECT_EQ(test::zdg_lines(kept.err), 1) << kept.err;
  const auto refused = test::run_mpi(
      2, "converge --shape ball:5 --estimator gauss-area --h 0.5 -o " + q + "/old --no-plot --mpi");
  EXPECT_EQ(refused.status, 2) << refused.err;
  EXPECT_EQ(test::zdg_lines(refused.err), 1) << refused.err;
  EXPECT_NE(refused.err.find("--force"), std::string::npos) << refused.err;
  for (const char* name : {"results.csv", "summary.json"}) {
    EXPECT_EQ(test::read_file(dir / "old" / name), "keep\n") << name;
  }
  for (const auto& e : fs::recursive_directory_iterator(dir)) // no staged file left
    EXPECT_NE(e.path().filename().string()[0], '.') << e.path();
  // Bad input, met by every rank: reported once.
  const auto bad =
      test::run_mpi(4, "converge --shape ball:5 --estimator nope --h 0.5 -o " + q + "/bad --mpi");
  EXPECT_EQ(bad.status, 2) << bad.err;
  EXPECT_EQ(test::zdg_lines(bad.err), 1) << bad.err;
  EXPECT_NE(bad.err.find("nope"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(dir / "bad"));
  // A paper made by a script is not a sweep.
  const auto script = test::run_mpi(2, "paper laplacian-comparison -o " + q + "/script --mpi");
  EXPECT_EQ(script.status, 2) << script.err;
  EXPECT_EQ(test::zdg_lines(script.err), 1) << script.err;
  EXPECT_NE(script.err.find("runs a script"), std::string::npos) << script.err;
  fs::remove_all(dir);
}

} // namespace
} // namespace zdg
