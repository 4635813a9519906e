// Chamfer distance transforms: the distance of a weighted mask (Borgefors, "Distance
// transformations in digital images", CVGIP 34, 1986; Rosenfeld, Pfaltz, "Sequential operations
// in digital picture processing", JACM 13, 1966), exact, and the mask's error bound against l2.
//
// A mask of dimension d (2 or 3) is given by its weights, one per class of moves:
//   2D <a>: the 4 axis moves (city block d4); <a,b>: and the 4 diagonals (<3,4>; <1,1> is the
//   chessboard d8); <a,b,c>: and the 8 knight moves (+-1,+-2), (+-2,+-1) (<5,7,11>);
//   3D <a>: the 6 face moves (d6); <a,b>: and the 12 edge moves (d18 for <1,1>); <a,b,c>: and the
//   8 vertex moves (<3,4,5>; <1,1,1> is d26).
// The chamfer distance d_M(x, y) is the least total weight of a path of mask moves from x to y
// inside the image's domain (a box; the axis moves make it connected); the transform gives every
// foreground point (value != 0) d_M to the nearest background point (value 0), 0 on the
// background.
//
// Algorithm: forward and backward raster scans, each taking the minimum over the half of the mask
// already visited (Rosenfeld-Pfaltz), repeated until a round of the two changes nothing. The
// result is the exact shortest-path distance for any positive weights (Bellman-Ford: every round
// relaxes every edge; the first round finds the standard masks' distances and the second
// confirms them). Time O(R N m) for N points, m moves and R rounds: R = 2 for the masks above;
// masks whose long moves are cheap (<1000,1> in 2D) make shortest paths turn back against the
// raster order and need up to O(n) rounds, n the longest extent. One thread, no extra memory.
//
// Width: the values are at most B = w_axis * sum_k (n_k - 1) (the path along the axes to any
// background point); T must hold B + the largest weight, else OverflowError before any work.
// T: std::uint32_t, std::uint64_t, Int64, Int128 or BigInt.
//
// Error bound (chamfer_error_bound): the gauge of the mask, g(v) = min sum lambda_i w_i over
// lambda >= 0 with sum lambda_i m_i = v, has unit ball the convex hull of the points +-m_i/w_i,
// is a lower bound of d_M on Z^d, and is its limit (d_M(n v) / n -> g(v)). It equals d_M on Z^d
// when the moves on each facet of the ball span unimodular cones: so for <a>, <a,b> and
// <5,7,11> in 2D and for <a>, <3,4,5>, <1,1,1> in 3D, not for 3D <a,b>, whose
// facet through three edge moves has determinant 2 (d18: g(1,1,1) = 3/2, d_M(1,1,1) = 2).
// rho_min |v| <= g(v) <= rho_max |v| with rho_min = min_i w_i / |m_i| (the hull's farthest
// vertex) and rho_max = max_f |c_f| over the hull's facets {<c_f, v> = 1}; both bounds are
// attained. Hence, for the transforms, rho_min DT_2(x) <= DT_M(x) always and DT_M(x) <= rho_max
// DT_2(x) when d_M = g (the masks named above). Normalized by a scale s (the axis weight by
// convention, or the optimal s = (rho_min + rho_max) / 2), the relative error against l2 lies in
// [rho_min / s - 1, rho_max / s - 1] (the classical masks' figures: README.md). rho_min^2 and
// rho_max^2 are computed exactly (rationals); their square roots are rounded.
#pragma once

#include <zdg/arith/integer.hpp>
#include <zdg/arith/rational.hpp>
#include <zdg/kernel/images/image.hpp>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace zdg {

/// One move of a mask: its step (C order, axis 0 first) and its weight.
struct ChamferMove {
  std::vector<std::int64_t> step;
  std::int64_t weight = 0;
};

/// A symmetric chamfer mask in 2D or 3D, from the weights of its classes of moves (above).
class ChamferMask {
public:
  /// dim 2 or 3, 1 to 3 positive weights; InvalidArgument otherwise.
  ChamferMask(int dim, std::vector<std::int64_t> weights);
  /// The weights as a comma list ("5,7,11"), decimal integers; InvalidArgument naming the text.
  static ChamferMask parse(int dim, std::string_view text);
  /// Borgefors' default: <3,4> in 2D, <3,4,5> in 3D.
  static ChamferMask borgefors(int dim);

  int dim() const { return dim_; }
  const std::vector<std::int64_t>& weights() const { return weights_; }
  /// Every move (both signs), grouped by class.
  const std::vector<ChamferMove>& moves() const { return moves_; }
  std::int64_t axis_weight() const { return weights_.front(); }
  std::int64_t max_weight() const;
  /// "<5,7,11>".
  std::string name() const;

private:
  int dim_;
  std::vector<std::int64_t> weights_;
  std::vector<ChamferMove> moves_;
};

/// The mask's bounds against the Euclidean length (above): rho_min^2 and rho_max^2 exact, and the
/// relative errors for the axis-weight scale and for the optimal scale.
struct ChamferErrorBound {
  Rational<BigInt> rho_min_squared, rho_max_squared;
  double rho_min = 0, rho_max = 0;
  /// With s = the axis weight: rho_min / s - 1 and rho_max / s - 1.
  double error_below = 0, error_above = 0;
  /// With s = (rho_min + rho_max) / 2: +-(rho_max - rho_min) / (rho_max + rho_min).
  double optimal_scale = 0, optimal_error = 0;
};
ChamferErrorBound chamfer_error_bound(const ChamferMask& mask);

/// The largest value a chamfer transform of this mask on this domain can take (B above).
BigInt chamfer_transform_max_value(const Domain& domain, const ChamferMask& mask);

/// The chamfer distance transform of `shape` (nonzero = foreground). Errors: InvalidArgument when
/// the image's dimension is not the mask's or it has no background point; OverflowError when T
/// cannot hold B + the largest weight.
template <class T>
Image<T> chamfer_transform(const Image<std::uint8_t>& shape, const ChamferMask& mask);

} // namespace zdg
