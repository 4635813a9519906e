// The 2D shapes of the registry (see convergence/shape.hpp for the contract):
//
//   ball:R                 disc of radius R centred at 0 (exact: x^2 + y^2 - R^2)
//   ellipse:A,B[,THETA]    half-axes A, B, rotated by THETA radians (exact when THETA = 0)
//   flower:R0,A,K[,PHI]    star r(t) = R0 + A cos(K t + PHI), K integer (membership in double)
//   accflower:R1,R2,P      star r(t) = R1 + R2 cos(P t^3), t in [-pi, pi) (in double);
//                          P = 2K/pi^2 is DGtal's AccFlower2D with K petals, smooth at
//                          t = +-pi (r is C^2 there, as for any P = m/pi^2, m integer);
//                          other P give a corner at t = +-pi (r' jumps by
//                          -6 R2 P pi^2 sin(P pi^3)), hence reach 0
//   polygon:X1,Y1,...      convex polygon with rational vertices (exact)
//   poly:EXPR              F(x, y) <= 0, F a polynomial with rational coefficients (exact)
//
// Ground truth: closed forms where known (ball; ellipse area and perimeter series; flower
// area), otherwise Newton projection (to 1e-14 in the parameter) and trapezoid quadrature on
// the parameter with 2^16 samples (2^20 for accflower): errors below 1e-10. project_chain
// warm-starts Newton and skips the robust search when a reach certificate (Federer 1959,
// Thm 4.18) proves the iterate is the nearest point to 4e-14 (1 + |x|). Reach: R for the
// ball, b^2/a for the ellipse, sampled and halved for flowers, 0 for polygons, unknown for
// poly: (damped Newton on F, no area or perimeter). Derivation and sampling details:
// docs/NOTES.md, "convergence/shapes_2d.hpp".
#pragma once

#include <zdg/convergence/shape.hpp>

namespace zdg {

/// Perimeter of the ellipse with half-axes a, b by the series
/// pi (a + b) sum_n binom(1/2, n)^2 H^n, H = ((a - b)/(a + b))^2 (to double precision).
double ellipse_perimeter(double a, double b);

/// Perimeter of a parametric 2D shape (ball, ellipse, flower, accflower) by the
/// trapezoid rule with n samples; throws InvalidArgument for other shapes.
double quadrature_perimeter(const Shape2& shape, int n);

} // namespace zdg
