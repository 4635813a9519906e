#include <zdg/kernel/hulls/convex_body_hull.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/hulls/lattice_polygon.hpp>

#include <boost/multiprecision/gmp.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>
#include <string>

namespace zdg {

const char* to_string(RegionKind k) {
  switch (k) {
  case RegionKind::bounded:
    return "bounded";
  case RegionKind::unbounded:
    return "unbounded";
  case RegionKind::empty:
    return "empty";
  }
  return "?";
}

template <TowerInt I>
I floor_sqrt(const I& n) {
  if (n < 0) throw InvalidArgument("square root of negative " + to_string(n));
  if constexpr (std::same_as<I, BigInt>) {
    return boost::multiprecision::sqrt(n);
  } else {
    using U = uint128_t;
    const U m = static_cast<U>(n.value());
    if (m < 2) return n;
    // A double estimate (off by at most a few units below 2^64), corrected exactly; past
    // 2^64, Newton from above (monotone down to the floor).
    U x = static_cast<U>(static_cast<std::uint64_t>(std::sqrt(static_cast<double>(m))));
    if (m >> 64 != 0) {
      x = static_cast<U>(static_cast<double>(x) * (1.0 + 1e-9)) + 2;
      for (;;) {
        U y = (x + m / x) / 2;
        if (y >= x) break;
        x = y;
      }
    }
    while (x * x > m) --x;
    while ((x + 1) * (x + 1) <= m) ++x;
    return I(static_cast<typename I::value_type>(x));
  }
}

namespace {

// Integers k with A k^2 + 2 B k + C <= 0, A > 0.
template <TowerInt I>
LineRange<I> quadratic_range(const I& A, const I& B, const I& C) {
  I delta = B * B - A * C;
  if (delta < 0) return std::nullopt;
  I s = floor_sqrt(delta);
  auto f_le0 = [&](const I& k) { return (A * k + 2 * B) * k + C <= 0; };
  I hi = floor_div(I(s - B), A);
  if (f_le0(I(hi + 1))) hi += 1;
  I lo = ceil_div(I(-B - s), A);
  if (f_le0(I(lo - 1))) lo -= 1;
  if (lo > hi) return std::nullopt;
  return std::pair<I, I>{lo, hi};
}

template <TowerInt I>
I lcm(const I& a, const I& b) {
  return a / gcd(a, b) * b;
}

} // namespace

template <TowerInt I>
bool QuadraticBody<I>::contains(const Point2<I>& p) const {
  I du = D * p.x - Cx, dv = D * p.y - Cy;
  return alpha * du * du + beta * dv * dv <= gamma;
}

template <TowerInt I>
LineRange<I> QuadraticBody<I>::line_range(const Point2<I>& q, const Point2<I>& v) const {
  I ux = D * q.x - Cx, uy = D * q.y - Cy, vx = D * v.x, vy = D * v.y;
  I A = alpha * vx * vx + beta * vy * vy;
  if (A == 0) throw InvalidArgument("line_range: zero direction");
  I B = alpha * ux * vx + beta * uy * vy;
  I C = alpha * ux * ux + beta * uy * uy - gamma;
  return quadratic_range(A, B, C);
}

// The quadratic A k^2 + 2 B k + C of the line q + k v: the fast paths decide the common
// short answers (k = 0 or 1) without a square root.
template <TowerInt I>
I QuadraticBody<I>::last_inside(const Point2<I>& q, const Point2<I>& v) const {
  I ux = D * q.x - Cx, uy = D * q.y - Cy, vx = D * v.x, vy = D * v.y;
  I A = alpha * vx * vx + beta * vy * vy;
  I B = alpha * ux * vx + beta * uy * vy;
  I C = alpha * ux * ux + beta * uy * uy - gamma;
  if (A + 2 * B + C > 0) return I(0); // f(1) > 0, and f(0) <= 0: the interval ends at 0
  return quadratic_range(A, B, C)->second;
}

template <TowerInt I>
std::optional<I> QuadraticBody<I>::first_inside(const Point2<I>& q, const Point2<I>& v) const {
  I ux = D * q.x - Cx, uy = D * q.y - Cy, vx = D * v.x, vy = D * v.y;
  I A = alpha * vx * vx + beta * vy * vy;
  I B = alpha * ux * vx + beta * uy * vy;
  I C = alpha * ux * ux + beta * uy * uy - gamma;
  if (A + 2 * B + C <= 0) return I(1);
  if (-B <= A) return std::nullopt; // the parabola's minimum is at k <= 1: f > 0 for k >= 1
  auto r = quadratic_range(A, B, C);
  if (!r || r->second < 1) return std::nullopt;
  return r->first;
}

namespace {
template <TowerInt I>
QuadraticBody<I> make_quadratic(const Rational<I>& cx, const Rational<I>& cy, I alpha, I beta,
                                I gamma, const Rational<I>& ax, const Rational<I>& ay) {
  QuadraticBody<I> b;
  b.D = lcm(cx.den(), cy.den());
  b.Cx = cx.num() * (b.D / cx.den());
  b.Cy = cy.num() * (b.D / cy.den());
  I g = gcd(alpha, gcd(beta, gamma));
  b.alpha = alpha / g;
  b.beta = beta / g;
  b.gamma = gamma / g;
  b.xlo = (cx - ax).ceil();
  b.xhi = (cx + ax).floor();
  b.ylo = (cy - ay).ceil();
  b.yhi = (cy + ay).floor();
  // Scan along the shorter axis (a tall ellipse by columns): few lines, each long.
  if (b.yhi - b.ylo > b.xhi - b.xlo) {
    b.u = {I(1), I(0)};
    b.tlo = b.xlo;
    b.thi = b.xhi;
  } else {
    b.tlo = b.ylo;
    b.thi = b.yhi;
  }
  return b;
}
} // namespace

template <TowerInt I>
QuadraticBody<I> disc_body(const Rational<I>& cx, const Rational<I>& cy, const Rational<I>& r) {
  if (r < Rational<I>(0)) throw InvalidArgument("negative radius " + r.str());
  I D = lcm(cx.den(), cy.den());
  I rd2 = r.den() * r.den();
  I g = D * r.num();
  QuadraticBody<I> b = make_quadratic(cx, cy, rd2, rd2, I(g * g), r, r);
  // A disc is scanned by rows whatever its box: the second row from the bottom already holds
  // a lattice point when r >= 1 (its chord is at least 2 sqrt(2r - 1) long), and the first
  // vertex found, the leftmost point of the lowest row, is then the first of the output (the
  // walk can be streamed).
  b.u = {I(0), I(1)};
  b.tlo = b.ylo;
  b.thi = b.yhi;
  return b;
}

template <TowerInt I>
QuadraticBody<I> ellipse_body(const Rational<I>& cx, const Rational<I>& cy, const Rational<I>& a,
                              const Rational<I>& b) {
  if (!(a > Rational<I>(0))) throw InvalidArgument("ellipse semi-axis a = " + a.str() + " <= 0");
  if (!(b > Rational<I>(0))) throw InvalidArgument("ellipse semi-axis b = " + b.str() + " <= 0");
  I D = lcm(cx.den(), cy.den());
  I alpha = a.den() * b.num(), beta = b.den() * a.num(), gamma = D * a.num() * b.num();
  return make_quadratic(cx, cy, I(alpha * alpha), I(beta * beta), I(gamma * gamma), a, b);
}

// --- half-planes -------------------------------------------------------------------------

template <TowerInt I>
bool PolygonBody<I>::contains(const Point2<I>& p) const {
  for (const auto& [a, b, c] : rows) {
    if (a * p.x + b * p.y > c) return false;
  }
  return true;
}

template <TowerInt I>
LineRange<I> PolygonBody<I>::line_range(const Point2<I>& q, const Point2<I>& v) const {
  std::optional<I> lo, hi;
  for (const auto& [a, b, c] : rows) {
    I s = a * v.x + b * v.y;
    I rhs = c - a * q.x - b * q.y;
    if (s > 0) {
      I k = floor_div(rhs, s);
      if (!hi || k < *hi) hi = k;
    } else if (s < 0) {
      I k = ceil_div(rhs, s);
      if (!lo || k > *lo) lo = k;
    } else if (rhs < 0) {
      return std::nullopt;
    }
  }
  if (!lo || !hi) throw InvalidArgument("line_range: the polygon is unbounded along the line");
  if (*lo > *hi) return std::nullopt;
  return std::pair<I, I>{*lo, *hi};
}

namespace {

using Row = std::array<std::int64_t, 3>;

// Feasible intersection points of pairs of lines (as X/det, Y/det with det > 0), and the
// largest |coordinate| of all pairwise intersections.
template <TowerInt I>
struct Vertices {
  std::vector<std::array<I, 3>> feasible; // X, Y, det (det > 0)
  I max_abs{0};
};

template <TowerInt I>
Vertices<I> pair_vertices(const std::vector<std::array<I, 3>>& rows) {
  Vertices<I> out;
  const std::size_t m = rows.size();
  for (std::size_t i = 0; i < m; ++i) {
    for (std::size_t j = i + 1; j < m; ++j) {
      const auto& [a1, b1, c1] = rows[i];
      const auto& [a2, b2, c2] = rows[j];
      I det = a1 * b2 - a2 * b1;
      if (det == 0) continue;
      I X = c1 * b2 - c2 * b1, Y = a1 * c2 - a2 * c1;
      if (det < 0) {
        det = -det;
        X = -X;
        Y = -Y;
      }
      I bx = abs(ceil_div(abs(X), det)), by = abs(ceil_div(abs(Y), det));
      if (bx > out.max_abs) out.max_abs = bx;
      if (by > out.max_abs) out.max_abs = by;
      bool ok = true;
      for (const auto& [a, b, c] : rows) {
        if (a * X + b * Y > c * det) {
          ok = false;
          break;
        }
      }
      if (ok) out.feasible.push_back({X, Y, det});
    }
  }
  return out;
}

} // namespace

template <TowerInt I>
std::pair<RegionKind, PolygonBody<I>> polygon_body(std::span<const HalfPlane<I>> hs) {
  PolygonBody<I> body;
  for (const auto& h : hs) {
    I L = lcm(lcm(h.a.den(), h.b.den()), h.c.den());
    I a = h.a.num() * (L / h.a.den()), b = h.b.num() * (L / h.b.den()),
      c = h.c.num() * (L / h.c.den());
    if (a == 0 && b == 0) {
      if (c < 0) return {RegionKind::empty, body};
      continue; // 0 <= c: the whole plane
    }
    I g = gcd(a, gcd(b, c));
    body.rows.push_back({I(a / g), I(b / g), I(c / g)});
  }
  if (body.rows.empty()) return {RegionKind::unbounded, body};
  // Bounded iff the recession cone {v : n_i . v <= 0} is {0}; a nontrivial cone contains a
  // vector orthogonal to some normal n_j.
  bool bounded = true;
  for (const auto& r : body.rows) {
    for (int sg : {1, -1}) {
      I vx = -r[1] * sg, vy = r[0] * sg;
      bool in_cone = true;
      for (const auto& s : body.rows) {
        if (s[0] * vx + s[1] * vy > 0) {
          in_cone = false;
          break;
        }
      }
      if (in_cone) bounded = false;
    }
  }
  auto vs = pair_vertices(body.rows);
  if (!bounded) {
    // Nonempty iff it meets a box holding every pairwise intersection and every axis
    // crossing of a line (a nonempty region has a minimal face there).
    I M = vs.max_abs + 1;
    for (const auto& [a, b, c] : body.rows) {
      if (a != 0) M = std::max(M, I(ceil_div(abs(c), abs(a)) + 1));
      if (b != 0) M = std::max(M, I(ceil_div(abs(c), abs(b)) + 1));
    }
    auto boxed = body.rows;
    boxed.push_back({I(1), I(0), M});
    boxed.push_back({I(-1), I(0), M});
    boxed.push_back({I(0), I(1), M});
    boxed.push_back({I(0), I(-1), M});
    auto bv = pair_vertices(boxed);
    return {bv.feasible.empty() ? RegionKind::empty : RegionKind::unbounded, body};
  }
  if (vs.feasible.empty()) return {RegionKind::empty, body};
  // A flat direction: the lattice width direction of the vertices scaled to integers.
  {
    I L = 1;
    for (const auto& vtx : vs.feasible) L = lcm(L, vtx[2]);
    std::vector<Point2<I>> scaled;
    for (const auto& [X, Y, det] : vs.feasible) scaled.push_back({X * (L / det), Y * (L / det)});
    std::sort(scaled.begin(), scaled.end(), [](const Point2<I>& a, const Point2<I>& b) {
      return a.x < b.x || (a.x == b.x && a.y < b.y);
    });
    scaled.erase(std::unique(scaled.begin(), scaled.end()), scaled.end());
    body.u = lattice_width<I>(std::span<const Point2<I>>(scaled)).direction;
    bool first_t = true;
    for (const auto& [X, Y, det] : vs.feasible) {
      I num = body.u.x * X + body.u.y * Y;
      I lo = ceil_div(num, det), hi = floor_div(num, det);
      if (first_t || lo < body.tlo) body.tlo = lo;
      if (first_t || hi > body.thi) body.thi = hi;
      first_t = false;
    }
  }
  bool first = true;
  for (const auto& [X, Y, det] : vs.feasible) {
    I xl = ceil_div(X, det), xh = floor_div(X, det), yl = ceil_div(Y, det), yh = floor_div(Y, det);
    if (first || xl < body.xlo) body.xlo = xl;
    if (first || xh > body.xhi) body.xhi = xh;
    if (first || yl < body.ylo) body.ylo = yl;
    if (first || yh > body.yhi) body.yhi = yh;
    first = false;
  }
  return {RegionKind::bounded, body};
}

// --- the walk ----------------------------------------------------------------------------

namespace detail {

// Scans of lattice rows without a lattice point (thin bodies) stop loudly past this many.
constexpr long kMaxEmptyRows = 1L << 26;

[[noreturn]] void throw_thin(const std::string& at) {
  throw InvalidArgument("convex body hull: more than 2^26 lattice rows without a lattice point "
                        "from row " +
                        at + " (a long thin region; not supported)");
}

// The lattice direction closest to d_out (counterclockwise side) with P + e in K, given the
// unimodular bracket: P + d_in in K, P + d_out not, det(d_out, d_in) = 1.
// Returns d_in and d_out of the final bracket (det(d_out, d_in) = 1).
template <TowerInt I, class Body>
std::pair<Point2<I>, Point2<I>> descend(const Body& K, const Point2<I>& P, Point2<I> din,
                                        Point2<I> dout) {
  for (;;) {
    din = din + K.last_inside(P + din, dout) * dout;
    Point2<I> m = din + dout;
    auto r2 = K.first_inside(P + m, din);
    if (!r2) return {din, dout};
    I ks = *r2;
    dout = m + I(ks - 1) * din;
    din = m + ks * din;
  }
}

// The next edge direction at the vertex P reached along d (P - d in K), given w with
// det(d, w) = 1: nullopt when every lattice point of K lies on the line of d (the hull is a
// segment). Returns the direction e and a w' with det(e, w') = 1 for the next call.
template <TowerInt I, class Body>
std::optional<std::pair<Point2<I>, Point2<I>>>
next_direction(const Body& K, const Point2<I>& P, const Point2<I>& d, const Point2<I>& w) {
  auto r = K.line_range(P + w, d);
  if (!r) return std::nullopt;
  Point2<I> din = w + r->second * d;
  auto [e, dout] = descend(K, P, din, din + d);
  return std::pair<Point2<I>, Point2<I>>{e, Point2<I>{I(-dout.x), I(-dout.y)}};
}

// w with det(d, w) = 1 for a primitive d.
template <TowerInt I>
Point2<I> unimodular_partner(const Point2<I>& d) {
  auto bz = ext_gcd(d.x, d.y); // s dx + t dy = 1; w = (-t, s)
  return {I(-bz.y), bz.x};
}

// The lattice scan frame of a body: lines <u, x> = t, each parametrized as q(t) + k v with
// det(v, w) = 1 and <u, w> = 1 (for u = (0, 1): rows, v = (1, 0), w = (0, 1)).
template <TowerInt I>
struct ScanFrame {
  Point2<I> u, v, w;
  Point2<I> origin(const I& t) const { return {t * w.x, t * w.y}; } // <u, origin> = t
};

template <TowerInt I>
ScanFrame<I> scan_frame(const Point2<I>& u) {
  auto bz = ext_gcd(u.x, u.y); // s ux + r uy = 1: w = (s, r)
  return {u, Point2<I>{u.y, I(-u.x)}, Point2<I>{bz.x, bz.y}};
}

// The first edge direction at the start vertex P0 (on the first nonempty scan line, the
// first lattice point along v) when P0 + v is not in K: the lattice direction of least angle
// from v in (0, pi).
template <TowerInt I, class Body>
std::optional<Point2<I>> first_direction(const Body& K, const ScanFrame<I>& F, const Point2<I>& P0,
                                         const I& t0) {
  if (auto r = K.line_range(P0 + F.w, F.v)) {
    Point2<I> din = F.w + r->second * F.v;
    return descend(K, P0, din, din + F.v).first;
  }
  // The next scan line misses the lattice: scan the lines beyond (thin bodies only).
  std::optional<Point2<I>> best;
  long empty = 0;
  for (I t = t0 + 2; t <= K.thi; ++t) {
    auto r = K.line_range(F.origin(t), F.v);
    if (!r) {
      if (++empty > kMaxEmptyRows) throw_thin(to_string(I(t0 + 2)));
      continue;
    }
    Point2<I> q = F.origin(t) + r->second * F.v;
    Point2<I> e{I(q.x - P0.x), I(q.y - P0.y)};
    if (!best || e.x * best->y - e.y * best->x > 0) best = e;
  }
  if (best) {
    I g = gcd(best->x, best->y);
    best = Point2<I>{I(best->x / g), I(best->y / g)};
  }
  return best;
}

} // namespace detail

template <TowerInt I, class Body>
std::size_t convex_body_hull_walk(const Body& K,
                                  const std::function<void(const Point2<I>&)>& emit) {
  if (K.tlo > K.thi || K.ylo > K.yhi || K.xlo > K.xhi) return 0;
  const auto F = detail::scan_frame(K.u);
  // The first scan line meeting the lattice; its first point along v is a hull vertex.
  std::optional<Point2<I>> p0;
  I kr, t0;
  long empty = 0;
  for (I t = K.tlo; t <= K.thi; ++t) {
    if (auto r = K.line_range(F.origin(t), F.v)) {
      p0 = F.origin(t) + r->first * F.v;
      kr = r->second - r->first;
      t0 = t;
      break;
    }
    if (++empty > detail::kMaxEmptyRows) detail::throw_thin(to_string(K.tlo));
  }
  if (!p0) return 0;
  emit(*p0);
  std::size_t count = 1;
  Point2<I> P, d;
  if (kr > 0) {
    P = *p0 + kr * F.v;
    d = F.v;
  } else {
    auto e = detail::first_direction(K, F, *p0, t0);
    if (!e) return count;
    P = *p0 + K.last_inside(*p0, *e) * *e;
    d = *e;
  }
  emit(P);
  ++count;
  Point2<I> w = detail::unimodular_partner(d);
  for (;;) {
    auto e = detail::next_direction(K, P, d, w);
    if (!e) break;
    d = e->first;
    w = e->second;
    Point2<I> Q = P + K.last_inside(P, d) * d;
    if (Q == *p0) break;
    emit(Q);
    ++count;
    P = Q;
  }
  return count;
}

template <TowerInt I, class Body>
std::vector<Point2<I>> convex_body_hull(const Body& K) {
  std::vector<Point2<I>> out;
  convex_body_hull_walk<I, Body>(K, [&out](const Point2<I>& p) { out.push_back(p); });
  // Start at the lowest, then leftmost vertex (a segment: its lowest-then-leftmost end).
  auto lowest =
      std::min_element(out.begin(), out.end(), [](const Point2<I>& a, const Point2<I>& b) {
        return a.y < b.y || (a.y == b.y && a.x < b.x);
      });
  std::rotate(out.begin(), lowest, out.end());
  return out;
}

template <TowerInt I>
std::vector<Point2<I>> disc_hull(const Rational<I>& cx, const Rational<I>& cy,
                                 const Rational<I>& r) {
  return convex_body_hull<I>(disc_body(cx, cy, r));
}

template <TowerInt I>
std::vector<Point2<I>> ellipse_hull(const Rational<I>& cx, const Rational<I>& cy,
                                    const Rational<I>& a, const Rational<I>& b) {
  return convex_body_hull<I>(ellipse_body(cx, cy, a, b));
}

template <TowerInt I>
HalfPlaneHull<I> halfplane_hull(std::span<const HalfPlane<I>> hs) {
  auto [kind, body] = polygon_body(hs);
  HalfPlaneHull<I> out;
  out.region = kind;
  if (kind == RegionKind::bounded) out.vertices = convex_body_hull<I>(body);
  return out;
}

namespace {
template <TowerInt I>
Rational<I> narrow(const Rational<BigInt>& q) {
  return Rational<I>(int_cast<I>(q.num()), int_cast<I>(q.den()));
}
template <TowerInt I>
std::vector<Point2<BigInt>> widen(const std::vector<Point2<I>>& v) {
  std::vector<Point2<BigInt>> out;
  out.reserve(v.size());
  for (const auto& p : v) out.push_back({to_bigint(p.x), to_bigint(p.y)});
  return out;
}
} // namespace

Escalated<BodyHull> disc_hull_exact(const Rational<BigInt>& cx, const Rational<BigInt>& cy,
                                    const Rational<BigInt>& r, std::uint64_t max_vertices) {
  check_disc_hull_vertices(r, max_vertices);
  return escalate([&]<class I>(std::type_identity<I>) {
    return BodyHull{RegionKind::bounded,
                    widen(disc_hull<I>(narrow<I>(cx), narrow<I>(cy), narrow<I>(r)))};
  });
}

Escalated<BodyHull> ellipse_hull_exact(const Rational<BigInt>& cx, const Rational<BigInt>& cy,
                                       const Rational<BigInt>& a, const Rational<BigInt>& b,
                                       std::uint64_t max_vertices) {
  ellipse_body(cx, cy, a, b); // validates a, b > 0 before any escalation
  check_ellipse_hull_vertices(a, b, max_vertices);
  return escalate([&]<class I>(std::type_identity<I>) {
    return BodyHull{RegionKind::bounded, widen(ellipse_hull<I>(narrow<I>(cx), narrow<I>(cy),
                                                               narrow<I>(a), narrow<I>(b)))};
  });
}

Escalated<BodyHull> halfplane_hull_exact(std::span<const HalfPlane<BigInt>> hs) {
  return escalate([&]<class I>(std::type_identity<I>) {
    std::vector<HalfPlane<I>> n;
    n.reserve(hs.size());
    for (const auto& h : hs) n.push_back({narrow<I>(h.a), narrow<I>(h.b), narrow<I>(h.c)});
    auto h = halfplane_hull<I>(std::span<const HalfPlane<I>>(n));
    return BodyHull{h.region, widen(h.vertices)};
  });
}

namespace {

// Hands a vertex of type I to the sink (int64 when it fits).
template <TowerInt I>
void send(HullVertexSink& sink, const Point2<I>& p) {
  if constexpr (std::same_as<I, Int64>) {
    sink.vertex(p.x.value(), p.y.value());
  } else if constexpr (std::same_as<I, Int128>) {
    const auto lo = static_cast<int128_t>(INT64_MIN), hi = static_cast<int128_t>(INT64_MAX);
    if (p.x.value() >= lo && p.x.value() <= hi && p.y.value() >= lo && p.y.value() <= hi) {
      sink.vertex(static_cast<std::int64_t>(p.x.value()), static_cast<std::int64_t>(p.y.value()));
    } else {
      sink.vertex(to_bigint(p.x), to_bigint(p.y));
    }
  } else {
    sink.vertex(p.x, p.y);
  }
}

// Streams the hull of a quadratic body, escalating: a run that overflows has handed over a
// prefix of the vertex sequence (the hull and the walk do not depend on the type), so the
// next type skips as many vertices as were already sent.
template <class MakeBody>
StreamedHull stream_quadratic(HullVertexSink& sink, MakeBody&& make_body) {
  std::size_t sent = 0;
  auto res = escalate([&]<class I>(std::type_identity<I>) {
    const QuadraticBody<I> body = make_body(std::type_identity<I>{});
    std::size_t index = 0;
    if (body.u == Point2<I>{I(0), I(1)}) {
      // Row scan: the walk starts at the lowest-then-leftmost vertex, the output order.
      return convex_body_hull_walk<I>(body, [&](const Point2<I>& p) {
        if (index++ < sent) return;
        send(sink, p);
        ++sent;
      });
    }
    // Column scan (a tall ellipse): the hull is buffered and rotated to the output order.
    auto v = convex_body_hull<I>(body);
    for (std::size_t k = sent; k < v.size(); ++k) send(sink, v[k]);
    sent = v.size();
    return v.size();
  });
  return {res.value, res.served};
}

} // namespace

StreamedHull disc_hull_stream(const Rational<BigInt>& cx, const Rational<BigInt>& cy,
                              const Rational<BigInt>& r, HullVertexSink& sink,
                              std::uint64_t max_vertices) {
  check_disc_hull_vertices(r, max_vertices);
  return stream_quadratic(sink, [&]<class I>(std::type_identity<I>) {
    return disc_body<I>(narrow<I>(cx), narrow<I>(cy), narrow<I>(r));
  });
}

StreamedHull ellipse_hull_stream(const Rational<BigInt>& cx, const Rational<BigInt>& cy,
                                 const Rational<BigInt>& a, const Rational<BigInt>& b,
                                 HullVertexSink& sink, std::uint64_t max_vertices) {
  ellipse_body(cx, cy, a, b); // validates a, b > 0 before any escalation
  check_ellipse_hull_vertices(a, b, max_vertices);
  return stream_quadratic(sink, [&]<class I>(std::type_identity<I>) {
    return ellipse_body<I>(narrow<I>(cx), narrow<I>(cy), narrow<I>(a), narrow<I>(b));
  });
}

namespace {
// An upper bound on a nonnegative rational, as a double rounded up (+inf past the range).
double upper_double(const Rational<BigInt>& q) {
  const double v = q.to_double();
  if (!std::isfinite(v)) return std::numeric_limits<double>::infinity();
  return std::nextafter(v * (1 + 1e-12), std::numeric_limits<double>::infinity());
}
} // namespace

std::uint64_t disc_hull_max_vertices(const Rational<BigInt>& r) {
  if (r < Rational<BigInt>(0)) throw InvalidArgument("negative radius " + r.str());
  // The hull lies in the disc: its perimeter is at most 2 pi r.
  return convex_lattice_polygon_max_vertices(2 * std::numbers::pi * upper_double(r));
}

std::uint64_t ellipse_hull_max_vertices(const Rational<BigInt>& a, const Rational<BigInt>& b) {
  if (!(a > Rational<BigInt>(0)) || !(b > Rational<BigInt>(0))) {
    throw InvalidArgument("ellipse semi-axes " + a.str() + ", " + b.str() + " must be > 0");
  }
  // The perimeter of an ellipse is at most pi sqrt(2 (a^2 + b^2)) (Euler's upper bound).
  const double A = upper_double(a), B = upper_double(b);
  return convex_lattice_polygon_max_vertices(std::numbers::pi * std::sqrt(2 * (A * A + B * B)) *
                                             (1 + 1e-12));
}

namespace {

std::string count_text(std::uint64_t n) {
  if (n == UINT64_MAX) return "more than 1.8e19";
  return std::to_string(n);
}

void check_vertex_bound(const std::string& body, std::uint64_t bound, std::uint64_t max_vertices,
                        const std::string& expected) {
  if (bound <= max_vertices) return;
  throw InvalidArgument(body + " hull: the hull could have up to " + count_text(bound) +
                        " vertices" + expected + ", more than the vertex bound " +
                        std::to_string(max_vertices) +
                        " (max_vertices, --max-vertices: raise it to compute this hull)");
}

} // namespace

void check_disc_hull_vertices(const Rational<BigInt>& r, std::uint64_t max_vertices) {
  const std::uint64_t bound = disc_hull_max_vertices(r); // refuses r < 0
  std::string expected;
  const double rd = r.to_double();
  if (std::isfinite(rd) && rd >= 1) {
    char buf[64];
    std::snprintf(buf, sizeof buf, " (about %.3g expected: 3.45 r^(2/3))",
                  3.45 * std::cbrt(rd * rd));
    expected = buf;
  }
  check_vertex_bound("disc", bound, max_vertices, expected);
}

void check_ellipse_hull_vertices(const Rational<BigInt>& a, const Rational<BigInt>& b,
                                 std::uint64_t max_vertices) {
  check_vertex_bound("ellipse", ellipse_hull_max_vertices(a, b), max_vertices, "");
}

#define ZDG_INSTANTIATE(I)                                                                         \
  template I floor_sqrt<I>(const I&);                                                              \
  template struct QuadraticBody<I>;                                                                \
  template struct PolygonBody<I>;                                                                  \
  template QuadraticBody<I> disc_body<I>(const Rational<I>&, const Rational<I>&,                   \
                                         const Rational<I>&);                                      \
  template QuadraticBody<I> ellipse_body<I>(const Rational<I>&, const Rational<I>&,                \
                                            const Rational<I>&, const Rational<I>&);               \
  template std::pair<RegionKind, PolygonBody<I>> polygon_body<I>(std::span<const HalfPlane<I>>);   \
  template std::vector<Point2<I>> convex_body_hull<I, QuadraticBody<I>>(const QuadraticBody<I>&);  \
  template std::size_t convex_body_hull_walk<I, QuadraticBody<I>>(                                 \
      const QuadraticBody<I>&, const std::function<void(const Point2<I>&)>&);                      \
  template std::size_t convex_body_hull_walk<I, PolygonBody<I>>(                                   \
      const PolygonBody<I>&, const std::function<void(const Point2<I>&)>&);                        \
  template std::vector<Point2<I>> convex_body_hull<I, PolygonBody<I>>(const PolygonBody<I>&);      \
  template std::vector<Point2<I>> disc_hull<I>(const Rational<I>&, const Rational<I>&,             \
                                               const Rational<I>&);                                \
  template std::vector<Point2<I>> ellipse_hull<I>(const Rational<I>&, const Rational<I>&,          \
                                                  const Rational<I>&, const Rational<I>&);         \
  template HalfPlaneHull<I> halfplane_hull<I>(std::span<const HalfPlane<I>>);
ZDG_INSTANTIATE(Int64)
ZDG_INSTANTIATE(Int128)
ZDG_INSTANTIATE(BigInt)
#undef ZDG_INSTANTIATE

} // namespace zdg
