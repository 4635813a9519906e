// Half-plane files parsed from text: round trip of random rational half-planes, and malformed
// lines named.
#include <zdg/kernel/io/halfplane_file.hpp>

#include "tests/support/tower.hpp"

#include <string>
#include <vector>

namespace {

using namespace zdg;

// Theorem (round trip): the half-planes printed as "a b c" (fractions, integers, decimals with
// leading zeros) are parsed back exactly, one a data line.
TEST(HalfPlaneFile, RoundTripOfRationals) {
  zdg::test::check_property([] {
    const int n = *rc::gen::inRange(1, 20);
    std::string text = "# half-planes\n";
    std::vector<HalfPlane<BigInt>> want;
    for (int k = 0; k < n; ++k) {
      Rational<BigInt> v[3];
      for (auto& x : v) {
        const std::int64_t p = *zdg::test::int64_in(-1000000, 1000000);
        const std::int64_t q = *zdg::test::int64_in(1, 1000);
        x = Rational<BigInt>(BigInt(p), BigInt(q));
        const int form = *rc::gen::inRange(0, 3);
        if (form == 0) {
          text += std::to_string(p) + "/" + std::to_string(q);
        } else if (form == 1) {
          x = Rational<BigInt>(BigInt(p)); // an integer with leading zeros
          text += (p < 0 ? "-00" : "00") + std::to_string(p < 0 ? -p : p);
        } else {
          x = Rational<BigInt>(BigInt(p), BigInt(1000)); // a decimal with three places
          const std::int64_t a = p < 0 ? -p : p;
          std::string frac = std::to_string(a % 1000);
          text += (p < 0 ? "-0" : "0") + std::to_string(a / 1000) + "." +
                  std::string(3 - frac.size(), '0') + frac;
        }
        text += " ";
      }
      text += "\n";
      want.push_back({v[0], v[1], v[2]});
    }
    auto got = parse_halfplane_file(text, "t");
    RC_ASSERT(got.size() == want.size());
    for (std::size_t k = 0; k < got.size(); ++k) {
      RC_ASSERT(got[k].a == want[k].a);
      RC_ASSERT(got[k].b == want[k].b);
      RC_ASSERT(got[k].c == want[k].c);
    }
  });
}

TEST(HalfPlaneFile, MalformedLinesAreNamed) {
  struct Case {
    std::string text, message;
  };
  const Case cases[] = {
      {"", "t: no half-plane (empty file)"},
      {"1 0 3\n1 / 2\n", "t:2:"},
      {"1 0 3\n1 2\n", "t:2: expected 'a b c' (a x + b y <= c), got 2 fields"},
      {"1 0 3/0\n", "t:1: zero denominator"},
      {"1 0 0x3\n", "t:1: not a rational number: '0x3'"},
  };
  for (const auto& c : cases) {
    try {
      parse_halfplane_file(c.text, "t");
      ADD_FAILURE() << "accepted: " << c.text;
    } catch (const IoError& e) {
      EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos) << e.what();
    }
  }
  auto h = parse_halfplane_file("010 -0.50 07/03\n", "t");
  EXPECT_EQ(h[0].a, Rational<BigInt>(10));
  EXPECT_EQ(h[0].b, Rational<BigInt>(BigInt(-1), BigInt(2)));
  EXPECT_EQ(h[0].c, Rational<BigInt>(BigInt(7), BigInt(3)));
}

} // namespace
