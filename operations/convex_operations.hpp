// The digital convexity operation of the front ends (zdg convex check, zdg serve "convex check",
// Python convex_check): a set of points of Z^2 or Z^3 in, the verdict of a definition (full
// convexity, Lachaud 2022, or H-convexity) and its witness out, one JSON form. The work is
// kernel/hulls/digital_convexity.hpp, exact by escalation.
//
// Errors: InvalidArgument for an unknown definition name, max_columns = 0, no point, a
// dimension other than 2 or 3, and (hull) a sweep past max_columns columns.
#pragma once

#include <zdg/arith/escalate.hpp>
#include <zdg/arith/integer.hpp>
#include <zdg/kernel/hulls/digital_convexity.hpp>

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace zdg {

/// "full" or "hull" (InvalidArgument "OPTION: 'TEXT' (full or hull)" otherwise).
ConvexityDefinition convexity_definition_from_name(const std::string& name,
                                                   const std::string& option = "definition");
const char* convexity_definition_name(ConvexityDefinition d);

struct ConvexCheckOptions {
  int dim = 2;
  std::vector<BigInt> coords; // row-major, duplicates count once
  ConvexityDefinition definition = ConvexityDefinition::full;
  std::uint64_t max_columns = kConvexityMaxColumns;
};
struct ConvexCheckResult {
  ConvexityCheck check;
  ConvexityDefinition definition = ConvexityDefinition::full;
  int dim = 2;
  std::size_t points = 0; // distinct
  IntKind served = IntKind::int64;
};
ConvexCheckResult convex_check_operation(const ConvexCheckOptions& o);
/// {"convex", "definition", "dimension", "points", "integer_type"} and, when not convex,
/// "witness": {"dimension", "khalimsky", "vertices", "point" (a 0-cell)}; integers as decimal
/// strings.
nlohmann::json to_json(const ConvexCheckResult& r);

/// The number of distinct points of row-major coordinates.
std::size_t distinct_point_count(int dim, const std::vector<BigInt>& coords);

} // namespace zdg
