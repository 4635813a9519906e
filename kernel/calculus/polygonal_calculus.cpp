#include <zdg/kernel/calculus/polygonal_calculus.hpp>

#include <zdg/arith/error.hpp>

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

PolygonalFace make_face(std::vector<P3> x, const std::string& where) {
  PolygonalFace F;
  const int n = int(x.size());
  F.n = n;
  P3 a{0, 0, 0}, c{0, 0, 0};
  for (int i = 0; i < n; ++i) {
    a = a + cross(x[std::size_t(i)], x[std::size_t((i + 1) % n)]);
    c = c + x[std::size_t(i)];
  }
  a = 0.5 * a;
  c = (1.0 / n) * c;
  const double A = std::sqrt(dot(a, a));
  if (!(A > 0) || !std::isfinite(A))
    throw InvalidArgument(where + ": a degenerate face (zero area: it has no normal)");
  const P3 nrm = (1.0 / A) * a;
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
  faces_.reserve(std::size_t(mesh.face_count()));
  for (std::int64_t f = 0; f < mesh.face_count(); ++f) {
    const auto idx = mesh.face(f);
    std::vector<P3> x;
    for (const auto v : idx) x.push_back(mesh.vertices[std::size_t(v)]);
    const std::string where = "polygonal calculus: face " + std::to_string(f);
    if (!normals.empty()) {
      P3 nu = normals[std::size_t(f)];
      const double l = std::sqrt(dot(nu, nu));
      if (!(l > 0) || !std::isfinite(l))
        throw InvalidArgument(where + ": its normal is zero or not finite");
      nu = (1.0 / l) * nu;
      P3 c{0, 0, 0};
      for (const auto& p : x) c = c + p;
      c = (1.0 / double(x.size())) * c;
      for (auto& p : x) p = p - dot(p - c, nu) * nu;
    }
    first_corner_.push_back(corners_);
    corners_ += std::int64_t(idx.size());
    index_.emplace_back(idx.begin(), idx.end());
    faces_.push_back(make_face(std::move(x), where));
  }
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
    return index_[f][std::size_t(i)];
  case Space::corner:
    return first_corner_[f] + i;
  case Space::face_vector:
    break;
  }
  return std::int64_t(3 * f) + i;
}

SparseMatrix PolygonalCalculus::assemble(std::vector<double> PolygonalFace::*block, Space rows,
                                         Space cols) const {
  std::vector<SparseTriplet> t;
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    const int n = faces_[f].n;
    scatter(
        t, faces_[f].*block, rows == Space::face_vector ? 3 : n, cols == Space::face_vector ? 3 : n,
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
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    const auto base = [&](int i) { return first_corner_[f] + i; };
    scatter(t, faces_[f].M(lambda), faces_[f].n, faces_[f].n, base, base);
  }
  return SparseMatrix::from_triplets(corners_, corners_, std::move(t));
}

SparseMatrix PolygonalCalculus::divergence(double lambda) const {
  check_lambda(lambda);
  std::vector<SparseTriplet> t;
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    const auto& F = faces_[f];
    // -D^T M V (n x 3)
    auto b = mul(transposed(F.D, F.n, F.n), mul(F.M(lambda), F.V, F.n, F.n, 3), F.n, F.n, 3);
    for (auto& x : b) x = -x;
    scatter(
        t, b, F.n, 3, [&](int i) { return index_[f][std::size_t(i)]; },
        [&](int j) { return std::int64_t(3 * f) + j; });
  }
  return SparseMatrix::from_triplets(vertices_, 3 * face_count(), std::move(t));
}

SparseMatrix PolygonalCalculus::laplacian(double lambda) const {
  check_lambda(lambda);
  std::vector<SparseTriplet> t;
  std::size_t entries = 0;
  for (const auto& F : faces_) entries += std::size_t(F.n) * std::size_t(F.n);
  t.reserve(entries);
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    const auto at = [&](int i) { return index_[f][std::size_t(i)]; };
    scatter(t, faces_[f].L(lambda), faces_[f].n, faces_[f].n, at, at);
  }
  return SparseMatrix::from_triplets(vertices_, vertices_, std::move(t));
}

std::vector<double> PolygonalCalculus::vertex_masses() const {
  std::vector<double> m(std::size_t(vertices_), 0.0);
  for (std::size_t f = 0; f < faces_.size(); ++f)
    for (const auto v : index_[f]) m[std::size_t(v)] += faces_[f].area / faces_[f].n;
  return m;
}

std::vector<double> PolygonalCalculus::face_areas() const {
  std::vector<double> a;
  a.reserve(faces_.size());
  for (const auto& F : faces_) a.push_back(F.area);
  return a;
}

} // namespace zdg
