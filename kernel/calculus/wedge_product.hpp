// The wedge product of two primal 1-forms on the cell complex of a digital surface
// (kernel/surfaces/surfel_complex.hpp), a primal 2-form: the cubical cup product averaged
// over the two opposite sides of each quad (the quad version of the DEC wedge, Desbrun,
// Hirani, Leok, Marsden 2005, 7; Desbrun, Kanso, Tong 2008, 3.5).
//
// On the surfel s with corners c0 c1 c2 c3 (counterclockwise seen from outside) let
// u = c1 - c0 and v = c3 - c0 (u x v points outwards), and for a 1-form a let a(i) be its value
// on side i run from corner i to corner i + 1 (kernel/calculus/exterior_derivative.hpp,
// side_sign). With a_u the mean of a on the two sides parallel to u run along +u (c0 -> c1 and c3
// -> c2) and a_v the mean on the two sides parallel to v run along +v (c0 -> c3 and c1 -> c2):
//     a_u = (a(0) - a(2)) / 2,   a_v = (a(1) - a(3)) / 2,
//     (a ^ b)(s) = a_u b_v - a_v b_u.
// Bilinear and antisymmetric (a ^ a = 0); for the 1-forms dx, dy of the coordinates
// (d0 of the pointels' x and y), (dx ^ dy)(s) = area(s) n_z(s), the oriented area of the
// projection of s on the xy plane, exactly. For integer forms the result is an integer
// divided by 4 (exact in double below 2^51). O(F); InvalidArgument on sizes other than one
// value per linel.
#pragma once

#include <zdg/kernel/surfaces/surfel_complex.hpp>

#include <span>
#include <vector>

namespace zdg {

std::vector<double> wedge_product(const SurfelComplex& c, std::span<const double> a,
                                  std::span<const double> b);

} // namespace zdg
