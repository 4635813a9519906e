// Runs the zdg program (path from zdg::test::cli_path(), tests/support/paths.hpp) for command-line
// tests: exit status, stdout and stderr of `zdg ARGS`.
//
//   auto r = zdg::test::run_zdg("cf 415/93 --json");
//   EXPECT_EQ(r.status, 0);
//   auto j = nlohmann::json::parse(r.out);   // include <nlohmann/json.hpp> yourself
//   auto m = zdg::test::run_mpi(3, "transform dt in.npy -o out.npy --mpi");   // 3 ranks
#pragma once

#include "tests/support/paths.hpp"
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <sys/wait.h>
#include <system_error>
#include <unistd.h>

namespace zdg::test {

struct CliResult {
  int status = -1;
  std::string out, err;
};

inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A fresh scratch directory under the system temporary directory, unique per test.
inline std::filesystem::path scratch_dir(const std::string& tag) {
  auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = tag;
  if (info != nullptr) name += std::string("_") + info->test_suite_name() + "_" + info->name();
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  auto dir = std::filesystem::temp_directory_path() /
             ("zdg_test_" + std::to_string(::getpid()) + "_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// Runs `zdg ARGS` through the shell (ARGS is not quoted: quote it yourself where needed).
inline CliResult run_zdg(const std::string& args, const std::string& stdin_text = "") {
  auto dir = scratch_dir("cli");
  auto out = dir / "stdout", err = dir / "stderr", in = dir / "stdin";
  {
    std::ofstream f(in);
    f << stdin_text;
  }
  std::string cmd = std::string("'") + zdg::test::cli_path() + "' " + args + " <'" + in.string() +
                    "' >'" + out.string() + "' 2>'" + err.string() + "'";
  int raw = std::system(cmd.c_str());
  CliResult r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  r.out = read_file(out);
  r.err = read_file(err);
  std::filesystem::remove_all(dir);
  return r;
}

/// Whether zdg was built with MPI (then the tests know mpiexec's path).
inline bool mpi_built() {
  return zdg::test::mpiexec_path()[0] != '\0';
}

/// `mpiexec -np P zdg ARGS` through the shell, stdout and stderr captured. OpenMPI refuses to
/// run as root (CI containers) unless told, and more ranks than cores unless oversubscribed;
/// under the sanitizers, OpenMPI's own allocations left at exit are not zdg's leaks. Each
/// launch gets its own session directory: OpenMPI 4 puts every job of a user under
/// $TMPDIR/ompi.HOST.UID, and two launches creating it at once (two tests in parallel under
/// ctest -j) fail with "mkdir ... File exists" (seen in CI). The path is short, as the
/// launcher's sockets live below it. A hang (ranks left waiting) fails the test in two minutes
/// (status 124) instead of stalling the suite.
inline CliResult run_mpi(int ranks, const std::string& args) {
  auto dir = scratch_dir("mpi_cli");
  auto out = dir / "stdout", err = dir / "stderr", in = dir / "stdin";
  { std::ofstream f(in); }
  char session[] = "/tmp/zdg-ompi-XXXXXX";
  if (::mkdtemp(session) == nullptr) throw std::runtime_error("run_mpi: mkdtemp failed");
  std::string env = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "
                    "OMPI_MCA_rmaps_base_oversubscribe=1 ";
  env += std::string("TMPDIR=") + session + " OMPI_MCA_orte_tmpdir_base=" + session + " ";
  if (std::getenv("ZDG_SANITIZE") != nullptr) {
    env += "ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 ";
  }
  const std::string cmd = "timeout -k 10 120 env " + env + "'" + zdg::test::mpiexec_path() +
                          "' -np " + std::to_string(ranks) + " --oversubscribe '" +
                          zdg::test::cli_path() + "' " + args + " <'" + in.string() + "' >'" +
                          out.string() + "' 2>'" + err.string() + "'";
  const int raw = std::system(cmd.c_str());
  std::error_code ec;
  std::filesystem::remove_all(session, ec);
  CliResult r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  r.out = read_file(out);
  r.err = read_file(err);
  std::filesystem::remove_all(dir, ec);
  return r;
}

/// The lines of zdg's own messages ("zdg: ...") in a stderr that also holds mpiexec's banners.
inline int zdg_lines(const std::string& err) {
  int n = 0;
  for (std::size_t at = 0; (at = err.find("zdg: ", at)) != std::string::npos; ++at) {
    if (at == 0 || err[at - 1] == '\n') ++n;
  }
  return n;
}

} // namespace zdg::test
