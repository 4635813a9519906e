#include <zdg/kernel/curves/digital_circular_arc.hpp>

#include <zdg/arith/error.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <sstream>
#include <utility>

namespace zdg {

namespace {

// --- Seidel's feasibility recursion on rows r.w >= rho, w in Q^d, d <= 4 -------------------
//
// A row holds the d coefficients in [0, d) and the right-hand side in [4]. At depth k the rows
// are the fraction-free (Bareiss) reductions of the input rows onto the hyperplanes of the k
// constraints made tight on the way down: their entries are (k + 1) x (k + 1) minors of the
// input matrix [coefficients | rho] (up to one sign common to a level), so every division
// below is exact, and multiplying by the positive |pivot| keeps each inequality's direction.

template <class I>
using Row = std::array<I, 5>;

template <class I>
struct Point4 {
  std::array<I, 4> x; // numerators
  I den;              // > 0
};

// gcd on the tower; binary (std::gcd) on 64 bits, where Euclid's divisions dominated the
// profile of the cover.
template <class I>
I fast_gcd(const I& a, const I& b) {
  if constexpr (std::same_as<I, Int64>) {
    auto mag = [](std::int64_t v) {
      return v < 0 ? std::uint64_t(0) - static_cast<std::uint64_t>(v)
                   : static_cast<std::uint64_t>(v);
    };
    const std::uint64_t g = std::gcd(mag(a.value()), mag(b.value()));
    if (g > static_cast<std::uint64_t>(INT64_MAX)) return gcd(a, b); // throws OverflowError
    return Int64(static_cast<std::int64_t>(g));
  } else {
    return gcd(a, b);
  }
}

template <class I>
void reduce(Point4<I>& p, int d) {
  I g = p.den;
  for (int l = 0; l < d && g != 1; ++l) g = fast_gcd(g, p.x[static_cast<std::size_t>(l)]);
  if (g > 1) {
    for (int l = 0; l < d; ++l) p.x[static_cast<std::size_t>(l)] /= g;
    p.den /= g;
  }
}

template <class I>
class Seidel {
public:
  /// The depth-0 rows of the next solve, to be filled in place (their buffer is kept between
  /// solves).
  std::vector<Row<I>>& input() { return levels_[0]; }

  /// Feasibility of the rows of input() at depth 0 (dimension 4), used in their order.
  std::optional<Point4<I>> solve() {
    violated_.clear();
    Point4<I> out;
    if (!solve_level(0, levels_[0].size(), I(1), out)) return std::nullopt;
    return out;
  }

private:
  static I dot(const Row<I>& r, const Point4<I>& p, int d) {
    I s = 0;
    for (int l = 0; l < d; ++l)
      s += r[static_cast<std::size_t>(l)] * p.x[static_cast<std::size_t>(l)];
    return s;
  }

  // One variable: r x >= rho for every row; the least feasible x when bounded below, else the
  // largest, else 0.
  static bool solve_line(const std::vector<Row<I>>& rows, std::size_t m, Point4<I>& out) {
    bool has_lo = false, has_hi = false;
    I lo_n = 0, lo_d = 1, hi_n = 0, hi_d = 1; // bounds as fractions with positive denominators
    for (std::size_t j = 0; j < m; ++j) {
      const I& r = rows[j][0];
      const I& rho = rows[j][4];
      if (r == 0) {
        if (rho > 0) return false;
      } else if (r > 0) { // x >= rho / r
        if (!has_lo || rho * lo_d > lo_n * r) lo_n = rho, lo_d = r, has_lo = true;
      } else { // x <= rho / r = (-rho) / (-r)
        I n = -rho, dd = -r;
        if (!has_hi || n * hi_d < hi_n * dd) hi_n = n, hi_d = dd, has_hi = true;
      }
    }
    if (has_lo && has_hi && lo_n * hi_d > hi_n * lo_d) return false;
    if (has_lo) {
      out.x[0] = lo_n, out.den = lo_d;
    } else if (has_hi) {
      out.x[0] = hi_n, out.den = hi_d;
    } else {
      out.x[0] = 0, out.den = 1;
    }
    return true;
  }

public:
  /// The input rows (indices) that cut off the feasible point at depth 0 during the last solve:
  /// the constraints that shaped the answer (or, on failure, the last one is part of the
  /// obstruction). Listed first in a later solve, they make it cheap (move-to-front).
  const std::vector<std::size_t>& violated() const { return violated_; }

private:
  bool solve_level(int depth, std::size_t m, const I& dprev, Point4<I>& out) {
    const int d = 4 - depth;
    const auto& rows = levels_[static_cast<std::size_t>(depth)];
    if (d == 1) return solve_line(rows, m, out);
    Point4<I> x;
    for (auto& v : x.x) v = 0;
    x.den = 1;
    for (std::size_t i = 0; i < m; ++i) {
      const Row<I>& ri = rows[i];
      if (dot(ri, x, d) >= ri[4] * x.den) continue;
      if (depth == 0) violated_.push_back(i);
      // Pivot: the coefficient of largest magnitude.
      int piv = -1;
      for (int l = 0; l < d; ++l) {
        const I& c = ri[static_cast<std::size_t>(l)];
        if (c != 0 && (piv < 0 || abs(c) > abs(ri[static_cast<std::size_t>(piv)]))) piv = l;
      }
      if (piv < 0) return false; // 0 >= rho with rho > 0
      const I p = ri[static_cast<std::size_t>(piv)];
      const I ap = abs(p);
      const int sp = p > 0 ? 1 : -1;
      auto& next = levels_[static_cast<std::size_t>(depth + 1)];
      next.resize(std::max(next.size(), i));
      for (std::size_t j = 0; j < i; ++j) {
        const Row<I>& rj = rows[j];
        const I f =
            sp > 0 ? rj[static_cast<std::size_t>(piv)] : I(-rj[static_cast<std::size_t>(piv)]);
        Row<I>& nj = next[j];
        int t = 0;
        for (int l = 0; l < d; ++l) {
          if (l == piv) continue;
          const auto L = static_cast<std::size_t>(l);
          nj[static_cast<std::size_t>(t++)] = (ap * rj[L] - f * ri[L]) / dprev;
        }
        nj[4] = (ap * rj[4] - f * ri[4]) / dprev;
      }
      Point4<I> y;
      if (!solve_level(depth + 1, i, ap, y)) return false;
      // Lift: x_piv = (rho_i - sum_{l != piv} r_il y_l / e) / p.
      I s = ri[4] * y.den;
      int t = 0;
      for (int l = 0; l < d; ++l) {
        if (l == piv) continue;
        s -= ri[static_cast<std::size_t>(l)] * y.x[static_cast<std::size_t>(t++)];
      }
      // x_piv = s / (p y.den). When the pivot divides s (the usual case: y.den is then a common
      // denominator of x, e.g. the determinant of the tight rows by Cramer's rule), x = (y, s / p)
      // / y.den keeps y's denominator and needs no gcd; otherwise scale by |p| and reduce.
      const I q = s / ap;
      const bool divides = q * ap == s; // |q ap| <= |s|: no overflow
      t = 0;
      for (int l = 0; l < d; ++l) {
        if (l == piv) continue;
        const I& yl = y.x[static_cast<std::size_t>(t++)];
        x.x[static_cast<std::size_t>(l)] = divides ? yl : I(yl * ap);
      }
      const I& num = divides ? q : s;
      x.x[static_cast<std::size_t>(piv)] = sp > 0 ? num : I(-num);
      x.den = divides ? y.den : I(ap * y.den);
      if (!divides) reduce(x, d);
    }
    out = x;
    return true;
  }

  std::array<std::vector<Row<I>>, 4> levels_;
  std::vector<std::size_t> violated_;

public:
  std::vector<std::size_t> scratch_idx, scratch_pos; // separate()'s order, kept between solves
};

// A fixed pseudo-random permutation (xorshift), identical on every run and platform.
void shuffle_tail(std::vector<std::size_t>& idx, std::size_t from, std::uint64_t seed) {
  std::uint64_t s = seed * 0x9E3779B97F4A7C15ULL + 0x2545F4914F6CDD1DULL;
  for (std::size_t k = idx.size(); k > from + 1; --k) {
    s ^= s << 13, s ^= s >> 7, s ^= s << 17;
    std::size_t r = from + static_cast<std::size_t>(s % (k - from));
    std::swap(idx[k - 1], idx[r]);
  }
}

template <class I>
Row<I> lifted_row(const Pixel& p, const Pixel& origin, bool inner) {
  I x = I(p.x) - I(origin.x), y = I(p.y) - I(origin.y);
  I z = x * x + y * y;
  Row<I> r{z, x, y, I(1), I(1)};
  if (!inner) {
    for (int l = 0; l < 4; ++l) r[static_cast<std::size_t>(l)] = -r[static_cast<std::size_t>(l)];
  }
  return r;
}

// A circle in a local frame: w = (d, a, b, c) for d |p - o|^2 + a (p - o).x + b (p - o).y + c.
template <class I>
struct LocalCircle {
  std::array<I, 4> w;
  Pixel origin;

  I value(const Pixel& p) const {
    I x = I(p.x) - I(origin.x), y = I(p.y) - I(origin.y);
    return w[0] * (x * x + y * y) + w[1] * x + w[2] * y + w[3];
  }
  SeparatingCircle global() const {
    const BigInt d = to_bigint(w[0]), a = to_bigint(w[1]), b = to_bigint(w[2]), c = to_bigint(w[3]);
    const BigInt ox(origin.x), oy(origin.y);
    return {d, BigInt(a - 2 * d * ox), BigInt(b - 2 * d * oy),
            BigInt(c + d * (ox * ox + oy * oy) - a * ox - b * oy)};
  }
};

double circle_curvature(const BigInt& d, const BigInt& a, const BigInt& b, const BigInt& c) {
  if (d == 0) return 0.0;
  const BigInt disc = a * a + b * b - 4 * d * c; // (2 d r)^2 > 0 for a separating circle
  return -2.0 * d.convert_to<double>() / std::sqrt(disc.convert_to<double>());
}

// Separating circle of the inner and outer points, in the frame of `origin`. The rows are
// numbered inner 0 .. |inner| - 1, then outer; those listed in `first` go first (in that order,
// once each), the others follow in a fixed pseudo-random order. `violated` receives the row
// numbers that cut off the running solution (Seidel::violated).
template <class I>
std::optional<LocalCircle<I>> separate(Seidel<I>& lp, std::span<const Pixel> inner,
                                       std::span<const Pixel> outer, const Pixel& origin,
                                       std::span<const std::size_t> first,
                                       std::vector<std::size_t>* violated = nullptr) {
  const std::size_t m = inner.size() + outer.size();
  std::vector<std::size_t>& idx = lp.scratch_idx;
  std::vector<std::size_t>& pos = lp.scratch_pos;
  idx.resize(m);
  pos.resize(m);
  for (std::size_t k = 0; k < m; ++k) idx[k] = pos[k] = k;
  std::size_t head = 0;
  for (std::size_t k : first) {
    if (k >= m || pos[k] < head) continue;
    const std::size_t at = pos[k], other = idx[head];
    std::swap(idx[head], idx[at]);
    pos[other] = at;
    pos[k] = head++;
  }
  shuffle_tail(idx, head, m);
  std::vector<Row<I>>& rows = lp.input();
  rows.resize(m);
  for (std::size_t t = 0; t < m; ++t) {
    const std::size_t k = idx[t];
    rows[t] = k < inner.size() ? lifted_row<I>(inner[k], origin, true)
                               : lifted_row<I>(outer[k - inner.size()], origin, false);
  }
  auto sol = lp.solve();
  if (violated) {
    violated->clear();
    for (std::size_t r : lp.violated()) violated->push_back(idx[r]);
  }
  if (!sol) return std::nullopt;
  LocalCircle<I> c;
  c.w = sol->x;
  c.origin = origin;
  // Common factor of the four coefficients (the denominator is irrelevant: w is homogeneous).
  I g = 0;
  for (const auto& v : c.w) g = gcd(g, v);
  if (g > 1) {
    for (auto& v : c.w) v /= g;
  }
  return c;
}

void check_pairs(std::span<const Pixel> inner, std::span<const Pixel> outer) {
  if (inner.empty() || inner.size() != outer.size()) {
    throw InvalidArgument("maximal_circular_arcs: needs as many outer as inner points, at least "
                          "one (got " +
                          std::to_string(inner.size()) + " inner, " + std::to_string(outer.size()) +
                          " outer)");
  }
  for (std::size_t k = 0; k < inner.size(); ++k) {
    const Pixel& p = inner[k];
    const Pixel& q = outer[k];
    const bool adjacent = (p.x == q.x && (q.y - p.y == 1 || p.y - q.y == 1)) ||
                          (p.y == q.y && (q.x - p.x == 1 || p.x - q.x == 1));
    if (!adjacent) {
      std::ostringstream m;
      m << "maximal_circular_arcs: pair " << k << " (inner " << p << ", outer " << q
        << ") is not two 4-adjacent pixels";
      throw InvalidArgument(m.str());
    }
  }
}

// The two-pointer sweep; mirrors cover() of kernel/curves/maximal_segments.cpp.
template <class I>
class ArcWalker {
public:
  ArcWalker(std::span<const Pixel> inner, std::span<const Pixel> outer)
      : in_(inner), out_(outer), n_(static_cast<std::int64_t>(inner.size())) {
    resolve(0, 0, 0);
  }

  std::size_t index(std::int64_t k) const {
    std::int64_t m = k % n_;
    return static_cast<std::size_t>(m < 0 ? m + n_ : m);
  }

  // Adds pair k (= j + 1 or i - 1) to the run i .. j (unwrapped indices).
  bool extend(std::int64_t i, std::int64_t j, std::int64_t k) {
    const std::size_t kk = index(k);
    if (i <= j && witness_.value(in_[kk]) > 0 && witness_.value(out_[kk]) < 0) return true;
    return resolve(std::min(i, k), std::max(j, k), k);
  }

  MaximalArc arc(std::int64_t i, std::int64_t j) const {
    MaximalArc a;
    a.begin = index(i);
    a.end = index(j);
    a.length = static_cast<std::size_t>(j - i + 1);
    a.circle = witness_.global();
    a.curvature = a.circle.curvature();
    return a;
  }

  std::int64_t size() const { return n_; }

  // Solves on the run lo .. hi (unwrapped) with pair k first; keeps the witness when feasible.
  bool resolve(std::int64_t lo, std::int64_t hi, std::int64_t k) {
    const auto len = static_cast<std::size_t>(hi - lo + 1);
    buf_in_.resize(len);
    buf_out_.resize(len);
    for (std::size_t t = 0; t < len; ++t) {
      const std::size_t s = index(lo + static_cast<std::int64_t>(t));
      buf_in_[t] = in_[s];
      buf_out_[t] = out_[s];
    }
    // First the new pair, then the pairs whose constraints shaped the last solve.
    first_.clear();
    first_.push_back(static_cast<std::size_t>(k - lo));
    first_.push_back(len + static_cast<std::size_t>(k - lo));
    for (std::int64_t g : hint_) {
      if (g < lo || g > hi) continue;
      first_.push_back(static_cast<std::size_t>(g - lo));
      first_.push_back(len + static_cast<std::size_t>(g - lo));
    }
    std::optional<LocalCircle<I>> c;
    bool solved = false;
    if constexpr (!std::same_as<I, Int64>) {
      // A run of small extent is solved on Int64 (the same exact steps, so the same circle);
      // Int64's overflow check still guards it, and I takes over when it fires.
      if (small_extent(buf_in_[0])) {
        try {
          auto c64 = separate<Int64>(lp64_, buf_in_, buf_out_, buf_in_[0], first_, &violated_);
          if (c64) {
            LocalCircle<I> w;
            for (std::size_t l = 0; l < 4; ++l) w.w[l] = int_cast<I>(c64->w[l]);
            w.origin = c64->origin;
            c = w;
          }
          solved = true;
        } catch (const OverflowError&) {
        }
      }
    }
    if (!solved) c = separate<I>(lp_, buf_in_, buf_out_, buf_in_[0], first_, &violated_);
    hint_.clear();
    for (std::size_t r : violated_) hint_.push_back(lo + static_cast<std::int64_t>(r % len));
    if (!c) return false;
    witness_ = *c;
    return true;
  }

  std::span<const Pixel> in_, out_;
  std::int64_t n_;
  // True when the run's points lie within 2^9 of `origin` on both axes (Int64 then serves: see
  // the header's width note).
  bool small_extent(const Pixel& origin) const {
    constexpr std::int64_t kLimit = std::int64_t(1) << 9;
    auto near = [&](const Pixel& p) {
      const int128_t dx = static_cast<int128_t>(p.x) - origin.x;
      const int128_t dy = static_cast<int128_t>(p.y) - origin.y;
      return dx < kLimit && dx > -kLimit && dy < kLimit && dy > -kLimit;
    };
    return std::all_of(buf_in_.begin(), buf_in_.end(), near) &&
           std::all_of(buf_out_.begin(), buf_out_.end(), near);
  }

  LocalCircle<I> witness_;
  Seidel<I> lp_;
  Seidel<Int64> lp64_;
  std::vector<Pixel> buf_in_, buf_out_;
  std::vector<std::size_t> first_, violated_;
  std::vector<std::int64_t> hint_; // unwrapped pair indices (move-to-front)
};

template <class I>
std::vector<MaximalArc> cover(std::span<const Pixel> inner, std::span<const Pixel> outer,
                              bool closed) {
  ArcWalker<I> w(inner, outer);
  const std::int64_t n = w.size();
  std::vector<MaximalArc> arcs;
  std::int64_t i = 0, j = 0; // the witness separates pairs i .. j (unwrapped indices)
  auto full = [&] { return j - i + 1 >= n; };
  auto grow_front = [&] {
    while (!full() && (closed || j + 1 < n) && w.extend(i, j, j + 1)) ++j;
  };
  if (closed) {
    while (!full() && w.extend(i, j, i - 1)) --i;
  }
  grow_front();
  arcs.push_back(w.arc(i, j));
  const std::int64_t i0 = i;
  while (!full() && (closed || j + 1 < n)) {
    // Retract the back until pair j + 1 fits (alone it always does: two 4-adjacent pixels).
    // Sub-runs of a DCA are DCA, so the new back is found by bisection: O(log L) solves.
    if (!w.extend(i, j, j + 1)) {
      std::int64_t lo = i + 1, hi = j + 1; // the new back is in [lo, hi]
      bool witness_at_hi = false;
      while (lo < hi) {
        const std::int64_t mid = lo + (hi - lo) / 2;
        if (w.resolve(mid, j + 1, j + 1)) {
          hi = mid;
          witness_at_hi = true;
        } else {
          lo = mid + 1; // a failed solve leaves the witness (of the run from hi) as it was
        }
      }
      i = lo;
      if (!witness_at_hi) w.resolve(i, j + 1, j + 1);
    }
    ++j;
    grow_front();
    if (closed && i >= i0 + n) break; // back to the first arc
    arcs.push_back(w.arc(i, j));
  }
  return arcs;
}

} // namespace

double SeparatingCircle::curvature() const {
  return circle_curvature(d, a, b, c);
}

BigInt SeparatingCircle::value(const Pixel& p) const {
  const BigInt x(p.x), y(p.y);
  return BigInt(d * (x * x + y * y) + a * x + b * y + c);
}

bool SeparatingCircle::separates(std::span<const Pixel> inner, std::span<const Pixel> outer) const {
  for (const auto& p : inner) {
    if (value(p) <= 0) return false;
  }
  for (const auto& q : outer) {
    if (value(q) >= 0) return false;
  }
  return true;
}

template <TowerInt I>
std::optional<SeparatingCircle> is_digital_circular_arc(std::span<const Pixel> inner,
                                                        std::span<const Pixel> outer) {
  if (inner.empty() || outer.empty()) {
    throw InvalidArgument("is_digital_circular_arc: needs at least one inner and one outer point "
                          "(got " +
                          std::to_string(inner.size()) + " inner, " + std::to_string(outer.size()) +
                          " outer)");
  }
  Seidel<I> lp;
  auto c = separate<I>(lp, inner, outer, inner[0], {});
  if (!c) return std::nullopt;
  return c->global();
}

Escalated<std::optional<SeparatingCircle>>
is_digital_circular_arc_exact(std::span<const Pixel> inner, std::span<const Pixel> outer) {
  return escalate(
      [&]<class I>(std::type_identity<I>) { return is_digital_circular_arc<I>(inner, outer); });
}

template <TowerInt I>
std::vector<MaximalArc> maximal_circular_arcs(std::span<const Pixel> inner,
                                              std::span<const Pixel> outer, bool closed) {
  check_pairs(inner, outer);
  return cover<I>(inner, outer, closed);
}

Escalated<std::vector<MaximalArc>> maximal_circular_arcs_exact(std::span<const Pixel> inner,
                                                               std::span<const Pixel> outer,
                                                               bool closed) {
  check_pairs(inner, outer);
  return escalate([&]<class I>(std::type_identity<I>) { return cover<I>(inner, outer, closed); });
}

LinelPairs linel_pairs(const DigitalContour& contour) {
  LinelPairs out;
  out.inner.reserve(contour.size());
  out.outer.reserve(contour.size());
  Pixel p = contour.start;
  for (auto code : contour.codes) {
    out.inner.push_back(DigitalContour::inner_pixel(p, code));
    out.outer.push_back(DigitalContour::outer_pixel(p, code));
    const Pixel s = freeman_step(code);
    p = Pixel{p.x + s.x, p.y + s.y};
  }
  return out;
}

#define ZDG_INSTANTIATE(I)                                                                         \
  template std::optional<SeparatingCircle> is_digital_circular_arc<I>(std::span<const Pixel>,      \
                                                                      std::span<const Pixel>);     \
  template std::vector<MaximalArc> maximal_circular_arcs<I>(std::span<const Pixel>,                \
                                                            std::span<const Pixel>, bool);
ZDG_INSTANTIATE(Int64)
ZDG_INSTANTIATE(Int128)
ZDG_INSTANTIATE(BigInt)
#undef ZDG_INSTANTIATE

} // namespace zdg
