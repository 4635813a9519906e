// Exhaustive: every entry of every simple-point table (2^26 configurations for each of the
// four 3D pairs) against the definition-level test, Bertrand's geodesic numbers by
// breadth-first search (tests/support/simple_point_oracles.hpp) and, for (26,6) and (6,26),
// Kong's attachment criterion. Multi-threaded over configurations.
#include <zdg/kernel/topology/simple_points.hpp>

#include "tests/support/simple_point_oracles.hpp"
#include <zdg/kernel/parallel/parallel_for.hpp>

#include <gtest/gtest.h>

#include <atomic>

namespace zdg {
namespace {

class SimplePointTableExhaustive : public ::testing::TestWithParam<AdjacencyPair> {};

TEST_P(SimplePointTableExhaustive, EveryConfigurationAgreesWithTheDefinitionAndTheOracles) {
  const AdjacencyPair pair = GetParam();
  const auto& table = SimplePointTable::of(pair);
  const std::uint32_t n = configuration_count(3);
  std::atomic<std::int64_t> wrong_definition{0}, wrong_geodesic{0}, wrong_attachment{0}, simple{0};
  std::atomic<std::uint32_t> first_wrong{0xFFFFFFFFu};
  const bool attachment = pair.object == 26 || pair.background == 26;
  parallel_chunks(n, 0, [&](std::int64_t b, std::int64_t e) {
    std::int64_t wd = 0, wg = 0, wa = 0, s = 0;
    for (std::int64_t i = b; i < e; ++i) {
      const auto c = static_cast<std::uint32_t>(i);
      const bool t = table.simple(c);
      s += t;
      bool bad = false;
      if (is_simple_by_definition(pair, c) != t) ++wd, bad = true;
      if (test::geodesic_simple(3, pair.object, pair.background, c) != t) ++wg, bad = true;
      if (attachment && test::attachment_is_contractible(pair.object, c) != t) ++wa, bad = true;
      if (bad) {
        std::uint32_t cur = first_wrong.load();
        while (c < cur && !first_wrong.compare_exchange_weak(cur, c)) {
        }
      }
    }
    wrong_definition += wd;
    wrong_geodesic += wg;
    wrong_attachment += wa;
    simple += s;
  });
  EXPECT_EQ(wrong_definition.load(), 0) << "first " << first_wrong.load();
  EXPECT_EQ(wrong_geodesic.load(), 0) << "first " << first_wrong.load();
  EXPECT_EQ(wrong_attachment.load(), 0) << "first " << first_wrong.load();
  // Complementary pairs have equally many simple configurations (x is (k, kbar)-simple in X
  // iff it is (kbar, k)-simple in the complement).
  const auto& dual = SimplePointTable::of(pair.complement());
  std::int64_t dual_simple = 0;
  for (std::uint32_t c = 0; c < n; ++c) dual_simple += dual.simple(c);
  EXPECT_EQ(simple.load(), dual_simple);
}

INSTANTIATE_TEST_SUITE_P(AllPairs, SimplePointTableExhaustive,
                         ::testing::Values(AdjacencyPair{3, 26, 6}, AdjacencyPair{3, 6, 26},
                                           AdjacencyPair{3, 18, 6}, AdjacencyPair{3, 6, 18}),
                         [](const auto& param_info) {
                           return "Pair" + std::to_string(param_info.param.object) + "_" +
                                  std::to_string(param_info.param.background);
                         });

} // namespace
} // namespace zdg
