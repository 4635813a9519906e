// zdg csg: outputs equal the kernel's operations, the Betti numbers of the result and of the
// inputs in the JSON, one-line errors.
#include "tests/support/cli.hpp"
#include <zdg/kernel/images/csg.hpp>
#include <zdg/kernel/io/npy_io.hpp>
#include <zdg/kernel/topology/betti_numbers.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace zdg {
namespace {

struct Files {
  std::filesystem::path dir = test::scratch_dir("csg");
  ~Files() { std::filesystem::remove_all(dir); }
  std::string operator()(const std::string& name) const {
    std::string q(1, '\'');
    q.append((dir / name).string());
    q.push_back('\'');
    return q;
  }
  std::string path(const std::string& name) const { return (dir / name).string(); }
};

// A 7 x 7 square ring (one hole) and a bar across it.
std::vector<std::uint8_t> ring() {
  std::vector<std::uint8_t> v(49, 0);
  for (int y = 1; y <= 5; ++y) {
    for (int x = 1; x <= 5; ++x)
      v[static_cast<std::size_t>(y * 7 + x)] = (y == 1 || y == 5 || x == 1 || x == 5) ? 1 : 0;
  }
  return v;
}
std::vector<std::uint8_t> bar() {
  std::vector<std::uint8_t> v(49, 0);
  for (int x = 0; x < 7; ++x) v[static_cast<std::size_t>(3 * 7 + x)] = 1;
  return v;
}

TEST(CsgCommands, OperationsAndTheirTopology) {
  Files f;
  write_npy(f.path("ring.npy"), make_npy<std::uint8_t>({7, 7}, ring()));
  write_npy(f.path("bar.npy"), make_npy<std::uint8_t>({7, 7}, bar()));
  const Image<std::uint8_t> a(Domain({7, 7}), ring()), b(Domain({7, 7}), bar());
  // union: the bar splits the hole in two (b1 = 2); difference: the ring cut twice (2 pieces).
  struct Expect {
    std::string op;
    CsgOperation kind;
    std::string b0, b1;
  };
  for (const auto& e :
       {Expect{"union", CsgOperation::union_of, "1", "2"},
        Expect{"intersection", CsgOperation::intersection, "2", "0"},
        Expect{"difference", CsgOperation::difference, "2", "0"},
        Expect{"symmetric-difference", CsgOperation::symmetric_difference, "", ""}}) {
    auto r = test::run_zdg("csg " + e.op + " " + f("ring.npy") + " " + f("bar.npy") + " -o " +
                           f("out.npy") + " --force --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["command"], "csg " + e.op);
    const auto want_betti = betti_numbers(csg(e.kind, a, b), default_adjacency_pair(2));
    EXPECT_EQ(j["betti"][0], std::to_string(want_betti.b[0])) << e.op;
    EXPECT_EQ(j["betti"][1], std::to_string(want_betti.b[1])) << e.op;
    if (!e.b0.empty()) {
      EXPECT_EQ(j["betti"][0], e.b0) << e.op;
      EXPECT_EQ(j["betti"][1], e.b1) << e.op;
    }
    EXPECT_EQ(j["inputs"][0]["betti"], nlohmann::json::parse(R"(["1", "1"])"));
    EXPECT_EQ(j["inputs"][1]["betti"], nlohmann::json::parse(R"(["1", "0"])"));
    const auto got = npy_to_int64(read_npy(f.path("out.npy"))).values();
    const auto want = csg(e.kind, a, b).values();
    ASSERT_EQ(got.size(), want.size());
    EXPECT_TRUE(std::equal(got.begin(), got.end(), want.begin())) << e.op;
  }
  // The complement of the ring in its box, under (4,8): the outside and the hole (b0 = 2), and
  // the ring is its one hole (b1 = 1): Alexander duality.
  auto r = test::run_zdg("csg complement " + f("ring.npy") + " -o " + f("c.npy") +
                         " --adjacency 4,8 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["betti"], nlohmann::json::parse(R"(["2", "1"])"));
  EXPECT_EQ(j["voxels"], "33");
}

TEST(CsgCommands, ErrorsAreOneLineAndLeaveNoOutput) {
  Files f;
  write_npy(f.path("ring.npy"), make_npy<std::uint8_t>({7, 7}, ring()));
  write_npy(f.path("small.npy"), make_npy<std::uint8_t>({3, 3}, std::vector<std::uint8_t>(9, 1)));
  write_npy(f.path("cube.npy"), make_npy<std::uint8_t>({2, 2, 2}, std::vector<std::uint8_t>(8, 1)));
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"csg union " + f("ring.npy") + " " + f("small.npy") + " -o " + f("o.npy"),
       "the images differ in shape: (7, 7) and (3, 3)"},
      {"csg union " + f("ring.npy") + " " + f("missing.npy") + " -o " + f("o.npy"), "missing.npy"},
      {"csg complement " + f("cube.npy") + " -o " + f("o.pgm"), "is 2D and the result is 3D"},
      {"csg complement " + f("ring.npy") + " -o " + f("o.txt"), "o.txt"},
      {"csg complement " + f("ring.npy") + " -o " + f("o.npy") + " --adjacency 6,26", "6,26"},
      {"csg complement " + f("ring.npy") + " -o " + f("ring.npy"), "ring.npy"},
  };
  for (const auto& [cmd, what] : cases) {
    const auto r = test::run_zdg(cmd);
    EXPECT_EQ(r.status, 2) << cmd;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(what), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(f.path("o.npy")));
    EXPECT_FALSE(std::filesystem::exists(f.path("o.pgm")));
  }
  // An existing output is replaced only with --force.
  ASSERT_EQ(test::run_zdg("csg complement " + f("ring.npy") + " -o " + f("o.npy")).status, 0);
  EXPECT_EQ(test::run_zdg("csg complement " + f("ring.npy") + " -o " + f("o.npy")).status, 2);
  EXPECT_EQ(
      test::run_zdg("csg complement " + f("ring.npy") + " -o " + f("o.npy") + " --force").status,
      0);
}

} // namespace
} // namespace zdg
