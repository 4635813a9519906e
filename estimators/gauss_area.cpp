#include <zdg/estimators/gauss_area.hpp>

#include <zdg/arith/integer.hpp>

namespace zdg {

std::int64_t pixel_count(const std::vector<DigitalContour>& contours) {
  Int128 twice = 0;
  for (const auto& c : contours) twice += Int128(c.twice_signed_area());
  return int_cast<Int64>(twice / 2).value();
}

double gauss_area(const std::vector<DigitalContour>& contours, double h) {
  return h * h * static_cast<double>(pixel_count(contours));
}

} // namespace zdg
