// The discrete calculus of polygonal surfaces (de Goes, Butts, Desbrun, "Discrete differential
// operators on polygonal meshes", ACM TOG 39(4), 2020), corrected for digital surfaces by
// re-embedding each face in the plane orthogonal to an estimated normal (Coeurjolly, Lachaud,
// "A simple discrete calculus for digital surfaces", DGMM 2022).
//
// Per face f of n vertices x_0 .. x_{n-1} (after the re-embedding: x_i - ((x_i - c) . nu) nu,
// c the vertices' mean, nu the face's given normal; without normals, the positions as they
// are), with e_i = x_{i+1} - x_i, m_i = (x_i + x_{i+1}) / 2, the vector area
// a = 1/2 sum x_i x x_{i+1}, the area A = |a|, the normal n = a / A, the centroid c:
//   D  (n x n)  (D u)_i = u_{i+1} - u_i                    (the 1-form of a 0-form, d0)
//   Av (n x n)  (Av u)_i = (u_i + u_{i+1}) / 2             (values on the edges)
//   G  (3 x n)  gradient  -(1/A) [n]x E^T Av   (the mean of grad u over the face by Stokes)
//   C  (3 x n)  co-gradient  [n]x G  = n x grad u
//   V  (n x 3)  flat   E (I - n n^T)      (an ambient vector to the 1-form on the edges)
//   U  (3 x n)  sharp  (1/A) [n]x (B^T - c 1^T), B's rows the m_i
//   P  (n x n)  projection  I - V U       (the part of a 1-form no vector field explains)
//   M  (n x n)  inner product of 1-forms  A U^T U + lambda P^T P
//   L  (n x n)  Laplacian  D^T M D        (the stiffness: symmetric, positive semi-definite)
// Identities (tested): U V = I - n n^T on a planar face; G u = the in-plane part of g for
// u = g . x on a planar face (linear precision), and then P D u = 0, so that L is exact on
// linear functions of a planar mesh at every interior vertex; L 1 = 0 and D 1 = 0 exactly.
//
// Global operators assemble the faces: 0-forms on the V vertices, vectors per face (3F rows,
// face f at 3f .. 3f + 2), 1-forms per face and edge (sum_f n_f rows, face f's edges after
// those of faces 0 .. f-1: the "corner" index, as in de Goes et al.). Divergence of a per-face
// vector field: the weak (integrated) -D^T M V, so that div(grad u) = -L u on linear u;
// Delta_S u at vertex v is estimated by -(L u)_v / m_v, m_v = sum over the
// faces at v of A_f / n_f (the lumped mass).
//
// Errors: InvalidArgument for an invalid mesh (PolygonMesh::validate), face normals that are
// neither absent nor one unit-able vector per face, a degenerate face (A = 0 after the
// re-embedding: no normal), lambda <= 0 or not finite. Cost: the constructor O(corners) (it
// keeps the re-embedded vertices, areas, normals and centroids; each face's operators are
// recomputed where an operator needs them, O(n_f^3)); every global operator O(sum n_f^3) time
// and O(sum n_f^2) entries. laplacian() builds its rows directly (the vertex-face incidence,
// each row's columns sorted, no triplets), on `threads` workers, with the same values whatever
// the count; doubles throughout, indices int64.
#pragma once

#include <zdg/arith/point.hpp>
#include <zdg/kernel/linalg/sparse_matrix.hpp>
#include <zdg/kernel/surfaces/mesh.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace zdg {

/// The operators of one face, dense and row-major (for the global matrices' tests).
struct PolygonalFace {
  int n = 0;
  std::vector<Point3<double>> x; ///< the (re-embedded) vertices
  Point3<double> normal{}, centroid{};
  double area = 0;
  std::vector<double> D, Av, G, C, V, U, P;   ///< n x n, n x n, 3 x n, 3 x n, n x 3, 3 x n, n x n
  std::vector<double> M(double lambda) const; ///< n x n
  std::vector<double> L(double lambda) const; ///< n x n
};

class PolygonalCalculus {
public:
  /// The calculus of mesh, each face re-embedded orthogonally to face_normals[f] when given
  /// (one per face; normalized here).
  explicit PolygonalCalculus(const PolygonMesh& mesh,
                             std::span<const Point3<double>> face_normals = {});

  std::int64_t vertex_count() const { return vertices_; }
  std::int64_t face_count() const { return static_cast<std::int64_t>(area_.size()); }
  std::int64_t corner_count() const { return corners_; } ///< sum of the faces' sizes

  /// The operators of face f (computed on each call: O(n_f^3)).
  PolygonalFace face(std::int64_t f) const;

  SparseMatrix derivative() const;                 ///< D: corners x V
  SparseMatrix gradient() const;                   ///< G: 3F x V
  SparseMatrix co_gradient() const;                ///< C: 3F x V
  SparseMatrix flat() const;                       ///< V: corners x 3F
  SparseMatrix sharp() const;                      ///< U: 3F x corners
  SparseMatrix projection() const;                 ///< P: corners x corners
  SparseMatrix inner_product(double lambda) const; ///< M: corners x corners
  SparseMatrix divergence(double lambda) const;    ///< -D^T M V: V x 3F
  /// D^T M D: V x V, rows computed by `threads` workers (0 = all cores).
  SparseMatrix laplacian(double lambda, unsigned threads = 1) const;
  std::vector<double> vertex_masses() const; ///< m_v
  std::vector<double> face_areas() const;    ///< A_f

private:
  // The index spaces of the global matrices: vertices, face corners, 3 coordinates per face.
  enum class Space { vertex, corner, face_vector };
  std::int64_t size_of(Space s) const;
  std::int64_t index_in(Space s, std::size_t f, int i) const;
  // The matrix whose (rows, cols) block of face f is face(f).*block.
  SparseMatrix assemble(std::vector<double> PolygonalFace::*block, Space rows, Space cols) const;

  std::int64_t vertices_ = 0, corners_ = 0;
  int face_size_ = 0;               ///< every face's vertex count (PolygonMesh::face_size)
  std::vector<std::int64_t> index_; ///< face f's vertices at face_size_ f ..
  std::vector<Point3<double>> x_;   ///< the re-embedded vertices, per corner
  std::vector<double> area_;        ///< A_f
};

} // namespace zdg
