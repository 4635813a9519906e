// Text files of rational half-planes a x + b y <= c, parsed from their bytes (fuzzed) and read
// from a path: one half-plane a line as three rationals "a b c" ("7", "-3/4", "1000.5", read
// by parse_rational: decimal whatever the leading zeros), separated by spaces or tabs; '#'
// starts a comment; blank lines are skipped (the tokenizer of kernel/io/point_file.hpp).
// At least one half-plane. Errors are IoError "SOURCE:LINE: what was wrong".
// Cost: O(size of the text) plus the rational conversions.
#pragma once

#include <zdg/kernel/hulls/convex_body_hull.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace zdg {

std::vector<HalfPlane<BigInt>> parse_halfplane_file(std::string_view text,
                                                    const std::string& source);
std::vector<HalfPlane<BigInt>> read_halfplane_file(const std::string& path);

} // namespace zdg
