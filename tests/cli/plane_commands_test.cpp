// zdg plane recognize|probe: JSON output checked against the kernel's theorems (the probed
// normal is the plane's own; a recognized set lies in the slab it prints) and exit status 2
// on bad input.
#include "tests/support/cli.hpp"

#include <zdg/arith/integer.hpp>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>

namespace {

using zdg::test::run_zdg;

class PlaneCli : public ::testing::Test {
protected:
  void SetUp() override { dir_ = zdg::test::scratch_dir("plane_input"); }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string write_file(const std::string& name, const std::string& text) {
    auto p = dir_ / name;
    std::ofstream(p) << text;
    return p.string();
  }

private:
  std::filesystem::path dir_;
};

TEST_F(PlaneCli, ProbeReturnsTheNormalWithBothAlgorithms) {
  for (const char* alg : {"h", "r"}) {
    auto r = run_zdg(std::string("plane probe --algorithm ") + alg + " --json -- 2 -6 15");
    ASSERT_EQ(r.status, 0) << r.err;
    auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["normal"], nlohmann::json({"2", "-6", "15"}));
    EXPECT_EQ(j["algorithm"], alg);
    EXPECT_EQ(j["plane"], "standard");
    EXPECT_EQ(j["served"], "int64");
    EXPECT_LE(j["steps"].get<int>(), 2 + 6 + 15 - 3); // the step bound of the header
  }
}

TEST_F(PlaneCli, ProbeBeyond64Bits) {
  // A random primitive normal of 70-bit components (R: about 200 steps, on Int128).
  auto r = run_zdg("plane probe --json -- 207188302008340381817 -242099146888925910983 "
                   "811906429599202878863");
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["normal"], nlohmann::json({"207188302008340381817", "-242099146888925910983",
                                         "811906429599202878863"}));
  EXPECT_EQ(j["served"], "int128");
  EXPECT_TRUE(j["reduced_basis"].get<bool>());
}

TEST_F(PlaneCli, RecognizeAStaircaseAndRefuseACube) {
  std::string stairs;
  for (int x = 0; x < 5; ++x)
    for (int y = 0; y < 5; ++y)
      stairs += std::to_string(x) + " " + std::to_string(y) + " " +
                std::to_string((x + 2 * y) / 3) + "\n";
  auto r = run_zdg("plane recognize " + write_file("stairs.txt", stairs) + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j["is_plane"].get<bool>());
  const zdg::BigInt a(j["normal"][0].get<std::string>()), b(j["normal"][1].get<std::string>()),
      c(j["normal"][2].get<std::string>()), mu(j["mu"].get<std::string>()),
      omega(j["omega"].get<std::string>());
  for (int x = 0; x < 5; ++x) {
    for (int y = 0; y < 5; ++y) {
      zdg::BigInt h = a * x + b * y + c * ((x + 2 * y) / 3);
      EXPECT_LE(mu, h);
      EXPECT_LT(h, mu + omega);
    }
  }
  auto cube =
      run_zdg("plane recognize " +
              write_file("cube.txt", "0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n") +
              " --json");
  ASSERT_EQ(cube.status, 0) << cube.err;
  EXPECT_FALSE(nlohmann::json::parse(cube.out)["is_plane"].get<bool>());
}

TEST_F(PlaneCli, BadInputIsOneLineAndStatusTwo) {
  for (const std::string& args :
       {std::string("plane probe 0 1 2"), std::string("plane probe 2 4 6"),
        std::string("plane probe 1 2 x"),
        std::string("plane probe 1 50 101 --algorithm h --max-steps 3"),
        std::string("plane recognize ") + write_file("bad.txt", "0 0 0\n1 2\n")}) {
    auto r = run_zdg(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
  }
}

} // namespace
