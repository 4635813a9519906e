#include <zdg/kernel/digitization/digital_disc.hpp>

#include "tests/support/tower.hpp"

#include <gtest/gtest.h>

#include <cstdint>

namespace {

TEST(DigitalDisc, RowsAreTheLatticePointsOfTheDisc) {
  // Oracle: x^2 + y^2 <= rho^2 by enumeration; the size is Gauss's circle count.
  for (double rho : {0.0, 0.5, 1.0, 1.5, 2.0, 7.3, 25.0}) {
    zdg::DigitalDisc d(rho);
    std::int64_t n = 0;
    for (std::int64_t y = -30; y <= 30; ++y) {
      for (std::int64_t x = -30; x <= 30; ++x) {
        const bool in = static_cast<double>(x * x + y * y) <= rho * rho;
        EXPECT_EQ(d.contains(x, y), in) << rho << " " << x << " " << y;
        n += in ? 1 : 0;
      }
    }
    EXPECT_EQ(d.size, n) << rho;
  }
  EXPECT_EQ(zdg::DigitalDisc(25.0).size, 1961); // N(25) of the Gauss circle problem
  EXPECT_THROW(zdg::DigitalDisc(-1.0), zdg::InvalidArgument);
}

TEST(DigitalDisc, RectangleTestsAgreeWithEnumeration) {
  // contains_rect / misses_rect are exact (centred rows, widths non-increasing in |dy|).
  zdg::test::check_property(
      [](std::uint8_t r, std::int8_t x0, std::uint8_t w, std::int8_t y0, std::uint8_t hgt) {
        zdg::DigitalDisc d(0.5 + (r % 40) * 0.37);
        const std::int64_t xa = x0 % 20, xb = xa + w % 25, ya = y0 % 20, yb = ya + hgt % 25;
        bool all = true, none = true;
        for (std::int64_t y = ya; y <= yb; ++y) {
          for (std::int64_t x = xa; x <= xb; ++x) {
            (d.contains(x, y) ? none : all) = false;
          }
        }
        RC_ASSERT(d.contains_rect(xa, xb, ya, yb) == all);
        RC_ASSERT(d.misses_rect(xa, xb, ya, yb) == none);
      });
}

} // namespace
