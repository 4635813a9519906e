#include <zdg/kernel/calculus/polygonal_calculus.hpp>

#include <zdg/arith/error.hpp>

#include <zdg/kernel/parallel/parallel_for.hpp>
#include <zdg/kernel/parallel/populate_pages.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace zdg {

namespace {

using P3 = Point3<double>;

// Dense row-major products of small matrices: (r x k) (k x c).
std::vector<double> mul(const std::vector<double>& a, const std::vector<double>& b, int r, int k,
                        int c) {
  std::vector<double> o(std::size_t(r) * std::size_t(c), 0.0);
  for (int i = 0; i < r; ++i)
    for (int l = 0; l < k; ++l) {
      const double x = a[std::size_t(i * k + l)];
      if (x == 0) continue;
      for (int j = 0; j < c; ++j) o[std::size_t(i * c + j)] += x * b[std::size_t(l * c + j)];
    }
  return o;
}

std::vector<double> transposed(const std::vector<double>& a, int r, int c) {
  std::vector<double> o(a.size());
  for (int i = 0; i < r; ++i)
    for (int j = 0; j < c; ++j) o[std::size_t(j * r + i)] = a[std::size_t(i * c + j)];
  return o;
}

// [n]x: the 3 x 3 matrix of v -> n x v.
std::vector<double> bracket(P3 n) {
  return {0, -n.z, n.y, n.z, 0, -n.x, -n.y, n.x, 0};
}

double comp(P3 p, int a) {
  return a == 0 ? p.x : (a == 1 ? p.y : p.z);
}

// The vector area's length A, the unit normal a / A and the centroid of the n points x.
struct FaceFrame {
  double area;
  P3 normal, centroid;
};

FaceFrame face_frame(const P3* x, int n) {
  P3 a{0, 0, 0}, c{0, 0, 0};
  for (int i = 0; i < n; ++i) {
    a = a + cross(x[i], x[(i + 1) % n]);
    c = c + x[i];
  }
  a = 0.5 * a;
  c = (1.0 / n) * c;
  const double A = std::sqrt(dot(a, a));
  return {A, (1.0 / A) * a, c};
}

PolygonalFace make_face(std::vector<P3> x, const std::string& where) {
  PolygonalFace F;
  const int n = int(x.size());
  F.n = n;
  const FaceFrame fr = face_frame(x.data(), n);
  const double A = fr.area;
  if (!(A > 0) || !std::isfinite(A))
    throw InvalidArgument(where + ": a degenerate face (zero area: it has no normal)");
  const P3 nrm = fr.normal, c = fr.centroid;
  F.area = A;
  F.normal = nrm;
  F.centroid = c;
  const auto nn = std::size_t(n);
  F.D.assign(nn * nn, 0.0);
  F.Av.assign(nn * nn, 0.0);
  for (std::size_t i = 0; i < nn; ++i) {
    F.D[i * nn + i] = -1;
    F.D[i * nn + (i + 1) % nn] += 1;
    F.Av[i * nn + i] = 0.5;
    F.Av[i * nn + (i + 1) % nn] += 0.5;
  }
  // E (n x 3), the projector T = I - n n^T, B^T - c 1^T (3 x n).
  std::vector<double> E(nn * 3), T(9), Bc(3 * nn);
  for (std::size_t i = 0; i < nn; ++i) {
    const P3 e = x[(i + 1) % nn] - x[i];
    const P3 m = 0.5 * (x[i] + x[(i + 1) % nn]) - c;
    for (int k = 0; k < 3; ++k) {
      E[i * 3 + std::size_t(k)] = comp(e, k);
      Bc[std::size_t(k) * nn + i] = comp(m, k);
    }
  }
  for (int r = 0; r < 3; ++r)
    for (int s = 0; s < 3; ++s) T[std::size_t(r * 3 + s)] = (r == s) - comp(nrm, r) * comp(nrm, s);
  const auto N = bracket(nrm);
  // G = -(1/A) [n]x E^T Av; C = [n]x G.
  F.G = mul(N, mul(transposed(E, n, 3), F.Av, 3, n, n), 3, 3, n);
  for (auto& g : F.G) g *= -1.0 / A;
  F.C = mul(N, F.G, 3, 3, n);
  F.V = mul(E, T, n, 3, 3);
  F.U = mul(N, Bc, 3, 3, n);
  for (auto& u : F.U) u /= A;
  const auto VU = mul(F.V, F.U, n, 3, n);
  F.P.assign(nn * nn, 0.0);
  for (std::size_t i = 0; i < nn; ++i)
    for (std::size_t j = 0; j < nn; ++j) F.P[i * nn + j] = (i == j) - VU[i * nn + j];
  F.x = std::move(x);
  return F;
}

void check_lambda(double lambda) {
  if (!(lambda > 0) || !std::isfinite(lambda))
    throw InvalidArgument("polygonal calculus: lambda must be a finite number > 0 (got " +
                          std::to_string(lambda) + ")");
}

// The reusable buffers of face_stiffness (one per worker).
struct StiffnessScratch {
  std::vector<P3> u, v;        // U's columns, V's rows
  std::vector<double> p, m, w; // n x n: P, M, M D
};

// L = D^T M(lambda) D of the face x[0 .. n) into out (n x n, row-major), by the formulas of
// make_face without its intermediate matrices: U's column i is (1/A) n x (m_i - c), V's row i
// is e_i - (e_i . n) n, P = I - V U, M = A U^T U + lambda P^T P, (M D)_ij = M_i,j-1 - M_ij,
// (D^T W)_ij = W_i-1,j - W_ij (indices mod n). The face is not degenerate (the constructor
// checked it).
void face_stiffness(const P3* x, int n, double lambda, double* out, StiffnessScratch& s) {
  const auto nn = std::size_t(n);
  s.u.resize(nn);
  s.v.resize(nn);
  s.p.resize(nn * nn);
  s.m.resize(nn * nn);
  s.w.resize(nn * nn);
  const FaceFrame fr = face_frame(x, n);
  const P3 nrm = fr.normal;
  for (std::size_t i = 0; i < nn; ++i) {
    const P3 next = x[(i + 1) % nn];
    const P3 e = next - x[i];
    const P3 mid = 0.5 * (x[i] + next) - fr.centroid;
    s.u[i] = (1.0 / fr.area) * cross(nrm, mid);
    s.v[i] = e - dot(e, nrm) * nrm;
  }
  for (std::size_t i = 0; i < nn; ++i)
    for (std::size_t j = 0; j < nn; ++j) s.p[i * nn + j] = double(i == j) - dot(s.v[i], s.u[j]);
  for (std::size_t i = 0; i < nn; ++i)
    for (std::size_t j = i; j < nn; ++j) {
      double pp = 0;
      for (std::size_t r = 0; r < nn; ++r) pp += s.p[r * nn + i] * s.p[r * nn + j];
      const double mij = fr.area * dot(s.u[i], s.u[j]) + lambda * pp;
      s.m[i * nn + j] = mij;
      s.m[j * nn + i] = mij;
    }
  for (std::size_t i = 0; i < nn; ++i)
    for (std::size_t j = 0; j < nn; ++j)
      s.w[i * nn + j] = s.m[i * nn + (j + nn - 1) % nn] - s.m[i * nn + j];
  for (std::size_t i = 0; i < nn; ++i)
    for (std::size_t j = 0; j < nn; ++j)
      out[i * nn + j] = s.w[((i + nn - 1) % nn) * nn + j] - s.w[i * nn + j];
}

} // namespace

std::vector<double> PolygonalFace::M(double lambda) const {
  check_lambda(lambda);
  auto m = mul(transposed(U, 3, n), U, n, 3, n);
  const auto pp = mul(transposed(P, n, n), P, n, n, n);
  for (std::size_t i = 0; i < m.size(); ++i) m[i] = area * m[i] + lambda * pp[i];
  return m;
}

std::vector<double> PolygonalFace::L(double lambda) const {
  return mul(transposed(D, n, n), mul(M(lambda), D, n, n, n), n, n, n);
}

PolygonalCalculus::PolygonalCalculus(const PolygonMesh& mesh,
                                     std::span<const Point3<double>> normals) {
  mesh.validate();
  if (!normals.empty() && std::int64_t(normals.size()) != mesh.face_count())
    throw InvalidArgument("polygonal calculus: " + std::to_string(normals.size()) +
                          " face normals for " + std::to_string(mesh.face_count()) + " faces");
  vertices_ = mesh.vertex_count();
  face_size_ = mesh.face_size;
  corners_ = std::int64_t(mesh.indices.size());
  index_ = mesh.indices;
  x_.resize(index_.size());
  area_.resize(std::size_t(mesh.face_count()));
  const auto k = std::size_t(face_size_);
  for (std::size_t f = 0; f < area_.size(); ++f) {
    P3* x = x_.data() + f * k;
    for (std::size_t i = 0; i < k; ++i) x[i] = mesh.vertices[std::size_t(index_[f * k + i])];
    if (!normals.empty()) {
      P3 nu = normals[f];
      const double l = std::sqrt(dot(nu, nu));
      if (!(l > 0) || !std::isfinite(l))
        throw InvalidArgument("polygonal calculus: face " + std::to_string(f) +
                              ": its normal is zero or not finite");
      nu = (1.0 / l) * nu;
      P3 c{0, 0, 0};
      for (std::size_t i = 0; i < k; ++i) c = c + x[i];
      c = (1.0 / double(k)) * c;
      for (std::size_t i = 0; i < k; ++i) x[i] = x[i] - dot(x[i] - c, nu) * nu;
    }
    const FaceFrame fr = face_frame(x, face_size_);
    if (!(fr.area > 0) || !std::isfinite(fr.area))
      throw InvalidArgument("polygonal calculus: face " + std::to_string(f) +
                            ": a degenerate face (zero area: it has no normal)");
    area_[f] = fr.area;
  }
}

PolygonalFace PolygonalCalculus::face(std::int64_t f) const {
  const auto k = std::size_t(face_size_);
  const auto first = x_.begin() + std::ptrdiff_t(std::size_t(f) * k);
  return make_face(std::vector<P3>(first, first + std::ptrdiff_t(k)),
                   "polygonal calculus: face " + std::to_string(f));
}

namespace {

// Scatters a dense block (r x c) at (row(i), col(j)).
template <class Row, class Col>
void scatter(std::vector<SparseTriplet>& t, const std::vector<double>& b, int r, int c, Row row,
             Col col) {
  for (int i = 0; i < r; ++i)
    for (int j = 0; j < c; ++j)
      if (const double v = b[std::size_t(i * c + j)]; v != 0) t.push_back({row(i), col(j), v});
}

} // namespace

std::int64_t PolygonalCalculus::size_of(Space s) const {
  return s == Space::vertex ? vertices_ : s == Space::corner ? corners_ : 3 * face_count();
}

std::int64_t PolygonalCalculus::index_in(Space s, std::size_t f, int i) const {
  switch (s) {
  case Space::vertex:
    return index_[f * std::size_t(face_size_) + std::size_t(i)];
  case Space::corner:
    return std::int64_t(f) * face_size_ + i;
  case Space::face_vector:
    break;
  }
  return std::int64_t(3 * f) + i;
}

SparseMatrix PolygonalCalculus::assemble(std::vector<double> PolygonalFace::*block, Space rows,
                                         Space cols) const {
  std::vector<SparseTriplet> t;
  for (std::size_t f = 0; f < area_.size(); ++f) {
    const PolygonalFace F = face(std::int64_t(f));
    scatter(
        t, F.*block, rows == Space::face_vector ? 3 : F.n, cols == Space::face_vector ? 3 : F.n,
        [&](int i) { return index_in(rows, f, i); }, [&](int j) { return index_in(cols, f, j); });
  }
  return SparseMatrix::from_triplets(size_of(rows), size_of(cols), std::move(t));
}

SparseMatrix PolygonalCalculus::derivative() const {
  return assemble(&PolygonalFace::D, Space::corner, Space::vertex);
}

SparseMatrix PolygonalCalculus::gradient() const {
  return assemble(&PolygonalFace::G, Space::face_vector, Space::vertex);
}

SparseMatrix PolygonalCalculus::co_gradient() const {
  return assemble(&PolygonalFace::C, Space::face_vector, Space::vertex);
}

SparseMatrix PolygonalCalculus::flat() const {
  return assemble(&PolygonalFace::V, Space::corner, Space::face_vector);
}

SparseMatrix PolygonalCalculus::sharp() const {
  return assemble(&PolygonalFace::U, Space::face_vector, Space::corner);
}

SparseMatrix PolygonalCalculus::projection() const {
  return assemble(&PolygonalFace::P, Space::corner, Space::corner);
}

SparseMatrix PolygonalCalculus::inner_product(double lambda) const {
  check_lambda(lambda);
  std::vector<SparseTriplet> t;
  for (std::size_t f = 0; f < area_.size(); ++f) {
    const auto base = [&](int i) { return std::int64_t(f) * face_size_ + i; };
    scatter(t, face(std::int64_t(f)).M(lambda), face_size_, face_size_, base, base);
  }
  return SparseMatrix::from_triplets(corners_, corners_, std::move(t));
}

SparseMatrix PolygonalCalculus::divergence(double lambda) const {
  check_lambda(lambda);
  std::vector<SparseTriplet> t;
  for (std::size_t f = 0; f < area_.size(); ++f) {
    const PolygonalFace F = face(std::int64_t(f));
    // -D^T M V (n x 3)
    auto b = mul(transposed(F.D, F.n, F.n), mul(F.M(lambda), F.V, F.n, F.n, 3), F.n, F.n, 3);
    for (auto& x : b) x = -x;
    scatter(
        t, b, F.n, 3, [&](int i) { return index_in(Space::vertex, f, i); },
        [&](int j) { return std::int64_t(3 * f) + j; });
  }
  return SparseMatrix::from_triplets(vertices_, 3 * face_count(), std::move(t));
}

// Row v of L sums the rows of the blocks L_f of its faces: its columns are the vertices of
// those faces. Built in two passes over the vertex-face incidence (row sizes, then columns and
// values); each row accumulates its faces in the order of their corners, whatever the worker.
SparseMatrix PolygonalCalculus::laplacian(double lambda, unsigned threads) const {
  check_lambda(lambda);
  const std::int64_t faces = face_count(), k = face_size_, kk = k * k;
  const unsigned workers = worker_count(threads, faces);
  std::vector<double> blocks;
  assign_populated(blocks, std::size_t(faces * kk), workers);
  parallel_chunks(faces, workers, [&](std::int64_t b, std::int64_t e) {
    StiffnessScratch s;
    for (std::int64_t f = b; f < e; ++f)
      face_stiffness(x_.data() + f * k, int(k), lambda, blocks.data() + f * kk, s);
  });
  // The corners at each vertex, in increasing order (a counting sort).
  std::vector<std::int64_t> at_start(std::size_t(vertices_) + 1, 0), at(index_.size());
  for (const auto v : index_) ++at_start[std::size_t(v) + 1];
  for (std::size_t v = 0; v < std::size_t(vertices_); ++v) at_start[v + 1] += at_start[v];
  {
    std::vector<std::int64_t> next(at_start.begin(), at_start.end() - 1);
    for (std::size_t c = 0; c < index_.size(); ++c)
      at[std::size_t(next[std::size_t(index_[c])]++)] = std::int64_t(c);
  }
  // Row v's columns, sorted and unique, into cols.
  const auto columns_of = [&](std::int64_t v, std::vector<std::int64_t>& cols) {
    cols.clear();
    for (auto i = at_start[std::size_t(v)]; i < at_start[std::size_t(v) + 1]; ++i) {
      const std::int64_t f = at[std::size_t(i)] / k;
      for (std::int64_t j = 0; j < k; ++j) cols.push_back(index_[std::size_t(f * k + j)]);
    }
    std::sort(cols.begin(), cols.end());
    cols.erase(std::unique(cols.begin(), cols.end()), cols.end());
  };
  SparseMatrix L;
  L.rows = L.cols = vertices_;
  L.row_start.assign(std::size_t(vertices_) + 1, 0);
  parallel_chunks(vertices_, workers, [&](std::int64_t b, std::int64_t e) {
    std::vector<std::int64_t> cols;
    for (std::int64_t v = b; v < e; ++v) {
      columns_of(v, cols);
      L.row_start[std::size_t(v) + 1] = std::int64_t(cols.size());
    }
  });
  for (std::size_t v = 0; v < std::size_t(vertices_); ++v) L.row_start[v + 1] += L.row_start[v];
  const auto nnz = std::size_t(L.row_start.back());
  assign_populated(L.column, nnz, workers);
  assign_populated(L.value, nnz, workers);
  parallel_chunks(vertices_, workers, [&](std::int64_t b, std::int64_t e) {
    std::vector<std::int64_t> cols;
    for (std::int64_t v = b; v < e; ++v) {
      columns_of(v, cols);
      const auto row = std::size_t(L.row_start[std::size_t(v)]);
      std::copy(cols.begin(), cols.end(), L.column.begin() + std::ptrdiff_t(row));
      for (auto i = at_start[std::size_t(v)]; i < at_start[std::size_t(v) + 1]; ++i) {
        const std::int64_t c = at[std::size_t(i)], f = c / k, a = c % k;
        const double* lf = blocks.data() + f * kk + a * k;
        for (std::int64_t j = 0; j < k; ++j) {
          const auto pos =
              std::lower_bound(cols.begin(), cols.end(), index_[std::size_t(f * k + j)]);
          L.value[row + std::size_t(pos - cols.begin())] += lf[j];
        }
      }
    }
  });
  return L;
}

std::vector<double> PolygonalCalculus::vertex_masses() const {
  std::vector<double> m(std::size_t(vertices_), 0.0);
  for (std::size_t c = 0; c < index_.size(); ++c)
    m[std::size_t(index_[c])] += area_[c / std::size_t(face_size_)] / face_size_;
  return m;
}

std::vector<double> PolygonalCalculus::face_areas() const {
  return area_;
}

} // namespace zdg
