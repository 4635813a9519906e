// Every operation of zdg is reachable from the three front ends (issue #34): the command line,
// zdg serve and the Python module, or the table below says why not. The table is checked both
// ways: each entry it claims exists (`zdg CLI --help` succeeds, `zdg serve` knows the
// operation, the module has the function), and each subcommand, served operation and public
// Python function is in the table, so that a new one cannot be added to one front end
// silently.
#include "tests/support/cli.hpp"
#include "tests/support/python.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace zdg {
namespace {

struct Operation {
  std::string cli;    // subcommand path ("" = none)
  std::string serve;  // zdg serve operation ("" = none)
  std::string python; // function of the module ("" = none)
  std::string why;    // why a front end is missing
};

const std::vector<Operation>& operations() {
  static const std::string files = "works on files (paths in, files out); Python reads and "
                                   "writes arrays";
  static const std::vector<Operation> ops = {
      {"cf", "cf", "cf", ""},
      {"christoffel", "christoffel", "christoffel", ""},
      {"floor-sum", "floor-sum", "floor_sum", ""},
      {"dss recognize", "dss recognize", "recognize_dss", ""},
      {"dss cover", "dss cover", "tangential_cover", ""},
      {"dss subsegment", "dss subsegment", "dsl_subsegment", ""},
      {"hull points", "hull points", "hull", ""},
      {"hull disc", "hull disc", "hull_disc", ""},
      {"hull ellipse", "", "hull_ellipse", "serve: not yet a served operation"},
      {"hull halfplanes", "", "", "serve and Python: not yet bound"},
      {"plane recognize", "", "recognize_plane", "serve: not yet a served operation"},
      {"plane probe", "plane probe", "probe_plane", ""},
      {"transform dt", "transform dt", "distance_transform", ""},
      {"transform voronoi", "transform voronoi", "voronoi_map", ""},
      {"transform power", "", "power_map", "serve: not yet a served operation"},
      {"transform rdt", "", "reverse_distance_transform", "serve: not yet a served operation"},
      {"transform rma", "", "reduced_medial_axis", "serve: not yet a served operation"},
      {"topology components", "", "connected_components", "serve: not yet a served operation"},
      {"topology betti", "topology betti", "betti_numbers", ""},
      {"topology simple", "", "", "serve and Python: not yet bound"},
      {"topology thin", "", "thinning", "serve: not yet a served operation"},
      {"topology skeleton", "topology skeleton", "skeleton", ""},
      {"surface", "surface", "surface", ""},
      {"contour", "", "", "serve and Python: not yet bound"},
      {"convert", "", "", "serve: " + files + " (read_volume, write_volume)"},
      {"", "", "read_volume", "command line: zdg convert reads and writes; serve: " + files},
      {"", "", "write_volume", "command line: zdg convert reads and writes; serve: " + files},
      {"", "", "surfels", "command line and serve: part of zdg surface"},
      {"", "", "ii_curvature", "command line and serve: zdg surface --estimate ii-*"},
      {"converge", "", "converge", "serve: an experiment is not a request"},
      {"", "", "plot",
       "command line: zdg converge and zdg paper draw their plots; serve: a "
       "picture is not a JSON answer"},
      {"paper", "", "", "serve and Python: reproduces a figure from the repository's papers/"},
      {"check", "", "", "the client of zdg serve; Python implementations are checked by it"},
      {"serve", "", "", "the server itself"},
  };
  return ops;
}

// The subcommand paths of `zdg ARGS --help`, recursively ("dss cover", ...): leaves only.
void leaves(const std::string& prefix, std::set<std::string>& out) {
  const auto r = test::run_zdg(prefix + (prefix.empty() ? "" : " ") + "--help");
  ASSERT_EQ(r.status, 0) << "zdg " << prefix << " --help: " << r.err;
  std::istringstream in(r.out);
  std::string line;
  bool in_list = false;
  std::vector<std::string> subs;
  while (std::getline(in, line)) {
    if (line.rfind("Subcommands:", 0) == 0) {
      in_list = true;
      continue;
    }
    if (!in_list) continue;
    if (line.size() > 2 && line[0] == ' ' && line[1] == ' ' && line[2] != ' ') {
      subs.push_back(line.substr(2, line.find(' ', 2) - 2));
    } else if (!line.empty() && line[0] != ' ') {
      in_list = false;
    }
  }
  if (subs.empty() && !prefix.empty()) out.insert(prefix);
  for (const auto& s : subs) leaves(prefix.empty() ? s : prefix + " " + s, out);
}

std::set<std::string> served_operations() {
  // An unknown operation's error lists the known ones: "(known: a, b, c)".
  const auto r = test::run_zdg("serve no-such-operation");
  const auto open = r.err.find("(known: ");
  EXPECT_NE(open, std::string::npos) << r.err;
  std::set<std::string> out;
  if (open == std::string::npos) return out;
  std::string list = r.err.substr(open + 8, r.err.rfind(')') - open - 8);
  std::size_t pos = 0;
  while (pos < list.size()) {
    const auto comma = list.find(", ", pos);
    out.insert(list.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos));
    if (comma == std::string::npos) break;
    pos = comma + 2;
  }
  return out;
}

TEST(FrontEnds, EveryOperationIsReachableOrSaysWhyNot) {
  std::set<std::string> cli, table_cli, table_serve, table_python;
  leaves("", cli);
  const auto served = served_operations();
  for (const auto& op : operations()) {
    const int fronts = !op.cli.empty() + !op.serve.empty() + !op.python.empty();
    EXPECT_TRUE(fronts == 3 || !op.why.empty())
        << op.cli << "/" << op.python << ": a front end is missing and the table says not why";
    if (!op.cli.empty()) {
      table_cli.insert(op.cli);
      EXPECT_TRUE(cli.count(op.cli)) << "zdg " << op.cli << " is not a subcommand";
    }
    if (!op.serve.empty()) {
      table_serve.insert(op.serve);
      EXPECT_TRUE(served.count(op.serve)) << "zdg serve does not answer '" << op.serve << "'";
    }
    if (!op.python.empty()) table_python.insert(op.python);
  }
  for (const auto& c : cli)
    EXPECT_TRUE(table_cli.count(c)) << "zdg " << c << " is not in the table";
  for (const auto& s : served)
    EXPECT_TRUE(table_serve.count(s)) << "served '" << s << "' is not in the table";

  const std::filesystem::path module_dir =
      std::filesystem::path(test::cli_path()).parent_path().parent_path() / "python";
  if (!std::filesystem::exists(module_dir / "zdg"))
    GTEST_SKIP() << "the Python module is not built";
  const auto r = test::run_python("import sys\nsys.path.insert(0, sys.argv[1])\nimport zdg\n"
                                  "print('\\n'.join(n for n in dir(zdg) if not n.startswith('_') "
                                  "and callable(getattr(zdg, n))))\n",
                                  {module_dir.string()});
  ASSERT_EQ(r.status, 0) << r.err;
  std::set<std::string> functions;
  std::istringstream in(r.out);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty()) functions.insert(line);
  }
  for (const auto& f : table_python)
    EXPECT_TRUE(functions.count(f)) << "the module has no function " << f;
  for (const auto& f : functions)
    EXPECT_TRUE(table_python.count(f)) << "zdg." << f << " is not in the table";
}

} // namespace
} // namespace zdg
