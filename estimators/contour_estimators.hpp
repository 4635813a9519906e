// The 2D estimators on the contours of a user's binary image (kernel/curves/image_contours.hpp), at
// grid step h (the physical size of a square pixel):
//   ii-curvature  at every linel (estimators/ii_curvature.hpp, radius R), the ball counts by
//                 Green's formula over all the contours (estimators/contour_ball_count.hpp:
//                 the contours of an image are its complete boundary)
//   bc-tangent    at every pointel (estimators/binomial_convolver.hpp), mask order
//                 n = max(2, round((R/h)^2)) made even (the smoothed curve's standard
//                 deviation sqrt(n)/2 pixels is then R/(2h)), lowered on a contour shorter
//                 than the mask to the largest order that fits (NaN when none does: a contour
//                 of at most 4 linels)
//   lmst-tangent  at every pointel (estimators/lambda_mst.hpp, parameter-free)
//   mlp-length    of every contour (estimators/mlp_length.hpp)
//   gauss-area    of the object, h^2 times its pixel count (estimators/gauss_area.hpp)
// Contours are processed in parallel (parallel_for over contours; one ball counter per
// worker); each estimator costs what its header says. The image must be the one whose
// contours are given (it answers the membership queries of the II counts).
#pragma once

#include <zdg/kernel/curves/image_contours.hpp>
#include <zdg/kernel/digitization/gauss_digitization.hpp>
#include <zdg/kernel/images/image.hpp>

#include <cstdint>
#include <vector>

namespace zdg {

/// The nonzero pixels of a 2D image as a digitized set (Z^2 coordinates, the image's lower
/// bounds; outside the domain is outside). The image must outlive it.
class BinaryImageSet2 final : public GaussDigitization2 {
public:
  explicit BinaryImageSet2(const Image<std::uint8_t>& image);

protected:
  bool inside(const Pixel& z) const override;

private:
  const std::uint8_t* data_;
  std::int64_t nx_;
  Pixel lower_;
};

struct ContourEstimateRequest {
  bool ii_curvature = false, bc_tangent = false, lmst_tangent = false, mlp_length = false,
       gauss_area = false;
};

struct ContourEstimates {
  std::vector<std::vector<double>> ii_curvature;         ///< [contour][linel]
  std::vector<std::vector<Point2<double>>> bc_tangent;   ///< [contour][pointel], unit
  std::vector<std::vector<Point2<double>>> lmst_tangent; ///< [contour][pointel], unit
  std::vector<double> mlp_length;                        ///< [contour]
  double gauss_area = 0;
  long bc_mask_order = 0;      ///< the order asked for (before lowering on short contours)
  std::int64_t bc_lowered = 0; ///< contours estimated with a lower order
  std::int64_t bc_skipped = 0; ///< contours too short for any mask (NaN tangents)
};

/// The requested estimators on the contours of image (contours = image_contours(image, ...)).
/// R is used by ii-curvature and bc-tangent (InvalidArgument unless R > 0 and h > 0).
ContourEstimates contour_estimates(const Image<std::uint8_t>& image, const ImageContours& contours,
                                   const ContourEstimateRequest& request, double h, double R,
                                   unsigned threads = 0);

} // namespace zdg
