// The digital-straight-segment operations of the front ends (zdg dss recognize | cover, the
// same operations of zdg serve, the Python functions recognize_dss and tangential_cover):
// options in, result out, one JSON form.
//
//   dss_recognize_operation  is the path a DSS? Its characteristics (a, b, mu, omega), or the
//                            longest prefix that is one (arith/dss_recognizer.hpp), O(n),
//                            exact by escalation
//   dss_cover_operation      the tangential cover (maximal segments) or the greedy
//                            segmentation of an open or closed path
//                            (kernel/curves/maximal_segments.hpp), O(n), int64 points
//
// The path: consecutive points 8-adjacent (4-adjacent when connectivity 4 is asked; for a
// closed path, also the last and the first); the connectivity is 4 when every step is an
// axis step, else 8, unless one is asked. A closed path given with its first point repeated at
// its end has that copy dropped. Errors (InvalidArgument): no point, two consecutive points
// that are not adjacent (named by `where`), a connectivity other than 0, 4 or 8, and for the
// cover a coordinate beyond 64 bits.
#pragma once

#include <zdg/arith/dss_recognizer.hpp>
#include <zdg/arith/escalate.hpp>
#include <zdg/kernel/curves/maximal_segments.hpp>

#include <nlohmann/json_fwd.hpp>

#include <functional>
#include <string>
#include <vector>

namespace zdg {

struct DssPathOptions {
  std::vector<Point2<BigInt>> points;
  int connectivity = 0; // 0: from the steps; 4 or 8: asked
  /// Names point k in messages ("FILE:LINE" for a file); default "point k" (0-based).
  std::function<std::string(std::size_t)> where;
};

struct DssRecognizeResult {
  DssRecognition recognition; // characteristics of the longest DSS prefix
  std::size_t points = 0;
  IntKind served = IntKind::int64;
};
DssRecognizeResult dss_recognize_operation(const DssPathOptions& o);
/// {"is_dss","connectivity", then "a","b","mu","omega" for a DSS or "longest_prefix",
/// "integer_type"} (integers as decimal strings).
nlohmann::json to_json(const DssRecognizeResult& r);

struct DssCoverOptions {
  DssPathOptions path;
  bool closed = false;
  bool greedy = false; // the greedy segmentation instead of the tangential cover
};
struct DssCoverResult {
  std::vector<MaximalSegment> segments;
  bool closed = false, greedy = false;
  Connectivity connectivity = Connectivity::four;
  std::size_t points = 0; // after the repeated closing point is dropped
};
DssCoverResult dss_cover_operation(DssCoverOptions o);
/// {"closed","connectivity","greedy","segments":[{"begin","end","a","b","mu"}, ...]}.
nlohmann::json to_json(const DssCoverResult& r);

} // namespace zdg
