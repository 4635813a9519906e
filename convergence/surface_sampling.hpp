// Points sampled uniformly on the area of a 3D shape of the registry (convergence/shapes_3d.hpp),
// with their exact outward normals, optional isotropic Gaussian noise: the input of the
// reconstruction estimators of `zdg converge --samples` (convergence/
// estimators_reconstruction.cpp).
//
// Method (exactly uniform up to floating point, not an approximation of the density):
//   1. A fine mesh M of the surface: zdg's marching cubes ((6,26), binary positions) of the
//      Gauss digitization of the shape at step h_f = (largest side of its bounding box) / 80.
//   2. A candidate: a triangle of M chosen with probability proportional to its area, a point
//      q uniform in it (square-root barycentric coordinates), its projection p = xi(q) on the
//      surface (Shape3::project: the nearest point, with the outward normal n and the principal
//      curvatures k1, k2, positive where convex).
//   3. Rejection: the candidate is kept with probability J(q) / J_max, where
//        J(q) = |n_T . n| / ((1 + d k1) (1 + d k2)),   d = (q - p) . n,
//      is the area of the surface per area of the triangle T at q (the projection along the
//      normals from T's plane to the parallel surface at distance d scales areas by |n_T . n|,
//      and the parallel surface's area element is (1 + d k1)(1 + d k2) times the surface's).
//      The density of p is then (1 / area(M)) (1 / J) (J / J_max), a constant: the points are
//      uniform on the area of the surface wherever xi maps M one-to-one onto it (M within the
//      reach of the surface, which the check below enforces with a margin of 2 h_f for the
//      shapes of the registry). J_max = 2; a candidate with J > J_max is an error (it would bias
//      the density), never met on the closed shapes of the registry at h_f.
//   4. Noise: the kept point p + sigma g, g a standard Gaussian vector of R^3 (Box-Muller); the
//      normal stays the exact unit normal at p.
// Random numbers: mt19937_64 seeded with `seed`, doubles from the top 53 bits, the triangle by
// binary search in the cumulative areas: the same points on every platform for one seed.
//
// The area: the closed form when the shape has one (spheres, torus, ellipsoid), else the
// estimate sum over T of area(T) J(centroid of T) (error O(h_f^2) relative on C^2 surfaces).
// The Betti numbers of the solid are those of the fine digitization ((6,26)), which equal the
// shape's for h_f below the reach's bound (Stelldinger, Koethe 2005).
//
// Errors (InvalidArgument, one line): a shape that is not 3D, n < 1 or n > 10^8, sigma
// negative or not finite; a shape whose fine mesh is empty or leaves the surface (a shape cut
// by its box, e.g. the cylinder: a triangle centroid farther than 2 h_f from the surface).
// Cost: the fine mesh once per shape (cached, shared between threads: O(h_f^-3) membership
// tests and O(h_f^-2) projections), then O(n (log M + projection)) per sampling (about two
// candidates per point). Thread-safe.
#pragma once

#include <zdg/convergence/shapes_3d.hpp>
#include <zdg/kernel/points/point_cloud.hpp>
#include <zdg/kernel/surfaces/mesh.hpp>
#include <zdg/kernel/topology/betti_numbers.hpp>

#include <cstdint>
#include <memory>
#include <vector>

namespace zdg {

/// The fine mesh of a shape with what sampling needs.
struct SamplingMesh {
  double h = 0;                   ///< h_f
  PolygonMesh mesh;               ///< triangles
  std::vector<double> cumulative; ///< cumulative triangle areas (cumulative.back() = area(M))
  double area = 0;                ///< the surface's area (closed form or estimate, above)
  bool area_exact = false;        ///< the closed form
  BettiNumbers betti;             ///< of the solid: the fine digitization, (6,26)
};

/// The fine mesh of `shape` (computed once per shape spec, then shared).
std::shared_ptr<const SamplingMesh> sampling_mesh(const Shape3& shape);

struct SurfaceSamples {
  PointCloud cloud; ///< the points (noisy when sigma > 0) with unit outward normals at exact[i]
  std::vector<Point3<double>> exact; ///< the noiseless points, on the surface
  double area = 0;                   ///< SamplingMesh::area
  std::int64_t candidates = 0;       ///< candidates drawn (kept: n)
};

/// n points uniform on the area of the surface (method above), seeded.
SurfaceSamples sample_surface(const Shape3& shape, std::int64_t n, double sigma,
                              std::uint64_t seed);

} // namespace zdg
