// Freeman chains: parsing with clear errors, points, round trip with freeman_chain_of.
#include <zdg/kernel/curves/freeman_chain.hpp>

#include "tests/support/tower.hpp"
#include <zdg/arith/error.hpp>

#include <cstdint>
#include <vector>

namespace {

using namespace zdg;

TEST(FreemanChain, ParsesAndWalks) {
  auto c = parse_freeman_chain("  -3 5 0011\n2233 ");
  EXPECT_EQ(c.start, (Point2<std::int64_t>{-3, 5}));
  EXPECT_EQ(c.codes, "00112233");
  auto pts = freeman_points(c);
  ASSERT_EQ(pts.size(), 9u);
  EXPECT_EQ(pts[2], (Point2<std::int64_t>{-1, 5}));
  EXPECT_EQ(pts[4], (Point2<std::int64_t>{-1, 7}));
  EXPECT_EQ(pts.back(), c.start);
  EXPECT_TRUE(is_closed(c));
  EXPECT_EQ(to_string(c), "-3 5 00112233");
  EXPECT_EQ(parse_freeman_chain("1 2").codes, "");
}

TEST(FreemanChain, ErrorsNameTheOffendingToken) {
  auto message = [](const char* text) {
    try {
      parse_freeman_chain(text);
    } catch (const InvalidArgument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("1 2 0124").find("'4' at code 4"), std::string::npos);
  EXPECT_NE(message("x 2 01").find("'x'"), std::string::npos);
  EXPECT_NE(message("7").find("missing y0"), std::string::npos);
  EXPECT_NE(message("99999999999999999999 0 0").find("99999999999999999999"), std::string::npos);
  EXPECT_THROW(freeman_points({{INT64_MAX, 0}, "0"}), OverflowError);
}

// Round trip: the chain of the points of a chain is the chain.
TEST(FreemanChain, RoundTrip) {
  test::check_property([] {
    auto codes = *rc::gen::container<std::string>(rc::gen::element('0', '1', '2', '3'));
    FreemanChain c{{*test::int64_in(-1000, 1000), *test::int64_in(-1000, 1000)}, codes};
    auto pts = freeman_points(c);
    RC_ASSERT(freeman_chain_of(pts) == c);
    RC_ASSERT(parse_freeman_chain(to_string(c)) == c);
  });
  std::vector<Point2<std::int64_t>> bad{{0, 0}, {1, 1}};
  EXPECT_THROW(freeman_chain_of(bad), InvalidArgument);
}

} // namespace
