#include <zdg/kernel/calculus/modular_rank.hpp>

#include <zdg/arith/error.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace zdg {

namespace {

bool is_prime(std::uint32_t p) {
  if (p < 2) return false;
  for (std::uint64_t d = 2; d * d <= p; ++d)
    if (p % d == 0) return false;
  return true;
}

std::uint32_t power_mod(std::uint64_t b, std::uint64_t e, std::uint32_t p) {
  std::uint64_t r = 1;
  b %= p;
  while (e) {
    if (e & 1) r = r * b % p;
    b = b * b % p;
    e >>= 1;
  }
  return static_cast<std::uint32_t>(r);
}

struct Entry {
  std::int64_t col;
  std::uint32_t val; ///< in [1, p)
};

} // namespace

std::int64_t rank_mod_p(const IncidenceMatrix& input, std::uint32_t p) {
  if (p >= (std::uint32_t{1} << 31) || !is_prime(p))
    throw InvalidArgument("rank_mod_p: " + std::to_string(p) + " is not a prime below 2^31");
  // The orientation with the shorter rows.
  const bool transpose = input.max_row_nonzeros() > input.transpose().max_row_nonzeros();
  const IncidenceMatrix a = transpose ? input.transpose() : input;
  const auto m = std::size_t(a.rows), n = std::size_t(a.cols);
  std::vector<std::vector<Entry>> rows(m);
  std::vector<std::vector<std::int64_t>> col_rows(n); // may hold stale rows
  std::vector<std::int64_t> col_count(n, 0);          // exact live count
  for (std::size_t i = 0; i < m; ++i)
    for (auto k = a.row_start[i]; k < a.row_start[i + 1]; ++k) {
      const auto j = a.column[std::size_t(k)];
      const int v = a.value[std::size_t(k)];
      rows[i].push_back({j, v > 0 ? std::uint32_t(v) : p - std::uint32_t(-v)});
      col_rows[std::size_t(j)].push_back(std::int64_t(i));
      ++col_count[std::size_t(j)];
    }
  std::int64_t rank = 0;
  std::vector<Entry> merged;
  for (std::size_t r = 0; r < m; ++r) {
    auto& pivot_row = rows[r];
    if (pivot_row.empty()) continue;
    const Entry pivot =
        *std::min_element(pivot_row.begin(), pivot_row.end(), [&](const Entry& x, const Entry& y) {
          return col_count[std::size_t(x.col)] < col_count[std::size_t(y.col)];
        });
    const std::uint64_t inverse = power_mod(pivot.val, p - 2, p);
    ++rank;
    auto& others = col_rows[std::size_t(pivot.col)];
    for (std::size_t t = 0; t < others.size(); ++t) {
      const auto s = std::size_t(others[t]);
      if (s == r) continue;
      auto& row = rows[s];
      const auto it = std::lower_bound(row.begin(), row.end(), pivot.col,
                                       [](const Entry& x, std::int64_t c) { return x.col < c; });
      if (it == row.end() || it->col != pivot.col) continue; // stale
      // row -= factor * pivot_row, factor = row[pivot.col] / pivot.
      const std::uint64_t factor = it->val * inverse % p;
      merged.clear();
      std::size_t i = 0, j = 0;
      while (i < row.size() || j < pivot_row.size()) {
        if (j == pivot_row.size() || (i < row.size() && row[i].col < pivot_row[j].col)) {
          merged.push_back(row[i++]);
        } else {
          const auto c = pivot_row[j].col;
          const std::uint32_t sub = std::uint32_t(factor * pivot_row[j].val % p);
          if (i < row.size() && row[i].col == c) {
            const std::uint32_t v = row[i].val >= sub ? row[i].val - sub : row[i].val + p - sub;
            if (v != 0)
              merged.push_back({c, v});
            else
              --col_count[std::size_t(c)];
            ++i;
          } else {
            merged.push_back({c, p - sub});
            ++col_count[std::size_t(c)];
            col_rows[std::size_t(c)].push_back(std::int64_t(s));
          }
          ++j;
        }
      }
      row.swap(merged);
    }
    for (const auto& e : pivot_row) --col_count[std::size_t(e.col)];
    std::vector<std::int64_t>().swap(others);
    std::vector<Entry>().swap(pivot_row);
  }
  return rank;
}

ExactRank exact_rank(const IncidenceMatrix& a) {
  ExactRank r;
  r.rank_p1 = rank_mod_p(a, 2147483647u);
  r.rank_p2 = rank_mod_p(a, 2147483629u);
  r.rank = std::max(r.rank_p1, r.rank_p2);
  return r;
}

} // namespace zdg
