// The exact sign of a polynomial with rational coefficients at a point known exactly, decided
// by a floating-point filter with a rigorous error bound and an exact rational fallback: the
// one predicate behind every polynomial digitization of zdg (the `poly:` shapes, ball,
// ellipse, polygon, and the named 3D surfaces of convergence/).
//
// Filter. F = sum_m c_m x^m, evaluated in double at an approximation p~ of the exact point p;
// with magnitudes X_i >= |p_i| + |p~_i - p_i| and the double coefficients c~_m = c_m (1 + d_m),
// |d_m| <= u = 2^-53 (a coefficient that rounds below the smallest normal double counts with
// that normal as its magnitude), every computed value satisfies
//   |F~(p~) - F(p)| <= gamma sum_m |c_m| X^m + slack,   gamma = 8 (deg + #terms + 2) u,
// the classical forward error bound of a sum of products (Higham, Accuracy and Stability of
// Numerical Algorithms, 2nd ed., ch. 3: gamma_n = n u / (1 - n u) per product chain of n
// roundings and per sum of n terms; the perturbation |p~ - p| enters as
// |prod (p~_i)^e_i - prod p_i^e_i| <= deg max_i(|p~_i - p_i|) X^(m - 1), covered by the
// factor 8), and slack = #ops 2^-1022 max(1, X)^deg for the absolute error of gradual
// underflow (at most #ops 2^-1074 max(1, X)^deg; the smallest normal keeps the bound's
// arithmetic out of subnormals). |F~| > bound certifies sign(F(p)) = sign(F~); otherwise (or when a
// value is not finite) the sign is F(p) evaluated in Rational<BigInt> (exact,
// Polynomial::sign_exact).
//
// Grid points. The digitization G_h(X + t) = { z in Z^d : h z - t in X } asks for the sign at
// p = h z - t with h, t doubles (exact dyadic rationals) and z integer: GridFrame gives
// p~ = fl(fl(h z) - t), the magnitude 2 (|fl(h z)| + |t|) (>= |p| + |p~ - p|, the two
// roundings being at most u (|h z| + |p|)) and p exactly. The filter decides all but the
// points within about 1e-15 (relative) of the zero set.
//
// Cost: O(#terms deg) flops per sign, plus one Rational<BigInt> evaluation (O(#terms deg)
// big multiplications) for the rare undecided points. Degree <= 2 in two variables (ball,
// ellipse, polygon edges) has a Horner form of the quadric, used by the hot loops. Objects are
// immutable after construction: safe to share between threads.
#pragma once

#include <zdg/arith/point.hpp>
#include <zdg/kernel/digitization/polynomial.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace zdg {

class GridFrame;

class PolynomialSign {
public:
  explicit PolynomialSign(Polynomial f);

  const Polynomial& polynomial() const { return f_; }
  int nvars() const { return f_.nvars(); }

  /// True when F has degree <= 2 in two variables; then quadric() holds the coefficients of
  /// x^2, xy, y^2, x, y, 1 (rounded to double) for hot loops.
  bool is_quadric() const { return quadric_; }
  const std::array<double, 6>& quadric() const { return q_; }

  /// F(p~) in double.
  double value(const double* p) const;
  /// The filter bound for the magnitudes X (|value(p~) - F(p)| <= error_bound(X) whenever
  /// X_i >= |p_i| + |p~_i - p_i|).
  double error_bound(const double* magnitude) const;

  /// sign(F(p)) in {-1, 0, 1}, exact: p~ and X as above, `exact()` returns p as an array of
  /// nvars() BigRational (called only when the filter does not decide).
  template <class ExactPoint>
  int sign(const double* p, const double* magnitude, ExactPoint&& exact) const {
    double bound = 0;
    const double v = value_and_bound(p, magnitude, bound);
    if (std::isfinite(v) && std::isfinite(bound)) {
      if (v > bound) return 1;
      if (v < -bound) return -1;
    }
    const auto q = exact();
    return f_.sign_exact(q.data());
  }

  /// The signs of F at the grid points h (x, y, z) - t of one column, z = z0..z1 (three
  /// variables): out[z - z0] = sign(F) <= 0. The same doubles as sign() at each point (the x
  /// and y factors of every term are the first products of its chain, computed once per
  /// column), the same exact fallback, so the same answers. Requires nvars() == 3.
  void column_inside(const GridFrame& frame, std::int64_t x, std::int64_t y, std::int64_t z0,
                     std::int64_t z1, std::uint8_t* out) const;

private:
  Polynomial f_;
  bool quadric_ = false;
  std::array<double, 6> q_{}, aq_{}; // x^2 xy y^2 x y 1 and their magnitudes
  std::vector<double> abs_;          // magnitude of each coefficient (>= the smallest normal)
  double gamma_ = 0;
  double ops_ = 0; // roundings that may underflow: #terms (deg + 2)

  double value_and_bound(const double* p, const double* magnitude, double& bound) const;
  double underflow_slack(const double* magnitude) const;
};

/// The points h z - t (z in Z^d, d = 2 or 3) of the grid of step h translated by -t, with h
/// and t doubles taken as exact dyadic rationals.
class GridFrame {
public:
  GridFrame(double h, std::span<const double> t);

  int dimension() const { return d_; }
  double step() const { return h_; }
  /// p~ = fl(fl(h z) - t) and the magnitudes 2 (|fl(h z)| + |t|) of the filter.
  void approximate(const std::int64_t* z, double* p, double* magnitude) const {
    for (int i = 0; i < d_; ++i) {
      const double hz = h_ * static_cast<double>(z[i]);
      p[i] = hz - t_[static_cast<std::size_t>(i)];
      magnitude[i] = 2.0 * (std::abs(hz) + std::abs(t_[static_cast<std::size_t>(i)]));
    }
  }
  /// h z - t exactly (the first dimension() entries).
  std::array<BigRational, 3> exact(const std::int64_t* z) const;
  /// sign(F(h z - t)), exact.
  int sign(const PolynomialSign& f, const std::int64_t* z) const {
    double p[3], m[3];
    approximate(z, p, m);
    return f.sign(p, m, [&] { return exact(z); });
  }

private:
  int d_;
  double h_;
  std::array<double, 3> t_{};
  BigRational hx_;
  std::array<BigRational, 3> tx_;
};

/// The digitization { z : F(h z - t) <= 0 } as a voxel predicate (the named 3D shapes of
/// convergence/): a named type, so that a consumer holding it in a VoxelPredicate can ask
/// for whole columns (kernel/images/column_runs.cpp: std::function::target). Shares F and the
/// frame, so it may outlive the shape; safe to call from several threads at once.
class PolynomialDigitization {
public:
  PolynomialDigitization(std::shared_ptr<const PolynomialSign> f, double h,
                         std::span<const double> t)
      : f_(std::move(f)), frame_(std::make_shared<const GridFrame>(h, t)) {}
  bool operator()(const Point3<std::int64_t>& z) const {
    const std::int64_t zz[3] = {z.x, z.y, z.z};
    return frame_->sign(*f_, zz) <= 0;
  }
  /// out[z - z0] = operator()({x, y, z}) for z = z0..z1, F's x and y factors once per column
  /// (three variables; the voxel-by-voxel answers otherwise).
  void column(std::int64_t x, std::int64_t y, std::int64_t z0, std::int64_t z1,
              std::uint8_t* out) const;

private:
  std::shared_ptr<const PolynomialSign> f_;
  std::shared_ptr<const GridFrame> frame_;
};

} // namespace zdg
