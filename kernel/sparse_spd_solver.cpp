#include <zdg/kernel/sparse_spd_solver.hpp>

#include <zdg/arith/error.hpp>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#ifdef ZDG_HAVE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include <limits>
#include <optional>

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
  std::optional<Eigen::CholmodSupernodalLLT<EigenSparse>> cholmod;
#endif
};

bool SparseSpdSolver::cholmod_available() {
#ifdef ZDG_HAVE_CHOLMOD
  return true;
#else
  return false;
#endif
}

SparseSpdSolver::SparseSpdSolver(const SparseMatrix& a, SpdBackend backend)
    : impl_(std::make_unique<Impl>()) {
  if (a.rows != a.cols)
    throw InvalidArgument("sparse solver: the matrix is " + std::to_string(a.rows) + " x " +
                          std::to_string(a.cols) + ", not square");
  if (backend == SpdBackend::cholmod && !cholmod_available())
    throw InvalidArgument("sparse solver: zdg was built without CHOLMOD (ZDG_CHOLMOD=OFF or "
                          "libsuitesparse-dev missing)");
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
      cholmod.emplace();
      // One ordering (AMD), not CHOLMOD's default search over AMD, METIS and NESDIS: the
      // analysis is then a small part of the cost on the surface meshes here.
      cholmod->cholmod().nmethods = 1;
      cholmod->cholmod().method[0].ordering = CHOLMOD_AMD;
      cholmod->cholmod().postorder = 1;
      cholmod->analyzePattern(m);
    }
    cholmod->factorize(m);
    if (cholmod->info() != Eigen::Success)
      throw Error("sparse solver (cholmod): the factorization failed (the matrix is not "
                  "symmetric positive definite)");
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

} // namespace zdg
