// Fuzz target: the test functions of the Laplace-Beltrami estimators (convergence/
// scalar_field.hpp, `--function` and the `u=` estimator parameter). Expected outcomes: a parsed
// function whose jet at a few points is finite or refused with zdg::InvalidArgument; a text
// that does not parse: zdg::InvalidArgument. Never a crash, a hang or undefined behaviour
// (deep nesting is refused past 200 levels, long texts past 1000 characters).
#include <zdg/arith/error.hpp>
#include <zdg/convergence/scalar_field.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const zdg::ScalarField u(text);
    if (u.text() != text) __builtin_trap();
    for (const zdg::Point3<double> p :
         {zdg::Point3<double>{0.3, -0.2, 0.9}, zdg::Point3<double>{0, 0, 0},
          zdg::Point3<double>{-1.5, 2.0, 0.25}}) {
      try {
        const zdg::Jet3 j = u.jet(p);
        if (!std::isfinite(j.value)) __builtin_trap(); // jet() refuses what is not finite
        const double lb = u.laplace_beltrami(p, {0, 0, 1}, 1, 1);
        if (std::isnan(lb) && std::isfinite(j.value)) {
          // finite jet entries give a finite combination unless it overflows to inf - inf
          bool big = false;
          for (double h : j.hessian) big = big || std::abs(h) > 1e300;
          for (double g : j.gradient) big = big || std::abs(g) > 1e300;
          if (!big) __builtin_trap();
        }
      } catch (const zdg::InvalidArgument&) {
      }
    }
  } catch (const zdg::InvalidArgument&) {
  }
  return 0;
}
