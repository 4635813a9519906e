#include <zdg/estimators/heat_laplace_beltrami.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/parallel_for.hpp>

#include <algorithm>
#include <array>
#include <cmath>
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
}

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
  const auto cells = std::int64_t(cell_start_.size()) - 1;
  parallel_for(cells, threads_, [&](std::int64_t c) {
    // Per surfel s: sum g w(r) u(r) - u(s) sum g w(r), accumulated over its pairs in order.
    std::int64_t current = -1;
    double a1 = 0, a0 = 0;
    auto flush = [&] {
      if (current >= 0)
        out[std::size_t(order_[std::size_t(current)])] =
            scale * (a1 - us[std::size_t(current)] * a0);
    };
    for (auto s = cell_start_[std::size_t(c)]; s < cell_start_[std::size_t(c) + 1]; ++s)
      out[std::size_t(order_[std::size_t(s)])] = 0; // surfels without a pair
    for_each_pair_of_cell(c, [&](std::int64_t s, std::int64_t r, double g) {
      if (s != current) {
        flush();
        current = s;
        a1 = a0 = 0;
      }
      a1 += g * wu[std::size_t(r)];
      a0 += g * w_[std::size_t(r)];
    });
    flush();
  });
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
