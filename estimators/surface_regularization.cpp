#include <zdg/estimators/surface_regularization.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/linalg/sparse_spd_solver.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
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

// Per-block partial results over [0, n) in fixed blocks of `block` items, fn(b, e) giving the
// K partials of [b, e): combined in block order by the caller, the same rounding for any thread
// count.
template <std::size_t K, class Fn>
std::vector<std::array<double, K>> block_partials(std::int64_t n, std::int64_t block,
                                                  unsigned threads, Fn&& fn) {
  const std::int64_t blocks = (n + block - 1) / block;
  std::vector<std::array<double, K>> part(static_cast<std::size_t>(blocks));
  parallel_chunks(blocks, threads, [&](std::int64_t b, std::int64_t e) {
    for (auto k = b; k < e; ++k) part[std::size_t(k)] = fn(k * block, std::min(n, (k + 1) * block));
  });
  return part;
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
      : in_(in), p_(p), nv_(mesh.vertex_count()) {
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
          corners_[k++] = {js[0], js[1], normals[std::size_t(f)]};
        }
        inv_degree_[std::size_t(i)] = 1.0 / double(in.degree(i));
      }
    });
    lap_.resize(std::size_t(3 * nv_));
  }

  std::int64_t size() const { return 3 * nv_; }

  /// y = S Q S x, S = diag(scale) (the identity when scale is empty).
  void apply(std::span<const double> x, std::span<double> y,
             std::span<const double> scale = {}) const {
    laplacian(x, scale);
    parallel_chunks(nv_, p_.threads, [&](std::int64_t b, std::int64_t e) {
      for (auto i = b; i < e; ++i) output(x, y, scale, i);
    });
  }

  /// apply, and epilogue(i, partials) after each vertex i's output, in fixed blocks of vertices
  /// (the partials of each block, in order: the same for any thread count).
  template <std::size_t K, class Epilogue>
  std::vector<std::array<double, K>>
  apply_reduce(std::span<const double> x, std::span<double> y, std::span<const double> scale,
               const std::array<double, K>& init, Epilogue&& epilogue) const {
    laplacian(x, scale);
    return block_partials<K>(nv_, 2048, p_.threads, [&](std::int64_t b, std::int64_t e) {
      std::array<double, K> part = init;
      for (auto i = b; i < e; ++i) {
        output(x, y, scale, i);
        epilogue(i, part);
      }
      return part;
    });
  }

  /// y += S Q S x for an x that is zero outside the vertices `moved` (sorted, no repeats):
  /// only the rows within 2 rings of them change, computed serially (the same rounding for any
  /// thread count). O(|moved|) for bounded degrees. Overwrites the scratch of apply.
  void add_local(std::span<const double> x, std::span<const std::int64_t> moved,
                 std::span<double> y, std::span<const double> scale) const {
    auto grow = [&](std::span<const std::int64_t> set) {
      std::vector<std::int64_t> out(set.begin(), set.end());
      for (auto v : set)
        for (auto j : in_.around(v)) out.push_back(j);
      std::sort(out.begin(), out.end());
      out.erase(std::unique(out.begin(), out.end()), out.end());
      return out;
    };
    // F x is zero outside ring 1 of `moved`, the rows of Q x outside ring 2; the rows of ring 2
    // read F x on ring 3.
    const auto ring1 = grow(moved);
    const auto ring2 = grow(ring1);
    for (auto v : grow(ring2)) laplacian_at(x, scale, v);
    for (auto i : ring2) {
      const Vec v = value(x, scale, i);
      const auto k = std::size_t(3 * i);
      y[k] += v.x;
      y[k + 1] += v.y;
      y[k + 2] += v.z;
    }
  }

  /// The 3x3 diagonal blocks of Q (row-major, one per vertex): (alpha + gamma (1 + sum_{m in
  /// N(i)} 1/|N(m)|^2)) I + 2 beta sum_corners n n^T.
  std::vector<Block> diagonal_blocks() const {
    std::vector<Block> d(static_cast<std::size_t>(nv_));
    parallel_chunks(nv_, p_.threads, [&](std::int64_t b, std::int64_t e) {
      for (auto i = b; i < e; ++i) {
        double fair = 1;
        for (auto m : in_.around(i))
          fair += inv_degree_[std::size_t(m)] * inv_degree_[std::size_t(m)];
        Block blk{};
        for (auto c = corner_start_[std::size_t(i)]; c < corner_start_[std::size_t(i + 1)]; ++c) {
          const Vec n = corners_[std::size_t(c)].n;
          const std::array<double, 3> v{n.x, n.y, n.z};
          for (std::size_t a = 0; a < 3; ++a)
            for (std::size_t k = 0; k < 3; ++k) blk[3 * a + k] += 2 * p_.beta * v[a] * v[k];
        }
        for (std::size_t a = 0; a < 3; ++a) blk[4 * a] += p_.alpha + p_.gamma * fair;
        d[std::size_t(i)] = blk;
      }
    });
    return d;
  }

private:
  static Vec at(std::span<const double> v, std::int64_t i) {
    return Vec{v[std::size_t(3 * i)], v[std::size_t(3 * i + 1)], v[std::size_t(3 * i + 2)]};
  }
  static Vec scaled_at(std::span<const double> x, std::span<const double> scale, std::int64_t i) {
    const auto k = std::size_t(3 * i);
    return scale.empty() ? Vec{x[k], x[k + 1], x[k + 2]}
                         : Vec{scale[k] * x[k], scale[k + 1] * x[k + 1], scale[k + 2] * x[k + 2]};
  }
  // lap_ = F (S x)
  void laplacian(std::span<const double> x, std::span<const double> scale) const {
    parallel_chunks(nv_, p_.threads, [&](std::int64_t b, std::int64_t e) {
      for (auto i = b; i < e; ++i) laplacian_at(x, scale, i);
    });
  }
  // (S Q S x)_i from lap_
  Vec value(std::span<const double> x, std::span<const double> scale, std::int64_t i) const {
    const Vec xi = scaled_at(x, scale, i);
    Vec align{0, 0, 0};
    for (auto c = corner_start_[std::size_t(i)]; c < corner_start_[std::size_t(i + 1)]; ++c) {
      const auto& k = corners_[std::size_t(c)];
      align += dot(k.n, 2.0 * xi - scaled_at(x, scale, k.next) - scaled_at(x, scale, k.prev)) * k.n;
    }
    const std::span<const double> lap(lap_);
    Vec fair = at(lap, i);
    for (auto m : in_.around(i)) fair -= inv_degree_[std::size_t(m)] * at(lap, m);
    const Vec out = p_.alpha * xi + p_.beta * align + p_.gamma * fair;
    if (scale.empty()) return out;
    const auto k = std::size_t(3 * i);
    return {scale[k] * out.x, scale[k + 1] * out.y, scale[k + 2] * out.z};
  }
  void output(std::span<const double> x, std::span<double> y, std::span<const double> scale,
              std::int64_t i) const {
    const Vec v = value(x, scale, i);
    const auto k = std::size_t(3 * i);
    y[k] = v.x;
    y[k + 1] = v.y;
    y[k + 2] = v.z;
  }
  // lap_ at vertex i (from x at i and N(i))
  void laplacian_at(std::span<const double> x, std::span<const double> scale,
                    std::int64_t i) const {
    Vec s{0, 0, 0};
    for (auto j : in_.around(i)) s += scaled_at(x, scale, j);
    const Vec l = scaled_at(x, scale, i) - inv_degree_[std::size_t(i)] * s;
    lap_[std::size_t(3 * i)] = l.x;
    lap_[std::size_t(3 * i + 1)] = l.y;
    lap_[std::size_t(3 * i + 2)] = l.z;
  }

  struct Corner {
    std::int64_t next, prev;
    Vec n; // the normal of the corner's face
  };
  const Incidence& in_;
  const RegularizationParameters& p_;
  std::int64_t nv_;
  std::vector<std::int64_t> corner_start_;
  std::vector<Corner> corners_;
  std::vector<double> inv_degree_;
  mutable std::vector<double> lap_;
};

// S Q S, the Jacobi-scaled operator of the minimizer.
struct ScaledOperator {
  const EnergyOperator& op;
  std::span<const double> s;
  void operator()(std::span<const double> x, std::span<double> y) const { op.apply(x, y, s); }
};

template <std::size_t K, class Fn>
std::array<double, K> block_sums(std::int64_t n, unsigned threads, Fn&& fn) {
  std::array<double, K> out{};
  for (const auto& s : block_partials<K>(n, 4096, threads, std::forward<Fn>(fn)))
    for (std::size_t k = 0; k < K; ++k) out[k] += s[k];
  return out;
}

// z = B_F^{-1} r_F on the free coordinates F of one vertex (zero on the others): B the vertex's
// 3x3 diagonal block of the scaled matrix, B_F its principal submatrix on F (positive definite:
// a principal submatrix of a positive definite matrix), solved by Cramer's rule.
void solve_free_block(const Block& bl, const std::array<bool, 3>& free, const double* r,
                      double* z) {
  std::array<std::size_t, 3> f{};
  std::size_t m = 0;
  for (std::size_t a = 0; a < 3; ++a) {
    z[a] = 0;
    if (free[a]) f[m++] = a;
  }
  if (m == 1) {
    z[f[0]] = r[f[0]] / bl[4 * f[0]];
  } else if (m == 2) {
    const double a = bl[4 * f[0]], b = bl[3 * f[0] + f[1]], d = bl[4 * f[1]];
    const double det = a * d - b * b, r0 = r[f[0]], r1 = r[f[1]];
    z[f[0]] = (d * r0 - b * r1) / det;
    z[f[1]] = (a * r1 - b * r0) / det;
  } else if (m == 3) {
    const double c00 = bl[4] * bl[8] - bl[5] * bl[7], c01 = bl[5] * bl[6] - bl[3] * bl[8];
    const double c02 = bl[3] * bl[7] - bl[4] * bl[6], c11 = bl[0] * bl[8] - bl[2] * bl[6];
    const double c12 = bl[1] * bl[6] - bl[0] * bl[7], c22 = bl[0] * bl[4] - bl[1] * bl[3];
    const double det = bl[0] * c00 + bl[1] * c01 + bl[2] * c02;
    z[0] = (c00 * r[0] + c01 * r[1] + c02 * r[2]) / det;
    z[1] = (c01 * r[0] + c11 * r[1] + c12 * r[2]) / det;
    z[2] = (c02 * r[0] + c12 * r[1] + c22 * r[2]) / det;
  }
}

// MPRGP (Dostal, Schoberl, Comput. Optim. Appl. 30, 2005; Dostal, "Optimal quadratic programming
// algorithms", Springer 2009, ch. 8) with preconditioning in face: min f(y) = y^T A y / 2 - b^T y
// over the box |y_k| <= u_k (u_k may be infinite), the unknowns in blocks of 3 (one vertex).
// Conjugate gradient steps on the free set, preconditioned by the free part of A's 3x3 diagonal
// blocks (z = M_F^{-1} phi, zero on the clamped coordinates), while they stay feasible and the
// chopped gradient is small against the free one (Gamma = 1); expansion steps when CG would leave
// the box: the whole CG step projected onto the box when f there is below f at the feasible CG step
// (cf. the "projected CG" expansion of Kruzik, Horak, Cermak, Pospisil, Pecha, "Active set
// expansion strategies in MPRGP algorithm", Adv. Eng. Softw. 149, 2020), else MPRGP's: the feasible
// CG step, then a projected gradient step of fixed length abar <= 2 / |A|; f decreases at every
// step; proportioning steps (along the chopped gradient) to release constraints. Stops when the
// projected gradient g^P (the free gradient plus the chopped one, zero exactly at the KKT point)
// has |g^P|_2 <= eps, checked again on the gradient recomputed from y (the recurrence's rounding
// does not decide). Without bounds it is the block-Jacobi preconditioned conjugate gradient method.
// Each pass over the unknowns does the work of one vertex at a time (update, preconditioner, the
// sums of the next test), in fixed blocks: the same rounding for any thread count.
struct MprgpOutcome {
  int iterations = 0;
  bool converged = false;
  double residual = 0; // |g^P(y)|_2 at the end (recomputed)
};

MprgpOutcome mprgp(const ScaledOperator& apply, std::span<const Block> blocks,
                   std::span<const double> b, std::span<const double> u, double abar, double eps,
                   int max_iterations, unsigned threads, std::vector<double>& y) {
  const auto n = std::int64_t(b.size());
  const std::int64_t nv = n / 3;
  const auto N = std::size_t(n);
  constexpr std::int64_t block = 2048; // vertices
  std::vector<double> g(N), p(N), ap(N), z(N), y_try(N), g_try(N), correction(N);
  std::vector<unsigned char> moved_flag(static_cast<std::size_t>(nv));
  std::vector<std::int64_t> moved;
  const double inv_abar = 1 / abar;
  auto is_free = [&](std::size_t k) { return std::abs(y[k]) < u[k]; };
  // chopped gradient: at the lower bound min(g, 0), at the upper max(g, 0)
  auto chopped = [&](std::size_t k) {
    if (is_free(k)) return 0.0;
    return y[k] < 0 ? std::min(g[k], 0.0) : std::max(g[k], 0.0);
  };
  auto free_part = [&](std::size_t k) { return is_free(k) ? g[k] : 0.0; };
  // z = M_F^{-1} phi(y) at vertex i
  auto precondition = [&](std::int64_t i) {
    const auto k = std::size_t(3 * i);
    solve_free_block(blocks[std::size_t(i)], {is_free(k), is_free(k + 1), is_free(k + 2)}, &g[k],
                     &z[k]);
  };
  // |beta|^2, phi~^T phi, |phi|^2 at vertex i (phi~: the reduced free gradient)
  auto tests = [&](std::int64_t i, std::array<double, 3>& s) {
    for (std::size_t k = std::size_t(3 * i); k < std::size_t(3 * i + 3); ++k) {
      const double be = chopped(k), ph = free_part(k);
      double reduced = 0;
      if (ph > 0)
        reduced = std::min((y[k] + u[k]) * inv_abar, ph);
      else if (ph < 0)
        reduced = std::max((y[k] - u[k]) * inv_abar, ph);
      s[0] += be * be;
      s[1] += reduced * ph;
      s[2] += ph * ph;
    }
  };
  auto sum3 = [](const std::vector<std::array<double, 3>>& part) {
    std::array<double, 3> out{};
    for (const auto& s : part)
      for (std::size_t k = 0; k < 3; ++k) out[k] += s[k];
    return out;
  };
  // p = z = M_F^{-1} phi(y) (after g -= b when `subtract_b`: g was A y), and the tests
  auto restart = [&](bool subtract_b) {
    return sum3(block_partials<3>(nv, block, threads, [&](std::int64_t lo, std::int64_t hi) {
      std::array<double, 3> s{};
      for (auto i = lo; i < hi; ++i) {
        const auto k = std::size_t(3 * i);
        if (subtract_b)
          for (std::size_t a = 0; a < 3; ++a) g[k + a] -= b[k + a];
        precondition(i);
        for (std::size_t a = 0; a < 3; ++a) p[k + a] = z[k + a];
        tests(i, s);
      }
      return s;
    }));
  };
  // ap = A v, with v^T A v, g^T v and the largest step along -v that stays in the box
  auto apply_along = [&](const std::vector<double>& v) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    const auto part = apply.op.apply_reduce<3>(
        v, ap, apply.s, {0, 0, inf}, [&](std::int64_t i, std::array<double, 3>& t) {
          for (auto k = std::size_t(3 * i); k < std::size_t(3 * i + 3); ++k) {
            t[0] += v[k] * ap[k];
            t[1] += g[k] * v[k];
            if (v[k] > 0)
              t[2] = std::min(t[2], (y[k] + u[k]) / v[k]);
            else if (v[k] < 0)
              t[2] = std::min(t[2], (y[k] - u[k]) / v[k]);
          }
        });
    std::array<double, 3> out{0, 0, inf};
    for (const auto& t : part) {
      out[0] += t[0];
      out[1] += t[1];
      out[2] = std::min(out[2], t[2]);
    }
    out[2] = std::max(out[2], 0.0);
    return out;
  };
  apply(y, g);
  std::array<double, 3> sums = restart(true);
  MprgpOutcome out;
  bool recomputed = true;
  for (;;) {
    out.residual = std::sqrt(sums[0] + sums[2]);
    if (out.residual <= eps) {
      if (recomputed) {
        out.converged = true;
        return out;
      }
      apply(y, g); // the recurrence said so: check on the true gradient
      sums = restart(true);
      recomputed = true;
      continue;
    }
    if (out.iterations >= max_iterations) return out;
    ++out.iterations;
    recomputed = false;
    if (sums[0] <= sums[1]) {
      const auto pa = apply_along(p);
      if (!(pa[0] > 0)) { // p = 0 up to rounding: restart from the true gradient
        apply(y, g);
        sums = restart(true);
        recomputed = true;
        continue;
      }
      const double acg = pa[1] / pa[0], af = pa[2];
      if (acg <= af) { // conjugate gradient step
        const auto za = block_sums<1>(nv, threads, [&](std::int64_t lo, std::int64_t hi) {
          std::array<double, 1> t{};
          for (auto i = lo; i < hi; ++i) {
            for (auto k = std::size_t(3 * i); k < std::size_t(3 * i + 3); ++k) {
              y[k] = std::clamp(y[k] - acg * p[k], -u[k], u[k]);
              g[k] -= acg * ap[k];
            }
            precondition(i);
            for (auto k = std::size_t(3 * i); k < std::size_t(3 * i + 3); ++k) t[0] += z[k] * ap[k];
          }
          return t;
        });
        const double gamma = za[0] / pa[0];
        sums = sum3(block_partials<3>(nv, block, threads, [&](std::int64_t lo, std::int64_t hi) {
          std::array<double, 3> s{};
          for (auto i = lo; i < hi; ++i) {
            for (auto k = std::size_t(3 * i); k < std::size_t(3 * i + 3); ++k)
              p[k] = z[k] - gamma * p[k];
            tests(i, s);
          }
          return s;
        }));
      } else { // expansion step
        // The whole CG step projected onto the box, kept when its f is below f at the feasible
        // step y - af p (where MPRGP's expansion starts); else MPRGP's expansion from there.
        // Its gradient: g - acg A p, plus A times the projection's correction, which is zero
        // but on the coordinates that the projection moved (a product near those vertices), or
        // a whole product when they are many.
        parallel_chunks(nv, threads, [&](std::int64_t lo, std::int64_t hi) {
          for (auto i = lo; i < hi; ++i) {
            moved_flag[std::size_t(i)] = 0;
            for (auto k = std::size_t(3 * i); k < std::size_t(3 * i + 3); ++k) {
              const double free_step = y[k] - acg * p[k];
              y_try[k] = std::clamp(free_step, -u[k], u[k]);
              correction[k] = y_try[k] - free_step;
              g_try[k] = g[k] - acg * ap[k];
              if (correction[k] != 0) moved_flag[std::size_t(i)] = 1;
            }
          }
        });
        moved.clear();
        for (std::int64_t i = 0; i < nv; ++i)
          if (moved_flag[std::size_t(i)]) moved.push_back(i);
        const bool local = std::int64_t(moved.size()) * 32 <= nv;
        if (local)
          apply.op.add_local(correction, moved, g_try, apply.s);
        else
          apply(y_try, g_try);
        const auto f2 = block_sums<2>(n, threads, [&](std::int64_t lo, std::int64_t hi) {
          std::array<double, 2> t{};
          for (auto k = std::size_t(lo); k < std::size_t(hi); ++k) {
            if (!local) g_try[k] -= b[k];
            t[0] += y_try[k] * (g_try[k] - b[k]);
            t[1] += y[k] * (g[k] - b[k]);
          }
          return t;
        });
        // f(y) = y^T (g - b) / 2; along -p it is a parabola
        const double f_feasible = f2[1] / 2 - af * pa[1] + af * af * pa[0] / 2;
        const bool taken = f2[0] / 2 < f_feasible;
        if (taken) {
          std::swap(y, y_try);
          std::swap(g, g_try);
        } else {
          parallel_chunks(n, threads, [&](std::int64_t lo, std::int64_t hi) {
            for (auto k = std::size_t(lo); k < std::size_t(hi); ++k) {
              y[k] = std::clamp(y[k] - af * p[k], -u[k], u[k]);
              g[k] -= af * ap[k];
              y[k] = std::clamp(y[k] - abar * free_part(k), -u[k], u[k]);
            }
          });
          apply(y, g);
        }
        sums = restart(!taken); // g_try was A y_try - b; here g = A y, b still to subtract
        recomputed = !(taken && local);
      }
    } else { // proportioning step along the chopped gradient (into the box)
      std::vector<double>& d = p;
      parallel_chunks(n, threads, [&](std::int64_t lo, std::int64_t hi) {
        for (auto k = std::size_t(lo); k < std::size_t(hi); ++k) d[k] = chopped(k);
      });
      const auto da = apply_along(d);
      const double a = std::min(da[1] / da[0], da[2]);
      parallel_chunks(n, threads, [&](std::int64_t lo, std::int64_t hi) {
        for (auto k = std::size_t(lo); k < std::size_t(hi); ++k) {
          y[k] = std::clamp(y[k] - a * d[k], -u[k], u[k]);
          g[k] -= a * ap[k];
        }
      });
      sums = restart(false);
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
  // The scaling S = D^{-1/2} and the preconditioner's blocks S_i Q_ii S_i (unit diagonal).
  std::vector<Block> blocks = op.diagonal_blocks();
  const auto N = 3 * blocks.size();
  std::vector<double> s(N);
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    for (std::size_t a = 0; a < 3; ++a) s[3 * i + a] = 1 / std::sqrt(blocks[i][4 * a]);
    for (std::size_t a = 0; a < 3; ++a)
      for (std::size_t c = 0; c < 3; ++c) blocks[i][3 * a + c] *= s[3 * i + a] * s[3 * i + c];
  }
  const double half = h / 2;
  std::vector<double> b(N), u(N);
  for (std::size_t k = 0; k < N; ++k) {
    b[k] = -s[k] * g[k];
    u[k] = p.clamp ? half / s[k] : std::numeric_limits<double>::infinity();
  }
  const ScaledOperator apply{op, s};
  const double abar = 1.9 / scaled_gershgorin(mesh, normals, in, p, s);
  const double b_norm = std::sqrt(std::inner_product(b.begin(), b.end(), b.begin(), 0.0));
  std::vector<double> y(N, 0.0);
  const MprgpOutcome out =
      mprgp(apply, blocks, b, u, abar, p.tolerance * b_norm, p.max_iterations, p.threads, y);
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
