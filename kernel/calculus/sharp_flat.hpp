// Flat and sharp between primal 1-forms (one value per linel) and tangent vector fields (one
// vector per surfel) on the cell complex of a digital surface (kernel/surfaces/
// surfel_complex.hpp); the simplest DEC choices (Hirani, "Discrete exterior calculus", thesis
// 2003, 5.5-5.7, primal-primal flat with averaged surfel vectors; on digital surfaces with
// the estimated normal's plane: Coeurjolly, Lachaud, DGMM 2022).
//
//   flat    (V^flat)(e) = ((V(f0) + V(f1)) / 2) . (b - a): the circulation along the linel
//           a -> b of the mean of the vectors of its two surfels. The linel lies in the plane
//           of both surfels, so only their tangential components count.
//   sharp   (a^sharp)(s) = the vector V with V . u = a_u, V . v = a_v, V . n = 0, where
//           u = c1 - c0, v = c3 - c0 are the surfel's sides and a_u, a_v the means of a on its
//           sides along +u and +v (kernel/calculus/wedge_product.hpp); n is the surfel's
//           elementary normal (its own plane) or, when `normals` is given, the estimated
//           normal (the vector tangent to the estimated plane whose circulations along u and v
//           are a_u and a_v). Solved by Cramer's rule on (u, v, n).
// sharp(flat(V)) = V for a field that is constant and tangent on a flat piece of the surface
// (each surfel of which has the elementary normal as n). O(F); doubles. InvalidArgument on
// sizes that do not match the complex, or (sharp) a normal in the plane of its surfel
// (det(u, v, n) = 0: no tangent vector has those circulations).
#pragma once

#include <zdg/arith/point.hpp>
#include <zdg/kernel/surfaces/surfel_complex.hpp>

#include <span>
#include <vector>

namespace zdg {

std::vector<double> flat(const SurfelComplex& c, std::span<const Point3<double>> field);

std::vector<Point3<double>> sharp(const SurfelComplex& c, std::span<const double> form,
                                  std::span<const Point3<double>> normals = {});

} // namespace zdg
