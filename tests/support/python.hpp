// Runs a Python snippet with Debian's /usr/bin/python3 (the one that sees python3-numpy and
// python3-nibabel) for tests that compare zdg with an independent reader.
//
//   if (!zdg::test::python_has("nibabel")) GTEST_SKIP() << "python3-nibabel is not installed";
//   auto r = zdg::test::run_python("import sys; print(sys.argv[1])", {"hello"});
//   EXPECT_EQ(r.status, 0) << r.err;   // r.out == "hello\n"
#pragma once

#include "tests/support/cli.hpp"

#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

namespace zdg::test {

/// Runs `code` with /usr/bin/python3 and the arguments (each single-quoted for the shell).
inline CliResult run_python(const std::string& code, const std::vector<std::string>& args = {}) {
  auto dir = scratch_dir("py");
  const auto script = dir / "snippet.py", out = dir / "stdout", err = dir / "stderr";
  {
    std::ofstream f(script);
    f << code;
  }
  std::string cmd = "/usr/bin/python3 '" + script.string() + "'";
  for (const auto& a : args) cmd += " '" + a + "'";
  cmd += " >'" + out.string() + "' 2>'" + err.string() + "'";
  const int raw = std::system(cmd.c_str());
  CliResult r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  r.out = read_file(out);
  r.err = read_file(err);
  std::filesystem::remove_all(dir);
  return r;
}

/// True when /usr/bin/python3 can import every module of the comma-separated list.
inline bool python_has(const std::string& modules) {
  return run_python("import " + modules + "\n").status == 0;
}

} // namespace zdg::test
