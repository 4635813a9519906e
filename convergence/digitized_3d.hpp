// The digitized boundary of a 3D shape for the estimators of the registry (internal to
// convergence/): the predicate of G_h(X + t) on the voxel box of the run, the boundary
// surfels of every connected surface (tracked from seeds found on a grid of 8 x 8 lines
// along x, never scanning the box), and which surfels carry an error.
//
// Clipping. A shape that leaves the box (cylinder, diabolo, distel) gets boundary surfels on
// the box faces (outer voxel outside the box): they are not part of dX_h and carry no
// error, and neither do the surfels closer than `margin` to a face where this happens (the
// kernel of an estimator there sees the cut, not the shape). A shape inside its box is
// never clipped (voxels outside the box are outside the shape), so every surfel counts.
#pragma once

#include <zdg/convergence/estimator.hpp>
#include <zdg/convergence/shapes_3d.hpp>

#include <string>
#include <vector>

namespace zdg::detail {

struct Digitized3 {
  const Shape3* shape = nullptr;
  Point3<double> t;
  double h = 0;
  VoxelBox box;
  VoxelPredicate inside;
  std::vector<Surfel> surfels;   ///< all tracked boundary surfels
  std::array<bool, 6> clipped{}; ///< faces -x, +x, -y, +y, -z, +z touched by the set
};

const Shape3& as_3d(const Shape& s);

/// Voxel box of the continuous box at step h (a margin of one voxel), checked.
VoxelBox voxel_box(const std::vector<std::pair<double, double>>& box, double h);

/// Digitizes the translated shape and tracks its boundary surfels.
Digitized3 digitize_3d(const RunInput& in);

/// The surfels of d that carry an error: not on a clipped face, and farther than margin
/// (continuous units) from every clipped face.
std::vector<Surfel> evaluated_surfels(const Digitized3& d, double margin);

/// The whole digitized surface (the calculus needs it closed): InvalidArgument naming
/// `estimator` when the box clips the shape.
Digitized3 whole_surface(const RunInput& in, const std::string& estimator);

/// The surfel weights h^2 mu(s), mu = n_II . n_elem, II normal of radius R
/// (estimators/digital_integration.hpp; convergence/estimators_calculus.cpp).
std::vector<double> ii_surfel_weights(const Digitized3& d, double h, double R);

} // namespace zdg::detail
