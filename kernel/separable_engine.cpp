#include <zdg/kernel/separable_engine.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace zdg::detail {

namespace {

enum Kind { kL1, kL2, kLinf, kLp };

template <class V>
V small(std::int64_t t) {
  return V(t);
}

// floor(a / b) for b > 0.
template <class V>
V floor_div_pos(const V& a, const V& b) {
  V q = a / b;
  if (a < 0 && q * b != a) q -= 1;
  return q;
}

template <class V>
double to_double(const V& v) {
  if constexpr (std::is_same_v<V, BigInt>) {
    return v.template convert_to<double>();
  } else {
    return static_cast<double>(v);
  }
}

template <int K, class V>
struct LineMetric {
  const V* pw = nullptr; // t -> t^p for kLp
  int p = 2;
  double inv_pow2 = 1; // 2^-(p-2)

  V eval(const V& f, std::int64_t dx) const {
    if constexpr (K == kL2) {
      V d = small<V>(dx); // the square needs no absolute value
      return f + d * d;
    }
    if (dx < 0) dx = -dx;
    if constexpr (K == kL1) {
      return f + small<V>(dx);
    } else if constexpr (K == kLinf) {
      V d = small<V>(dx);
      return f < d ? d : f;
    } else {
      return f + pw[dx];
    }
  }

  // The last t in [lo, hi) where g_i(t) <= g_u(t) (i < u, and g_i(lo) <= g_u(lo)); hi - 1
  // when u never wins strictly in [lo, hi).
  std::int64_t sep(std::int64_t i, const V& fi, std::int64_t u, const V& fu, std::int64_t lo,
                   std::int64_t hi) const {
    V r;
    if constexpr (K == kL2) {
      V num = small<V>(u - i) * small<V>(u + i) + (fu - fi);
      r = floor_div_pos(num, small<V>(2 * (u - i)));
    } else if constexpr (K == kL1) {
      if (fu - fi >= small<V>(u - i)) return hi - 1;
      r = floor_div_pos(V(fu - fi + small<V>(u + i)), V(2));
    } else if constexpr (K == kLinf) {
      V mid = small<V>((i + u) / 2);
      if (fi <= fu) {
        V a = small<V>(i) + fu;
        r = a < mid ? mid : a;
      } else {
        V a = small<V>(u) - fi;
        r = a < mid ? a : mid;
      }
    } else {
      // Exact search for the last t where i wins, started from a floating-point guess (a
      // Newton step from the midpoint; it only chooses where to look, every decision is an
      // exact integer comparison): gallop from the guess, then bisect.
      auto wins = [&](std::int64_t x) { return !(eval(fu, x - u) < eval(fi, x - i)); };
      // h(t) = g_u(t) - g_i(t) has slope -2 p ((u - i) / 2)^(p - 1) at the midpoint.
      const double slope = p * to_double(pw[u - i]) * inv_pow2 / static_cast<double>(u - i);
      double guess = 0.5 * static_cast<double>(i + u) + to_double(fu - fi) / slope;
      std::int64_t x0 = lo;
      if (std::isfinite(guess)) {
        x0 = guess <= static_cast<double>(lo)       ? lo
             : guess >= static_cast<double>(hi - 1) ? hi - 1
                                                    : static_cast<std::int64_t>(guess);
      }
      std::int64_t a = lo, b = hi; // g_i wins at a; b is "u wins" (or the sentinel hi)
      if (wins(x0)) {
        a = x0;
        std::int64_t step = 1;
        while (a + step < hi && wins(a + step)) {
          a += step;
          step *= 2;
        }
        b = std::min(a + step, hi);
      } else {
        b = x0;
        std::int64_t step = 1;
        while (b - step > lo && !wins(b - step)) {
          b -= step;
          step *= 2;
        }
        a = std::max(b - step, lo);
      }
      while (b - a > 1) {
        std::int64_t m = a + (b - a) / 2;
        if (eval(fu, m - u) < eval(fi, m - i)) {
          b = m;
        } else {
          a = m;
        }
      }
      return a;
    }
    if (r >= small<V>(hi - 1)) return hi - 1;
    if (r < small<V>(lo)) return lo;
    if constexpr (std::is_same_v<V, BigInt>) {
      return r.template convert_to<std::int64_t>();
    } else {
      return static_cast<std::int64_t>(r);
    }
  }
};

// Lower envelope of g_e(t) = f[e] + |t - e|^p over positions e in [0, len) (f[e] == inf: no
// function), evaluated at t in [qlo, qhi): g[t - qlo] and, when WithArg, the winning
// position arg[t - qlo] (-1 when there is no function at all). g may alias f (the query
// reads only the stack). s, t, fs: scratch of size len.
//
// ZeroRuns (values >= 0, as in a distance transform): a 0 between two 0s is a function
// that only wins at its own position (its neighbours are strictly closer everywhere else),
// so it is not pushed and every point of value 0 keeps 0 and itself as the argument.
template <bool WithArg, bool ZeroRuns, int K, class V>
void envelope_line(const LineMetric<K, V>& m, V* f, std::int64_t len, std::int64_t qlo,
                   std::int64_t qhi, const V& inf, V* g, std::int64_t* arg, std::int64_t* s,
                   std::int64_t* t, V* fs) {
  std::int64_t q = -1;
  const V zero{};
  for (std::int64_t u = 0; u < len; ++u) {
    const V fu = f[u];
    if (fu == inf) continue;
    if constexpr (ZeroRuns) {
      if (fu == zero && u > 0 && u + 1 < len && f[u - 1] == zero && f[u + 1] == zero) continue;
    }
    while (q >= 0 && m.eval(fs[q], t[q] - s[q]) > m.eval(fu, t[q] - u)) --q;
    if (q < 0) {
      q = 0;
      s[0] = u;
      t[0] = qlo;
      fs[0] = fu;
    } else {
      std::int64_t w = 1 + m.sep(s[q], fs[q], u, fu, t[q], qhi);
      if (w < qhi) {
        ++q;
        s[q] = u;
        t[q] = w;
        fs[q] = fu;
      }
    }
  }
  if (q < 0) {
    for (std::int64_t x = qlo; x < qhi; ++x) {
      g[x - qlo] = inf;
      if constexpr (WithArg) arg[x - qlo] = -1;
    }
    return;
  }
  t[q + 1] = qhi;
  for (std::int64_t k = 0; k <= q; ++k) {
    const std::int64_t sk = s[k];
    const V fk = fs[k];
    for (std::int64_t x = t[k]; x < t[k + 1]; ++x) {
      if constexpr (ZeroRuns) {
        // g[x - qlo] may alias f[x - qlo] only (written after f[x] is read at index >= it)
        if (f[x] == zero) {
          g[x - qlo] = zero;
          if constexpr (WithArg) arg[x - qlo] = x;
          continue;
        }
      }
      g[x - qlo] = m.eval(fk, x - sk);
      if constexpr (WithArg) arg[x - qlo] = sk;
    }
  }
}

template <class V>
struct Scratch {
  std::vector<V> buf, fs;
  std::vector<std::int64_t> sbuf, arg, s, t;
};

// One pass along axis a: every line of that axis becomes the lower envelope of its values.
// The lines are those of the columns j in [jb, je) of each block of st = stride(a) values (all
// of them by default; a part for the out-of-core transform, kernel/out_of_core_transform.hpp).
template <int K, class V>
void envelope_pass(const Domain& dom, int a, bool periodic, bool nonnegative,
                   const LineMetric<K, V>& m, V* f, const V& inf, std::vector<std::int64_t>* sites,
                   unsigned threads, std::int64_t jb = 0, std::int64_t je = -1) {
  const std::int64_t n = dom.extent(a), st = dom.stride(a);
  if (je < 0) je = st;
  if (je <= jb) return;
  const std::int64_t outer = dom.size() / (n * st);
  constexpr std::int64_t kBlock = sizeof(V) <= 4 ? 16 : 8;
  const std::int64_t bw_max = std::min(je - jb, kBlock);
  const std::int64_t nblocks = (je - jb + bw_max - 1) / bw_max;
  const std::int64_t len = periodic ? 3 * n : n, qlo = periodic ? n : 0;
  V* fp = f;
  std::int64_t* sp = sites != nullptr ? sites->data() : nullptr;
  parallel_chunks(outer * nblocks, threads, [&](std::int64_t begin, std::int64_t end) {
    Scratch<V> sc;
    const auto ub = static_cast<std::size_t>(bw_max);
    const auto ulen = static_cast<std::size_t>(len), un = static_cast<std::size_t>(n);
    sc.buf.assign(ub * ulen, V{});
    if (sp != nullptr) {
      sc.sbuf.assign(ub * un, 0);
      sc.arg.assign(ub * un, 0);
    }
    sc.s.assign(ulen + 1, 0);
    sc.t.assign(ulen + 1, 0);
    sc.fs.assign(ulen + 1, V{});
    for (std::int64_t unit = begin; unit < end; ++unit) {
      const std::int64_t o = unit / nblocks, j0 = jb + (unit % nblocks) * bw_max;
      const std::int64_t bw = std::min(bw_max, je - j0);
      const std::int64_t base = o * n * st + j0;
      V* bp = sc.buf.data();
      constexpr std::int64_t kAhead = 24;
      for (std::int64_t x = 0; x < n; ++x) {
        if (st > 1 && x + kAhead < n) __builtin_prefetch(fp + base + (x + kAhead) * st);
        const V* row = fp + base + x * st;
        for (std::int64_t b = 0; b < bw; ++b) bp[b * len + qlo + x] = row[b];
      }
      if (sp != nullptr) {
        for (std::int64_t x = 0; x < n; ++x) {
          const std::int64_t* row = sp + base + x * st;
          for (std::int64_t b = 0; b < bw; ++b)
            sc.sbuf[static_cast<std::size_t>(b * n + x)] = row[b];
        }
      }
      for (std::int64_t b = 0; b < bw; ++b) {
        V* line = bp + b * len;
        if (periodic) {
          for (std::int64_t x = 0; x < n; ++x) {
            line[x] = line[n + x];
            line[2 * n + x] = line[n + x];
          }
        }
        if (sp != nullptr) {
          if (nonnegative) {
            envelope_line<true, true>(m, line, len, qlo, qlo + n, inf, line, sc.arg.data() + b * n,
                                      sc.s.data(), sc.t.data(), sc.fs.data());
          } else {
            envelope_line<true, false>(m, line, len, qlo, qlo + n, inf, line, sc.arg.data() + b * n,
                                       sc.s.data(), sc.t.data(), sc.fs.data());
          }
        } else if (nonnegative) {
          envelope_line<false, true>(m, line, len, qlo, qlo + n, inf, line, nullptr, sc.s.data(),
                                     sc.t.data(), sc.fs.data());
        } else {
          envelope_line<false, false>(m, line, len, qlo, qlo + n, inf, line, nullptr, sc.s.data(),
                                      sc.t.data(), sc.fs.data());
        }
      }
      for (std::int64_t x = 0; x < n; ++x) {
        V* row = fp + base + x * st;
        for (std::int64_t b = 0; b < bw; ++b) row[b] = bp[b * len + x];
      }
      if (sp != nullptr) {
        for (std::int64_t x = 0; x < n; ++x) {
          std::int64_t* row = sp + base + x * st;
          for (std::int64_t b = 0; b < bw; ++b) {
            std::int64_t e = sc.arg[static_cast<std::size_t>(b * n + x)];
            row[b] = e < 0 ? -1 : sc.sbuf[static_cast<std::size_t>(b * n + (periodic ? e % n : e))];
          }
        }
      }
    }
  });
}

// First pass of a binary image along the last (contiguous) axis: distance along the line to
// the nearest point with mask == 0 (two scans), turned into its metric length.
template <int K, class V>
void mask_pass(const Domain& dom, bool periodic, const LineMetric<K, V>& m,
               const std::uint8_t* mask, int item, V* f, const V& inf,
               std::vector<std::int64_t>* sites, unsigned threads) {
  const int a = dom.dim() - 1;
  const std::int64_t n = dom.extent(a), lines = dom.size() / n;
  V* fp = f;
  std::int64_t* sp = sites != nullptr ? sites->data() : nullptr;
  const V zero{};
  // site_at(mk, x): point x of the line starting at mk is a site (every byte of its item is
  // 0). The loops are compiled twice: for one-byte items (the common case, kept as fast as a
  // plain byte test) and for wider ones.
  auto lines_with = [&](auto site_at) {
    parallel_chunks(lines, threads, [&](std::int64_t begin, std::int64_t end) {
      std::vector<std::int64_t> dist(static_cast<std::size_t>(n)),
          near(static_cast<std::size_t>(n));
      for (std::int64_t line = begin; line < end; ++line) {
        const std::int64_t base = line * n;
        const std::uint8_t* mk = mask + base * item;
        auto site = [&](std::int64_t x) { return site_at(mk, x); };
        std::int64_t z = -1;
        for (std::int64_t x = 0; x < n && z < 0; ++x) {
          if (site(x)) z = x;
        }
        if (z < 0) {
          for (std::int64_t x = 0; x < n; ++x) {
            fp[base + x] = inf;
            if (sp != nullptr) sp[base + x] = -1;
          }
          continue;
        }
        if (!periodic) {
          std::int64_t last = -1;
          for (std::int64_t x = 0; x < n; ++x) {
            if (site(x)) last = x;
            near[static_cast<std::size_t>(x)] = last;
            dist[static_cast<std::size_t>(x)] = last < 0 ? n : x - last;
          }
          last = -1;
          for (std::int64_t x = n; x-- > 0;) {
            if (site(x)) last = x;
            if (last >= 0 && last - x < dist[static_cast<std::size_t>(x)]) {
              dist[static_cast<std::size_t>(x)] = last - x;
              near[static_cast<std::size_t>(x)] = last;
            }
          }
        } else {
          // Around the circle from the zero z: forward, then backward.
          std::int64_t last = 0;
          for (std::int64_t k = 0; k < n; ++k) {
            std::int64_t x = (z + k) % n;
            if (site(x)) last = k;
            near[static_cast<std::size_t>(x)] = (z + last) % n;
            dist[static_cast<std::size_t>(x)] = k - last;
          }
          last = 0;
          for (std::int64_t k = 0; k < n; ++k) {
            std::int64_t x = ((z - k) % n + n) % n;
            if (site(x)) last = k;
            if (k - last < dist[static_cast<std::size_t>(x)]) {
              dist[static_cast<std::size_t>(x)] = k - last;
              near[static_cast<std::size_t>(x)] = ((z - last) % n + n) % n;
            }
          }
        }
        for (std::int64_t x = 0; x < n; ++x) {
          fp[base + x] = m.eval(zero, dist[static_cast<std::size_t>(x)]);
          if (sp != nullptr) sp[base + x] = base + near[static_cast<std::size_t>(x)];
        }
      }
    });
  };
  if (item == 1) {
    lines_with([](const std::uint8_t* mk, std::int64_t x) { return mk[x] == 0; });
  } else {
    lines_with([item](const std::uint8_t* mk, std::int64_t x) {
      const std::uint8_t* p = mk + x * item;
      for (int b = 0; b < item; ++b) {
        if (p[b] != 0) return false;
      }
      return true;
    });
  }
}

template <int K, class V>
void run_passes(const Domain& dom, const TransformOptions& opt, const std::uint8_t* mask, int item,
                V* f, const V& inf, std::vector<std::int64_t>* sites, const std::vector<V>& pw,
                const EnvelopePart& part) {
  LineMetric<K, V> m;
  m.pw = pw.data();
  m.p = opt.metric.p;
  m.inv_pow2 = std::ldexp(1.0, -(opt.metric.p - 2));
  const unsigned threads = resolve_threads(opt.threads, dom.size());
  const int d = dom.dim();
  if (part.slices) {
    if (mask != nullptr) {
      mask_pass(dom, opt.periodic(d - 1), m, mask, item, f, inf, sites, threads);
    } else {
      if (sites != nullptr) {
        sites->resize(static_cast<std::size_t>(dom.size()));
        for (std::int64_t i = 0; i < dom.size(); ++i) (*sites)[static_cast<std::size_t>(i)] = i;
      }
      envelope_pass(dom, d - 1, opt.periodic(d - 1), false, m, f, inf, sites, threads);
    }
    if (part.after_pass) part.after_pass(d - 1);
    for (int a = d - 2; a >= 1; --a) {
      envelope_pass(dom, a, opt.periodic(a), mask != nullptr, m, f, inf, sites, threads);
      if (part.after_pass) part.after_pass(a);
    }
  }
  if (part.axis0 && d >= 2) {
    envelope_pass(dom, 0, opt.periodic(0), part.from_mask, m, f, inf, sites, threads,
                  part.column_begin, part.column_end);
    if (part.after_pass) part.after_pass(0);
  }
}
} // namespace

unsigned resolve_threads(unsigned requested, std::int64_t n) {
  // Below 2^15 points a thread costs more than it saves.
  return n < (std::int64_t{1} << 15) ? 1u : worker_count(requested, n);
}

EnvelopeBounds envelope_bounds(const Domain& dom, const TransformOptions& opt,
                               const BigInt& weight_max) {
  const Metric& mt = opt.metric;
  if (!mt.is_inf() && mt.p < 1) {
    throw InvalidArgument("metric: p = " + std::to_string(mt.p) + " is not an integer >= 1");
  }
  if (!opt.torus.empty() && static_cast<int>(opt.torus.size()) != dom.dim()) {
    throw InvalidArgument("torus: " + std::to_string(opt.torus.size()) + " flags for a " +
                          std::to_string(dom.dim()) + "-D image");
  }
  if (!mt.is_inf()) {
    // The bit budget of the p-th powers (kernel/lp_metric.hpp), checked before any of them is
    // computed: p log2(L) < kMaxMetricBits - 8 leaves room for the sums and the factor 2.
    std::int64_t l = 1;
    for (int k = 0; k < dom.dim(); ++k) {
      l = std::max(l, opt.periodic(k) ? 3 * dom.extent(k) : dom.extent(k));
    }
    const double bits = mt.p * std::log2(static_cast<double>(l));
    const int budget = kMaxMetricBits - 8;
    if (bits > budget) {
      throw InvalidArgument(
          "metric " + mt.name() + ": its exact values on lines of " + std::to_string(l) +
          " points would need about " + std::to_string(static_cast<long long>(bits)) +
          " bits; zdg supports l_p while L^p < 2^" + std::to_string(kMaxMetricBits) +
          " (here p <= " +
          std::to_string(static_cast<long long>(budget / std::log2(static_cast<double>(l)))) +
          "; linf is the limit of l_p)");
    }
  }
  BigInt vmax = 0;
  std::int64_t lmax = 1;
  for (int k = 0; k < dom.dim(); ++k) {
    std::int64_t n = dom.extent(k);
    std::int64_t mk = opt.periodic(k) ? n / 2 : n - 1;
    BigInt pk = metric_power(mt, mk);
    if (mt.is_inf()) {
      vmax = std::max(vmax, pk);
    } else {
      vmax += pk;
    }
    lmax = std::max(lmax, opt.periodic(k) ? 3 * n : n);
  }
  EnvelopeBounds b;
  b.value_max = vmax;
  b.need = 2 * (vmax + weight_max + metric_power(mt, lmax)) + 2 * BigInt(lmax);
  const unsigned bits = opt.min_engine_bits;
  if (bits <= 32 && b.need < BigInt(std::numeric_limits<std::int32_t>::max())) {
    b.width = ValueWidth::I32;
  } else if (bits <= 64 && b.need < BigInt(std::numeric_limits<std::int64_t>::max())) {
    b.width = ValueWidth::I64;
  } else if (bits <= 128 && b.need < (BigInt(1) << 126)) {
    b.width = ValueWidth::I128;
  } else {
    b.width = ValueWidth::Big;
  }
  return b;
}

std::uint64_t engine_value_bytes(ValueWidth w) {
  switch (w) {
  case ValueWidth::I32:
    return 4;
  case ValueWidth::I64:
    return 8;
  case ValueWidth::I128:
    return 16;
  case ValueWidth::Big:
    break;
  }
  return 0;
}

void require_output_fits(const EnvelopeBounds& b, const TransformOptions& opt,
                         const BigInt& out_max, const char* who) {
  if (b.value_max > out_max) {
    throw OverflowError(std::string(who) + ": values up to " + b.value_max.str() + " (" +
                        opt.metric.name() + ") do not fit the output type (max " + out_max.str() +
                        ")");
  }
}

void require_mask_item_bytes(int mask_item_bytes, const char* who) {
  if (mask_item_bytes != 1 && mask_item_bytes != 2 && mask_item_bytes != 4 &&
      mask_item_bytes != 8) {
    throw InvalidArgument(std::string(who) + ": mask items of " + std::to_string(mask_item_bytes) +
                          " bytes (1, 2, 4 or 8)");
  }
}

template <class V>
V envelope_infinity(const EnvelopeBounds& b) {
  if constexpr (std::is_same_v<V, BigInt>) {
    return b.need + 1;
  } else if constexpr (std::is_same_v<V, int128_t>) {
    return static_cast<int128_t>((~static_cast<uint128_t>(0)) >> 1);
  } else {
    return std::numeric_limits<V>::max();
  }
}

template <class V>
void separable_envelope_part(const Domain& dom, const TransformOptions& opt,
                             const std::uint8_t* mask, V* f, const V& inf,
                             std::vector<std::int64_t>* sites, int mask_item_bytes,
                             const EnvelopePart& part) {
  require_mask_item_bytes(mask_item_bytes, "transform");
  if (sites != nullptr) sites->resize(static_cast<std::size_t>(dom.size()));
  const Metric& mt = opt.metric;
  std::vector<V> pw;
  if (mt.is_inf()) {
    run_passes<kLinf>(dom, opt, mask, mask_item_bytes, f, inf, sites, pw, part);
  } else if (mt.p == 1) {
    run_passes<kL1>(dom, opt, mask, mask_item_bytes, f, inf, sites, pw, part);
  } else if (mt.p == 2) {
    run_passes<kL2>(dom, opt, mask, mask_item_bytes, f, inf, sites, pw, part);
  } else {
    // The table covers the axes this part runs only: a part's other extents (the out-of-core
    // column block's width, for one) may exceed every extent the bounds were computed on.
    std::int64_t lmax = 1;
    const int d = dom.dim();
    for (int k = 0; k < d; ++k) {
      const bool runs = k == 0 ? (d == 1 ? part.slices : part.axis0) : part.slices;
      if (runs) lmax = std::max(lmax, opt.periodic(k) ? 3 * dom.extent(k) : dom.extent(k));
    }
    pw.resize(static_cast<std::size_t>(lmax) + 1);
    for (std::int64_t t = 0; t <= lmax; ++t) {
      // t^p by square-and-multiply (p <= kMaxMetricP; the bound checked at entry holds it).
      V v = 1, b = small<V>(t);
      for (unsigned e = static_cast<unsigned>(mt.p);; b *= b) {
        if (e & 1u) v *= b;
        e >>= 1;
        if (e == 0) break;
      }
      pw[static_cast<std::size_t>(t)] = v;
    }
    run_passes<kLp>(dom, opt, mask, mask_item_bytes, f, inf, sites, pw, part);
  }
}

template <class V>
void separable_envelope(const Domain& dom, const TransformOptions& opt, const std::uint8_t* mask,
                        V* f, const V& inf, std::vector<std::int64_t>* sites, int mask_item_bytes) {
  EnvelopePart whole;
  whole.from_mask = mask != nullptr;
  separable_envelope_part<V>(dom, opt, mask, f, inf, sites, mask_item_bytes, whole);
}

#define ZDG_ENGINE_INSTANTIATE(V)                                                                  \
  template V envelope_infinity<V>(const EnvelopeBounds&);                                          \
  template void separable_envelope_part<V>(const Domain&, const TransformOptions&,                 \
                                           const std::uint8_t*, V*, const V&,                      \
                                           std::vector<std::int64_t>*, int, const EnvelopePart&);  \
  template void separable_envelope<V>(const Domain&, const TransformOptions&, const std::uint8_t*, \
                                      V*, const V&, std::vector<std::int64_t>*, int);
ZDG_ENGINE_INSTANTIATE(std::int32_t)
ZDG_ENGINE_INSTANTIATE(std::int64_t)
ZDG_ENGINE_INSTANTIATE(int128_t)
ZDG_ENGINE_INSTANTIATE(BigInt)
#undef ZDG_ENGINE_INSTANTIATE

} // namespace zdg::detail
