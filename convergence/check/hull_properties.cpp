// The lattice hull family of zdg check: hulls of point sets and of the lattice points of a
// disc, against brute force (edge tests, enumeration) and Pick's theorem.
#include <zdg/arith/rational.hpp>
#include <zdg/convergence/check/property.hpp>
#include <zdg/kernel/hulls/convex_body_hull.hpp>
#include <zdg/kernel/hulls/lattice_hull_2d.hpp>
#include <zdg/kernel/hulls/lattice_polygon.hpp>

#include <algorithm>
#include <cstdlib>
#include <numeric>
#include <span>
#include <vector>

namespace zdg::check {

namespace {

using P = Point2<BigInt>;

BigInt cross(const P& o, const P& a, const P& b) {
  return BigInt((a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x));
}

bool lowest_then_leftmost(const P& a, const P& b) {
  return a.y < b.y || (a.y == b.y && a.x < b.x);
}

// Hull vertices by brute force: (p, q) is a counterclockwise edge iff every point is strictly
// left of pq or on the closed segment [p, q]. O(n^3) orientation tests. Vertices are then
// chained from the lowest-then-leftmost one. Degenerate sets: one point, or the two ends of a
// segment.
std::vector<P> brute_hull(std::vector<P> pts) {
  std::sort(pts.begin(), pts.end(), lowest_then_leftmost);
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() == 1) return pts;
  auto on_segment = [](const P& p, const P& q, const P& r) {
    return std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= r.y &&
           r.y <= std::max(p.y, q.y);
  };
  std::vector<std::ptrdiff_t> next(pts.size(), -1);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    for (std::size_t j = 0; j < pts.size(); ++j) {
      if (i == j) continue;
      bool edge = true;
      for (std::size_t k = 0; k < pts.size() && edge; ++k) {
        if (k == i || k == j) continue;
        BigInt o = cross(pts[i], pts[j], pts[k]);
        edge = o > 0 || (o == 0 && on_segment(pts[i], pts[j], pts[k]));
      }
      if (edge) next[i] = static_cast<std::ptrdiff_t>(j);
    }
  }
  std::vector<P> hull;
  std::size_t at = 0; // pts[0] is the lowest-then-leftmost point, a vertex
  do {
    hull.push_back(pts[at]);
    if (next[at] < 0 || hull.size() > pts.size()) break; // never for a correct oracle
    at = static_cast<std::size_t>(next[at]);
  } while (at != 0);
  return hull;
}

std::vector<BigInt> flat(const std::vector<P>& v) {
  std::vector<BigInt> out;
  for (const auto& p : v) {
    out.push_back(p.x);
    out.push_back(p.y);
  }
  return out;
}

// Shoelace and gcd counts (same degenerate conventions as kernel/hulls/lattice_polygon.hpp: a point
// has boundary 1, a segment gcd + 1).
std::pair<BigInt, BigInt> area2_and_boundary(const std::vector<P>& v) {
  if (v.size() == 1) return {BigInt(0), BigInt(1)};
  if (v.size() == 2) {
    return {BigInt(0), BigInt(gcd(abs(BigInt(v[1].x - v[0].x)), abs(BigInt(v[1].y - v[0].y))) + 1)};
  }
  BigInt area2 = 0, boundary = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const P &a = v[i], &b = v[(i + 1) % v.size()];
    area2 += a.x * b.y - b.x * a.y;
    boundary += gcd(abs(BigInt(b.x - a.x)), abs(BigInt(b.y - a.y)));
  }
  return {area2, boundary};
}

std::vector<P> points_of(const Record& c) {
  const Field& f = c.at("points");
  std::vector<P> pts;
  for (std::size_t k = 0; k < f.shape[0]; ++k) pts.push_back({f.ints[2 * k], f.ints[2 * k + 1]});
  return pts;
}

Record polygon_record(const std::vector<P>& v, const BigInt& area2, const BigInt& boundary,
                      const BigInt& interior) {
  return Record()
      .array("vertices", {v.size(), 2}, flat(v))
      .integer("area2", area2)
      .integer("boundary_points", boundary)
      .integer("interior_points", interior);
}

Record zdg_polygon(const std::vector<P>& v, IntKind served) {
  auto m = lattice_polygon_measures_exact(std::span<const P>(v)).value;
  return polygon_record(v, m.area2, m.boundary, m.interior)
      .text("integer_type", std::string(to_string(served)));
}

// --- hull.points.brute_force ----------------------------------------------------------------

Record points_generate(Rng& rng, const Params& params) {
  const auto n = static_cast<std::size_t>(rng.range(1, static_cast<std::int64_t>(params.max_size)));
  const BigInt cx = rng.edgy(params.bits), cy = rng.edgy(params.bits);
  const bool tight = rng.chance(1, 2); // small spread: duplicates and collinear points
  std::vector<BigInt> v;
  for (std::size_t k = 0; k < n; ++k) {
    if (tight) {
      v.push_back(cx + rng.range(-3, 3));
      v.push_back(cy + rng.range(-3, 3));
    } else {
      v.push_back(cx + rng.edgy(params.bits));
      v.push_back(cy + rng.edgy(params.bits));
    }
  }
  return Record().array("points", {n, 2}, std::move(v), Shrink::list);
}

bool points_valid(const Record& c, const Params& params) {
  const Field& f = c.at("points");
  return f.shape.size() == 2 && f.shape[0] >= 1 && f.shape[0] <= params.max_size;
}

Record points_oracle(const Record& c) {
  auto v = brute_hull(points_of(c));
  auto [area2, boundary] = area2_and_boundary(v);
  // Pick: area2 = 2 interior + boundary - 2 (0 for a point or a segment).
  BigInt interior = v.size() <= 2 ? BigInt(0) : BigInt((area2 - boundary + 2) / 2);
  return polygon_record(v, area2, boundary, interior);
}

Record points_compute(const Record& c, IntKind type) {
  const auto pts = points_of(c);
  auto r = escalate_from(type, [&]<class I>(std::type_identity<I>) {
    std::vector<Point2<I>> q;
    for (const auto& p : pts) q.push_back({int_cast<I>(p.x), int_cast<I>(p.y)});
    std::vector<P> out;
    for (const auto& p : lattice_hull_2d<I>(std::span<const Point2<I>>(q))) {
      out.push_back({to_bigint(p.x), to_bigint(p.y)});
    }
    return out;
  });
  return zdg_polygon(r.value, r.served);
}

// --- hull.disc.pick --------------------------------------------------------------------------

Record disc_generate(Rng& rng, const Params& params) {
  const std::int64_t den = rng.chance(1, 3) ? 1 : rng.range(1, 12);
  const std::int64_t r = rng.range(den, static_cast<std::int64_t>(params.max_size) * den);
  return Record()
      .integer("cx", rng.edgy(params.bits) * den + rng.range(0, den - 1), Shrink::toward_zero)
      .integer("cy", rng.edgy(params.bits) * den + rng.range(0, den - 1), Shrink::toward_zero)
      .integer("r", BigInt(r), Shrink::toward_zero)
      .integer("den", BigInt(den), Shrink::toward_zero);
}

bool disc_valid(const Record& c, const Params& params) {
  const BigInt &den = c.int_of("den"), &r = c.int_of("r");
  return den >= 1 && den <= 1000 && r >= den && r <= BigInt(params.max_size) * den;
}

Record disc_request(const Record& c) {
  const std::string den = c.int_of("den").str();
  return Record()
      .text("cx", c.int_of("cx").str() + "/" + den)
      .text("cy", c.int_of("cy").str() + "/" + den)
      .text("r", c.int_of("r").str() + "/" + den);
}

// The lattice points of the disc (den x - cx)^2 + (den y - cy)^2 <= r^2 enumerated around
// (X0, Y0) = floor of the centre (local quantities fit int64), their hull by brute force, and
// the interior count by enumeration: interior = |disc cap Z^2| - boundary (the lattice points
// of conv(K cap Z^2) are those of K, K convex).
Record disc_oracle(const Record& c) {
  const BigInt &cx = c.int_of("cx"), &cy = c.int_of("cy");
  const std::int64_t den = c.i64_of("den"), r = c.i64_of("r");
  const BigInt X0 = floor_div(cx, BigInt(den)), Y0 = floor_div(cy, BigInt(den));
  const std::int64_t fx = int_cast<Int64>(BigInt(cx - X0 * den)).value();
  const std::int64_t fy = int_cast<Int64>(BigInt(cy - Y0 * den)).value();
  const std::int64_t R = r / den + 2;
  std::int64_t count = 0;
  std::vector<P> extremes; // only the ends of a column can be vertices
  for (std::int64_t dx = -R; dx <= R; ++dx) {
    std::int64_t lo = 0, hi = -1;
    for (std::int64_t dy = -R; dy <= R; ++dy) {
      const std::int64_t u = den * dx - fx, w = den * dy - fy;
      if (u * u + w * w > r * r) continue;
      ++count;
      if (hi < lo) lo = dy;
      hi = dy;
    }
    if (hi < lo) continue;
    extremes.push_back({BigInt(dx), BigInt(lo)});
    if (hi != lo) extremes.push_back({BigInt(dx), BigInt(hi)});
  }
  auto v = brute_hull(extremes);
  auto [area2, boundary] = area2_and_boundary(v);
  BigInt interior = BigInt(count) - boundary;
  for (auto& p : v) {
    p.x += X0;
    p.y += Y0;
  }
  return polygon_record(v, area2, boundary, interior);
}

Record disc_compute(const Record& c, IntKind type) {
  const BigInt den = c.int_of("den");
  auto r = escalate_from(type, [&]<class I>(std::type_identity<I>) {
    const I d = int_cast<I>(den);
    auto v = disc_hull<I>(Rational<I>(int_cast<I>(c.int_of("cx")), d),
                          Rational<I>(int_cast<I>(c.int_of("cy")), d),
                          Rational<I>(int_cast<I>(c.int_of("r")), d));
    std::vector<P> out;
    for (const auto& p : v) out.push_back({to_bigint(p.x), to_bigint(p.y)});
    return out;
  });
  return zdg_polygon(r.value, r.served);
}

// Pick's theorem on any answer: area2 = 2 interior + boundary - 2 for a polygon.
std::optional<std::string> pick_judge(const Record&, const Record&, const Record& got) {
  if (!got.has("area2") || !got.has("boundary_points") || !got.has("interior_points") ||
      !got.has("vertices")) {
    return std::nullopt;
  }
  if (got.at("vertices").shape.empty() || got.at("vertices").shape[0] < 3) return std::nullopt;
  const BigInt &a = got.int_of("area2"), &b = got.int_of("boundary_points"),
               &i = got.int_of("interior_points");
  if (a != 2 * i + b - 2) {
    return "Pick's theorem fails on the answer: area2 = " + a.str() +
           " but 2 interior + boundary "
           "- 2 = " +
           BigInt(2 * i + b - 2).str();
  }
  return std::nullopt;
}

} // namespace

void add_hull_properties(std::vector<Property>& out) {
  {
    Property p;
    p.name = "hull.points.brute_force";
    p.theorem = "the hull vertices of a finite set of Z^2 (counterclockwise from the lowest-then-"
                "leftmost, collinear points excluded) are the ends of the edges that leave every "
                "point on their left or on them; area2 by the shoelace formula, boundary points "
                "by gcds, interior points by Pick";
    p.source = "oracle: O(n^3) edge test (brute force); algorithm: Andrew 1979 with the Akl-"
               "Toussaint throw-away; Pick 1899";
    p.operation = "hull points";
    p.sizes = "points <= max-size; coordinates of up to --bits bits";
    p.cost = Cost::moderate;
    p.default_max_size = 16;
    p.max_max_size = 200;
    p.generate = points_generate;
    p.valid = points_valid;
    p.oracle = points_oracle;
    p.compute = points_compute;
    p.judge = pick_judge;
    out.push_back(std::move(p));
  }
  {
    Property p;
    p.name = "hull.disc.pick";
    p.theorem = "the hull of the lattice points of a disc with rational centre and radius "
                "equals the hull of the enumerated points, and area2 = 2 I + B - 2 with I + B "
                "the number of lattice points of the disc (Pick)";
    p.source = "oracle: enumeration of the disc and a brute-force hull; algorithm: Harvey 1999, "
               "Balza-Gomez, Moreau, Michelucci 1999; Pick 1899";
    p.operation = "hull disc";
    p.sizes = "radius <= max-size (denominators <= 12); centre of up to --bits bits";
    p.cost = Cost::heavy;
    p.default_max_size = 6;
    p.max_max_size = 60;
    p.generate = disc_generate;
    p.valid = disc_valid;
    p.request = disc_request;
    p.oracle = disc_oracle;
    p.compute = disc_compute;
    p.judge = pick_judge;
    out.push_back(std::move(p));
  }
}

} // namespace zdg::check
