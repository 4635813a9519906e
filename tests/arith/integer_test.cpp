// Checked arithmetic of the integer tower against BigInt, floor/ceil division, modulo,
// gcd and Bezout, on every tower type.
#include <zdg/arith/integer.hpp>

#include "tests/support/tower.hpp"

#include <cstdint>
#include <cstdio>
#include <limits>
#include <new>
#include <sstream>
#include <string>
#include <tuple>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {

using namespace zdg;
using test::check_property;

constexpr std::int64_t kMin = std::numeric_limits<std::int64_t>::min();
constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();

bool fits_int64(const BigInt& v) {
  return v >= BigInt(kMin) && v <= BigInt(kMax);
}

// Theorem: Int64 arithmetic is exact or throws OverflowError, and it throws exactly when the
// true (BigInt) result leaves [-2^63, 2^63).
TEST(CheckedInt64, OperationsAgreeWithBigIntAndReportOverflowExactly) {
  check_property([] {
    std::int64_t a = *test::edgy_int64(), b = *test::edgy_int64();
    BigInt A(a), B(b);
    auto agree = [](auto op_checked, const BigInt& truth) {
      if (fits_int64(truth)) {
        RC_ASSERT(to_bigint(op_checked()) == truth);
      } else {
        RC_ASSERT_THROWS_AS(op_checked(), OverflowError);
      }
    };
    agree([&] { return Int64(a) + Int64(b); }, A + B);
    agree([&] { return Int64(a) - Int64(b); }, A - B);
    agree([&] { return Int64(a) * Int64(b); }, A * B);
    agree([&] { return -Int64(a); }, BigInt(-A));
    agree([&] { return abs(Int64(a)); }, BigInt(A < 0 ? BigInt(-A) : A));
    if (b != 0) agree([&] { return Int64(a) / Int64(b); }, BigInt(A / B));
  });
}

TEST(CheckedInt128, MultiplicationAgreesWithBigIntAndReportsOverflow) {
  check_property([] {
    std::int64_t a = *test::edgy_int64(), b = *test::edgy_int64(), c = *test::edgy_int64();
    // a * b always fits 127 bits; (a * b) * c may not.
    Int128 ab = Int128(a) * Int128(b);
    RC_ASSERT(to_bigint(ab) == BigInt(a) * BigInt(b));
    BigInt truth = BigInt(a) * BigInt(b) * BigInt(c);
    BigInt lim = BigInt(1) << 127;
    if (truth >= -lim && truth < lim) {
      RC_ASSERT(to_bigint(ab * Int128(c)) == truth);
    } else {
      RC_ASSERT_THROWS_AS(ab * Int128(c), OverflowError);
    }
  });
}

TEST(CheckedInt64, EdgeCasesAtTheLimits) {
  EXPECT_THROW(Int64::max() + 1, OverflowError);
  EXPECT_THROW(Int64::min() - 1, OverflowError);
  EXPECT_THROW(-Int64::min(), OverflowError);
  EXPECT_THROW(Int64::min() / -1, OverflowError);
  EXPECT_EQ(Int64::min() % -1, 0);
  EXPECT_THROW(Int64(1) / 0, InvalidArgument);
  EXPECT_THROW(Int64(std::uint64_t{1} << 63), OverflowError);
  EXPECT_THROW(Int64(static_cast<int128_t>(kMax) + 1), OverflowError);
  EXPECT_EQ(Int64(kMax) - Int64(kMax), 0);
  EXPECT_THROW(int_cast<Int64>(BigInt(kMax) + 1), OverflowError);
  EXPECT_EQ(int_cast<Int64>(BigInt(kMin)), Int64::min());
  EXPECT_EQ(to_string(Int128::min()), "-170141183460469231731687303715884105728");
  EXPECT_EQ(to_bigint(Int128::min()), -(BigInt(1) << 127));
  EXPECT_EQ(int_cast<Int128>(-(BigInt(1) << 127)), Int128::min());
  EXPECT_THROW(int_cast<Int128>(BigInt(1) << 127), OverflowError);
}

TEST(CheckedInt64, ParsesEveryInt64AndRejectsGarbage) {
  EXPECT_EQ(parse_integer<Int64>("-9223372036854775808"), Int64::min());
  EXPECT_EQ(parse_integer<Int64>("+9223372036854775807"), Int64::max());
  EXPECT_THROW(parse_integer<Int64>("9223372036854775808"), OverflowError);
  EXPECT_THROW(parse_integer<Int64>("12a"), InvalidArgument);
  EXPECT_THROW(parse_integer<Int64>(""), InvalidArgument);
  EXPECT_THROW(parse_integer<Int64>("-"), InvalidArgument);
  EXPECT_EQ(parse_integer<BigInt>("-123456789012345678901234567890").str(),
            "-123456789012345678901234567890");
}

template <class I>
class TowerDivision : public ::testing::Test {};
TYPED_TEST_SUITE(TowerDivision, test::TowerTypes, test::TowerNames);

// Theorem (division with remainder): for b != 0, q = floor(a/b) is the unique integer with
// q b <= a < (q+1) b (b > 0; reversed for b < 0); ceil(a/b) = -floor(-a/b); the Euclidean
// modulo lies in [0, |b|) and a - mod(a, b) is a multiple of b.
TYPED_TEST(TowerDivision, FloorCeilAndModuloIdentities) {
  using I = TypeParam;
  check_property([] {
    std::int64_t a64 = *test::edgy_int64(), b64 = *test::edgy_int64();
    RC_PRE(b64 != 0);
    // Skip the one quotient that leaves int64 (min / -1) on the int64 type.
    if constexpr (std::same_as<I, Int64>) RC_PRE(!(a64 == kMin && b64 == -1));
    I a = a64, b = b64;
    I q = floor_div(a, b);
    BigInt A(a64), B(b64), Q = to_bigint(q);
    if (B > 0) {
      RC_ASSERT(Q * B <= A && A < (Q + 1) * B);
    } else {
      RC_ASSERT(Q * B >= A && A > (Q + 1) * B);
    }
    RC_ASSERT(to_bigint(ceil_div(a, b)) ==
              BigInt(-to_bigint(floor_div(int_cast<BigInt>(a64) * -1, B))));
    I m = mod(a, b);
    RC_ASSERT(m >= 0);
    RC_ASSERT(to_bigint(m) < (B < 0 ? BigInt(-B) : B));
    RC_ASSERT((A - to_bigint(m)) % B == 0);
    I fm = floor_mod(a, b);
    RC_ASSERT(to_bigint(fm) == A - Q * B);
  });
}

// Theorem (Bezout): g = gcd(a, b) divides a and b, g >= 0, and a x + b y = g; the
// coefficients are bounded by max(1, |b|/g) and max(1, |a|/g).
TYPED_TEST(TowerDivision, BezoutIdentity) {
  using I = TypeParam;
  check_property([] {
    std::int64_t a64 = *test::edgy_int64(), b64 = *test::edgy_int64();
    if constexpr (std::same_as<I, Int64>) RC_PRE(a64 != kMin && b64 != kMin);
    auto [g, x, y] = ext_gcd(I(a64), I(b64));
    BigInt A(a64), B(b64), G = to_bigint(g);
    RC_ASSERT(G >= 0);
    RC_ASSERT(A * to_bigint(x) + B * to_bigint(y) == G);
    if (G != 0) {
      RC_ASSERT(A % G == 0 && B % G == 0);
      BigInt absA = A < 0 ? BigInt(-A) : A, absB = B < 0 ? BigInt(-B) : B;
      BigInt X = to_bigint(x), Y = to_bigint(y);
      RC_ASSERT((X < 0 ? BigInt(-X) : X) <= std::max(BigInt(1), BigInt(absB / G)));
      RC_ASSERT((Y < 0 ? BigInt(-Y) : Y) <= std::max(BigInt(1), BigInt(absA / G)));
    }
    RC_ASSERT(g == gcd(I(a64), I(b64)));
  });
}

TYPED_TEST(TowerDivision, WorkedExamples) {
  using I = TypeParam;
  EXPECT_EQ(floor_div(I(-7), I(2)), -4);
  EXPECT_EQ(ceil_div(I(-7), I(2)), -3);
  EXPECT_EQ(floor_div(I(7), I(-2)), -4);
  EXPECT_EQ(mod(I(-7), I(3)), 2);
  EXPECT_EQ(mod(I(-7), I(-3)), 2);
  EXPECT_EQ(floor_mod(I(-7), I(-3)), -1);
  EXPECT_EQ(gcd(I(0), I(0)), 0);
  EXPECT_EQ(gcd(I(-12), I(18)), 6);
  auto r = ext_gcd(I(240), I(46)); // Bezout: 240 (-9) + 46 (47) = 2
  EXPECT_EQ(r.g, 2);
  EXPECT_EQ(r.x, -9);
  EXPECT_EQ(r.y, 47);
  EXPECT_THROW(floor_div(I(1), I(0)), InvalidArgument);
}

} // namespace

namespace {
// Shrunk counterexample: mod(a, b) added |b|, which does not fit for b = -2^63.
TEST(TowerDivisionRegression, ModuloByInt64Minimum) {
  EXPECT_EQ(zdg::mod(zdg::Int64(-50), zdg::Int64::min()), zdg::Int64(9223372036854775758));
}
} // namespace

// --- decimal text: one parser for every type ------------------------------------------------

namespace {

using namespace zdg;
using test::check_property;

bool fits_int64_(const BigInt& v) {
  return v >= BigInt(std::numeric_limits<std::int64_t>::min()) &&
         v <= BigInt(std::numeric_limits<std::int64_t>::max());
}

namespace decimal {

struct DecimalCase {
  std::string text;  // what is parsed
  BigInt value;      // the oracle: Horner's rule on the digits, in BigInt arithmetic
  std::string canon; // the canonical decimal text of value (no '+', no leading zero, no "-0")
};

// Random decimal text: an optional sign, up to 6 leading zeros, then digits (short ones near
// the machine limits as often as huge ones); the oracle reads the digits one by one.
rc::Gen<DecimalCase> decimal_case() {
  auto digits = rc::gen::oneOf(
      rc::gen::container<std::string>(rc::gen::inRange('0', static_cast<char>('9' + 1))),
      rc::gen::mapcat(rc::gen::inRange(1, 45),
                      [](int n) {
                        return rc::gen::container<std::string>(
                            static_cast<std::size_t>(n),
                            rc::gen::inRange('0', static_cast<char>('9' + 1)));
                      }),
      rc::gen::map(test::edgy_int64(), [](std::int64_t v) {
        std::string s = std::to_string(v);
        return s[0] == '-' ? s.substr(1) : s;
      }));
  return rc::gen::map(
      rc::gen::tuple(rc::gen::element<std::string>("", "+", "-"), rc::gen::inRange(0, 7), digits),
      [](const std::tuple<std::string, int, std::string>& t) {
        auto [sign, zeros, body] = t;
        if (body.empty()) body = "0";
        DecimalCase c;
        c.text = sign + std::string(static_cast<std::size_t>(zeros), '0') + body;
        BigInt v = 0;
        for (char d : body) v = v * 10 + (d - '0');
        c.value = sign == "-" ? BigInt(-v) : v;
        std::ostringstream o;
        o << c.value; // GMP's printing, independent of the parser
        c.canon = o.str();
        return c;
      });
}

template <class T>
bool fits(const BigInt& v) {
  using L = std::numeric_limits<T>;
  return v >= BigInt(L::min()) && v <= BigInt(L::max());
}

// parse_integer<T> agrees with the oracle for a machine type T: the value when it fits, else
// OverflowError.
template <class T>
void check_machine(const DecimalCase& c) {
  if (fits<T>(c.value)) {
    RC_ASSERT(BigInt(parse_integer<T>(c.text)) == c.value);
  } else {
    RC_ASSERT_THROWS_AS(parse_integer<T>(c.text), OverflowError);
  }
}

} // namespace decimal

template <class I>
class DecimalText : public ::testing::Test {};
TYPED_TEST_SUITE(DecimalText, test::TowerTypes, test::TowerNames);

// Theorem: integer text is decimal for every type: parse_integer<I>(s) is the value of the
// digits read by Horner's rule in base 10 (leading zeros included, never octal) whenever it
// fits I, OverflowError exactly when it does not; printing the result gives the canonical
// text back, and parsing a printed value gives the value (round trip).
TYPED_TEST(DecimalText, EveryTypeReadsDecimalAndRoundTrips) {
  using I = TypeParam;
  check_property([] {
    const auto c = *decimal::decimal_case();
    const bool in_range = [&] {
      if constexpr (std::same_as<I, BigInt>) {
        return true;
      } else if constexpr (std::same_as<I, Int64>) {
        return fits_int64_(c.value);
      } else {
        return c.value >= to_bigint(Int128::min()) && c.value <= to_bigint(Int128::max());
      }
    }();
    if (!in_range) {
      RC_ASSERT_THROWS_AS(parse_integer<I>(c.text), OverflowError);
      return;
    }
    const I v = parse_integer<I>(c.text);
    RC_ASSERT(to_bigint(v) == c.value);
    RC_ASSERT(to_string(v) == c.canon);
    RC_ASSERT(parse_integer<I>(to_string(v)) == v);
  });
}

// Theorem: the machine-integer parsers (the command line's int and unsigned options) agree
// with the BigInt parser on every text: same value when it fits the type, OverflowError
// otherwise.
TEST(DecimalText, MachineTypesAgreeWithBigInt) {
  check_property([] {
    const auto c = *decimal::decimal_case();
    RC_ASSERT(parse_integer<BigInt>(c.text) == c.value);
    decimal::check_machine<int>(c);
    decimal::check_machine<unsigned>(c);
    decimal::check_machine<std::int64_t>(c);
    decimal::check_machine<std::uint64_t>(c);
  });
}

// Theorem: text that is not [+-]digits is rejected by every parser with InvalidArgument (a
// character that is not a digit inserted anywhere in a valid text, or a sign alone).
TEST(DecimalText, AnythingButSignAndDigitsIsRejectedByEveryType) {
  check_property([] {
    auto c = *decimal::decimal_case();
    const char bad = *rc::gen::element(' ', 'x', 'e', '.', '_', '\n', '\0', 'O', '/', '+', '-');
    const auto at = *rc::gen::inRange<std::size_t>(0, c.text.size() + 1);
    std::string s = c.text;
    // A sign is still valid in front of digits: put it after the first character instead.
    const bool is_sign = bad == '+' || bad == '-';
    s.insert(is_sign ? std::max<std::size_t>(at, 1) : at, 1, bad);
    RC_ASSERT_THROWS_AS(parse_integer<Int64>(s), InvalidArgument);
    RC_ASSERT_THROWS_AS(parse_integer<Int128>(s), InvalidArgument);
    RC_ASSERT_THROWS_AS(parse_integer<BigInt>(s), InvalidArgument);
    RC_ASSERT_THROWS_AS(parse_integer<int>(s), InvalidArgument);
    RC_ASSERT_THROWS_AS(parse_integer<unsigned>(s), InvalidArgument);
  });
}

// The reproducers of issue #18: "010" was read as octal eight by the BigInt parser (Boost's
// string constructor), "08" and "09" aborted the program.
TEST(DecimalText, RegressionLeadingZerosAreDecimalNotOctal) {
  EXPECT_EQ(parse_integer<BigInt>("010"), BigInt(10));
  EXPECT_EQ(parse_integer<BigInt>("08"), BigInt(8));
  EXPECT_EQ(parse_integer<BigInt>("09"), BigInt(9));
  EXPECT_EQ(parse_integer<BigInt>("-0077"), BigInt(-77));
  EXPECT_EQ(parse_integer<BigInt>("+000"), BigInt(0));
  EXPECT_EQ(parse_integer<Int64>("010"), Int64(10));
  EXPECT_EQ(parse_integer<Int128>("-010"), Int128(-10));
  EXPECT_EQ(parse_integer<int>("010"), 10);
  EXPECT_EQ(parse_integer<unsigned>("-0"), 0u);
  EXPECT_EQ(parse_integer<std::uint64_t>("018446744073709551615"),
            std::numeric_limits<std::uint64_t>::max());
  EXPECT_THROW(parse_integer<std::uint64_t>("18446744073709551616"), OverflowError);
  EXPECT_THROW(parse_integer<unsigned>("-1"), OverflowError);
  EXPECT_THROW(parse_integer<int>("2147483648"), OverflowError);
  EXPECT_EQ(parse_integer<int>("-2147483648"), std::numeric_limits<int>::min());
  for (const char* bad : {"0x10", "0X1", "1e3", " 1", "1 ", "", "+", "-", "--1", "+-1", "1_000",
                          "0b1", "0o7", "\xd9\xa3" /* Arabic-Indic three */}) {
    EXPECT_THROW(parse_integer<BigInt>(bad), InvalidArgument) << bad;
    EXPECT_THROW(parse_integer<Int64>(bad), InvalidArgument) << bad;
    EXPECT_THROW(parse_integer<unsigned>(bad), InvalidArgument) << bad;
  }
}

TEST(DecimalText, ErrorsNameAShortExcerptOfTheText) {
  try {
    parse_integer<BigInt>(std::string(1000, '7') + "x");
    FAIL();
  } catch (const InvalidArgument& e) {
    const std::string what = e.what();
    EXPECT_LT(what.size(), 120u);
    EXPECT_NE(what.find("1001 characters"), std::string::npos) << what;
  }
}

} // namespace

namespace {

// Issue #41: a failed GMP allocation is std::bad_alloc (arith/integer.cpp installs GMP's
// allocation functions), not GMP's abort. In a child process under RLIMIT_AS: squaring a
// number until the address space is exhausted throws through GMP's C frames (mpz_mul and its
// temporary allocations) and is caught here; the child exits 0, where GMP's default handler
// would abort it (SIGABRT, "GNU MP: Cannot allocate memory").
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
TEST(BigIntMemory, DISABLED_FailedGmpAllocationIsBadAlloc) {} // the sanitizers reserve the space
#else
TEST(BigIntMemory, FailedGmpAllocationIsBadAlloc) {
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    long pages = 0;
    if (FILE* f = std::fopen("/proc/self/statm", "r")) {
      if (std::fscanf(f, "%ld", &pages) != 1) pages = 0;
      std::fclose(f);
    }
    const rlim_t limit = static_cast<rlim_t>(pages) * static_cast<rlim_t>(::sysconf(_SC_PAGESIZE)) +
                         (rlim_t{64} << 20);
    const rlimit rl{limit, limit};
    if (::setrlimit(RLIMIT_AS, &rl) != 0) ::_exit(5);
    try {
      zdg::BigInt x = (zdg::BigInt(1) << (1 << 22)) - 1;
      for (int i = 0; i < 40; ++i) x = x * x; // 512 KiB doubling: past 64 MiB at i = 7
      ::_exit(4);
    } catch (const std::bad_alloc&) {
      // GMP still works after the failure.
      const zdg::BigInt y = zdg::BigInt(12345) * zdg::BigInt(67890);
      ::_exit(y == zdg::BigInt(838102050) ? 0 : 6);
    } catch (...) {
      ::_exit(3);
    }
  }
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status)) << "the child was killed by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 0);
}
#endif

} // namespace
