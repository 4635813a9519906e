// The unit sphere digitized at step h for the calculus tests (#14): voxel z inside iff
// |h z| <= 1, its boundary surfels, their complex at step h, and the integral-invariant
// normals (R = 2 h^{1/3}, the rate h^{2/3}) with the surfel weights h^2 n_II . n_elem.
#pragma once

#include <zdg/estimators/digital_integration.hpp>
#include <zdg/estimators/ii_3d.hpp>
#include <zdg/kernel/surfaces/digital_surface.hpp>
#include <zdg/kernel/surfaces/surfel_complex.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

namespace zdg::test {

struct DigitalSphere {
  double h = 0;
  VoxelPredicate inside;
  VoxelBox box;
  std::vector<Surfel> surfels;
  SurfelComplex complex;
  std::vector<Point3<double>> ii_normals; ///< empty unless asked for
  std::vector<double> weights;            ///< h^2 mu with the II normals (idem)
};

inline DigitalSphere digital_sphere(double h, bool normals = true) {
  DigitalSphere s;
  s.h = h;
  const double r2 = 1.0 / (h * h);
  s.inside = [r2](const Voxel& z) {
    return static_cast<double>(z.x * z.x + z.y * z.y + z.z * z.z) <= r2;
  };
  const auto n = static_cast<std::int64_t>(std::ceil(1.0 / h)) + 2;
  s.box = VoxelBox{{-n, -n, -n}, {n, n, n}};
  s.surfels = boundary_surfels(s.inside, s.box);
  s.complex = surfel_complex(primal_surface(s.surfels), h);
  if (normals) {
    for (const auto& c :
         ii_principal_curvatures(s.inside, s.box, s.surfels, h, 2.0 * std::cbrt(h), 2))
      s.ii_normals.push_back(c.normal);
    s.weights = surfel_weights(surfel_measure(s.ii_normals, s.complex.normals), s.complex.areas);
  }
  return s;
}

} // namespace zdg::test
