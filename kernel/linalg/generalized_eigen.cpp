#include <zdg/kernel/linalg/generalized_eigen.hpp>

#include <zdg/arith/error.hpp>

#include <Eigen/Core>
#include <Spectra/SymGEigsShiftSolver.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <span>
#include <string>

namespace zdg {

namespace {

// y = (L - sigma M)^{-1} x by one sparse Cholesky factorization (Spectra's OpType contract:
// Scalar, rows, cols, set_shift, perform_op).
class ShiftInvertOp {
public:
  using Scalar = double;
  ShiftInvertOp(const SparseMatrix& l, const SparseMatrix& m, SpdBackend backend)
      : l_(l), m_(m), backend_(backend) {}
  Eigen::Index rows() const { return l_.rows; }
  Eigen::Index cols() const { return l_.rows; }
  void set_shift(double sigma) {
    // Every Lanczos run at sigma (the deflated ones too) shares one factorization; a run at the
    // mu of the inertia count solves by that count's LDL^T.
    counted_ = solver_ && sigma == mu_ && sigma != sigma_;
    if (counted_ || (solver_ && sigma == sigma_)) return;
    sigma_ = sigma;
    try {
      // Nested dissection: on a surface mesh of 10^6 vertices, a factor with 40% fewer entries
      // than AMD's (the solves, memory bound, take that much less time) and 3x fewer flops (the
      // factorization and the inertia count below): worth its longer analysis.
      solver_.emplace(add(1.0, l_, -sigma, m_), backend_, SpdOrdering::nested_dissection);
    } catch (const InvalidArgument&) {
      throw;
    } catch (const Error& e) {
      throw Error("generalized eigenpairs: L - sigma M (sigma = " + std::to_string(sigma) +
                  ") is not positive definite: L must be positive semi-definite and M positive "
                  "definite (" +
                  e.what() + ")");
    }
  }
  void perform_op(const double* x, double* y) const {
    const auto n = static_cast<std::size_t>(l_.rows);
    std::vector<double> r = counted_ ? solver_->solve_counted(std::span<const double>(x, n))
                                     : solver_->solve(std::span<const double>(x, n));
    // Deflation: r -= V (V^T M r), V the M-orthonormal eigenvectors already found (they become
    // eigenvectors of eigenvalue 0 of the shift-inverted operator, never selected again).
    for (std::size_t j = 0; j < deflated_.size(); ++j) {
      double c = 0;
      for (std::size_t i = 0; i < n; ++i) c += mass_deflated_[j][i] * r[i];
      for (std::size_t i = 0; i < n; ++i) r[i] -= c * deflated_[j][i];
    }
    std::copy(r.begin(), r.end(), y);
    ++solves_;
  }
  /// Projects the M-orthonormal vectors v (and M v) out of every result from now on.
  void deflate(const std::vector<double>& v) {
    deflated_.push_back(v);
    mass_deflated_.push_back(m_.multiply(v));
  }
  std::int64_t solves() const { return solves_; }
  /// The negative inertia of B (the pattern of L - sigma M), on the factorization's analysis.
  /// (b = L - mu M; with the CHOLMOD backend, its LDL^T serves a later run at shift mu).
  std::int64_t negative_inertia(const SparseMatrix& b, double mu) {
    mu_ = std::numeric_limits<double>::quiet_NaN();
    const std::int64_t count = solver_->negative_inertia(b);
    if (solver_->backend() == SpdBackend::cholmod) mu_ = mu;
    return count;
  }
  /// Whether a run at shift mu can solve by the LDL^T of the count.
  bool counted_at(double mu) const { return mu == mu_; }
  SpdBackend backend() const { return solver_->backend(); }

private:
  const SparseMatrix& l_;
  const SparseMatrix& m_;
  SpdBackend backend_;
  std::optional<SparseSpdSolver> solver_;
  double sigma_ = 0;                                     // the shift factored
  double mu_ = std::numeric_limits<double>::quiet_NaN(); // the shift of the LDL^T kept
  bool counted_ = false;                                 // the current run solves by the LDL^T kept
  std::vector<std::vector<double>> deflated_, mass_deflated_;
  mutable std::int64_t solves_ = 0;
};

// y = M x (Spectra's BOpType contract).
class MassOp {
public:
  using Scalar = double;
  explicit MassOp(const SparseMatrix& m) : m_(m) {}
  Eigen::Index rows() const { return m_.rows; }
  Eigen::Index cols() const { return m_.rows; }
  // Row by row into y: Lanczos calls it several times a step (the M inner products), and a
  // vector allocated per call costs page faults at 10^6 unknowns.
  void perform_op(const double* x, double* y) const {
    for (std::size_t i = 0; i < std::size_t(m_.rows); ++i) {
      double s = 0;
      for (auto k = std::size_t(m_.row_start[i]); k < std::size_t(m_.row_start[i + 1]); ++k)
        s += m_.value[k] * x[m_.column[k]];
      y[i] = s;
    }
  }

private:
  const SparseMatrix& m_;
};

double max_abs(const SparseMatrix& a) {
  double out = 0;
  for (double v : a.value) out = std::max(out, std::abs(v));
  return out;
}

void check_symmetric(const SparseMatrix& a, const char* name) {
  const double scale = max_abs(a);
  const double asym = a.asymmetry();
  if (!(asym <= 1e-10 * scale)) {
    throw InvalidArgument(std::string("generalized eigenpairs: ") + name +
                          " is not symmetric (max |a_ij - a_ji| = " + std::to_string(asym) +
                          ", max |a_ij| = " + std::to_string(scale) + ")");
  }
}

} // namespace

GeneralizedEigenpairs smallest_generalized_eigenpairs(const SparseMatrix& l, const SparseMatrix& m,
                                                      std::int64_t k,
                                                      const GeneralizedEigenOptions& options) {
  const std::string what = "generalized eigenpairs: ";
  if (l.rows != l.cols) {
    throw InvalidArgument(what + "L is not square (" + std::to_string(l.rows) + " x " +
                          std::to_string(l.cols) + ")");
  }
  if (m.rows != m.cols || m.rows != l.rows) {
    throw InvalidArgument(what + "M is " + std::to_string(m.rows) + " x " + std::to_string(m.cols) +
                          ", L is " + std::to_string(l.rows) + " x " + std::to_string(l.cols) +
                          ": sizes differ");
  }
  const std::int64_t n = l.rows;
  if (k < 1 || k >= n) {
    throw InvalidArgument(what + "k = " + std::to_string(k) + " eigenpairs of a " +
                          std::to_string(n) + " x " + std::to_string(n) +
                          " problem: need 1 <= k < n");
  }
  if (!(options.shift <= 0) || !std::isfinite(options.shift)) {
    throw InvalidArgument(what + "shift " + std::to_string(options.shift) +
                          " must be negative (0: the default)");
  }
  if (options.subspace != 0 && (options.subspace <= k || options.subspace > n)) {
    throw InvalidArgument(what + "subspace dimension " + std::to_string(options.subspace) +
                          " must be in (k, n] = (" + std::to_string(k) + ", " + std::to_string(n) +
                          "]");
  }
  if (options.max_iterations < 1 || !(options.tolerance > 0)) {
    throw InvalidArgument(what + "max_iterations must be >= 1 and tolerance > 0");
  }
  check_symmetric(l, "L");
  check_symmetric(m, "M");
  double top = 0;
  for (std::int64_t i = 0; i < n; ++i) {
    const double mi = m.at(i, i);
    if (!(mi > 0)) {
      throw InvalidArgument(what + "M is not positive definite (M_" + std::to_string(i) + "," +
                            std::to_string(i) + " = " + std::to_string(mi) + ")");
    }
    top = std::max(top, std::abs(l.at(i, i)) / mi);
  }
  const double sigma = options.shift < 0 ? options.shift : -1e-6 * (top > 0 ? top : 1.0);
  const std::int64_t ncv = options.subspace != 0
                               ? options.subspace
                               : std::min<std::int64_t>(n, std::max<std::int64_t>(2 * k + 1, 20));

  ShiftInvertOp op(l, m, options.backend);
  MassOp mass(m);
  GeneralizedEigenpairs out;
  std::int64_t restarts = 0;
  // One Lanczos run for `want` pairs, deflated by every vector found so far; its pairs are
  // M-orthogonalized against those and each other (Gram-Schmidt, twice) and merged in increasing
  // order.
  //
  // A run at shift mu (the certificate's, solving by its LDL^T) looks for missing eigenvalues
  // next to mu: a small subspace (2 want + 10), no retry, and a pair is kept only when its
  // residual is small (||L x - rho M x|| <= 1e-6 (||L x|| + |rho| ||M x||)), since the LDL^T has
  // no pivoting; whatever it misses, a run at sigma finds.
  const auto run = [&](std::int64_t want, double shift) {
    const bool at_sigma = shift == sigma;
    // A subspace too small for a cluster may not converge: it is doubled (up to n) and retried.
    Eigen::VectorXd values;
    Eigen::MatrixXd vectors;
    const std::int64_t first = at_sigma ? std::max(ncv, 2 * want + 1) : 2 * want + 10;
    for (std::int64_t basis = std::min<std::int64_t>(n, first);;
         basis = std::min<std::int64_t>(n, 2 * basis)) {
      Spectra::SymGEigsShiftSolver<ShiftInvertOp, MassOp, Spectra::GEigsMode::ShiftInvert> eigs(
          op, mass, want, basis, shift);
      eigs.init();
      // At mu, the missing eigenvalues are the only ones below mu left (1 / (lambda - mu) < 0):
      // the operator's smallest (most negative) eigenvalues.
      eigs.compute(at_sigma ? Spectra::SortRule::LargestMagn : Spectra::SortRule::SmallestAlge,
                   options.max_iterations, options.tolerance, Spectra::SortRule::SmallestAlge);
      restarts += eigs.num_iterations();
      if (eigs.info() == Spectra::CompInfo::Successful) {
        values = eigs.eigenvalues();
        vectors = eigs.eigenvectors();
        break;
      }
      if (!at_sigma) return;
      if (basis == n || basis >= 8 * first) {
        throw Error(what + "Lanczos did not converge (" + std::to_string(want) + " eigenpairs, " +
                    std::to_string(eigs.num_iterations()) + " restarts, subspace " +
                    std::to_string(basis) + ", tolerance " + std::to_string(options.tolerance) +
                    ")");
      }
    }
    const std::size_t before = out.vectors.size();
    std::vector<std::vector<double>> mass_before;
    for (std::size_t q = 0; q < before; ++q) mass_before.push_back(m.multiply(out.vectors[q]));
    const auto m_norm2 = [&](const std::vector<double>& x) {
      const std::vector<double> mx = m.multiply(x);
      double s = 0;
      for (std::int64_t i = 0; i < n; ++i) s += mx[std::size_t(i)] * x[std::size_t(i)];
      return s;
    };
    for (Eigen::Index j = 0; j < values.size(); ++j) {
      std::vector<double> x(vectors.col(j).data(), vectors.col(j).data() + n);
      // Spectra's vectors are not always M-normalized (seen when the subspace is all of R^n):
      // the length is measured before and after the projection.
      const double norm0 = m_norm2(x);
      if (!(norm0 > 0) || !std::isfinite(norm0) || !std::isfinite(values(j))) {
        if (!at_sigma) continue; // the LDL^T's rounding: a run at sigma follows
        throw Error(what + "Lanczos returned a zero or non-finite eigenvector");
      }
      for (int pass = 0; pass < 2; ++pass) {
        for (std::size_t q = 0; q < out.vectors.size(); ++q) {
          double c = 0;
          for (std::int64_t i = 0; i < n; ++i)
            c += mass_before[q][std::size_t(i)] * x[std::size_t(i)];
          for (std::int64_t i = 0; i < n; ++i)
            x[std::size_t(i)] -= c * out.vectors[q][std::size_t(i)];
        }
      }
      const double norm = m_norm2(x);
      if (!(norm > 0.25 * norm0)) continue; // a copy of a vector found before: dropped
      for (double& v : x) v /= std::sqrt(norm);
      mass_before.push_back(m.multiply(x));
      // The value is x's Rayleigh quotient x^T L x (x^T M x = 1): Spectra's Ritz value was seen
      // wrong (2 for L = M = I) when the Krylov space breaks down on a single eigenspace.
      const std::vector<double> lx = l.multiply(x);
      double rayleigh = 0;
      for (std::int64_t i = 0; i < n; ++i) rayleigh += lx[std::size_t(i)] * x[std::size_t(i)];
      if (!at_sigma) {
        const std::vector<double>& mx = mass_before.back();
        double r2 = 0, l2 = 0, m2 = 0;
        for (std::size_t i = 0; i < std::size_t(n); ++i) {
          const double r = lx[i] - rayleigh * mx[i];
          r2 += r * r;
          l2 += lx[i] * lx[i];
          m2 += mx[i] * mx[i];
        }
        if (!(std::sqrt(r2) <= 1e-6 * (std::sqrt(l2) + std::abs(rayleigh) * std::sqrt(m2)))) {
          mass_before.pop_back();
          continue;
        }
      }
      out.values.push_back(rayleigh);
      out.vectors.push_back(std::move(x));
    }
    for (std::size_t q = before; q < out.vectors.size(); ++q) op.deflate(out.vectors[q]);
    std::vector<std::size_t> order(out.values.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return out.values[a] < out.values[b]; });
    GeneralizedEigenpairs sorted;
    for (const std::size_t j : order) {
      sorted.values.push_back(out.values[j]);
      sorted.vectors.push_back(std::move(out.vectors[j]));
    }
    out.values = std::move(sorted.values);
    out.vectors = std::move(sorted.vectors);
  };
  // Lanczos may miss copies of a multiple eigenvalue. Certificate (Sylvester's law of inertia):
  // the number of eigenvalues below mu = lambda_k (1 - 1e-6) is the inertia of L - mu M, counted
  // once; while it exceeds the number found below mu, a deflated run looks for the missing ones
  // (they are the smallest eigenvalues of the deflated problem). When every eigenvalue below mu
  // is found, so are the first k: the k-th found is at most lambda_k, and mu is the count's.
  run(k, sigma);
  double mu = 0;
  bool tried_mu = false;
  std::int64_t below = -1;
  for (int round = 0;; ++round) {
    const auto room = n - static_cast<std::int64_t>(out.values.size()) - 1;
    if (static_cast<std::int64_t>(out.values.size()) < k) {
      // A run returned copies of one vector (dropped above): the rest is asked for again.
      if (round > k || room < 1)
        throw Error(what + "Lanczos found " + std::to_string(out.values.size()) + " of " +
                    std::to_string(k) + " independent eigenvectors");
      run(std::min(k - static_cast<std::int64_t>(out.values.size()), room), sigma);
      continue;
    }
    if (below < 0) {
      const double lk = out.values[std::size_t(k - 1)];
      // A pivot of exactly 0 in the elimination order fails the LDL^T: another mu a little
      // lower (the count below it is the same unless an eigenvalue lies in between) is tried.
      for (int attempt = 0; attempt < 4 && below < 0; ++attempt) {
        mu = lk - 1e-6 * double(1 << attempt) * std::max(std::abs(lk), std::abs(sigma));
        if (!(mu > 0)) {
          below = 0; // L is positive semi-definite: no eigenvalue below mu <= 0
          break;
        }
        try {
          below = op.negative_inertia(add(1.0, l, -mu, m), mu);
        } catch (const InvalidArgument&) {
          throw;
        } catch (const Error&) {
          if (attempt == 3) throw;
        }
      }
    }
    const auto found_below = static_cast<std::int64_t>(
        std::lower_bound(out.values.begin(), out.values.end(), mu) - out.values.begin());
    if (below <= found_below) break;
    if (round > k || room < 1) {
      throw Error(what + std::to_string(below) + " eigenvalues lie below " + std::to_string(mu) +
                  " (inertia of L - mu M) but Lanczos found " + std::to_string(found_below) +
                  " after " + std::to_string(round) + " deflated runs");
    }
    // One copy of each multiple eigenvalue per run (a Krylov space sees one per eigenspace):
    // ask for the missing ones only, so that every pair asked for exists in the deflated space.
    // First a run at mu by the count's LDL^T (the missing copies of a cluster that straddles
    // lambda_k lie next to mu), then runs at sigma.
    const bool at_mu = !tried_mu && op.counted_at(mu);
    tried_mu = tried_mu || at_mu;
    run(std::min(below - found_below, room), at_mu ? mu : sigma);
  }
  out.values.resize(std::size_t(k));
  out.vectors.resize(std::size_t(k));
  out.shift = sigma;
  out.iterations = restarts;
  out.operations = op.solves();
  out.backend = op.backend();
  return out;
}

} // namespace zdg
