#include <zdg/estimators/heat_laplace_beltrami.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>
#include <zdg/kernel/parallel/parallel_rounds.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <numeric>
#include <string>
#include <tuple>

namespace zdg {

double heat_kernel_time(double h, double alpha) {
  if (!(h > 0) || !std::isfinite(h))
    throw InvalidArgument("heat kernel: the grid step must be positive, got " + std::to_string(h));
  if (!(alpha > 0 && alpha < 1))
    throw InvalidArgument("heat kernel: alpha = " + std::to_string(alpha) +
                          " is outside (0, 1) (t = h^alpha)");
  return std::pow(h, alpha);
}

namespace {
using Cell = std::array<std::int64_t, 3>;

// Eight floats and four doubles (GCC and clang vector extensions: one AVX register each, two
// SSE2 ones). The helpers are inlined into block_sums, so no 32-byte vector crosses a call (the
// -Wpsabi note of GCC and clang about the AVX calling convention does not apply:
// CMakeLists.txt turns it off for this file).
typedef float F8 __attribute__((vector_size(32)));
typedef std::int32_t I8 __attribute__((vector_size(32)));
typedef double V4 __attribute__((vector_size(32)));

// exp(x) in single precision for x <= 0 lane by lane (arguments below -87 give exp(-87), -inf
// included): x = n ln 2 + r with n = round(x log2 e) (the 1.5 2^23 shifter), r by Cody and
// Waite's two-part ln 2 (|r| <= ln 2 / 2), e^r by its Taylor polynomial of degree 7 (remainder
// (ln 2 / 2)^8 / 8! < 6e-9), 2^n from the exponent bits (n >= -126): relative error below
// 2e-7 (1.73e-7 the largest against std::exp over [-87, 0] in steps of 1e-6, measured). No
// branch, no call.
[[gnu::always_inline]] inline F8 expf_nonpositive(F8 x) {
  const F8 low = {-87.f, -87.f, -87.f, -87.f, -87.f, -87.f, -87.f, -87.f};
  x = x < low ? low : x;
  const F8 k = x * 1.44269504f + 12582912.f; // 1.5 * 2^23
  const F8 n = k - 12582912.f;
  const F8 r = (x - n * 0.693359375f) - n * -2.12194440e-4f;
  const F8 r2 = r * r;
  const F8 q0 = r + 1.f, q1 = r * (1.f / 6) + 0.5f, q2 = r * (1.f / 120) + 1.f / 24,
           q3 = r * (1.f / 5040) + 1.f / 720;
  const F8 p = (r2 * r2) * (r2 * q3 + q2) + (r2 * q1 + q0);
  const I8 e = (__builtin_convertvector(n, I8) + 127) << 23;
  F8 scale;
  std::memcpy(&scale, &e, sizeof scale);
  return p * scale;
}

// The kernel values of 8 pairs, as two vectors of doubles.
[[gnu::always_inline]] inline void widen(F8 k, V4& lo, V4& hi) {
  typedef double V8 __attribute__((vector_size(64)));
  const V8 d = __builtin_convertvector(k, V8);
  std::memcpy(&lo, &d, sizeof lo);
  std::memcpy(&hi, reinterpret_cast<const char*>(&d) + sizeof lo, sizeof hi);
}

constexpr int kGroup = 4;
// Positions per block of apply()'s schedule (a multiple of 8: the column sums are stored by
// eight).
constexpr std::int64_t kBlock = 256;

// The sums of a group of G surfels s (G <= kGroup) against the m centres r of a block, eight at
// a time (the tail padded with far-away lanes whose kernel value is 0): for each s, a1 +=
// sum g w(r) u(r) and a0 += sum g w(r), with g = exp(-|x_r - x_s|^2 / (4t)) where |x_r - x_s|
// <= rho, else 0 (r = s included: its terms cancel in a1 - u(s) a0); with Both, also the
// columns' sums c1[r] += g w(s) u(s), c0[r] += g w(s) (c1, c0: m rounded up to 8 entries), so
// that one exp serves (s, r) and (r, s). The coordinates are floats relative to the block's
// first centre, in units of rho (xs: the surfels' own, relative to the same point; the reach
// is 1, inv4t = rho^2 / (4t)):
// |x - origin| <= 2 sqrt(3) rho for every pair within reach, so the single-precision
// differences keep about 2^-23 of rho. The kernel values are single precision (relative error
// below 2.4e-7 + 4e-7 c^2: the header); the sums are double precision, and a1 and a0 take the
// same products (L 1 = 0 exactly). The G surfels share each load of eight centres.
// GCC on x86-64: an x86-64-v3 (AVX2 + FMA) clone next to the baseline SSE2 one, chosen at load
// time by the CPU (an ifunc); the sums are the same up to rounding.
template <bool Both, int G>
[[gnu::always_inline]] inline void
block_sums_body(const float* x, const float* y, const float* z, const double* w, const double* wu,
                std::int64_t m, const float* xs, const float* ys, const float* zs, const double* ws,
                const double* wus, float inv4t, double* a1, double* a0, double* c1, double* c0) {
  V4 s1[G] = {}, s0[G] = {};
  const F8 fzero = {};
  for (std::int64_t r = 0; r < m; r += 8) {
    F8 vx, vy, vz;
    V4 w_lo, w_hi, wu_lo, wu_hi;
    if (r + 8 <= m) {
      std::memcpy(&vx, x + r, sizeof vx);
      std::memcpy(&vy, y + r, sizeof vy);
      std::memcpy(&vz, z + r, sizeof vz);
      std::memcpy(&w_lo, w + r, sizeof w_lo);
      std::memcpy(&w_hi, w + r + 4, sizeof w_hi);
      std::memcpy(&wu_lo, wu + r, sizeof wu_lo);
      std::memcpy(&wu_hi, wu + r + 4, sizeof wu_hi);
    } else {
      for (int i = 0; i < 8; ++i) {
        const bool in = r + i < m;
        vx[i] = in ? x[r + i] : 1e18f; // outside the radius of every surfel: masked
        vy[i] = in ? y[r + i] : 0;
        vz[i] = in ? z[r + i] : 0;
        const double wi = in ? w[r + i] : 0, wui = in ? wu[r + i] : 0;
        if (i < 4) {
          w_lo[i] = wi;
          wu_lo[i] = wui;
        } else {
          w_hi[i - 4] = wi;
          wu_hi[i - 4] = wui;
        }
      }
    }
    V4 t1_lo = {}, t1_hi = {}, t0_lo = {}, t0_hi = {};
#pragma GCC unroll 4
    for (int g = 0; g < G; ++g) {
      const F8 dx = vx - xs[g], dy = vy - ys[g], dz = vz - zs[g];
      const F8 d2 = dx * dx + dy * dy + dz * dz;
      const F8 k = d2 <= 1.f ? expf_nonpositive(-d2 * inv4t) : fzero;
      V4 k_lo, k_hi;
      widen(k, k_lo, k_hi);
      s1[g] += k_lo * wu_lo + k_hi * wu_hi;
      s0[g] += k_lo * w_lo + k_hi * w_hi;
      if constexpr (Both) {
        t1_lo += k_lo * wus[g];
        t1_hi += k_hi * wus[g];
        t0_lo += k_lo * ws[g];
        t0_hi += k_hi * ws[g];
      }
    }
    if constexpr (Both) {
      const auto add = [](double* c, V4 t) {
        V4 o;
        std::memcpy(&o, c, sizeof o);
        o += t;
        std::memcpy(c, &o, sizeof o);
      };
      add(c1 + r, t1_lo);
      add(c1 + r + 4, t1_hi);
      add(c0 + r, t0_lo);
      add(c0 + r + 4, t0_hi);
    }
  }
  for (int g = 0; g < G; ++g) {
    a1[g] += (s1[g][0] + s1[g][1]) + (s1[g][2] + s1[g][3]);
    a0[g] += (s0[g][0] + s0[g][1]) + (s0[g][2] + s0[g][3]);
  }
}

// block_sums_body for G surfels, the columns' sums too when c1 is not null.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
__attribute__((target_clones("arch=x86-64-v3", "default")))
#endif
void block_sums(int G, const float* x, const float* y, const float* z, const double* w,
                const double* wu, std::int64_t m, const float* xs, const float* ys, const float* zs,
                const double* ws, const double* wus, float inv4t, double* a1, double* a0,
                double* c1, double* c0) {
  switch (G + (c1 != nullptr ? kGroup : 0)) {
#define ZDG_CASE(BOTH, N)                                                                          \
  case N + (BOTH ? kGroup : 0):                                                                    \
    return block_sums_body<BOTH, N>(x, y, z, w, wu, m, xs, ys, zs, ws, wus, inv4t, a1, a0, c1, c0);
    ZDG_CASE(false, 1)
    ZDG_CASE(false, 2)
    ZDG_CASE(false, 3)
    ZDG_CASE(false, 4)
    ZDG_CASE(true, 1)
    ZDG_CASE(true, 2)
    ZDG_CASE(true, 3)
    ZDG_CASE(true, 4)
#undef ZDG_CASE
  }
}
static_assert(kGroup == 4, "block_sums instantiates G = 1 .. 4");

} // namespace

HeatLaplaceBeltrami::HeatLaplaceBeltrami(std::span<const Point3<double>> centres,
                                         std::span<const double> weights, double t,
                                         double cutoff_sigmas, unsigned threads)
    : t_(t), threads_(threads) {
  if (centres.size() != weights.size())
    throw InvalidArgument("heat Laplace-Beltrami: " + std::to_string(centres.size()) +
                          " centres and " + std::to_string(weights.size()) + " weights");
  if (!(t > 0) || !std::isfinite(t))
    throw InvalidArgument("heat Laplace-Beltrami: the time t must be positive, got " +
                          std::to_string(t));
  if (!(cutoff_sigmas > 0) || !std::isfinite(cutoff_sigmas))
    throw InvalidArgument("heat Laplace-Beltrami: the cutoff must be positive, got " +
                          std::to_string(cutoff_sigmas));
  rho_ = cutoff_sigmas * std::sqrt(2 * t);
  const std::size_t n = centres.size();
  std::vector<Cell> cell(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& p = centres[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) ||
        !std::isfinite(weights[i]))
      throw InvalidArgument("heat Laplace-Beltrami: centre or weight " + std::to_string(i) +
                            " is not finite");
    const double q[3] = {p.x / rho_, p.y / rho_, p.z / rho_};
    for (int a = 0; a < 3; ++a) {
      if (!(std::abs(q[a]) < 1e15))
        throw InvalidArgument("heat Laplace-Beltrami: the centres span more than 1e15 kernel "
                              "radii");
      cell[i][std::size_t(a)] = static_cast<std::int64_t>(std::floor(q[a]));
    }
  }
  order_.resize(n);
  std::iota(order_.begin(), order_.end(), std::int64_t{0});
  std::sort(order_.begin(), order_.end(), [&](std::int64_t a, std::int64_t b) {
    return std::tie(cell[std::size_t(a)], a) < std::tie(cell[std::size_t(b)], b);
  });
  x_.resize(n);
  y_.resize(n);
  z_.resize(n);
  w_.resize(n);
  std::vector<Cell> cells;
  for (std::size_t k = 0; k < n; ++k) {
    const auto i = std::size_t(order_[k]);
    x_[k] = centres[i].x;
    y_[k] = centres[i].y;
    z_[k] = centres[i].z;
    w_[k] = weights[i];
    if (cells.empty() || cells.back() != cell[i]) {
      cells.push_back(cell[i]);
      cell_start_.push_back(std::int64_t(k));
    }
  }
  cell_start_.push_back(std::int64_t(n));
  const std::size_t nc = cells.size();
  neighbours_.assign(27 * nc, -1);
  parallel_chunks(std::int64_t(nc), threads_, [&](std::int64_t b, std::int64_t e) {
    for (auto c = std::size_t(b); c < std::size_t(e); ++c) {
      int k = 0;
      for (std::int64_t dx = -1; dx <= 1; ++dx)
        for (std::int64_t dy = -1; dy <= 1; ++dy)
          for (std::int64_t dz = -1; dz <= 1; ++dz) {
            const Cell q{cells[c][0] + dx, cells[c][1] + dy, cells[c][2] + dz};
            const auto it = std::lower_bound(cells.begin(), cells.end(), q);
            if (it != cells.end() && *it == q)
              neighbours_[27 * c + std::size_t(k++)] = std::int64_t(it - cells.begin());
          }
    }
  });

  // apply()'s schedule. Blocks: each cell cut into runs of kBlock positions.
  std::vector<std::int64_t> first_block(nc + 1);
  for (std::size_t c = 0; c < nc; ++c) {
    first_block[c] = std::int64_t(block_start_.size());
    for (auto b = cell_start_[c]; b < cell_start_[c + 1]; b += kBlock) block_start_.push_back(b);
  }
  first_block[nc] = std::int64_t(block_start_.size());
  const auto blocks = std::size_t(first_block[nc]);
  block_start_.push_back(std::int64_t(n));
  // Single-precision coordinates relative to the first centre of their block, in units of rho
  // (every quantity of the float kernel is then of order 1, whatever the scale of the input).
  xf_.resize(n);
  yf_.resize(n);
  zf_.resize(n);
  const double per_rho = 1 / rho_;
  for (std::size_t B = 0; B < blocks; ++B) {
    const auto o = std::size_t(block_start_[B]);
    for (auto k = o; k < std::size_t(block_start_[B + 1]); ++k) {
      xf_[k] = float((x_[k] - x_[o]) * per_rho);
      yf_[k] = float((y_[k] - y_[o]) * per_rho);
      zf_[k] = float((z_[k] - z_[o]) * per_rho);
    }
  }
  // The pairs I < J (blocks are sorted by cell: a neighbour cell after the block's own holds
  // only later blocks), then a greedy colouring of the pairs in that order: the smallest round
  // in which neither block is used yet (at most 2 D - 1 rounds for D pairs per block).
  std::vector<std::array<std::int64_t, 2>> pairs;
  for (std::size_t c = 0; c < nc; ++c)
    for (auto I = first_block[c]; I < first_block[c + 1]; ++I)
      for (std::size_t k = 0; k < 27; ++k) {
        const auto nb = neighbours_[27 * c + k];
        if (nb < 0) break;
        if (std::size_t(nb) < c) continue;
        for (auto J = std::max(first_block[std::size_t(nb)], I + 1);
             J < first_block[std::size_t(nb) + 1]; ++J)
          pairs.push_back({I, J});
      }
  std::vector<std::vector<std::uint64_t>> used(blocks);
  std::vector<std::int64_t> round(pairs.size());
  std::int64_t rounds = 0;
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    auto& u = used[std::size_t(pairs[p][0])];
    auto& v = used[std::size_t(pairs[p][1])];
    std::size_t word = 0;
    std::uint64_t free = 0;
    for (;; ++word) {
      const std::uint64_t a = word < u.size() ? u[word] : 0, b = word < v.size() ? v[word] : 0;
      free = ~(a | b);
      if (free != 0) break;
    }
    const int bit = std::countr_zero(free);
    for (auto* s : {&u, &v}) {
      if (s->size() <= word) s->resize(word + 1, 0);
      (*s)[word] |= std::uint64_t{1} << bit;
    }
    round[p] = std::int64_t(word) * 64 + bit;
    rounds = std::max(rounds, round[p] + 1);
  }
  // Round 0: each block with itself (disjoint), then the coloured rounds.
  round_start_.assign(std::size_t(rounds) + 2, 0);
  round_start_[1] = std::int64_t(blocks);
  for (const auto k : round) ++round_start_[std::size_t(k) + 2];
  std::partial_sum(round_start_.begin(), round_start_.end(), round_start_.begin());
  pairs_.resize(blocks + pairs.size());
  for (std::size_t B = 0; B < blocks; ++B) pairs_[B] = {std::int64_t(B), std::int64_t(B)};
  std::vector<std::int64_t> fill(round_start_.begin() + 1, round_start_.end() - 1);
  for (std::size_t p = 0; p < pairs.size(); ++p)
    pairs_[std::size_t(fill[std::size_t(round[p])]++)] = pairs[p];
}

// fn(s, r, g) for every sorted position s in the cell and every r != s within the radius,
// with g = exp(-|x_r - x_s|^2 / (4t)).
template <class Fn>
void HeatLaplaceBeltrami::for_each_pair_of_cell(std::int64_t cell, Fn&& fn) const {
  const double r2max = rho_ * rho_, inv4t = 1 / (4 * t_);
  const auto c = std::size_t(cell);
  for (auto s = cell_start_[c]; s < cell_start_[c + 1]; ++s) {
    const double xs = x_[std::size_t(s)], ys = y_[std::size_t(s)], zs = z_[std::size_t(s)];
    for (std::size_t k = 0; k < 27; ++k) {
      const auto nb = neighbours_[27 * c + k];
      if (nb < 0) break;
      const auto b = cell_start_[std::size_t(nb)], e = cell_start_[std::size_t(nb) + 1];
      for (auto r = b; r < e; ++r) {
        const double dx = x_[std::size_t(r)] - xs, dy = y_[std::size_t(r)] - ys,
                     dz = z_[std::size_t(r)] - zs;
        const double d2 = dx * dx + dy * dy + dz * dz;
        if (d2 <= r2max && r != s) fn(s, r, std::exp(-d2 * inv4t));
      }
    }
  }
}

std::vector<double> HeatLaplaceBeltrami::apply(std::span<const double> u) const {
  const std::size_t n = order_.size();
  if (u.size() != n)
    throw InvalidArgument("heat Laplace-Beltrami: a function of " + std::to_string(u.size()) +
                          " values on " + std::to_string(n) + " surfels");
  std::vector<double> us(n), wu(n), out(n);
  for (std::size_t k = 0; k < n; ++k) {
    us[k] = u[std::size_t(order_[k])];
    wu[k] = us[k] * w_[k];
  }
  const double scale = 1 / (4 * std::numbers::pi * t_ * t_);
  // Every pair once: the sums of (s, r) and of (r, s) share their exp. Round 0 pairs each block
  // with itself (rows only: both orders are in the block, s = r included: its terms cancel in
  // a1 - u(s) a0), the later rounds pairs of distinct blocks, each block's sums added in round
  // order. In units of rho: |x_r - x_s|^2 / rho^2 <= 1 within reach, exp(-d^2 rho^2 / (4t)).
  std::vector<double> a1(n, 0.0), a0(n, 0.0);
  const auto inv4t = float(rho_ * rho_ / (4 * t_));
  const double per_rho = 1 / rho_;
  parallel_rounds(round_start_, threads_, [&](std::int64_t p) {
    const auto [I, J] = pairs_[std::size_t(p)];
    const auto b = std::size_t(block_start_[std::size_t(J)]);
    const auto m = block_start_[std::size_t(J) + 1] - block_start_[std::size_t(J)];
    double c1[kBlock] = {}, c0[kBlock] = {};
    const bool both = I != J;
    for (auto s = block_start_[std::size_t(I)]; s < block_start_[std::size_t(I) + 1];) {
      const auto G = int(std::min<std::int64_t>(kGroup, block_start_[std::size_t(I) + 1] - s));
      // The group's coordinates relative to the first centre of block J, in units of rho.
      float xs[kGroup], ys[kGroup], zs[kGroup];
      for (int g = 0; g < G; ++g) {
        xs[g] = float((x_[std::size_t(s + g)] - x_[b]) * per_rho);
        ys[g] = float((y_[std::size_t(s + g)] - y_[b]) * per_rho);
        zs[g] = float((z_[std::size_t(s + g)] - z_[b]) * per_rho);
      }
      block_sums(G, xf_.data() + b, yf_.data() + b, zf_.data() + b, w_.data() + b, wu.data() + b, m,
                 xs, ys, zs, w_.data() + s, wu.data() + s, inv4t, a1.data() + s, a0.data() + s,
                 both ? c1 : nullptr, both ? c0 : nullptr);
      s += G;
    }
    if (both)
      for (std::int64_t r = 0; r < m; ++r) {
        a1[b + std::size_t(r)] += c1[r];
        a0[b + std::size_t(r)] += c0[r];
      }
  });
  for (std::size_t k = 0; k < n; ++k) out[std::size_t(order_[k])] = scale * (a1[k] - us[k] * a0[k]);
  return out;
}

std::int64_t HeatLaplaceBeltrami::pair_count() const {
  const auto cells = std::int64_t(cell_start_.size()) - 1;
  std::vector<std::int64_t> count(std::size_t(std::max<std::int64_t>(cells, 0)), 0);
  parallel_for(cells, threads_, [&](std::int64_t c) {
    std::int64_t k = 0;
    for_each_pair_of_cell(c, [&](std::int64_t, std::int64_t, double) { ++k; });
    count[std::size_t(c)] = k;
  });
  return std::accumulate(count.begin(), count.end(), std::int64_t{0});
}

SparseMatrix HeatLaplaceBeltrami::matrix() const {
  const std::size_t n = order_.size();
  const double scale = 1 / (4 * std::numbers::pi * t_ * t_);
  const auto cells = std::int64_t(cell_start_.size()) - 1;
  // Row lengths (pairs + the diagonal), then the rows, each sorted by column.
  std::vector<std::int64_t> len(n, 1);
  parallel_for(cells, threads_, [&](std::int64_t c) {
    for_each_pair_of_cell(c, [&](std::int64_t s, std::int64_t, double) {
      ++len[std::size_t(order_[std::size_t(s)])];
    });
  });
  SparseMatrix m;
  m.rows = m.cols = std::int64_t(n);
  m.row_start.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) m.row_start[i + 1] = m.row_start[i] + len[i];
  m.column.resize(std::size_t(m.row_start[n]));
  m.value.resize(std::size_t(m.row_start[n]));
  parallel_for(cells, threads_, [&](std::int64_t c) {
    std::vector<std::pair<std::int64_t, double>> row;
    std::int64_t current = -1;
    auto flush = [&] {
      if (current < 0) return;
      const auto i = std::size_t(order_[std::size_t(current)]);
      double diag = 0;
      for (const auto& [j, v] : row) diag -= v;
      row.emplace_back(std::int64_t(i), diag);
      std::sort(row.begin(), row.end());
      auto k = std::size_t(m.row_start[i]);
      for (const auto& [j, v] : row) {
        m.column[k] = j;
        m.value[k++] = v;
      }
      row.clear();
    };
    for (auto s = cell_start_[std::size_t(c)]; s < cell_start_[std::size_t(c) + 1]; ++s) {
      const auto i = std::size_t(order_[std::size_t(s)]);
      if (len[i] == 1) { // no pair: the row is the zero diagonal
        m.column[std::size_t(m.row_start[i])] = std::int64_t(i);
        m.value[std::size_t(m.row_start[i])] = 0;
      }
    }
    for_each_pair_of_cell(c, [&](std::int64_t s, std::int64_t r, double g) {
      if (s != current) {
        flush();
        current = s;
      }
      row.emplace_back(order_[std::size_t(r)], scale * g * w_[std::size_t(r)]);
    });
    flush();
  });
  return m;
}

} // namespace zdg
