#include <zdg/operations/dss_operations.hpp>

#include <zdg/arith/error.hpp>

#include <nlohmann/json.hpp>

namespace zdg {

namespace {

std::string show(const Point2<BigInt>& p) {
  std::string s(1, '(');
  s.append(p.x.str()).append(", ").append(p.y.str()).push_back(')');
  return s;
}

std::string where(const DssPathOptions& o, std::size_t k) {
  return o.where ? o.where(k) : "point " + std::to_string(k);
}

// Consecutive points adjacent (8, or 4 when asked); the connectivity the path uses.
Connectivity checked_connectivity(const DssPathOptions& o, bool closed) {
  if (o.connectivity != 0 && o.connectivity != 4 && o.connectivity != 8) {
    throw InvalidArgument("connectivity " + std::to_string(o.connectivity) + " is not 4 or 8");
  }
  if (o.points.empty()) throw InvalidArgument("no point");
  const auto& pts = o.points;
  const std::size_t n = pts.size();
  Connectivity c = Connectivity::four;
  for (std::size_t k = 1; k <= n; ++k) {
    if (k == n && (!closed || n == 1)) break;
    const auto &p = pts[k - 1], &q = pts[k % n];
    const BigInt dx = abs(BigInt(q.x - p.x)), dy = abs(BigInt(q.y - p.y));
    const bool ok = dx <= 1 && dy <= 1 && (dx + dy) > 0 && (o.connectivity != 4 || dx + dy == 1);
    if (!ok) {
      const std::string what = k == n
                                   ? "the last point " + show(p) + " and the first point " + show(q)
                                   : "point " + show(q) + " and the previous point " + show(p);
      throw InvalidArgument(where(o, k % n) + ": " + what + " are not " +
                            (o.connectivity == 4 ? "4" : "8") + "-adjacent");
    }
    if (dx == 1 && dy == 1) c = Connectivity::eight;
  }
  return o.connectivity == 8 ? Connectivity::eight : c;
}

int number(Connectivity c) {
  return c == Connectivity::four ? 4 : 8;
}

} // namespace

DssRecognizeResult dss_recognize_operation(const DssPathOptions& o) {
  const Connectivity c = checked_connectivity(o, false);
  auto r = recognize_dss_exact(std::span<const Point2<BigInt>>(o.points), c);
  return {r.value, o.points.size(), r.served};
}

nlohmann::json to_json(const DssRecognizeResult& r) {
  const auto& rec = r.recognition;
  nlohmann::json j{{"is_dss", rec.is_dss}, {"connectivity", number(rec.connectivity)}};
  if (rec.is_dss) {
    j["a"] = rec.characteristics.a.str();
    j["b"] = rec.characteristics.b.str();
    j["mu"] = rec.characteristics.mu.str();
    j["omega"] = rec.characteristics.omega.str();
  } else {
    j["longest_prefix"] = rec.longest_prefix;
  }
  j["integer_type"] = std::string(to_string(r.served));
  return j;
}

DssCoverResult dss_cover_operation(DssCoverOptions o) {
  auto& pts = o.path.points;
  if (o.closed && pts.size() > 1 && pts.front() == pts.back()) pts.pop_back();
  DssCoverResult out;
  out.closed = o.closed;
  out.greedy = o.greedy;
  out.connectivity = checked_connectivity(o.path, o.closed);
  out.points = pts.size();
  std::vector<Point2<std::int64_t>> p64;
  p64.reserve(pts.size());
  for (std::size_t k = 0; k < pts.size(); ++k) {
    try {
      p64.push_back({int_cast<Int64>(pts[k].x).value(), int_cast<Int64>(pts[k].y).value()});
    } catch (const OverflowError&) {
      throw InvalidArgument(where(o.path, k) + ": point " + show(pts[k]) +
                            " has a coordinate beyond 64 bits (the cover works on int64 points)");
    }
  }
  out.segments = o.greedy ? greedy_segmentation_exact(p64, o.closed, out.connectivity).value
                          : maximal_segments_exact(p64, o.closed, out.connectivity).value;
  return out;
}

nlohmann::json to_json(const DssCoverResult& r) {
  nlohmann::json arr = nlohmann::json::array();
  for (const auto& s : r.segments) {
    arr.push_back({{"begin", s.begin},
                   {"end", s.end},
                   {"a", std::to_string(s.a)},
                   {"b", std::to_string(s.b)},
                   {"mu", to_string(Int128(s.mu))}});
  }
  return {{"closed", r.closed},
          {"connectivity", number(r.connectivity)},
          {"greedy", r.greedy},
          {"segments", arr}};
}

} // namespace zdg
