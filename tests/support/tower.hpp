// Test support shared by every zdg test: the list of tower integer types that each property
// battery runs on, RapidCheck generators biased towards the edges of int64, and
// check_property() to run a RapidCheck property inside a (typed) GoogleTest test.
//
//   template <class I> class MyTest : public ::testing::Test {};
//   TYPED_TEST_SUITE(MyTest, zdg::test::TowerTypes, zdg::test::TowerNames);
//   TYPED_TEST(MyTest, TheoremName) {
//     using I = TypeParam;
//     zdg::test::check_property([](std::int64_t a) { RC_ASSERT(...); });
//   }
//
// Shrunk counterexamples are kept as plain TEST()s named Regression* next to the property.
#pragma once

#include <zdg/arith/integer.hpp>

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cstdint>
#include <limits>
#include <string>

namespace zdg::test {

using TowerTypes = ::testing::Types<Int64, Int128, BigInt>;

struct TowerNames {
  template <class T>
  static std::string GetName(int) {
    return int_name<T>();
  }
};

/// Runs a RapidCheck property; a failure (with the shrunk counterexample) fails the
/// enclosing GoogleTest test.
template <class Testable>
void check_property(Testable&& testable) {
  rc::detail::checkGTest(std::forward<Testable>(testable));
}

/// int64 values: arbitrary ones, small ones, and values at and next to the limits and to
/// powers of two (where overflow lives).
inline rc::Gen<std::int64_t> edgy_int64() {
  using L = std::numeric_limits<std::int64_t>;
  return rc::gen::oneOf(
      rc::gen::arbitrary<std::int64_t>(), rc::gen::inRange<std::int64_t>(-50, 51),
      rc::gen::element<std::int64_t>(L::min(), L::min() + 1, -1, 0, 1, L::max() - 1, L::max()),
      rc::gen::map(rc::gen::pair(rc::gen::inRange(0, 63), rc::gen::inRange(-2, 3)),
                   [](std::pair<int, int> e) {
                     std::int64_t p = std::int64_t{1} << e.first;
                     return e.second < 0 ? -p - e.second : p + e.second - 1;
                   }));
}

/// Values in [lo, hi] (int64), uniformly.
inline rc::Gen<std::int64_t> int64_in(std::int64_t lo, std::int64_t hi) {
  if (hi == std::numeric_limits<std::int64_t>::max()) {
    // inRange's end is exclusive: hi + 1 would overflow.
    return rc::gen::oneOf(rc::gen::inRange<std::int64_t>(lo, hi), rc::gen::just(hi));
  }
  return rc::gen::inRange<std::int64_t>(lo, hi + 1);
}

} // namespace zdg::test
