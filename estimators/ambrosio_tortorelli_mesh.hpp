// The Ambrosio-Tortorelli (AT) functional on a polygon mesh with u on the faces and the
// discontinuity function v on the vertices, as in Coeurjolly, Foare, Gueth, Lachaud,
// "Piecewise smooth reconstruction of normal vector field on digital data", Pacific Graphics
// 2016, Computer Graphics Forum 35(7) (u a primal 2-form, v a primal 0-form of the discrete
// exterior calculus; the seeds' DGtal::ATSolver2D). The same code runs on the primal mesh of a
// digital surface (faces = surfels, vertices = pointels: kernel/surfaces/surfel_complex.hpp) and
// on any manifold triangle or polygon mesh (a PLY: `zdg mesh at`). Beside it,
// estimators/ambrosio_tortorelli.hpp keeps the other discretization (v on the linels).
//
// The calculus. Lengths are measured in units of the mesh's mean edge length h (h = the grid
// step on a digital surface), so that the parameters are per cell, as in the linel version.
//   A_f   the area of face f (|sum_i p_i x p_{i+1}| / 2: the vector area of the polygon)
//   l_e   the length of edge e = (a, b);  c_f the mean of f's vertices;  m_e the midpoint of e
//   d_e   the barycentric dual edge length |c_f0 - m_e| + |m_e - c_f1| (|c_f0 - m_e| on a
//         boundary edge)
//   A_v   the dual area of vertex v: sum over its faces f of A_f / (number of vertices of f)
//   (delta u)(e) = u(f0) - u(f1)  (the codifferential of the 2-form u across an interior edge
//                                  e; boundary edges carry no jump)
//   (M v)(e)     = (v(a) + v(b)) / 2  (the vertex-to-edge average M01 of the paper)
//   (d0 v)(e)    = v(b) - v(a)
// The Hodge stars are diagonal: *2 = 1 / A_f, *1 = d_e / l_e, *0 = A_v. They are the
// circumcentric (cotangent) stars on squares and equilateral triangles, and, unlike the
// cotangent weights, positive on every mesh; on a digital surface every A_f, l_e, d_e is 1 and
// A_v = (surfels at the pointel) / 4, the unit stars of DGtal but for that last one.
//
// The functional, for unit normals g per face and weights m_f in [0, inf) (1; 0 on the
// faces to inpaint):
//   AT_eps(u, v) = alpha sum_f m_f A_f |u(f) - g(f)|^2
//                + sum_{e interior} (l_e / d_e) (M v)(e)^2 |(delta u)(e)|^2
//                + lambda eps sum_e (d_e / l_e) (d0 v)(e)^2
//                + lambda / (4 eps) sum_v A_v (1 - v(v))^2,
// the discretization of alpha int |u - g|^2 + int v^2 |grad u|^2 + lambda eps int |grad v|^2
// + lambda / (4 eps) int (1 - v)^2 (for u affine on a flat grid of squares or of equilateral
// triangles the second sum is exactly int |grad u|^2, and for v affine the third is
// lambda eps int |grad v|^2). Writing A = diag(A_f m_f), W = diag(l_e / d_e) (interior edges),
// K = diag(d_e / l_e), D_v = diag(A_v), the two block minimisers are the linear systems
//   u-step  (alpha A + delta^T W diag((M v)^2) delta) u = alpha A g   (one per coordinate)
//   v-step  (lambda / (4 eps) D_v + lambda eps d0^T K d0 + M^T W diag(|delta u|^2) M) v
//                                                      = lambda / (4 eps) D_v 1,
// both symmetric; the v-step matrix is positive definite; the u-step matrix is positive
// semi-definite and definite when every connected component of the face adjacency (through
// the edges with (M v)(e) != 0) has a face with m_f > 0 (checked for the start, v = 1:
// InvalidArgument when a component is all inpainted).
// Proven properties (tested): each half step does not increase AT_eps (exact minimisers, up
// to the linear solver's tolerance); u = g when alpha -> inf (the u-step's solution tends to
// g); v = 1 exactly when u is constant across every edge. Not a theorem here, unlike the
// linel version: 0 <= v <= 1 (M^T W diag M has positive off-diagonal entries, so the v-step
// matrix is not an M-matrix); zdg reports min v and max v, and the tests measure them.
//
// Minimisation: u = g, v = 1; for eps = epsilon1, epsilon1 / factor, ... >= epsilon2, at most
// max_iterations times the u-step then the v-step, until max |v_new - v_old| < tolerance
// (ATParameters of estimators/ambrosio_tortorelli.hpp, same defaults); the normals are u / |u|.
//
// Segmentation by v: two faces sharing an interior edge (a, b) are in the same segment when
// max(v(a), v(b)) >= threshold (an edge whose two ends lie on the discontinuity set cuts); the
// segments are the connected components, labelled 0, 1, ... by decreasing size (ties: the
// smallest face first).
//
// Linear solves: `cholesky` factors each matrix (kernel/linalg/sparse_spd_solver.hpp; the
// pattern is analysed once); `conjugate_gradient` (the default) runs conjugate gradients
// preconditioned by block Jacobi with the zero-fill incomplete Cholesky factor of each diagonal
// block of 4096 rows (Meijerink, van der Vorst 1977; a pivot that is not positive, possible on
// the v-step's matrix, which is not an M-matrix, is replaced by the diagonal entry) from the
// previous iterate until ||r|| <= cg_tolerance ||b|| (relative
// residual, for each coordinate of u; Error past cg_max_iterations), the three coordinates of u
// in lockstep (one pass over the matrix serves the three), every pass on one team of `threads`
// workers; the dot products are summed by fixed blocks of rows, so that the result is the same,
// bit for bit, whatever the thread count.
// The matrices are assembled in place on a pattern computed once: O(F + E) per step.
//
// Cost: building the calculus O(F log F) (edges by sorting the directed sides); per half step
// O(nnz) assembly plus the solve (CG: O(nnz) per CG iteration; Cholesky: about n^{3/2} flops
// on a surface). Memory O(F + V + E). Widths: indices int64, values double.
//
// Errors (InvalidArgument, one line): an empty mesh; an edge of more than two faces (not a
// manifold: naming the edge's vertices); a face with a repeated vertex; a zero-length edge or a
// face of zero area; g or the weights of the wrong size or not finite; weights < 0; the
// parameters outside their domain (those of at_normals, and threshold in [0, 1]).
#pragma once

#include <zdg/arith/point.hpp>
#include <zdg/estimators/ambrosio_tortorelli.hpp>
#include <zdg/kernel/linalg/sparse_matrix.hpp>
#include <zdg/kernel/surfaces/mesh.hpp>
#include <zdg/kernel/surfaces/surfel_complex.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace zdg {

struct ATMeshEdge {
  std::int64_t a = 0, b = 0;                ///< its vertices, a < b
  std::array<std::int64_t, 2> face{-1, -1}; ///< its faces; face[1] = -1 on a boundary edge
};

/// The calculus of a polygon mesh for AT (see above), lengths in units of `unit`.
struct ATMesh {
  std::int64_t vertex_count = 0;
  std::vector<std::int64_t> face_start{0}; ///< face f: face_vertices[face_start[f] ..]
  std::vector<std::int64_t> face_vertices;
  std::vector<ATMeshEdge> edges;
  std::vector<double> face_area;   ///< A_f
  std::vector<double> vertex_area; ///< A_v
  std::vector<double> jump_weight; ///< l_e / d_e (0 on a boundary edge)
  std::vector<double> edge_weight; ///< d_e / l_e
  double unit = 1;                 ///< the mean edge length, in the mesh's units

  std::int64_t face_count() const { return static_cast<std::int64_t>(face_start.size()) - 1; }
  std::int64_t edge_count() const { return static_cast<std::int64_t>(edges.size()); }
};

/// The calculus of a polygon mesh (any face size; see the errors above). O(F log F).
ATMesh at_mesh(const PolygonMesh& mesh);
/// The calculus of the primal mesh of a digital surface: faces = surfels (in order), vertices =
/// pointels, edges = linels (pinched linels keep the complex's pairing). O(F).
ATMesh at_mesh(const SurfelComplex& complex);

enum class ATLinearSolver { conjugate_gradient, cholesky };

struct ATMeshOptions {
  ATLinearSolver solver = ATLinearSolver::conjugate_gradient;
  double cg_tolerance = 1e-6;         ///< relative residual of each CG solve (> 0)
  std::int64_t cg_max_iterations = 0; ///< 0: 10 n + 1000 for n unknowns
  unsigned threads = 1;               ///< for the products of CG (0: all cores)
  double threshold = 0.5;             ///< the segmentation's threshold on v, in [0, 1]
};

struct ATMeshResult {
  std::vector<Point3<double>> u;       ///< the raw minimiser, per face
  std::vector<Point3<double>> normals; ///< u / |u| (g where u = 0), per face
  std::vector<double> v;               ///< the discontinuity function, per vertex
  std::vector<std::int64_t> segment;   ///< per face (see above)
  std::int64_t segments = 0;
  std::vector<ATStep> steps;      ///< every half step, in order
  int iterations = 0;             ///< alternating (u, v) steps, all levels together
  std::int64_t cg_iterations = 0; ///< all CG iterations together (0 with Cholesky)
  std::string solver;             ///< "conjugate-gradient" or the Cholesky backend's name
};

/// AT_eps(u, v) (see above); `weights` empty means m_f = 1.
double at_mesh_energy(const ATMesh& mesh, std::span<const Point3<double>> g,
                      std::span<const Point3<double>> u, std::span<const double> v,
                      const ATParameters& parameters, double eps,
                      std::span<const double> weights = {});

/// The matrix of the u-step for v (F x F) and of the v-step for u and eps (V x V).
SparseMatrix at_mesh_u_matrix(const ATMesh& mesh, std::span<const double> v, double alpha,
                              std::span<const double> weights = {});
SparseMatrix at_mesh_v_matrix(const ATMesh& mesh, std::span<const Point3<double>> u, double lambda,
                              double eps);

/// The AT minimisation from u = g, v = 1 (see above).
ATMeshResult at_mesh_normals(const ATMesh& mesh, std::span<const Point3<double>> g,
                             const ATParameters& parameters = {}, const ATMeshOptions& options = {},
                             std::span<const double> weights = {});

/// The segments of v (see above): a label per face, and their number.
std::pair<std::vector<std::int64_t>, std::int64_t>
at_mesh_segments(const ATMesh& mesh, std::span<const double> v, double threshold);

/// A per-vertex field brought to the faces: the minimum over each face's vertices (0 on a face
/// that touches the discontinuity set), or the mean.
std::vector<double> at_face_values(const ATMesh& mesh, std::span<const double> v,
                                   ATSurfelPolicy policy = ATSurfelPolicy::minimum);

/// The unit normal of each face of the mesh (its vector area, normalised; InvalidArgument for
/// a face of zero area).
std::vector<Point3<double>> mesh_face_normals(const PolygonMesh& mesh);

} // namespace zdg
