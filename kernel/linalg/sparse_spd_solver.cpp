#include <zdg/kernel/linalg/sparse_spd_solver.hpp>

#include <zdg/arith/error.hpp>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#ifdef ZDG_HAVE_CHOLMOD
#include <cholmod.h>
#include <dlfcn.h>
#endif

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
  std::vector<Eigen::Triplet<double, int>> t;
  t.reserve(std::size_t(a.nonzeros()));
  for (std::int64_t i = 0; i < a.rows; ++i)
    for (std::int64_t k = a.row_start[std::size_t(i)]; k < a.row_start[std::size_t(i) + 1]; ++k)
      t.emplace_back(int(i), int(a.column[std::size_t(k)]), a.value[std::size_t(k)]);
  EigenSparse m(int(a.rows), int(a.cols));
  m.setFromTriplets(t.begin(), t.end());
  m.makeCompressed();
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
    return a;
  }();
  return api;
}

// A supernodal L L^T factorization of the lower triangle (what Eigen's CholmodSupernodalLLT
// does, called through the functions loaded above): one ordering (AMD), not CHOLMOD's default
// search over AMD, METIS and NESDIS, so that the analysis is a small part of the cost on the
// surface meshes here.
class CholmodFactor {
public:
  explicit CholmodFactor(const CholmodApi& api) : api_(api) {
    api_.start(&common_);
    // CHOLMOD prints its own warnings with printf, on stdout (a matrix that is not positive
    // definite, ...), where a command's --json goes; zdg reports every failure itself: off.
    common_.print = 0;
    common_.final_asis = 1;
    common_.supernodal = CHOLMOD_SUPERNODAL;
    common_.nmethods = 1;
    common_.method[0].ordering = CHOLMOD_AMD;
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

SparseSpdSolver::SparseSpdSolver(const SparseMatrix& a, SpdBackend backend)
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
      cholmod.emplace(cholmod_api());
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

SparseSpdSolver::~SparseSpdSolver() = default;
SparseSpdSolver::SparseSpdSolver(SparseSpdSolver&&) noexcept = default;
SparseSpdSolver& SparseSpdSolver::operator=(SparseSpdSolver&&) noexcept = default;

std::int64_t SparseSpdSolver::size() const {
  return impl_->n;
}

SpdBackend SparseSpdSolver::backend() const {
  return impl_->backend;
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
