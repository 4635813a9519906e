#include <zdg/estimators/surface_regularization.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/linalg/sparse_spd_solver.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numeric>

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

// The factorization of Q + shift I, one solve per call.
SparseSpdSolver factor_shifted(const SparseMatrix& q, double shift) {
  if (shift == 0) return SparseSpdSolver(q);
  const std::vector<double> d(static_cast<std::size_t>(q.rows), shift);
  return SparseSpdSolver(add(1.0, q, 1.0, SparseMatrix::diagonal(d)));
}

// max_k s_k sum_j |Q_kj| s_j: Gershgorin's bound on the largest eigenvalue of S Q S.
double scaled_gershgorin(const PolygonMesh& mesh, std::span<const Vec> normals, const Incidence& in,
                         const RegularizationParameters& p, std::span<const double> s) {
  const std::int64_t nv = mesh.vertex_count();
  std::vector<double> rows(static_cast<std::size_t>(nv), 0.0);
  parallel_chunks(nv, p.threads, [&](std::int64_t b, std::int64_t e) {
    std::vector<std::pair<std::int64_t, Block>> row;
    for (auto i = b; i < e; ++i) {
      block_row(mesh, normals, in, p, i, row);
      double worst = 0;
      for (int a = 0; a < 3; ++a) {
        double sum = 0;
        for (const auto& [col, blk] : row)
          for (int c = 0; c < 3; ++c)
            sum += std::abs(blk[std::size_t(3 * a + c)]) * s[std::size_t(3 * col + c)];
        worst = std::max(worst, sum * s[std::size_t(3 * i + a)]);
      }
      rows[std::size_t(i)] = worst;
    }
  });
  return *std::max_element(rows.begin(), rows.end());
}

// Q applied without assembling it (the minimizer's inner loop): per vertex i, its corners
// (face f, next and previous vertex: the two sides of f at i) and its umbrella N(i):
//   (Q x)_i = alpha x_i + beta sum_corners n_f (n_f . (2 x_i - x_next - x_prev))
//           + gamma (L_i - sum_{m in N(i)} L_m / |N(m)|),  L = F x = x_i - mean_{N(i)} x.
// Two gathers over the vertices (no scatter: deterministic for any thread count).
class EnergyOperator {
public:
  EnergyOperator(const PolygonMesh& mesh, std::span<const Vec> normals, const Incidence& in,
                 const RegularizationParameters& p)
      : in_(in), normals_(normals), p_(p), nv_(mesh.vertex_count()) {
    corner_start_.assign(std::size_t(nv_ + 1), 0);
    for (std::int64_t i = 0; i < nv_; ++i)
      corner_start_[std::size_t(i + 1)] =
          corner_start_[std::size_t(i)] + std::int64_t(in.faces_of(i).size());
    corners_.resize(std::size_t(corner_start_.back()));
    inv_degree_.resize(std::size_t(nv_));
    parallel_chunks(nv_, p.threads, [&](std::int64_t b, std::int64_t e) {
      for (auto i = b; i < e; ++i) {
        auto k = std::size_t(corner_start_[std::size_t(i)]);
        for (auto f : in.faces_of(i)) {
          int found = 0;
          const auto js = sides_at(mesh, f, i, found);
          corners_[k++] = {f, js[0], js[1]};
        }
        inv_degree_[std::size_t(i)] = 1.0 / double(in.degree(i));
      }
    });
    lap_.resize(std::size_t(3 * nv_));
  }

  std::int64_t size() const { return 3 * nv_; }

  void apply(std::span<const double> x, std::span<double> y) const {
    auto at = [](std::span<const double> v, std::int64_t i) {
      return Vec{v[std::size_t(3 * i)], v[std::size_t(3 * i + 1)], v[std::size_t(3 * i + 2)]};
    };
    parallel_chunks(nv_, p_.threads, [&](std::int64_t b, std::int64_t e) {
      for (auto i = b; i < e; ++i) {
        Vec s{0, 0, 0};
        for (auto j : in_.around(i)) s += at(x, j);
        const Vec l = at(x, i) - inv_degree_[std::size_t(i)] * s;
        lap_[std::size_t(3 * i)] = l.x;
        lap_[std::size_t(3 * i + 1)] = l.y;
        lap_[std::size_t(3 * i + 2)] = l.z;
      }
    });
    const std::span<const double> lap(lap_);
    parallel_chunks(nv_, p_.threads, [&](std::int64_t b, std::int64_t e) {
      for (auto i = b; i < e; ++i) {
        const Vec xi = at(x, i);
        Vec align{0, 0, 0};
        for (auto c = corner_start_[std::size_t(i)]; c < corner_start_[std::size_t(i + 1)]; ++c) {
          const auto& k = corners_[std::size_t(c)];
          const Vec n = normals_[std::size_t(k.face)];
          align += dot(n, 2.0 * xi - at(x, k.next) - at(x, k.prev)) * n;
        }
        Vec fair = at(lap, i);
        for (auto m : in_.around(i)) fair -= inv_degree_[std::size_t(m)] * at(lap, m);
        const Vec out = p_.alpha * xi + p_.beta * align + p_.gamma * fair;
        y[std::size_t(3 * i)] = out.x;
        y[std::size_t(3 * i + 1)] = out.y;
        y[std::size_t(3 * i + 2)] = out.z;
      }
    });
  }

  /// The diagonal of Q: alpha + 2 beta sum_corners n_a^2 + gamma (1 + sum_{m in N(i)}
  /// 1/|N(m)|^2).
  std::vector<double> diagonal() const {
    std::vector<double> d(std::size_t(3 * nv_));
    parallel_chunks(nv_, p_.threads, [&](std::int64_t b, std::int64_t e) {
      for (auto i = b; i < e; ++i) {
        double fair = 1;
        for (auto m : in_.around(i))
          fair += inv_degree_[std::size_t(m)] * inv_degree_[std::size_t(m)];
        Vec nn{0, 0, 0};
        for (auto c = corner_start_[std::size_t(i)]; c < corner_start_[std::size_t(i + 1)]; ++c) {
          const Vec n = normals_[std::size_t(corners_[std::size_t(c)].face)];
          nn += Vec{n.x * n.x, n.y * n.y, n.z * n.z};
        }
        d[std::size_t(3 * i)] = p_.alpha + 2 * p_.beta * nn.x + p_.gamma * fair;
        d[std::size_t(3 * i + 1)] = p_.alpha + 2 * p_.beta * nn.y + p_.gamma * fair;
        d[std::size_t(3 * i + 2)] = p_.alpha + 2 * p_.beta * nn.z + p_.gamma * fair;
      }
    });
    return d;
  }

private:
  struct Corner {
    std::int64_t face, next, prev;
  };
  const Incidence& in_;
  std::span<const Vec> normals_;
  const RegularizationParameters& p_;
  std::int64_t nv_;
  std::vector<std::int64_t> corner_start_;
  std::vector<Corner> corners_;
  std::vector<double> inv_degree_;
  mutable std::vector<double> lap_;
};

// Sums over [0, n) in fixed blocks, the blocks' partial sums added in order: the same rounding
// for any thread count. fn(b, e) returns the partial sums of [b, e) as an array of K doubles.
template <std::size_t K, class Fn>
std::array<double, K> block_sums(std::int64_t n, unsigned threads, Fn&& fn) {
  constexpr std::int64_t block = 8192;
  const std::int64_t blocks = (n + block - 1) / block;
  std::vector<std::array<double, K>> part(static_cast<std::size_t>(blocks));
  parallel_chunks(blocks, threads, [&](std::int64_t b, std::int64_t e) {
    for (auto k = b; k < e; ++k) part[std::size_t(k)] = fn(k * block, std::min(n, (k + 1) * block));
  });
  std::array<double, K> out{};
  for (const auto& s : part)
    for (std::size_t k = 0; k < K; ++k) out[k] += s[k];
  return out;
}

// MPRGP (Dostal, Schoberl, Comput. Optim. Appl. 30, 2005; Dostal, "Optimal quadratic
// programming algorithms", Springer 2009, ch. 8): min f(y) = y^T A y / 2 - b^T y over the box
// |y_k| <= u_k (u_k may be infinite). Conjugate gradient steps on the free set while they stay
// feasible and the chopped gradient is small against the free one (Gamma = 1), expansion steps
// (the feasible CG step, then a projected gradient step of fixed length abar <= 2 / |A|) when CG
// would leave the box, proportioning steps (along the chopped gradient) to release constraints.
// Stops when the projected gradient g^P (the free gradient plus the chopped one, zero exactly
// at the KKT point) has |g^P|_2 <= eps, checked again on the gradient recomputed from y (the
// recurrence's rounding does not decide). Without bounds it is the conjugate gradient method.
struct MprgpOutcome {
  int iterations = 0;
  bool converged = false;
  double residual = 0; // |g^P(y)|_2 at the end (recomputed)
};

MprgpOutcome mprgp(const std::function<void(std::span<const double>, std::span<double>)>& apply,
                   std::span<const double> b, std::span<const double> u, double abar, double eps,
                   int max_iterations, unsigned threads, std::vector<double>& y) {
  const auto n = std::int64_t(b.size());
  const auto N = std::size_t(n);
  std::vector<double> g(N), p(N), ap(N);
  auto gradient = [&] {
    apply(y, g);
    parallel_chunks(n, threads, [&](std::int64_t lo, std::int64_t hi) {
      for (auto k = lo; k < hi; ++k) g[std::size_t(k)] -= b[std::size_t(k)];
    });
  };
  auto is_free = [&](std::size_t k) { return std::abs(y[k]) < u[k]; };
  // chopped gradient: at the lower bound min(g, 0), at the upper max(g, 0)
  auto chopped = [&](std::size_t k) {
    if (is_free(k)) return 0.0;
    return y[k] < 0 ? std::min(g[k], 0.0) : std::max(g[k], 0.0);
  };
  auto free_part = [&](std::size_t k) { return is_free(k) ? g[k] : 0.0; };
  // p = phi(y)
  auto restart = [&] {
    parallel_chunks(n, threads, [&](std::int64_t lo, std::int64_t hi) {
      for (auto k = lo; k < hi; ++k) p[std::size_t(k)] = free_part(std::size_t(k));
    });
  };
  // the largest step along -v that stays in the box
  auto feasible_step = [&](const std::vector<double>& v) {
    double a = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < N; ++k) {
      if (v[k] > 0)
        a = std::min(a, (y[k] + u[k]) / v[k]);
      else if (v[k] < 0)
        a = std::min(a, (y[k] - u[k]) / v[k]);
    }
    return std::max(a, 0.0);
  };
  auto clamp_y = [&](std::size_t k) { y[k] = std::clamp(y[k], -u[k], u[k]); };
  gradient();
  restart();
  MprgpOutcome out;
  bool recomputed = true;
  for (;;) {
    // |beta|^2, phi~^T phi, |phi|^2
    const auto sums = block_sums<3>(n, threads, [&](std::int64_t lo, std::int64_t hi) {
      std::array<double, 3> s{};
      for (auto k = lo; k < hi; ++k) {
        const auto i = std::size_t(k);
        const double be = chopped(i), ph = free_part(i);
        double reduced = 0;
        if (ph > 0)
          reduced = std::min((y[i] + u[i]) / abar, ph);
        else if (ph < 0)
          reduced = std::max((y[i] - u[i]) / abar, ph);
        s[0] += be * be;
        s[1] += reduced * ph;
        s[2] += ph * ph;
      }
      return s;
    });
    out.residual = std::sqrt(sums[0] + sums[2]);
    if (out.residual <= eps) {
      if (recomputed) {
        out.converged = true;
        return out;
      }
      gradient(); // the recurrence said so: check on the true gradient
      restart();
      recomputed = true;
      continue;
    }
    if (out.iterations >= max_iterations) return out;
    ++out.iterations;
    recomputed = false;
    if (sums[0] <= sums[1]) {
      apply(p, ap);
      const auto pa = block_sums<2>(n, threads, [&](std::int64_t lo, std::int64_t hi) {
        std::array<double, 2> s{};
        for (auto k = lo; k < hi; ++k) {
          s[0] += p[std::size_t(k)] * ap[std::size_t(k)];
          s[1] += g[std::size_t(k)] * p[std::size_t(k)];
        }
        return s;
      });
      if (!(pa[0] > 0)) { // p = 0 up to rounding: restart from the true gradient
        gradient();
        restart();
        recomputed = true;
        continue;
      }
      const double acg = pa[1] / pa[0], af = feasible_step(p);
      if (acg <= af) { // conjugate gradient step
        const auto s = block_sums<1>(n, threads, [&](std::int64_t lo, std::int64_t hi) {
          std::array<double, 1> t{};
          for (auto k = lo; k < hi; ++k) {
            const auto i = std::size_t(k);
            y[i] -= acg * p[i];
            clamp_y(i);
            g[i] -= acg * ap[i];
            t[0] += free_part(i) * ap[i];
          }
          return t;
        });
        const double gamma = s[0] / pa[0];
        parallel_chunks(n, threads, [&](std::int64_t lo, std::int64_t hi) {
          for (auto k = lo; k < hi; ++k)
            p[std::size_t(k)] = free_part(std::size_t(k)) - gamma * p[std::size_t(k)];
        });
      } else { // expansion step
        parallel_chunks(n, threads, [&](std::int64_t lo, std::int64_t hi) {
          for (auto k = lo; k < hi; ++k) {
            const auto i = std::size_t(k);
            y[i] -= af * p[i];
            clamp_y(i);
            g[i] -= af * ap[i];
            y[i] -= abar * free_part(i);
            clamp_y(i);
          }
        });
        gradient();
        restart();
        recomputed = true;
      }
    } else { // proportioning step along the chopped gradient (into the box)
      std::vector<double>& d = p;
      parallel_chunks(n, threads, [&](std::int64_t lo, std::int64_t hi) {
        for (auto k = lo; k < hi; ++k) d[std::size_t(k)] = chopped(std::size_t(k));
      });
      apply(d, ap);
      const auto da = block_sums<2>(n, threads, [&](std::int64_t lo, std::int64_t hi) {
        std::array<double, 2> s{};
        for (auto k = lo; k < hi; ++k) {
          s[0] += d[std::size_t(k)] * ap[std::size_t(k)];
          s[1] += g[std::size_t(k)] * d[std::size_t(k)];
        }
        return s;
      });
      const double a = std::min(da[1] / da[0], feasible_step(d));
      parallel_chunks(n, threads, [&](std::int64_t lo, std::int64_t hi) {
        for (auto k = lo; k < hi; ++k) {
          const auto i = std::size_t(k);
          y[i] -= a * d[i];
          clamp_y(i);
          g[i] -= a * ap[i];
        }
      });
      restart();
    }
  }
}

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

namespace {

// The direct path: Q factored; the unconstrained minimizer, kept when it lies in the box, else
// ADMM from its clamp with Q + rho I factored once.
std::vector<double> regularize_direct(const PolygonMesh& mesh, std::span<const Vec> normals,
                                      double h, const RegularizationParameters& p,
                                      RegularizationResult& r) {
  const RegularizationSystem sys = regularization_system(mesh, normals, p);
  std::vector<double> minus_g(sys.g.size());
  for (std::size_t i = 0; i < sys.g.size(); ++i) minus_g[i] = -sys.g[i];
  const SparseSpdSolver free = factor_shifted(sys.q, 0.0);
  r.solver = spd_backend_name(free.backend());
  std::vector<double> d = free.solve(minus_g);
  const double half = h / 2;
  if (!p.clamp || max_abs(d) <= half) return d;
  const auto size = d.size();
  std::vector<double> z(size), u(size, 0.0), rhs(size);
  for (std::size_t i = 0; i < size; ++i) z[i] = std::clamp(d[i], -half, half);
  const double rho = p.rho > 0 ? p.rho : std::sqrt(p.alpha * (p.alpha + 4 * p.beta + 4 * p.gamma));
  const SparseSpdSolver shifted = factor_shifted(sys.q, rho);
  const double tol = p.tolerance * h;
  for (int it = 1;; ++it) {
    for (std::size_t i = 0; i < size; ++i) rhs[i] = minus_g[i] + rho * (z[i] - u[i]);
    d = shifted.solve(rhs);
    double primal = 0, change = 0;
    for (std::size_t i = 0; i < size; ++i) {
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
  return z;
}

// The iterative path: MPRGP on the Jacobi-scaled problem y = D^{1/2} d (D = diag Q), min
// y^T A y / 2 + (S g)^T y with A = S Q S, S = D^{-1/2}, over |y_k| <= (h/2) / S_k.
std::vector<double> regularize_iterative(const PolygonMesh& mesh, std::span<const Vec> normals,
                                         double h, const RegularizationParameters& p,
                                         RegularizationResult& r) {
  const Incidence in = incidence(mesh, p.threads);
  for (std::int64_t i = 0; i < mesh.vertex_count(); ++i)
    if (in.degree(i) == 0)
      throw InvalidArgument(fmt::format("surface regularization: vertex {} is in no face", i));
  const std::vector<double> g = assemble_g(mesh, normals, in, p);
  const EnergyOperator op(mesh, normals, in, p);
  std::vector<double> s = op.diagonal();
  for (double& v : s) v = 1 / std::sqrt(v);
  const auto n = std::int64_t(s.size());
  const auto N = s.size();
  const double half = h / 2;
  std::vector<double> b(N), u(N), tmp(N);
  for (std::size_t k = 0; k < N; ++k) {
    b[k] = -s[k] * g[k];
    u[k] = p.clamp ? half / s[k] : std::numeric_limits<double>::infinity();
  }
  auto apply = [&](std::span<const double> y, std::span<double> out) {
    parallel_chunks(n, p.threads, [&](std::int64_t lo, std::int64_t hi) {
      for (auto k = lo; k < hi; ++k) tmp[std::size_t(k)] = s[std::size_t(k)] * y[std::size_t(k)];
    });
    op.apply(tmp, out);
    parallel_chunks(n, p.threads, [&](std::int64_t lo, std::int64_t hi) {
      for (auto k = lo; k < hi; ++k) out[std::size_t(k)] *= s[std::size_t(k)];
    });
  };
  const double abar = 1.9 / scaled_gershgorin(mesh, normals, in, p, s);
  const double b_norm = std::sqrt(std::inner_product(b.begin(), b.end(), b.begin(), 0.0));
  std::vector<double> y(N, 0.0);
  const MprgpOutcome out =
      mprgp(apply, b, u, abar, p.tolerance * b_norm, p.max_iterations, p.threads, y);
  r.solver = "mprgp";
  r.iterations = out.iterations;
  r.converged = out.converged;
  r.kkt_residual = b_norm > 0 ? out.residual / b_norm : 0.0;
  if (!p.clamp && !out.converged)
    throw Error(fmt::format("surface regularization: the conjugate gradient did not reach the "
                            "relative residual {:.3g} in {} iterations",
                            p.tolerance, p.max_iterations));
  std::vector<double> d(N);
  for (std::size_t k = 0; k < N; ++k)
    d[k] = p.clamp ? std::clamp(s[k] * y[k], -half, half) : s[k] * y[k];
  return d;
}

} // namespace

RegularizationResult regularize_surface(const PolygonMesh& mesh, std::span<const Vec> normals,
                                        double h, const RegularizationParameters& parameters) {
  check_regularization_input(mesh, normals, h, parameters);
  // Threads pay only on large meshes (each parallel loop starts its workers).
  RegularizationParameters p = parameters;
  p.threads = worker_count(p.threads, mesh.vertex_count(), 20000);
  RegularizationResult r;
  if (mesh.vertex_count() == 0) {
    r.solver = "none";
    return r;
  }
  const bool direct =
      p.solver == RegularizationSolver::direct ||
      (p.solver == RegularizationSolver::automatic && !p.clamp && mesh.vertex_count() <= 30000);
  const std::vector<double> d = direct ? regularize_direct(mesh, normals, h, p, r)
                                       : regularize_iterative(mesh, normals, h, p, r);
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
