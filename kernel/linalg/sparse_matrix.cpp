#include <zdg/kernel/linalg/sparse_matrix.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace zdg {

SparseMatrix SparseMatrix::from_triplets(std::int64_t rows, std::int64_t cols,
                                         std::vector<SparseTriplet> triplets) {
  if (rows < 0 || cols < 0)
    throw InvalidArgument("sparse matrix: negative size " + std::to_string(rows) + " x " +
                          std::to_string(cols));
  for (const auto& t : triplets) {
    if (t.row < 0 || t.row >= rows || t.col < 0 || t.col >= cols)
      throw InvalidArgument("sparse matrix: entry (" + std::to_string(t.row) + ", " +
                            std::to_string(t.col) + ") outside " + std::to_string(rows) + " x " +
                            std::to_string(cols));
  }
  // Counting sort by row (stable), then each row's entries by column (insertion sort for the
  // short rows of mesh operators, stable_sort past 64): O(nnz + rows) for bounded rows, and
  // duplicates are summed in their input order.
  {
    std::vector<std::int64_t> next(static_cast<std::size_t>(rows) + 1, 0);
    for (const auto& t : triplets) ++next[static_cast<std::size_t>(t.row) + 1];
    for (std::size_t i = 0; i < static_cast<std::size_t>(rows); ++i) next[i + 1] += next[i];
    const std::vector<std::int64_t> first = next;
    std::vector<SparseTriplet> by_row(triplets.size());
    for (const auto& t : triplets) by_row[static_cast<std::size_t>(next[std::size_t(t.row)]++)] = t;
    const auto by_col = [](const SparseTriplet& a, const SparseTriplet& b) {
      return a.col < b.col;
    };
    for (std::size_t r = 0; r < static_cast<std::size_t>(rows); ++r) {
      const auto b = by_row.begin() + first[r], e = by_row.begin() + first[r + 1];
      if (e - b > 64) {
        std::stable_sort(b, e, by_col);
        continue;
      }
      for (auto i = b + (b != e ? 1 : 0); i < e; ++i) {
        const SparseTriplet x = *i;
        auto j = i;
        for (; j > b && x.col < (j - 1)->col; --j) *j = *(j - 1);
        *j = x;
      }
    }
    triplets = std::move(by_row);
  }
  SparseMatrix m;
  m.rows = rows;
  m.cols = cols;
  m.row_start.assign(static_cast<std::size_t>(rows) + 1, 0);
  std::size_t unique = 0;
  for (std::size_t k = 0; k < triplets.size(); ++k)
    unique +=
        k == 0 || triplets[k].row != triplets[k - 1].row || triplets[k].col != triplets[k - 1].col;
  m.column.reserve(unique);
  m.value.reserve(unique);
  for (std::size_t k = 0; k < triplets.size();) {
    std::size_t e = k;
    double v = 0;
    while (e < triplets.size() && triplets[e].row == triplets[k].row &&
           triplets[e].col == triplets[k].col)
      v += triplets[e++].value;
    m.column.push_back(triplets[k].col);
    m.value.push_back(v);
    ++m.row_start[static_cast<std::size_t>(triplets[k].row) + 1];
    k = e;
  }
  for (std::size_t i = 0; i < static_cast<std::size_t>(rows); ++i)
    m.row_start[i + 1] += m.row_start[i];
  return m;
}

SparseMatrix SparseMatrix::diagonal(std::span<const double> d) {
  SparseMatrix m;
  m.rows = m.cols = static_cast<std::int64_t>(d.size());
  m.row_start.resize(d.size() + 1);
  for (std::size_t i = 0; i <= d.size(); ++i) m.row_start[i] = static_cast<std::int64_t>(i);
  m.column.resize(d.size());
  for (std::size_t i = 0; i < d.size(); ++i) m.column[i] = static_cast<std::int64_t>(i);
  m.value.assign(d.begin(), d.end());
  return m;
}

std::vector<double> SparseMatrix::multiply(std::span<const double> x, unsigned threads) const {
  if (static_cast<std::int64_t>(x.size()) != cols)
    throw InvalidArgument("sparse matrix: a vector of " + std::to_string(x.size()) +
                          " entries for " + std::to_string(cols) + " columns");
  std::vector<double> y(static_cast<std::size_t>(rows), 0.0);
  parallel_chunks(rows, threads, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t i = begin; i < end; ++i) {
      double s = 0;
      for (std::int64_t k = row_start[std::size_t(i)]; k < row_start[std::size_t(i) + 1]; ++k)
        s += value[std::size_t(k)] * x[std::size_t(column[std::size_t(k)])];
      y[std::size_t(i)] = s;
    }
  });
  return y;
}

double SparseMatrix::at(std::int64_t i, std::int64_t j) const {
  if (i < 0 || i >= rows || j < 0 || j >= cols) return 0;
  const auto b = column.begin() + row_start[std::size_t(i)];
  const auto e = column.begin() + row_start[std::size_t(i) + 1];
  const auto it = std::lower_bound(b, e, j);
  return it != e && *it == j ? value[std::size_t(it - column.begin())] : 0.0;
}

SparseMatrix SparseMatrix::transpose() const {
  SparseMatrix t;
  t.rows = cols;
  t.cols = rows;
  t.row_start.assign(static_cast<std::size_t>(cols) + 1, 0);
  for (auto c : column) ++t.row_start[std::size_t(c) + 1];
  for (std::size_t j = 0; j < static_cast<std::size_t>(cols); ++j)
    t.row_start[j + 1] += t.row_start[j];
  t.column.resize(column.size());
  t.value.resize(value.size());
  std::vector<std::int64_t> next(t.row_start.begin(), t.row_start.end() - 1);
  for (std::int64_t i = 0; i < rows; ++i) {
    for (std::int64_t k = row_start[std::size_t(i)]; k < row_start[std::size_t(i) + 1]; ++k) {
      const auto p = std::size_t(next[std::size_t(column[std::size_t(k)])]++);
      t.column[p] = i;
      t.value[p] = value[std::size_t(k)];
    }
  }
  return t;
}

double SparseMatrix::asymmetry() const {
  if (rows != cols)
    throw InvalidArgument("sparse matrix: asymmetry of a " + std::to_string(rows) + " x " +
                          std::to_string(cols) + " matrix");
  double worst = 0;
  for (std::int64_t i = 0; i < rows; ++i) {
    for (std::int64_t k = row_start[std::size_t(i)]; k < row_start[std::size_t(i) + 1]; ++k) {
      const double d = std::abs(value[std::size_t(k)] - at(column[std::size_t(k)], i));
      if (!(d <= worst)) worst = d;
    }
  }
  return worst;
}

SparseMatrix add(double s, const SparseMatrix& a, double t, const SparseMatrix& b) {
  if (a.rows != b.rows || a.cols != b.cols)
    throw InvalidArgument("sparse matrix: sum of a " + std::to_string(a.rows) + " x " +
                          std::to_string(a.cols) + " and a " + std::to_string(b.rows) + " x " +
                          std::to_string(b.cols) + " matrix");
  // Row by row, the two sorted column lists merged (the union pattern, no entry dropped, a
  // shared entry s a_ij + t b_ij as the triplets' sum in input order): O(nnz(a) + nnz(b)).
  SparseMatrix out;
  out.rows = a.rows;
  out.cols = a.cols;
  out.row_start.assign(std::size_t(a.rows) + 1, 0);
  out.column.reserve(a.column.size() + b.column.size());
  out.value.reserve(a.column.size() + b.column.size());
  for (std::size_t i = 0; i < std::size_t(a.rows); ++i) {
    auto p = std::size_t(a.row_start[i]), q = std::size_t(b.row_start[i]);
    const auto pe = std::size_t(a.row_start[i + 1]), qe = std::size_t(b.row_start[i + 1]);
    while (p < pe || q < qe) {
      if (q == qe || (p < pe && a.column[p] < b.column[q])) {
        out.column.push_back(a.column[p]);
        out.value.push_back(s * a.value[p++]);
      } else if (p == pe || b.column[q] < a.column[p]) {
        out.column.push_back(b.column[q]);
        out.value.push_back(t * b.value[q++]);
      } else {
        out.column.push_back(a.column[p]);
        out.value.push_back(s * a.value[p++] + t * b.value[q++]);
      }
    }
    out.row_start[i + 1] = std::int64_t(out.column.size());
  }
  return out;
}

} // namespace zdg
