// Runs the zdg program (path from zdg::test::cli_path(), tests/support/paths.hpp) for command-line
// tests: exit status, stdout and stderr of `zdg ARGS`.
//
//   auto r = zdg::test::run_zdg("cf 415/93 --json");
//   EXPECT_EQ(r.status, 0);
//   auto j = nlohmann::json::parse(r.out);   // include <nlohmann/json.hpp> yourself
#pragma once

#include "tests/support/paths.hpp"
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
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

} // namespace zdg::test
