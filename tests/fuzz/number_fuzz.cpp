// Fuzz target: integer and rational text (arith/integer.hpp parse_integer, arith/rational.hpp
// parse_rational). Besides "no crash, no sanitizer report", it checks the theorem of the
// decimal parsers: every type accepts the same texts, gives the same value whenever it fits
// (OverflowError exactly when it does not), and printing then parsing gives the value back.
#include <zdg/arith/integer.hpp>
#include <zdg/arith/rational.hpp>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

namespace {

using namespace zdg;

// A failed check is a crash for libFuzzer.
void require(bool ok) {
  if (!ok) __builtin_trap();
}

enum class Outcome { value, invalid, overflow };

template <class T, class F>
Outcome attempt(F&& f, std::optional<T>& out) {
  try {
    out = f();
    return Outcome::value;
  } catch (const InvalidArgument&) {
    return Outcome::invalid;
  } catch (const OverflowError&) {
    return Outcome::overflow;
  }
}

template <class T>
bool fits(const BigInt& v) {
  if constexpr (std::same_as<T, Int64>) {
    return v >= BigInt(INT64_MIN) && v <= BigInt(INT64_MAX);
  } else if constexpr (std::same_as<T, Int128>) {
    return v >= to_bigint(Int128::min()) && v <= to_bigint(Int128::max());
  } else {
    return v >= BigInt(std::numeric_limits<T>::min()) && v <= BigInt(std::numeric_limits<T>::max());
  }
}

BigInt big_of(const BigInt& v) {
  return v;
}
template <class T>
BigInt big_of(const T& v) {
  if constexpr (TowerInt<T>) {
    return to_bigint(v);
  } else {
    return BigInt(v);
  }
}

// parse_integer<T> agrees with the BigInt parse (whose outcome is `ref`).
template <class T>
void check_integer(std::string_view text, Outcome ref, const std::optional<BigInt>& big) {
  std::optional<T> v;
  const Outcome o = attempt<T>([&] { return parse_integer<T>(text); }, v);
  if (ref == Outcome::invalid) {
    require(o == Outcome::invalid);
    return;
  }
  require(ref == Outcome::value);
  if (fits<T>(*big)) {
    require(o == Outcome::value && big_of(*v) == *big);
  } else {
    require(o == Outcome::overflow);
  }
}

template <TowerInt I>
void check_rational(std::string_view text, Outcome ref,
                    const std::optional<Rational<BigInt>>& big) {
  std::optional<Rational<I>> r;
  const Outcome o = attempt<Rational<I>>([&] { return parse_rational<I>(text); }, r);
  if (ref == Outcome::invalid) {
    require(o == Outcome::invalid);
    return;
  }
  // A narrower type may overflow on the unreduced parts; a value it gives must be the same.
  if (o == Outcome::value) {
    require(to_bigint(r->num()) == big->num() && to_bigint(r->den()) == big->den());
  } else {
    require(o == Outcome::overflow);
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::optional<BigInt> big;
  const Outcome ref = attempt<BigInt>([&] { return parse_integer<BigInt>(text); }, big);
  require(ref != Outcome::overflow); // BigInt never overflows
  if (ref == Outcome::value) {
    // Round trip: the printed value parses to itself.
    require(parse_integer<BigInt>(big->str()) == *big);
  }
  check_integer<Int64>(text, ref, big);
  check_integer<Int128>(text, ref, big);
  check_integer<int>(text, ref, big);
  check_integer<unsigned>(text, ref, big);
  check_integer<std::int64_t>(text, ref, big);
  check_integer<std::uint64_t>(text, ref, big);

  std::optional<Rational<BigInt>> q;
  const Outcome qref = attempt<Rational<BigInt>>([&] { return parse_rational<BigInt>(text); }, q);
  require(qref != Outcome::overflow);
  if (ref == Outcome::value) require(qref == Outcome::value && q->num() == *big && q->den() == 1);
  if (qref == Outcome::value) {
    require(q->den() > 0 && gcd(q->num(), q->den()) == 1);
    require(parse_rational<BigInt>(q->str()) == *q);
  }
  check_rational<Int64>(text, qref, q);
  check_rational<Int128>(text, qref, q);
  return 0;
}
