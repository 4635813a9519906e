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
// Ground truth. Parametric shapes (ball, ellipse, flowers) project a point by sampling
// the parameter in a window around the polar guess then Newton on (C(s) - p).C'(s) = 0
// (to 1e-14 in the parameter); tangent C'/|C'|, curvature (x'y'' - y'x'')/|C'|^3. Their
// area, perimeter and moments come from closed forms where known (ball; ellipse area and
// perimeter series pi (a+b) sum binom(1/2,n)^2 H^n; flower area pi (R0^2 + A^2/2)), otherwise
// from the trapezoid rule on the periodic parameter with 2^16 samples (2^20 for accflower,
// whose radius has a corner at t = +-pi): errors below 1e-10, far below the estimators'.
//
// Chains. project_chain warm-starts Newton from the previous point's parameter and accepts
// the iterate x = C(s) without the robust search when a reach certificate holds: with
// rho <= reach (reach_lower_bound), write p - x = d n + eps tau (n, tau the unit normal
// and tangent at x; eps = |g| / |C'| the Newton residual). Federer's formula gives
// |(y - x) . n| <= |y - x|^2 / (2 rho) for every boundary point y, so
//   |y - p|^2 - |x - p|^2 = |y - x|^2 - 2 (y - x).(p - x)
//                         >= |y - x|^2 (1 - d / rho) - 2 eps |y - x|,
// positive as soon as |y - x| > 2 eps / (1 - d / rho): the nearest boundary point lies
// within 4 eps of x when d <= rho / 2. Accepted: d <= rho / 2 and eps <= 1e-14 (1 + |x|),
// i.e. x is the nearest point to 4e-14 (1 + |x|) (Federer 1959, Thm 4.18 for the bound on
// |(y - x).n|; the inequality covers every boundary point y, so no sampling is needed; d
// and eps are evaluated in double, from C(s) accurate to a few ulps). Otherwise (coarse h, d > rho
// / 2, no convergence in 8 steps, or no reach bound) the point goes through `project`. About 3
// curve evaluations per point instead of 25 + Newton.
//
// Reach. Ball R; ellipse b^2/a (b <= a, its minimal radius of curvature; the medial axis
// ends at the centres of curvature of the vertices); flowers: Federer's formula
// inf |y - x|^2 / (2 |(y - x).n_x|) over pairs of 4096 parameter samples together with
// the minimal radius of curvature over 2^16 samples, divided by a safety factor 2
// (sampled values only overestimate the infimum), 0 with a corner at the seam; polygon 0
// (corners); poly: unknown.
//
// Polygons use closed forms. poly: projects by damped Newton on F (40 iterations at most),
// with curvature (Fy^2 Fxx - 2 Fx Fy Fxy + Fx^2 Fyy) / |grad F|^3; no area or perimeter.
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
