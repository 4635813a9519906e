#include <zdg/estimators/ambrosio_tortorelli_mesh.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/linalg/sparse_spd_solver.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <optional>
#include <string>
#include <tuple>
#include <utility>

namespace zdg {

namespace {

using P = Point3<double>;

std::size_t idx(std::int64_t i) {
  return static_cast<std::size_t>(i);
}

std::string str(std::int64_t i) {
  return std::to_string(i);
}

[[noreturn]] void bad(const std::string& what) {
  throw InvalidArgument("Ambrosio-Tortorelli (mesh): " + what);
}

double norm(P p) {
  return std::sqrt(dot(p, p));
}

// The vector area of face f (half the sum of the cross products of its sides, from its first
// vertex).
P vector_area(std::span<const P> positions, std::span<const std::int64_t> face) {
  P s{0, 0, 0};
  const P o = positions[idx(face[0])];
  for (std::size_t i = 1; i + 1 < face.size(); ++i)
    s = s + cross(positions[idx(face[i])] - o, positions[idx(face[i + 1])] - o);
  return 0.5 * s;
}

std::span<const std::int64_t> face_of(const ATMesh& m, std::int64_t f) {
  const auto b = m.face_start[idx(f)], e = m.face_start[idx(f) + 1];
  return std::span<const std::int64_t>(m.face_vertices).subspan(idx(b), idx(e - b));
}

// The measures of the calculus from the vertex positions (the header's list).
void measure(ATMesh& m, std::span<const P> positions) {
  const std::int64_t nf = m.face_count();
  if (m.edges.empty()) bad("the mesh has no edges");
  double total = 0;
  for (std::size_t e = 0; e < m.edges.size(); ++e) {
    const double l = norm(positions[idx(m.edges[e].a)] - positions[idx(m.edges[e].b)]);
    if (!(l > 0) || !std::isfinite(l))
      bad("edge (" + str(m.edges[e].a) + ", " + str(m.edges[e].b) + ") has length zero");
    total += l;
  }
  m.unit = total / static_cast<double>(m.edges.size());
  const double h = m.unit;
  std::vector<P> centre(idx(nf));
  m.face_area.assign(idx(nf), 0.0);
  m.vertex_area.assign(idx(m.vertex_count), 0.0);
  for (std::int64_t f = 0; f < nf; ++f) {
    const auto face = face_of(m, f);
    const double a = norm(vector_area(positions, face)) / (h * h);
    if (!(a > 0) || !std::isfinite(a)) bad("face " + str(f) + " has zero area");
    m.face_area[idx(f)] = a;
    P c{0, 0, 0};
    for (const auto v : face) {
      c = c + positions[idx(v)];
      m.vertex_area[idx(v)] += a / static_cast<double>(face.size());
    }
    centre[idx(f)] = (1.0 / static_cast<double>(face.size())) * c;
  }
  m.jump_weight.assign(m.edges.size(), 0.0);
  m.edge_weight.assign(m.edges.size(), 0.0);
  for (std::size_t e = 0; e < m.edges.size(); ++e) {
    const auto& ed = m.edges[e];
    const P pa = positions[idx(ed.a)], pb = positions[idx(ed.b)];
    const P mid = 0.5 * (pa + pb);
    const double l = norm(pa - pb) / h;
    double d = norm(centre[idx(ed.face[0])] - mid) / h;
    if (ed.face[1] >= 0) d += norm(centre[idx(ed.face[1])] - mid) / h;
    if (!(d > 0)) bad("edge (" + str(ed.a) + ", " + str(ed.b) + ") has a dual edge of length zero");
    m.edge_weight[e] = d / l;
    if (ed.face[1] >= 0) m.jump_weight[e] = l / d;
  }
}

} // namespace

ATMesh at_mesh(const PolygonMesh& mesh) {
  mesh.validate();
  const std::int64_t nf = mesh.face_count();
  if (nf == 0) bad("the mesh is empty (no faces)");
  ATMesh m;
  m.vertex_count = mesh.vertex_count();
  std::vector<std::int64_t> start(idx(nf) + 1);
  for (std::int64_t f = 0; f <= nf; ++f) start[idx(f)] = f * mesh.face_size;
  m.face_start = std::move(start);
  m.face_vertices = mesh.indices;
  // The sides (min, max, face), sorted: one side is a boundary edge, two an interior edge.
  std::vector<std::tuple<std::int64_t, std::int64_t, std::int64_t>> sides;
  sides.reserve(mesh.indices.size());
  for (std::int64_t f = 0; f < nf; ++f) {
    const auto face = mesh.face(f);
    for (std::size_t i = 0; i < face.size(); ++i) {
      const auto a = face[i], b = face[(i + 1) % face.size()];
      for (std::size_t j = i + 1; j < face.size(); ++j)
        if (face[j] == face[i]) bad("face " + str(f) + " uses vertex " + str(a) + " twice");
      sides.emplace_back(std::min(a, b), std::max(a, b), f);
    }
  }
  std::sort(sides.begin(), sides.end());
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i + 1;
    while (j < sides.size() && std::get<0>(sides[j]) == std::get<0>(sides[i]) &&
           std::get<1>(sides[j]) == std::get<1>(sides[i]))
      ++j;
    if (j - i > 2)
      bad("the edge (" + str(std::get<0>(sides[i])) + ", " + str(std::get<1>(sides[i])) + ") has " +
          str(static_cast<std::int64_t>(j - i)) +
          " faces: not a manifold mesh (at most two faces per edge)");
    ATMeshEdge e;
    e.a = std::get<0>(sides[i]);
    e.b = std::get<1>(sides[i]);
    e.face = {std::get<2>(sides[i]), j - i == 2 ? std::get<2>(sides[i + 1]) : -1};
    m.edges.push_back(e);
    i = j;
  }
  measure(m, mesh.vertices);
  return m;
}

ATMesh at_mesh(const SurfelComplex& complex) {
  const std::int64_t nf = complex.surfel_count();
  if (nf == 0) bad("the surface is empty (no surfels)");
  ATMesh m;
  m.vertex_count = complex.pointel_count();
  std::vector<std::int64_t> start(idx(nf) + 1);
  m.face_vertices.reserve(idx(nf) * 4);
  for (std::int64_t f = 0; f < nf; ++f) {
    start[idx(f)] = 4 * f;
    for (const auto p : complex.surfels[idx(f)]) m.face_vertices.push_back(p);
  }
  start[idx(nf)] = 4 * nf;
  m.face_start = std::move(start);
  m.edges.reserve(complex.linels.size());
  for (const auto& l : complex.linels) {
    ATMeshEdge e;
    e.a = std::min(l.a, l.b);
    e.b = std::max(l.a, l.b);
    e.face = l.face;
    m.edges.push_back(e);
  }
  measure(m, complex.pointels);
  return m;
}

std::vector<Point3<double>> mesh_face_normals(const PolygonMesh& mesh) {
  mesh.validate();
  std::vector<P> n(idx(mesh.face_count()));
  for (std::int64_t f = 0; f < mesh.face_count(); ++f) {
    const P a = vector_area(mesh.vertices, mesh.face(f));
    const double l = norm(a);
    if (!(l > 0) || !std::isfinite(l)) bad("face " + str(f) + " has zero area");
    n[idx(f)] = (1 / l) * a;
  }
  return n;
}

namespace {

void check_options(const ATMeshOptions& o) {
  if (!(o.cg_tolerance > 0) || !std::isfinite(o.cg_tolerance))
    bad("the CG tolerance must be positive, got " + std::to_string(o.cg_tolerance));
  if (o.cg_max_iterations < 0)
    bad("cg_max_iterations must be non-negative, got " + str(o.cg_max_iterations));
  if (!(o.threshold >= 0 && o.threshold <= 1))
    bad("the threshold must be in [0, 1], got " + std::to_string(o.threshold));
}

void check_eps(double eps) {
  if (!(eps > 0) || !std::isfinite(eps)) bad("eps must be positive, got " + std::to_string(eps));
}

void check_faces(const ATMesh& m, std::span<const P> f, const char* name) {
  if (static_cast<std::int64_t>(f.size()) != m.face_count())
    bad(std::string(name) + " has " + str(static_cast<std::int64_t>(f.size())) + " entries for " +
        str(m.face_count()) + " faces");
  for (std::size_t i = 0; i < f.size(); ++i)
    if (!std::isfinite(f[i].x) || !std::isfinite(f[i].y) || !std::isfinite(f[i].z))
      bad(std::string(name) + " at face " + str(static_cast<std::int64_t>(i)) + " is not finite");
}

void check_weights(const ATMesh& m, std::span<const double> w) {
  if (w.empty()) return;
  if (static_cast<std::int64_t>(w.size()) != m.face_count())
    bad("the weights have " + str(static_cast<std::int64_t>(w.size())) + " entries for " +
        str(m.face_count()) + " faces");
  for (std::size_t i = 0; i < w.size(); ++i)
    if (!(w[i] >= 0) || !std::isfinite(w[i]))
      bad("the weight of face " + str(static_cast<std::int64_t>(i)) +
          " must be finite and non-negative, got " + std::to_string(w[i]));
}

void check_vertices(const ATMesh& m, std::span<const double> v) {
  if (static_cast<std::int64_t>(v.size()) != m.vertex_count)
    bad("v has " + str(static_cast<std::int64_t>(v.size())) + " entries for " +
        str(m.vertex_count) + " vertices");
  for (std::size_t i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i]))
      bad("v at vertex " + str(static_cast<std::int64_t>(i)) + " is not finite");
}

double weight(std::span<const double> w, std::size_t f) {
  return w.empty() ? 1.0 : w[f];
}

/// Union-find with path halving.
struct Components {
  std::vector<std::int64_t> parent;
  explicit Components(std::int64_t n) : parent(idx(n)) {
    std::iota(parent.begin(), parent.end(), std::int64_t{0});
  }
  std::int64_t find(std::int64_t x) {
    while (parent[idx(x)] != x) {
      parent[idx(x)] = parent[idx(parent[idx(x)])];
      x = parent[idx(x)];
    }
    return x;
  }
  void join(std::int64_t a, std::int64_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[idx(std::max(a, b))] = std::min(a, b);
  }
};

// A symmetric matrix whose pattern is the diagonal plus the pairs (i, j) of `pairs`, with the
// positions of each pair's two entries and of the diagonal, for assembly in place.
struct Pattern {
  SparseMatrix m;
  std::vector<std::int64_t> diag, ij, ji;

  Pattern(std::int64_t n, const std::vector<std::pair<std::int64_t, std::int64_t>>& pairs) {
    std::vector<std::int64_t> count(idx(n) + 1, 1);
    count[idx(n)] = 0;
    for (const auto& [i, j] : pairs) {
      ++count[idx(i)];
      ++count[idx(j)];
    }
    std::vector<std::int64_t> start(idx(n) + 1, 0);
    for (std::int64_t i = 0; i < n; ++i) start[idx(i) + 1] = start[idx(i)] + count[idx(i)];
    std::vector<std::int64_t> cols(idx(start[idx(n)]));
    std::vector<std::int64_t> fill(start.begin(), start.end() - 1);
    for (std::int64_t i = 0; i < n; ++i) cols[idx(fill[idx(i)]++)] = i;
    for (const auto& [i, j] : pairs) {
      cols[idx(fill[idx(i)]++)] = j;
      cols[idx(fill[idx(j)]++)] = i;
    }
    m.rows = m.cols = n;
    m.row_start.assign(1, 0);
    m.row_start.reserve(idx(n) + 1);
    for (std::int64_t i = 0; i < n; ++i) {
      auto b = cols.begin() + start[idx(i)], e = cols.begin() + start[idx(i) + 1];
      std::sort(b, e);
      e = std::unique(b, e);
      m.column.insert(m.column.end(), b, e);
      m.row_start.push_back(static_cast<std::int64_t>(m.column.size()));
    }
    m.value.assign(m.column.size(), 0.0);
    const auto at = [&](std::int64_t i, std::int64_t j) {
      const auto b = m.column.begin() + m.row_start[idx(i)];
      const auto e = m.column.begin() + m.row_start[idx(i) + 1];
      return static_cast<std::int64_t>(std::lower_bound(b, e, j) - m.column.begin());
    };
    diag.resize(idx(n));
    for (std::int64_t i = 0; i < n; ++i) diag[idx(i)] = at(i, i);
    ij.resize(pairs.size());
    ji.resize(pairs.size());
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      ij[k] = at(pairs[k].first, pairs[k].second);
      ji[k] = at(pairs[k].second, pairs[k].first);
    }
  }
  void clear() { std::fill(m.value.begin(), m.value.end(), 0.0); }
  // Adds w (x_i - x_j)^2's matrix, or w (x_i + x_j)^2 / 4's when `sum`.
  void add_pair(std::size_t k, std::int64_t i, std::int64_t j, double w, bool sum) {
    const double d = sum ? w / 4 : w, o = sum ? w / 4 : -w;
    m.value[idx(diag[idx(i)])] += d;
    m.value[idx(diag[idx(j)])] += d;
    m.value[idx(ij[k])] += o;
    m.value[idx(ji[k])] += o;
  }
};

std::vector<std::pair<std::int64_t, std::int64_t>> face_pairs(const ATMesh& m) {
  std::vector<std::pair<std::int64_t, std::int64_t>> p;
  p.reserve(m.edges.size());
  for (const auto& e : m.edges)
    if (e.face[1] >= 0) p.emplace_back(e.face[0], e.face[1]);
  return p;
}

std::vector<std::pair<std::int64_t, std::int64_t>> vertex_pairs(const ATMesh& m) {
  std::vector<std::pair<std::int64_t, std::int64_t>> p;
  p.reserve(m.edges.size());
  for (const auto& e : m.edges) p.emplace_back(e.a, e.b);
  return p;
}

double squared_jump(std::span<const P> u, const ATMeshEdge& e) {
  const P d = u[idx(e.face[0])] - u[idx(e.face[1])];
  return dot(d, d);
}

// The u-step matrix on its pattern (pairs: the interior edges in order).
void assemble_u(const ATMesh& m, Pattern& pat, std::span<const double> v, double alpha,
                std::span<const double> w) {
  pat.clear();
  for (std::int64_t f = 0; f < m.face_count(); ++f)
    pat.m.value[idx(pat.diag[idx(f)])] = alpha * m.face_area[idx(f)] * weight(w, idx(f));
  std::size_t k = 0;
  for (std::size_t e = 0; e < m.edges.size(); ++e) {
    const auto& ed = m.edges[e];
    if (ed.face[1] < 0) continue;
    const double mv = 0.5 * (v[idx(ed.a)] + v[idx(ed.b)]);
    pat.add_pair(k++, ed.face[0], ed.face[1], m.jump_weight[e] * mv * mv, false);
  }
}

// The v-step matrix on its pattern (pairs: every edge in order).
void assemble_v(const ATMesh& m, Pattern& pat, std::span<const P> u, double lambda, double eps) {
  pat.clear();
  const double well = lambda / (4 * eps);
  for (std::int64_t p = 0; p < m.vertex_count; ++p)
    pat.m.value[idx(pat.diag[idx(p)])] = well * m.vertex_area[idx(p)];
  for (std::size_t e = 0; e < m.edges.size(); ++e) {
    const auto& ed = m.edges[e];
    pat.add_pair(e, ed.a, ed.b, lambda * eps * m.edge_weight[e], false);
    if (ed.face[1] >= 0) pat.add_pair(e, ed.a, ed.b, m.jump_weight[e] * squared_jump(u, ed), true);
  }
}

// AT_eps, its four sums taken by fixed blocks (of faces, edges, vertices) added in block order:
// the same value on any number of threads.
double energy(const ATMesh& m, std::span<const P> g, std::span<const P> u,
              std::span<const double> v, const ATParameters& p, double eps,
              std::span<const double> w, unsigned threads = 1) {
  constexpr std::int64_t kSpan = 1 << 15;
  const auto nf = std::int64_t(g.size()), ne = m.edge_count(), nv = std::int64_t(v.size());
  const std::int64_t bf = (nf + kSpan - 1) / kSpan, be = (ne + kSpan - 1) / kSpan,
                     bv = (nv + kSpan - 1) / kSpan;
  std::vector<std::array<double, 4>> part(idx(bf + be + bv), {0, 0, 0, 0});
  parallel_for(bf + be + bv, threads, [&](std::int64_t blk) {
    auto& s = part[idx(blk)];
    if (blk < bf) {
      for (auto f = idx(blk * kSpan); f < idx(std::min(nf, (blk + 1) * kSpan)); ++f) {
        const P d = u[f] - g[f];
        s[0] += weight(w, f) * m.face_area[f] * dot(d, d);
      }
    } else if (blk < bf + be) {
      const auto b0 = (blk - bf) * kSpan;
      for (auto e = idx(b0); e < idx(std::min(ne, b0 + kSpan)); ++e) {
        const auto& ed = m.edges[e];
        const double dv = v[idx(ed.b)] - v[idx(ed.a)];
        s[2] += m.edge_weight[e] * dv * dv;
        if (ed.face[1] < 0) continue;
        const double mv = 0.5 * (v[idx(ed.a)] + v[idx(ed.b)]);
        s[1] += m.jump_weight[e] * mv * mv * squared_jump(u, ed);
      }
    } else {
      const auto b0 = (blk - bf - be) * kSpan;
      for (auto q = idx(b0); q < idx(std::min(nv, b0 + kSpan)); ++q)
        s[3] += m.vertex_area[q] * (1 - v[q]) * (1 - v[q]);
    }
  });
  double data = 0, coupling = 0, dirichlet = 0, well = 0;
  for (const auto& s : part) {
    data += s[0];
    coupling += s[1];
    dirichlet += s[2];
    well += s[3];
  }
  return p.alpha * data + coupling + p.lambda * eps * dirichlet + p.lambda / (4 * eps) * well;
}

// Preconditioned conjugate gradients on a for K right-hand sides at once (column k of b and x
// at K i + k), from x (the previous iterate): K independent CG runs in lockstep, each with its
// own scalars, each stopping when ||r_k|| <= tol ||b_k|| (its later iterations leave it
// unchanged), sharing each pass over the matrix. The rows are cut into fixed blocks of kBlock;
// the preconditioner is Jacobi, or (incomplete_cholesky) block Jacobi with the zero-fill
// incomplete Cholesky factor IC(0) of each diagonal block (Meijerink, van der Vorst, Math.
// Comp. 31, 1977: it exists for the M-matrices of the u-step; a pivot that is not positive is
// replaced by the diagonal entry, which keeps the preconditioner symmetric positive definite).
// One team of workers for the whole solve; each block's partial dot products are summed in
// block order, so that the iterates do not depend on the thread count and every worker takes
// the same decisions. Returns the iterations of the K runs together; Error past max_iterations
// (per run) or on a matrix that is not positive definite along a search direction.
struct CGWork {
  std::vector<double> inv, r, p, ap, z;
  std::vector<double> l, ldiag_inv; // IC(0): L's entries at A's positions, 1 / its diagonal
  // Row i's entries in its block: [lo, dg) left of the diagonal, (dg, hi) right of it; tpos of
  // an entry (i, j) right of the diagonal: the position of (j, i), where L holds l_ji.
  std::vector<std::int64_t> lo, dg, hi, tpos;
};

constexpr std::int64_t kBlock = 4096;

// IC(0) of the diagonal block [i0, i1) of a (rows' columns sorted).
void factor_block(const SparseMatrix& a, std::int64_t i0, std::int64_t i1, CGWork& w) {
  for (std::int64_t i = i0; i < i1; ++i) {
    const auto rb = a.column.begin() + a.row_start[idx(i)];
    const auto re = a.column.begin() + a.row_start[idx(i) + 1];
    w.lo[idx(i)] = std::lower_bound(rb, re, i0) - a.column.begin();
    w.dg[idx(i)] = std::lower_bound(rb, re, i) - a.column.begin();
    w.hi[idx(i)] = std::lower_bound(rb, re, i1) - a.column.begin();
    const double aii = a.value[idx(w.dg[idx(i)])];
    double d = aii;
    for (auto q = w.lo[idx(i)]; q < w.dg[idx(i)]; ++q) {
      const auto j = a.column[idx(q)];
      // l_ij = (a_ij - sum_{k < j} l_ik l_jk) / l_jj, k over both rows' lower entries
      double t = a.value[idx(q)];
      auto qi = w.lo[idx(i)], qj = w.lo[idx(j)];
      while (qi < q && qj < w.dg[idx(j)]) {
        const auto ci = a.column[idx(qi)], cj = a.column[idx(qj)];
        if (ci == cj)
          t -= w.l[idx(qi++)] * w.l[idx(qj++)];
        else if (ci < cj)
          ++qi;
        else
          ++qj;
      }
      const double lij = t * w.ldiag_inv[idx(j)];
      w.l[idx(q)] = lij;
      d -= lij * lij;
      // row j's entry (j, i), right of its diagonal: where the backward sweep finds l_ij
      const auto jb = a.column.begin() + w.dg[idx(j)], je = a.column.begin() + w.hi[idx(j)];
      w.tpos[idx(std::lower_bound(jb, je, i) - a.column.begin())] = q;
    }
    w.ldiag_inv[idx(i)] = 1 / std::sqrt(d > 0 && std::isfinite(d) ? d : aii);
  }
}

// z = M^-1 r on the rows [i0, i1) (K columns).
template <int K>
void precondition(const SparseMatrix& a, std::int64_t i0, std::int64_t i1, bool ic, const CGWork& w,
                  const double* r, double* z) {
  if (!ic) {
    for (std::int64_t i = i0; i < i1; ++i)
      for (int k = 0; k < K; ++k) z[K * i + k] = w.inv[idx(i)] * r[K * i + k];
    return;
  }
  const std::int64_t* const column = a.column.data();
  const double* const l = w.l.data();
  for (std::int64_t i = i0; i < i1; ++i) { // L y = r (y in z)
    double y[K];
    for (int k = 0; k < K; ++k) y[k] = r[K * i + k];
    for (auto q = w.lo[idx(i)]; q < w.dg[idx(i)]; ++q) {
      const double* zj = z + K * column[q];
      for (int k = 0; k < K; ++k) y[k] -= l[q] * zj[k];
    }
    for (int k = 0; k < K; ++k) z[K * i + k] = y[k] * w.ldiag_inv[idx(i)];
  }
  for (std::int64_t i = i1 - 1; i >= i0; --i) { // L^T z = y, row i of L^T by tpos
    double y[K];
    for (int k = 0; k < K; ++k) y[k] = z[K * i + k];
    for (auto q = w.dg[idx(i)] + 1; q < w.hi[idx(i)]; ++q) {
      const double* zj = z + K * column[q];
      const double lq = l[w.tpos[idx(q)]];
      for (int k = 0; k < K; ++k) y[k] -= lq * zj[k];
    }
    for (int k = 0; k < K; ++k) z[K * i + k] = y[k] * w.ldiag_inv[idx(i)];
  }
}

template <int K>
std::int64_t block_cg(const SparseMatrix& a, std::span<const double> b, std::span<double> x,
                      const ATMeshOptions& o, const char* which, CGWork& work,
                      bool incomplete_cholesky) {
  const std::int64_t n = a.rows;
  const std::int64_t blocks = (n + kBlock - 1) / kBlock;
  const std::int64_t max_it = o.cg_max_iterations > 0 ? o.cg_max_iterations : 10 * n + 1000;
  work.inv.resize(idx(n));
  for (auto* v : {&work.r, &work.p, &work.ap, &work.z}) v->resize(idx(K * n));
  if (incomplete_cholesky) {
    work.l.resize(a.value.size());
    work.tpos.resize(a.value.size());
    work.ldiag_inv.resize(idx(n));
    for (auto* v : {&work.lo, &work.dg, &work.hi}) v->resize(idx(n));
  }
  std::vector<double>&r = work.r, &p = work.p, &ap = work.ap, &z = work.z;
  std::vector<std::int64_t> bad_row(idx(blocks), -1); // the first row of each block with d <= 0
  parallel_for(blocks, o.threads, [&](std::int64_t blk) {
    for (std::int64_t i = blk * kBlock; i < std::min(n, (blk + 1) * kBlock); ++i) {
      const double d = a.at(i, i);
      if (d > 0)
        work.inv[idx(i)] = 1 / d;
      else if (bad_row[idx(blk)] < 0)
        bad_row[idx(blk)] = i;
    }
  });
  for (const auto i : bad_row)
    if (i >= 0)
      throw Error(std::string("Ambrosio-Tortorelli (mesh): the ") + which +
                  "-step matrix has a zero diagonal entry at row " + str(i) +
                  " (an inpainted face cut off by v = 0)");
  using Sums = std::array<double, 3 * K>;
  std::array<std::vector<Sums>, 2> part{std::vector<Sums>(idx(blocks)),
                                        std::vector<Sums>(idx(blocks))};
  const std::int64_t* const row_start = a.row_start.data();
  const std::int64_t* const column = a.column.data();
  const double* const value = a.value.data();
  const auto row_product = [=](std::int64_t i, const double* v, double* out) {
    double acc[K] = {};
    for (auto q = row_start[i]; q < row_start[i + 1]; ++q) {
      const double w = value[q];
      const double* vj = v + K * column[q];
      for (int k = 0; k < K; ++k) acc[k] += w * vj[k];
    }
    for (int k = 0; k < K; ++k) out[k] = acc[k];
  };
  std::array<std::int64_t, K> it{};
  // What stopped the runs (set by rank 0; every rank stops at the same point).
  enum class Failure { none, not_definite, too_many } failure = Failure::none;
  double failed_pap = 0;
  parallel_team(o.threads, blocks, [&](unsigned rank, unsigned size, const auto& sync) {
    std::array<std::int64_t, K> done{}; // iterations per run (the same on every rank)
    const auto publish = [&] {
      if (rank == 0) it = done;
    };
    int phase = 0;
    // fn(i0, i1, sums) over this rank's blocks, then the barrier, then every block's sums
    // added in block order (two buffers alternate, so that the next phase may write while a
    // slower rank still reads).
    const auto sweep = [&](auto&& fn) {
      auto& buf = part[idx(phase++ % 2)];
      for (auto blk = std::int64_t(rank); blk < blocks; blk += size) {
        Sums s{};
        fn(blk * kBlock, std::min(n, (blk + 1) * kBlock), s);
        buf[idx(blk)] = s;
      }
      sync();
      Sums total{};
      for (const auto& s : buf)
        for (int k = 0; k < 3 * K; ++k) total[idx(k)] += s[idx(k)];
      return total;
    };
    // The block's factor; r = b - A x, p = z = M^-1 r; sums ||b_k||^2, r_k . z_k, ||r_k||^2.
    const Sums start = sweep([&](std::int64_t i0, std::int64_t i1, Sums& s) {
      if (incomplete_cholesky) factor_block(a, i0, i1, work);
      for (std::int64_t i = i0; i < i1; ++i) {
        double y[K];
        row_product(i, x.data(), y);
        for (int k = 0; k < K; ++k) r[idx(K * i + k)] = b[idx(K * i + k)] - y[k];
      }
      precondition<K>(a, i0, i1, incomplete_cholesky, work, r.data(), z.data());
      for (std::int64_t i = i0; i < i1; ++i)
        for (int k = 0; k < K; ++k) {
          const auto e = idx(K * i + k);
          p[e] = z[e];
          s[idx(k)] += b[e] * b[e];
          s[idx(K + k)] += r[e] * z[e];
          s[idx(2 * K + k)] += r[e] * r[e];
        }
    });
    std::array<double, K> rz{}, stop{};
    std::array<bool, K> active{}, zero{};
    bool any = false;
    for (int k = 0; k < K; ++k) {
      stop[idx(k)] = o.cg_tolerance * o.cg_tolerance * start[idx(k)];
      rz[idx(k)] = start[idx(K + k)];
      zero[idx(k)] = start[idx(k)] == 0; // the solution is 0
      active[idx(k)] = !zero[idx(k)] && start[idx(2 * K + k)] > stop[idx(k)];
      any = any || active[idx(k)];
    }
    for (auto blk = std::int64_t(rank); blk < blocks; blk += size)
      for (std::int64_t i = blk * kBlock; i < std::min(n, (blk + 1) * kBlock); ++i)
        for (int k = 0; k < K; ++k)
          if (zero[idx(k)]) x[idx(K * i + k)] = 0;
    while (any) {
      bool over = false;
      for (int k = 0; k < K; ++k) over = over || (active[idx(k)] && done[idx(k)] == max_it);
      if (over) {
        if (rank == 0) failure = Failure::too_many;
        return;
      }
      // ap = A p, p . ap (p is complete: the last sweep ended on the barrier)
      const Sums pap = sweep([&](std::int64_t i0, std::int64_t i1, Sums& s) {
        for (std::int64_t i = i0; i < i1; ++i) {
          double* y = ap.data() + K * i;
          row_product(i, p.data(), y);
          for (int k = 0; k < K; ++k) s[idx(k)] += p[idx(K * i + k)] * y[k];
        }
      });
      std::array<double, K> step{}; // 0 for a finished run: its x and r stay as they are
      for (int k = 0; k < K; ++k) {
        if (!active[idx(k)]) continue;
        if (!(pap[idx(k)] > 0)) {
          if (rank == 0) {
            failure = Failure::not_definite;
            failed_pap = pap[idx(k)];
          }
          return;
        }
        step[idx(k)] = rz[idx(k)] / pap[idx(k)];
      }
      // x += step p, r -= step ap, z = M^-1 r; sums r . z and r . r
      const Sums sums = sweep([&](std::int64_t i0, std::int64_t i1, Sums& s) {
        for (std::int64_t i = i0; i < i1; ++i)
          for (int k = 0; k < K; ++k) {
            const auto e = idx(K * i + k);
            x[e] += step[idx(k)] * p[e];
            r[e] -= step[idx(k)] * ap[e];
          }
        precondition<K>(a, i0, i1, incomplete_cholesky, work, r.data(), z.data());
        for (std::int64_t i = i0; i < i1; ++i)
          for (int k = 0; k < K; ++k) {
            const auto e = idx(K * i + k);
            s[idx(k)] += r[e] * z[e];
            s[idx(K + k)] += r[e] * r[e];
          }
      });
      std::array<double, K> beta{}; // 0 for a finished run: its p is not used again
      for (int k = 0; k < K; ++k) {
        if (!active[idx(k)]) continue;
        beta[idx(k)] = sums[idx(k)] / rz[idx(k)];
        rz[idx(k)] = sums[idx(k)];
        ++done[idx(k)];
      }
      // p = z + beta p
      sweep([&](std::int64_t i0, std::int64_t i1, Sums&) {
        for (std::int64_t i = i0; i < i1; ++i)
          for (int k = 0; k < K; ++k) {
            const auto e = idx(K * i + k);
            p[e] = z[e] + beta[idx(k)] * p[e];
          }
      });
      any = false;
      for (int k = 0; k < K; ++k) {
        active[idx(k)] = active[idx(k)] && sums[idx(K + k)] > stop[idx(k)];
        any = any || active[idx(k)];
      }
    }
    publish();
  });
  if (failure == Failure::too_many)
    throw Error(std::string("Ambrosio-Tortorelli (mesh): conjugate gradients on the ") + which +
                "-step did not reach the relative residual " + std::to_string(o.cg_tolerance) +
                " in " + str(max_it) + " iterations");
  if (failure == Failure::not_definite)
    throw Error(std::string("Ambrosio-Tortorelli (mesh): the ") + which +
                "-step matrix is not positive definite (p^T A p = " + std::to_string(failed_pap) +
                ")");
  std::int64_t total = 0;
  for (const auto t : it) total += t;
  return total;
}

// One linear solver per step: CG, or a Cholesky factorization analysed once.
struct StepSolver {
  const ATMeshOptions& options;
  const char* which;
  std::optional<SparseSpdSolver> cholesky;
  std::int64_t iterations = 0;
  CGWork work{};
  std::vector<double> rhs, iterate; // the step's right-hand side and iterate

  void solve(const SparseMatrix& a, std::span<const double> b, std::vector<double>& x) {
    if (options.solver == ATLinearSolver::cholesky) {
      if (cholesky)
        cholesky->refactor(a);
      else
        cholesky.emplace(a);
      x = cholesky->solve(b);
    } else {
      iterations += block_cg<1>(a, b, x, options, which, work, true);
    }
  }
  // The three coordinates of u (interleaved: x[3 f + k]) with one matrix.
  void solve3(const SparseMatrix& a, std::span<const double> b, std::vector<double>& x) {
    if (options.solver == ATLinearSolver::cholesky) {
      const std::size_t n = b.size() / 3;
      std::vector<double> bk(n), xk;
      for (std::size_t k = 0; k < 3; ++k) {
        for (std::size_t f = 0; f < n; ++f) bk[f] = b[3 * f + k];
        solve(a, bk, xk);
        for (std::size_t f = 0; f < n; ++f) x[3 * f + k] = xk[f];
      }
    } else {
      iterations += block_cg<3>(a, b, x, options, which, work, true);
    }
  }
};

void solve_u(const ATMesh& m, Pattern& pat, std::span<const P> g, std::span<const double> v,
             double alpha, std::span<const double> w, std::vector<P>& u, StepSolver& s) {
  assemble_u(m, pat, v, alpha, w);
  const std::size_t n = g.size();
  std::vector<double>&b = s.rhs, &x = s.iterate;
  b.resize(3 * n);
  x.resize(3 * n);
  for (std::size_t f = 0; f < n; ++f) {
    const double c = alpha * m.face_area[f] * weight(w, f);
    b[3 * f] = c * g[f].x;
    b[3 * f + 1] = c * g[f].y;
    b[3 * f + 2] = c * g[f].z;
    x[3 * f] = u[f].x;
    x[3 * f + 1] = u[f].y;
    x[3 * f + 2] = u[f].z;
  }
  s.solve3(pat.m, b, x);
  for (std::size_t f = 0; f < n; ++f) u[f] = {x[3 * f], x[3 * f + 1], x[3 * f + 2]};
}

void solve_v(const ATMesh& m, Pattern& pat, std::span<const P> u, double lambda, double eps,
             std::vector<double>& v, StepSolver& s) {
  assemble_v(m, pat, u, lambda, eps);
  std::vector<double>& b = s.rhs;
  b.resize(v.size());
  for (std::size_t q = 0; q < b.size(); ++q) b[q] = lambda / (4 * eps) * m.vertex_area[q];
  s.solve(pat.m, b, v);
}

// With weights: every component of the face adjacency has a face of positive weight.
void check_anchored(const ATMesh& m, std::span<const double> w) {
  if (w.empty()) return;
  Components c(m.face_count());
  for (const auto& e : m.edges)
    if (e.face[1] >= 0) c.join(e.face[0], e.face[1]);
  std::vector<char> anchored(idx(m.face_count()), 0);
  for (std::int64_t f = 0; f < m.face_count(); ++f)
    if (w[idx(f)] > 0) anchored[idx(c.find(f))] = 1;
  for (std::int64_t f = 0; f < m.face_count(); ++f)
    if (!anchored[idx(c.find(f))])
      bad("every face of the connected part of face " + str(f) +
          " has weight 0 (all inpainted): nothing to fill it from");
}

} // namespace

double at_mesh_energy(const ATMesh& mesh, std::span<const Point3<double>> g,
                      std::span<const Point3<double>> u, std::span<const double> v,
                      const ATParameters& parameters, double eps, std::span<const double> weights) {
  check_at_parameters(parameters, "Ambrosio-Tortorelli (mesh)");
  check_eps(eps);
  check_faces(mesh, g, "g");
  check_faces(mesh, u, "u");
  check_vertices(mesh, v);
  check_weights(mesh, weights);
  return energy(mesh, g, u, v, parameters, eps, weights);
}

SparseMatrix at_mesh_u_matrix(const ATMesh& mesh, std::span<const double> v, double alpha,
                              std::span<const double> weights) {
  check_vertices(mesh, v);
  check_weights(mesh, weights);
  if (!(alpha > 0) || !std::isfinite(alpha))
    bad("alpha must be positive, got " + std::to_string(alpha));
  Pattern pat(mesh.face_count(), face_pairs(mesh));
  assemble_u(mesh, pat, v, alpha, weights);
  return std::move(pat.m);
}

SparseMatrix at_mesh_v_matrix(const ATMesh& mesh, std::span<const Point3<double>> u, double lambda,
                              double eps) {
  check_faces(mesh, u, "u");
  check_eps(eps);
  if (!(lambda > 0) || !std::isfinite(lambda))
    bad("lambda must be positive, got " + std::to_string(lambda));
  Pattern pat(mesh.vertex_count, vertex_pairs(mesh));
  assemble_v(mesh, pat, u, lambda, eps);
  return std::move(pat.m);
}

std::pair<std::vector<std::int64_t>, std::int64_t>
at_mesh_segments(const ATMesh& mesh, std::span<const double> v, double threshold) {
  check_vertices(mesh, v);
  if (!(threshold >= 0 && threshold <= 1))
    bad("the threshold must be in [0, 1], got " + std::to_string(threshold));
  const std::int64_t nf = mesh.face_count();
  Components c(nf);
  for (const auto& e : mesh.edges)
    if (e.face[1] >= 0 && std::max(v[idx(e.a)], v[idx(e.b)]) >= threshold)
      c.join(e.face[0], e.face[1]);
  // Roots are the smallest face of their component; sizes, then labels by decreasing size.
  std::vector<std::int64_t> size(idx(nf), 0), root(idx(nf));
  for (std::int64_t f = 0; f < nf; ++f) ++size[idx(root[idx(f)] = c.find(f))];
  std::vector<std::int64_t> roots;
  for (std::int64_t f = 0; f < nf; ++f)
    if (root[idx(f)] == f) roots.push_back(f);
  std::stable_sort(roots.begin(), roots.end(),
                   [&](std::int64_t a, std::int64_t b) { return size[idx(a)] > size[idx(b)]; });
  std::vector<std::int64_t> label(idx(nf), -1);
  for (std::size_t k = 0; k < roots.size(); ++k)
    label[idx(roots[k])] = static_cast<std::int64_t>(k);
  std::vector<std::int64_t> out(idx(nf));
  for (std::int64_t f = 0; f < nf; ++f) out[idx(f)] = label[idx(root[idx(f)])];
  return {std::move(out), static_cast<std::int64_t>(roots.size())};
}

std::vector<double> at_face_values(const ATMesh& mesh, std::span<const double> v,
                                   ATSurfelPolicy policy) {
  check_vertices(mesh, v);
  std::vector<double> out(idx(mesh.face_count()));
  for (std::int64_t f = 0; f < mesh.face_count(); ++f) {
    const auto face = face_of(mesh, f);
    double r = policy == ATSurfelPolicy::minimum ? v[idx(face[0])] : 0.0;
    for (const auto q : face)
      r = policy == ATSurfelPolicy::minimum ? std::min(r, v[idx(q)]) : r + v[idx(q)];
    out[idx(f)] = policy == ATSurfelPolicy::minimum ? r : r / static_cast<double>(face.size());
  }
  return out;
}

ATMeshResult at_mesh_normals(const ATMesh& mesh, std::span<const Point3<double>> g,
                             const ATParameters& parameters, const ATMeshOptions& options,
                             std::span<const double> weights) {
  check_at_parameters(parameters, "Ambrosio-Tortorelli (mesh)");
  check_options(options);
  check_faces(mesh, g, "g");
  check_weights(mesh, weights);
  check_anchored(mesh, weights);
  ATMeshResult r;
  r.u.assign(g.begin(), g.end());
  r.v.assign(idx(mesh.vertex_count), 1.0);
  Pattern upat(mesh.face_count(), face_pairs(mesh));
  Pattern vpat(mesh.vertex_count, vertex_pairs(mesh));
  StepSolver us{options, "u", std::nullopt, 0, {}, {}, {}},
      vs{options, "v", std::nullopt, 0, {}, {}, {}};
  const auto energy_now = [&](double eps) {
    return energy(mesh, g, r.u, r.v, parameters, eps, weights, options.threads);
  };
  for (int k = 0;; ++k) {
    const double eps = parameters.epsilon1 / std::pow(parameters.epsilon_factor, k);
    if (eps < parameters.epsilon2 * (1 - 1e-12)) break;
    r.steps.push_back({ATStep::Kind::start, eps, energy_now(eps), 0});
    for (int i = 0; i < parameters.max_iterations; ++i) {
      solve_u(mesh, upat, g, r.v, parameters.alpha, weights, r.u, us);
      r.steps.push_back({ATStep::Kind::u, eps, energy_now(eps), 0});
      std::vector<double> v = r.v;
      solve_v(mesh, vpat, r.u, parameters.lambda, eps, v, vs);
      double change = 0;
      for (std::size_t q = 0; q < v.size(); ++q) change = std::max(change, std::abs(v[q] - r.v[q]));
      r.v = std::move(v);
      r.steps.push_back({ATStep::Kind::v, eps, energy_now(eps), change});
      ++r.iterations;
      if (change < parameters.tolerance) break;
    }
  }
  r.normals.resize(r.u.size());
  for (std::size_t f = 0; f < r.u.size(); ++f) {
    const double n = norm(r.u[f]);
    r.normals[f] = n > 0 ? (1 / n) * r.u[f] : g[f];
  }
  std::tie(r.segment, r.segments) = at_mesh_segments(mesh, r.v, options.threshold);
  r.cg_iterations = us.iterations + vs.iterations;
  if (options.solver == ATLinearSolver::cholesky)
    r.solver = us.cholesky ? spd_backend_name(us.cholesky->backend()) : "cholesky";
  else
    r.solver = "conjugate-gradient";
  return r;
}

} // namespace zdg
