#include <zdg/kernel/hulls/lattice_polygon.hpp>

#include <zdg/arith/error.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

namespace zdg {

template <TowerInt I>
I polygon_area2(std::span<const Point2<I>> v) {
  I s = 0;
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i) {
    const auto& a = v[i];
    const auto& b = v[(i + 1) % n];
    s += a.x * b.y - b.x * a.y;
  }
  return s;
}

template <TowerInt I>
LatticePolygonMeasures<I> lattice_polygon_measures(std::span<const Point2<I>> v) {
  LatticePolygonMeasures<I> m;
  const std::size_t n = v.size();
  if (n == 0) return m;
  if (n == 1) {
    m.boundary = 1;
    return m;
  }
  if (n == 2) {
    m.boundary = gcd(I(v[1].x - v[0].x), I(v[1].y - v[0].y)) + 1;
    return m;
  }
  m.area2 = polygon_area2(v);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& a = v[i];
    const auto& b = v[(i + 1) % n];
    m.boundary += gcd(I(b.x - a.x), I(b.y - a.y));
  }
  m.interior = (m.area2 - m.boundary + 2) / 2;
  return m;
}

Escalated<LatticePolygonMeasures<BigInt>>
lattice_polygon_measures_exact(std::span<const Point2<BigInt>> v) {
  return escalate([&]<class I>(std::type_identity<I>) {
    std::vector<Point2<I>> w;
    w.reserve(v.size());
    for (const auto& p : v) w.push_back({int_cast<I>(p.x), int_cast<I>(p.y)});
    auto m = lattice_polygon_measures<I>(std::span<const Point2<I>>(w));
    return LatticePolygonMeasures<BigInt>{to_bigint(m.area2), to_bigint(m.boundary),
                                          to_bigint(m.interior)};
  });
}

namespace {

// w(u) = max <u, p> - min <u, p>: a norm on R^2 when the polygon is full-dimensional.
template <TowerInt I>
I width_along(std::span<const Point2<I>> v, const Point2<I>& u) {
  I lo = u.x * v[0].x + u.y * v[0].y, hi = lo;
  for (const auto& p : v) {
    I s = u.x * p.x + u.y * p.y;
    if (s < lo) lo = s;
    if (s > hi) hi = s;
  }
  return hi - lo;
}

// The integer mu minimizing the convex function f(mu) = w(b - mu a).
template <TowerInt I>
I best_multiple(std::span<const Point2<I>> v, const Point2<I>& a, const Point2<I>& b) {
  auto f = [&](const I& mu) { return width_along(v, Point2<I>{b.x - mu * a.x, b.y - mu * a.y}); };
  I f0 = f(I(0));
  int dir = 0;
  if (f(I(1)) < f0) {
    dir = 1;
  } else if (f(I(-1)) < f0) {
    dir = -1;
  } else {
    return I(0);
  }
  // Gallop to a point where f stops decreasing, then bisect on the sign of f(m+1) - f(m).
  I lo = 0, step = 1, hi;
  for (;;) {
    I cand = lo + step * dir;
    if (f(cand + dir) < f(cand)) {
      lo = cand;
      step = step * 2;
    } else {
      hi = cand;
      break;
    }
  }
  // f decreases from lo to some point <= hi (in direction dir); find the last decreasing step.
  I a0 = lo, b0 = hi; // invariant: f(a0 + dir) < f(a0), and f(b0 + dir) >= f(b0)
  while (abs(I(b0 - a0)) > 1) {
    I mid = a0 + (b0 - a0) / 2;
    if (f(mid + dir) < f(mid)) {
      a0 = mid;
    } else {
      b0 = mid;
    }
  }
  return b0;
}

} // namespace

template <TowerInt I>
LatticeWidth<I> lattice_width(std::span<const Point2<I>> v) {
  if (v.empty()) throw InvalidArgument("lattice width of an empty set");
  LatticeWidth<I> r;
  if (v.size() <= 2) { // a point or a segment: width 0 along a normal of the segment
    if (v.size() == 2) {
      I dx = v[1].x - v[0].x, dy = v[1].y - v[0].y;
      I g = gcd(dx, dy);
      r.direction = {I(-dy / g), I(dx / g)};
    }
    return r;
  }
  Point2<I> a{I(1), I(0)}, b{I(0), I(1)};
  I wa = width_along(v, a), wb = width_along(v, b);
  if (wb < wa) {
    std::swap(a, b);
    std::swap(wa, wb);
  }
  // Generalized Gauss reduction: w(a) <= w(b); reduce b by the best multiple of a; swap
  // while that gets shorter than a. Ends with a a shortest nonzero vector for w.
  for (;;) {
    I mu = best_multiple(v, a, b);
    b = {b.x - mu * a.x, b.y - mu * a.y};
    wb = width_along(v, b);
    if (wb >= wa) break;
    std::swap(a, b);
    std::swap(wa, wb);
  }
  r.width = wa;
  r.direction = a;
  return r;
}

// --- incremental measures ----------------------------------------------------------------

namespace {
// Stein's binary gcd: shifts and subtractions, no division (the meter's hot path).
std::uint64_t binary_gcd(std::uint64_t a, std::uint64_t b) {
  if (a == 0) return b;
  if (b == 0) return a;
  const int shift = __builtin_ctzll(a | b);
  a >>= __builtin_ctzll(a);
  do {
    b >>= __builtin_ctzll(b);
    if (a > b) std::swap(a, b);
    b -= a;
  } while (b != 0);
  return a << shift;
}
} // namespace

void LatticePolygonMeter::big_edge(const BigInt& ax, const BigInt& ay, const BigInt& bx,
                                   const BigInt& by, BigInt& area, BigInt& boundary) const {
  area += ax * by - bx * ay;
  boundary += gcd(BigInt(bx - ax), BigInt(by - ay));
}

void LatticePolygonMeter::to_big() {
  big_ = true;
  bx0_ = x0_;
  by0_ = y0_;
  bx_ = x_;
  by_ = y_;
}

void LatticePolygonMeter::edge_to(std::int64_t x, std::int64_t y) {
  // The shoelace term on 128 bits: each product fits, their difference may not (only when
  // coordinates are near +-2^63).
  const int128_t p = static_cast<int128_t>(x_) * y, q = static_cast<int128_t>(x) * y_;
  int128_t term;
  if (__builtin_sub_overflow(p, q, &term)) {
    big_area_ += BigInt(x_) * BigInt(y) - BigInt(x) * BigInt(y_);
  } else if (int128_t sum; __builtin_add_overflow(area_, term, &sum)) {
    big_area_ += to_bigint(Int128(area_)) + to_bigint(Int128(term));
    area_ = 0;
  } else {
    area_ = sum;
  }
  // |dx|, |dy| <= 2^64 - 1: a gcd on 64 bits.
  const int128_t dx = static_cast<int128_t>(x) - x_, dy = static_cast<int128_t>(y) - y_;
  std::uint64_t a = static_cast<std::uint64_t>(dx < 0 ? -dx : dx);
  std::uint64_t b = static_cast<std::uint64_t>(dy < 0 ? -dy : dy);
  const std::uint64_t g = binary_gcd(a, b);
  boundary_ += g;
  if (n_ == 1) first_edge_gcd_ = BigInt(g);
  x_ = x;
  y_ = y;
}

void LatticePolygonMeter::add(std::int64_t x, std::int64_t y) {
  if (big_) {
    add(BigInt(x), BigInt(y));
    return;
  }
  if (n_ == 0) {
    x0_ = x_ = x;
    y0_ = y_ = y;
  } else {
    edge_to(x, y);
  }
  ++n_;
}

void LatticePolygonMeter::add(const BigInt& x, const BigInt& y) {
  if (!big_) to_big();
  if (n_ == 0) {
    bx0_ = bx_ = x;
    by0_ = by_ = y;
  } else {
    BigInt b;
    big_edge(bx_, by_, x, y, big_area_, b);
    if (n_ == 1) first_edge_gcd_ = b;
    big_boundary_ += b;
    bx_ = x;
    by_ = y;
  }
  ++n_;
}

LatticePolygonMeasures<BigInt> LatticePolygonMeter::finish() const {
  LatticePolygonMeasures<BigInt> m;
  if (n_ == 0) return m;
  if (n_ == 1) {
    m.boundary = 1;
    return m;
  }
  if (n_ == 2) {
    m.boundary = first_edge_gcd_ + 1;
    return m;
  }
  BigInt area = big_area_ + to_bigint(Int128(area_));
  BigInt boundary = big_boundary_ + to_bigint(Int128(boundary_));
  if (big_) {
    big_edge(bx_, by_, bx0_, by0_, area, boundary);
  } else {
    big_edge(BigInt(x_), BigInt(y_), BigInt(x0_), BigInt(y0_), area, boundary);
  }
  m.area2 = area;
  m.boundary = boundary;
  m.interior = (area - boundary + 2) / 2;
  return m;
}

// --- vertex bound ---------------------------------------------------------------------------

std::uint64_t convex_lattice_polygon_max_vertices(double perimeter) {
  if (!(perimeter >= 0)) return 1; // NaN or negative: a point at most
  // L(V) from the header, in long double; 1e-9 of slack covers its rounding (L is increasing).
  auto L = [](long double V) {
    const long double pi = 3.141592653589793238462643383279502884L;
    const long double integral =
        2.0L / (3.0L * std::sqrt(pi)) * (std::pow(V + 1, 1.5L) - 1) - V * std::sqrt(0.5L);
    return std::max(V, integral) * (1 - 1e-9L);
  };
  const std::uint64_t cap = std::uint64_t{1} << 62;
  if (L(static_cast<long double>(cap)) <= perimeter) return UINT64_MAX;
  std::uint64_t lo = 1, hi = cap; // L(hi) > perimeter; the answer is in [lo, hi)
  while (hi - lo > 1) {
    const std::uint64_t mid = lo + (hi - lo) / 2;
    if (L(static_cast<long double>(mid)) <= perimeter) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return lo;
}

#define ZDG_INSTANTIATE(I)                                                                         \
  template I polygon_area2<I>(std::span<const Point2<I>>);                                         \
  template LatticePolygonMeasures<I> lattice_polygon_measures<I>(std::span<const Point2<I>>);      \
  template LatticeWidth<I> lattice_width<I>(std::span<const Point2<I>>);
ZDG_INSTANTIATE(Int64)
ZDG_INSTANTIATE(Int128)
ZDG_INSTANTIATE(BigInt)
#undef ZDG_INSTANTIATE

} // namespace zdg
