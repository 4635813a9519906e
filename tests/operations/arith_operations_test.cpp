// The arithmetic operations: worked examples, their JSON form, and the three front ends giving
// that form (zdg OP --json and zdg serve OP answer to_json of the same result).
#include <zdg/arith/error.hpp>
#include <zdg/operations/arith_operations.hpp>

#include "tests/support/cli.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <rapidcheck/gtest.h>

#include <algorithm>

namespace zdg {
namespace {

TEST(ArithOperations, WorkedExamples) {
  // 415/93 = [4; 2, 6, 7] (the classic example of continued-fraction texts).
  const auto cf = continued_fraction_operation(parse_fraction("415/93"));
  EXPECT_EQ(
      to_json(cf).dump(),
      R"({"convergents":[["4","1"],["9","2"],["58","13"],["415","93"]],"integer_type":"int64","p":"415","q":"93","terms":["4","2","6","7"]})");
  // Slope 2/5: lower Christoffel word 0001001 (the prefix of length k holds floor(2k/7) ones),
  // Stern-Brocot parents 1/3 and 1/2 (2/5 is their mediant).
  const auto c = christoffel_operation({parse_fraction("4/10"), false, true});
  EXPECT_EQ(c.letters, "0001001");
  EXPECT_EQ(to_json(c)["parents"], nlohmann::json::parse(R"([["1","3"],["1","2"]])"))
      << to_json(c).dump();
  EXPECT_EQ(floor_sum_operation({BigInt(10), BigInt(3), BigInt(2), BigInt(1)}).value, 30);
  EXPECT_THROW(parse_fraction("1/0"), InvalidArgument);
  EXPECT_THROW(parse_fraction("0x10"), InvalidArgument);
  EXPECT_THROW(christoffel_operation({{BigInt(-1), BigInt(2)}}), InvalidArgument);
  EXPECT_THROW(floor_sum_operation({BigInt(-1), BigInt(3), BigInt(0), BigInt(0)}), InvalidArgument);
  EXPECT_THROW(floor_sum_operation({BigInt(1), BigInt(0), BigInt(0), BigInt(0)}), InvalidArgument);
}

// Theorem (Christoffel words, ARCHITECTURE.md conventions): the lower word of p/q has q zeros and
// p ones, its prefix of length k holds floor(k p / (p + q)) ones; the upper word is its reverse;
// the standard factorization concatenates to the word.
RC_GTEST_PROP(ArithOperations, ChristoffelWordsAndFactorizations, ()) {
  const auto p = *rc::gen::inRange<std::int64_t>(0, 60);
  const auto q = *rc::gen::inRange<std::int64_t>(1, 60);
  const auto lower = christoffel_operation({{BigInt(p), BigInt(q)}, false, true});
  const auto upper = christoffel_operation({{BigInt(p), BigInt(q)}, true, true});
  const auto n = static_cast<std::int64_t>(lower.letters.size());
  RC_ASSERT(lower.p + lower.q == n);
  std::int64_t ones = 0;
  for (std::int64_t k = 0; k <= n; ++k) {
    RC_ASSERT(BigInt(ones) == BigInt(k) * lower.p / (lower.p + lower.q));
    if (k < n) ones += lower.letters[static_cast<std::size_t>(k)] == '1';
  }
  RC_ASSERT(std::string(lower.letters.rbegin(), lower.letters.rend()) == upper.letters);
  if (lower.factorization) {
    RC_ASSERT(lower.factorization->first + lower.factorization->second == lower.letters);
    RC_ASSERT(upper.factorization->first + upper.factorization->second == upper.letters);
  } else {
    RC_ASSERT(p == 0);
  }
}

// One JSON form: the command line and zdg serve print to_json of the operation's result.
TEST(ArithOperations, FrontEndsPrintTheOperationsJson) {
  const std::string big = "123456789012345678901234567890/987654321";
  const auto cf = to_json(continued_fraction_operation(parse_fraction(big)));
  auto r = test::run_zdg("cf " + big + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out), cf);
  r = test::run_zdg("serve cf", R"({"fraction": ")" + big + "\"}\n");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out), cf);

  const auto ch = to_json(christoffel_operation({parse_fraction("3/8"), true, true}));
  r = test::run_zdg("christoffel 3/8 --upper --json");
  EXPECT_EQ(nlohmann::json::parse(r.out), ch);
  r = test::run_zdg("serve christoffel", R"({"slope": "3/8", "upper": true})"
                                         "\n");
  EXPECT_EQ(nlohmann::json::parse(r.out), ch);

  const auto fs = to_json(floor_sum_operation({BigInt(7), BigInt(-3), BigInt(5), BigInt(2)}));
  r = test::run_zdg("floor-sum 7 -3 5 2 --json");
  EXPECT_EQ(nlohmann::json::parse(r.out), fs);
  r = test::run_zdg("serve floor-sum", R"({"n": "7", "m": "-3", "a": "5", "b": "2"})"
                                       "\n");
  EXPECT_EQ(nlohmann::json::parse(r.out), fs);
}

} // namespace
} // namespace zdg
