// Numbers as experiment descriptions write them (flags, TOML values, estimator and shape
// specs): rationals `7`, `-3/4`, `0.125` (exact, decimal: `010` is ten) and decimals in
// scientific notation `1.7e-4`, read as the nearest double. Every reader refuses what is not a
// finite number in its range with InvalidArgument naming `what` and the text (one line).
#pragma once

#include <cstdint>
#include <string>

namespace zdg {

/// A finite real: a rational or a decimal in scientific notation (not inf, not nan, and not a
/// non-zero value that rounds to 0 or to a subnormal double).
double parse_real(const std::string& text, const std::string& what);

/// A real with lo < value <= hi (a positive parameter: lo = 0).
double parse_real_in(const std::string& text, const std::string& what, double lo, double hi);

/// A decimal integer with lo <= value <= hi.
std::int64_t parse_integer_in(const std::string& text, const std::string& what, std::int64_t lo,
                              std::int64_t hi);

/// The shortest text that reads back as v (std::to_chars), for numbers from TOML.
std::string real_text(double v);

} // namespace zdg
