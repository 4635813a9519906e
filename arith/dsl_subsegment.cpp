#include <zdg/arith/dsl_subsegment.hpp>

#include <zdg/arith/floor_sum.hpp>
#include <zdg/arith/stern_brocot.hpp>

#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

namespace zdg {

namespace {

// The subsegment in local coordinates: X = x - x0, Y = y - k0, points (X, floor((a X + c)/b))
// for 0 <= X < n, with 0 <= c < b (so the first point is (0, 0)).
template <TowerInt I>
struct Local {
  I a, b, c, n, x0, k0;
  std::vector<I> samples; // X = 0, n - 1 and the first / last leaning points of the line in S

  void set_samples() {
    samples = {I(0), I(n - 1)};
    if (a == 0) return;
    I inv = mod(ext_gcd(a, b).x, b);
    for (const I& r : {I(0), I(b - 1)}) { // upper (R = 0) and lower (R = b - 1) leaning points
      I first = mod(I(mod(I(r - c), b) * inv), b);
      if (first >= n) continue;
      samples.push_back(first);
      samples.push_back(first + (n - 1 - first) / b * b);
    }
  }

  // min over S of g(X) = p X - q Y(X) when S fits a naive line of slope p/q, else nullopt.
  std::optional<I> fit(const I& p, const I& q) const {
    // below(m): some X has g(X) < m; monotone in m. g(0) = 0, so min g is in (-q, 0] when the
    // thickness max g - min g is < q.
    // Necessary condition from a few points (the ends of S and the leaning points of the line,
    // where g is often extreme): max - min < q. Then min g lies in [max - q + 1, min]; search
    // the largest m there with !below(m).
    I gmin = 0, gmax = 0;
    for (const I& x : samples) {
      I g = p * x - q * floor_div(I(a * x + c), b);
      if (g < gmin) gmin = g;
      if (g > gmax) gmax = g;
    }
    I lo = gmax - (q - 1), hi = gmin;
    if (lo > hi) return std::nullopt;
    // Often the minimum is at a sample: then !below(gmin) proves min g = gmin at once.
    if (!below(p, q, hi)) {
      if (above(p, q, hi)) return std::nullopt;
      return hi;
    }
    --hi; // below(gmin) holds, so min g < gmin
    if (lo > hi || below(p, q, lo)) return std::nullopt;
    while (lo < hi) {
      I mid = hi - (hi - lo) / 2;
      if (below(p, q, mid)) {
        hi = mid - 1;
      } else {
        lo = mid;
      }
    }
    if (above(p, q, lo)) return std::nullopt;
    return lo;
  }

  // Sum over X in [s, e] of floor((p X - m)/q) - floor((a X + c)/b).
  I diff_sum(const I& p, const I& q, const I& m, const I& s, const I& e) const {
    I cnt = e - s + 1;
    return floor_sum(cnt, q, p, I(p * s - m)) - floor_sum(cnt, b, a, I(a * s + c));
  }
  // The X range where Delta X <= K (side = -1) or Delta X >= K (side = +1), within [0, n).
  std::pair<I, I> side_range(const I& p, const I& q, const I& m, int side) const {
    I delta = p * b - q * a, k = b * m + q * c;
    I s = 0, e = n - 1;
    if (delta == 0) {
      bool all = side < 0 ? k >= 0 : k <= 0;
      return all ? std::pair<I, I>{s, e} : std::pair<I, I>{I(1), I(0)};
    }
    bool upper_bound = (side < 0) == (delta > 0); // the side is X <= t, else X >= t
    if (upper_bound) {
      I t = floor_div(k, delta);
      if (t < e) e = t;
    } else {
      I t = ceil_div(k, delta);
      if (t > s) s = t;
    }
    return {s, e};
  }
  bool below(const I& p, const I& q, const I& m) const {
    auto [s, e] = side_range(p, q, m, -1);
    return s <= e && diff_sum(p, q, m, s, e) < 0;
  }
  bool above(const I& p, const I& q, const I& m) const {
    auto [s, e] = side_range(p, q, m, +1);
    return s <= e && diff_sum(p, q, m, s, e) > 0;
  }

  DslSubsegment<I> answer(const I& p, const I& q, const I& m) const {
    // p x - q y = p X - q Y + p x0 - q k0
    return {p, q, I(m + p * x0 - q * k0)};
  }
};

template <TowerInt I>
struct Prepared {
  Local<I> loc;
  std::optional<DslSubsegment<I>> done; // answered without search
};

template <TowerInt I>
Prepared<I> prepare(I a, I b, I mu, const I& x0, const I& x1) {
  if (b <= 0) throw InvalidArgument("DSL subsegment: b = " + to_string(b) + " must be > 0");
  if (a < 0 || a >= b) {
    throw InvalidArgument("DSL subsegment: a = " + to_string(a) +
                          " must satisfy 0 <= a < b = " + to_string(b));
  }
  if (x1 < x0) {
    throw InvalidArgument("DSL subsegment: x1 = " + to_string(x1) + " < x0 = " + to_string(x0));
  }
  I g = gcd(a, b);
  if (g != 1) { // mu <= g t < mu + b  <=>  ceil(mu/g) <= t < ceil(mu/g) + b/g
    a /= g;
    b /= g;
    mu = ceil_div(mu, g);
  }
  Prepared<I> pr;
  I c = a * x0 - mu;
  I k0 = floor_div(c, b);
  pr.loc = Local<I>{a, b, I(c - k0 * b), I(x1 - x0 + 1), x0, k0, {}};
  if (x1 == x0) {
    pr.done = DslSubsegment<I>{0, 1, I(-k0)};
  } else if (pr.loc.n > 2 * b) {
    // Two full periods: the line itself; mu is the line's.
    pr.done = DslSubsegment<I>{a, b, mu};
  } else if (a == 0) {
    pr.done = DslSubsegment<I>{0, 1, mu};
  } else {
    pr.loc.set_samples();
  }
  return pr;
}

template <TowerInt I>
struct PathRun {
  char dir;
  I k;
  Fraction<I> base, bound; // N_j = base + j * bound for j = 0..k
  Fraction<I> node(const I& j) const { return {base.p + j * bound.p, base.q + j * bound.q}; }
};

// The runs of the Stern-Brocot path of a/b from 1/1 (0 < a < b).
template <TowerInt I>
std::vector<PathRun<I>> path_runs(const I& a, const I& b) {
  std::vector<PathRun<I>> out;
  Fraction<I> lb{0, 1}, rb{1, 0}, n{1, 1};
  for (const auto& [dir, k] : stern_brocot_path_runs(a, b)) {
    PathRun<I> r{dir, k, n, dir == 'L' ? lb : rb};
    Fraction<I> end = r.node(k), before = r.node(k - 1);
    if (dir == 'L') {
      rb = before;
    } else {
      lb = before;
    }
    n = end;
    out.push_back(r);
  }
  return out;
}

// The answer at the first node of `run` in [lo, hi] that fits, given that node hi fits and
// that feasibility is monotone on [lo, hi] (the nodes approach a/b from one side): binary
// search, O(log k) fit tests.
template <TowerInt I, class Local>
DslSubsegment<I> first_fitting_node(const Local& L, const PathRun<I>& run, I lo, I hi) {
  while (lo < hi) {
    I mid = lo + (hi - lo) / 2;
    auto g = run.node(mid);
    if (L.fit(g.p, g.q)) {
      hi = mid;
    } else {
      lo = mid + 1;
    }
  }
  auto best = run.node(lo);
  return L.answer(best.p, best.q, *L.fit(best.p, best.q));
}

} // namespace

template <TowerInt I>
DslSubsegment<I> subsegment_top_down_search(const I& a, const I& b, const I& mu, const I& x0,
                                            const I& x1) {
  auto pr = prepare(a, b, mu, x0, x1);
  if (pr.done) return *pr.done;
  const auto& L = pr.loc;
  if (auto m = L.fit(I(0), I(1))) return L.answer(I(0), I(1), *m);
  if (auto m = L.fit(I(1), I(1))) return L.answer(I(1), I(1), *m);
  // Nodes N_0 .. N_{k-1} of a run lie on one side of a/b and approach it (N_k starts the
  // next run, on the other side): feasibility is monotone on them.
  for (const auto& run : path_runs(L.a, L.b)) {
    auto f = run.node(run.k - 1);
    if (L.fit(f.p, f.q)) return first_fitting_node(L, run, I(0), I(run.k - 1));
  }
  if (auto m = L.fit(L.a, L.b)) return L.answer(L.a, L.b, *m);
  throw Error("DSL subsegment: no feasible slope on the path (internal error)");
}

template <TowerInt I>
DslSubsegment<I> subsegment_bottom_up(const I& a, const I& b, const I& mu, const I& x0,
                                      const I& x1) {
  auto pr = prepare(a, b, mu, x0, x1);
  if (pr.done) return *pr.done;
  const auto& L = pr.loc;
  auto runs = path_runs(L.a, L.b);
  auto root_answer = [&]() {
    if (auto m = L.fit(I(0), I(1))) return L.answer(I(0), I(1), *m);
    return L.answer(I(1), I(1), *L.fit(I(1), I(1)));
  };
  // Position (r, j): node j of run r; (r, 0) is the last node of run r - 1, (0, 0) is 1/1.
  std::size_t r = runs.size();
  I j = 0;
  if (r == 0) return root_answer(); // a/b = 1/1 cannot happen (a < b); kept for safety
  --r;
  j = runs[r].k;
  while (true) {
    if (j == 0) {
      if (r == 0) return root_answer();
      --r;
      j = runs[r].k;
      continue;
    }
    const auto& run = runs[r];
    // The other parent of every node N_j (j >= 1) of this run is its bound.
    const auto& bound = run.bound;
    if (bound.q != 0 && L.fit(bound.p, bound.q)) {
      if (r == 0) return L.answer(bound.p, bound.q, *L.fit(bound.p, bound.q)); // 0/1
      // The bound is node k - 1 of the previous run (runs alternate directions).
      --r;
      j = runs[r].k - 1;
      continue;
    }
    // Climb the run: N_0 .. N_{k-1} approach a/b from one side, so feasibility is monotone on
    // them; with the current node N_j (feasible) the predicate stays monotone on [1, j].
    auto n0 = run.node(I(0));
    if (L.fit(n0.p, n0.q)) {
      j = 0;
      continue;
    }
    return first_fitting_node(L, run, I(1), j); // node j is feasible
  }
}

namespace {

// Smallest u + i q >= x, largest u + i q <= x (q > 0).
template <TowerInt I>
I lattice_ceil(const I& u, const I& q, const I& x) {
  return u + ceil_div(I(x - u), q) * q;
}
template <TowerInt I>
I lattice_floor(const I& u, const I& q, const I& x) {
  return u + floor_div(I(x - u), q) * q;
}

} // namespace

// The reversed climb. Window X in [0, last]; the current line has slope t = P/Q and upper
// leaning points u + k Q (remainder R = 0); parents l = p_l/q_l < t < r = p_r/q_r, with
// P q_l - Q p_l = 1 = Q p_r - P q_r and q_l + q_r = Q.
// Lemma. For X = U + k: P k / Q = p_l k / q_l + k / (Q q_l); writing p_l k = m q_l + rho, the
// floors agree iff 0 <= rho Q + k < Q q_l, i.e. for -q_l < k < Q (rho >= 1 when q_l does not
// divide k; rho = 0 at k = -q_l). Mirrored: the r-line through U agrees for -Q < k < q_r.
// Conversely, a lower leaning point L (R = Q - 1) and the upper one L + q_l in S give
// g_l = (q_l R - X) / Q two values q_l (Q - 1) + q_l apart over Q, a thickness >= q_l: no
// line of slope l holds both. So l fits iff [0, last] lies in one agreement window: the one of
// the last U <= q_l - 1 is the widest to the right. Likewise r with the first U >= last-q_r+1.
// Runs. With t = N_j = N_0 + j beta (direction L: beta = l, N_{j-1} = r; direction R mirrored)
// and beta not fitting, every N_j-line containing S has a lower leaning point v - q_beta and
// the upper one v in S; v is the only upper leaning point that can anchor the r-parent test,
// and v stays the smallest upper leaning point >= q_beta of the new line, so by induction
// N_{i-1} fits iff Q_{i-1} >= last - v + 1 and Q_i >= v + 1 (direction R: Q_{i-1} >= v + 1 and
// Q_i >= last - v + 1). Q_i = q(N_0) + i q_beta: the first fitting node is a ceiling division.
// If it is N_0, the climb goes on from N_0 with anchor v; otherwise that node is the answer
// (neither parent fits), with v an upper leaning point in S, which gives mu.
template <TowerInt I>
DslSubsegment<I> subsegment_reversed_smart_dss(const I& a, const I& b, const I& mu, const I& x0,
                                               const I& x1) {
  auto pr = prepare(a, b, mu, x0, x1);
  if (pr.done) return *pr.done;
  const auto& L = pr.loc;
  const I last = L.n - 1; // the window is X in [0, last]
  auto runs = path_runs(L.a, L.b);
  // The characteristics at slope f with upper leaning point v (in the window).
  auto answer_at = [&](const Fraction<I>& f, const I& v) {
    return L.answer(f.p, f.q, I(f.p * v - f.q * floor_div(I(L.a * v + L.c), L.b)));
  };
  // u: an upper leaning point of the current line (slope t, containing the window).
  I u = mod(I(mod(I(-L.c), L.b) * mod(ext_gcd(L.a, L.b).x, L.b)), L.b);
  std::size_t r = runs.size() - 1;
  I j = runs[r].k;
  while (true) {
    if (j == 0) {
      if (r == 0) { // t = 1/1: its parents are 0/1 and 1/0 (infeasible: two abscissae)
        if (floor_div(I(L.a * last + L.c), L.b) == 0) return answer_at({I(0), I(1)}, I(0));
        return answer_at({I(1), I(1)}, I(0));
      }
      --r;
      j = runs[r].k;
      continue;
    }
    const auto& run = runs[r];
    const Fraction<I> t = run.node(j);
    const Fraction<I>& beta = run.bound;
    // 1. The bound beta, a parent of t: feasible iff the window lies in the part of the
    //    t-line that coincides with a beta-line through an upper leaning point U of t.
    I up = run.dir == 'L' ? lattice_floor(u, t.q, I(beta.q - 1))
                          : lattice_ceil(u, t.q, I(last - beta.q + 1));
    bool beta_fits = run.dir == 'L' ? last <= up + t.q - 1 : up <= t.q - 1;
    if (beta_fits) {
      if (r == 0) return answer_at({I(0), I(1)}, I(0)); // beta = 0/1
      u = up;
      --r;
      j = runs[r].k - 1; // the bound of run r is node k - 1 of run r - 1
      continue;
    }
    // 2. beta does not fit: the window holds the upper leaning point v of every line of slope
    //    N_i (i <= j) containing it, and N_{i-1} fits iff Q_{i-1}, Q_i clear v's distances.
    I v, need;
    if (run.dir == 'L') {
      v = lattice_ceil(u, t.q, beta.q);
      need = std::max(I(last - v + 1), I(v + 1 - beta.q));
    } else {
      v = lattice_ceil(u, t.q, I(0));
      need = std::max(I(v + 1), I(last - v + 1 - beta.q));
    }
    I first = need <= run.base.q ? I(0) : ceil_div(I(need - run.base.q), beta.q);
    if (first > j) first = j; // t itself is feasible
    if (first >= 1) return answer_at(run.node(first), v);
    u = v;
    j = 0; // N_0 fits: go on from the end of the previous run
  }
}

// SmartDSS: the minimal characteristics of the prefixes [0, X] of the window, read from its
// first point (Debled-Rennesson and Reveilles' update), jumping from one exit of the current
// line to the next (O(1) divisions) and over a run of Stern-Brocot steps in one division.
// State: slope s = p/q with parents lp < s < rp (q rp.p - p rp.q = 1, so p^-1 = -rp.q mod q),
// the prefix [0, X] fits mu_s <= p x - q y < mu_s + q tightly (m = mu_s, local). The first
// point of the t-line (t = a/b) after X off this s-line is, by DR's theorem, weakly exterior,
// and above the s-line when s < t (else s would still fit the longer prefix), below when
// s > t. Above: relative to the first upper leaning point U (t-remainder R) of the prefix,
// x = U + k is above iff p k = -1 (mod q) and k (q a - p b) >= b - q R; below: relative to the
// first lower leaning point L, p k = 1 (mod q) and k (q a - p b) < b (q - 1) - q R. DR's
// update: the new slope is (k, y(U + k) - y(U)) (resp. from L): a Stern-Brocot descendant of s
// with parents s and the new slope minus s; U (resp. L) stays the first leaning point. Run
// jump: from such a state (X = U + q) the next update gives s + rp again iff the point at
// U + q + q_rp is above, i.e. R + delta(s + rp) >= 0 with delta(f) = f.q a - f.p b, linear
// along s + i rp: the number of consecutive such steps (while s < t and the window lasts) is
// one division (mirrored below with lp, L and b - 1 - R). Every other update turns in the
// Stern-Brocot tree, so there are O(number of partial quotients of a/b) iterations.
template <TowerInt I>
DslSubsegment<I> subsegment_smart_dss(const I& a, const I& b, const I& mu, const I& x0,
                                      const I& x1) {
  auto pr = prepare(a, b, mu, x0, x1);
  if (pr.done) return *pr.done;
  const auto& L = pr.loc;
  const I last = L.n - 1; // the window is X in [0, last]
  auto y = [&](const I& x) { return floor_div(I(L.a * x + L.c), L.b); };
  auto delta = [&](const Fraction<I>& f) { return I(f.q * L.a - f.p * L.b); }; // sign of t - f
  Fraction<I> s{0, 1}, lp{-1, 1}, rp{1, 0}; // the prefix [0, 0]: one point, slope 0/1
  I m = 0, X = 0;
  while (true) {
    const I d = delta(s);
    if (d == 0) break; // s = t: no point of the window leaves the line
    const bool above = d > 0;
    const I pinv = mod(I(-rp.q), s.q);
    // The first upper (above) or lower leaning point x >= 0 of the prefix: p x = m (resp.
    // m - 1) mod q; its t-remainder R.
    const I anchor = mod(I(mod(above ? m : I(m - 1), s.q) * pinv), s.q);
    const I r = mod(I(L.a * anchor + L.c), L.b);
    I k;
    if (above) {
      I kmin = std::max(I(X - anchor + 1), ceil_div(I(L.b - s.q * r), d));
      k = kmin + mod(I(-pinv - kmin), s.q);
    } else {
      I kmin = std::max(I(X - anchor + 1), I(floor_div(I(s.q * r - L.b * (s.q - 1)), I(-d)) + 1));
      k = kmin + mod(I(pinv - kmin), s.q);
    }
    if (anchor + k > last) break; // the whole window fits the s-line
    const Fraction<I> next{I(y(anchor + k) - y(anchor)), k};
    const Fraction<I> diff{next.p - s.p, next.q - s.q};
    if (above) {
      lp = s;
      rp = diff;
    } else {
      rp = s;
      lp = diff;
    }
    s = next;
    // Run jump: n further steps s -> s + beta (beta = rp above, lp below).
    const Fraction<I>& beta = above ? rp : lp;
    const I ds = delta(s), db = delta(beta);
    if ((above ? ds > 0 : ds < 0) && beta.q > 0) {
      I n = above ? std::min(ceil_div(ds, I(-db)), floor_div(I(r + ds), I(-db)))
                  : std::min(ceil_div(I(-ds), db), floor_div(I(L.b - 1 - r - ds), db));
      n = std::min(n, floor_div(I(last - anchor - s.q), beta.q));
      if (n > 0) {
        Fraction<I> before{s.p + (n - 1) * beta.p, s.q + (n - 1) * beta.q};
        s = {s.p + n * beta.p, s.q + n * beta.q};
        (above ? lp : rp) = before;
      }
    }
    // Tight remainder: the anchor is an upper (resp. lower) leaning point of the new line.
    m = s.p * anchor - s.q * y(anchor);
    if (!above) m = m - s.q + 1;
    X = anchor + s.q;
  }
  return L.answer(s.p, s.q, m);
}

Escalated<DslSubsegment<BigInt>> dsl_subsegment_exact(const BigInt& a, const BigInt& b,
                                                      const BigInt& mu, const BigInt& x0,
                                                      const BigInt& x1,
                                                      DslSubsegmentAlgorithm algorithm) {
  return escalate([&]<class I>(std::type_identity<I>) {
    auto run = algorithm == DslSubsegmentAlgorithm::smart_dss ? &subsegment_smart_dss<I>
                                                              : &subsegment_reversed_smart_dss<I>;
    auto r = run(int_cast<I>(a), int_cast<I>(b), int_cast<I>(mu), int_cast<I>(x0), int_cast<I>(x1));
    return DslSubsegment<BigInt>{to_bigint(r.a), to_bigint(r.b), to_bigint(r.mu)};
  });
}

#define ZDG_INSTANTIATE(I)                                                                         \
  template DslSubsegment<I> subsegment_top_down_search<I>(const I&, const I&, const I&, const I&,  \
                                                          const I&);                               \
  template DslSubsegment<I> subsegment_bottom_up<I>(const I&, const I&, const I&, const I&,        \
                                                    const I&);                                     \
  template DslSubsegment<I> subsegment_reversed_smart_dss<I>(const I&, const I&, const I&,         \
                                                             const I&, const I&);                  \
  template DslSubsegment<I> subsegment_smart_dss<I>(const I&, const I&, const I&, const I&,        \
                                                    const I&);
ZDG_INSTANTIATE(Int64)
ZDG_INSTANTIATE(Int128)
ZDG_INSTANTIATE(BigInt)
#undef ZDG_INSTANTIATE

} // namespace zdg
