// Integral-invariant curvature in 2D (Coeurjolly, Lachaud, Levallois, DGCI 2013 and CVIU
// 2014): with A = h^2 #(B_{R/h}(c) intersected with G_h(X)), the area of the digitized shape
// inside the digital ball of radius R/h centred at the pixel c,
//     kappa ~ 3 pi / (2 R) - 3 A / R^3,
// converging in O(h^{1/3}) for R = k h^{1/3} (C^3 boundary with positive reach, R below
// half the reach). Evaluated at every linel of a contour as the average of the counts of
// the balls centred at its inner and at its outer pixel, as the reference implementations
// do.
//
// Cost: the digital ball { d in Z^2 : |d|^2 <= (R/h)^2 } is stored as its row half-widths;
// moving the centre by one pixel changes the count by the pixels of the symmetric
// difference (one column or row span end per row or column), i.e. 2 (2r + 1) membership
// queries, r = R/h. Along a contour the inner and outer pixels move by at most two unit
// steps per linel, so a contour of n linels costs O(n R/h) queries instead of
// O(n (R/h)^2). Counts are exact int64_t (the ball has < 2^62 pixels).
//
// When every contour of the digitized set is known (complete boundary), the counts come
// instead from Green's formula over the contours (estimators/contour_ball_count.hpp):
// O(log n) per linel, independent of R/h, and the same integers.
#pragma once

#include <zdg/estimators/contour_ball_count.hpp>
#include <zdg/kernel/curves/digital_contour.hpp>
#include <zdg/kernel/digitization/digital_disc.hpp>
#include <zdg/kernel/digitization/gauss_digitization.hpp>

#include <cstdint>
#include <vector>

namespace zdg {

/// Count of G_h(X) in the digital ball of radius r (in pixels) around a moving centre.
class DigitalBallCounter {
public:
  DigitalBallCounter(const GaussDigitization2& set, double radius_pixels);
  /// Counts the ball around c from scratch: O(r^2) queries.
  std::int64_t direct_count(const Pixel& c) const;
  /// Moves the ball to c (incrementally when c is within r of the current centre) and
  /// returns the count.
  std::int64_t move_to(const Pixel& c);
  std::int64_t radius() const { return disc_.r; }
  /// Number of pixels of the ball.
  std::int64_t ball_size() const { return disc_.size; }

private:
  const GaussDigitization2& set_;
  DigitalDisc disc_;
  Pixel c_{};
  std::int64_t count_ = 0;
  bool placed_ = false;
  std::vector<Pixel> add_, rem_;
  void step(int code);
};

/// Curvature at every linel of the contour (same order as contour.codes), R in the units
/// of the embedding (R/h pixels).
std::vector<double> ii_curvature(const GaussDigitization2& set, const DigitalContour& contour,
                                 double h, double radius);

/// Same values, with the counts of `counter` (built on the set and ALL its contours, with
/// radius R/h pixels): O(n log n) for the contour instead of O(n R/h).
std::vector<double> ii_curvature(ContourBallCounter& counter, const DigitalContour& contour,
                                 double h, double radius);

} // namespace zdg
