#include <zdg/kernel/images/object_selection.hpp>

#include <zdg/arith/integer.hpp>
#include <zdg/arith/rational.hpp>

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

namespace zdg {
namespace {

// The exact rational value of a finite double: m 2^(e - 53) with m the 53-bit mantissa.
Rational<BigInt> exact(double t) {
  int e = 0;
  const double m = std::frexp(t, &e);
  const auto mant = static_cast<std::int64_t>(std::ldexp(m, 53));
  BigInt num(mant), den(1);
  const int shift = e - 53;
  for (int k = 0; k < std::abs(shift); ++k) (shift > 0 ? num : den) *= 2;
  return Rational<BigInt>(num, den);
}

// The oracle: the rule decided on exact rationals (integers) or IEEE doubles (floats).
template <class T>
bool oracle(const ObjectSelection& s, T v) {
  bool in = false;
  if constexpr (std::is_floating_point_v<T>) {
    const double x = v;
    if (std::isnan(x)) return s.invert;
    if (s.rule == ObjectSelection::Rule::nonzero) in = x != 0;
    if (s.rule == ObjectSelection::Rule::at_least) in = x >= s.low;
    if (s.rule == ObjectSelection::Rule::range) in = s.low <= x && x <= s.high;
    if (s.rule == ObjectSelection::Rule::equal) in = x == s.low;
  } else {
    const Rational<BigInt> x{BigInt(v)};
    if (s.rule == ObjectSelection::Rule::nonzero) in = v != 0;
    if (s.rule == ObjectSelection::Rule::at_least) in = x >= exact(s.low);
    if (s.rule == ObjectSelection::Rule::range) in = exact(s.low) <= x && x <= exact(s.high);
    if (s.rule == ObjectSelection::Rule::equal) in = x == exact(s.low);
  }
  return in != s.invert;
}

template <class T>
DType dtype_of() {
  if constexpr (std::is_same_v<T, std::uint8_t>) return DType::U8;
  if constexpr (std::is_same_v<T, std::int8_t>) return DType::I8;
  if constexpr (std::is_same_v<T, std::uint16_t>) return DType::U16;
  if constexpr (std::is_same_v<T, std::int16_t>) return DType::I16;
  if constexpr (std::is_same_v<T, std::uint32_t>) return DType::U32;
  if constexpr (std::is_same_v<T, std::int32_t>) return DType::I32;
  if constexpr (std::is_same_v<T, std::uint64_t>) return DType::U64;
  if constexpr (std::is_same_v<T, std::int64_t>) return DType::I64;
  if constexpr (std::is_same_v<T, float>) return DType::F32;
  return DType::F64;
}

template <class T>
ScalarVolume volume_of(const std::vector<T>& values, std::vector<std::int64_t> shape) {
  NpyArray a;
  a.dtype = dtype_of<T>();
  a.shape = std::move(shape);
  a.bytes.resize(values.size() * sizeof(T));
  if (!values.empty()) std::memcpy(a.bytes.data(), values.data(), a.bytes.size());
  return make_scalar_volume(std::move(a));
}

// Bounds near the values: the values themselves, +-1/2, +-2^-30, and the ends of the range.
template <class T>
rc::Gen<double> bound_near(const std::vector<T>& values) {
  return rc::gen::exec([values] {
    const int kind = *rc::gen::inRange(0, 4);
    double base = values.empty() ? 0.0 : static_cast<double>(*rc::gen::elementOf(values));
    if (std::isnan(base)) base = 0.0; // a NaN bound is refused (tested below)
    if (kind == 0) return base;
    if (kind == 1) return base + (*rc::gen::arbitrary<bool>() ? 0.5 : -0.5);
    if (kind == 2)
      return base * (1 + (*rc::gen::arbitrary<bool>() ? 1 : -1) * std::ldexp(1.0, -30));
    return static_cast<double>(*rc::gen::elementOf(
        std::vector<double>{static_cast<double>(std::numeric_limits<T>::lowest()),
                            static_cast<double>(std::numeric_limits<T>::max()), 0.0, -1e30, 1e30}));
  });
}

template <class T>
void check_selection_matches_oracle() {
  rc::detail::checkGTest([] {
    const auto n = *rc::gen::inRange<std::size_t>(1, 60);
    auto values = *rc::gen::container<std::vector<T>>(n, rc::gen::arbitrary<T>());
    if constexpr (std::is_floating_point_v<T>) {
      if (*rc::gen::arbitrary<bool>()) values[0] = std::numeric_limits<T>::quiet_NaN();
    }
    ObjectSelection s;
    s.rule = *rc::gen::elementOf(std::vector<ObjectSelection::Rule>{
        ObjectSelection::Rule::nonzero, ObjectSelection::Rule::at_least,
        ObjectSelection::Rule::range, ObjectSelection::Rule::equal});
    s.low = *bound_near(values);
    s.high = *bound_near(values);
    if (s.low > s.high) std::swap(s.low, s.high);
    s.invert = *rc::gen::arbitrary<bool>();
    const auto v = volume_of(values, {1, static_cast<std::int64_t>(n)});
    const auto got = select_object(v, s, *rc::gen::inRange(1u, 4u));
    std::int64_t count = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const bool want = oracle(s, values[i]);
      RC_ASSERT(got.mask.values()[i] == (want ? 1 : 0));
      count += want ? 1 : 0;
    }
    RC_ASSERT(got.voxels == count);
  });
}

// Theorem: the mask is { p : value(p) satisfies the rule } (complemented by invert), decided
// exactly: the oracle compares integers with the bound as exact rationals (BigInt).
TEST(ObjectSelection, MatchesExactOracleOnEveryDtype) {
  check_selection_matches_oracle<std::uint8_t>();
  check_selection_matches_oracle<std::int8_t>();
  check_selection_matches_oracle<std::uint16_t>();
  check_selection_matches_oracle<std::int16_t>();
  check_selection_matches_oracle<std::uint32_t>();
  check_selection_matches_oracle<std::int32_t>();
  check_selection_matches_oracle<std::uint64_t>();
  check_selection_matches_oracle<std::int64_t>();
  check_selection_matches_oracle<float>();
  check_selection_matches_oracle<double>();
}

// Past 2^53 a double comparison would call 2^53 + 1 equal to 2^53; the exact one does not.
TEST(ObjectSelection, RegressionIntegersPast2To53AreComparedExactly) {
  const std::int64_t big = (std::int64_t{1} << 53) + 1;
  const auto v = volume_of(std::vector<std::int64_t>{big, big - 1, big + 1}, {1, 3});
  ObjectSelection s;
  s.rule = ObjectSelection::Rule::equal;
  s.low = 9007199254740992.0; // 2^53
  EXPECT_EQ(select_object(v, s).mask.values(), (std::vector<std::uint8_t>{0, 1, 0}));
  s.rule = ObjectSelection::Rule::at_least;
  EXPECT_EQ(select_object(v, s).mask.values(), (std::vector<std::uint8_t>{1, 1, 1}));
  s.low = 9007199254740994.0; // 2^53 + 2
  EXPECT_EQ(select_object(v, s).mask.values(), (std::vector<std::uint8_t>{0, 0, 1}));
  const auto u = volume_of(std::vector<std::uint64_t>{~std::uint64_t{0}}, {1, 1});
  s.low = 18446744073709551616.0; // 2^64 > every uint64
  EXPECT_EQ(select_object(u, s).voxels, 0);
}

TEST(ObjectSelection, ScaledValuesAndRanges) {
  auto v = volume_of(std::vector<std::int16_t>{0, 1, 2, 3, 4, 5}, {2, 3});
  v.slope = 2.0;
  v.inter = -1.0; // physical: -1, 1, 3, 5, 7, 9
  ObjectSelection s;
  s.rule = ObjectSelection::Rule::range;
  s.low = 1;
  s.high = 7;
  auto got = select_object(v, s);
  EXPECT_EQ(got.mask.values(), (std::vector<std::uint8_t>{0, 1, 1, 1, 1, 0}));
  EXPECT_EQ(got.voxels, 4);
  EXPECT_EQ(got.min_value, -1.0);
  EXPECT_EQ(got.max_value, 9.0);
  EXPECT_EQ(got.mask.domain(), Domain({2, 3}));
  s.invert = true;
  EXPECT_EQ(select_object(v, s).mask.values(), (std::vector<std::uint8_t>{1, 0, 0, 0, 0, 1}));
  EXPECT_EQ(s.describe(), "not (1 <= value <= 7)");
  s = ObjectSelection{};
  EXPECT_EQ(s.describe(), "value != 0");
  s.rule = ObjectSelection::Rule::at_least;
  s.low = 0.1;
  EXPECT_EQ(s.describe(), "value >= 0.1");
  s.rule = ObjectSelection::Rule::range;
  s.low = 3;
  s.high = 2;
  EXPECT_THROW(select_object(v, s), InvalidArgument);
  s.high = std::nan("");
  EXPECT_THROW(select_object(v, s), InvalidArgument);
}

TEST(ObjectSelection, NanIsNeverSelectedAndEmptyIsReported) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto v = volume_of(std::vector<double>{nan, 1.0, -2.0, nan}, {2, 2});
  ObjectSelection s; // nonzero: NaN != 0 but NaN is no value
  auto got = select_object(v, s);
  EXPECT_EQ(got.mask.values(), (std::vector<std::uint8_t>{0, 1, 1, 0}));
  EXPECT_EQ(got.min_value, -2.0);
  EXPECT_EQ(got.max_value, 1.0);
  s.invert = true;
  EXPECT_EQ(select_object(v, s).mask.values(), (std::vector<std::uint8_t>{1, 0, 0, 1}));
  s.invert = false;
  s.rule = ObjectSelection::Rule::at_least;
  s.low = 5;
  EXPECT_EQ(select_object(v, s).voxels, 0);
  const auto all_nan = volume_of(std::vector<float>{std::nanf(""), std::nanf("")}, {1, 2});
  EXPECT_TRUE(std::isnan(select_object(all_nan, s).min_value));
}

} // namespace
} // namespace zdg
