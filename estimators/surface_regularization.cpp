#include <zdg/estimators/surface_regularization.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/linalg/sparse_spd_solver.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <optional>

namespace zdg {

namespace {

using Vec = Point3<double>;
using Block = std::array<double, 9>; // row-major 3x3

// Vertex -> incident faces and vertex -> edge neighbours N(i), as CSR tables.
struct Incidence {
  std::vector<std::int64_t> face_start, faces;           // faces around each vertex
  std::vector<std::int64_t> neighbour_start, neighbours; // N(i), sorted, no repeats
  std::int64_t degree(std::int64_t i) const {
    return neighbour_start[std::size_t(i + 1)] - neighbour_start[std::size_t(i)];
  }
  std::span<const std::int64_t> around(std::int64_t i) const {
    return std::span<const std::int64_t>(neighbours)
        .subspan(std::size_t(neighbour_start[std::size_t(i)]), std::size_t(degree(i)));
  }
  std::span<const std::int64_t> faces_of(std::int64_t i) const {
    const auto b = face_start[std::size_t(i)], e = face_start[std::size_t(i + 1)];
    return std::span<const std::int64_t>(faces).subspan(std::size_t(b), std::size_t(e - b));
  }
};

Incidence incidence(const PolygonMesh& mesh, unsigned threads) {
  const std::int64_t nv = mesh.vertex_count(), nf = mesh.face_count();
  Incidence in;
  in.face_start.assign(std::size_t(nv + 1), 0);
  for (auto v : mesh.indices) ++in.face_start[std::size_t(v + 1)];
  std::partial_sum(in.face_start.begin(), in.face_start.end(), in.face_start.begin());
  in.faces.resize(mesh.indices.size());
  std::vector<std::int64_t> fill(in.face_start.begin(), in.face_start.end() - 1);
  for (std::int64_t f = 0; f < nf; ++f)
    for (auto v : mesh.face(f)) in.faces[std::size_t(fill[std::size_t(v)]++)] = f;
  // N(i): the other ends of the quad sides at i, over the faces around i.
  in.neighbour_start.assign(std::size_t(nv + 1), 0);
  std::vector<std::int64_t> counts(static_cast<std::size_t>(nv), 0);
  auto row_of = [&](std::int64_t i, std::vector<std::int64_t>& out) {
    out.clear();
    for (auto f : in.faces_of(i)) {
      const auto q = mesh.face(f);
      for (int k = 0; k < 4; ++k) {
        if (q[std::size_t(k)] != i) continue;
        out.push_back(q[std::size_t((k + 1) % 4)]);
        out.push_back(q[std::size_t((k + 3) % 4)]);
      }
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  };
  parallel_chunks(nv, threads, [&](std::int64_t b, std::int64_t e) {
    std::vector<std::int64_t> row;
    for (auto i = b; i < e; ++i) {
      row_of(i, row);
      counts[std::size_t(i)] = std::int64_t(row.size());
    }
  });
  for (std::int64_t i = 0; i < nv; ++i)
    in.neighbour_start[std::size_t(i + 1)] =
        in.neighbour_start[std::size_t(i)] + counts[std::size_t(i)];
  in.neighbours.resize(std::size_t(in.neighbour_start.back()));
  parallel_chunks(nv, threads, [&](std::int64_t b, std::int64_t e) {
    std::vector<std::int64_t> row;
    for (auto i = b; i < e; ++i) {
      row_of(i, row);
      std::copy(row.begin(), row.end(),
                in.neighbours.begin() + std::ptrdiff_t(in.neighbour_start[std::size_t(i)]));
    }
  });
  return in;
}

// The two sides of face f at vertex i: the next and the previous corner.
std::array<std::int64_t, 2> sides_at(const PolygonMesh& mesh, std::int64_t f, std::int64_t i,
                                     int& count) {
  const auto q = mesh.face(f);
  count = 0;
  std::array<std::int64_t, 2> out{};
  for (int k = 0; k < 4 && count == 0; ++k) {
    if (q[std::size_t(k)] != i) continue;
    out = {q[std::size_t((k + 1) % 4)], q[std::size_t((k + 3) % 4)]};
    count = 1;
  }
  return out;
}

// Row i of Q (as 3x3 blocks by column vertex, sorted, merged).
void block_row(const PolygonMesh& mesh, std::span<const Vec> normals, const Incidence& in,
               const RegularizationParameters& p, std::int64_t i,
               std::vector<std::pair<std::int64_t, Block>>& out) {
  out.clear();
  auto add = [&](std::int64_t col, const Block& b, double s) {
    Block t;
    for (int k = 0; k < 9; ++k) t[std::size_t(k)] = s * b[std::size_t(k)];
    out.emplace_back(col, t);
  };
  const Block identity{1, 0, 0, 0, 1, 0, 0, 0, 1};
  add(i, identity, p.alpha);
  // Alignment: each side (i, j) of each face s at i gives beta n n^T at (i, i), -beta n n^T at
  // (i, j).
  for (auto f : in.faces_of(i)) {
    int found = 0;
    const auto js = sides_at(mesh, f, i, found);
    const Vec n = normals[std::size_t(f)];
    const Block nn{n.x * n.x, n.x * n.y, n.x * n.z, n.y * n.x, n.y * n.y,
                   n.y * n.z, n.z * n.x, n.z * n.y, n.z * n.z};
    for (auto j : js) {
      add(i, nn, p.beta);
      add(j, nn, -p.beta);
    }
  }
  // Fairness: (F^T F)_{ik} = sum_m F_mi F_mk, F_mm = 1, F_mj = -1/|N(m)| for j in N(m); F_mi != 0
  // for m = i and m in N(i) (N is symmetric).
  auto fair_row = [&](std::int64_t m, double fmi) {
    const double w = p.gamma * fmi;
    add(m, identity, w);
    const double c = -1.0 / double(in.degree(m));
    for (auto k : in.around(m)) add(k, identity, w * c);
  };
  fair_row(i, 1.0);
  for (auto m : in.around(i)) fair_row(m, -1.0 / double(in.degree(m)));
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::size_t w = 0;
  for (std::size_t r = 0; r < out.size(); ++r) {
    if (w > 0 && out[w - 1].first == out[r].first) {
      for (int k = 0; k < 9; ++k)
        out[w - 1].second[std::size_t(k)] += out[r].second[std::size_t(k)];
    } else {
      out[w++] = out[r];
    }
  }
  out.resize(w);
}

SparseMatrix assemble_q(const PolygonMesh& mesh, std::span<const Vec> normals, const Incidence& in,
                        const RegularizationParameters& p) {
  const std::int64_t nv = mesh.vertex_count();
  std::vector<std::int64_t> blocks(static_cast<std::size_t>(nv), 0);
  parallel_chunks(nv, p.threads, [&](std::int64_t b, std::int64_t e) {
    std::vector<std::pair<std::int64_t, Block>> row;
    for (auto i = b; i < e; ++i) {
      block_row(mesh, normals, in, p, i, row);
      blocks[std::size_t(i)] = std::int64_t(row.size());
    }
  });
  SparseMatrix q;
  q.rows = q.cols = 3 * nv;
  q.row_start.assign(std::size_t(3 * nv + 1), 0);
  std::vector<std::int64_t> start(static_cast<std::size_t>(nv + 1), 0);
  for (std::int64_t i = 0; i < nv; ++i)
    start[std::size_t(i + 1)] = start[std::size_t(i)] + 9 * blocks[std::size_t(i)];
  for (std::int64_t i = 0; i < nv; ++i)
    for (int a = 0; a < 3; ++a)
      q.row_start[std::size_t(3 * i + a + 1)] =
          start[std::size_t(i)] + 3 * blocks[std::size_t(i)] * (a + 1);
  q.column.resize(std::size_t(start.back()));
  q.value.resize(std::size_t(start.back()));
  parallel_chunks(nv, p.threads, [&](std::int64_t b, std::int64_t e) {
    std::vector<std::pair<std::int64_t, Block>> row;
    for (auto i = b; i < e; ++i) {
      block_row(mesh, normals, in, p, i, row);
      for (int a = 0; a < 3; ++a) {
        auto k = std::size_t(q.row_start[std::size_t(3 * i + a)]);
        for (const auto& [col, blk] : row) {
          for (int c = 0; c < 3; ++c) {
            q.column[k] = 3 * col + c;
            q.value[k++] = blk[std::size_t(3 * a + c)];
          }
        }
      }
    }
  });
  return q;
}

// g = (beta A^T A + gamma F^T F) p, from the edge vectors and the umbrella vectors of p (so that
// a translation of p changes nothing but roundings of the differences).
std::vector<double> assemble_g(const PolygonMesh& mesh, std::span<const Vec> normals,
                               const Incidence& in, const RegularizationParameters& p) {
  const std::int64_t nv = mesh.vertex_count();
  const auto& x = mesh.vertices;
  std::vector<Vec> lap(static_cast<std::size_t>(nv)); // F p
  parallel_chunks(nv, p.threads, [&](std::int64_t b, std::int64_t e) {
    for (auto i = b; i < e; ++i) {
      Vec s{0, 0, 0};
      const auto& xi = x[std::size_t(i)];
      for (auto j : in.around(i)) s += x[std::size_t(j)] - xi;
      lap[std::size_t(i)] = -(1.0 / double(in.degree(i))) * s;
    }
  });
  std::vector<double> g(static_cast<std::size_t>(3 * nv));
  parallel_chunks(nv, p.threads, [&](std::int64_t b, std::int64_t e) {
    for (auto i = b; i < e; ++i) {
      Vec s{0, 0, 0};
      for (auto f : in.faces_of(i)) {
        int found = 0;
        const auto js = sides_at(mesh, f, i, found);
        const Vec n = normals[std::size_t(f)];
        for (auto j : js) s -= (p.beta * dot(n, x[std::size_t(j)] - x[std::size_t(i)])) * n;
      }
      Vec fair = lap[std::size_t(i)];
      for (auto m : in.around(i)) fair -= (1.0 / double(in.degree(m))) * lap[std::size_t(m)];
      s += p.gamma * fair;
      g[std::size_t(3 * i)] = s.x;
      g[std::size_t(3 * i + 1)] = s.y;
      g[std::size_t(3 * i + 2)] = s.z;
    }
  });
  return g;
}

double max_abs(std::span<const double> v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

// Jacobi-preconditioned conjugate gradient on (Q + shift I) y = b from the start y, until
// |r|_2 <= tol. Returns the iterations; Error past max_iterations.
int conjugate_gradient(const SparseMatrix& q, double shift, std::span<const double> b,
                       std::vector<double>& y, double tol, int max_iterations, unsigned threads) {
  const std::size_t n = b.size();
  std::vector<double> inv(n);
  for (std::size_t i = 0; i < n; ++i)
    inv[i] = 1.0 / (q.at(std::int64_t(i), std::int64_t(i)) + shift);
  auto apply = [&](const std::vector<double>& v) {
    auto out = q.multiply(v, threads);
    for (std::size_t i = 0; i < n; ++i) out[i] += shift * v[i];
    return out;
  };
  auto r = apply(y);
  for (std::size_t i = 0; i < n; ++i) r[i] = b[i] - r[i];
  auto norm2 = [](const std::vector<double>& v) {
    return std::inner_product(v.begin(), v.end(), v.begin(), 0.0);
  };
  if (std::sqrt(norm2(r)) <= tol) return 0;
  std::vector<double> z(n), dir(n);
  for (std::size_t i = 0; i < n; ++i) dir[i] = z[i] = inv[i] * r[i];
  double rz = std::inner_product(r.begin(), r.end(), z.begin(), 0.0);
  for (int it = 1; it <= max_iterations; ++it) {
    const auto ad = apply(dir);
    const double a = rz / std::inner_product(dir.begin(), dir.end(), ad.begin(), 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      y[i] += a * dir[i];
      r[i] -= a * ad[i];
    }
    if (std::sqrt(norm2(r)) <= tol) return it;
    for (std::size_t i = 0; i < n; ++i) z[i] = inv[i] * r[i];
    const double rz_new = std::inner_product(r.begin(), r.end(), z.begin(), 0.0);
    const double beta = rz_new / rz;
    rz = rz_new;
    for (std::size_t i = 0; i < n; ++i) dir[i] = z[i] + beta * dir[i];
  }
  throw Error(fmt::format("surface regularization: conjugate gradient did not reach {:.3g} in {} "
                          "iterations",
                          tol, max_iterations));
}

// Solves (Q + shift I) y = b: one factorization, or CG warm-started from y.
class ShiftedSolver {
public:
  ShiftedSolver(const SparseMatrix& q, double shift, bool direct, int max_iterations,
                unsigned threads)
      : q_(q), shift_(shift), max_iterations_(max_iterations), threads_(threads) {
    if (direct) {
      if (shift > 0) {
        const std::vector<double> d(static_cast<std::size_t>(q.rows), shift);
        direct_.emplace(add(1.0, q, 1.0, SparseMatrix::diagonal(d)));
      } else {
        direct_.emplace(q);
      }
    }
  }
  void solve(std::span<const double> b, std::vector<double>& y, double tol) {
    if (direct_) {
      y = direct_->solve(b);
      return;
    }
    cg_iterations += conjugate_gradient(q_, shift_, b, y, tol, max_iterations_, threads_);
  }
  std::string name() const { return direct_ ? spd_backend_name(direct_->backend()) : "cg"; }
  int cg_iterations = 0;

private:
  const SparseMatrix& q_;
  double shift_;
  int max_iterations_;
  unsigned threads_;
  std::optional<SparseSpdSolver> direct_;
};

void check_parameter(double v, const char* name) {
  if (!(v > 0) || !std::isfinite(v))
    throw InvalidArgument(fmt::format("surface regularization: {} = {} (a positive number is "
                                      "needed)",
                                      name, v));
}

} // namespace

void check_regularization_input(const PolygonMesh& mesh, std::span<const Vec> normals, double h,
                                const RegularizationParameters& p) {
  if (mesh.face_size != 4)
    throw InvalidArgument(fmt::format("surface regularization: the mesh has faces of {} vertices; "
                                      "it needs the primal quad mesh (one quad per surfel)",
                                      mesh.face_size));
  mesh.validate();
  if (std::int64_t(normals.size()) != mesh.face_count())
    throw InvalidArgument(fmt::format("surface regularization: {} normals for {} faces",
                                      normals.size(), mesh.face_count()));
  for (std::size_t f = 0; f < normals.size(); ++f) {
    const double len = std::sqrt(dot(normals[f], normals[f]));
    if (!(std::abs(len - 1) <= 1e-6))
      throw InvalidArgument(fmt::format("surface regularization: the normal of face {} has "
                                        "length {} (unit normals are needed)",
                                        f, len));
  }
  check_parameter(h, "h");
  check_parameter(p.alpha, "alpha");
  check_parameter(p.beta, "beta");
  check_parameter(p.gamma, "gamma");
  check_parameter(p.tolerance, "tolerance");
  if (p.rho != 0) check_parameter(p.rho, "rho");
  if (p.max_iterations < 1)
    throw InvalidArgument(
        fmt::format("surface regularization: max_iterations = {} (at least 1)", p.max_iterations));
}

RegularizationEnergy regularization_energy(const PolygonMesh& mesh, std::span<const Vec> normals,
                                           std::span<const Vec> x,
                                           const RegularizationParameters& p) {
  if (std::int64_t(x.size()) != mesh.vertex_count())
    throw InvalidArgument(fmt::format("surface regularization: {} positions for {} vertices",
                                      x.size(), mesh.vertex_count()));
  const Incidence in = incidence(mesh, p.threads);
  RegularizationEnergy e;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Vec d = x[i] - mesh.vertices[i];
    e.data += dot(d, d);
    Vec s{0, 0, 0};
    for (auto j : in.around(std::int64_t(i))) s += x[std::size_t(j)] - x[i];
    const Vec l = (1.0 / double(in.degree(std::int64_t(i)))) * s;
    e.fairness += dot(l, l);
  }
  for (std::int64_t f = 0; f < mesh.face_count(); ++f) {
    const auto q = mesh.face(f);
    for (int k = 0; k < 4; ++k) {
      const double t =
          dot(x[std::size_t(q[std::size_t((k + 1) % 4)])] - x[std::size_t(q[std::size_t(k)])],
              normals[std::size_t(f)]);
      e.alignment += t * t;
    }
  }
  e.data *= p.alpha;
  e.alignment *= p.beta;
  e.fairness *= p.gamma;
  return e;
}

RegularizationSystem regularization_system(const PolygonMesh& mesh, std::span<const Vec> normals,
                                           const RegularizationParameters& p) {
  check_regularization_input(mesh, normals, 1.0, p);
  const Incidence in = incidence(mesh, p.threads);
  for (std::int64_t i = 0; i < mesh.vertex_count(); ++i)
    if (in.degree(i) == 0)
      throw InvalidArgument(fmt::format("surface regularization: vertex {} is in no face", i));
  return {assemble_q(mesh, normals, in, p), assemble_g(mesh, normals, in, p)};
}

RegularizationResult regularize_surface(const PolygonMesh& mesh, std::span<const Vec> normals,
                                        double h, const RegularizationParameters& parameters) {
  check_regularization_input(mesh, normals, h, parameters);
  // Threads pay only on large meshes (each product starts its workers).
  RegularizationParameters p = parameters;
  p.threads = worker_count(p.threads, mesh.vertex_count(), 20000);
  RegularizationResult r;
  if (mesh.vertex_count() == 0) {
    r.solver = "none";
    return r;
  }
  const RegularizationSystem sys = regularization_system(mesh, normals, p);
  const std::int64_t n = sys.q.rows;
  const bool direct = p.solver == RegularizationSolver::direct ||
                      (p.solver == RegularizationSolver::automatic && mesh.vertex_count() <= 30000);
  std::vector<double> minus_g(sys.g.size());
  for (std::size_t i = 0; i < sys.g.size(); ++i) minus_g[i] = -sys.g[i];
  std::vector<double> d(static_cast<std::size_t>(n), 0.0);
  const double tol = p.tolerance * h;
  if (!p.clamp) {
    ShiftedSolver solver(sys.q, 0.0, direct, p.max_iterations, p.threads);
    // |d - d*|_2 <= |r|_2 / alpha.
    solver.solve(minus_g, d, tol * p.alpha);
    r.solver = solver.name();
    r.cg_iterations = solver.cg_iterations;
  } else {
    const double half = h / 2;
    const auto size = static_cast<std::size_t>(n);
    std::vector<double> z(size, 0.0), u(size, 0.0), rhs(size);
    if (direct) {
      // The unconstrained minimizer, when it lies in the box, is the box-constrained one; else
      // ADMM starts from its clamp.
      ShiftedSolver free(sys.q, 0.0, true, p.max_iterations, p.threads);
      free.solve(minus_g, d, 0);
      if (max_abs(d) <= half) {
        r.solver = free.name();
        r.positions.resize(mesh.vertices.size());
        for (std::size_t i = 0; i < r.positions.size(); ++i)
          r.positions[i] = mesh.vertices[i] + Vec{d[3 * i], d[3 * i + 1], d[3 * i + 2]};
        r.max_displacement = max_abs(d) / h;
        r.before = regularization_energy(mesh, normals, mesh.vertices, p);
        r.after = regularization_energy(mesh, normals, r.positions, p);
        return r;
      }
      for (std::size_t i = 0; i < size; ++i) z[i] = std::clamp(d[i], -half, half);
    }
    const double rho =
        p.rho > 0 ? p.rho : std::sqrt(p.alpha * (p.alpha + 4 * p.beta + 4 * p.gamma));
    ShiftedSolver solver(sys.q, rho, direct, p.max_iterations, p.threads);
    for (int it = 1;; ++it) {
      for (std::size_t i = 0; i < rhs.size(); ++i) rhs[i] = minus_g[i] + rho * (z[i] - u[i]);
      solver.solve(rhs, d, 0.1 * tol * (rho + p.alpha));
      double primal = 0, change = 0;
      for (std::size_t i = 0; i < z.size(); ++i) {
        const double zi = std::clamp(d[i] + u[i], -half, half);
        change = std::max(change, std::abs(zi - z[i]));
        z[i] = zi;
        u[i] += d[i] - zi;
        primal = std::max(primal, std::abs(d[i] - zi));
      }
      r.iterations = it;
      r.converged = primal <= tol && change <= tol;
      if (r.converged || it >= p.max_iterations) break;
    }
    d = std::move(z);
    r.solver = solver.name();
    r.cg_iterations = solver.cg_iterations;
  }
  r.positions.resize(mesh.vertices.size());
  for (std::size_t i = 0; i < r.positions.size(); ++i)
    r.positions[i] = mesh.vertices[i] + Vec{d[3 * i], d[3 * i + 1], d[3 * i + 2]};
  r.max_displacement = max_abs(d) / h;
  r.before = regularization_energy(mesh, normals, mesh.vertices, p);
  r.after = regularization_energy(mesh, normals, r.positions, p);
  return r;
}

Vec quad_vector_area(const PolygonMesh& mesh, std::span<const Vec> x, std::int64_t f) {
  const auto q = mesh.face(f);
  const Vec a = x[std::size_t(q[2])] - x[std::size_t(q[0])];
  const Vec b = x[std::size_t(q[3])] - x[std::size_t(q[1])];
  return 0.5 * cross(a, b);
}

} // namespace zdg
