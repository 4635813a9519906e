// Principal angles between two subspaces of R^n (Bjorck, Golub, "Numerical methods for
// computing angles between linear subspaces", Math. Comp. 27(123), 1973): for
// A = span(a_1..a_p), B = span(b_1..b_q) and the inner product <x, y>_W = sum_i w_i x_i y_i
// (w_i > 0), the angles 0 <= theta_1 <= ... <= theta_m <= pi/2, m = min(p, q), with
// cos theta_i the singular values of Q_A^T W Q_B (Q_A, Q_B W-orthonormal bases). The small
// angles are taken from the sines (singular values of Q_B - Q_A Q_A^T W Q_B, for q <= p), which
// stay accurate where the cosines round to 1. Two equal subspaces give angles ~ 1e-15; the
// largest angle measures how far one eigenspace is from another (e.g. an eigenvalue cluster at
// two grid steps, or mapped by a symmetry of the shape).
//
// Cost: O(n (p + q)^2) (Householder QR of each basis, then an SVD of size p x q).
// Requirements (InvalidArgument otherwise): every vector of both lists has n = weights.size()
// entries, p, q >= 1, every weight positive and finite, each list linearly independent (rank
// p, resp. q, at relative tolerance 1e-10).
#pragma once

#include <span>
#include <vector>

namespace zdg {

/// The min(p, q) principal angles (radians, increasing) between span(a) and span(b) in the
/// W-inner product.
std::vector<double> principal_angles(std::span<const std::vector<double>> a,
                                     std::span<const std::vector<double>> b,
                                     std::span<const double> weights);

} // namespace zdg
