// Test helper: the digital contour of the pixels {z in [-r, r]^2 : f(z)}, for shapes given by
// an integer predicate (digital discs x^2 + y^2 <= r2, ellipses, rings) rather than by an
// implicit shape and a grid step.
#pragma once

#include <zdg/kernel/curves/digital_contour.hpp>
#include <zdg/kernel/digitization/gauss_digitization.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <utility>

namespace zdg::test {

// The pixels of [-r, r]^2 where f holds, as a digitization.
class PredicateSet final : public GaussDigitization2 {
public:
  PredicateSet(std::function<bool(const Pixel&)> f, std::int64_t r)
      : GaussDigitization2(Box2{{-r, -r}, {r, r}}), f_(std::move(f)) {}

protected:
  bool inside(const Pixel& z) const override { return f_(z); }

private:
  std::function<bool(const Pixel&)> f_;
};

// The first contour of {f} in [-r - 2, r + 2]^2 (a shape inside [-r, r]^2 has one when it is
// connected and simply connected; the test fails when there is none).
inline DigitalContour contour_of(const std::function<bool(const Pixel&)>& f, std::int64_t r) {
  PredicateSet set(f, r + 2);
  auto cs = digital_contours(set, {}, {0});
  EXPECT_FALSE(cs.empty());
  return cs.at(0);
}

} // namespace zdg::test
