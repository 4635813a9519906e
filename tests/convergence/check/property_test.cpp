// The campaign runner of zdg check: it finds a planted counterexample, shrinks it to the
// boundary, reports the same first failure whatever the number of threads, replays it from its
// token, stops at the time budget; and every registered operation property rejects a corrupted
// answer (none of them is a check that cannot fail).
#include <zdg/convergence/check/property.hpp>

#include "tests/support/tower.hpp"

#include <chrono>
#include <thread>

namespace {

using namespace zdg;
using namespace zdg::check;

// "Every integer is below 1000", false past 1000: the minimal counterexample is 1000.
Property below_1000() {
  Property p;
  p.name = "test.below_1000";
  p.generate = [](Rng& rng, const Params& params) {
    return Record().integer("v", rng.edgy_natural(params.bits), Shrink::toward_zero);
  };
  p.valid = [](const Record& c, const Params&) { return c.int_of("v") >= 0; };
  p.holds = [](const Record& c, IntKind) -> std::optional<std::string> {
    if (c.int_of("v") < 1000) return std::nullopt;
    return "v = " + c.int_of("v").str() + " >= 1000";
  };
  return p;
}

TEST(CheckRunner, FindsAndShrinksToTheBoundary) {
  const Property p = below_1000();
  Options opt;
  opt.seed = 5;
  opt.runs = 2000;
  const Report r = run_check(p, Params{}, opt);
  ASSERT_TRUE(r.failure.has_value());
  EXPECT_EQ(r.failure->shrunk.int_of("v"), 1000);
  EXPECT_GE(r.failure->original.int_of("v"), 1000);
  EXPECT_EQ(r.failure->verdict.why, "v = 1000 >= 1000");
  EXPECT_TRUE(r.failure->shrink_note.empty());
  // The replay token regenerates the original failing case.
  const Report again = replay_check(p, r.failure->token, opt);
  ASSERT_TRUE(again.failure.has_value());
  EXPECT_EQ(again.failure->original, r.failure->original);
  EXPECT_EQ(again.failure->shrunk, r.failure->shrunk);
}

TEST(CheckRunner, FirstFailureDoesNotDependOnThreads) {
  const Property p = below_1000();
  Options opt;
  opt.seed = 11;
  opt.runs = 3000;
  const Report one = run_check(p, Params{}, opt);
  opt.threads = 4;
  const Report four = run_check(p, Params{}, opt);
  ASSERT_TRUE(one.failure && four.failure);
  EXPECT_EQ(one.failure->index, four.failure->index);
  EXPECT_EQ(one.failure->token, four.failure->token);
}

TEST(CheckRunner, HoldingPropertyRunsEveryCaseAndBudgetStopsEarly) {
  Property p = below_1000();
  p.holds = [](const Record&, IntKind) -> std::optional<std::string> {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    return std::nullopt;
  };
  Options opt;
  opt.runs = 20;
  EXPECT_EQ(run_check(p, Params{}, opt).runs, 20);
  opt.runs = 1000000;
  opt.time_budget_s = 0.2;
  const Report r = run_check(p, Params{}, opt);
  EXPECT_TRUE(r.budget_exhausted);
  EXPECT_LT(r.runs, 1000);
  EXPECT_FALSE(r.failure.has_value());
}

TEST(CheckRunner, TokensRoundTripAndBadTokensAreRefused) {
  Params params{IntKind::int128, 100, 12};
  const auto [back, seed] = parse_token(make_token(params, 0xdeadbeef12345678ULL));
  EXPECT_EQ(back.type, IntKind::int128);
  EXPECT_EQ(back.bits, 100);
  EXPECT_EQ(back.max_size, 12u);
  EXPECT_EQ(seed, 0xdeadbeef12345678ULL);
  for (const char* bad : {"", "int64.64.12", "int32.64.12.0000000000000001",
                          "int64.x.12.0000000000000001", "int64.64.12.000000000000000g"}) {
    EXPECT_THROW(parse_token(bad), InvalidArgument) << bad;
  }
}

// A copy of the answer with its first comparable field changed.
Record corrupt(const Record& answer) {
  Record r = answer;
  for (auto& f : r.fields) {
    switch (f.kind) {
    case FieldKind::integer:
      f.ints[0] += 1;
      return r;
    case FieldKind::boolean:
      f.flag = !f.flag;
      return r;
    case FieldKind::text:
      f.texts[0] += "1";
      return r;
    case FieldKind::texts:
      if (f.texts.empty()) break;
      f.texts[0] += "1";
      return r;
    case FieldKind::array:
      if (f.ints.empty()) break;
      f.ints[0] += 1;
      return r;
    }
  }
  return r;
}

class FixedAnswer : public AnswerSource {
public:
  explicit FixedAnswer(Record r) : r_(std::move(r)) {}
  Record answer(const Property&, const Record&, const Record&) override { return r_; }

private:
  Record r_;
};

TEST(CheckRegistry, EveryOperationPropertyRejectsACorruptedAnswer) {
  int operations = 0;
  for (const auto& p : registry()) {
    if (!p.is_operation()) continue;
    ++operations;
    SCOPED_TRACE(p.name);
    EXPECT_FALSE(p.theorem.empty());
    EXPECT_FALSE(p.source.empty());
    for (std::uint64_t s = 1; s <= 20; ++s) {
      Params params{p.types.front(), default_bits(p.types.front()), p.default_max_size};
      Rng rng(s);
      const Record c = p.generate(rng, params);
      ASSERT_TRUE(p.valid(c, params)) << to_json(c);
      const Record good = p.compute(c, params.type);
      FixedAnswer right(good), wrong(corrupt(good));
      EXPECT_TRUE(evaluate(p, c, params.type, &right).holds) << to_json(c);
      const Verdict v = evaluate(p, c, params.type, &wrong);
      EXPECT_FALSE(v.holds) << to_json(c);
      EXPECT_FALSE(v.why.empty());
    }
  }
  EXPECT_GE(operations, 14);
  EXPECT_THROW(find_property("no.such"), InvalidArgument);
}

} // namespace
