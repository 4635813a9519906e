// Digital integration on a digital surface: the measure of a surfel and the integral of a
// function (Lachaud, Thibert, "Properties of Gauss digitized shapes and digital surface
// integration", JMIV 2016; Lachaud, Coeurjolly, Levallois 2017; Caissard et al., JMIV 2019).
//
// With n_est(s) a unit normal estimated at the surfel s (outward) and n_elem(s) its elementary
// normal (kernel/surfaces/cubical_cells.hpp), the surfel measure is
//     mu(s) = n_est(s) . n_elem(s)            (in [-1, 1]; about |n_x|, |n_y| or |n_z|),
// the weight of s is w(s) = area(s) mu(s) (h^2 mu(s) on the grid of step h), and
//     DI_h(f) = sum over surfels s of w(s) f(s)
// converges to the surface integral of f when the digital surface is the boundary of the Gauss
// digitization of a compact domain with C^2 boundary (reach > 0): |DI_h(f) - int f| =
// O(h ||f||_Lip) + O(||f||_inf * max |n_est - n|) (Lachaud-Thibert 2016, Thm 9), so with the
// integral-invariant normal (O(h^{2/3}), R = k h^{1/3}) the error is O(h^{2/3}); with the
// elementary normal (mu = 1) it does not converge (the area of a staircase).
//
// O(n) time; widths: double. mu is kept signed (a normal estimate pointing into the solid
// gives a negative weight: the data says so).
#pragma once

#include <zdg/arith/point.hpp>

#include <span>
#include <vector>

namespace zdg {

/// mu(s) = n_est(s) . n_elem(s) per surfel (spans of equal sizes; InvalidArgument otherwise).
std::vector<double> surfel_measure(std::span<const Point3<double>> estimated_normals,
                                   std::span<const Point3<double>> elementary_normals);

/// w(s) = area(s) mu(s) per surfel.
std::vector<double> surfel_weights(std::span<const double> measure, std::span<const double> areas);

/// DI(f) = sum_s w(s) f(s) (compensated summation: the error does not grow with n).
double digital_integral(std::span<const double> weights, std::span<const double> f);

} // namespace zdg
