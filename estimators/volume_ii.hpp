// Integral-invariant curvature estimators (estimators/ii_3d.hpp: mean curvature H, principal
// curvatures k1 <= k2 and Gaussian curvature k1 k2, principal directions, normal; Coeurjolly,
// Lachaud, Levallois, CVIU 2014) on the boundary surfels of a user's binary volume.
//
// The digitized set is the volume's object X (nonzero voxels; outside the domain is outside),
// at grid step h (the physical size of an isotropic voxel) and kernel radius R (physical
// units, R / h voxels): the estimators of ii_3d.hpp run on the membership predicate of the
// image, so they return exactly the numbers of the synthetic driver (convergence/) on the
// same digitization. Surfels are those of image_surfels, in its order.
//
// Cost: that of ii_3d (about 2 pi (R/h)^2 look-ups per kernel centre, incremental along a
// walk, on `threads` threads), run on batches of 2^18 surfels so that the memory stays about
// 200 bytes per surfel of a batch whatever the number of surfels (the predicate cache of
// ii_3d covers the batch's slab of the volume). Requirements: R > 0, h > 0, R / h <= 256
// (ii_digital_radius2), InvalidArgument otherwise.
#pragma once

#include <zdg/estimators/ii_3d.hpp>
#include <zdg/kernel/images/image.hpp>
#include <zdg/kernel/surfaces/image_surfels.hpp>

#include <cstdint>
#include <vector>

namespace zdg {

/// II mean curvature at every surfel (surfels = image_surfels(image)).
std::vector<double> volume_ii_mean_curvature(const Image<std::uint8_t>& image,
                                             const ImageSurfels& surfels, double h, double R,
                                             unsigned threads = 0);

/// II principal curvatures, directions and normal at every surfel.
std::vector<IIPrincipalCurvatures> volume_ii_principal_curvatures(const Image<std::uint8_t>& image,
                                                                  const ImageSurfels& surfels,
                                                                  double h, double R,
                                                                  unsigned threads = 0);

/// The membership predicate of the nonzero voxels of a 3D image, in Z^3 coordinates (the
/// image's lower bounds), false outside the domain; the image must outlive it.
VoxelPredicate volume_predicate(const Image<std::uint8_t>& image);

} // namespace zdg
