// zdg topology: JSON summaries, outputs checked against the kernel, bad-input rows.
#include "tests/support/binary_images.hpp"
#include "tests/support/cli.hpp"
#include <zdg/kernel/io/npy_io.hpp>
#include <zdg/kernel/io/pgm_io.hpp>
#include <zdg/kernel/topology/betti_numbers.hpp>
#include <zdg/kernel/topology/connected_components.hpp>
#include <zdg/kernel/topology/critical_kernel_thinning.hpp>
#include <zdg/kernel/topology/homotopic_thinning.hpp>
#include <zdg/kernel/topology/simple_points.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

namespace zdg {
namespace {

struct Files {
  std::filesystem::path dir = test::scratch_dir("topology");
  ~Files() { std::filesystem::remove_all(dir); }
  std::string operator()(const std::string& name) const {
    return "'" + (dir / name).string() + "'";
  }
  std::string path(const std::string& name) const { return (dir / name).string(); }
};

void save(const std::string& path, const Image<std::uint8_t>& img) {
  write_npy(path, make_npy<std::uint8_t>(img.domain().extents(), img.values()));
}

Image<std::uint8_t> load_mask(const std::string& path) {
  return npy_to_mask(read_npy(path));
}

TEST(TopologyCommands, BettiJsonIn3DAnd2D) {
  Files f;
  const auto torus = test::torus_image(8, 3);
  save(f.path("torus.npy"), torus);
  for (const std::string pair : {"26,6", "6,26", "18,6", "6,18"}) {
    auto r = test::run_zdg("topology betti " + f("torus.npy") + " --adjacency " + pair + " --json");
    ASSERT_EQ(r.status, 0) << r.err;
    auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["betti"], nlohmann::json::array({"1", "1", "0"}));
    EXPECT_EQ(j["components"], "1");
    EXPECT_EQ(j["adjacency"], pair);
    std::int64_t n = 0;
    for (auto v : torus.values()) n += v;
    EXPECT_EQ(j["voxels"], std::to_string(n));
    EXPECT_TRUE(j["seconds"].is_number());
  }
  // 2D from a PGM with a threshold: an annulus of grey level 200 on 100: (1, 1).
  const auto ring = test::annulus_image(10, 20, 90);
  Image<std::uint64_t> grey(ring.domain(), std::uint64_t{100});
  for (std::int64_t i = 0; i < ring.size(); ++i) {
    if (ring[i] != 0) grey[i] = 200;
  }
  write_pgm(f.path("ring.pgm"), grey);
  auto r = test::run_zdg("topology betti " + f("ring.pgm") + " --threshold 150 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["betti"], nlohmann::json::array({"1", "1"}));
  EXPECT_EQ(j["adjacency"], "8,4");
}

TEST(TopologyCommands, OutputsEqualTheKernel) {
  Files f;
  const auto img = test::torus_image(9, 3);
  save(f.path("in.npy"), img);
  // Components: labels by decreasing size.
  auto r = test::run_zdg("topology components " + f("in.npy") + " -o " + f("lab.npy") + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto labels = npy_to_int64(read_npy(f.path("lab.npy")));
  const auto c = connected_components(img, 26);
  for (std::int64_t i = 0; i < img.size(); ++i) EXPECT_EQ(labels[i], c.labels[i]);
  // Skeleton (sequential, curve) and thin (critical kernel, ultimate).
  r = test::run_zdg("topology skeleton " + f("in.npy") + " -o " + f("sk.npy") + " --json --quiet");
  ASSERT_EQ(r.status, 0) << r.err;
  ThinningOptions opt;
  opt.skeleton = SkeletonKind::curve;
  const auto sk = homotopic_thinning(img, opt);
  EXPECT_EQ(load_mask(f.path("sk.npy")), sk.skeleton);
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["deleted"], std::to_string(sk.deleted));
  EXPECT_EQ(j["betti"], nlohmann::json::array({"1", "1", "0"}));
  r = test::run_zdg("topology thin " + f("in.npy") + " -o " + f("th.npy") +
                    " --method critical-kernel --threads 3 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(load_mask(f.path("th.npy")), critical_kernel_thinning(img).skeleton);
  // A user priority (the opposite of the axis-0 coordinate) and anchors.
  Image<std::int64_t> prio(img.domain(), std::int64_t{0});
  Image<std::uint8_t> anchors(img.domain(), std::uint8_t{0});
  for (std::int64_t i = 0; i < img.size(); ++i) prio[i] = -img.domain().point(i)[0];
  anchors[img.size() / 2] = 1;
  write_npy(f.path("prio.npy"), make_npy<std::int64_t>(img.domain().extents(), prio.values()));
  save(f.path("anchors.npy"), anchors);
  r = test::run_zdg("topology thin " + f("in.npy") + " -o " + f("p.npy") + " --priority " +
                    f("prio.npy") + " --anchors " + f("anchors.npy") + " --adjacency 6,26");
  ASSERT_EQ(r.status, 0) << r.err;
  ThinningOptions po;
  po.pair = {3, 6, 26};
  po.priority = &prio;
  po.anchors = &anchors;
  EXPECT_EQ(load_mask(f.path("p.npy")), homotopic_thinning(img, po).skeleton);
  // Simple points.
  r = test::run_zdg("topology simple " + f("in.npy") + " -o " + f("s.npy") + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto s = load_mask(f.path("s.npy"));
  std::int64_t count = 0;
  for (std::int64_t i = 0; i < img.size(); ++i) {
    if (img[i] == 0) continue;
    const bool simple = is_simple_by_definition({3, 26, 6}, neighbourhood_configuration(img, i));
    EXPECT_EQ(s[i] != 0, simple);
    count += simple;
  }
  EXPECT_EQ(nlohmann::json::parse(r.out)["simple"], std::to_string(count));
}

// Bad input: one line on stderr, exit 2, nothing created, an existing output untouched.
// Issue #35: --html on a skeleton writes the viewer page of the result's voxels: as many faces
// as zdg surface counts surfels on the written skeleton; a 2D input is refused before any work.
TEST(TopologyCommands, SkeletonViewerPageHoldsTheResultsBoundary) {
  Files f;
  save(f.path("in.npy"), test::torus_image(9, 3));
  auto r = test::run_zdg("topology skeleton " + f("in.npy") + " -o " + f("sk.npy") + " --html " +
                         f("sk.html") + " --quiet");
  ASSERT_EQ(r.status, 0) << r.err;
  r = test::run_zdg("surface " + f("sk.npy") + " --adjacency 26,6 --json --quiet");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto surfels = nlohmann::json::parse(r.out)["surfels"].get<std::string>();
  const std::string page = test::read_file(f.path("sk.html"));
  EXPECT_NE(page.find("\"faces\":" + surfels + ","), std::string::npos) << surfels;
  Image<std::uint8_t> flat(Domain({5, 5}), std::uint8_t{1});
  flat[12] = 0;
  save(f.path("flat.npy"), flat);
  r = test::run_zdg("topology skeleton " + f("flat.npy") + " -o " + f("fs.npy") + " --html " +
                    f("fs.html"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--html shows 3D results"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(f.path("fs.npy")));
}

TEST(TopologyCommands, BadInputRows) {
  Files f;
  save(f.path("in.npy"), test::torus_image(6, 2));
  save(f.path("empty.npy"), Image<std::uint8_t>(Domain({4, 4, 4}), std::uint8_t{0}));
  write_npy(f.path("prio.npy"),
            make_npy<std::int64_t>({4, 4, 5}, std::vector<std::int64_t>(80, 0)));
  save(f.path("line.npy"), Image<std::uint8_t>(Domain({5}), std::uint8_t{1}));
  {
    std::ofstream keep(f.path("existing.npy"));
    keep << "keep me";
  }
  struct Row {
    std::string args, message;
  };
  const Row rows[] = {
      {"betti " + f("empty.npy"), "selects no voxel"},
      {"thin " + f("in.npy") + " -o " + f("o.npy") + " --threshold 2", "selects no voxel"},
      {"betti " + f("in.npy") + " --adjacency 26,26", "not admissible"},
      {"betti " + f("in.npy") + " --adjacency 8,4", "not admissible"},
      {"components " + f("in.npy") + " --adjacency 6-26", "is not K,KBAR"},
      {"thin " + f("in.npy") + " -o " + f("o.npy") + " --priority " + f("prio.npy"),
       "another size"},
      {"thin " + f("in.npy") + " -o " + f("o.npy") + " --anchors " + f("prio.npy"), "another size"},
      {"thin " + f("in.npy") + " -o " + f("o.npy") + " --method magic", "--method"},
      {"thin " + f("in.npy") + " -o " + f("o.npy") + " --skeleton bones", "skeleton"},
      {"thin " + f("in.npy") + " -o " + f("o.npy") + " --method critical-kernel --adjacency 6,26",
       "critical-kernel"},
      {"thin " + f("in.npy") + " -o " + f("o.npy") + " --method critical-kernel --priority " +
           f("in.npy"),
       "sequential only"},
      {"thin " + f("in.npy"), "no output"},
      {"thin " + f("in.npy") + " -o " + f("o.txt"), "unknown output format"},
      {"thin " + f("in.npy") + " -o " + f("o.pgm"), ".pgm image is 2D"},
      {"thin " + f("in.npy") + " -o " + f("existing.npy"), "exists"},
      {"components " + f("in.npy") + " -o " + f("in.npy") + " --force", "input file"},
      {"betti " + f("missing.npy"), "no such file"},
      {"betti " + f("line.npy"), "1-D array is not a volume"},
      {"betti " + f("in.npy") + " -o " + f("o.npy"), "writes no file"},
  };
  for (const auto& row : rows) {
    const auto before = std::distance(std::filesystem::directory_iterator(f.dir),
                                      std::filesystem::directory_iterator{});
    auto r = test::run_zdg("topology " + row.args);
    EXPECT_EQ(r.status, 2) << row.args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(row.message), std::string::npos) << row.args << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << row.args;
    const auto after = std::distance(std::filesystem::directory_iterator(f.dir),
                                     std::filesystem::directory_iterator{});
    EXPECT_EQ(after, before) << row.args;
    EXPECT_EQ(test::read_file(f.path("existing.npy")), "keep me");
  }
}

// zdg topology graph: a ring (solid torus) has one loop; a plus-shaped object
// one junction with four branches to four ends; the loops are b1 of the skeleton.
TEST(TopologyCommands, GraphOfRingAndPlus) {
  Files f;
  save(f.path("torus.npy"), test::torus_image(8, 3));
  auto r = test::run_zdg("topology graph " + f("torus.npy") + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["command"], "graph");
  EXPECT_EQ(j["loops"], 1);
  EXPECT_EQ(j["betti"][1], "1");
  double length = 0;
  for (const auto& b : j["branches"]) length += b["length"].get<double>();
  EXPECT_GT(length, 40.0); // the core circle: 2 pi 8
  const std::int64_t n = 21;
  Image<std::uint8_t> plus(Domain({7, n, n}), std::uint8_t{0});
  for (std::int64_t z = 2; z <= 4; ++z) {
    for (std::int64_t t = 2; t < n - 2; ++t) {
      for (std::int64_t u = 9; u <= 11; ++u) {
        plus[(z * n + t) * n + u] = 1;
        plus[(z * n + u) * n + t] = 1;
      }
    }
  }
  save(f.path("plus.npy"), plus);
  for (const std::string method : {"sequential", "critical-kernel"}) {
    r = test::run_zdg("topology graph " + f("plus.npy") + " --method " + method + " --json");
    ASSERT_EQ(r.status, 0) << r.err;
    j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["junctions"], 1) << method;
    EXPECT_EQ(j["ends"], 4) << method;
    EXPECT_EQ(j["loops"], 0);
    ASSERT_EQ(j["branches"].size(), 4u);
    for (const auto& b : j["branches"]) {
      EXPECT_GT(b["length"].get<double>(), 0.0);
      EXPECT_EQ(b["radii"].size(), b["voxels"].get<std::size_t>());
    }
    for (const auto& node : j["nodes"]) {
      if (node["kind"] == "junction") {
        EXPECT_EQ(node["degree"], 4);
      }
    }
  }
  r = test::run_zdg("topology graph " + f("plus.npy"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("junctions 1"), std::string::npos) << r.out;
  r = test::run_zdg("topology graph " + f("plus.npy") + " -o " + f("g.npy"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("writes no file"), std::string::npos) << r.err;
}

} // namespace
} // namespace zdg

namespace zdg {
namespace {

// zdg topology betti --generators: the PLY holds b_k cycles per dimension (the header's comment
// and the JSON agree with the Betti numbers), and the edges of each 1-cycle meet every vertex an
// even number of times (a cycle mod 2).
TEST(TopologyCommands, BettiGeneratorsWriteCyclesToPly) {
  Files f;
  save(f.path("torus.npy"), test::torus_image(8, 3));
  const auto r = test::run_zdg("topology betti " + f("torus.npy") + " --generators -o " +
                               f("cycles.ply") + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["generators"], nlohmann::json::parse("[1, 1, 0]"));
  EXPECT_EQ(j["betti"], nlohmann::json::array({"1", "1", "0"}));
  std::ifstream in(f.path("cycles.ply"));
  std::string line;
  std::map<std::string, std::int64_t> count;
  bool betti = false;
  while (std::getline(in, line) && line != "end_header") {
    if (line == "comment betti 1 1 0") betti = true;
    std::istringstream w(line);
    std::string word, name;
    std::int64_t n = 0;
    if (w >> word >> name >> n && word == "element") count[name] = n;
  }
  EXPECT_TRUE(betti);
  ASSERT_GT(count["vertex"], 0);
  EXPECT_EQ(count["point"], 1);
  EXPECT_EQ(count["face"], 0);
  for (std::int64_t i = 0; i < count["vertex"] + count["point"]; ++i) std::getline(in, line);
  std::map<std::int64_t, int> degree;
  for (std::int64_t i = 0; i < count["edge"]; ++i) {
    std::int64_t a = 0, b = 0, cycle = 0;
    in >> a >> b >> cycle;
    EXPECT_EQ(cycle, 1);
    ++degree[a];
    ++degree[b];
  }
  ASSERT_GE(degree.size(), 8u);
  for (const auto& [v, k] : degree) EXPECT_EQ(k % 2, 0) << "vertex " << v;
}

} // namespace
} // namespace zdg
