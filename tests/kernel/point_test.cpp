#include "kernel/point.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <sstream>

namespace {

TEST(Point, LexicographicOrderAndPrinting) {
  using P = zdg::Point2<std::int64_t>;
  EXPECT_LT((P{1, 5}), (P{2, 0}));
  EXPECT_LT((P{1, 0}), (P{1, 1}));
  EXPECT_EQ((P{3, 4}), (P{3, 4}));
  std::ostringstream s;
  s << zdg::Point3<int>{1, -2, 3};
  EXPECT_EQ(s.str(), "(1, -2, 3)");
}

} // namespace
