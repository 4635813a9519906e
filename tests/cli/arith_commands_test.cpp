// zdg cf / christoffel / floor-sum: JSON formats, exactness on huge input, exit codes.
#include "tests/support/cli.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <sys/wait.h>

namespace {

using zdg::test::run_zdg;
using json = nlohmann::json;

// [[a, b], [c, d], ...] (a plain braced list would read as an object).
json pairs(std::initializer_list<std::pair<const char*, const char*>> ps) {
  json out = json::array();
  for (auto [a, b] : ps) out.push_back(json::array({a, b}));
  return out;
}

TEST(CliCf, JsonFormatAndConvergents) {
  auto r = run_zdg("cf 415/93 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = json::parse(r.out);
  EXPECT_EQ(j["p"], "415");
  EXPECT_EQ(j["q"], "93");
  EXPECT_EQ(j["terms"], json::array({"4", "2", "6", "7"}));
  EXPECT_EQ(j["convergents"], pairs({{"4", "1"}, {"9", "2"}, {"58", "13"}, {"415", "93"}}));
}

TEST(CliCf, HugeInputIsExact) {
  // F(200)/F(199): 199 terms 1 then 2 (Fibonacci numbers of ~42 digits).
  auto r = run_zdg("cf 280571172992510140037611932413038677189525/"
                   "173402521172797813159685037284371942044301 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = json::parse(r.out);
  EXPECT_EQ(j["integer_type"], "bigint");
  EXPECT_EQ(j["terms"].back(), "2");
  EXPECT_EQ(j["convergents"].back()[0], "280571172992510140037611932413038677189525");
}

TEST(CliChristoffel, WordFactorizationParents) {
  auto r = run_zdg("christoffel 8/14 --json"); // reduced first: 4/7
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = json::parse(r.out);
  EXPECT_EQ(j["p"], "4");
  EXPECT_EQ(j["q"], "7");
  EXPECT_EQ(j["word"], "00100100101");
  EXPECT_EQ(j["standard_factorization"], json::array({"001", "00100101"}));
  EXPECT_EQ(j["parents"], pairs({{"1", "2"}, {"3", "5"}}));
  auto up = json::parse(run_zdg("christoffel 4/7 --upper --json").out);
  EXPECT_EQ(up["word"], "10100100100");
  EXPECT_EQ(std::string(up["standard_factorization"][0]) +
                std::string(up["standard_factorization"][1]),
            "10100100100");
  auto huge = run_zdg("christoffel 1000000000000000000000001/1000000000000000000000000 --no-word "
                      "--json");
  ASSERT_EQ(huge.status, 0) << huge.err;
  auto h = json::parse(huge.out);
  EXPECT_FALSE(h.contains("word"));
  EXPECT_EQ(h["parents"][0], json::array({"1", "1"}));
}

TEST(CliFloorSum, ValueAndEscalation) {
  auto j = json::parse(run_zdg("floor-sum 31415 92653 58979 32384 --json").out);
  EXPECT_EQ(j["value"], "314095480");
  auto big = json::parse(run_zdg("floor-sum 1000000000000 7 123456789123 -5 --json").out);
  EXPECT_EQ(big["integer_type"], "int128");
}

// zdg sturmian: 1/phi^2 = (3 - sqrt 5)/2 = [0; 2, (1)], whose characteristic word is the
// Fibonacci word; its Christoffel convergents are the slopes F_n / F_{n+1}; a surd past int64
// escalates.
TEST(CliSturmian, FibonacciWordAndEscalation) {
  auto r = run_zdg("sturmian 3 -1 5 2 --length 20 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = json::parse(r.out);
  EXPECT_EQ(j["surd"], "(-3 + sqrt(5))/-2");
  EXPECT_EQ(j["preperiod"], json::array({"0", "2"}));
  EXPECT_EQ(j["period"], json::array({"1"}));
  EXPECT_EQ(j["floor"], "0");
  EXPECT_EQ(j["word"], "01001010010010100101");
  EXPECT_EQ(j["christoffel_convergents"],
            pairs({{"1", "1"}, {"1", "2"}, {"2", "3"}, {"3", "5"}, {"5", "8"}, {"8", "13"}}));
  EXPECT_EQ(j["integer_type"], "int64");
  r = run_zdg("sturmian 0 4 1152921504606846977 1 --length 0 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  j = json::parse(r.out);
  EXPECT_EQ(j["period"], json::array({"536870912", "8589934592"}));
  EXPECT_EQ(j["integer_type"], "int128");
  r = run_zdg("sturmian 0 1 2 1 --length 8");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("(0 + sqrt(2))/1 = [1; (2)]"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("01010010"), std::string::npos) << r.out; // sqrt 2 - 1
}

TEST(CliErrors, BadInputExitsTwoWithOneLineNamingTheValue) {
  for (const char* args :
       {"cf 5/0", "cf x/3", "christoffel -- -1/2", "christoffel 1/-2", "floor-sum 1 0 2 3",
        "floor-sum -1 2 3 4", "floor-sum 1 2 3", "cf", "no-such-command"}) {
    auto r = run_zdg(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
    EXPECT_EQ(r.err.rfind("zdg: ", 0), 0u) << r.err;
  }
  EXPECT_NE(run_zdg("cf x/3").err.find("'x'"), std::string::npos);
  EXPECT_NE(run_zdg("cf 5/0").err.find("5/0"), std::string::npos);
}

TEST(CliHelp, EverySubcommandHasHelp) {
  for (const char* sub : {"cf", "christoffel", "floor-sum"}) {
    auto r = run_zdg(std::string(sub) + " --help");
    EXPECT_EQ(r.status, 0) << sub;
    EXPECT_NE(r.out.find("--json"), std::string::npos) << sub;
  }
}

// Issue #41: GMP running out of memory is zdg's one-line error, not GMP's abort ("GNU MP: Cannot
// allocate memory", SIGABRT): the convergents of a 200,000-bit fraction need gigabytes, under a
// 400 MB address-space limit (ulimit -v). The same in zdg serve, which answers and goes on.
#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
TEST(CliCf, OutOfMemoryIsOneLine) {
  const auto dir = zdg::test::scratch_dir("oom");
  std::string p = "1", q = "3";
  std::uint64_t x = 41;
  for (int i = 0; i < 60000; ++i) {
    x = x * 6364136223846793005ULL + 1442695040888963407ULL;
    p += static_cast<char>('0' + (x >> 33) % 10);
    if (i < 59990) q += static_cast<char>('0' + (x >> 43) % 10);
  }
  std::ofstream(dir / "fraction") << p << "/" << q;
  std::ofstream(dir / "request") << "{\"fraction\":\"" << p << "/" << q
                                 << "\"}\n{\"fraction\":\"415/93\"}\n";
  const std::string zdg = "'" + std::string(zdg::test::cli_path()) + "'";
  const std::string d = "'" + dir.string() + "'";
  std::string cmd = "ulimit -v 400000; ";
  cmd.append(zdg).append(" cf \"$(cat ").append(d).append("/fraction)\" >/dev/null 2>");
  cmd.append(d).append("/err");
  const int cli = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(cli));
  EXPECT_EQ(WEXITSTATUS(cli), 2);
  EXPECT_EQ(zdg::test::read_file(dir / "err"), "zdg: out of memory\n");
  cmd = "ulimit -v 400000; ";
  cmd.append(zdg).append(" serve cf <").append(d).append("/request >").append(d).append("/out 2>");
  cmd.append(d).append("/err");
  const int serve = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(serve));
  EXPECT_EQ(WEXITSTATUS(serve), 0) << zdg::test::read_file(dir / "err");
  const std::string out = zdg::test::read_file(dir / "out");
  EXPECT_EQ(out.substr(0, out.find('\n')), "{\"error\":\"out of memory\"}");
  EXPECT_NE(out.find("\"terms\":[\"4\",\"2\",\"6\",\"7\"]"), std::string::npos) << out;
  std::filesystem::remove_all(dir);
}
#endif

} // namespace
