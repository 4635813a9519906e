#include <zdg/kernel/linalg/sparse_spd_solver.hpp>

#include <zdg/arith/error.hpp>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#ifdef ZDG_HAVE_CHOLMOD
#include <cholmod.h>
#include <dlfcn.h>
#endif

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>

namespace zdg {

namespace {

using EigenSparse = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

EigenSparse to_eigen(const SparseMatrix& a) {
  constexpr auto limit = std::int64_t{std::numeric_limits<int>::max()};
  if (a.rows >= limit || a.nonzeros() >= limit)
    throw InvalidArgument("sparse solver: " + std::to_string(a.rows) + " unknowns and " +
                          std::to_string(a.nonzeros()) +
                          " nonzeros exceed the 32-bit indices of the factorization");
  // The compressed columns of A by one counting pass over its rows (row indices increasing in
  // each column): O(n + nnz).
  EigenSparse m(int(a.rows), int(a.cols));
  m.resizeNonZeros(Eigen::Index(a.nonzeros()));
  int* outer = m.outerIndexPtr();
  std::fill(outer, outer + a.cols + 1, 0);
  for (const auto c : a.column) ++outer[c + 1];
  for (std::int64_t j = 0; j < a.cols; ++j) outer[j + 1] += outer[j];
  std::vector<int> next(outer, outer + a.cols);
  for (std::int64_t i = 0; i < a.rows; ++i) {
    for (auto k = a.row_start[std::size_t(i)]; k < a.row_start[std::size_t(i) + 1]; ++k) {
      const int at = next[std::size_t(a.column[std::size_t(k)])]++;
      m.innerIndexPtr()[at] = int(i);
      m.valuePtr()[at] = a.value[std::size_t(k)];
    }
  }
  return m;
}

#ifdef ZDG_HAVE_CHOLMOD
#define ZDG_CHOLMOD_STR2(x) #x
#define ZDG_CHOLMOD_STR(x) ZDG_CHOLMOD_STR2(x)
// The library of the ABI of the header compiled against (SuiteSparse names it by CHOLMOD's
// major version: libcholmod.so.3 for CHOLMOD 3.0 in Debian 12).
constexpr const char* kCholmodSoname = "libcholmod.so." ZDG_CHOLMOD_STR(CHOLMOD_MAIN_VERSION);

// CHOLMOD is loaded at its first use (dlopen), not linked: linked, it and what it brings (OpenBLAS,
// LAPACK, METIS, libgfortran, libgomp, AMD and the other orderings) were loaded and relocated by
// every process that links zdg, whether it solves anything or not: `zdg --version` took 24-28 ms
// with them and 12.7-15 ms without on the development VM (perf stat, 30-40 runs, alternating).
// The functions are looked up once; the handle stays open for the process's life.
struct CholmodApi {
  decltype(&cholmod_start) start = nullptr;
  decltype(&cholmod_finish) finish = nullptr;
  decltype(&cholmod_analyze) analyze = nullptr;
  decltype(&cholmod_factorize_p) factorize_p = nullptr;
  decltype(&cholmod_solve) solve = nullptr;
  decltype(&cholmod_free_factor) free_factor = nullptr;
  decltype(&cholmod_free_dense) free_dense = nullptr;
  // BLAS's dgemm (Fortran ABI, 32-bit integers), from the BLAS CHOLMOD itself loads: the
  // supernodal LDL^T of the inertia count below.
  using Dgemm = void (*)(const char*, const char*, const int*, const int*, const int*,
                         const double*, const double*, const int*, const double*, const int*,
                         const double*, double*, const int*);
  Dgemm dgemm = nullptr;
  std::string error; // why it could not be loaded; empty when it was
};

const CholmodApi& cholmod_api() {
  static const CholmodApi api = [] {
    CholmodApi a;
    void* h = ::dlopen(kCholmodSoname, RTLD_NOW | RTLD_LOCAL);
    if (h == nullptr) {
      const char* e = ::dlerror();
      a.error = e != nullptr ? e : kCholmodSoname;
      return a;
    }
    const auto find = [&](auto& fn, const char* name) {
      fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(::dlsym(h, name));
      if (fn == nullptr && a.error.empty())
        a.error = std::string(kCholmodSoname) + " has no function " + name;
    };
    find(a.start, "cholmod_start");
    find(a.finish, "cholmod_finish");
    find(a.analyze, "cholmod_analyze");
    find(a.factorize_p, "cholmod_factorize_p");
    find(a.solve, "cholmod_solve");
    find(a.free_factor, "cholmod_free_factor");
    find(a.free_dense, "cholmod_free_dense");
    find(a.dgemm, "dgemm_"); // dlsym searches the library's dependencies too
    return a;
  }();
  return api;
}

// A supernodal L L^T factorization of the lower triangle (what Eigen's CholmodSupernodalLLT
// does, called through the functions loaded above): one ordering (AMD, or METIS's nested
// dissection when asked for), not CHOLMOD's default search over AMD, METIS and NESDIS, so that
// the analysis is a small part of the cost on the surface meshes here.
class CholmodFactor {
public:
  CholmodFactor(const CholmodApi& api, SpdOrdering ordering) : api_(api) {
    api_.start(&common_);
    // CHOLMOD prints its own warnings with printf, on stdout (a matrix that is not positive
    // definite, ...), where a command's --json goes; zdg reports every failure itself: off.
    common_.print = 0;
    common_.final_asis = 1;
    common_.supernodal = CHOLMOD_SUPERNODAL;
    common_.nmethods = 1;
    common_.method[0].ordering =
        ordering == SpdOrdering::nested_dissection ? CHOLMOD_METIS : CHOLMOD_AMD;
    common_.postorder = 1;
  }
  ~CholmodFactor() {
    if (factor_ != nullptr) api_.free_factor(&factor_, &common_);
    api_.finish(&common_);
  }
  CholmodFactor(const CholmodFactor&) = delete;
  CholmodFactor& operator=(const CholmodFactor&) = delete;

  void analyze(const EigenSparse& m) {
    auto a = view(m);
    factor_ = api_.analyze(&a, &common_);
    if (factor_ == nullptr)
      throw Error("sparse solver (cholmod): the analysis failed (status " +
                  std::to_string(common_.status) + ")");
  }
  void factorize(const EigenSparse& m) {
    auto a = view(m);
    double beta[2] = {0.0, 0.0};
    const int ok = api_.factorize_p(&a, beta, nullptr, 0, factor_, &common_);
    // On success minor == n; otherwise minor is the column where it failed.
    if (ok == 0 || factor_->minor != factor_->n)
      throw Error("sparse solver (cholmod): the factorization failed (the matrix is not "
                  "symmetric positive definite)");
  }
  Eigen::VectorXd solve(const Eigen::Map<const Eigen::VectorXd>& b) const {
    cholmod_dense rhs{};
    rhs.nrow = rhs.nzmax = rhs.d = static_cast<std::size_t>(b.size());
    rhs.ncol = 1;
    rhs.x = const_cast<double*>(b.data()); // read only
    rhs.xtype = CHOLMOD_REAL;
    rhs.dtype = CHOLMOD_DOUBLE;
    cholmod_dense* x = api_.solve(CHOLMOD_A, factor_, &rhs, &common_);
    if (x == nullptr)
      throw Error("sparse solver (cholmod): the solve failed (status " +
                  std::to_string(common_.status) + ")");
    Eigen::VectorXd out =
        Eigen::Map<const Eigen::VectorXd>(static_cast<const double*>(x->x), b.size());
    api_.free_dense(&x, &common_);
    return out;
  }

  // The negative pivots of B's LDL^T (no pivoting) on the supernodal structure of the factor
  // (B has the pattern analysed): left-looking, the supernodes in order; each is assembled from
  // B's lower triangle (permuted by the analysis's ordering), updated by every descendant d
  // (L_d D_d L_d^T restricted to its rows, one dgemm), then factored as a dense panel (blocks of
  // 32 columns, the trailing columns by dgemm). Only the signs of D are kept.
  std::int64_t negative_inertia(const SparseMatrix& b) const {
    ldl_ = {}; // a count that fails keeps no factor (solve_counted then refuses)
    const cholmod_factor& f = *factor_;
    if (!f.is_super) throw Error("inertia (cholmod): the factor is not supernodal");
    const auto n = static_cast<int>(f.n);
    const auto nsuper = static_cast<int>(f.nsuper);
    const auto* super = static_cast<const int*>(f.super);
    const auto* pi = static_cast<const int*>(f.pi);
    const auto* px = static_cast<const int*>(f.px);
    const auto* ls = static_cast<const int*>(f.s);
    const auto* perm = static_cast<const int*>(f.Perm);
    std::vector<int> pinv(std::size_t(n), 0);
    for (int k = 0; k < n; ++k) pinv[std::size_t(perm[k])] = k;
    // B's lower triangle, permuted, by columns: entry (r, c), r >= c, goes to column min(pinv).
    std::vector<int> cp(std::size_t(n) + 1, 0), ci;
    std::vector<double> cx;
    for (int pass = 0; pass < 2; ++pass) {
      std::vector<int> fill;
      if (pass == 1) {
        for (int j = 0; j < n; ++j) cp[std::size_t(j) + 1] += cp[std::size_t(j)];
        ci.resize(std::size_t(cp[std::size_t(n)]));
        cx.resize(ci.size());
        fill.assign(cp.begin(), cp.end() - 1);
      }
      for (int r = 0; r < n; ++r) {
        for (auto q = b.row_start[std::size_t(r)]; q < b.row_start[std::size_t(r) + 1]; ++q) {
          const auto c = static_cast<int>(b.column[std::size_t(q)]);
          if (c > r) continue;
          const int pr = pinv[std::size_t(r)], pc = pinv[std::size_t(c)];
          const int j = std::min(pr, pc);
          if (pass == 0) {
            ++cp[std::size_t(j) + 1];
          } else {
            const auto at = std::size_t(fill[std::size_t(j)]++);
            ci[at] = std::max(pr, pc);
            cx[at] = b.value[std::size_t(q)];
          }
        }
      }
    }
    std::vector<int> super_of(std::size_t(n), 0);
    for (int s = 0; s < nsuper; ++s)
      for (int k = super[s]; k < super[s + 1]; ++k) super_of[std::size_t(k)] = s;
    std::vector<double> lx(f.xsize, 0.0), w, c;
    std::vector<int> map(std::size_t(n), 0), head(std::size_t(nsuper), -1),
        next(std::size_t(nsuper), -1), pos(std::size_t(nsuper), 0);
    const auto link = [&](int d, int p) { // d updates the supernode of its p-th row next
      pos[std::size_t(d)] = p;
      if (p < pi[d + 1] - pi[d]) {
        const int t = super_of[std::size_t(ls[pi[d] + p])];
        next[std::size_t(d)] = head[std::size_t(t)];
        head[std::size_t(t)] = d;
      }
    };
    const char no = 'N', tr = 'T';
    const double one = 1, minus_one = -1, zero = 0;
    std::int64_t negative = 0;
    for (int s = 0; s < nsuper; ++s) {
      const int k1 = super[s], k2 = super[s + 1], ncol = k2 - k1, nrow = pi[s + 1] - pi[s];
      const int* rows = ls + pi[s];
      double* a = lx.data() + px[s]; // nrow x ncol, column-major
      for (int p = 0; p < nrow; ++p) map[std::size_t(rows[p])] = p;
      for (int j = k1; j < k2; ++j)
        for (int q = cp[std::size_t(j)]; q < cp[std::size_t(j) + 1]; ++q)
          a[std::size_t(j - k1) * std::size_t(nrow) +
            std::size_t(map[std::size_t(ci[std::size_t(q)])])] += cx[std::size_t(q)];
      for (int d = head[std::size_t(s)]; d != -1;) {
        const int d_next = next[std::size_t(d)];
        const int dcol = super[d + 1] - super[d], drow = pi[d + 1] - pi[d];
        const int* drows = ls + pi[d];
        const double* ld = lx.data() + px[d];
        const int p1 = pos[std::size_t(d)];
        int p2 = p1;
        while (p2 < drow && drows[p2] < k2) ++p2;
        const int m1 = p2 - p1, m2 = drow - p1;
        // W = L_d(p1:p2, :) D_d, C = L_d(p1:, :) W^T.
        w.resize(std::size_t(m1) * std::size_t(dcol));
        for (int j = 0; j < dcol; ++j) {
          const double dj = ld[std::size_t(j) * std::size_t(drow) + std::size_t(j)];
          for (int i = 0; i < m1; ++i)
            w[std::size_t(j) * std::size_t(m1) + std::size_t(i)] =
                ld[std::size_t(j) * std::size_t(drow) + std::size_t(p1 + i)] * dj;
        }
        c.resize(std::size_t(m2) * std::size_t(m1));
        api_.dgemm(&no, &tr, &m2, &m1, &dcol, &one, ld + p1, &drow, w.data(), &m1, &zero, c.data(),
                   &m2);
        for (int j = 0; j < m1; ++j) {
          double* col = a + std::size_t(drows[p1 + j] - k1) * std::size_t(nrow);
          for (int i = j; i < m2; ++i)
            col[map[std::size_t(drows[p1 + i])]] -=
                c[std::size_t(j) * std::size_t(m2) + std::size_t(i)];
        }
        link(d, p2);
        d = d_next;
      }
      // The panel: LDL^T of the diagonal block, L below it, in blocks of 32 columns.
      const auto at = [&](int i, int j) -> double& {
        return a[std::size_t(j) * std::size_t(nrow) + std::size_t(i)];
      };
      for (int kb = 0; kb < ncol; kb += 32) {
        const int ke = std::min(ncol, kb + 32);
        for (int j = kb; j < ke; ++j) {
          const double dj = at(j, j);
          if (!std::isfinite(dj) || dj == 0)
            throw Error("inertia: pivot " + std::to_string(k1 + j) + " is " + std::to_string(dj) +
                        " (the matrix or a leading minor is singular)");
          if (dj < 0) ++negative;
          for (int k = j + 1; k < ke; ++k) {
            const double lkj = at(k, j) / dj;
            for (int i = k; i < nrow; ++i) at(i, k) -= at(i, j) * lkj;
          }
          for (int i = j + 1; i < nrow; ++i) at(i, j) /= dj;
        }
        const int rest = ncol - ke, below = nrow - ke, width = ke - kb;
        if (rest <= 0) continue;
        w.resize(std::size_t(rest) * std::size_t(width));
        for (int j = kb; j < ke; ++j)
          for (int i = 0; i < rest; ++i)
            w[std::size_t(j - kb) * std::size_t(rest) + std::size_t(i)] = at(ke + i, j) * at(j, j);
        api_.dgemm(&no, &tr, &below, &rest, &width, &minus_one, &at(ke, kb), &nrow, w.data(), &rest,
                   &one, &at(ke, ke), &nrow);
      }
      link(s, ncol);
    }
    ldl_ = std::move(lx);
    return negative;
  }

  // x with B x = b, B the last matrix counted (its LDL^T kept): the permuted right-hand side,
  // L y = b column by column, D, L^T x = y, permuted back. O(nnz(L)).
  Eigen::VectorXd solve_counted(const Eigen::Map<const Eigen::VectorXd>& b) const {
    if (ldl_.empty())
      throw InvalidArgument("sparse solver: no inertia counted, no LDL^T to solve by");
    const cholmod_factor& f = *factor_;
    const auto* super = static_cast<const int*>(f.super);
    const auto* pi = static_cast<const int*>(f.pi);
    const auto* px = static_cast<const int*>(f.px);
    const auto* ls = static_cast<const int*>(f.s);
    const auto* perm = static_cast<const int*>(f.Perm);
    const auto n = static_cast<Eigen::Index>(f.n);
    const auto nsuper = static_cast<int>(f.nsuper);
    Eigen::VectorXd y(n);
    for (Eigen::Index k = 0; k < n; ++k) y[k] = b[perm[k]];
    for (int s = 0; s < nsuper; ++s) {
      const int k1 = super[s], ncol = super[s + 1] - k1, nrow = pi[s + 1] - pi[s];
      const int* rows = ls + pi[s];
      for (int j = 0; j < ncol; ++j) {
        const double* col = ldl_.data() + px[s] + std::size_t(j) * std::size_t(nrow);
        const double yj = y[k1 + j];
        for (int i = j + 1; i < nrow; ++i) y[rows[i]] -= col[i] * yj;
      }
    }
    for (int s = nsuper - 1; s >= 0; --s) {
      const int k1 = super[s], ncol = super[s + 1] - k1, nrow = pi[s + 1] - pi[s];
      const int* rows = ls + pi[s];
      for (int j = ncol - 1; j >= 0; --j) {
        const double* col = ldl_.data() + px[s] + std::size_t(j) * std::size_t(nrow);
        double v = y[k1 + j] / col[j];
        for (int i = j + 1; i < nrow; ++i) v -= col[i] * y[rows[i]];
        y[k1 + j] = v;
      }
    }
    Eigen::VectorXd x(n);
    for (Eigen::Index k = 0; k < n; ++k) x[perm[k]] = y[k];
    return x;
  }

private:
  // The matrix as CHOLMOD's compressed-column view of its lower triangle (stype -1), no copy.
  static cholmod_sparse view(const EigenSparse& m) {
    cholmod_sparse a{};
    a.nrow = static_cast<std::size_t>(m.rows());
    a.ncol = static_cast<std::size_t>(m.cols());
    a.nzmax = static_cast<std::size_t>(m.nonZeros());
    a.p = const_cast<int*>(m.outerIndexPtr()); // CHOLMOD reads A only
    a.i = const_cast<int*>(m.innerIndexPtr());
    a.x = const_cast<double*>(m.valuePtr());
    a.stype = -1;
    a.itype = CHOLMOD_INT;
    a.xtype = CHOLMOD_REAL;
    a.dtype = CHOLMOD_DOUBLE;
    a.sorted = 1;
    a.packed = 1;
    return a;
  }
  const CholmodApi& api_;
  mutable std::vector<double> ldl_; // the LDL^T of the last matrix counted
  mutable cholmod_common common_{}; // CHOLMOD's workspace, also used by the solves
  cholmod_factor* factor_ = nullptr;
};
#endif

} // namespace

std::string spd_backend_name(SpdBackend backend) {
  switch (backend) {
  case SpdBackend::cholmod:
    return "cholmod";
  case SpdBackend::eigen_ldlt:
    return "eigen-simplicial-ldlt";
  default:
    return "automatic";
  }
}

struct SparseSpdSolver::Impl {
  std::int64_t n = 0;
  SpdBackend backend = SpdBackend::eigen_ldlt;
  SpdOrdering ordering = SpdOrdering::minimum_degree;
  std::vector<std::int64_t> row_start, column; // the pattern analysed
  void factor(const EigenSparse& m, bool analyse);
  std::optional<Eigen::SimplicialLDLT<EigenSparse>> ldlt;
#ifdef ZDG_HAVE_CHOLMOD
  std::optional<CholmodFactor> cholmod;
#endif
};

bool SparseSpdSolver::cholmod_available() {
#ifdef ZDG_HAVE_CHOLMOD
  return cholmod_api().error.empty();
#else
  return false;
#endif
}

std::string SparseSpdSolver::cholmod_library() {
#ifdef ZDG_HAVE_CHOLMOD
  return kCholmodSoname;
#else
  return {};
#endif
}

SparseSpdSolver::SparseSpdSolver(const SparseMatrix& a, SpdBackend backend, SpdOrdering ordering)
    : impl_(std::make_unique<Impl>()) {
  if (a.rows != a.cols)
    throw InvalidArgument("sparse solver: the matrix is " + std::to_string(a.rows) + " x " +
                          std::to_string(a.cols) + ", not square");
  if (backend == SpdBackend::cholmod && !cholmod_available()) {
#ifdef ZDG_HAVE_CHOLMOD
    throw InvalidArgument("sparse solver: CHOLMOD could not be loaded (" + cholmod_api().error +
                          ")");
#else
    throw InvalidArgument("sparse solver: zdg was built without CHOLMOD (ZDG_CHOLMOD=OFF or "
                          "libsuitesparse-dev missing)");
#endif
  }
  impl_->n = a.rows;
  impl_->ordering = ordering;
  impl_->row_start = a.row_start;
  impl_->column = a.column;
  const bool use_cholmod =
      backend == SpdBackend::cholmod || (backend == SpdBackend::automatic && cholmod_available());
  impl_->backend = use_cholmod ? SpdBackend::cholmod : SpdBackend::eigen_ldlt;
  impl_->factor(to_eigen(a), true);
}

void SparseSpdSolver::Impl::factor(const EigenSparse& m, bool analyse) {
#ifdef ZDG_HAVE_CHOLMOD
  if (backend == SpdBackend::cholmod) {
    if (analyse) {
      cholmod.emplace(cholmod_api(), ordering);
      cholmod->analyze(m);
    }
    cholmod->factorize(m);
    return;
  }
#endif
  if (analyse) {
    ldlt.emplace();
    ldlt->analyzePattern(m);
  }
  ldlt->factorize(m);
  if (ldlt->info() != Eigen::Success)
    throw Error("sparse solver (eigen-simplicial-ldlt): the factorization failed (the matrix is "
                "not symmetric positive definite)");
  // LDLT succeeds on indefinite matrices: positive definiteness is D > 0.
  const auto d = ldlt->vectorD();
  for (Eigen::Index i = 0; i < d.size(); ++i)
    if (!(d[i] > 0))
      throw Error("sparse solver (eigen-simplicial-ldlt): the matrix is not positive definite "
                  "(pivot " +
                  std::to_string(i) + " is " + std::to_string(d[i]) + ")");
}

void SparseSpdSolver::refactor(const SparseMatrix& b) {
  if (b.rows != impl_->n || b.cols != impl_->n || b.row_start != impl_->row_start ||
      b.column != impl_->column)
    throw InvalidArgument("sparse solver: refactor needs the pattern of the matrix analysed (" +
                          std::to_string(impl_->n) + " x " + std::to_string(impl_->n) + ", " +
                          std::to_string(impl_->column.size()) + " stored entries)");
  impl_->factor(to_eigen(b), false);
}

std::int64_t SparseSpdSolver::negative_inertia(const SparseMatrix& b) const {
  if (b.rows != impl_->n || b.cols != impl_->n || b.row_start != impl_->row_start ||
      b.column != impl_->column)
    throw InvalidArgument("inertia: the matrix needs the pattern of the matrix analysed (" +
                          std::to_string(impl_->n) + " x " + std::to_string(impl_->n) + ", " +
                          std::to_string(impl_->column.size()) + " stored entries)");
#ifdef ZDG_HAVE_CHOLMOD
  if (impl_->cholmod) return impl_->cholmod->negative_inertia(b);
#endif
  return zdg::negative_inertia(b);
}

SparseSpdSolver::~SparseSpdSolver() = default;
SparseSpdSolver::SparseSpdSolver(SparseSpdSolver&&) noexcept = default;
SparseSpdSolver& SparseSpdSolver::operator=(SparseSpdSolver&&) noexcept = default;

std::int64_t SparseSpdSolver::size() const {
  return impl_->n;
}

SpdBackend SparseSpdSolver::backend() const {
  return impl_->backend;
}

std::vector<double> SparseSpdSolver::solve_counted(std::span<const double> b) const {
  if (static_cast<std::int64_t>(b.size()) != impl_->n)
    throw InvalidArgument("sparse solver: a right-hand side of " + std::to_string(b.size()) +
                          " entries for " + std::to_string(impl_->n) + " unknowns");
#ifdef ZDG_HAVE_CHOLMOD
  if (impl_->cholmod) {
    const Eigen::VectorXd x = impl_->cholmod->solve_counted(
        Eigen::Map<const Eigen::VectorXd>(b.data(), Eigen::Index(b.size())));
    return std::vector<double>(x.data(), x.data() + x.size());
  }
#endif
  throw InvalidArgument("sparse solver: the Eigen backend keeps no LDL^T of the matrix counted");
}

std::vector<double> SparseSpdSolver::solve(std::span<const double> b) const {
  if (static_cast<std::int64_t>(b.size()) != impl_->n)
    throw InvalidArgument("sparse solver: a right-hand side of " + std::to_string(b.size()) +
                          " entries for " + std::to_string(impl_->n) + " unknowns");
  const Eigen::Map<const Eigen::VectorXd> rhs(b.data(), Eigen::Index(b.size()));
  Eigen::VectorXd x;
#ifdef ZDG_HAVE_CHOLMOD
  if (impl_->cholmod) x = impl_->cholmod->solve(rhs);
#endif
  if (impl_->ldlt) x = impl_->ldlt->solve(rhs);
  return std::vector<double>(x.data(), x.data() + x.size());
}

std::int64_t negative_inertia(const SparseMatrix& a) {
  if (a.rows != a.cols)
    throw InvalidArgument("inertia: the matrix is " + std::to_string(a.rows) + " x " +
                          std::to_string(a.cols) + ", not square");
  Eigen::SimplicialLDLT<EigenSparse, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt(to_eigen(a));
  if (ldlt.info() != Eigen::Success) throw Error("inertia: the LDL^T factorization failed");
  const Eigen::VectorXd d = ldlt.vectorD();
  std::int64_t negative = 0;
  for (Eigen::Index i = 0; i < d.size(); ++i) {
    if (!std::isfinite(d(i)) || d(i) == 0)
      throw Error("inertia: pivot " + std::to_string(i) + " is " + std::to_string(d(i)) +
                  " (the matrix or a leading minor is singular)");
    if (d(i) < 0) ++negative;
  }
  return negative;
}

} // namespace zdg
