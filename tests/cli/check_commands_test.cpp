// zdg check and zdg serve: campaigns on zdg's own answers, and on external commands through the
// line-JSON protocol. Planted bugs (tests/cli/check_planted/*.py, run with
// /usr/bin/python3) wrong only on negative inputs, only past 2^63, only for 4-connected paths,
// only on one octant, are each caught within 2,000 runs and shrunk to a small input; zdg serve
// passes 10,000 runs; a command that crashes, exits, hangs or answers garbage ends with exit 1
// and one clear line, within --request-timeout even when its answer line never ends.
// What runs here: cli/serve_commands.cpp (the request loop) and serve_handlers.cpp
// (the answers), cli/external_command.cpp and external_command.hpp (the pipes of
// --against, two batches in flight), and the properties of convergence/check/
// (arith_properties.cpp, dss_properties.cpp, hull_properties.cpp, image_properties.cpp,
// plane_properties.cpp) through zdg check.
#include "tests/support/cli.hpp"
#include "tests/support/paths.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <set>
#include <string>

namespace {

using nlohmann::json;

const std::string kPlanted = std::string(zdg::test::source_dir()) + "/tests/cli/check_planted/";
const std::string kZdg = zdg::test::cli_path();

std::string python(const std::string& script, const std::string& args = "") {
  return "'/usr/bin/python3 " + kPlanted + script + (args.empty() ? "" : " " + args) + "'";
}

json run_json(const std::string& args, int expected_status) {
  auto r = zdg::test::run_zdg(args + " --json --quiet");
  EXPECT_EQ(r.status, expected_status) << args << "\n" << r.err;
  return json::parse(r.out);
}

std::string abs_text(const std::string& s) {
  return s[0] == '-' ? s.substr(1) : s;
}

TEST(CheckCommand, ListNamesEveryPropertyWithItsTheoremAndCost) {
  auto j = run_json("check --list", 0);
  std::set<std::string> names;
  for (const auto& p : j["properties"]) {
    names.insert(p["name"].get<std::string>());
    EXPECT_FALSE(p["theorem"].get<std::string>().empty());
    EXPECT_FALSE(p["source"].get<std::string>().empty());
    EXPECT_TRUE(p["cost"] == "cheap" || p["cost"] == "moderate" || p["cost"] == "heavy");
  }
  for (const char* n :
       {"floor_sum.oracle", "cf.roundtrip", "christoffel.factorization", "dss.recognize.minimal",
        "dss.subsegment", "hull.points.brute_force", "hull.disc.pick", "dt.l2.brute_force",
        "betti.euler", "simple_point.lut", "dss.cover.maximal", "voronoi.l2.nearest",
        "skeleton.homotopic", "plane.probe.normal", "surface.counts"}) {
    EXPECT_TRUE(names.count(n)) << n;
  }
  auto text = zdg::test::run_zdg("check --list");
  EXPECT_EQ(text.status, 0);
  EXPECT_NE(text.out.find("floor_sum.oracle"), std::string::npos);
}

TEST(CheckCommand, EveryPropertyHoldsOnZdgInProcess) {
  auto j = run_json("check --list", 0);
  std::string args = "check";
  for (const auto& p : j["properties"]) {
    args += ' ';
    args += p["name"].get<std::string>();
  }
  args += " --runs 150 --seed 3 --threads 2";
  auto r = run_json(args, 0);
  EXPECT_TRUE(r["holds"].get<bool>());
  EXPECT_EQ(r["failed"], 0);
  for (const auto& c : r["results"]) {
    EXPECT_EQ(c["runs"], 150) << c["property"];
    EXPECT_TRUE(c["holds"].get<bool>()) << c.dump();
  }
}

// Every operation answered by zdg serve passes its property (zdg itself is a valid COMMAND).
TEST(CheckCommand, ZdgServeAnswersPassEveryOperationProperty) {
  const std::pair<const char*, const char*> ops[] = {{"floor_sum.oracle", "floor-sum"},
                                                     {"cf.roundtrip", "cf"},
                                                     {"christoffel.factorization", "christoffel"},
                                                     {"dss.recognize.minimal", "dss recognize"},
                                                     {"dss.subsegment", "dss subsegment"},
                                                     {"hull.points.brute_force", "hull points"},
                                                     {"hull.disc.pick", "hull disc"},
                                                     {"dt.l2.brute_force", "transform dt"},
                                                     {"betti.euler", "topology betti"},
                                                     {"dss.cover.maximal", "dss cover"},
                                                     {"voronoi.l2.nearest", "transform voronoi"},
                                                     {"skeleton.homotopic", "topology skeleton"},
                                                     {"plane.probe.normal", "plane probe"},
                                                     {"surface.counts", "surface"}};
  for (const auto& [prop, op] : ops) {
    auto r = run_json(std::string("check ") + prop + " --runs 60 --seed 9 --against '" + kZdg +
                          " serve " + op + "'",
                      0);
    EXPECT_TRUE(r["holds"].get<bool>()) << prop << ": " << r.dump();
  }
}

TEST(CheckCommand, ZdgServePassesTenThousandRuns) {
  auto r = run_json("check floor_sum.oracle --type int64 --runs 10000 --seed 4 --against '" + kZdg +
                        " serve floor-sum'",
                    0);
  ASSERT_EQ(r["results"].size(), 1u);
  EXPECT_EQ(r["results"][0]["runs"], 10000);
  EXPECT_TRUE(r["results"][0]["holds"].get<bool>());
}

json failure_of(const std::string& args) {
  auto r = run_json(args, 1);
  EXPECT_FALSE(r["holds"].get<bool>());
  json f = r["results"][0]["failure"];
  EXPECT_LT(f["run"].get<int>(), 2000);
  EXPECT_FALSE(f["external_error"].get<bool>());
  EXPECT_NE(f["replay"].get<std::string>().find("--replay " + f["token"].get<std::string>()),
            std::string::npos);
  return f;
}

TEST(CheckCommand, PlantedBugOnNegativeInputsIsCaughtAndShrunk) {
  json f = failure_of("check floor_sum.oracle --type int64 --runs 2000 --seed 1 --against " +
                      python("floor_sum_truncating.py"));
  const json& c = f["case"];
  // Truncation and floor differ only when (a i + b) / m is negative and not an integer.
  EXPECT_TRUE(c["m"].get<std::string>()[0] == '-' || c["a"].get<std::string>()[0] == '-' ||
              c["b"].get<std::string>()[0] == '-')
      << c.dump();
  for (const char* k : {"n", "m", "a", "b"}) {
    EXPECT_LE(abs_text(c[k].get<std::string>()).size(), 1u) << c.dump(); // |v| <= 9
  }
  EXPECT_NE(f["expected"]["value"], f["answer"]["value"]);
}

TEST(CheckCommand, PlantedBugPastTwoToThe63IsCaughtAndShrunk) {
  json f = failure_of("check floor_sum.oracle --type int64 --runs 2000 --seed 1 --against " +
                      python("floor_sum_int64_inputs.py"));
  const json& c = f["case"];
  int wide = 0;
  for (const char* k : {"n", "m", "a", "b"}) {
    const std::string v = abs_text(c[k].get<std::string>());
    if (v.size() >= 19 && v >= std::string("9223372036854775808"))
      ++wide;
    else
      EXPECT_LE(v.size(), 1u) << c.dump();
  }
  EXPECT_EQ(wide, 1) << c.dump(); // one input past 2^63, the others shrunk to small values
}

TEST(CheckCommand, PlantedBugOnFourConnectedPathsIsCaughtAndShrunk) {
  json f = failure_of("check dss.recognize.minimal --type int64 --runs 2000 --seed 1 --against " +
                      python("dss_proxy.py", kZdg + " four-omega"));
  EXPECT_EQ(f["case"]["connectivity"], "4");
  EXPECT_LE(f["case"]["points"].size(), 3u) << f.dump();
  EXPECT_EQ(f["case"]["points"][0], json::array({"0", "0"})); // translated to the origin
}

TEST(CheckCommand, PlantedBugOnOneOctantIsCaughtAndShrunk) {
  json f = failure_of("check dss.recognize.minimal --type int64 --runs 2000 --seed 1 --against " +
                      python("dss_proxy.py", kZdg + " octant"));
  const auto a = std::stoll(f["expected"]["a"].get<std::string>());
  const auto b = std::stoll(f["expected"]["b"].get<std::string>());
  EXPECT_TRUE(0 < a && a < b) << f.dump();
  EXPECT_LE(f["case"]["points"].size(), 3u) << f.dump();
  // The replay command reproduces it.
  auto r = zdg::test::run_zdg(f["replay"].get<std::string>().substr(4) + " --json --quiet");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(json::parse(r.out)["results"][0]["failure"]["case"], f["case"]);
}

// Planted bugs in the image, cover and plane operations (check_planted/op_proxy.py).
json planted(const std::string& property, const std::string& bug) {
  return failure_of("check " + property + " --type int64 --runs 2000 --seed 1 --against " +
                    python("op_proxy.py", kZdg + " " + bug));
}

TEST(CheckCommand, PlantedCoverBugOnFourConnectedPathsIsCaughtAndShrunk) {
  json f = planted("dss.cover.maximal", "cover-naive");
  EXPECT_EQ(f["case"]["connectivity"], "4");
  EXPECT_LE(f["case"]["points"].size(), 3u) << f.dump();
  EXPECT_EQ(f["case"]["points"][0], json::array({"0", "0"}));
  EXPECT_NE(f["expected"]["segments"], f["answer"]["segments"]);
}

TEST(CheckCommand, PlantedVoronoiBugInTheMetricIsCaughtAndShrunk) {
  json f = planted("voronoi.l2.nearest", "voronoi-l1");
  // l1 and l2 nearest sites differ first on an image of at most 3 x 3 points.
  std::size_t points = 1;
  for (const json* v = &f["case"]["image"]; v->is_array(); v = &(*v)[0]) points *= v->size();
  EXPECT_LE(points, 9u) << f.dump();
  EXPECT_NE(f["why"].get<std::string>().find("squared distance"), std::string::npos) << f.dump();
}

TEST(CheckCommand, PlantedSkeletonBugIn3DIsCaughtAndShrunk) {
  json f = planted("skeleton.homotopic", "skeleton-3d");
  const json& img = f["case"]["image"];
  ASSERT_TRUE(img[0][0].is_array()) << f.dump(); // a 3D image: the bug is right in 2D
  EXPECT_LE(img.size() * img[0].size() * img[0][0].size(), 8u) << f.dump();
}

TEST(CheckCommand, PlantedProbingBugOnOneOctantIsCaughtAndShrunk) {
  json f = planted("plane.probe.normal", "probe-octant");
  const json& c = f["case"];
  EXPECT_EQ(c["a"], "-1") << f.dump(); // shrunk to the smallest normal of that octant
  EXPECT_EQ(c["b"], "1") << f.dump();
  EXPECT_EQ(c["c"], "1") << f.dump();
}

TEST(CheckCommand, PlantedSurfaceBugForgettingCavitiesIsCaughtAndShrunk) {
  json f = planted("surface.counts", "surface-cavities");
  const json& img = f["case"]["image"];
  // The smallest object with a cavity: a 3 x 3 x 3 image at most.
  EXPECT_LE(img.size() * img[0].size() * img[0][0].size(), 27u) << f.dump();
  EXPECT_NE(f["why"].get<std::string>().find("component pairs that touch"), std::string::npos)
      << f.dump();
}

TEST(CheckCommand, InProcessReplayAndSeedsAreDeterministic) {
  const std::string args = "check floor_sum.oracle --type int64 --runs 2000 --seed 1 --against " +
                           python("floor_sum_truncating.py");
  json one = run_json(args, 1), three = run_json(args + " --threads 3", 1);
  EXPECT_EQ(one["results"][0]["failure"]["run"], three["results"][0]["failure"]["run"]);
  EXPECT_EQ(one["results"][0]["failure"]["case"], three["results"][0]["failure"]["case"]);
  auto text = zdg::test::run_zdg(args + " --quiet");
  EXPECT_EQ(text.status, 1);
  EXPECT_NE(text.out.find("COUNTEREXAMPLE"), std::string::npos);
  EXPECT_NE(text.out.find("replay:   zdg check floor_sum.oracle --replay int64.64.200."),
            std::string::npos);
  EXPECT_TRUE(text.err.empty()) << text.err; // no progress when stderr is not a terminal
}

void expect_command_failure(const std::string& mode, const std::string& line_piece) {
  SCOPED_TRACE(mode);
  auto r = zdg::test::run_zdg("check floor_sum.oracle --type int64 --runs 100 --seed 1 "
                              "--request-timeout 1s --quiet --against " +
                              python("misbehaving.py", mode + " " + kZdg));
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.out.find("EXTERNAL COMMAND FAILED at run 3 of 100"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(line_piece), std::string::npos) << r.out;
}

TEST(CheckCommand, CrashHangAndGarbageOfTheCommandAreReportedWithExitOne) {
  expect_command_failure("crash", "(crash)");
  expect_command_failure("exit", "exited with status 3 before answering");
  const auto t0 = std::chrono::steady_clock::now();
  expect_command_failure("hang", "did not answer within 1.0");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 10);
  expect_command_failure("garbage", "malformed answer (not JSON): 'value = 42'");
}

// Issue #41: --request-timeout covers the whole answer line. A command that keeps writing one
// line (data always waiting in the pipe, so the wait for data never times out) is a hang once the
// timeout has passed since the request, not after the 256 MiB line limit (41 s before the fix).
TEST(CheckCommand, AnAnswerLineThatNeverEndsIsAHangWithinTheTimeout) {
  const auto t0 = std::chrono::steady_clock::now();
  expect_command_failure("endless", "did not answer within 1.0");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 6);
}

TEST(CheckCommand, TimeBudgetEndsACampaignEarly) {
  const auto t0 = std::chrono::steady_clock::now();
  auto r = run_json("check floor_sum.oracle --type int64 --runs 100000000 --time-budget 500ms", 0);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 10);
  EXPECT_TRUE(r["results"][0]["budget_exhausted"].get<bool>());
  EXPECT_LT(r["results"][0]["runs"].get<long long>(), 100000000);
}

// Issue #41: the library's bounds hold in zdg serve too: a disc whose proven vertex bound passes
// max_vertices (default 10^8) and an H-probing past its step bound are refused at once, in the
// answer, and the loop goes on; the bounds are request fields.
TEST(ServeCommand, HullAndProbingBoundsAreTheLibrarys) {
  const auto lines = [](const std::string& out) {
    std::vector<json> v;
    std::size_t start = 0;
    for (std::size_t nl; (nl = out.find('\n', start)) != std::string::npos; start = nl + 1) {
      v.push_back(json::parse(out.substr(start, nl - start)));
    }
    return v;
  };
  auto h = zdg::test::run_zdg("serve hull disc",
                              "{\"cx\":\"0\",\"cy\":\"0\",\"r\":\"1000000000000000\"}\n"
                              "{\"cx\":\"0\",\"cy\":\"0\",\"r\":\"18446744073709551616\"}\n"
                              "{\"cx\":\"0\",\"cy\":\"0\",\"r\":\"1000\",\"max_vertices\":10}\n"
                              "{\"cx\":\"0\",\"cy\":\"0\",\"r\":\"5\",\"max_vertices\":\"-1\"}\n"
                              "{\"cx\":\"0\",\"cy\":\"0\",\"r\":\"5\",\"max_vertices\":24}\n");
  EXPECT_EQ(h.status, 0) << h.err;
  const auto hl = lines(h.out);
  ASSERT_EQ(hl.size(), 5u) << h.out;
  for (int i = 0; i < 3; ++i) {
    EXPECT_NE(hl[i].value("error", "").find("more than the vertex bound"), std::string::npos)
        << hl[i].dump();
  }
  EXPECT_NE(hl[3].value("error", "").find("max_vertices"), std::string::npos) << hl[3].dump();
  // r = 5: the proven bound is 24 vertices (refused under 24), the hull has 12.
  EXPECT_EQ(hl[4]["vertices"].size(), 12u) << hl[4].dump();
  auto p = zdg::test::run_zdg(
      "serve plane probe",
      "{\"a\":\"1000000007\",\"b\":\"1000000009\",\"c\":\"3\",\"algorithm\":\"h\"}\n"
      "{\"a\":\"2\",\"b\":\"6\",\"c\":\"15\",\"algorithm\":\"h\",\"max_steps\":19}\n"
      "{\"a\":\"2\",\"b\":\"6\",\"c\":\"15\",\"algorithm\":\"h\",\"max_steps\":\"20\"}\n");
  EXPECT_EQ(p.status, 0) << p.err;
  const auto pl = lines(p.out);
  ASSERT_EQ(pl.size(), 3u) << p.out;
  EXPECT_NE(pl[0].value("error", "").find("||N||_1 - 3 = 2000000016"), std::string::npos)
      << pl[0].dump();
  EXPECT_NE(pl[1].value("error", "").find("more than max_steps 19"), std::string::npos)
      << pl[1].dump();
  EXPECT_FALSE(pl[2].contains("error")) << pl[2].dump();
}

TEST(ServeCommand, AnswersEachLineAndReportsErrorsInTheAnswer) {
  auto r =
      zdg::test::run_zdg("serve floor-sum", "{\"n\":\"5\",\"m\":\"7\",\"a\":\"-3\",\"b\":\"12\"}\n"
                                            "{\"n\":\"5\",\"m\":\"0\",\"a\":\"1\",\"b\":\"1\"}\n"
                                            "not json\n"
                                            "{\"n\":5,\"m\":7,\"a\":-3,\"b\":12}\n");
  EXPECT_EQ(r.status, 0) << r.err;
  std::vector<json> lines;
  std::size_t start = 0;
  for (std::size_t nl; (nl = r.out.find('\n', start)) != std::string::npos; start = nl + 1) {
    lines.push_back(json::parse(r.out.substr(start, nl - start)));
  }
  ASSERT_EQ(lines.size(), 4u) << r.out;
  // sum_{i<5} floor((12 - 3 i) / 7) = 1 + 1 + 0 + 0 + 0 = 2
  EXPECT_EQ(lines[0]["value"], "2");
  EXPECT_TRUE(lines[1].contains("error"));
  EXPECT_TRUE(lines[2].contains("error"));
  EXPECT_EQ(lines[3]["value"], "2");
}

// Regression (fuzz target serve_request, tests/fuzz/regressions/serve_request/): a request
// that is not UTF-8 got an error message quoting its bytes, and writing that answer threw
// (zdg serve ended in std::terminate). The answer is one line of JSON and the loop goes on.
TEST(ServeCommand, RequestBytesThatAreNotUtf8GetAnErrorLine) {
  auto r = zdg::test::run_zdg(
      "serve topology skeleton",
      "{\"image\":[[1,1,1],[1,1,1],[1,1,1]],\"adjacency\":\"8,4\",\xa2skeleton\":"
      "\"curve\"}\n{\"image\":[[1,1],[1,1]]}\n");
  EXPECT_EQ(r.status, 0) << r.err;
  const auto nl = r.out.find('\n');
  ASSERT_NE(nl, std::string::npos) << r.out;
  const json first = json::parse(r.out.substr(0, nl));
  EXPECT_TRUE(first.contains("error")) << r.out;
  const json second = json::parse(r.out.substr(nl + 1));
  EXPECT_TRUE(second.contains("skeleton")) << r.out; // the next request is answered
}

// examples/check-python: the naive programs and the counterexamples their README shows.
TEST(CheckCommand, ExamplesFindTheirCounterexamples) {
  const std::string ex = std::string(zdg::test::source_dir()) + "/examples/check-python/";
  json f = failure_of("check floor_sum.oracle --type int64 --runs 2000 --seed 1 --against "
                      "'/usr/bin/python3 " +
                      ex + "naive_floor_sum.py'");
  EXPECT_EQ(f["case"], json::parse(R"({"n":"1","m":"1","a":"0","b":"9007199254740993"})"));
  json g = failure_of("check dss.recognize.minimal --type int64 --runs 2000 --seed 1 --against "
                      "'/usr/bin/python3 " +
                      ex + "naive_dss.py'");
  EXPECT_EQ(g["case"]["points"].size(), 4u);
  EXPECT_EQ(g["expected"]["omega"], "2");
  EXPECT_EQ(g["answer"]["omega"], "3");
}

} // namespace
