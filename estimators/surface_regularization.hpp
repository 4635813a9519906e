// Digital surface regularization (Coeurjolly, Gueth, Lachaud, "Digital surface regularization
// with guarantees", IEEE TVCG 27(6), 2021): the vertices of the primal surface mesh (one per
// pointel, faces = surfels, kernel/surfaces/primal_surface_mesh.hpp) move so that every quad
// becomes orthogonal to an estimated normal of its surfel (e.g. the II normal,
// estimators/ii_3d.hpp), while staying near their pointel and fair.
//
// Energy over the positions x (p the original pointels, n_s the unit normal of surfel s, e(x)
// = x_j - x_i over the four sides i -> j of each quad, N(i) the vertices sharing an edge with i):
//   E(x) = alpha sum_i |x_i - p_i|^2                                   (data)
//        + beta  sum_s sum_{e in s} (e(x) . n_s)^2                    (alignment)
//        + gamma sum_i |x_i - (1/|N(i)|) sum_{j in N(i)} x_j|^2        (fairness)
// (defaults alpha 0.001, beta 1, gamma 0.05: the paper's and DGtal's). With d = x - p,
// E = d^T Q d + 2 g^T d + E(p), Q = alpha I + beta A^T A + gamma F^T F (3V x 3V, A the rows
// n_s^T (e_j - e_i), F = (I - B) (x) I_3): symmetric positive definite for alpha > 0, so E has
// one minimizer, Q d = -g.
//
// Guarantee (the paper's clamped variant): with `clamp` (default) the result minimizes E over
// the box |x_i - p_i|_inf <= h/2 (the cube of side h centred at each pointel), so the
// regularized surface stays within the Hausdorff bound of the digitization; every displacement
// d_i is clamped to [-h/2, h/2]^3 at the end, so every vertex lies in its cube exactly (up to one
// rounding of p_i + d_i), whatever the solver's accuracy. Without `clamp`, the unconstrained
// minimizer Q d = -g.
//
// Solvers. `conjugate_gradient` (and `automatic` with clamp, or past 30,000 vertices): MPRGP
// (Dostal, Schoberl, Comput. Optim. Appl. 30(1), 2005) with preconditioning in face, on the
// Jacobi-scaled problem y = D^{1/2} d, D = diag Q (a box stays a box): conjugate gradient steps on
// the free coordinates, preconditioned by each vertex's 3x3 diagonal block of D^{-1/2} Q D^{-1/2}
// restricted to its free coordinates (block Jacobi: the block holds the vertex's normal directions,
// which a diagonal scaling splits across the axes); expansion steps when a CG step would leave the
// box: the whole CG step projected onto the box when E there is below E at the feasible part of the
// CG step (cf. the projected-CG expansion of Kruzik et al., Adv. Eng. Softw. 149, 2020), else
// MPRGP's (that feasible step, then a projected gradient step of length 1.9 / (Gershgorin bound)),
// so E decreases at every step (the projected step's gradient by the CG recurrence plus Q times
// the projection's correction, a product over the 2-ring of the vertices it moved when they are
// at most 1/32 of all, else a whole product); proportioning steps releasing constraints. Q is
// applied without assembly (two gathers over the vertices, O(F) per product: about 40 flops per
// corner); without clamp it is block-Jacobi preconditioned CG.
// Stopping criterion (stated, and checked on the gradient recomputed from the result): the
// scaled projected gradient -- the KKT residual, D^{-1/2} times the gradient on the free
// coordinates plus its component pointing out of the box on the clamped ones, zero exactly at
// the constrained minimizer -- has 2-norm <= tolerance times its value at d = 0 (|D^{-1/2} g|_2);
// `kkt_residual` reports the ratio reached. The preconditioner changes the path, not this
// criterion. The CG part of the iterations is bounded by the square root of the condition number
// of the block-Jacobi preconditioned Q times log(1 / tolerance), plus the active set's changes;
// that condition number does not grow with the mesh (Q's smallest eigenvalue is alpha, the
// translations; its largest is bounded by the vertex degrees and the weights), but the count
// below the bound does, as finer meshes have more low-frequency modes near alpha and more
// constraints to find.
// `direct` (and `automatic` without clamp up to 30,000 vertices): Q factored once with
// kernel/linalg/sparse_spd_solver.hpp (about n^{3/2} flops for n = 3V); the unconstrained
// minimizer, which is the answer when it lies in the box; else ADMM (Boyd et al., Found. Trends
// ML 3(1), 2011) from its clamp, with Q + rho I factored once: (Q + rho I) d = -g + rho (z - u),
// z = clamp(d + u), u += d - z, until max |d - z| and max |z - z_prev| are below tolerance h
// (or max_iterations); the result is z. Assembly of Q (direct, and the Gershgorin bound) O(F),
// nnz(Q) about 39 per row (the 2-ring). Widths: int64 indices (the direct solver needs 3V <
// 2^31), doubles; sums in fixed blocks, so results do not depend on the thread count.
//
// Input requirements (InvalidArgument, one line, naming the value): a quad mesh (face_size 4;
// marching cubes' triangles are refused), one finite unit normal per face (|n| within 1e-6 of
// 1), h > 0, alpha, beta, gamma > 0 and finite, tolerance > 0. Error when CG does not converge
// within max_iterations without clamp (with clamp:
// converged = false, the result still in the box).
#pragma once

#include <zdg/arith/point.hpp>
#include <zdg/kernel/linalg/sparse_matrix.hpp>
#include <zdg/kernel/surfaces/mesh.hpp>

#include <span>
#include <string>
#include <vector>

namespace zdg {

enum class RegularizationSolver { automatic, direct, conjugate_gradient };

struct RegularizationParameters {
  double alpha = 0.001, beta = 1, gamma = 0.05;
  bool clamp = true;       ///< the guarantee: each vertex within the cube of side h
  double tolerance = 1e-6; ///< MPRGP: relative KKT residual; ADMM: relative to h
  double rho = 0;          ///< direct ADMM penalty; 0: sqrt(alpha (alpha + 4 beta + 4 gamma))
  int max_iterations = 20000;
  RegularizationSolver solver = RegularizationSolver::automatic;
  unsigned threads = 0; ///< for the products (0: all cores)
};

/// The three terms of E (unweighted sums times their coefficient) and their total.
struct RegularizationEnergy {
  double data = 0, alignment = 0, fairness = 0;
  double total() const { return data + alignment + fairness; }
};

struct RegularizationResult {
  std::vector<Point3<double>> positions; ///< one per vertex of the input mesh
  RegularizationEnergy before, after;    ///< at the pointels, at the result
  double max_displacement = 0;           ///< max_i |x_i - p_i|_inf / h
  int iterations = 0;                    ///< MPRGP or ADMM iterations (0: direct, unclamped)
  bool converged = true;   ///< false: stopped at max_iterations (the result is in the box)
  double kkt_residual = 0; ///< MPRGP: the relative scaled KKT residual reached (direct: 0)
  std::string solver;      ///< "cholmod", "eigen-simplicial-ldlt" or "mprgp"
};

/// Checks the mesh, normals, h and parameters (the requirements above).
void check_regularization_input(const PolygonMesh& mesh, std::span<const Point3<double>> normals,
                                double h, const RegularizationParameters& parameters);

/// E's terms at positions x (one per vertex).
RegularizationEnergy regularization_energy(const PolygonMesh& mesh,
                                           std::span<const Point3<double>> normals,
                                           std::span<const Point3<double>> x,
                                           const RegularizationParameters& parameters);

/// The quadratic form of E in the displacements d = x - p: Q (3V x 3V, row 3 i + a for
/// coordinate a of vertex i) and g (3V entries), E(p + d) = d^T Q d + 2 g^T d + E(p).
struct RegularizationSystem {
  SparseMatrix q;
  std::vector<double> g;
};
RegularizationSystem regularization_system(const PolygonMesh& mesh,
                                           std::span<const Point3<double>> normals,
                                           const RegularizationParameters& parameters);

/// The regularized positions of the mesh's vertices (mesh.vertices are the pointels p).
RegularizationResult regularize_surface(const PolygonMesh& mesh,
                                        std::span<const Point3<double>> normals, double h,
                                        const RegularizationParameters& parameters = {});

/// The vector area (1/2) (x2 - x0) x (x3 - x1) of quad f at positions x: its length is the
/// area and its direction the normal of a planar quad (of a skew quad: the area and normal of
/// its projection along the normal, the mean of the two triangulations' vector areas).
Point3<double> quad_vector_area(const PolygonMesh& mesh, std::span<const Point3<double>> x,
                                std::int64_t f);

} // namespace zdg
