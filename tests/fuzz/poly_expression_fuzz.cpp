// Fuzz target: `poly:` expressions (kernel/digitization/polynomial.hpp), in 2 variables when the
// first byte is even, 3 otherwise. Expected outcomes: a polynomial, or zdg::InvalidArgument
// (bounded nesting, degree and work). On success the filtered sign
// (kernel/digitization/polynomial_sign.hpp) at a few grid points must agree with the exact
// Rational<BigInt> sign (checked for small polynomials, where the exact evaluation is cheap): a
// disagreement traps.
#include <zdg/arith/error.hpp>
#include <zdg/kernel/digitization/polynomial.hpp>
#include <zdg/kernel/digitization/polynomial_sign.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const int nvars = data[0] % 2 == 0 ? 2 : 3;
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    zdg::Polynomial f = zdg::Polynomial::parse(text, nvars);
    if (f.degree() > zdg::kPolynomialMaxDegree) __builtin_trap();
    if (f.terms().size() > 64 || f.degree() > 16) return 0;
    const zdg::PolynomialSign sign(f);
    const std::array<double, 3> t{0.125, -0.375, 1.0 / 3.0};
    const zdg::GridFrame frame(0.5, std::span<const double>(t.data(), std::size_t(nvars)));
    for (std::int64_t a = -2; a <= 2; ++a) {
      const std::int64_t z[3] = {a, 1 - a, 2 * a};
      const auto p = frame.exact(z);
      const zdg::BigRational v = f.value_exact(p.data());
      const int exact = v < zdg::BigRational(0) ? -1 : (v > zdg::BigRational(0) ? 1 : 0);
      if (frame.sign(sign, z) != exact) __builtin_trap();
    }
  } catch (const zdg::InvalidArgument&) {
  }
  return 0;
}
