// zdg dss recognize | cover | subsegment: JSON formats, agreement with the library, errors with
// line numbers and exit status 2.
#include "tests/support/cli.hpp"
#include "tests/support/contours.hpp"
#include <zdg/arith/dsl_subsegment.hpp>
#include <zdg/kernel/curves/maximal_segments.hpp>

#include <nlohmann/json.hpp>

#include <fstream>
#include <string>

namespace {

using nlohmann::json;
using zdg::test::run_zdg;

// 'path' for the shell (appended piecewise: GCC 12 warns wrongly on "'" + s + "'").
std::string quoted(const std::filesystem::path& p) {
  std::string q(1, '\'');
  q.append(p.string());
  q.push_back('\'');
  return q;
}

std::string write(const std::filesystem::path& dir, const std::string& name,
                  const std::string& text) {
  auto p = dir / name;
  std::ofstream(p) << text;
  return quoted(p);
}

TEST(DssCli, RecognizeADss) {
  auto dir = zdg::test::scratch_dir("dss");
  std::string pts = "# y = floor(3x/7)\n";
  for (int x = 0; x < 20; ++x) pts += std::to_string(x) + " " + std::to_string(3 * x / 7) + "\n";
  auto r = run_zdg("dss recognize " + write(dir, "line.txt", pts) + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(json::parse(r.out),
            json::parse(R"({"is_dss":true,"connectivity":8,"a":"3","b":"7","integer_type":"int64",
                                                "mu":"0","omega":"7"})"));
  // A 4-connected staircase given as a Freeman chain: two periods of 00101 (three steps (1,0),
  // two steps (0,1)), a conjugate of the Christoffel word of 2/3: a standard DSS of slope 2/3.
  r = run_zdg("dss recognize " + write(dir, "chain.txt", "10 -4 0010100101\n") + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = json::parse(r.out);
  EXPECT_EQ(j["connectivity"], 4);
  EXPECT_EQ(j["is_dss"], true);
  EXPECT_EQ(j["a"], "2");
  EXPECT_EQ(j["b"], "3");
  EXPECT_EQ(j["omega"], "5");
  // 0011 is not balanced (00 and 11): the first 4 points only.
  r = run_zdg("dss recognize " + write(dir, "chain.txt", "10 -4 0011\n") + " --json");
  EXPECT_EQ(json::parse(r.out),
            json::parse(
                R"({"is_dss":false,"connectivity":4,"longest_prefix":4,"integer_type":"int64"})"));
  std::filesystem::remove_all(dir);
}

TEST(DssCli, RecognizeReportsTheLongestPrefix) {
  auto dir = zdg::test::scratch_dir("dss");
  // Steps (1,1) (1,1) (1,0) (1,0): both 11 and 00 occur, the fifth point breaks the DSS.
  auto r = run_zdg("dss recognize " + write(dir, "p.txt", "0 0\n1 1\n2 2\n3 2\n4 2\n") + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(json::parse(r.out),
            json::parse(
                R"({"is_dss":false,"connectivity":8,"longest_prefix":4,"integer_type":"int64"})"));
  r = run_zdg("dss recognize " + write(dir, "p.txt", "5 5\n") + " --json");
  EXPECT_EQ(json::parse(r.out),
            json::parse(R"({"is_dss":true,"connectivity":4,"a":"0","b":"1","integer_type":"int64",
                                                "mu":"-5","omega":"1"})"));
  std::filesystem::remove_all(dir);
}

TEST(DssCli, HugeCoordinates) {
  auto dir = zdg::test::scratch_dir("dss");
  // Beyond 64 bits: points (2^70 + x, x) for x = 0..3, slope 1 (omega 1).
  std::string big = "1180591620717411303424"; // 2^70
  std::string pts;
  for (int x = 0; x < 4; ++x) {
    pts += big.substr(0, big.size() - 1) + std::to_string(4 + x) + " " + std::to_string(x) + "\n";
  }
  auto r = run_zdg("dss recognize " + write(dir, "h.txt", pts) + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = json::parse(r.out);
  EXPECT_EQ(j["a"], "1");
  EXPECT_EQ(j["b"], "1");
  EXPECT_EQ(j["mu"], big); // x - y = 2^70 on every point
  std::filesystem::remove_all(dir);
}

TEST(DssCli, CoverMatchesTheLibrary) {
  auto dir = zdg::test::scratch_dir("dss");
  auto c = zdg::test::disc_contour(3, -2, 50);
  std::string pts;
  for (const auto& p : c) pts += std::to_string(p.x) + " " + std::to_string(p.y) + "\n";
  auto r = run_zdg("dss cover " + write(dir, "disc.txt", pts) + " --closed --json");
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = json::parse(r.out);
  auto segs = zdg::maximal_segments_exact(c, true).value;
  ASSERT_EQ(j["segments"].size(), segs.size());
  EXPECT_EQ(j["closed"], true);
  EXPECT_EQ(j["connectivity"], 4);
  for (std::size_t k = 0; k < segs.size(); ++k) {
    const auto& s = j["segments"][k];
    EXPECT_EQ(s, (json{{"begin", segs[k].begin},
                       {"end", segs[k].end},
                       {"a", std::to_string(segs[k].a)},
                       {"b", std::to_string(segs[k].b)},
                       {"mu", zdg::to_string(zdg::Int128(segs[k].mu))}}));
  }
  // The rectangle of pointels as a closed Freeman chain (the repeated start is dropped).
  r = run_zdg("dss cover " + write(dir, "rect.txt", "0 0 0001122233\n") + " --closed --json");
  ASSERT_EQ(r.status, 0) << r.err;
  j = json::parse(r.out);
  ASSERT_EQ(j["segments"].size(), 8u);
  EXPECT_EQ(j["segments"][0], json::parse(R"({"begin":7,"end":0,"a":"-2","b":"-1","mu":"0"})"));
  // Greedy segmentation of an open path.
  r = run_zdg("dss cover " + write(dir, "rect.txt", "0 0 0001122233\n") + " --greedy --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(json::parse(r.out)["segments"][0]["end"], 4);
  std::filesystem::remove_all(dir);
}

TEST(DssCli, Subsegment) {
  auto r = run_zdg("dss subsegment 3 7 0 0 3 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(json::parse(r.out), json::parse(R"({"a":"1","b":"3","mu":"0"})"));
  // Values near 2^62 (negative MU and X0 included) agree with the library.
  r = run_zdg("dss subsegment 2305843009213706257 4611686018427387847 -123456789012345 "
              "-4611686018427387000 -4611686018427380000 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  auto want = zdg::dsl_subsegment_exact(
                  zdg::BigInt("2305843009213706257"), zdg::BigInt("4611686018427387847"),
                  zdg::BigInt("-123456789012345"), zdg::BigInt("-4611686018427387000"),
                  zdg::BigInt("-4611686018427380000"))
                  .value;
  EXPECT_EQ(json::parse(r.out),
            (json{{"a", want.a.str()}, {"b", want.b.str()}, {"mu", want.mu.str()}}));
  // SmartDSS gives the same output, JSON and text.
  for (std::string args : {"3 7 0 0 3", "2305843009213706257 4611686018427387847 -123456789012345 "
                                        "-4611686018427387000 -4611686018427380000"}) {
    for (std::string fmt : {" --json", ""}) {
      auto reversed = run_zdg("dss subsegment " + args + fmt);
      auto smart = run_zdg("dss subsegment " + args + " --algorithm smart" + fmt);
      ASSERT_EQ(smart.status, 0) << smart.err;
      EXPECT_EQ(smart.out, reversed.out) << args << fmt;
      EXPECT_EQ(run_zdg("dss subsegment " + args + " --algorithm reversed" + fmt).out,
                reversed.out);
    }
  }
}

TEST(DssCli, ErrorsNameTheLineOrValueAndExitWithTwo) {
  auto dir = zdg::test::scratch_dir("dss");
  struct Case {
    std::string args, message;
  };
  std::vector<Case> cases{
      {"dss recognize " + write(dir, "a.txt", "0 0\n1 0\n\n3 0\n"), "a.txt:4: point (3, 0)"},
      {"dss recognize " + write(dir, "b.txt", "0 0\n1 x\n"), "b.txt:2: expected two integers"},
      {"dss recognize " + write(dir, "c.txt", "0 0 0140\n"),
       "c.txt:1: Freeman chain: invalid code '4'"},
      {"dss recognize " + quoted(dir / "missing.txt"), "cannot open"},
      {"dss cover " + write(dir, "d.txt", "0 0\n1 0\n2 0\n") + " --closed",
       "d.txt:1: the last point"},
      {"dss recognize " + write(dir, "e.txt", "0 0\n1 1\n") + " --connectivity 4",
       "not 4-adjacent"},
      {"dss subsegment 3 7 0 10 2", "X1 = 2 is smaller than X0 = 10"},
      {"dss subsegment 3 0 0 0 2", "B = 0 must be > 0"},
      {"dss subsegment 7 7 0 0 2", "0 <= A < B"},
      {"dss subsegment 1 2 z 0 2", "MU = 'z'"},
      {"dss subsegment 1 2 0 0 2 --algorithm fast", "--algorithm"},
  };
  for (const auto& c : cases) {
    auto r = run_zdg(c.args);
    EXPECT_EQ(r.status, 2) << c.args;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << " -> " << r.err;
    EXPECT_EQ(r.err.rfind("zdg: ", 0), 0u) << r.err;
  }
  std::filesystem::remove_all(dir);
}

} // namespace
