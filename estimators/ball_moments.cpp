#include <zdg/estimators/ball_moments.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/images/column_runs.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <tuple>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#endif

namespace zdg {

namespace {

constexpr std::int64_t kMaxRadius = 256;
// Lines of the disc are summed in int32 up to this radius (2 r (r+1)(2r+1)^2 < 2^31).
constexpr std::int64_t kInt32LineRadius = 100;
static_assert(2 * kInt32LineRadius * (kInt32LineRadius + 1) * (2 * kInt32LineRadius + 1) *
                  (2 * kInt32LineRadius + 1) <
              std::int64_t{std::numeric_limits<std::int32_t>::max()});
// One set of column runs at most this many columns; beyond, the centres are split in tiles.
constexpr std::int64_t kMaxColumns = std::int64_t{1} << 24;
constexpr std::int64_t kTile = 1024;

std::int64_t isqrt(std::int64_t n) {
  auto r = std::int64_t(std::sqrt(double(n)));
  while (r > 0 && r * r > n) --r;
  while ((r + 1) * (r + 1) <= n) ++r;
  return r;
}

/// The disc of the ball: for v in [-r, r], the half-width U(v) of the line and the
/// half-lengths w(u, v), u = -U..U, stored from offset[v + r].
struct Disc {
  std::int64_t r = 0;
  std::vector<std::int32_t> half, offset, w;
};

Disc disc_of(std::int64_t r2) {
  Disc d;
  d.r = isqrt(r2);
  for (std::int64_t v = -d.r; v <= d.r; ++v) {
    const std::int64_t U = isqrt(r2 - v * v);
    d.half.push_back(std::int32_t(U));
    d.offset.push_back(std::int32_t(d.w.size()));
    for (std::int64_t u = -U; u <= U; ++u) d.w.push_back(std::int32_t(isqrt(r2 - v * v - u * u)));
  }
  return d;
}

/// Sums over one line of the disc (fixed v), u = j - U: count, u count, u^2 count,
/// 2 sum t, 2 u sum t, 6 sum t^2.
struct LineSums {
  std::int64_t n = 0, nu = 0, nuu = 0, s1x2 = 0, s1ux2 = 0, s2x6 = 0;
};

// The closed forms of one column segment, clamped so that an empty intersection gives
// lo = hi + 1 with |lo|, |hi| <= w + 1 (all terms then vanish and stay small).
#define ZDG_LINE_BODY(ACC)                                                                         \
  ACC n = 0, nu = 0, nuu = 0, s1 = 0, s1u = 0, s2 = 0;                                             \
  for (std::int32_t j = 0; j < len; ++j) {                                                         \
    const std::int32_t wj = w[j], u = j - U;                                                       \
    std::int32_t lo = std::max(a[j] - zc, -wj);                                                    \
    std::int32_t hi = std::min(b[j] - zc, wj);                                                     \
    lo = std::min(lo, wj + 1);                                                                     \
    hi = std::max(hi, lo - 1);                                                                     \
    const std::int32_t cnt = hi - lo + 1;                                                          \
    const std::int32_t t1 = (lo + hi) * cnt;                                                       \
    const std::int32_t lm = lo - 1;                                                                \
    const std::int32_t t2 = hi * (hi + 1) * (2 * hi + 1) - lm * (lm + 1) * (2 * lm + 1);           \
    n += ACC(cnt);                                                                                 \
    nu += ACC(u * cnt);                                                                            \
    nuu += ACC(u * u * cnt);                                                                       \
    s1 += ACC(t1);                                                                                 \
    s1u += ACC(u * t1);                                                                            \
    s2 += ACC(t2);                                                                                 \
  }                                                                                                \
  return {n, nu, nuu, s1, s1u, s2};

__attribute__((target_clones("avx2", "default"))) LineSums
line_sums32(const std::int32_t* a, const std::int32_t* b, const std::int32_t* w, std::int32_t len,
            std::int32_t zc, std::int32_t U) {
  ZDG_LINE_BODY(std::int32_t)
}

__attribute__((target_clones("avx2", "default"))) LineSums
line_sums64(const std::int32_t* a, const std::int32_t* b, const std::int32_t* w, std::int32_t len,
            std::int32_t zc, std::int32_t U) {
  ZDG_LINE_BODY(std::int64_t)
}

// Counts only.
__attribute__((target_clones("avx2", "default"))) std::int64_t
line_counts(const std::int32_t* a, const std::int32_t* b, const std::int32_t* w, std::int32_t len,
            std::int32_t zc) {
  std::int64_t n = 0;
  for (std::int32_t j = 0; j < len; ++j) {
    const std::int32_t wj = w[j];
    const std::int32_t lo = std::max(a[j] - zc, -wj);
    const std::int32_t hi = std::min(b[j] - zc, wj);
    n += std::max(hi - lo + 1, 0);
  }
  return n;
}

#undef ZDG_LINE_BODY

struct Tile {
  std::vector<std::uint32_t> ids; // indices of the centres, sorted by (y, x, z)
  VoxelBox region;
};

/// The blocks of `region` within distance r of a block holding a centre.
BlockMask needed_blocks(const VoxelBox& region, std::span<const Voxel> centres,
                        std::span<const std::uint32_t> ids, std::int64_t r2) {
  const std::int64_t B = ColumnRuns::kBlock;
  BlockMask m;
  m.bx = (region.hi.x - region.lo.x + B) / B;
  m.by = (region.hi.y - region.lo.y + B) / B;
  m.bz = (region.hi.z - region.lo.z + B) / B;
  m.needed.assign(std::size_t(m.bx * m.by * m.bz), 0);
  std::vector<std::uint8_t> holds(m.needed.size(), 0);
  std::vector<std::int64_t> held;
  for (const auto id : ids) {
    const Voxel& c = centres[id];
    const std::int64_t i = (c.x - region.lo.x) / B, j = (c.y - region.lo.y) / B,
                       k = (c.z - region.lo.z) / B;
    const std::int64_t lin = (k * m.by + j) * m.bx + i;
    if (!holds[std::size_t(lin)]) {
      holds[std::size_t(lin)] = 1;
      held.push_back(lin);
    }
  }
  // Offsets between blocks whose voxels can be within distance r: along an axis the
  // nearest voxels of blocks d apart are max(0, |d| B - (B - 1)) apart.
  const std::int64_t reach = (isqrt(r2) + B - 1) / B + 1;
  std::vector<std::array<std::int64_t, 3>> offsets;
  const auto gap = [&](std::int64_t d) {
    return std::max<std::int64_t>(0, std::abs(d) * B - (B - 1));
  };
  for (std::int64_t dk = -reach; dk <= reach; ++dk)
    for (std::int64_t dj = -reach; dj <= reach; ++dj)
      for (std::int64_t di = -reach; di <= reach; ++di)
        if (gap(di) * gap(di) + gap(dj) * gap(dj) + gap(dk) * gap(dk) <= r2)
          offsets.push_back({di, dj, dk});
  for (const auto lin : held) {
    const std::int64_t i = lin % m.bx, j = (lin / m.bx) % m.by, k = lin / (m.bx * m.by);
    for (const auto& o : offsets) {
      const std::int64_t a = i + o[0], b = j + o[1], c = k + o[2];
      if (a < 0 || b < 0 || c < 0 || a >= m.bx || b >= m.by || c >= m.bz) continue;
      m.needed[std::size_t((c * m.by + b) * m.bx + a)] = 1;
    }
  }
  return m;
}

template <bool Second>
BallMoments ball_from_runs(const ColumnRuns& runs, const Disc& disc, const Voxel& c,
                           std::size_t& layer_segments) {
  const std::int32_t zc = std::int32_t(c.z - runs.region.lo.z);
  const std::int64_t r = disc.r;
  // 2 m_z, 6 m_zz, 2 m_xz, 2 m_yz are summed, then divided exactly.
  std::int64_t m0 = 0, mx = 0, my = 0, mz2 = 0, mxx = 0, myy = 0, mzz6 = 0, mxy = 0, mxz2 = 0,
               myz2 = 0;
  for (std::int64_t v = -r; v <= r; ++v) {
    const std::int32_t U = disc.half[std::size_t(v + r)];
    const std::int32_t* w = disc.w.data() + disc.offset[std::size_t(v + r)];
    const std::int32_t len = 2 * U + 1;
    const std::int64_t y = c.y + v, x0 = c.x - U;
    const std::size_t col = runs.column(x0, y);
    for (int k = 0; k < runs.layers(); ++k) {
      std::int32_t j0 = 0, j1 = len - 1;
      if (k > 0) {
        // Only between the first and the last column of the line with more than k runs.
        const auto [first, last] = runs.deeper_range(k, y, x0, x0 + 2 * U);
        if (first > last) break;
        j0 = std::int32_t(first - x0);
        j1 = std::int32_t(last - x0);
        layer_segments += std::size_t(j1 - j0 + 1);
      }
      const std::int32_t n = j1 - j0 + 1;
      const std::int32_t* a = runs.begin[std::size_t(k)].data() + col + std::size_t(j0);
      const std::int32_t* b = runs.end[std::size_t(k)].data() + col + std::size_t(j0);
      if constexpr (Second) {
        const LineSums s = r <= kInt32LineRadius ? line_sums32(a, b, w + j0, n, zc, U - j0)
                                                 : line_sums64(a, b, w + j0, n, zc, U - j0);
        m0 += s.n;
        mx += s.nu;
        my += v * s.n;
        mz2 += s.s1x2;
        mxx += s.nuu;
        myy += v * v * s.n;
        mzz6 += s.s2x6;
        mxy += v * s.nu;
        mxz2 += s.s1ux2;
        myz2 += v * s.s1x2;
      } else {
        m0 += line_counts(a, b, w + j0, n, zc);
      }
    }
  }
  BallMoments out;
  out.m0 = m0;
  if constexpr (Second) {
    out.m1 = {mx, my, mz2 / 2};
    out.m2 = {mxx, myy, mzz6 / 6, mxy, mxz2 / 2, myz2 / 2};
  }
  return out;
}

#if defined(__x86_64__) && defined(__GNUC__)
#define ZDG_BALL_AVX512 1
// ball_from_runs<true> written out for AVX-512 (r <= kInt32LineRadius). The compiler's
// vectorization of line_sums32 leaves a scalar epilogue of up to 15 columns per line and
// reduces six vectors to scalars at the end of every line (a latency chain, then the sums
// pass through memory): measured 2-3x slower than this on lines of 60-150 columns. Here a
// line is 16 columns per step with the tail by a masked load (masked-off lanes contribute
// zero), and its six int32 vectors are folded to 8 lanes and widened into ten int64 vector
// accumulators of the ball, the v-weighted ones by vpmuldq; one horizontal sum per moment
// and ball. Exactness: every term of a line is below 2 r (r + 1)(2 r + 1) in absolute value
// and a line has at most 2 r + 1 of them, so any partial sum of a line's terms (a lane, two
// lanes) is below 2^31 (the bound of line_sums32): the int32 lane sums are exact, and the
// int64 sums of the ball are below 2^48 (header).

using V16 = std::int32_t __attribute__((vector_size(64)));

__attribute__((target("avx512f"), always_inline)) inline __m512i widen_fold(__m512i x) {
  // lanes i and i + 8 added (exact, above), then sign-extended to 8 int64 lanes. (GCC 12's
  // _mm512_extracti64x4_epi64 and _mm512_min/max_epi32 pass an "undefined" vector that its
  // own -Wuninitialized flags; the shuffles and zero-masked forms avoid it.)
  const V16 v = V16(x);
  const __m256i h =
      _mm256_add_epi32(__m256i(__builtin_shufflevector(v, v, 0, 1, 2, 3, 4, 5, 6, 7)),
                       __m256i(__builtin_shufflevector(v, v, 8, 9, 10, 11, 12, 13, 14, 15)));
  return _mm512_maskz_cvtepi32_epi64(0xff, h);
}

__attribute__((target("avx512f"), always_inline)) inline std::int64_t hsum64(__m512i x) {
  alignas(64) std::int64_t lane[8];
  _mm512_store_si512(lane, x);
  return ((lane[0] + lane[1]) + (lane[2] + lane[3])) + ((lane[4] + lane[5]) + (lane[6] + lane[7]));
}

struct Acc512 {
  __m512i m0, mx, my, mz2, mxx, myy, mzz6, mxy, mxz2, myz2;
};

/// Adds the segment a[0..len), b, w (column j at u = j - U) of line v to acc.
__attribute__((target("avx512f"), always_inline)) inline void
line512(const std::int32_t* a, const std::int32_t* b, const std::int32_t* w, std::int32_t len,
        std::int32_t zc, std::int32_t U, std::int64_t v, Acc512& acc) {
  const __mmask16 all = 0xffff;
  const __m512i vzc = _mm512_set1_epi32(zc), one = _mm512_set1_epi32(1);
  const __m512i sixteen = _mm512_set1_epi32(16), zero = _mm512_setzero_si512();
  __m512i u =
      _mm512_sub_epi32(_mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15),
                       _mm512_set1_epi32(U));
  __m512i n = zero, nu = zero, nuu = zero, s1 = zero, s1u = zero, s2 = zero;
  for (std::int32_t j = 0; j < len; j += 16) {
    const std::int32_t rest = len - j;
    const __mmask16 m = rest >= 16 ? all : __mmask16((1u << rest) - 1u);
    const __m512i wj = _mm512_maskz_loadu_epi32(m, w + j);
    const __m512i aj = _mm512_maskz_loadu_epi32(m, a + j);
    const __m512i bj = _mm512_maskz_loadu_epi32(m, b + j);
    // lo = max(a - zc, -w) (kept <= w + 1), hi = min(b - zc, w), cnt = max(hi - lo + 1, 0);
    // t1 = 2 sum t = (lo + hi) cnt and t2 = 6 sum t^2 = cnt (2 (s^2 - lo hi) + hi - lo),
    // s = lo + hi: both vanish with cnt, so lanes with an empty intersection (whatever lo and
    // hi are there) and the masked-off lanes contribute zero.
    const __m512i w1 = _mm512_add_epi32(wj, one);
    const __m512i lo = _mm512_maskz_min_epi32(
        all, _mm512_maskz_max_epi32(all, _mm512_sub_epi32(aj, vzc), _mm512_sub_epi32(zero, wj)),
        w1);
    const __m512i hi = _mm512_maskz_min_epi32(all, _mm512_sub_epi32(bj, vzc), wj);
    const __m512i d = _mm512_sub_epi32(hi, lo); // cnt - 1 where the intersection is not empty
    const __m512i cnt = _mm512_maskz_max_epi32(m, _mm512_add_epi32(d, one), zero);
    const __m512i sum = _mm512_add_epi32(lo, hi);
    const __m512i t1 = _mm512_mullo_epi32(sum, cnt);
    const __m512i q = _mm512_sub_epi32(_mm512_mullo_epi32(sum, sum), _mm512_mullo_epi32(lo, hi));
    const __m512i t2 = _mm512_mullo_epi32(_mm512_add_epi32(_mm512_add_epi32(q, q), d), cnt);
    const __m512i ucnt = _mm512_mullo_epi32(u, cnt);
    n = _mm512_add_epi32(n, cnt);
    nu = _mm512_add_epi32(nu, ucnt);
    nuu = _mm512_add_epi32(nuu, _mm512_mullo_epi32(u, ucnt));
    s1 = _mm512_add_epi32(s1, t1);
    s1u = _mm512_add_epi32(s1u, _mm512_mullo_epi32(u, t1));
    s2 = _mm512_add_epi32(s2, t2);
    u = _mm512_add_epi32(u, sixteen);
  }
  const __m512i V = _mm512_set1_epi64(v), VV = _mm512_set1_epi64(v * v);
  const __m512i N = widen_fold(n), NU = widen_fold(nu), S1 = widen_fold(s1);
  acc.m0 = _mm512_add_epi64(acc.m0, N);
  acc.mx = _mm512_add_epi64(acc.mx, NU);
  acc.my = _mm512_add_epi64(acc.my, _mm512_maskz_mul_epi32(0xff, N, V));
  acc.mz2 = _mm512_add_epi64(acc.mz2, S1);
  acc.mxx = _mm512_add_epi64(acc.mxx, widen_fold(nuu));
  acc.myy = _mm512_add_epi64(acc.myy, _mm512_maskz_mul_epi32(0xff, N, VV));
  acc.mzz6 = _mm512_add_epi64(acc.mzz6, widen_fold(s2));
  acc.mxy = _mm512_add_epi64(acc.mxy, _mm512_maskz_mul_epi32(0xff, NU, V));
  acc.mxz2 = _mm512_add_epi64(acc.mxz2, widen_fold(s1u));
  acc.myz2 = _mm512_add_epi64(acc.myz2, _mm512_maskz_mul_epi32(0xff, S1, V));
}

// The lines of the ball (and the stretches of deeper layers within them) fed to LINE with
// the accumulators of type ACC, summed at the end by HSUM: the body of both vectorized
// routines below, which differ only in these (and in their target).
#define ZDG_BALL_BY_LINES(LINE, ACC, HSUM, VEC, SETZERO)                                           \
  const std::int32_t zc = std::int32_t(c.z - runs.region.lo.z);                                    \
  const std::int64_t r = disc.r;                                                                   \
  const VEC zero = SETZERO();                                                                      \
  ACC acc{zero, zero, zero, zero, zero, zero, zero, zero, zero, zero};                             \
  for (std::int64_t v = -r; v <= r; ++v) {                                                         \
    const std::int32_t U = disc.half[std::size_t(v + r)];                                          \
    const std::int32_t* w = disc.w.data() + disc.offset[std::size_t(v + r)];                       \
    const std::int32_t len = 2 * U + 1;                                                            \
    const std::int64_t y = c.y + v, x0 = c.x - U;                                                  \
    const std::size_t col = runs.column(x0, y);                                                    \
    LINE(runs.begin[0].data() + col, runs.end[0].data() + col, w, len, zc, U, v, acc);             \
    for (int k = 1; k < runs.layers(); ++k) {                                                      \
      const auto [first, last] = runs.deeper_range(k, y, x0, x0 + 2 * U);                          \
      if (first > last) break;                                                                     \
      const std::int32_t j0 = std::int32_t(first - x0), j1 = std::int32_t(last - x0);              \
      layer_segments += std::size_t(j1 - j0 + 1);                                                  \
      LINE(runs.begin[std::size_t(k)].data() + col + std::size_t(j0),                              \
           runs.end[std::size_t(k)].data() + col + std::size_t(j0), w + j0, j1 - j0 + 1, zc,       \
           U - j0, v, acc);                                                                        \
    }                                                                                              \
  }                                                                                                \
  BallMoments out;                                                                                 \
  out.m0 = HSUM(acc.m0);                                                                           \
  out.m1 = {HSUM(acc.mx), HSUM(acc.my), HSUM(acc.mz2) / 2};                                        \
  out.m2 = {HSUM(acc.mxx), HSUM(acc.myy),      HSUM(acc.mzz6) / 6,                                 \
            HSUM(acc.mxy), HSUM(acc.mxz2) / 2, HSUM(acc.myz2) / 2};                                \
  return out;

__attribute__((target("avx512f"))) BallMoments ball_from_runs_avx512(const ColumnRuns& runs,
                                                                     const Disc& disc,
                                                                     const Voxel& c,
                                                                     std::size_t& layer_segments) {
  ZDG_BALL_BY_LINES(line512, Acc512, hsum64, __m512i, _mm512_setzero_si512)
}
#endif

#ifdef ZDG_BALL_AVX512
// The same for AVX2 (8 columns per step, the tail by vpmaskmovd, the line's lanes folded to
// 4 and widened into int64 accumulators of 4 lanes): CPUs without AVX-512.

struct Acc256 {
  __m256i m0, mx, my, mz2, mxx, myy, mzz6, mxy, mxz2, myz2;
};

__attribute__((target("avx2"), always_inline)) inline __m256i widen_fold256(__m256i x) {
  return _mm256_cvtepi32_epi64(
      _mm_add_epi32(_mm256_castsi256_si128(x), _mm256_extracti128_si256(x, 1)));
}

__attribute__((target("avx2"), always_inline)) inline std::int64_t hsum256(__m256i x) {
  alignas(32) std::int64_t lane[4];
  _mm256_store_si256(reinterpret_cast<__m256i*>(lane), x);
  return (lane[0] + lane[1]) + (lane[2] + lane[3]);
}

__attribute__((target("avx2"), always_inline)) inline void
line256(const std::int32_t* a, const std::int32_t* b, const std::int32_t* w, std::int32_t len,
        std::int32_t zc, std::int32_t U, std::int64_t v, Acc256& acc) {
  const __m256i vzc = _mm256_set1_epi32(zc), one = _mm256_set1_epi32(1);
  const __m256i eight = _mm256_set1_epi32(8), zero = _mm256_setzero_si256();
  const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  __m256i u = _mm256_sub_epi32(lane, _mm256_set1_epi32(U));
  __m256i n = zero, nu = zero, nuu = zero, s1 = zero, s1u = zero, s2 = zero;
  for (std::int32_t j = 0; j < len; j += 8) {
    const __m256i m = _mm256_cmpgt_epi32(_mm256_set1_epi32(len - j), lane);
    const __m256i wj = _mm256_maskload_epi32(w + j, m);
    const __m256i aj = _mm256_maskload_epi32(a + j, m);
    const __m256i bj = _mm256_maskload_epi32(b + j, m);
    const __m256i lo =
        _mm256_min_epi32(_mm256_max_epi32(_mm256_sub_epi32(aj, vzc), _mm256_sub_epi32(zero, wj)),
                         _mm256_add_epi32(wj, one));
    const __m256i hi = _mm256_min_epi32(_mm256_sub_epi32(bj, vzc), wj);
    const __m256i d = _mm256_sub_epi32(hi, lo);
    const __m256i cnt = _mm256_and_si256(m, _mm256_max_epi32(_mm256_add_epi32(d, one), zero));
    const __m256i sum = _mm256_add_epi32(lo, hi);
    const __m256i t1 = _mm256_mullo_epi32(sum, cnt);
    const __m256i q = _mm256_sub_epi32(_mm256_mullo_epi32(sum, sum), _mm256_mullo_epi32(lo, hi));
    const __m256i t2 = _mm256_mullo_epi32(_mm256_add_epi32(_mm256_add_epi32(q, q), d), cnt);
    const __m256i ucnt = _mm256_mullo_epi32(u, cnt);
    n = _mm256_add_epi32(n, cnt);
    nu = _mm256_add_epi32(nu, ucnt);
    nuu = _mm256_add_epi32(nuu, _mm256_mullo_epi32(u, ucnt));
    s1 = _mm256_add_epi32(s1, t1);
    s1u = _mm256_add_epi32(s1u, _mm256_mullo_epi32(u, t1));
    s2 = _mm256_add_epi32(s2, t2);
    u = _mm256_add_epi32(u, eight);
  }
  const __m256i V = _mm256_set1_epi64x(v), VV = _mm256_set1_epi64x(v * v);
  const __m256i N = widen_fold256(n), NU = widen_fold256(nu), S1 = widen_fold256(s1);
  acc.m0 = _mm256_add_epi64(acc.m0, N);
  acc.mx = _mm256_add_epi64(acc.mx, NU);
  acc.my = _mm256_add_epi64(acc.my, _mm256_mul_epi32(N, V));
  acc.mz2 = _mm256_add_epi64(acc.mz2, S1);
  acc.mxx = _mm256_add_epi64(acc.mxx, widen_fold256(nuu));
  acc.myy = _mm256_add_epi64(acc.myy, _mm256_mul_epi32(N, VV));
  acc.mzz6 = _mm256_add_epi64(acc.mzz6, widen_fold256(s2));
  acc.mxy = _mm256_add_epi64(acc.mxy, _mm256_mul_epi32(NU, V));
  acc.mxz2 = _mm256_add_epi64(acc.mxz2, widen_fold256(s1u));
  acc.myz2 = _mm256_add_epi64(acc.myz2, _mm256_mul_epi32(S1, V));
}

__attribute__((target("avx2"))) BallMoments ball_from_runs_avx2(const ColumnRuns& runs,
                                                                const Disc& disc, const Voxel& c,
                                                                std::size_t& layer_segments) {
  ZDG_BALL_BY_LINES(line256, Acc256, hsum256, __m256i, _mm256_setzero_si256)
}
#endif

#undef ZDG_BALL_BY_LINES

/// The lanes of the widest vectorized form this CPU runs: 16 (AVX-512F), 8 (AVX2) or 0
/// (the portable loop); decided once.
int simd_lanes() {
#ifdef ZDG_BALL_AVX512
  static const int lanes = __builtin_cpu_supports("avx512f") ? 16
                           : __builtin_cpu_supports("avx2")  ? 8
                                                             : 0;
  return lanes;
#else
  return 0;
#endif
}

} // namespace

BallMoments direct_ball_moments(const VoxelPredicate& inside, const VoxelBox& box,
                                const Voxel& centre, std::int64_t r2) {
  if (r2 < 0 || r2 > kMaxRadius * kMaxRadius)
    throw InvalidArgument("ball moments: squared digital radius " + std::to_string(r2) +
                          " is outside [0, 256^2]");
  const std::int64_t r = isqrt(r2);
  BallMoments m;
  for (std::int64_t z = -r; z <= r; ++z)
    for (std::int64_t y = -r; y <= r; ++y)
      for (std::int64_t x = -r; x <= r; ++x) {
        if (x * x + y * y + z * z > r2) continue;
        const Voxel p{centre.x + x, centre.y + y, centre.z + z};
        if (!box.contains(p) || !inside(p)) continue;
        ++m.m0;
        m.m1[0] += x;
        m.m1[1] += y;
        m.m1[2] += z;
        m.m2[0] += x * x;
        m.m2[1] += y * y;
        m.m2[2] += z * z;
        m.m2[3] += x * y;
        m.m2[4] += x * z;
        m.m2[5] += y * z;
      }
  return m;
}

ColumnMoments ball_moments_by_columns(const VoxelPredicate& inside, const VoxelBox& box,
                                      std::span<const Voxel> centres, std::int64_t r2,
                                      unsigned threads, bool second_order) {
  return detail::ball_moments_by_columns(inside, box, centres, r2, threads, second_order, 16);
}

int detail::ball_moments_simd_lanes() {
  return simd_lanes();
}

ColumnMoments detail::ball_moments_by_columns(const VoxelPredicate& inside, const VoxelBox& box,
                                              std::span<const Voxel> centres, std::int64_t r2,
                                              unsigned threads, bool second_order, int max_lanes) {
  check_voxel_box(box);
  if (r2 < 0 || r2 > kMaxRadius * kMaxRadius)
    throw InvalidArgument("ball moments: squared digital radius " + std::to_string(r2) +
                          " is outside [0, 256^2]");
  ColumnMoments out;
  out.moments.resize(centres.size());
  out.stats.centres = centres.size();
  if (centres.empty()) return out;
  if (centres.size() >= (std::size_t{1} << 32))
    throw InvalidArgument("ball moments: more than 2^32 centres");
  const std::int64_t r = isqrt(r2);
  const std::int64_t limit = kMaxVoxelCoordinate - kMaxRadius - 8;
  for (const Voxel& c : centres)
    if (std::abs(c.x) > limit || std::abs(c.y) > limit || std::abs(c.z) > limit)
      throw InvalidArgument("ball moments: centre coordinate beyond 2^40");
  const Disc disc = disc_of(r2);

  // Tiles: one when the columns of the bounding box of the balls are few enough, else
  // cubes of kTile voxels.
  Voxel lo = centres[0], hi = centres[0];
  for (const Voxel& c : centres) {
    lo = {std::min(lo.x, c.x), std::min(lo.y, c.y), std::min(lo.z, c.z)};
    hi = {std::max(hi.x, c.x), std::max(hi.y, c.y), std::max(hi.z, c.z)};
  }
  const bool one =
      double(hi.x - lo.x + 2 * r + 1) * double(hi.y - lo.y + 2 * r + 1) <= double(kMaxColumns) &&
      hi.z - lo.z + 2 * r + 1 < (std::int64_t{1} << 27);
  std::vector<std::uint32_t> order(centres.size());
  std::iota(order.begin(), order.end(), 0u);
  auto tile_of = [&](const Voxel& c) {
    if (one) return std::tuple<std::int64_t, std::int64_t, std::int64_t>{0, 0, 0};
    auto t = [](std::int64_t v) { return v >= 0 ? v / kTile : -((-v + kTile - 1) / kTile); };
    return std::tuple{t(c.z), t(c.y), t(c.x)};
  };
  std::sort(order.begin(), order.end(), [&](std::uint32_t i, std::uint32_t j) {
    const Voxel &p = centres[i], &q = centres[j];
    return std::tuple_cat(tile_of(p), std::tie(p.y, p.x, p.z)) <
           std::tuple_cat(tile_of(q), std::tie(q.y, q.x, q.z));
  });
  std::vector<Tile> tiles;
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    const auto t = tile_of(centres[order[i]]);
    Tile tile;
    Voxel tl = centres[order[i]], th = tl;
    while (j < order.size() && tile_of(centres[order[j]]) == t) {
      const Voxel& c = centres[order[j]];
      tl = {std::min(tl.x, c.x), std::min(tl.y, c.y), std::min(tl.z, c.z)};
      th = {std::max(th.x, c.x), std::max(th.y, c.y), std::max(th.z, c.z)};
      tile.ids.push_back(order[j]);
      ++j;
    }
    tile.region = {{tl.x - r, tl.y - r, tl.z - r}, {th.x + r, th.y + r, th.z + r}};
    tiles.push_back(std::move(tile));
    i = j;
  }

  const unsigned workers = worker_count(threads, std::numeric_limits<std::int64_t>::max());
  // The vectorized forms: second order, r <= kInt32LineRadius (their int32 line sums).
  const int lanes = second_order && r <= kInt32LineRadius ? std::min(max_lanes >= 16  ? 16
                                                                     : max_lanes >= 8 ? 8
                                                                                      : 0,
                                                                     simd_lanes())
                                                          : 0;
  out.stats.simd_lanes = lanes;
  std::atomic<std::size_t> layer_segments{0};
  for (const Tile& tile : tiles) {
    const BlockMask mask = needed_blocks(tile.region, centres, tile.ids, r2);
    const ColumnRuns runs = column_runs(inside, box, tile.region, workers, &mask);
    out.stats.evaluations += runs.evaluations;
    out.stats.layers = std::max(out.stats.layers, runs.layers());
    out.stats.region_voxels += std::size_t(runs.nx * runs.ny * runs.nz);
    if (runs.layers() == 0) continue; // nothing inside: all moments stay zero
    constexpr std::int64_t kBatch = 64;
    const std::int64_t n = std::int64_t(tile.ids.size());
    parallel_for((n + kBatch - 1) / kBatch, workers, [&](std::int64_t batch) {
      std::size_t extra = 0;
      const std::int64_t e = std::min(n, (batch + 1) * kBatch);
      for (std::int64_t i = batch * kBatch; i < e; ++i) {
        const auto id = tile.ids[std::size_t(i)];
#ifdef ZDG_BALL_AVX512
        if (lanes == 16) {
          out.moments[id] = ball_from_runs_avx512(runs, disc, centres[id], extra);
          continue;
        }
        if (lanes == 8) {
          out.moments[id] = ball_from_runs_avx2(runs, disc, centres[id], extra);
          continue;
        }
#endif
        out.moments[id] = second_order ? ball_from_runs<true>(runs, disc, centres[id], extra)
                                       : ball_from_runs<false>(runs, disc, centres[id], extra);
      }
      layer_segments += extra;
    });
  }
  out.stats.segments = centres.size() * disc.w.size();
  out.stats.layer_segments = layer_segments.load();
  return out;
}

} // namespace zdg
