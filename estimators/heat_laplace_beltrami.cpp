#include <zdg/estimators/heat_laplace_beltrami.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/parallel_for.hpp>

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

// Four doubles (GCC and clang vector extensions: one AVX register, two SSE2 ones). The helpers
// are inlined into pair_sums, so no 32-byte vector crosses a call (the -Wpsabi note of GCC and
// clang about the AVX calling convention does not apply: CMakeLists.txt turns it off for this
// file).
typedef double V4 __attribute__((vector_size(32)));
typedef std::int64_t I4 __attribute__((vector_size(32)));

// exp(x) for x <= 0 lane by lane (arguments below -700 give exp(-700)): x log2(e) = n + f with
// n = round (the 1.5 2^52 shifter), |f| <= 1/2, 2^n from the exponent bits, e^{f ln 2} by its
// Taylor polynomial of degree 13 (remainder (ln2 / 2)^14 / 14! < 4e-18): a few ulps from
// std::exp. No branch, no call: explicit vector code.
[[gnu::always_inline]] inline V4 exp_nonpositive(V4 x) {
  const V4 low = {-700.0, -700.0, -700.0, -700.0};
  x = x < low ? low : x;
  const V4 y = x * 1.4426950408889634;
  const V4 k = y + 6755399441055744.0; // 1.5 * 2^52
  const V4 n = k - 6755399441055744.0;
  const V4 r = (y - n) * 0.6931471805599453;
  // Estrin's scheme: the 14 terms in pairs, then pairs of pairs by r^2, r^4, r^8: four
  // multiply-adds deep instead of Horner's thirteen, so that the iterations of the caller's
  // loop overlap (Horner's chain of dependent FMAs held the loop at its latency).
  const V4 r2 = r * r;
  const V4 q0 = r + 1.0, q1 = r * (1.0 / 6.0) + 0.5, q2 = r * (1.0 / 120.0) + 1.0 / 24.0,
           q3 = r * (1.0 / 5040.0) + 1.0 / 720.0, q4 = r * (1.0 / 362880.0) + 1.0 / 40320.0,
           q5 = r * (1.0 / 39916800.0) + 1.0 / 3628800.0,
           q6 = r * (1.0 / 6227020800.0) + 1.0 / 479001600.0;
  const V4 r4 = r2 * r2;
  const V4 s0 = r2 * q1 + q0, s1 = r2 * q3 + q2, s2 = r2 * q5 + q4;
  const V4 t0 = r4 * s1 + s0, t1 = r4 * q6 + s2;
  const V4 p = (r4 * r4) * t1 + t0;
  // The low bits of k hold 2^51 + n: (n + 1023) << 52 is 2^n (n >= -1010 here).
  I4 bits;
  std::memcpy(&bits, &k, sizeof bits);
  bits = (bits + 1023) << 52;
  V4 scale;
  std::memcpy(&scale, &bits, sizeof scale);
  return p * scale;
}

// For each of the G surfels s of a group (G <= 4): the sums over r in [b, e) of g(r) w(r) u(r)
// and of g(r) w(r), g = exp(-|x_r - x_s|^2 / (4t)) where |x_r - x_s| <= rho, else 0 (r = s
// included: its terms cancel in a1 - u(s) a0), four centres at a time (the tail padded with
// far-away lanes whose mask is 0). The G surfels share each load of four centres (a fifth of
// the loads of one surfel at a time). Each surfel's sums are those of its own loop, in order.
// GCC on x86-64: an x86-64-v3 (AVX2 + FMA) clone next to the baseline SSE2 one, chosen at load
// time by the CPU (an ifunc); the sums are the same up to rounding.
constexpr int kGroup = 4;
// Positions per block of apply()'s schedule (a multiple of 4: the column sums are stored by
// four).
constexpr std::int64_t kBlock = 256;

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
__attribute__((target_clones("arch=x86-64-v3", "default")))
#endif
void pair_sums(int G, const double* x, const double* y, const double* z, const double* w,
               const double* wu, std::int64_t b, std::int64_t e, const double* xs,
               const double* ys, const double* zs, double r2max, double inv4t, double* a1,
               double* a0) {
  V4 s1[kGroup] = {}, s0[kGroup] = {};
  const V4 zero = {0, 0, 0, 0};
  for (std::int64_t r = b; r < e; r += 4) {
    V4 vx, vy, vz, vw, vwu;
    if (r + 4 <= e) {
      std::memcpy(&vx, x + r, sizeof vx);
      std::memcpy(&vy, y + r, sizeof vy);
      std::memcpy(&vz, z + r, sizeof vz);
      std::memcpy(&vw, w + r, sizeof vw);
      std::memcpy(&vwu, wu + r, sizeof vwu);
    } else {
      for (int i = 0; i < 4; ++i) {
        const bool in = r + i < e;
        vx[i] = in ? x[r + i] : 1e300; // outside the radius of every surfel: masked
        vy[i] = in ? y[r + i] : 0;
        vz[i] = in ? z[r + i] : 0;
        vw[i] = in ? w[r + i] : 0;
        vwu[i] = in ? wu[r + i] : 0;
      }
    }
    for (int g = 0; g < kGroup; ++g) {
      if (g >= G) break;
      const V4 dx = vx - xs[g], dy = vy - ys[g], dz = vz - zs[g];
      const V4 d2 = dx * dx + dy * dy + dz * dz;
      const V4 k = d2 <= r2max ? exp_nonpositive(-d2 * inv4t) : zero;
      s1[g] += k * vwu;
      s0[g] += k * vw;
    }
  }
  for (int g = 0; g < G; ++g) {
    a1[g] += (s1[g][0] + s1[g][1]) + (s1[g][2] + s1[g][3]);
    a0[g] += (s0[g][0] + s0[g][1]) + (s0[g][2] + s0[g][3]);
  }
}

// Both sides of the pairs between a group of G surfels s (G <= 4) and the centres r in [0, m) of
// another block: the rows' sums as in pair_sums (into a1, a0) and the columns' sums
// c1[r] += g w(s) u(s), c0[r] += g w(s) (c1, c0 hold m rounded up to 4 entries), so that every
// exp serves both (s, r) and (r, s).
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
__attribute__((target_clones("arch=x86-64-v3", "default")))
#endif
void pair_sums_both(int G, const double* x, const double* y, const double* z, const double* w,
                    const double* wu, std::int64_t m, const double* xs, const double* ys,
                    const double* zs, const double* ws, const double* wus, double r2max,
                    double inv4t, double* a1, double* a0, double* c1, double* c0) {
  V4 s1[kGroup] = {}, s0[kGroup] = {};
  const V4 zero = {0, 0, 0, 0};
  for (std::int64_t r = 0; r < m; r += 4) {
    V4 vx, vy, vz, vw, vwu;
    if (r + 4 <= m) {
      std::memcpy(&vx, x + r, sizeof vx);
      std::memcpy(&vy, y + r, sizeof vy);
      std::memcpy(&vz, z + r, sizeof vz);
      std::memcpy(&vw, w + r, sizeof vw);
      std::memcpy(&vwu, wu + r, sizeof vwu);
    } else {
      for (int i = 0; i < 4; ++i) {
        const bool in = r + i < m;
        vx[i] = in ? x[r + i] : 1e300; // outside the radius of every surfel: masked
        vy[i] = in ? y[r + i] : 0;
        vz[i] = in ? z[r + i] : 0;
        vw[i] = in ? w[r + i] : 0;
        vwu[i] = in ? wu[r + i] : 0;
      }
    }
    V4 t1 = zero, t0 = zero;
    for (int g = 0; g < kGroup; ++g) {
      if (g >= G) break;
      const V4 dx = vx - xs[g], dy = vy - ys[g], dz = vz - zs[g];
      const V4 d2 = dx * dx + dy * dy + dz * dz;
      const V4 k = d2 <= r2max ? exp_nonpositive(-d2 * inv4t) : zero;
      s1[g] += k * vwu;
      s0[g] += k * vw;
      t1 += k * wus[g];
      t0 += k * ws[g];
    }
    V4 o1, o0;
    std::memcpy(&o1, c1 + r, sizeof o1);
    std::memcpy(&o0, c0 + r, sizeof o0);
    o1 += t1;
    o0 += t0;
    std::memcpy(c1 + r, &o1, sizeof o1);
    std::memcpy(c0 + r, &o0, sizeof o0);
  }
  for (int g = 0; g < G; ++g) {
    a1[g] += (s1[g][0] + s1[g][1]) + (s1[g][2] + s1[g][3]);
    a0[g] += (s0[g][0] + s0[g][1]) + (s0[g][2] + s0[g][3]);
  }
}

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
  round_start_.assign(std::size_t(rounds) + 1, 0);
  for (const auto k : round) ++round_start_[std::size_t(k) + 1];
  std::partial_sum(round_start_.begin(), round_start_.end(), round_start_.begin());
  pairs_.resize(pairs.size());
  std::vector<std::int64_t> fill(round_start_.begin(), round_start_.end() - 1);
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
  const double r2max = rho_ * rho_, inv4t = 1 / (4 * t_);
  // Every pair once: the sums of (s, r) and of (r, s) share their exp. First the pairs within
  // each block (rows only: both orders are in the block, s = r included: its terms cancel in
  // a1 - u(s) a0), then the rounds of pairs of blocks, each block's sums added in round order.
  std::vector<double> a1(n, 0.0), a0(n, 0.0);
  const auto blocks = std::int64_t(block_start_.size()) - 1;
  auto groups = [&](std::int64_t I, auto&& fn) {
    for (auto s = block_start_[std::size_t(I)]; s < block_start_[std::size_t(I) + 1];) {
      const auto G = int(std::min<std::int64_t>(kGroup, block_start_[std::size_t(I) + 1] - s));
      fn(s, G);
      s += G;
    }
  };
  parallel_for(blocks, threads_, [&](std::int64_t I) {
    const auto b = block_start_[std::size_t(I)], e = block_start_[std::size_t(I) + 1];
    groups(I, [&](std::int64_t s, int G) {
      pair_sums(G, x_.data(), y_.data(), z_.data(), w_.data(), wu.data(), b, e, x_.data() + s,
                y_.data() + s, z_.data() + s, r2max, inv4t, a1.data() + s, a0.data() + s);
    });
  });
  for (std::size_t k = 0; k + 1 < round_start_.size(); ++k)
    parallel_for(round_start_[k + 1] - round_start_[k], threads_, [&](std::int64_t p) {
      const auto [I, J] = pairs_[std::size_t(round_start_[k] + p)];
      const auto b = std::size_t(block_start_[std::size_t(J)]);
      const auto m = block_start_[std::size_t(J) + 1] - block_start_[std::size_t(J)];
      double c1[kBlock] = {}, c0[kBlock] = {};
      groups(I, [&](std::int64_t s, int G) {
        pair_sums_both(G, x_.data() + b, y_.data() + b, z_.data() + b, w_.data() + b, wu.data() + b,
                       m, x_.data() + s, y_.data() + s, z_.data() + s, w_.data() + s, wu.data() + s,
                       r2max, inv4t, a1.data() + s, a0.data() + s, c1, c0);
      });
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
