// The 2D shapes of the registry (see convergence/shape.hpp for the contract):
//
//   ball:R                 disc of radius R centred at 0 (exact: x^2 + y^2 - R^2)
//   ellipse:A,B[,THETA]    half-axes A, B, rotated by THETA radians (exact when THETA = 0)
//   flower:R0,A,K[,PHI]    star r(t) = R0 + A cos(K t + PHI), K integer (membership in double)
//   accflower:R1,R2,P      star r(t) = R1 + R2 cos(P t^3), t in [-pi, pi) (in double)
//   polygon:X1,Y1,...      convex polygon with rational vertices (exact)
//   poly:EXPR              F(x, y) <= 0, F a polynomial with rational coefficients (exact)
//
// Ground truth. Parametric shapes (ball, ellipse, flowers) project a point by sampling
// the parameter in a window around the polar guess then Newton on (C(s) - p).C'(s) = 0
// (to 1e-14 in the parameter); tangent C'/|C'|, curvature (x'y'' - y'x'')/|C'|^3. Their
// area, perimeter and moments come from closed forms where known (ball; ellipse area and
// perimeter series pi (a+b) sum binom(1/2,n)^2 H^n; flower area pi (R0^2 + A^2/2)), otherwise
// from the trapezoid rule on the periodic parameter with 2^16 samples (2^20 for accflower,
// whose radius has a corner at t = +-pi): errors below 1e-10, far below the estimators'.
// Polygons use closed forms. poly: projects by damped Newton on F (40 iterations at most),
// with curvature (Fy^2 Fxx - 2 Fx Fy Fxy + Fx^2 Fyy) / |grad F|^3; no area or perimeter.
#pragma once

#include "convergence/shape.hpp"

namespace zdg {

/// Perimeter of the ellipse with half-axes a, b by the series
/// pi (a + b) sum_n binom(1/2, n)^2 H^n, H = ((a - b)/(a + b))^2 (to double precision).
double ellipse_perimeter(double a, double b);

/// Perimeter of a parametric 2D shape (ball, ellipse, flower, accflower) by the
/// trapezoid rule with n samples; throws InvalidArgument for other shapes.
double quadrature_perimeter(const Shape2& shape, int n);

} // namespace zdg
