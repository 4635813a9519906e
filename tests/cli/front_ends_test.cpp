// Every operation of zdg is reachable from the three front ends (issue #34): the command line,
// zdg serve and the Python module, or the table below says why not. The table is checked both
// ways: each entry it claims exists (`zdg CLI --help` succeeds, `zdg serve` knows the
// operation, the module has the function), and each subcommand, served operation and public
// Python function is in the table, so that a new one cannot be added to one front end
// silently.
#include "tests/support/cli.hpp"
#include "tests/support/python.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
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
  static const std::string kIntegerImage = "serve: takes an image of integer values (weights, "
                                           "squared radii); a served 'image' is a binary mask";
  static const std::vector<Operation> ops = {
      {"cf", "cf", "cf", ""},
      {"christoffel", "christoffel", "christoffel", ""},
      {"floor-sum", "floor-sum", "floor_sum", ""},
      {"dss recognize", "dss recognize", "recognize_dss", ""},
      {"dss cover", "dss cover", "tangential_cover", ""},
      {"dss subsegment", "dss subsegment", "dsl_subsegment", ""},
      {"hull points", "hull points", "hull", ""},
      {"hull disc", "hull disc", "hull_disc", ""},
      {"hull ellipse", "hull ellipse", "hull_ellipse", ""},
      {"hull halfplanes", "hull halfplanes", "hull_halfplanes", ""},
      {"plane recognize", "plane recognize", "recognize_plane", ""},
      {"plane probe", "plane probe", "probe_plane", ""},
      {"transform dt", "transform dt", "distance_transform", ""},
      {"transform voronoi", "transform voronoi", "voronoi_map", ""},
      {"transform power", "", "power_map", kIntegerImage},
      {"transform rdt", "", "reverse_distance_transform", kIntegerImage},
      {"transform rma", "", "reduced_medial_axis", kIntegerImage},
      {"transform chamfer", "transform chamfer", "chamfer_transform", ""},
      {"sturmian", "sturmian", "sturmian", ""},
      {"csg union", "", "",
       "serve and Python: numpy's logical operators on arrays; the command adds the volume files "
       "and the Betti numbers (kernel/images/csg.hpp)"},
      {"csg intersection", "", "", "as csg union"},
      {"csg difference", "", "", "as csg union"},
      {"csg symmetric-difference", "", "", "as csg union"},
      {"csg complement", "", "", "as csg union"},
      {"motion check", "", "motion_check",
       "serve: not served yet (Python's motion_check is the certificate of one rotation; the "
       "check of a volume works on files)"},
      {"motion apply", "", "", files},
      {"hull delaunay", "", "",
       "not served or bound yet: a report of cells and exact Voronoi vertices from a point file "
       "(kernel/hulls/lattice_delaunay.hpp)"},
      {"topology components", "topology components", "connected_components", ""},
      {"topology betti", "topology betti", "betti_numbers", ""},
      {"topology simple", "topology simple", "simple_points", ""},
      {"topology thin", "", "thinning",
       "serve: 'topology skeleton' with \"skeleton\": \"ultimate\" is this thinning"},
      {"topology skeleton", "topology skeleton", "skeleton", ""},
      {"surface", "surface", "surface", ""},
      {"contour", "contour", "contour", ""},
      {"convert", "", "", "serve: " + files + " (read_volume, write_volume)"},
      {"", "", "read_volume", "command line: zdg convert reads and writes; serve: " + files},
      {"", "", "write_volume", "command line: zdg convert reads and writes; serve: " + files},
      {"", "", "surfels", "command line and serve: part of zdg surface"},
      {"", "", "ii_curvature", "command line and serve: zdg surface --estimate ii-*"},
      {"converge", "", "converge", "serve: an experiment is not a request"},
      {"", "", "plot",
       "command line: zdg converge and zdg paper draw their plots; serve: a "
       "picture is not a JSON answer"},
      {"view", "", "view",
       "serve: a page is not a JSON answer (Python's view takes a mesh or a surface() result, "
       "not a .ply)"},
      {"", "", "Viewer", "the page object zdg.view returns (_repr_html_, save)"},
      {"", "", "mesh_html",
       "command line: zdg view and the commands' --html write the page; serve: a page is not a "
       "JSON answer"},
      {"paper", "", "", "serve and Python: reproduces a figure from the repository's papers/"},
      {"laplacians", "", "",
       "serve and Python: the measurement behind papers/laplacian-comparison (zdg paper runs it); "
       "the operators themselves are reached through zdg converge's lb-* estimators"},
      {"mesh at", "", "",
       "serve and Python: works on files (a .ply mesh in, a .ply mesh with the fields out)"},
      {"reconstruct", "", "reconstruct",
       "serve: a point cloud of 10^5 points is not a line of JSON; the command reads point "
       "files, Python takes arrays"},
      {"normals", "", "",
       "serve and Python: works on files (a point cloud in, the points with their normals out); "
       "the library function is estimators/point_normals.hpp"},
      {"render volume", "", "",
       "serve and Python: writes a picture file (a served answer is JSON; Python users have "
       "matplotlib); the library function is kernel/render/volume_render.hpp"},
      {"check", "", "", "the client of zdg serve; Python implementations are checked by it"},
      {"serve", "", "", "the server itself"},
      {"convex check", "convex check", "convex_check", ""},
      {"convex envelope", "", "",
       "serve and Python: works on files (a point file in, a point file out); the library "
       "function is fully_convex_envelope_exact (kernel/hulls/digital_convexity.hpp)"},
      {"transform thickness", "", "local_thickness",
       "serve: a served image answers exact integers, the thickness is float32 diameters (its "
       "exact R2 is local_thickness_squared_radius in kernel/transforms/local_thickness.hpp)"},
      {"topology graph", "", "",
       "serve and Python: not bound yet (issue #39 names the command line); the library "
       "function is kernel/topology/skeleton_graph.hpp"},
      {"topology persistence", "", "",
       "serve and Python: not bound yet (issue #39 names the command line); the library "
       "function is cubical_persistence (kernel/topology/cubical_persistence.hpp)"},
      {"voxelize", "", "",
       "serve and Python: works on files (a mesh in, a volume out); the library function is "
       "voxelize (kernel/digitization/voxelize.hpp)"},
      {"dag", "", "voxel_dag",
       "serve: not served yet (Python's voxel_dag and dag_ray_hits take arrays; the command also "
       "streams a mesh's voxelization)"},
      {"", "", "dag_ray_hits", "command line and serve: zdg dag --ray"},
      {"render dag", "", "",
       "serve and Python: writes a picture file; the library function is render_dag "
       "(kernel/render/dag_render.hpp)"},
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

// The operations added to zdg serve answer what the command line prints (same keys, same
// values) on the same input: the contours of an image with a hole, an ellipse hull, the
// half-plane hull of a triangle, a plane segment, the components and simple points of an image.
TEST(FrontEnds, ServedOperationsAnswerWhatTheCommandLinePrints) {
  const auto dir = test::scratch_dir("front_ends_serve");
  // A 7 x 6 image: a ring (one hole) and an isolated pixel, as PGM for the command line.
  const std::vector<std::string> rows = {"0000000", "0111100", "0100100",
                                         "0111100", "0000000", "0000001"};
  std::string pgm = "P2\n7 6\n1\n", image = "[";
  for (const auto& row : rows) {
    image += std::string(image.size() > 1 ? "," : "") + "[";
    for (std::size_t x = 0; x < row.size(); ++x) {
      pgm += std::string(1, row[x]) + (x + 1 < row.size() ? " " : "\n");
      image += std::string(x > 0 ? "," : "") + row[x];
    }
    image += "]";
  }
  image += "]";
  {
    std::ofstream f(dir / "ring.pgm");
    f << pgm;
  }
  const auto serve = [](const std::string& op, const std::string& request) {
    const auto r = test::run_zdg("serve " + op, request + "\n");
    EXPECT_EQ(r.status, 0) << r.err;
    return nlohmann::json::parse(r.out);
  };
  const auto cli = [](const std::string& args) {
    const auto r = test::run_zdg(args);
    EXPECT_EQ(r.status, 0) << args << ": " << r.err;
    return nlohmann::json::parse(r.out);
  };

  auto sc =
      serve("contour", "{\"image\":" + image + ",\"estimates\":[\"mlp-length\",\"gauss-area\"]}");
  auto cc = cli("contour " + (dir / "ring.pgm").string() +
                " --estimate mlp-length,gauss-area --json --quiet");
  for (const char* k : {"adjacency", "betti", "euler", "linels", "contours", "estimates"})
    EXPECT_EQ(sc[k], cc[k]) << k << ": " << sc[k].dump() << " vs " << cc[k].dump();
  EXPECT_EQ(sc["betti"], nlohmann::json({"2", "1"}));

  auto se = serve("hull ellipse", R"({"cx":"1/2","cy":"0","a":"7","b":"3"})");
  auto ce = cli("hull ellipse 1/2 0 7 3 --json");
  EXPECT_EQ(se["vertices"], ce["vertices"]) << se.dump() << " vs " << ce.dump();

  {
    std::ofstream f(dir / "triangle.txt");
    f << "-1 0 0\n0 -1 0\n1 1 7/2\n";
  }
  auto sh = serve("hull halfplanes", R"({"halfplanes":[[-1,0,0],[0,-1,0],[1,1,"7/2"]]})");
  auto ch = cli("hull halfplanes " + (dir / "triangle.txt").string() + " --json");
  EXPECT_EQ(sh["vertices"], ch["vertices"]) << sh.dump() << " vs " << ch.dump();
  EXPECT_EQ(sh["vertices"].size(), 3u) << sh.dump(); // (0,0), (3,0), (0,3)

  {
    std::ofstream f(dir / "plane.txt");
    for (int x = 0; x < 4; ++x)
      for (int y = 0; y < 4; ++y) f << x << " " << y << " " << (2 * x + y) / 3 << "\n";
  }
  std::string pts = "[";
  for (int x = 0; x < 4; ++x)
    for (int y = 0; y < 4; ++y)
      pts += std::string(pts.size() > 1 ? "," : "") + "[" + std::to_string(x) + "," +
             std::to_string(y) + "," + std::to_string((2 * x + y) / 3) + "]";
  pts += "]";
  auto sp = serve("plane recognize", "{\"points\":" + pts + "}");
  auto cp = cli("plane recognize " + (dir / "plane.txt").string() + " --json");
  for (const char* k : {"is_plane", "normal", "mu", "omega", "points"})
    EXPECT_EQ(sp[k], cp[k]) << k << ": " << sp.dump() << " vs " << cp.dump();
  EXPECT_TRUE(sp["is_plane"].get<bool>());

  auto sk = serve("topology components", "{\"image\":" + image + "}");
  auto ck = cli("topology components " + (dir / "ring.pgm").string() + " --json");
  EXPECT_EQ(sk["components"], ck["components"]) << sk.dump() << " vs " << ck.dump();
  EXPECT_EQ(sk["sizes"], nlohmann::json({"10", "1"}));
  EXPECT_EQ(sk["labels"][1][1], 1);
  EXPECT_EQ(sk["labels"][5][6], 2);

  auto ss = serve("topology simple", "{\"image\":" + image + "}");
  auto cs = cli("topology simple " + (dir / "ring.pgm").string() + " --json");
  EXPECT_EQ(ss["count"], cs["simple"]) << ss.dump() << " vs " << cs.dump();
  std::filesystem::remove_all(dir);
}

} // namespace
} // namespace zdg
