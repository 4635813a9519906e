#include <zdg/kernel/transforms/separable_engine.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <mutex>
#include <string>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#endif

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
// Values only (!WithArg): local peaks are left out, as in the vectorized envelopes. A point u
// with f[u] >= f[u-1] and f[u] >= f[u+1] never does better than u-1 left of u (f[u-1] <= f[u]
// and |x-u+1| < |x-u|: g_{u-1}(x) <= g_u(x) for every metric) nor than u+1 right of it; when
// u-1 is a peak too, the same one step further, down to a pushed point or to x itself, whose
// own value the query's min(g(x), f(x)) restores. So the envelope's values are unchanged, for
// any sign of f (a neighbour without a function, inf, is never <= f[u]).
// With the argument (WithArg), ties must keep the sites they had, so only ZeroRuns (values >=
// 0, as in a distance transform): a 0 between two 0s is a function that only wins at its own
// position (its neighbours are strictly closer everywhere else), so it is not pushed and every
// point of value 0 keeps 0 and itself as the argument.
template <bool WithArg, bool ZeroRuns, int K, class V>
void envelope_line(const LineMetric<K, V>& m, V* f, std::int64_t len, std::int64_t qlo,
                   std::int64_t qhi, const V& inf, V* g, std::int64_t* arg, std::int64_t* s,
                   std::int64_t* t, V* fs) {
  static_assert(WithArg || !ZeroRuns, "values only: the peaks left out include the zero runs");
  std::int64_t q = -1;
  const V zero{};
  for (std::int64_t u = 0; u < len; ++u) {
    const V& fu = f[u];
    if (fu == inf) continue;
    if constexpr (!WithArg) {
      if (u > 0 && u + 1 < len && !(fu < f[u - 1]) && !(fu < f[u + 1])) continue;
    } else if constexpr (ZeroRuns) {
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
      // g[x - qlo] may alias f[x - qlo] only (written after f[x] is read at index >= it)
      if constexpr (!WithArg) {
        V v = m.eval(fk, x - sk);
        if (f[x] < v) v = f[x]; // a peak left out restores itself
        g[x - qlo] = std::move(v);
      } else if (ZeroRuns && f[x] == zero) {
        g[x - qlo] = zero;
        arg[x - qlo] = x;
      } else {
        g[x - qlo] = m.eval(fk, x - sk);
        arg[x - qlo] = sk;
      }
    }
  }
}

#if defined(__x86_64__) && defined(__GNUC__)
#define ZDG_ENVELOPE_AVX512 1

// Halves of a vector of 16 int32 and back (vector extensions: GCC 12's cast and extract
// intrinsics warn -Wmaybe-uninitialized).
typedef std::int32_t I32x8 __attribute__((vector_size(32)));
typedef std::int32_t I32x16 __attribute__((vector_size(64)));
template <int H>
__attribute__((target("avx512f"), always_inline)) inline __m256i half(__m512i v) {
  const auto x = reinterpret_cast<I32x16>(v);
  if constexpr (H == 0) {
    return reinterpret_cast<__m256i>(__builtin_shufflevector(x, x, 0, 1, 2, 3, 4, 5, 6, 7));
  } else {
    return reinterpret_cast<__m256i>(__builtin_shufflevector(x, x, 8, 9, 10, 11, 12, 13, 14, 15));
  }
}
__attribute__((target("avx512f"), always_inline)) inline __m512i join(__m256i a, __m256i b) {
  return reinterpret_cast<__m512i>(
      __builtin_shufflevector(reinterpret_cast<I32x8>(a), reinterpret_cast<I32x8>(b), 0, 1, 2, 3, 4,
                              5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15));
}

// g + metric length of dx (LineMetric::eval) in 16 lanes; |dx|^p by p - 1 products (the
// int32 engine holds L^p, so p is small: p <= 30, and p <= 3 for lines of 1,000 points).
template <int K>
__attribute__((target("avx512f"), always_inline)) inline __m512i eval16(__m512i f, __m512i dx,
                                                                        int p) {
  const __mmask16 all = 0xFFFF;
  if constexpr (K == kL2) {
    (void)p;
    return _mm512_add_epi32(f, _mm512_mullo_epi32(dx, dx));
  } else {
    const __m512i a = _mm512_maskz_abs_epi32(all, dx);
    if constexpr (K == kL1) {
      (void)p;
      return _mm512_add_epi32(f, a);
    } else if constexpr (K == kLinf) {
      (void)p;
      return _mm512_maskz_max_epi32(all, f, a);
    } else {
      __m512i r = a;
      for (int k = 1; k < p; ++k) r = _mm512_mullo_epi32(r, a);
      return _mm512_add_epi32(f, r);
    }
  }
}

// The lanes where u is strictly below the top at y (g_u(y) < g_s(y)).
template <int K>
__attribute__((target("avx512f"), always_inline)) inline __mmask16
u_wins16(__m512i y, __m512i vu, __m512i fu, __m512i ts, __m512i tf, int p) {
  return _mm512_cmplt_epi32_mask(eval16<K>(fu, _mm512_sub_epi32(y, vu), p),
                                 eval16<K>(tf, _mm512_sub_epi32(y, ts), p));
}

// The separator r (LineMetric::sep before its clamp to [t_top, end - 1]; `far`: lanes where
// u never wins) of the tops (ts, tf) and u (fu) in the lanes of `full`; for l_p, the clamped
// one, by bisection over [tt, hi).
template <int K>
__attribute__((target("avx512f"), always_inline)) inline __m512i
separator16(__m512i vu, __m512i fu, __m512i ts, __m512i tt, __m512i tf, __m512i vhi, int p,
            __mmask16 full, __mmask16& far) {
  const __mmask16 all = 0xFFFF;
  const __m512i one = _mm512_set1_epi32(1);
  far = 0;
  if constexpr (K == kL2) {
    (void)tt;
    (void)vhi;
    (void)p;
    (void)full;
    const __m512i diff = _mm512_sub_epi32(vu, ts);
    const __m512i num = _mm512_add_epi32(_mm512_mullo_epi32(diff, _mm512_add_epi32(vu, ts)),
                                         _mm512_sub_epi32(fu, tf));
    const __m512i den = _mm512_add_epi32(diff, diff);
    // floor(num / den) in two halves of 8 doubles (exact, see envelope_block_avx512)
    const __m512d nlo = _mm512_maskz_cvtepi32_pd(0xFF, half<0>(num));
    const __m512d nhi = _mm512_maskz_cvtepi32_pd(0xFF, half<1>(num));
    const __m512d dlo = _mm512_maskz_cvtepi32_pd(0xFF, half<0>(den));
    const __m512d dhi = _mm512_maskz_cvtepi32_pd(0xFF, half<1>(den));
    const __m256i qlo8 = _mm512_maskz_cvt_roundpd_epi32(0xFF, _mm512_div_pd(nlo, dlo),
                                                        _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
    const __m256i qhi8 = _mm512_maskz_cvt_roundpd_epi32(0xFF, _mm512_div_pd(nhi, dhi),
                                                        _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
    return join(qlo8, qhi8);
  } else if constexpr (K == kL1) {
    (void)tt;
    (void)vhi;
    (void)p;
    const __m512i df = _mm512_sub_epi32(fu, tf);
    far = full & _mm512_cmpge_epi32_mask(df, _mm512_sub_epi32(vu, ts));
    return _mm512_maskz_srai_epi32(all, _mm512_add_epi32(df, _mm512_add_epi32(vu, ts)), 1);
  } else if constexpr (K == kLinf) {
    (void)tt;
    (void)vhi;
    (void)p;
    (void)full;
    const __m512i mid = _mm512_maskz_srai_epi32(all, _mm512_add_epi32(vu, ts), 1);
    const __mmask16 le = _mm512_cmple_epi32_mask(tf, fu);
    const __m512i a_le = _mm512_add_epi32(ts, fu), a_gt = _mm512_sub_epi32(vu, tf);
    return _mm512_mask_mov_epi32(_mm512_maskz_min_epi32(all, a_gt, mid), le,
                                 _mm512_maskz_max_epi32(all, a_le, mid));
  } else {
    // A guess x0, then two exact tests at x0 and x0 + 1 settle the lanes where it is right, a
    // gallop from there brackets the others, then bisection: the top wins at lo, u wins at hi
    // (or hi is the end of the line). The guess only chooses where to look. It is the
    // midpoint (exact where f_u = f_s), and for p = 3 the root of
    // h(t) = c + |t - u|^3 - |t - s|^3, c = f_u - f_s, D = u - s, in float where it lies
    // outside [s, u] (the common case in a distance transform: neighbouring sites of
    // different heights): for t >= u (c >= D^3), with a = t - u, h = c - D (3a^2 + 3aD + D^2),
    // so a = (sqrt(12 c / D - 3 D^2) - 3D) / 6; for t <= s (c <= -D^3) the mirror image.
    // (Newton steps from the midpoint were measured: slower, far roots need many.)
    __m512i x0 = _mm512_maskz_srai_epi32(all, _mm512_add_epi32(ts, vu), 1);
    if (p == 3) {
      const __m512i di = _mm512_sub_epi32(vu, ts), ci = _mm512_sub_epi32(fu, tf);
      const __m512 dd = _mm512_maskz_cvtepi32_ps(all, di);
      const __m512 cc = _mm512_maskz_cvtepi32_ps(all, ci);
      const __m512 d3 = _mm512_mul_ps(_mm512_mul_ps(dd, dd), dd);
      const __m512 ac = _mm512_abs_ps(cc);
      const __m512 disc = _mm512_sub_ps(_mm512_div_ps(_mm512_mul_ps(_mm512_set1_ps(12.0f), ac), dd),
                                        _mm512_mul_ps(_mm512_set1_ps(3.0f), _mm512_mul_ps(dd, dd)));
      const __m512 a =
          _mm512_mul_ps(_mm512_sub_ps(_mm512_maskz_sqrt_ps(
                                          all, _mm512_maskz_max_ps(all, disc, _mm512_setzero_ps())),
                                      _mm512_mul_ps(_mm512_set1_ps(3.0f), dd)),
                        _mm512_set1_ps(1.0f / 6.0f));
      const __m512i ai =
          _mm512_maskz_cvt_roundps_epi32(all, a, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
      const __mmask16 right = _mm512_cmp_ps_mask(cc, d3, _CMP_GE_OQ);
      const __mmask16 left =
          _mm512_cmp_ps_mask(cc, _mm512_sub_ps(_mm512_setzero_ps(), d3), _CMP_LE_OQ);
      x0 = _mm512_mask_mov_epi32(x0, right, _mm512_add_epi32(vu, ai));
      // t = s - b, b = a(|c|): floor(s - b) = s - ceil(b) ~ s - floor(b) - 1
      x0 = _mm512_mask_mov_epi32(x0, left, _mm512_sub_epi32(_mm512_sub_epi32(ts, ai), one));
    }
    x0 = _mm512_maskz_min_epi32(all, _mm512_maskz_max_epi32(all, x0, tt),
                                _mm512_sub_epi32(vhi, one));
    const __m512i x1 = _mm512_add_epi32(x0, one);
    const __mmask16 top0 = full & ~u_wins16<K>(x0, vu, fu, ts, tf, p);
    const __mmask16 in1 = _mm512_cmplt_epi32_mask(x1, vhi);
    const __mmask16 top1 = in1 & ~u_wins16<K>(x1, vu, fu, ts, tf, p);
    __m512i lo = _mm512_mask_mov_epi32(tt, top0, x0);
    lo = _mm512_mask_mov_epi32(lo, top0 & top1, x1);
    __m512i hi = _mm512_mask_mov_epi32(vhi, full & ~top0, x0);
    hi = _mm512_mask_mov_epi32(hi, top0 & in1 & ~top1, x1);
    // Gallop from the guess (the guess is off by a few points where it is off at all): up
    // where the top still wins at x0 + 1, down where u already wins at x0.
    __mmask16 up = top0 & top1, down = full & ~top0;
    for (__m512i step = one; up != 0; step = _mm512_add_epi32(step, step)) {
      const __m512i y = _mm512_add_epi32(lo, step);
      const __mmask16 test = up & _mm512_cmplt_epi32_mask(y, vhi);
      const __mmask16 tw = test & ~u_wins16<K>(y, vu, fu, ts, tf, p);
      lo = _mm512_mask_mov_epi32(lo, tw, y);
      hi = _mm512_mask_mov_epi32(hi, test & ~tw, y);
      up = tw;
    }
    for (__m512i step = one; down != 0; step = _mm512_add_epi32(step, step)) {
      const __m512i y = _mm512_sub_epi32(hi, step);
      const __mmask16 test = down & _mm512_cmpgt_epi32_mask(y, tt);
      const __mmask16 tw = test & ~u_wins16<K>(y, vu, fu, ts, tf, p);
      lo = _mm512_mask_mov_epi32(lo, tw, y);
      hi = _mm512_mask_mov_epi32(hi, test & ~tw, y);
      down = test & ~tw;
    }
    for (;;) {
      const __mmask16 open = full & _mm512_cmpgt_epi32_mask(_mm512_sub_epi32(hi, lo), one);
      if (open == 0) break;
      const __m512i mid =
          _mm512_add_epi32(lo, _mm512_maskz_srai_epi32(all, _mm512_sub_epi32(hi, lo), 1));
      const __mmask16 uw = open & u_wins16<K>(mid, vu, fu, ts, tf, p);
      hi = _mm512_mask_mov_epi32(hi, uw, mid);
      lo = _mm512_mask_mov_epi32(lo, open & static_cast<__mmask16>(~uw), mid);
    }
    return lo;
  }
}

// Packed entries: the element below u, in row u of one table of 64-bit entries per lane (the
// 16 lanes' entries of a row are two vectors of 8), its value in the low half and site + 1 and
// segment start in the high and low 16 bits of the high half. A pop then gathers 16 entries
// once: gathers cost by the entries they fetch (and are not cheaper for masked lanes), so one
// 64-bit gather of the three fields costs half the two 32-bit gathers of two tables.
__attribute__((target("avx512f"), always_inline)) inline void
store_packed(std::int32_t* row, __m512i ts, __m512i tt, __m512i tf) {
  const __mmask16 all = 0xFFFF;
  const __m512i one = _mm512_set1_epi32(1);
  const __m512i pk = _mm512_or_si512(_mm512_maskz_slli_epi32(all, _mm512_add_epi32(ts, one), 16),
                                     _mm512_and_si512(tt, _mm512_set1_epi32(0xFFFF)));
  const __m512i lo = _mm512_setr_epi32(0, 16, 1, 17, 2, 18, 3, 19, 4, 20, 5, 21, 6, 22, 7, 23);
  const __m512i hi = _mm512_add_epi32(lo, _mm512_set1_epi32(8));
  _mm512_store_si512(row, _mm512_maskz_permutex2var_epi32(all, tf, lo, pk));
  _mm512_store_si512(row + 16, _mm512_maskz_permutex2var_epi32(all, tf, hi, pk));
}

// Pops the lanes of `go`: the element below the top (its site, segment start and value), from
// row ts of the tables (Packed: of the one table of 64-bit entries, P).
template <bool Packed>
__attribute__((target("avx512f"), always_inline)) inline void
below(__m512i& ts, __m512i& tt, __m512i& tf, __mmask16 go, const std::int32_t* P,
      const std::int32_t* B, const std::int32_t* BT, const std::int32_t* BF) {
  const __mmask16 all = 0xFFFF;
  const __m512i lane = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
  // lane l of row r: entry 16 r + l (64-bit words of P, or 32-bit words of B, BT, BF)
  const __m512i at = _mm512_add_epi32(_mm512_maskz_slli_epi32(all, ts, 4), lane);
  if constexpr (Packed) {
    (void)B;
    (void)BT;
    (void)BF;
    const auto* base = reinterpret_cast<const long long*>(P);
    const __m512i e0 = _mm512_mask_i32gather_epi64(_mm512_setzero_si512(),
                                                   static_cast<__mmask8>(go), half<0>(at), base, 8);
    const __m512i e1 = _mm512_mask_i32gather_epi64(
        _mm512_setzero_si512(), static_cast<__mmask8>(go >> 8), half<1>(at), base, 8);
    const __m512i even =
        _mm512_setr_epi32(0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30);
    const __m512i f = _mm512_maskz_permutex2var_epi32(all, e0, even, e1);
    const __m512i pk =
        _mm512_maskz_permutex2var_epi32(all, e0, _mm512_add_epi32(even, _mm512_set1_epi32(1)), e1);
    ts = _mm512_mask_sub_epi32(ts, go, _mm512_maskz_srai_epi32(all, pk, 16), _mm512_set1_epi32(1));
    tt = _mm512_mask_and_epi32(tt, go, pk, _mm512_set1_epi32(0xFFFF));
    tf = _mm512_mask_mov_epi32(tf, go, f);
  } else {
    (void)P;
    ts = _mm512_mask_i32gather_epi32(ts, go, at, B, 4);
    tt = _mm512_mask_i32gather_epi32(tt, go, at, BT, 4);
    tf = _mm512_mask_i32gather_epi32(tf, go, at, BF, 4);
  }
}

// The envelopes of NB blocks of 16 adjacent lines in int32, one line per lane of an AVX-512
// vector (the lines' rows are contiguous in memory, so a row of a block is one vector load: no
// transpose). It is the stack sweep of envelope_line<false, ...> run in lockstep (the
// peaks below left out as there), with the stack of each lane kept as a
// list linked through positions: pushing u stores, in row u of position-indexed tables, the
// element below it (its site, segment start and value; plain vector stores: every lane writes
// row u), and popping u reads them back (gathers from the same index), so no scatter is
// needed. Lines under 2^15 points hold the three in one 64-bit entry (see store_packed).
// The queries walk each lane's list from the top, x from the end of the line down.
// The NB blocks advance together (each pop round gathers for all of them): their dependency
// chains of gathers overlap, and a row of the NB blocks is NB adjacent cache lines.
// Separators (LineMetric::sep, the same integers):
// - l2: floor(((u - s)(u + s) + f_u - f_s) / (2 (u - s))) computed in double: the numerator
//   is below 2^31 in magnitude and the denominator below 2^17, so the rounded quotient is
//   within 2^-22 of the exact one, closer than any non-integer quotient is to an integer
//   (1 / den), and the floor of the rounded quotient is the exact floor;
// - l1 and linf: their closed forms (a shift is the floor of a halving);
// - l_p: the last t in [t_top, end) where the top still wins, by exact tests in every lane at
//   once (the predicate is monotone, so it is the same t as the scalar gallop from a guess).
// Every other operation is the int32 arithmetic of the scalar loop (bounded by `need`,
// separable_engine.hpp), so the values are the same to the bit.
//
// Peaks: a point u inside the line with f(u) >= f(u - 1) and f(u) >= f(u + 1) is not pushed,
// and each query takes min(g(x), f(x)).
// The values stay those of the envelope of every point: for x < u, g_{u-1}(x) < g_u(x)
// (f(u - 1) <= f(u) and |x - u + 1| < |x - u|; every metric's value grows with both), and
// if u - 1 is a peak too the same holds one step further left, down to a point that was
// pushed, or to x itself, whose value f(x) the min adds back; the mirror image for x > u.
// No sign or metric is assumed beyond that growth, so it holds for weighted values too. (It
// takes runs of zeros, and in a distance transform the many points no site is nearer to
// through them than through a neighbour.)
//
// src: the first block's first value, rows st values apart, bw lanes used in all (the first
// bw of the 16 NB columns); written in place. tables: 4 NB len 16 int32, 64-byte aligned.
template <int K, int NB, bool Packed>
__attribute__((target("avx512f"))) void
envelope_block_avx512(std::int32_t* src, std::int64_t st, int bw, std::int64_t n, bool periodic,
                      std::int32_t inf, int p, std::int32_t* tables) {
  const std::int64_t len = periodic ? 3 * n : n, qlo = periodic ? n : 0, qhi = qlo + n;
  const __m512i vinf = _mm512_set1_epi32(inf), zero = _mm512_setzero_si512();
  const __m512i one = _mm512_set1_epi32(1);
  // (the maskz_ forms with every lane: GCC 12's plain forms warn -Wmaybe-uninitialized)
  const __mmask16 all = 0xFFFF;
  __mmask16 used[NB];
  std::int32_t *F[NB], *P[NB], *B[NB], *BT[NB], *BF[NB];
  for (int b = 0; b < NB; ++b) {
    const int w = std::clamp(bw - 16 * b, 0, 16);
    used[b] = static_cast<__mmask16>((1u << w) - 1u);
    F[b] = tables + 4 * b * len * 16;
    P[b] = F[b] + len * 16; // Packed: 2 len 16 (64-bit entries)
    B[b] = F[b] + len * 16; // not Packed: three tables
    BT[b] = B[b] + len * 16;
    BF[b] = BT[b] + len * 16;
  }
  // The rows: on a torus, copied three times into F (unused lanes hold inf: no function);
  // otherwise read in place (the queries read row x before they write it).
  constexpr std::int64_t kAhead = 16;
  const bool ahead = st > 16 * NB; // rows in different cache lines: prefetch
  const std::int32_t* R[NB];
  const std::int64_t rs = periodic ? 16 : st;
  for (int b = 0; b < NB; ++b) R[b] = periodic ? F[b] : src + 16 * b;
  if (periodic) {
    for (std::int64_t x = 0; x < n; ++x) {
      if (ahead && x + kAhead < n) {
        for (int b = 0; b < NB; ++b) __builtin_prefetch(src + (x + kAhead) * st + 16 * b);
      }
      for (int b = 0; b < NB; ++b) {
        const __m512i row = _mm512_mask_loadu_epi32(vinf, used[b], src + x * st + 16 * b);
        _mm512_store_si512(F[b] + x * 16, row);
        _mm512_store_si512(F[b] + (n + x) * 16, row);
        _mm512_store_si512(F[b] + (2 * n + x) * 16, row);
      }
    }
  }
  // Stack tops per lane: site s (-1: empty), segment start t, value f.
  __m512i ts[NB], tt[NB], tf[NB];
  for (int b = 0; b < NB; ++b) {
    ts[b] = _mm512_set1_epi32(-1);
    tt[b] = _mm512_set1_epi32(std::numeric_limits<std::int32_t>::min());
    tf[b] = zero;
  }
  const __m512i vhi = _mm512_set1_epi32(static_cast<std::int32_t>(qhi));
  const __m512i vhi1 = _mm512_set1_epi32(static_cast<std::int32_t>(qhi - 1));
  const __m512i vqlo = _mm512_set1_epi32(static_cast<std::int32_t>(qlo));
  for (std::int64_t u = 0; u < len; ++u) {
    const __m512i vu = _mm512_set1_epi32(static_cast<std::int32_t>(u));
    __m512i fu[NB];
    __mmask16 active[NB], pop[NB];
    bool any = false;
    if (!periodic && ahead && u + kAhead < n) {
      for (int b = 0; b < NB; ++b) __builtin_prefetch(src + (u + kAhead) * st + 16 * b);
    }
    for (int b = 0; b < NB; ++b) {
      fu[b] = _mm512_mask_loadu_epi32(vinf, used[b], R[b] + u * rs);
      active[b] = _mm512_cmpneq_epi32_mask(fu[b], vinf);
      if (u > 0 && u + 1 < len) {
        // (masked loads: the lanes past the block's columns may lie past the buffer)
        const __m512i before = _mm512_maskz_loadu_epi32(used[b], R[b] + (u - 1) * rs);
        const __m512i after = _mm512_maskz_loadu_epi32(used[b], R[b] + (u + 1) * rs);
        const __mmask16 peak =
            _mm512_cmpge_epi32_mask(fu[b], before) & _mm512_cmpge_epi32_mask(fu[b], after);
        active[b] &= static_cast<__mmask16>(~peak);
      }
      any |= active[b] != 0;
    }
    if (!any) continue;
    for (;;) {
      // Pop where the top's value at its segment start exceeds u's there.
      bool popped = false;
      for (int b = 0; b < NB; ++b) {
        const __mmask16 cand = active[b] & _mm512_cmpge_epi32_mask(ts[b], zero);
        const __m512i gtop = eval16<K>(tf[b], _mm512_sub_epi32(tt[b], ts[b]), p);
        const __m512i gu = eval16<K>(fu[b], _mm512_sub_epi32(tt[b], vu), p);
        pop[b] = _mm512_mask_cmpgt_epi32_mask(cand, gtop, gu);
        popped |= pop[b] != 0;
      }
      if (!popped) break;
      for (int b = 0; b < NB; ++b) {
        below<Packed>(ts[b], tt[b], tf[b], pop[b], P[b], B[b], BT[b], BF[b]);
      }
    }
    for (int b = 0; b < NB; ++b) {
      if (active[b] == 0) continue;
      const __mmask16 empty = active[b] & _mm512_cmplt_epi32_mask(ts[b], zero);
      const __mmask16 full = active[b] & static_cast<__mmask16>(~empty);
      __m512i w = vqlo;
      __mmask16 push = empty;
      if (full != 0) {
        __mmask16 far = 0;
        __m512i r = separator16<K>(vu, fu[b], ts[b], tt[b], tf[b], vhi, p, full, far);
        if constexpr (K != kLp) {
          r = _mm512_maskz_min_epi32(all, _mm512_maskz_max_epi32(all, r, tt[b]), vhi1);
          r = _mm512_mask_mov_epi32(r, far, vhi1);
        }
        push |= full & _mm512_cmplt_epi32_mask(r, vhi1);
        w = _mm512_mask_mov_epi32(w, full, _mm512_add_epi32(r, one));
      }
      if (push == 0) continue;
      // Row u of the tables: the element below u (rows of lanes that do not push u are never
      // read: u is not on their lists).
      if constexpr (Packed) {
        store_packed(P[b] + u * 32, ts[b], tt[b], tf[b]);
      } else {
        _mm512_store_si512(B[b] + u * 16, ts[b]);
        _mm512_store_si512(BT[b] + u * 16, tt[b]);
        _mm512_store_si512(BF[b] + u * 16, tf[b]);
      }
      ts[b] = _mm512_mask_mov_epi32(ts[b], push, vu);
      tt[b] = _mm512_mask_mov_epi32(tt[b], push, w);
      tf[b] = _mm512_mask_mov_epi32(tf[b], push, fu[b]);
    }
  }
  // Queries, from the end of the line: the segment of x is the first one from the top whose
  // start is <= x. The bottom's segment starts at qlo, so a stack does not empty here: the
  // lanes with a function (`some`) are known once. Segments are not empty (a push starts one
  // after the top's start, at most at qhi - 1), so from x + 1 to x a lane steps down at most
  // once.
  __mmask16 some[NB];
  for (int b = 0; b < NB; ++b) some[b] = _mm512_cmpge_epi32_mask(ts[b], zero);
  for (std::int64_t x = qhi; x-- > qlo;) {
    if (ahead && x - kAhead >= qlo) {
      for (int b = 0; b < NB; ++b) __builtin_prefetch(src + (x - kAhead - qlo) * st + 16 * b, 1);
    }
    const __m512i vx = _mm512_set1_epi32(static_cast<std::int32_t>(x));
    __mmask16 down[NB];
    bool moved = false;
    for (int b = 0; b < NB; ++b) {
      down[b] = _mm512_mask_cmpgt_epi32_mask(some[b], tt[b], vx);
      moved |= down[b] != 0;
    }
    if (moved) {
      for (int b = 0; b < NB; ++b) {
        below<Packed>(ts[b], tt[b], tf[b], down[b], P[b], B[b], BT[b], BF[b]);
      }
    }
    for (int b = 0; b < NB; ++b) {
      __m512i g = eval16<K>(tf[b], _mm512_sub_epi32(vx, ts[b]), p);
      g = _mm512_mask_mov_epi32(vinf, some[b], g);
      // x's own value, which the envelope lacks where x is a peak
      g = _mm512_maskz_min_epi32(all, g, _mm512_mask_loadu_epi32(vinf, used[b], R[b] + x * rs));
      _mm512_mask_storeu_epi32(src + (x - qlo) * st + 16 * b, used[b], g);
    }
  }
}

// The sites (items 0) of a line of n one-byte items as bits, 64 per word (bit x of word x / 64;
// no bits past n).
inline void site_bits(const std::uint8_t* mk, std::int64_t n, std::uint64_t* bits) {
  const __m128i zero = _mm_setzero_si128();
  const auto sites16 = [&](const std::uint8_t* p) {
    const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
    return static_cast<std::uint64_t>(
        static_cast<std::uint16_t>(_mm_movemask_epi8(_mm_cmpeq_epi8(v, zero))));
  };
  std::int64_t x = 0;
  for (; x + 64 <= n; x += 64) {
    bits[x / 64] = sites16(mk + x) | sites16(mk + x + 16) << 16 | sites16(mk + x + 32) << 32 |
                   sites16(mk + x + 48) << 48;
  }
  if (x < n) {
    std::uint64_t w = 0;
    for (std::int64_t k = x; k < n; ++k) w |= static_cast<std::uint64_t>(mk[k] == 0) << (k - x);
    bits[x / 64] = w;
  }
}

// The first site at or after x (positions from the bits of site_bits), or `none`.
inline std::int64_t next_site(const std::uint64_t* bits, std::int64_t n, std::int64_t x,
                              std::int64_t none) {
  if (x >= n) return none;
  const std::int64_t words = (n + 63) / 64;
  std::int64_t w = x / 64;
  std::uint64_t m = bits[w] & (~std::uint64_t{0} << (x % 64));
  while (m == 0) {
    if (++w >= words) return none;
    m = bits[w];
  }
  return w * 64 + __builtin_ctzll(m);
}

// The mask pass of one line (item 0: site), in one sweep of 16 points at a time: the sites as
// bits first, then each vector's distance to the last site before it and to the first after
// it (both from the bits), and inside a vector with sites a prefix max and a suffix min of the
// site positions. bits: (n + 63) / 64 words of scratch.
template <int K>
__attribute__((target("avx512f"))) void mask_line_avx512(const std::uint8_t* mk, std::int32_t* out,
                                                         std::int64_t n, const std::int32_t* pw,
                                                         std::int32_t inf, std::uint64_t* bits) {
  const __mmask16 all = 0xFFFF;
  const __m512i lane = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
  const auto nn = static_cast<std::int32_t>(n);
  const __m512i none_before = _mm512_set1_epi32(-2 * nn), none_after = _mm512_set1_epi32(3 * nn);
  const __m512i zero = _mm512_setzero_si512();
  site_bits(mk, n, bits);
  std::int64_t after = next_site(bits, n, 0, 3 * n); // the first site at or after x0 + 16
  if (after == 3 * n) {                              // no site on the line
    for (std::int64_t x = 0; x < n; ++x) out[x] = inf;
    return;
  }
  std::int64_t before = -2 * n; // the last site before x0
  for (std::int64_t x0 = 0; x0 < n; x0 += 16) {
    const __mmask16 valid = n - x0 >= 16 ? all : static_cast<__mmask16>((1u << (n - x0)) - 1u);
    const __m512i pos = _mm512_add_epi32(lane, _mm512_set1_epi32(static_cast<std::int32_t>(x0)));
    const auto site = static_cast<__mmask16>(bits[x0 / 64] >> (x0 % 64));
    if (after < x0 + 16) after = next_site(bits, n, x0 + 16, 3 * n);
    const __m512i vb = _mm512_set1_epi32(static_cast<std::int32_t>(before));
    const __m512i va = _mm512_set1_epi32(static_cast<std::int32_t>(after));
    __m512i d;
    if (site == 0) { // (runs of one kind are common: shortcuts for whole vectors)
      d = _mm512_maskz_min_epi32(all, _mm512_sub_epi32(pos, vb), _mm512_sub_epi32(va, pos));
    } else if (site == all) {
      d = zero;
      before = x0 + 15;
    } else {
      __m512i c = _mm512_mask_mov_epi32(none_before, site, pos);
      c = _mm512_maskz_max_epi32(all, c, _mm512_maskz_alignr_epi32(all, c, none_before, 15));
      c = _mm512_maskz_max_epi32(all, c, _mm512_maskz_alignr_epi32(all, c, none_before, 14));
      c = _mm512_maskz_max_epi32(all, c, _mm512_maskz_alignr_epi32(all, c, none_before, 12));
      c = _mm512_maskz_max_epi32(all, c, _mm512_maskz_alignr_epi32(all, c, none_before, 8));
      c = _mm512_maskz_max_epi32(all, c, vb);
      __m512i e = _mm512_mask_mov_epi32(none_after, site, pos);
      e = _mm512_maskz_min_epi32(all, e, _mm512_maskz_alignr_epi32(all, none_after, e, 1));
      e = _mm512_maskz_min_epi32(all, e, _mm512_maskz_alignr_epi32(all, none_after, e, 2));
      e = _mm512_maskz_min_epi32(all, e, _mm512_maskz_alignr_epi32(all, none_after, e, 4));
      e = _mm512_maskz_min_epi32(all, e, _mm512_maskz_alignr_epi32(all, none_after, e, 8));
      e = _mm512_maskz_min_epi32(all, e, va);
      d = _mm512_maskz_min_epi32(all, _mm512_sub_epi32(pos, c), _mm512_sub_epi32(e, pos));
      before = x0 + 31 - __builtin_clz(static_cast<unsigned>(site));
    }
    __m512i g = d;
    if constexpr (K == kL2) {
      g = _mm512_mullo_epi32(d, d);
    } else if constexpr (K == kLp) {
      g = _mm512_mask_i32gather_epi32(zero, valid, d, pw, 4);
    }
    _mm512_mask_storeu_epi32(out + x0, valid, g);
  }
}

bool envelope_avx512_supported() {
  static const bool ok = __builtin_cpu_supports("avx512f");
  return ok;
}

// ---- The int64 engine in 8 lanes (AVX-512F and DQ) -------------------------------------------
//
// The same sweep as envelope_block_avx512, one line per 64-bit lane (8 adjacent lines: a row of a
// block is one 64-byte cache line), for the values past the int32 engine (need >= 2^31: l3 on
// lines of 1,000 or more points, l2 on volumes past about 30,000 a side, weights past 2^30).
// Every value and every intermediate below is an int64 bounded by `need` (separable_engine.hpp)
// as in the scalar loop, except the floating-point guesses, which only choose where the exact
// tests look:
// - l1 and linf: their closed forms (an arithmetic shift is the floor of a halving);
// - l2 and l_p: the last t in [t_top, end) where the top still wins, found by exact integer
//   tests g_u(t) < g_s(t) in every lane (the predicate is monotone in t): a guess (for l2 the
//   quotient ((u - s)(u + s) + f_u - f_s) / (2 (u - s)) in double, right or one off; for l3 the
//   closed-form root as in separator16; else the midpoint), two tests at the guess and the next
//   point, a gallop from there, then bisection. The answer is the scalar sep's, exactly.
// The stack tables: one 64-bit entry per row and lane for the element below (site + 1 in the
// high half, segment start in the low half: lines under 2^30 points) and one for its value.
// Positions and differences of positions fit 32 bits, so |t - s|^2 is one signed 32 x 32 -> 64
// product (vpmuldq); higher powers multiply in 64 bits (vpmullq, AVX-512DQ).

// (the maskz_ forms with every lane: GCC 12's plain forms warn -Wmaybe-uninitialized)
constexpr __mmask8 kAll8 = 0xFF;

template <int K>
__attribute__((target("avx512f,avx512dq"), always_inline)) inline __m512i eval8(__m512i f,
                                                                                __m512i dx, int p) {
  if constexpr (K == kL2) {
    (void)p;
    return _mm512_add_epi64(f, _mm512_maskz_mul_epi32(kAll8, dx, dx));
  } else {
    const __m512i a = _mm512_maskz_abs_epi64(kAll8, dx);
    if constexpr (K == kL1) {
      (void)p;
      return _mm512_add_epi64(f, a);
    } else if constexpr (K == kLinf) {
      (void)p;
      return _mm512_maskz_max_epi64(kAll8, f, a);
    } else {
      __m512i r = _mm512_maskz_mul_epi32(kAll8, a, a);
      for (int k = 2; k < p; ++k) r = _mm512_maskz_mullo_epi64(kAll8, r, a);
      return _mm512_add_epi64(f, r);
    }
  }
}

// The lanes where u is strictly below the top at y (g_u(y) < g_s(y)).
template <int K>
__attribute__((target("avx512f,avx512dq"), always_inline)) inline __mmask8
u_wins8(__m512i y, __m512i vu, __m512i fu, __m512i ts, __m512i tf, int p) {
  return _mm512_cmplt_epi64_mask(eval8<K>(fu, _mm512_sub_epi64(y, vu), p),
                                 eval8<K>(tf, _mm512_sub_epi64(y, ts), p));
}

// The separator of the tops (ts, tt, tf) and u (fu) in the lanes of `full` (see above): for l1
// and linf before the clamp to [t_top, end - 1] (`far`: lanes where u never wins), for l2 and
// l_p the clamped one.
template <int K>
__attribute__((target("avx512f,avx512dq"), always_inline)) inline __m512i
separator8(__m512i vu, __m512i fu, __m512i ts, __m512i tt, __m512i tf, __m512i vhi, int p,
           __mmask8 full, __mmask8& far) {
  const __m512i one = _mm512_set1_epi64(1);
  far = 0;
  if constexpr (K == kL1) {
    (void)tt;
    (void)vhi;
    (void)p;
    const __m512i df = _mm512_sub_epi64(fu, tf);
    far = full & _mm512_cmpge_epi64_mask(df, _mm512_sub_epi64(vu, ts));
    return _mm512_maskz_srai_epi64(kAll8, _mm512_add_epi64(df, _mm512_add_epi64(vu, ts)), 1);
  } else if constexpr (K == kLinf) {
    (void)tt;
    (void)vhi;
    (void)p;
    (void)full;
    const __m512i mid = _mm512_maskz_srai_epi64(kAll8, _mm512_add_epi64(vu, ts), 1);
    const __mmask8 le = _mm512_cmple_epi64_mask(tf, fu);
    const __m512i a_le = _mm512_add_epi64(ts, fu), a_gt = _mm512_sub_epi64(vu, tf);
    return _mm512_mask_mov_epi64(_mm512_maskz_min_epi64(kAll8, a_gt, mid), le,
                                 _mm512_maskz_max_epi64(kAll8, a_le, mid));
  } else if constexpr (K == kL2) {
    (void)p;
    // clamp(floor(num / den), t_top, end - 1), num = (u - s)(u + s) + f_u - f_s, den = 2 (u - s):
    // the quotient in double is a guess q (clamped to the segment first, so that q den fits),
    // then the exact remainder num - q den moves q down while it is negative (the top wins at
    // t_top: num >= t_top den, so q stays >= t_top) and up while it is >= den (up to end - 1).
    const __m512i diff = _mm512_sub_epi64(vu, ts), den = _mm512_add_epi64(diff, diff);
    const __m512i num = _mm512_add_epi64(
        _mm512_maskz_mul_epi32(kAll8, diff, _mm512_add_epi64(vu, ts)), _mm512_sub_epi64(fu, tf));
    const __m512d q =
        _mm512_div_pd(_mm512_maskz_cvtepi64_pd(kAll8, num), _mm512_maskz_cvtepi64_pd(kAll8, den));
    const __m512d lo = _mm512_maskz_cvtepi64_pd(kAll8, tt);
    const __m512d hi = _mm512_maskz_cvtepi64_pd(kAll8, _mm512_sub_epi64(vhi, one));
    __m512i x = _mm512_maskz_cvt_roundpd_epi64(
        kAll8, _mm512_maskz_min_pd(kAll8, _mm512_maskz_max_pd(kAll8, q, lo), hi),
        _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
    const __m512i last = _mm512_sub_epi64(vhi, one);
    __m512i rem = _mm512_sub_epi64(num, _mm512_maskz_mul_epi32(kAll8, x, den));
    for (;;) {
      const __mmask8 down = full & _mm512_cmplt_epi64_mask(rem, _mm512_setzero_si512());
      const __mmask8 up =
          full & _mm512_cmpge_epi64_mask(rem, den) & _mm512_cmplt_epi64_mask(x, last);
      if ((down | up) == 0) break;
      x = _mm512_mask_sub_epi64(x, down, x, one);
      rem = _mm512_mask_add_epi64(rem, down, rem, den);
      x = _mm512_mask_add_epi64(x, up, x, one);
      rem = _mm512_mask_sub_epi64(rem, up, rem, den);
    }
    return x;
  } else {
    __m512i x0 = _mm512_maskz_srai_epi64(kAll8, _mm512_add_epi64(ts, vu), 1);
    const __m512d dd = _mm512_maskz_cvtepi64_pd(kAll8, _mm512_sub_epi64(vu, ts));
    const __m512d cc = _mm512_maskz_cvtepi64_pd(kAll8, _mm512_sub_epi64(fu, tf));
    if (p == 3) {
      // the root of c + |t - u|^3 - |t - s|^3 outside [s, u] (separator16), in double
      const __m512d d3 = _mm512_mul_pd(_mm512_mul_pd(dd, dd), dd);
      const __m512d ac = _mm512_abs_pd(cc);
      const __m512d disc = _mm512_sub_pd(_mm512_div_pd(_mm512_mul_pd(_mm512_set1_pd(12.0), ac), dd),
                                         _mm512_mul_pd(_mm512_set1_pd(3.0), _mm512_mul_pd(dd, dd)));
      const __m512d a = _mm512_mul_pd(
          _mm512_sub_pd(
              _mm512_maskz_sqrt_pd(kAll8, _mm512_maskz_max_pd(kAll8, disc, _mm512_setzero_pd())),
              _mm512_mul_pd(_mm512_set1_pd(3.0), dd)),
          _mm512_set1_pd(1.0 / 6.0));
      const __m512i ai = _mm512_maskz_cvt_roundpd_epi64(
          kAll8, _mm512_maskz_min_pd(kAll8, a, _mm512_set1_pd(4.0e18)),
          _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
      const __mmask8 right = _mm512_cmp_pd_mask(cc, d3, _CMP_GE_OQ);
      const __mmask8 left =
          _mm512_cmp_pd_mask(cc, _mm512_sub_pd(_mm512_setzero_pd(), d3), _CMP_LE_OQ);
      x0 = _mm512_mask_mov_epi64(x0, right, _mm512_add_epi64(vu, ai));
      x0 = _mm512_mask_mov_epi64(x0, left, _mm512_sub_epi64(_mm512_sub_epi64(ts, ai), one));
    }
    x0 = _mm512_maskz_min_epi64(kAll8, _mm512_maskz_max_epi64(kAll8, x0, tt),
                                _mm512_sub_epi64(vhi, one));
    const __m512i x1 = _mm512_add_epi64(x0, one);
    const __mmask8 top0 = full & static_cast<__mmask8>(~u_wins8<K>(x0, vu, fu, ts, tf, p));
    const __mmask8 in1 = _mm512_cmplt_epi64_mask(x1, vhi);
    const __mmask8 top1 = in1 & static_cast<__mmask8>(~u_wins8<K>(x1, vu, fu, ts, tf, p));
    __m512i lo = _mm512_mask_mov_epi64(tt, top0, x0);
    lo = _mm512_mask_mov_epi64(lo, top0 & top1, x1);
    __m512i hi = _mm512_mask_mov_epi64(vhi, full & static_cast<__mmask8>(~top0), x0);
    hi = _mm512_mask_mov_epi64(hi, top0 & in1 & static_cast<__mmask8>(~top1), x1);
    __mmask8 up = top0 & top1, down = full & static_cast<__mmask8>(~top0);
    for (__m512i step = one; up != 0; step = _mm512_add_epi64(step, step)) {
      const __m512i y = _mm512_add_epi64(lo, step);
      const __mmask8 test = up & _mm512_cmplt_epi64_mask(y, vhi);
      const __mmask8 tw = test & static_cast<__mmask8>(~u_wins8<K>(y, vu, fu, ts, tf, p));
      lo = _mm512_mask_mov_epi64(lo, tw, y);
      hi = _mm512_mask_mov_epi64(hi, test & static_cast<__mmask8>(~tw), y);
      up = tw;
    }
    for (__m512i step = one; down != 0; step = _mm512_add_epi64(step, step)) {
      const __m512i y = _mm512_sub_epi64(hi, step);
      const __mmask8 test = down & _mm512_cmpgt_epi64_mask(y, tt);
      const __mmask8 tw = test & static_cast<__mmask8>(~u_wins8<K>(y, vu, fu, ts, tf, p));
      lo = _mm512_mask_mov_epi64(lo, tw, y);
      hi = _mm512_mask_mov_epi64(hi, test & static_cast<__mmask8>(~tw), y);
      down = test & static_cast<__mmask8>(~tw);
    }
    for (;;) {
      const __mmask8 open = full & _mm512_cmpgt_epi64_mask(_mm512_sub_epi64(hi, lo), one);
      if (open == 0) break;
      const __m512i mid =
          _mm512_add_epi64(lo, _mm512_maskz_srai_epi64(kAll8, _mm512_sub_epi64(hi, lo), 1));
      const __mmask8 uw = open & u_wins8<K>(mid, vu, fu, ts, tf, p);
      hi = _mm512_mask_mov_epi64(hi, uw, mid);
      lo = _mm512_mask_mov_epi64(lo, open & static_cast<__mmask8>(~uw), mid);
    }
    return lo;
  }
}

// Pops the lanes of `go`: the element below the top, from row ts of the tables (P: site + 1 and
// segment start, BF: value).
__attribute__((target("avx512f,avx512dq"), always_inline)) inline void
below8(__m512i& ts, __m512i& tt, __m512i& tf, __mmask8 go, const std::int64_t* P,
       const std::int64_t* BF) {
  const __m512i lane = _mm512_setr_epi64(0, 1, 2, 3, 4, 5, 6, 7);
  const __m512i at = _mm512_add_epi64(_mm512_maskz_slli_epi64(kAll8, ts, 3), lane);
  const __m512i pk = _mm512_mask_i64gather_epi64(_mm512_setzero_si512(), go, at, P, 8);
  tf = _mm512_mask_i64gather_epi64(tf, go, at, BF, 8);
  ts = _mm512_mask_sub_epi64(ts, go, _mm512_maskz_srli_epi64(kAll8, pk, 32), _mm512_set1_epi64(1));
  tt = _mm512_mask_and_epi64(tt, go, pk, _mm512_set1_epi64(0xFFFFFFFFLL));
}

// The envelopes of NB blocks of 8 adjacent lines in int64 (envelope_block_avx512's sweep, peaks
// left out as there). src: the first block's first value, rows st values apart, bw lanes used in
// all; written in place. tables: 3 NB len 8 int64, 64-byte aligned.
template <int K, int NB>
__attribute__((target("avx512f,avx512dq"))) void
envelope_block8(std::int64_t* src, std::int64_t st, int bw, std::int64_t n, bool periodic,
                std::int64_t inf, int p, std::int64_t* tables) {
  const std::int64_t len = periodic ? 3 * n : n, qlo = periodic ? n : 0, qhi = qlo + n;
  const __m512i vinf = _mm512_set1_epi64(inf), zero = _mm512_setzero_si512();
  const __m512i one = _mm512_set1_epi64(1);
  __mmask8 used[NB];
  std::int64_t *F[NB], *P[NB], *BF[NB];
  for (int b = 0; b < NB; ++b) {
    const int w = std::clamp(bw - 8 * b, 0, 8);
    used[b] = static_cast<__mmask8>((1u << w) - 1u);
    F[b] = tables + 3 * b * len * 8;
    P[b] = F[b] + len * 8;
    BF[b] = P[b] + len * 8;
  }
  constexpr std::int64_t kAhead = 16;
  const bool ahead = st > 8 * NB;
  const std::int64_t* R[NB];
  const std::int64_t rs = periodic ? 8 : st;
  for (int b = 0; b < NB; ++b) R[b] = periodic ? F[b] : src + 8 * b;
  if (periodic) {
    for (std::int64_t x = 0; x < n; ++x) {
      for (int b = 0; b < NB; ++b) {
        const __m512i row = _mm512_mask_loadu_epi64(vinf, used[b], src + x * st + 8 * b);
        _mm512_store_si512(F[b] + x * 8, row);
        _mm512_store_si512(F[b] + (n + x) * 8, row);
        _mm512_store_si512(F[b] + (2 * n + x) * 8, row);
      }
    }
  }
  __m512i ts[NB], tt[NB], tf[NB];
  for (int b = 0; b < NB; ++b) {
    ts[b] = _mm512_set1_epi64(-1);
    tt[b] = zero;
    tf[b] = zero;
  }
  const __m512i vhi = _mm512_set1_epi64(qhi), vhi1 = _mm512_set1_epi64(qhi - 1);
  const __m512i vqlo = _mm512_set1_epi64(qlo);
  __m512i prev[NB], cur[NB];
  for (int b = 0; b < NB; ++b) {
    prev[b] = vinf;
    cur[b] = _mm512_mask_loadu_epi64(vinf, used[b], R[b]);
  }
  for (std::int64_t u = 0; u < len; ++u) {
    const __m512i vu = _mm512_set1_epi64(u);
    __m512i fu[NB];
    __mmask8 active[NB], pop[NB];
    bool any = false;
    if (!periodic && ahead && u + kAhead < n) {
      for (int b = 0; b < NB; ++b) __builtin_prefetch(src + (u + kAhead) * st + 8 * b);
    }
    for (int b = 0; b < NB; ++b) {
      // rows u - 1, u, u + 1 of the block kept in registers: one load per row
      fu[b] = cur[b];
      const __m512i after =
          u + 1 < len ? _mm512_mask_loadu_epi64(vinf, used[b], R[b] + (u + 1) * rs) : vinf;
      active[b] = _mm512_cmpneq_epi64_mask(fu[b], vinf);
      if (u > 0 && u + 1 < len) {
        const __mmask8 peak =
            _mm512_cmpge_epi64_mask(fu[b], prev[b]) & _mm512_cmpge_epi64_mask(fu[b], after);
        active[b] &= static_cast<__mmask8>(~peak);
      }
      prev[b] = cur[b];
      cur[b] = after;
      any |= active[b] != 0;
    }
    if (!any) continue;
    for (;;) {
      bool popped = false;
      for (int b = 0; b < NB; ++b) {
        const __mmask8 cand = active[b] & _mm512_cmpge_epi64_mask(ts[b], zero);
        const __m512i gtop = eval8<K>(tf[b], _mm512_sub_epi64(tt[b], ts[b]), p);
        const __m512i gu = eval8<K>(fu[b], _mm512_sub_epi64(tt[b], vu), p);
        pop[b] = _mm512_mask_cmpgt_epi64_mask(cand, gtop, gu);
        popped |= pop[b] != 0;
      }
      if (!popped) break;
      for (int b = 0; b < NB; ++b) below8(ts[b], tt[b], tf[b], pop[b], P[b], BF[b]);
    }
    for (int b = 0; b < NB; ++b) {
      if (active[b] == 0) continue;
      const __mmask8 empty = active[b] & _mm512_cmplt_epi64_mask(ts[b], zero);
      const __mmask8 full = active[b] & static_cast<__mmask8>(~empty);
      __m512i w = vqlo;
      __mmask8 push = empty;
      if (full != 0) {
        __mmask8 far = 0;
        __m512i r = separator8<K>(vu, fu[b], ts[b], tt[b], tf[b], vhi, p, full, far);
        if constexpr (K == kL1 || K == kLinf) {
          r = _mm512_maskz_min_epi64(kAll8, _mm512_maskz_max_epi64(kAll8, r, tt[b]), vhi1);
          r = _mm512_mask_mov_epi64(r, far, vhi1);
        }
        push |= full & _mm512_cmplt_epi64_mask(r, vhi1);
        w = _mm512_mask_mov_epi64(w, full, _mm512_add_epi64(r, one));
      }
      if (push == 0) continue;
      const __m512i pk =
          _mm512_or_si512(_mm512_maskz_slli_epi64(kAll8, _mm512_add_epi64(ts[b], one), 32),
                          _mm512_and_si512(tt[b], _mm512_set1_epi64(0xFFFFFFFFLL)));
      _mm512_store_si512(P[b] + u * 8, pk);
      _mm512_store_si512(BF[b] + u * 8, tf[b]);
      ts[b] = _mm512_mask_mov_epi64(ts[b], push, vu);
      tt[b] = _mm512_mask_mov_epi64(tt[b], push, w);
      tf[b] = _mm512_mask_mov_epi64(tf[b], push, fu[b]);
    }
  }
  __mmask8 some[NB];
  for (int b = 0; b < NB; ++b) some[b] = _mm512_cmpge_epi64_mask(ts[b], zero);
  for (std::int64_t x = qhi; x-- > qlo;) {
    if (ahead && x - kAhead >= qlo) {
      for (int b = 0; b < NB; ++b) __builtin_prefetch(src + (x - kAhead - qlo) * st + 8 * b, 1);
    }
    const __m512i vx = _mm512_set1_epi64(x);
    __mmask8 down[NB];
    bool moved = false;
    for (int b = 0; b < NB; ++b) {
      down[b] = _mm512_mask_cmpgt_epi64_mask(some[b], tt[b], vx);
      moved |= down[b] != 0;
    }
    if (moved) {
      for (int b = 0; b < NB; ++b) below8(ts[b], tt[b], tf[b], down[b], P[b], BF[b]);
    }
    for (int b = 0; b < NB; ++b) {
      __m512i g = eval8<K>(tf[b], _mm512_sub_epi64(vx, ts[b]), p);
      g = _mm512_mask_mov_epi64(vinf, some[b], g);
      g = _mm512_maskz_min_epi64(kAll8, g, _mm512_mask_loadu_epi64(vinf, used[b], R[b] + x * rs));
      _mm512_mask_storeu_epi64(src + (x - qlo) * st + 8 * b, used[b], g);
    }
  }
}

// The mask pass of one line into int64: the distances to the sites by mask_line_avx512<kL1>
// (int32, lines under 2^28 points), then their metric lengths in 64 bits. d: n int32 of scratch,
// rounded up to a multiple of 8.
template <int K>
__attribute__((target("avx512f,avx512dq"))) void
mask_line8(const std::uint8_t* mk, std::int64_t* out, std::int64_t n, int p, std::int64_t inf,
           std::int32_t* d, std::uint64_t* bits) {
  constexpr std::int32_t kNone = std::numeric_limits<std::int32_t>::max();
  mask_line_avx512<kL1>(mk, d, n, nullptr, kNone, bits);
  const __m512i vnone = _mm512_set1_epi64(kNone), vinf = _mm512_set1_epi64(inf);
  for (std::int64_t x = 0; x < n; x += 8) {
    const __mmask8 valid =
        n - x >= 8 ? static_cast<__mmask8>(0xFF) : static_cast<__mmask8>((1u << (n - x)) - 1u);
    const __m512i dx = _mm512_maskz_cvtepi32_epi64(
        kAll8, _mm256_loadu_si256(reinterpret_cast<const __m256i*>(d + x)));
    __m512i g = eval8<K>(_mm512_setzero_si512(), dx, p); // (linf: max(0, d) = d)
    g = _mm512_mask_mov_epi64(g, _mm512_cmpeq_epi64_mask(dx, vnone), vinf);
    _mm512_mask_storeu_epi64(out + x, valid, g);
  }
}

// The largest finite value (values >= 0, inf excluded) of n rows of w values, `stride` apart,
// in 16 or 8 lanes (envelope_pass's max_value, on a unit of lines just written, in cache).
__attribute__((target("avx512f"))) std::uint64_t rows_max_avx512(const std::int32_t* at,
                                                                 std::int64_t stride,
                                                                 std::int64_t w, std::int64_t n,
                                                                 std::int32_t inf) {
  const __m512i vinf = _mm512_set1_epi32(inf);
  __m512i acc = _mm512_setzero_si512();
  for (std::int64_t x = 0; x < n; ++x) {
    const std::int32_t* row = at + x * stride;
    for (std::int64_t b = 0; b < w; b += 16) {
      const __mmask16 in = w - b >= 16 ? static_cast<__mmask16>(0xFFFF)
                                       : static_cast<__mmask16>((1u << (w - b)) - 1u);
      const __m512i v = _mm512_maskz_loadu_epi32(in, row + b);
      acc = _mm512_mask_max_epi32(acc, _mm512_mask_cmpneq_epi32_mask(in, v, vinf), acc, v);
    }
  }
  alignas(64) std::int32_t lanes[16];
  _mm512_store_si512(lanes, acc);
  return static_cast<std::uint64_t>(*std::max_element(lanes, lanes + 16));
}

__attribute__((target("avx512f"))) std::uint64_t rows_max_avx512(const std::int64_t* at,
                                                                 std::int64_t stride,
                                                                 std::int64_t w, std::int64_t n,
                                                                 std::int64_t inf) {
  const __m512i vinf = _mm512_set1_epi64(inf);
  __m512i acc = _mm512_setzero_si512();
  for (std::int64_t x = 0; x < n; ++x) {
    const std::int64_t* row = at + x * stride;
    for (std::int64_t b = 0; b < w; b += 8) {
      const __mmask8 in =
          w - b >= 8 ? static_cast<__mmask8>(0xFF) : static_cast<__mmask8>((1u << (w - b)) - 1u);
      const __m512i v = _mm512_maskz_loadu_epi64(in, row + b);
      acc = _mm512_mask_max_epi64(acc, _mm512_mask_cmpneq_epi64_mask(in, v, vinf), acc, v);
    }
  }
  alignas(64) std::int64_t lanes[8];
  _mm512_store_si512(lanes, acc);
  return static_cast<std::uint64_t>(*std::max_element(lanes, lanes + 8));
}

bool envelope_avx512dq_supported() {
  static const bool ok = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq");
  return ok;
}
#endif

std::atomic<bool> g_envelope_simd{true};

#if defined(ZDG_ENVELOPE_AVX512)
// The vectorized passes run: allowed (set_envelope_simd) and offered by the CPU.
bool use_simd() {
  return g_envelope_simd.load(std::memory_order_relaxed) && envelope_avx512_supported();
}

// The vectorized mask pass takes the lines: one-byte items, no torus along them, no sites.
bool simd_mask_lines(int item, bool periodic, const std::vector<std::int64_t>* sites,
                     std::int64_t n) {
  return item == 1 && !periodic && sites == nullptr && n < (std::int64_t{1} << 28) && use_simd();
}

// The int64 engine's vectorized passes run: allowed, offered by the CPU (AVX-512F and DQ), and
// lines (of len points, 3 n on a torus) under 2^30 points: positions fit the 32-bit halves of
// the stack entries and of the products.
bool use_simd64(std::int64_t len) {
  return g_envelope_simd.load(std::memory_order_relaxed) && envelope_avx512dq_supported() &&
         len < (std::int64_t{1} << 30);
}

// The vectorized int64 mask pass takes the same lines.
bool simd_mask_lines64(int item, bool periodic, const std::vector<std::int64_t>* sites,
                       std::int64_t n) {
  return item == 1 && !periodic && sites == nullptr && n < (std::int64_t{1} << 28) && use_simd64(n);
}

// The mask pass of lines [begin, end) of n points (vectorized).
template <int K>
void mask_lines_avx512(const std::uint8_t* mask, std::int32_t* f, std::int64_t n,
                       std::int64_t begin, std::int64_t end, const LineMetric<K, std::int32_t>& m,
                       std::int32_t inf) {
  std::vector<std::uint64_t> bits(static_cast<std::size_t>((n + 63) / 64));
  for (std::int64_t line = begin; line < end; ++line) {
    mask_line_avx512<K>(mask + line * n, f + line * n, n, m.pw, inf, bits.data());
  }
}
#endif

#if defined(ZDG_ENVELOPE_AVX512)
// The mask pass of lines [begin, end) of n points into int64 (vectorized).
template <int K>
void mask_lines8(const std::uint8_t* mask, std::int64_t* f, std::int64_t n, std::int64_t begin,
                 std::int64_t end, int p, std::int64_t inf) {
  std::vector<std::uint64_t> bits(static_cast<std::size_t>((n + 63) / 64));
  std::vector<std::int32_t> d(static_cast<std::size_t>((n + 7) / 8 * 8));
  for (std::int64_t line = begin; line < end; ++line) {
    mask_line8<K>(mask + line * n, f + line * n, n, p, inf, d.data(), bits.data());
  }
}

constexpr int kSimdBlocks8 = 4; // blocks of 8 lines advancing together (int64)

// Scratch of envelope_columns8 for lines of len points (64-byte aligned).
struct SimdTables8 {
  std::vector<std::int64_t> buf;
  std::int64_t* get(std::int64_t len) {
    const auto need = static_cast<std::size_t>(3 * kSimdBlocks8 * len * 8 + 8);
    if (buf.size() < need) buf.assign(need, 0);
    std::int64_t* q = buf.data();
    return q + (8 - (reinterpret_cast<std::uintptr_t>(q) / 8) % 8) % 8;
  }
};

// The envelopes of the columns [0, cw) of lines of n points starting at base, rows `stride`
// apart, in int64: units of kSimdBlocks8 blocks of 8 columns starting on 64-byte boundaries (a
// narrower first block up to the first boundary), as envelope_columns_avx512.
template <int K>
void envelope_columns8(std::int64_t* base, std::int64_t stride, std::int64_t cw, std::int64_t n,
                       bool periodic, std::int64_t inf, int p, std::int64_t* tables) {
  constexpr std::int64_t kWide = 8 * kSimdBlocks8;
  const auto addr = reinterpret_cast<std::uintptr_t>(base) / sizeof(std::int64_t);
  const std::int64_t lead = std::min<std::int64_t>(cw, (8 - addr % 8) % 8);
  if (lead > 0)
    envelope_block8<K, 1>(base, stride, static_cast<int>(lead), n, periodic, inf, p, tables);
  for (std::int64_t j0 = lead; j0 < cw; j0 += kWide) {
    const std::int64_t bw = std::min(kWide, cw - j0);
    std::int64_t* at = base + j0;
    const int w = static_cast<int>(bw);
    if (bw <= 8) {
      envelope_block8<K, 1>(at, stride, w, n, periodic, inf, p, tables);
    } else if (bw <= 16) {
      envelope_block8<K, 2>(at, stride, w, n, periodic, inf, p, tables);
    } else {
      envelope_block8<K, kSimdBlocks8>(at, stride, w, n, periodic, inf, p, tables);
    }
  }
}

// The mask pass and the envelope pass of axis d - 2 fused slice by slice, in int64 (as
// fused_mask_pass_avx512).
template <int K>
void fused_mask_pass8(const Domain& dom, bool periodic_columns, int p, const std::uint8_t* mask,
                      std::int64_t* f, std::int64_t inf, unsigned threads) {
  const int d = dom.dim();
  const std::int64_t n = dom.extent(d - 1), rows = dom.extent(d - 2);
  const std::int64_t slices = dom.size() / (n * rows);
  const std::int64_t len = periodic_columns ? 3 * rows : rows;
  parallel_chunks(slices, threads, [&](std::int64_t begin, std::int64_t end) {
    SimdTables8 tables;
    for (std::int64_t o = begin; o < end; ++o) {
      mask_lines8<K>(mask, f, n, o * rows, (o + 1) * rows, p, inf);
      envelope_columns8<K>(f + o * rows * n, n, n, rows, periodic_columns, inf, p, tables.get(len));
    }
  });
}

constexpr int kSimdBlocks = 4; // blocks of 16 lines advancing together

// Scratch of envelope_columns_avx512 for lines of len points (64-byte aligned).
struct SimdTables {
  std::vector<std::int32_t> buf;
  std::int32_t* get(std::int64_t len) {
    const auto need = static_cast<std::size_t>(4 * kSimdBlocks * len * 16 + 16);
    if (buf.size() < need) buf.assign(need, 0);
    std::int32_t* q = buf.data();
    return q + (16 - (reinterpret_cast<std::uintptr_t>(q) / 4) % 16) % 16;
  }
};

template <int K, int NB>
void envelope_block_dispatch(std::int32_t* at, std::int64_t stride, std::int64_t w, std::int64_t n,
                             bool periodic, std::int32_t inf, int p, std::int32_t* tables) {
  // Sites and segment starts fit 16 bits on lines under 2^15 points (always for p >= 2 on
  // the int32 engine: L^p < 2^30), so a pop gathers one table of 64-bit entries instead of
  // three of 32-bit ones.
  if ((periodic ? 3 * n : n) < (std::int64_t{1} << 15)) {
    envelope_block_avx512<K, NB, true>(at, stride, static_cast<int>(w), n, periodic, inf, p,
                                       tables);
  } else {
    envelope_block_avx512<K, NB, false>(at, stride, static_cast<int>(w), n, periodic, inf, p,
                                        tables);
  }
}

// The envelopes of the columns [0, cw) of lines of n points starting at base, rows `stride`
// apart: units of kSimdBlocks blocks of 16 columns starting on 64-byte boundaries (a narrower
// first block up to the first boundary): a row of a block is then one cache line, not two,
// when the stride is a multiple of 16.
template <int K>
void envelope_columns_avx512(std::int32_t* base, std::int64_t stride, std::int64_t cw,
                             std::int64_t n, bool periodic, std::int32_t inf, int p,
                             std::int32_t* tables) {
  constexpr std::int64_t kWide = 16 * kSimdBlocks;
  const auto addr = reinterpret_cast<std::uintptr_t>(base) / sizeof(std::int32_t);
  const std::int64_t lead = std::min<std::int64_t>(cw, (16 - addr % 16) % 16);
  if (lead > 0) {
    envelope_block_dispatch<K, 1>(base, stride, lead, n, periodic, inf, p, tables);
  }
  for (std::int64_t j0 = lead; j0 < cw; j0 += kWide) {
    const std::int64_t bw = std::min(kWide, cw - j0);
    std::int32_t* at = base + j0;
    if (bw <= 16) {
      envelope_block_dispatch<K, 1>(at, stride, bw, n, periodic, inf, p, tables);
    } else if (bw <= 32) {
      envelope_block_dispatch<K, 2>(at, stride, bw, n, periodic, inf, p, tables);
    } else {
      envelope_block_dispatch<K, kSimdBlocks>(at, stride, bw, n, periodic, inf, p, tables);
    }
  }
}

// The mask pass and the envelope pass of the next axis (d - 2) fused, slice by slice: a slice
// of the last two axes is transformed along its lines, then along its columns while it is
// still in cache, instead of two passes over the whole volume through memory. Each line sees
// the operations of the two passes in the same order: the same values.
template <int K>
void fused_mask_pass_avx512(const Domain& dom, bool periodic_columns,
                            const LineMetric<K, std::int32_t>& m, const std::uint8_t* mask,
                            std::int32_t* f, std::int32_t inf, unsigned threads) {
  const int d = dom.dim();
  const std::int64_t n = dom.extent(d - 1), rows = dom.extent(d - 2);
  const std::int64_t slices = dom.size() / (n * rows);
  const std::int64_t len = periodic_columns ? 3 * rows : rows;
  parallel_chunks(slices, threads, [&](std::int64_t begin, std::int64_t end) {
    SimdTables tables;
    for (std::int64_t o = begin; o < end; ++o) {
      mask_lines_avx512<K>(mask, f, n, o * rows, (o + 1) * rows, m, inf);
      envelope_columns_avx512<K>(f + o * rows * n, n, n, rows, periodic_columns, inf, m.p,
                                 tables.get(len));
    }
  });
}

// The int64 engine's first two passes in int32 where their values allow it (issue #40 item 4):
// after the mask pass and the pass along axis d - 2, every value is the 2D transform of its
// slice, bounded by the slice's own bounds (envelope_bounds on the slice's two axes: m_{d-1}^p
// + m_{d-2}^p, intermediates below 2 (that + L^p) + 2 L); when those fit the int32 engine, a
// slice is transformed by the int32 vectorized passes (fused_mask_pass_avx512's) in a scratch
// slice, then widened into f (inf to inf), the same integers as the int64 passes. The last
// passes run in int64. For a 3D l3 on 672^3 (int64 engine: the full bound is 2.4e9) the slices'
// bound is 1.8e9: two of the three passes move and compute half the bytes.
template <int K>
void fused_mask_pass_narrow(const Domain& dom, bool periodic_columns,
                            const LineMetric<K, std::int32_t>& m, const std::uint8_t* mask,
                            std::int64_t* f, std::int64_t inf, unsigned threads) {
  const int d = dom.dim();
  const std::int64_t n = dom.extent(d - 1), rows = dom.extent(d - 2);
  const std::int64_t slices = dom.size() / (n * rows);
  const std::int64_t len = periodic_columns ? 3 * rows : rows;
  constexpr std::int32_t inf32 = std::numeric_limits<std::int32_t>::max();
  parallel_chunks(slices, threads, [&](std::int64_t begin, std::int64_t end) {
    SimdTables tables;
    std::vector<std::int32_t> slice(static_cast<std::size_t>(rows * n));
    for (std::int64_t o = begin; o < end; ++o) {
      // (the slice at f's rows, so that the int32 passes see the same mask lines)
      mask_lines_avx512<K>(mask + o * rows * n, slice.data(), n, 0, rows, m, inf32);
      envelope_columns_avx512<K>(slice.data(), n, n, rows, periodic_columns, inf32, m.p,
                                 tables.get(len));
      std::int64_t* out = f + o * rows * n;
      for (std::int64_t i = 0; i < rows * n; ++i) {
        const std::int32_t v = slice[static_cast<std::size_t>(i)];
        out[i] = v == inf32 ? inf : v;
      }
    }
  });
}
#endif

template <class V>
struct Scratch {
  std::vector<V> buf, fs;
  std::vector<std::int64_t> sbuf, arg, s, t;
};

// One pass along axis a: every line of that axis becomes the lower envelope of its values.
// The lines are those of the columns j in [jb, je) of each block of st = stride(a) values (all
// of them by default; a part for the out-of-core transform,
// kernel/transforms/out_of_core_transform.hpp).
template <int K, class V>
void envelope_pass(const Domain& dom, int a, bool periodic, bool nonnegative,
                   const LineMetric<K, V>& m, V* f, const V& inf, std::vector<std::int64_t>* sites,
                   unsigned threads, std::int64_t jb = 0, std::int64_t je = -1,
                   std::uint64_t* max_out = nullptr) {
  const std::int64_t n = dom.extent(a), st = dom.stride(a);
  // max_out (int32 and int64 values >= 0): the largest finite value the pass writes, taken from
  // each unit of lines right after its envelopes, while the unit is still in cache.
  std::mutex max_lock;
  const auto unit_max = [&](const V* at, std::int64_t stride, std::int64_t w, std::uint64_t& mx) {
    if constexpr (std::is_integral_v<V>) {
#if defined(ZDG_ENVELOPE_AVX512)
      if constexpr (std::is_same_v<V, std::int32_t> || std::is_same_v<V, std::int64_t>) {
        if (envelope_avx512_supported()) {
          mx = std::max(mx, rows_max_avx512(at, stride, w, n, inf));
          return;
        }
      }
#endif
      V top = 0;
      for (std::int64_t x = 0; x < n; ++x) {
        const V* row = at + x * stride;
        for (std::int64_t b = 0; b < w; ++b) {
          const V v = row[b];
          top = v != inf && v > top ? v : top;
        }
      }
      mx = std::max(mx, static_cast<std::uint64_t>(top));
    } else {
      (void)at;
      (void)stride;
      (void)w;
      (void)mx;
    }
  };
  const auto merge_max = [&](std::uint64_t mx) {
    const std::lock_guard<std::mutex> hold(max_lock);
    *max_out = std::max(*max_out, mx);
  };
  if (je < 0) je = st;
  if (je <= jb) return;
  const std::int64_t outer = dom.size() / (n * st);
  constexpr std::int64_t kBlock = sizeof(V) <= 4 ? 16 : 8;
  const std::int64_t bw_max = std::min(je - jb, kBlock);
  const std::int64_t nblocks = (je - jb + bw_max - 1) / bw_max;
  const std::int64_t len = periodic ? 3 * n : n, qlo = periodic ? n : 0;
  V* fp = f;
  std::int64_t* sp = sites != nullptr ? sites->data() : nullptr;
#if defined(ZDG_ENVELOPE_AVX512)
  if constexpr (std::is_same_v<V, std::int32_t>) {
    if (sp == nullptr && st > 1 && use_simd()) {
      // Units of up to kChunk columns of one block of lines, cut at 64-byte boundaries of
      // the first block (the units of the others too when the block size is a multiple of 16
      // values): only a unit's first 16-column block may be misaligned.
      constexpr std::int64_t kChunk = 256;
      const auto addr = reinterpret_cast<std::uintptr_t>(fp + jb) / sizeof(V);
      const std::int64_t origin = jb - static_cast<std::int64_t>(addr % 16);
      const std::int64_t per_outer = (je - origin + kChunk - 1) / kChunk;
      parallel_chunks(outer * per_outer, threads, [&](std::int64_t begin, std::int64_t end) {
        SimdTables tables;
        std::uint64_t mx = 0;
        for (std::int64_t unit = begin; unit < end; ++unit) {
          const std::int64_t o = unit / per_outer, c = origin + (unit % per_outer) * kChunk;
          const std::int64_t j0 = std::max(jb, c), j1 = std::min(je, c + kChunk);
          envelope_columns_avx512<K>(fp + o * n * st + j0, st, j1 - j0, n, periodic, inf, m.p,
                                     tables.get(len));
          if (max_out != nullptr) unit_max(fp + o * n * st + j0, st, j1 - j0, mx);
        }
        if (max_out != nullptr) merge_max(mx);
      });
      return;
    }
  }
  if constexpr (std::is_same_v<V, std::int64_t>) {
    if (sp == nullptr && st > 1 && use_simd64(len)) {
      constexpr std::int64_t kChunk = 128; // columns of a unit (int64: the same bytes)
      const auto addr = reinterpret_cast<std::uintptr_t>(fp + jb) / sizeof(V);
      const std::int64_t origin = jb - static_cast<std::int64_t>(addr % 8);
      const std::int64_t per_outer = (je - origin + kChunk - 1) / kChunk;
      parallel_chunks(outer * per_outer, threads, [&](std::int64_t begin, std::int64_t end) {
        SimdTables8 tables;
        std::uint64_t mx = 0;
        for (std::int64_t unit = begin; unit < end; ++unit) {
          const std::int64_t o = unit / per_outer, c = origin + (unit % per_outer) * kChunk;
          const std::int64_t j0 = std::max(jb, c), j1 = std::min(je, c + kChunk);
          envelope_columns8<K>(fp + o * n * st + j0, st, j1 - j0, n, periodic, inf, m.p,
                               tables.get(len));
          if (max_out != nullptr) unit_max(fp + o * n * st + j0, st, j1 - j0, mx);
        }
        if (max_out != nullptr) merge_max(mx);
      });
      return;
    }
  }
#endif
  parallel_chunks(outer * nblocks, threads, [&](std::int64_t begin, std::int64_t end) {
    Scratch<V> sc;
    std::uint64_t mx = 0;
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
        } else {
          // (values only: peaks left out whatever the sign, so one form)
          envelope_line<false, false>(m, line, len, qlo, qlo + n, inf, line, nullptr, sc.s.data(),
                                      sc.t.data(), sc.fs.data());
        }
      }
      for (std::int64_t x = 0; x < n; ++x) {
        V* row = fp + base + x * st;
        for (std::int64_t b = 0; b < bw; ++b) row[b] = bp[b * len + x];
      }
      if (max_out != nullptr) unit_max(fp + base, st, bw, mx);
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
    if (max_out != nullptr) merge_max(mx);
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
#if defined(ZDG_ENVELOPE_AVX512)
  if constexpr (std::is_same_v<V, std::int32_t>) {
    if (simd_mask_lines(item, periodic, sites, n)) {
      parallel_chunks(lines, threads, [&](std::int64_t begin, std::int64_t end) {
        mask_lines_avx512<K>(mask, fp, n, begin, end, m, inf);
      });
      return;
    }
  }
  if constexpr (std::is_same_v<V, std::int64_t>) {
    if (simd_mask_lines64(item, periodic, sites, n)) {
      parallel_chunks(lines, threads, [&](std::int64_t begin, std::int64_t end) {
        mask_lines8<K>(mask, fp, n, begin, end, m.p, inf);
      });
      return;
    }
  }
#endif
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
    bool fused = false; // the mask pass and axis d - 2 in one
#if defined(ZDG_ENVELOPE_AVX512)
    if constexpr (std::is_same_v<V, std::int32_t>) {
      if (mask != nullptr && d >= 3 &&
          simd_mask_lines(item, opt.periodic(d - 1), sites, dom.extent(d - 1))) {
        fused_mask_pass_avx512<K>(dom, opt.periodic(d - 2), m, mask, f, inf, threads);
        fused = true;
      }
    }
    if constexpr (std::is_same_v<V, std::int64_t>) {
      if (mask != nullptr && d >= 3 &&
          simd_mask_lines64(item, opt.periodic(d - 1), sites, dom.extent(d - 1)) &&
          use_simd64(opt.periodic(d - 2) ? 3 * dom.extent(d - 2) : dom.extent(d - 2))) {
        // The slices' own bounds (their two axes, no weights): int32 when they allow it.
        TransformOptions slice_opt = opt;
        slice_opt.min_engine_bits = 0;
        slice_opt.torus.clear();
        if (!opt.torus.empty()) slice_opt.torus = {opt.torus[d - 2], opt.torus[d - 1]};
        const Domain slice_dom({dom.extent(d - 2), dom.extent(d - 1)});
        if (use_simd() &&
            envelope_bounds(slice_dom, slice_opt, BigInt(0)).width == ValueWidth::I32) {
          std::vector<std::int32_t> pw32(pw.size());
          for (std::size_t t = 0; t < pw.size(); ++t) {
            // (t^p < 2^31 for every t on the slice's lines: the bound above)
            pw32[t] = t <= static_cast<std::size_t>(std::max(dom.extent(d - 1), dom.extent(d - 2)))
                          ? static_cast<std::int32_t>(pw[t])
                          : 0;
          }
          LineMetric<K, std::int32_t> m32;
          m32.pw = pw32.data();
          m32.p = m.p;
          m32.inv_pow2 = m.inv_pow2;
          fused_mask_pass_narrow<K>(dom, opt.periodic(d - 2), m32, mask, f, inf, threads);
        } else {
          fused_mask_pass8<K>(dom, opt.periodic(d - 2), m.p, mask, f, inf, threads);
        }
        fused = true;
      }
    }
#endif
    if (!fused && mask != nullptr) {
      mask_pass(dom, opt.periodic(d - 1), m, mask, item, f, inf, sites, threads);
    } else if (!fused) {
      if (sites != nullptr) {
        sites->resize(static_cast<std::size_t>(dom.size()));
        for (std::int64_t i = 0; i < dom.size(); ++i) (*sites)[static_cast<std::size_t>(i)] = i;
      }
      envelope_pass(dom, d - 1, opt.periodic(d - 1), false, m, f, inf, sites, threads);
    }
    if (part.after_pass) part.after_pass(d - 1);
    if (fused && part.after_pass) part.after_pass(d - 2);
    for (int a = fused ? d - 3 : d - 2; a >= 1; --a) {
      envelope_pass(dom, a, opt.periodic(a), mask != nullptr, m, f, inf, sites, threads);
      if (part.after_pass) part.after_pass(a);
    }
  }
  if (part.axis0 && d >= 2) {
    envelope_pass(dom, 0, opt.periodic(0), part.from_mask, m, f, inf, sites, threads,
                  part.column_begin, part.column_end, part.max_value);
    if (part.after_pass) part.after_pass(0);
  }
}
} // namespace

bool set_envelope_simd(bool allowed) {
  return g_envelope_simd.exchange(allowed);
}

bool envelope_simd_available() {
#if defined(ZDG_ENVELOPE_AVX512)
  return envelope_avx512_supported();
#else
  return false;
#endif
}

unsigned resolve_threads(unsigned requested, std::int64_t n) {
  // Below 2^15 points a thread costs more than it saves.
  return worker_count(requested, n, std::int64_t{1} << 15);
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
    // The bit budget of the p-th powers (kernel/transforms/lp_metric.hpp), checked before any of
    // them is computed: p log2(L) < kMaxMetricBits - 8 leaves room for the sums and the factor 2.
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
