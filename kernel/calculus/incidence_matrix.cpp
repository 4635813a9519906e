#include <zdg/kernel/calculus/incidence_matrix.hpp>

#include <zdg/arith/error.hpp>

#include <algorithm>
#include <string>
#include <tuple>

namespace zdg {

namespace {

std::int64_t checked_add(std::int64_t a, std::int64_t b, std::int64_t row) {
  std::int64_t s = 0;
  if (__builtin_add_overflow(a, b, &s))
    throw OverflowError("incidence matrix: a sum in row " + std::to_string(row) + " leaves int64");
  return s;
}

} // namespace

IncidenceMatrix IncidenceMatrix::from_triplets(std::int64_t rows, std::int64_t cols,
                                               std::vector<IntegerTriplet> triplets) {
  if (rows < 0 || cols < 0)
    throw InvalidArgument("incidence matrix: negative size " + std::to_string(rows) + " x " +
                          std::to_string(cols));
  for (const auto& t : triplets)
    if (t.row < 0 || t.row >= rows || t.col < 0 || t.col >= cols)
      throw InvalidArgument("incidence matrix: entry (" + std::to_string(t.row) + ", " +
                            std::to_string(t.col) + ") outside " + std::to_string(rows) + " x " +
                            std::to_string(cols));
  std::sort(triplets.begin(), triplets.end(), [](const IntegerTriplet& a, const IntegerTriplet& b) {
    return std::tie(a.row, a.col) < std::tie(b.row, b.col);
  });
  IncidenceMatrix m;
  m.rows = rows;
  m.cols = cols;
  m.row_start.assign(std::size_t(rows) + 1, 0);
  for (std::size_t k = 0; k < triplets.size();) {
    std::size_t e = k;
    std::int64_t sum = 0;
    while (e < triplets.size() && triplets[e].row == triplets[k].row &&
           triplets[e].col == triplets[k].col)
      sum = checked_add(sum, triplets[e++].value, triplets[k].row);
    if (sum < -1 || sum > 1)
      throw InvalidArgument("incidence matrix: entry (" + std::to_string(triplets[k].row) + ", " +
                            std::to_string(triplets[k].col) + ") is " + std::to_string(sum) +
                            ", not -1, 0 or +1");
    if (sum != 0) {
      m.column.push_back(triplets[k].col);
      m.value.push_back(static_cast<std::int8_t>(sum));
      ++m.row_start[std::size_t(triplets[k].row) + 1];
    }
    k = e;
  }
  for (std::size_t i = 0; i < std::size_t(rows); ++i) m.row_start[i + 1] += m.row_start[i];
  return m;
}

int IncidenceMatrix::at(std::int64_t i, std::int64_t j) const {
  if (i < 0 || i >= rows || j < 0 || j >= cols) return 0;
  const auto b = column.begin() + row_start[std::size_t(i)];
  const auto e = column.begin() + row_start[std::size_t(i) + 1];
  const auto it = std::lower_bound(b, e, j);
  return it != e && *it == j ? value[std::size_t(it - column.begin())] : 0;
}

IncidenceMatrix IncidenceMatrix::transpose() const {
  IncidenceMatrix t;
  t.rows = cols;
  t.cols = rows;
  t.row_start.assign(std::size_t(cols) + 1, 0);
  for (auto j : column) ++t.row_start[std::size_t(j) + 1];
  for (std::size_t j = 0; j < std::size_t(cols); ++j) t.row_start[j + 1] += t.row_start[j];
  t.column.resize(column.size());
  t.value.resize(value.size());
  std::vector<std::int64_t> next(t.row_start.begin(), t.row_start.end() - 1);
  // Rows of A in increasing order: the columns of each row of A^T come out increasing.
  for (std::int64_t i = 0; i < rows; ++i)
    for (auto k = row_start[std::size_t(i)]; k < row_start[std::size_t(i) + 1]; ++k) {
      const auto pos = std::size_t(next[std::size_t(column[std::size_t(k)])]++);
      t.column[pos] = i;
      t.value[pos] = value[std::size_t(k)];
    }
  return t;
}

IncidenceMatrix IncidenceMatrix::negated() const {
  IncidenceMatrix n = *this;
  for (auto& v : n.value) v = static_cast<std::int8_t>(-v);
  return n;
}

std::vector<std::int64_t> IncidenceMatrix::multiply(std::span<const std::int64_t> x) const {
  if (static_cast<std::int64_t>(x.size()) != cols)
    throw InvalidArgument("incidence matrix: a vector of " + std::to_string(x.size()) +
                          " entries for " + std::to_string(cols) + " columns");
  std::vector<std::int64_t> y(std::size_t(rows), 0);
  for (std::int64_t i = 0; i < rows; ++i) {
    std::int64_t s = 0;
    for (auto k = row_start[std::size_t(i)]; k < row_start[std::size_t(i) + 1]; ++k) {
      const std::int64_t xv = x[std::size_t(column[std::size_t(k)])];
      if (value[std::size_t(k)] < 0 && xv == INT64_MIN)
        throw OverflowError("incidence matrix: -x leaves int64 in row " + std::to_string(i));
      s = checked_add(s, value[std::size_t(k)] > 0 ? xv : -xv, i);
    }
    y[std::size_t(i)] = s;
  }
  return y;
}

std::vector<double> IncidenceMatrix::multiply(std::span<const double> x) const {
  if (static_cast<std::int64_t>(x.size()) != cols)
    throw InvalidArgument("incidence matrix: a vector of " + std::to_string(x.size()) +
                          " entries for " + std::to_string(cols) + " columns");
  std::vector<double> y(std::size_t(rows), 0.0);
  for (std::int64_t i = 0; i < rows; ++i) {
    double s = 0;
    for (auto k = row_start[std::size_t(i)]; k < row_start[std::size_t(i) + 1]; ++k)
      s += value[std::size_t(k)] * x[std::size_t(column[std::size_t(k)])];
    y[std::size_t(i)] = s;
  }
  return y;
}

SparseMatrix IncidenceMatrix::to_real() const {
  SparseMatrix m;
  m.rows = rows;
  m.cols = cols;
  m.row_start = row_start;
  m.column = column;
  m.value.assign(value.begin(), value.end());
  return m;
}

std::int64_t IncidenceMatrix::max_row_nonzeros() const {
  std::int64_t best = 0;
  for (std::size_t i = 0; i < std::size_t(rows); ++i)
    best = std::max(best, row_start[i + 1] - row_start[i]);
  return best;
}

std::vector<IntegerTriplet> integer_product(const IncidenceMatrix& a, const IncidenceMatrix& b) {
  if (a.cols != b.rows)
    throw InvalidArgument("integer product: " + std::to_string(a.rows) + " x " +
                          std::to_string(a.cols) + " times " + std::to_string(b.rows) + " x " +
                          std::to_string(b.cols));
  std::vector<IntegerTriplet> out;
  std::vector<std::int64_t> acc(std::size_t(b.cols), 0);
  std::vector<std::int64_t> touched;
  std::vector<char> seen(std::size_t(b.cols), 0);
  for (std::int64_t i = 0; i < a.rows; ++i) {
    for (auto k = a.row_start[std::size_t(i)]; k < a.row_start[std::size_t(i) + 1]; ++k) {
      const auto r = std::size_t(a.column[std::size_t(k)]);
      const std::int64_t av = a.value[std::size_t(k)];
      for (auto l = b.row_start[r]; l < b.row_start[r + 1]; ++l) {
        const auto j = std::size_t(b.column[std::size_t(l)]);
        acc[j] = checked_add(acc[j], av * b.value[std::size_t(l)], i);
        if (!seen[j]) {
          seen[j] = 1;
          touched.push_back(std::int64_t(j));
        }
      }
    }
    std::sort(touched.begin(), touched.end());
    for (auto j : touched) {
      if (acc[std::size_t(j)] != 0) out.push_back({i, j, acc[std::size_t(j)]});
      acc[std::size_t(j)] = 0;
      seen[std::size_t(j)] = 0;
    }
    touched.clear();
  }
  return out;
}

} // namespace zdg
