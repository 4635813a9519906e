// Discrete exterior derivatives on the cell complex of a closed digital surface
// (kernel/surfaces/surfel_complex.hpp), as exact integer incidence matrices
// (kernel/calculus/incidence_matrix.hpp).
//
// Forms (Desbrun, Hirani, Leok, Marsden, "Discrete exterior calculus", 2005; Desbrun, Kanso,
// Tong, "Discrete differential forms for computational modeling", 2008; on digital surfaces:
// Coeurjolly, Lachaud, "A simple discrete calculus for digital surfaces", DGMM 2022):
//   primal 0-forms  one value per pointel      dual 2-forms  per dual face of a pointel
//   primal 1-forms  one value per linel a -> b dual 1-forms  per dual edge of a linel
//   primal 2-forms  one value per surfel       dual 0-forms  per dual vertex of a surfel
// Orientations: linel e runs from pointel a to pointel b; surfel s is its corner cycle,
// counterclockwise seen from outside; the dual edge of e runs from the surfel face[1] to the
// surfel face[0] (the linel turned by +90 degrees about the outward normal: face[0], which
// runs a -> b counterclockwise, lies on the left of e).
//
//   d0 (linels x pointels)   (d0 u)(e) = u(b) - u(a)
//   d1 (surfels x linels)    (d1 w)(s) = sum over the sides of s of +-w(e), + where s runs
//                            e from a to b (s = face[0]), - where it runs b -> a (face[1])
//   dual_d0 = d1^T (linels x surfels)    (dual_d0 g)(e) = g(face[0]) - g(face[1])
//   dual_d1 = -d0^T (pointels x linels)  the circulation of a dual 1-form around the dual
//                                        face of a pointel
// (the dual derivatives are (-1)^k d_{n-k}^T for n = 2, as in Desbrun et al. 2005, 4.3).
//
// Identities, exact in integers: d1 d0 = 0 (each side's pointel difference telescopes around
// the surfel's cycle) and dual_d1 dual_d0 = -(d1 d0)^T = 0; Stokes' theorem on every surfel:
// (d1 w)(s) is the sum of w around the boundary of s. Entries -1, 0, +1 (int8); O(F log F)
// for F surfels. InvalidArgument when the complex is inconsistent (a surfel side that is not
// the linel recorded for it).
#pragma once

#include <zdg/kernel/calculus/incidence_matrix.hpp>
#include <zdg/kernel/surfaces/surfel_complex.hpp>

#include <array>
#include <cstdint>

namespace zdg {

IncidenceMatrix primal_d0(const SurfelComplex& c);
IncidenceMatrix primal_d1(const SurfelComplex& c);
/// d1^T: dual 0-forms (surfels) to dual 1-forms (linels).
IncidenceMatrix dual_d0(const SurfelComplex& c);
/// -d0^T: dual 1-forms (linels) to dual 2-forms (pointels).
IncidenceMatrix dual_d1(const SurfelComplex& c);

/// The sign of side i of surfel s along its linel: +1 when the side (corner i -> i + 1) runs
/// the linel a -> b, -1 when b -> a. InvalidArgument when it is neither.
int side_sign(const SurfelComplex& c, std::int64_t s, int i);

} // namespace zdg
