#include <zdg/convergence/shapes_2d.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/digitization/polynomial.hpp>
#include <zdg/kernel/digitization/polynomial_sign.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <numbers>
#include <span>

namespace zdg {

namespace {

using P2 = Point2<double>;
constexpr double kPi = std::numbers::pi;

// --- exact digitization of F <= 0 for polynomials F --------------------------------------

// G_h(X + t) for X = { F_i <= 0 for all i }: each sign by the filtered predicate of
// kernel/digitization/polynomial_sign.hpp at the grid point h z - t.
class PolyDigitization final : public GaussDigitization2 {
public:
  PolyDigitization(const std::vector<PolynomialSign>* preds, double h, P2 t, Box2 box)
      : GaussDigitization2(box), preds_(preds), h_(h), t_(t),
        frame_(h, std::array<double, 2>{t.x, t.y}) {
    if (preds_->size() == 1 && preds_->front().is_quadric()) {
      auto mag = [&](std::int64_t a, std::int64_t b, double off) {
        return 2.0 * (std::max(std::abs(h * static_cast<double>(a)),
                               std::abs(h * static_cast<double>(b))) +
                      std::abs(off));
      };
      const double m[2] = {mag(box.lo.x, box.hi.x, t.x), mag(box.lo.y, box.hi.y, t.y)};
      box_bound_ = preds_->front().error_bound(m);
    }
  }

  // Hot loop of the integral invariants. One quadric (ball, ellipse): a branch-free pass
  // compares F with the filter bound valid for the whole box (the magnitudes at the box
  // corners); the few pixels it does not certify go through test().
  std::int64_t count(std::span<const Pixel> zs) const override {
    if (preds_->size() != 1 || !preds_->front().is_quadric()) {
      std::int64_t n = 0;
      for (const auto& z : zs) n += (box().contains(z) && test(z)) ? 1 : 0;
      return n;
    }
    const auto& q = preds_->front().quadric();
    const Box2& b = box();
    std::int64_t n = 0, unsure = 0;
    for (const auto& z : zs) {
      const double x = h_ * static_cast<double>(z.x) - t_.x,
                   y = h_ * static_cast<double>(z.y) - t_.y;
      const double v = ((q[0] * x + q[1] * y + q[3]) * x + (q[2] * y + q[4]) * y) + q[5];
      const bool in_box = (b.lo.x <= z.x) & (z.x <= b.hi.x) & (b.lo.y <= z.y) & (z.y <= b.hi.y);
      n += static_cast<std::int64_t>(in_box & (v < -box_bound_));
      unsure += static_cast<std::int64_t>(in_box & !(std::abs(v) > box_bound_));
    }
    if (unsure > 0) {
      for (const auto& z : zs) {
        if (!box().contains(z)) continue;
        const double x = h_ * static_cast<double>(z.x) - t_.x,
                     y = h_ * static_cast<double>(z.y) - t_.y;
        const double v = ((q[0] * x + q[1] * y + q[3]) * x + (q[2] * y + q[4]) * y) + q[5];
        if (!(std::abs(v) > box_bound_) && test(z)) ++n;
      }
    }
    return n;
  }

protected:
  bool inside(const Pixel& z) const override { return test(z); }

private:
  const std::vector<PolynomialSign>* preds_;
  double box_bound_ = 0;
  double h_;
  P2 t_;
  GridFrame frame_;

  bool test(const Pixel& z) const {
    const std::int64_t zz[2] = {z.x, z.y};
    double p[2], m[2];
    frame_.approximate(zz, p, m);
    for (const auto& f : *preds_) {
      if (f.sign(p, m, [&] { return frame_.exact(zz); }) > 0) return false;
    }
    return true;
  }
};

// G_h(X + t) for a double-precision membership test.
template <class Inside>
class DoubleDigitization final : public GaussDigitization2 {
public:
  DoubleDigitization(Inside f, double h, P2 t, Box2 box)
      : GaussDigitization2(box), f_(std::move(f)), h_(h), t_(t) {}
  std::int64_t count(std::span<const Pixel> zs) const override {
    std::int64_t n = 0;
    for (const auto& z : zs) n += (box().contains(z) && inside(z)) ? 1 : 0;
    return n;
  }

protected:
  bool inside(const Pixel& z) const override {
    return f_(h_ * static_cast<double>(z.x) - t_.x, h_ * static_cast<double>(z.y) - t_.y);
  }

private:
  Inside f_;
  double h_;
  P2 t_;
};

// --- parametric boundary --------------------------------------------------------------------

struct CurveJet {
  P2 c, d1, d2;
};

// A shape whose boundary is C(s), s in [-pi, pi), counter-clockwise.
class ParametricShape : public Shape2 {
public:
  virtual CurveJet jet(double s) const = 0;
  virtual double guess(P2 p) const = 0;
  virtual double min_speed() const = 0; // lower bound of |C'|
  virtual int quadrature_samples() const { return 1 << 16; }

  BoundaryPoint2 project(P2 p) const override { return point_of(jet(project_parameter(p))); }

  // The robust projection: sample a window around the polar guess, then clamped Newton.
  double project_parameter(P2 p) const {
    double s0 = guess(p);
    CurveJet j0 = jet(s0);
    double d0 = std::hypot(j0.c.x - p.x, j0.c.y - p.y);
    double delta = std::min(kPi, 3.0 * d0 / min_speed() + 1e-9);
    constexpr int kSamples = 24;
    double best_s = s0, best_d = d0;
    for (int i = 0; i <= kSamples; ++i) {
      double s = s0 - delta + 2.0 * delta * i / kSamples;
      CurveJet j = jet(s);
      double d = std::hypot(j.c.x - p.x, j.c.y - p.y);
      if (d < best_d) {
        best_d = d;
        best_s = s;
      }
    }
    double step_limit = 2.0 * delta / kSamples + 1e-12;
    double s = best_s;
    // A step that increases the distance stops Newton; increases within the rounding noise
    // of the coordinates (a few ulps of |p|) do not, or Newton would stop short near the
    // minimum, where the distance is flat.
    const double noise =
        1e-15 + 8 * std::numeric_limits<double>::epsilon() * (std::abs(p.x) + std::abs(p.y) + d0);
    for (int it = 0; it < 40; ++it) {
      CurveJet j = jet(s);
      double rx = j.c.x - p.x, ry = j.c.y - p.y;
      double g = rx * j.d1.x + ry * j.d1.y;
      double dg = j.d1.x * j.d1.x + j.d1.y * j.d1.y + rx * j.d2.x + ry * j.d2.y;
      double step = dg > 0 ? g / dg : 0.0;
      step = std::clamp(step, -step_limit, step_limit);
      double ns = s - step;
      CurveJet jn = jet(ns);
      if (std::hypot(jn.c.x - p.x, jn.c.y - p.y) > std::hypot(rx, ry) + noise) break;
      s = ns;
      if (std::abs(step) < 1e-14) break;
    }
    return s;
  }

  static BoundaryPoint2 point_of(const CurveJet& j) {
    double speed = std::hypot(j.d1.x, j.d1.y);
    return {j.c,
            {j.d1.x / speed, j.d1.y / speed},
            (j.d1.x * j.d2.y - j.d1.y * j.d2.x) / (speed * speed * speed)};
  }

  // Warm start with a reach certificate (see shapes_2d.hpp): Newton on
  // g(s) = (C(s) - p).C'(s) from the previous point's parameter; the iterate x = C(s) is
  // accepted once its tangential residual eps = |g| / |C'| is below kChainTol (1 + |x|) and
  // its normal distance |(p - x) x C'| / |C'| is at most reach_lower_bound / 2, which
  // proves that the nearest boundary point lies within 4 eps of x. Otherwise `project`.
  std::vector<BoundaryPoint2> project_chain(std::span<const P2> pts) const override {
    const std::optional<double> reach = reach_lower_bound();
    if (pts.empty() || !reach || !(*reach > 0)) return Shape2::project_chain(pts);
    constexpr int kMaxSteps = 8;
    constexpr double kChainTol = 1e-14, kMaxStep = 0.1;
    const double dmax2 = (*reach / 2) * (*reach / 2);
    std::vector<BoundaryPoint2> out;
    out.reserve(pts.size());
    double s = project_parameter(pts[0]);
    CurveJet j = jet(s);
    out.push_back(point_of(j));
    for (std::size_t i = 1; i < pts.size(); ++i) {
      const P2 p = pts[i];
      bool certified = false;
      for (int it = 0;; ++it) {
        const double rx = j.c.x - p.x, ry = j.c.y - p.y;
        const double speed2 = j.d1.x * j.d1.x + j.d1.y * j.d1.y;
        const double g = rx * j.d1.x + ry * j.d1.y, cross = rx * j.d1.y - ry * j.d1.x;
        const double tol2 = kChainTol * kChainTol * (1 + j.c.x * j.c.x + j.c.y * j.c.y);
        if (g * g <= tol2 * speed2 && cross * cross <= dmax2 * speed2) {
          certified = true;
          break;
        }
        const double dg = speed2 + rx * j.d2.x + ry * j.d2.y;
        if (it == kMaxSteps || !(dg > 0)) break;
        s -= std::clamp(g / dg, -kMaxStep, kMaxStep);
        j = jet(s);
      }
      if (!certified) {
        s = project_parameter(p);
        j = jet(s);
      }
      out.push_back(point_of(j));
    }
    return out;
  }

  // Federer's formula sampled: the minimum of |y - x|^2 / (2 |(y - x) . n_x|) over pairs of
  // n_pairs samples of the parameter, and of the radius of curvature over n_dense samples.
  // Each sampled value is >= the infimum, so the result may overestimate the reach; callers
  // divide it by a safety factor. O(n_pairs^2 + n_dense).
  double sampled_reach(int n_pairs, int n_dense) const {
    double kmax = 0;
    for (int i = 0; i < n_dense; ++i) {
      CurveJet j = jet(-kPi + 2 * kPi * i / n_dense);
      double speed = std::hypot(j.d1.x, j.d1.y);
      kmax = std::max(kmax, std::abs(j.d1.x * j.d2.y - j.d1.y * j.d2.x) / (speed * speed * speed));
    }
    double best = kmax > 0 ? 1 / kmax : std::numeric_limits<double>::infinity();
    const auto n = static_cast<std::size_t>(n_pairs);
    std::vector<double> x(n), y(n), nx(n), ny(n);
    for (std::size_t i = 0; i < n; ++i) {
      CurveJet j = jet(-kPi + 2 * kPi * static_cast<double>(i) / n_pairs);
      double speed = std::hypot(j.d1.x, j.d1.y);
      x[i] = j.c.x;
      y[i] = j.c.y;
      nx[i] = j.d1.y / speed;
      ny[i] = -j.d1.x / speed;
    }
    // Both orders of a pair at once: min(q / |d.n_i|, q / |d.n_j|) = q / max(...).
    constexpr double kInf = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < n; ++i) {
      double m = best;
      for (std::size_t k = i + 1; k < n; ++k) {
        const double dx = x[k] - x[i], dy = y[k] - y[i];
        const double den =
            2 * std::max(std::abs(dx * nx[i] + dy * ny[i]), std::abs(dx * nx[k] + dy * ny[k]));
        const double r = den > 0 ? (dx * dx + dy * dy) / den : kInf; // den = 0: no constraint
        m = r < m ? r : m;
      }
      best = std::min(best, m);
    }
    return best;
  }

  // Trapezoid rule over one period: perimeter, and Green's formulas for the moments.
  double quad_perimeter(int n) const {
    double sum = 0;
    for (int i = 0; i < n; ++i) {
      CurveJet j = jet(-kPi + 2 * kPi * i / n);
      sum += std::hypot(j.d1.x, j.d1.y);
    }
    return sum * 2 * kPi / n;
  }
  Moments2 quad_moments(int n) const {
    // m_pq = integral of x^(p+1) y^q / (p+1) dy along the boundary.
    Moments2 m{};
    for (int i = 0; i < n; ++i) {
      CurveJet j = jet(-kPi + 2 * kPi * i / n);
      double x = j.c.x, y = j.c.y, dy = j.d1.y;
      m[0] += x * dy;
      m[1] += x * x / 2 * dy;
      m[2] += x * y * dy;
      m[3] += x * x * x / 3 * dy;
      m[4] += x * x / 2 * y * dy;
      m[5] += x * y * y * dy;
    }
    for (double& v : m) v *= 2 * kPi / n;
    return m;
  }
  std::optional<double> area() const override { return quad_moments(quadrature_samples())[0]; }
  std::optional<double> perimeter() const override { return quad_perimeter(quadrature_samples()); }
  std::optional<Moments2> moments() const override { return quad_moments(quadrature_samples()); }
};

// Star-shaped r(s) (cos s, sin s).
class StarShape : public ParametricShape {
public:
  struct Radius {
    double r, d1, d2;
  };
  virtual Radius radius(double s) const = 0;
  virtual double r_min() const = 0;
  virtual double r_max() const = 0;

  CurveJet jet(double s) const override {
    Radius r = radius(s);
    double c = std::cos(s), sn = std::sin(s);
    return {{r.r * c, r.r * sn},
            {r.d1 * c - r.r * sn, r.d1 * sn + r.r * c},
            {(r.d2 - r.r) * c - 2 * r.d1 * sn, (r.d2 - r.r) * sn + 2 * r.d1 * c}};
  }
  double guess(P2 p) const override { return std::atan2(p.y, p.x); }
  double min_speed() const override { return r_min(); }
  bool contains(P2 p) const override {
    return std::hypot(p.x, p.y) <= radius(std::atan2(p.y, p.x)).r;
  }
  /// Upper bound of |r'| (for the sector filter).
  virtual double max_dr() const = 0;
  /// The membership test in double: |p| <= r(theta).
  virtual bool star_test(double x, double y, double rr) const {
    return std::sqrt(rr) <= radius(std::atan2(y, x)).r;
  }

  // Sector filter: the pseudo-angle q in [0, 4) (monotone in theta, no atan2) selects one of
  // kSectors sectors with precomputed bounds lo <= r <= hi (dense samples widened by
  // max|r'| times the sample spacing); |p| <= lo or |p| > hi decides at once, the rest goes
  // through star_test.
  std::unique_ptr<GaussDigitization2> digitize(double h, P2 t, Box2 box) const override {
    constexpr int kSectors = 4096, kSamples = 16;
    auto table = std::make_shared<std::vector<std::array<double, 2>>>(kSectors);
    auto theta_of = [](double q) {
      double quadrant = std::floor(q), f = q - quadrant;
      double th = quadrant * kPi / 2 + std::atan2(f, 1 - f);
      return th >= kPi ? th - 2 * kPi : th;
    };
    for (int k = 0; k < kSectors; ++k) {
      double q0 = 4.0 * k / kSectors, q1 = 4.0 * (k + 1) / kSectors;
      double th0 = theta_of(q0), th1 = theta_of(q1 - 1e-15);
      if (th1 < th0) th1 += 2 * kPi;
      double lo = std::numeric_limits<double>::infinity(), hi = 0;
      for (int i = 0; i <= kSamples; ++i) {
        double r = radius(th0 + (th1 - th0) * i / kSamples).r;
        lo = std::min(lo, r);
        hi = std::max(hi, r);
      }
      // Between samples r moves by at most max|r'| times the spacing (plus 1e-6 rad of
      // slack for the rounding of q near sector ends).
      double margin = max_dr() * ((th1 - th0) / kSamples + 1e-6) + 1e-9 * r_max();
      lo = std::max(0.0, lo - margin);
      hi += margin;
      (*table)[static_cast<std::size_t>(k)] = {lo * lo, hi * hi};
    }
    auto f = [this, table](double x, double y) {
      double rr = x * x + y * y;
      double ax = std::abs(x), ay = std::abs(y), s = ax + ay;
      if (s == 0) return true;
      double q = x >= 0 ? (y >= 0 ? y / s : 3 + x / s) : (y >= 0 ? 1 - x / s : 2 - y / s);
      auto k = std::min(kSectors - 1, static_cast<int>(q * (kSectors / 4.0)));
      const auto& b = (*table)[static_cast<std::size_t>(k)];
      if (rr < b[0]) return true;
      if (rr > b[1]) return false;
      return star_test(x, y, rr);
    };
    return std::make_unique<DoubleDigitization<decltype(f)>>(f, h, t, box);
  }
  std::optional<std::vector<std::pair<double, double>>> bounding_box() const override {
    return std::vector<std::pair<double, double>>{{-r_max(), r_max()}, {-r_max(), r_max()}};
  }

  /// True when r or r' jumps across the seam t = +-pi: the boundary has a corner there.
  virtual bool seam_corner() const { return false; }

  // Federer's formula on 4096 samples (pairs) and the curvature on 2^16 samples, divided by
  // kReachSafety = 2 (sampling only overestimates an infimum); 0 with a corner. Computed
  // once, on first use (about 20 ms), thread-safely.
  std::optional<double> reach_lower_bound() const override {
    constexpr int kPairs = 4096, kDense = 1 << 16;
    constexpr double kReachSafety = 2.0;
    std::call_once(reach_once_, [this] {
      reach_ = seam_corner() ? 0.0 : sampled_reach(kPairs, kDense) / kReachSafety;
    });
    return reach_;
  }

private:
  mutable std::once_flag reach_once_;
  mutable double reach_ = 0;
};

class Flower final : public StarShape {
public:
  // cos(K theta + PHI) from (x + i y)^K / rho^K (K a non-negative integer): no atan2.
  bool star_test(double x, double y, double rr) const override {
    if (k_ < 0 || k_ > 64) return StarShape::star_test(x, y, rr);
    const int k = static_cast<int>(k_);
    double re = 1, im = 0;
    for (int i = 0; i < k; ++i) {
      double nre = re * x - im * y;
      im = re * y + im * x;
      re = nre;
    }
    // rho <= r0 + a cos(K theta + PHI), multiplied by rho^K > 0.
    double rho = std::sqrt(rr), rk = 1;
    for (int i = 0; i < k; ++i) rk *= rho;
    return rho * rk <= r0_ * rk + a_ * (cp_ * re - sp_ * im);
  }
  double max_dr() const override { return std::abs(a_ * k_); }
  // r = R0 + A cos(K t + PHI) is analytic and |A| < R0: a C^infinity boundary (convex only
  // for small A, not claimed).
  ShapeClass shape_class() const override { return {.c3 = true}; }

  Flower(std::string spec, double r0, double a, double k, double phi)
      : spec_(std::move(spec)), r0_(r0), a_(a), k_(k), phi_(phi), cp_(std::cos(phi)),
        sp_(std::sin(phi)) {}
  std::string spec() const override { return spec_; }
  Radius radius(double s) const override {
    double u = k_ * s + phi_;
    return {r0_ + a_ * std::cos(u), -a_ * k_ * std::sin(u), -a_ * k_ * k_ * std::cos(u)};
  }
  double r_min() const override { return r0_ - std::abs(a_); }
  double r_max() const override { return r0_ + std::abs(a_); }
  std::optional<double> area() const override {
    return kPi * (r0_ * r0_ + (k_ != 0 ? a_ * a_ / 2 : 0.0));
  }

private:
  std::string spec_;
  double r0_, a_, k_, phi_, cp_, sp_;
};

class AccFlower final : public StarShape {
public:
  AccFlower(std::string spec, double r1, double r2, double p)
      : spec_(std::move(spec)), r1_(r1), r2_(r2), p_(p) {}
  std::string spec() const override { return spec_; }
  Radius radius(double s) const override {
    // t wrapped to [-pi, pi)
    return radius_unwrapped(s - 2 * kPi * std::floor((s + kPi) / (2 * kPi)));
  }
  // r(pi) = r(-pi) always (cos is even); r'(pi) - r'(-pi) = -6 R2 P pi^2 sin(P pi^3)
  // vanishes iff P = m / pi^2 (m integer). The tolerance 1e-11 (max r + max |r'|) absorbs
  // the rounding of such a P to a double (a jump of about 1e-14 of that scale for
  // 10 / pi^2); a P off by 1e-9 relative is a corner.
  bool seam_corner() const override {
    Radius a = radius_unwrapped(kPi), b = radius_unwrapped(-kPi);
    double tol = 1e-11 * (r_max() + max_dr());
    return std::abs(a.r - b.r) > tol || std::abs(a.d1 - b.d1) > tol;
  }
  double r_min() const override { return r1_ - std::abs(r2_); }
  double r_max() const override { return r1_ + std::abs(r2_); }
  int quadrature_samples() const override { return 1 << 20; }
  // C^2 at t = +-pi at best (the third derivative of r jumps there; a corner unless
  // P = m / pi^2): not C^3, so no theory check applies.
  ShapeClass shape_class() const override { return {}; }
  double max_dr() const override { return std::abs(r2_ * p_) * 3 * kPi * kPi; }

private:
  std::string spec_;
  double r1_, r2_, p_;

  Radius radius_unwrapped(double t) const {
    double u = p_ * t * t * t;
    double du = 3 * p_ * t * t, ddu = 6 * p_ * t;
    return {r1_ + r2_ * std::cos(u), -r2_ * std::sin(u) * du,
            -r2_ * (std::cos(u) * du * du + std::sin(u) * ddu)};
  }
};

// Ball and ellipse: parametric ground truth, exact polynomial membership.
class Ellipse final : public ParametricShape {
public:
  Ellipse(std::string spec, double a, double b, double theta, Polynomial f)
      : spec_(std::move(spec)), a_(a), b_(b), c_(std::cos(theta)), s_(std::sin(theta)),
        theta_(theta) {
    preds_.emplace_back(std::move(f));
  }
  std::string spec() const override { return spec_; }
  CurveJet jet(double t) const override {
    double ct = std::cos(t), st = std::sin(t);
    auto rot = [&](double x, double y) { return P2{c_ * x - s_ * y, s_ * x + c_ * y}; };
    return {rot(a_ * ct, b_ * st), rot(-a_ * st, b_ * ct), rot(-a_ * ct, -b_ * st)};
  }
  double guess(P2 p) const override {
    double x = c_ * p.x + s_ * p.y, y = -s_ * p.x + c_ * p.y;
    return std::atan2(y / b_, x / a_);
  }
  double min_speed() const override { return std::min(a_, b_); }
  // Ball and ellipse: convex, analytic boundary, curvature >= b / a^2 > 0.
  ShapeClass shape_class() const override {
    return {.convex = true, .c3 = true, .positive_curvature = true};
  }
  // The reach of an ellipse is its minimal radius of curvature b^2/a (b <= a), at the
  // ends of the major axis: the medial axis of the inside is the segment between the two
  // centres of curvature (+-(a - b^2/a), 0), at distance >= b^2/a from the boundary; the
  // outside, convex complement, has none. Ball: R.
  std::optional<double> reach_lower_bound() const override {
    return std::min(a_, b_) * std::min(a_, b_) / std::max(a_, b_);
  }
  bool contains(P2 p) const override {
    double x = c_ * p.x + s_ * p.y, y = -s_ * p.x + c_ * p.y;
    return (x / a_) * (x / a_) + (y / b_) * (y / b_) <= 1.0;
  }
  std::unique_ptr<GaussDigitization2> digitize(double h, P2 t, Box2 box) const override {
    return std::make_unique<PolyDigitization>(&preds_, h, t, box);
  }
  std::optional<double> area() const override { return kPi * a_ * b_; }
  std::optional<double> perimeter() const override {
    return a_ == b_ ? 2 * kPi * a_ : ellipse_perimeter(a_, b_);
  }
  std::optional<Moments2> moments() const override {
    // Axis-aligned: m00 = pi a b, m20 = pi a^3 b / 4, m02 = pi a b^3 / 4; then rotate.
    double m00 = kPi * a_ * b_, u = kPi * a_ * a_ * a_ * b_ / 4, v = kPi * a_ * b_ * b_ * b_ / 4;
    return Moments2{
        m00, 0, 0, c_ * c_ * u + s_ * s_ * v, c_ * s_ * (u - v), s_ * s_ * u + c_ * c_ * v};
  }
  std::optional<std::vector<std::pair<double, double>>> bounding_box() const override {
    double wx = std::sqrt(a_ * a_ * c_ * c_ + b_ * b_ * s_ * s_),
           wy = std::sqrt(a_ * a_ * s_ * s_ + b_ * b_ * c_ * c_);
    return std::vector<std::pair<double, double>>{{-wx, wx}, {-wy, wy}};
  }

private:
  std::string spec_;
  double a_, b_, c_, s_, theta_;
  std::vector<PolynomialSign> preds_;
};

// Convex polygon, counter-clockwise, rational vertices.
class Polygon final : public Shape2 {
public:
  Polygon(std::string spec, std::vector<std::array<BigRational, 2>> v) : spec_(std::move(spec)) {
    const int nv = 2;
    for (std::size_t i = 0; i < v.size(); ++i) {
      const auto& a = v[i];
      const auto& b = v[(i + 1) % v.size()];
      BigRational bx = b[0] - a[0], by = b[1] - a[1];
      // F = by x - bx y + (bx ay - by ax) <= 0 on the left of a -> b.
      Polynomial f = Polynomial::constant(by, nv) * Polynomial::variable(0, nv) -
                     Polynomial::constant(bx, nv) * Polynomial::variable(1, nv) +
                     Polynomial::constant(bx * a[1] - by * a[0], nv);
      preds_.emplace_back(std::move(f));
      vd_.push_back({a[0].to_double(), a[1].to_double()});
    }
  }
  std::string spec() const override { return spec_; }
  bool contains(P2 p) const override {
    for (std::size_t i = 0; i < vd_.size(); ++i) {
      P2 a = vd_[i], b = vd_[(i + 1) % vd_.size()];
      if ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x) < 0) return false;
    }
    return true;
  }
  std::unique_ptr<GaussDigitization2> digitize(double h, P2 t, Box2 box) const override {
    return std::make_unique<PolyDigitization>(&preds_, h, t, box);
  }
  BoundaryPoint2 project(P2 p) const override {
    BoundaryPoint2 best;
    double best_d = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < vd_.size(); ++i) {
      P2 a = vd_[i], b = vd_[(i + 1) % vd_.size()];
      double ex = b.x - a.x, ey = b.y - a.y, len2 = ex * ex + ey * ey;
      double u = std::clamp(((p.x - a.x) * ex + (p.y - a.y) * ey) / len2, 0.0, 1.0);
      P2 q{a.x + u * ex, a.y + u * ey};
      double d = std::hypot(p.x - q.x, p.y - q.y);
      if (d < best_d) {
        best_d = d;
        double len = std::sqrt(len2);
        best = {q, {ex / len, ey / len}, 0.0};
      }
    }
    return best;
  }
  // Corners: the medial axis of the inside reaches the vertices.
  std::optional<double> reach_lower_bound() const override { return 0.0; }
  ShapeClass shape_class() const override { return {.convex = true, .polygon = true}; }
  std::optional<double> area() const override { return moments()->at(0); }
  std::optional<double> perimeter() const override {
    double s = 0;
    for (std::size_t i = 0; i < vd_.size(); ++i) {
      P2 a = vd_[i], b = vd_[(i + 1) % vd_.size()];
      s += std::hypot(b.x - a.x, b.y - a.y);
    }
    return s;
  }
  std::optional<Moments2> moments() const override {
    Moments2 m{};
    for (std::size_t i = 0; i < vd_.size(); ++i) {
      P2 a = vd_[i], b = vd_[(i + 1) % vd_.size()];
      double cr = a.x * b.y - b.x * a.y;
      m[0] += cr / 2;
      m[1] += (a.x + b.x) * cr / 6;
      m[2] += (a.y + b.y) * cr / 6;
      m[3] += (a.x * a.x + a.x * b.x + b.x * b.x) * cr / 12;
      m[4] += (a.x * b.y + 2 * a.x * a.y + 2 * b.x * b.y + b.x * a.y) * cr / 24;
      m[5] += (a.y * a.y + a.y * b.y + b.y * b.y) * cr / 12;
    }
    return m;
  }
  std::optional<std::vector<std::pair<double, double>>> bounding_box() const override {
    double x0 = vd_[0].x, x1 = x0, y0 = vd_[0].y, y1 = y0;
    for (const auto& v : vd_) {
      x0 = std::min(x0, v.x);
      x1 = std::max(x1, v.x);
      y0 = std::min(y0, v.y);
      y1 = std::max(y1, v.y);
    }
    return std::vector<std::pair<double, double>>{{x0, x1}, {y0, y1}};
  }

private:
  std::string spec_;
  std::vector<PolynomialSign> preds_;
  std::vector<P2> vd_;
};

// F(x, y) <= 0.
class PolyShape final : public Shape2 {
public:
  PolyShape(std::string spec, Polynomial f) : spec_(std::move(spec)) {
    preds_.emplace_back(std::move(f));
  }
  std::string spec() const override { return spec_; }
  const Polynomial& f() const { return preds_[0].polynomial(); }
  // Assumed C^3 with positive reach (the user's polynomial; no check that grad F != 0 on the
  // curve): the theory checks apply as for a smooth shape.
  ShapeClass shape_class() const override { return {.c3 = true}; }
  bool contains(P2 p) const override {
    double q[2] = {p.x, p.y};
    return f().value(q) <= 0;
  }
  std::unique_ptr<GaussDigitization2> digitize(double h, P2 t, Box2 box) const override {
    return std::make_unique<PolyDigitization>(&preds_, h, t, box);
  }
  BoundaryPoint2 project(P2 p) const override {
    double q[2] = {p.x, p.y}, g[2], hs[4];
    for (int it = 0; it < 40; ++it) {
      double v = f().value(q);
      f().gradient(q, g);
      double g2 = g[0] * g[0] + g[1] * g[1];
      if (g2 == 0) break;
      double sx = v * g[0] / g2, sy = v * g[1] / g2;
      double damp = 1.0;
      // Damped: halve the step while |F| does not decrease.
      for (int k = 0; k < 30; ++k) {
        double r[2] = {q[0] - damp * sx, q[1] - damp * sy};
        if (std::abs(f().value(r)) <= std::abs(v)) break;
        damp /= 2;
      }
      q[0] -= damp * sx;
      q[1] -= damp * sy;
      if (std::hypot(damp * sx, damp * sy) < 1e-15 * (1 + std::hypot(q[0], q[1]))) break;
    }
    f().gradient(q, g);
    f().hessian(q, hs);
    double n = std::hypot(g[0], g[1]);
    double k = (g[1] * g[1] * hs[0] - 2 * g[0] * g[1] * hs[1] + g[0] * g[0] * hs[3]) / (n * n * n);
    return {{q[0], q[1]}, {-g[1] / n, g[0] / n}, k};
  }

private:
  std::string spec_;
  std::vector<PolynomialSign> preds_;
};

// --- parsing --------------------------------------------------------------------------------

// Parameters are finite and in a range where the shapes' double computations (projection,
// quadrature, sector tables) are meaningful: 0 or 1e-9 <= |value| <= 1e9, at most
// kMaxShapeParameters of them.
constexpr double kMaxShapeMagnitude = 1e9, kMinShapeMagnitude = 1e-9;
constexpr std::size_t kMaxShapeParameters = 20000;

std::string shown_spec(std::string_view spec) {
  return "shape '" +
         (spec.size() <= 60 ? std::string(spec) : std::string(spec.substr(0, 57)) + "...") + "'";
}

std::vector<BigRational> rationals(std::string_view args, std::string_view spec) {
  std::vector<BigRational> out;
  if (args.empty()) throw InvalidArgument(shown_spec(spec) + ": missing parameters");
  std::size_t start = 0;
  for (;;) {
    auto comma = args.find(',', start);
    std::string_view item =
        args.substr(start, comma == std::string_view::npos ? args.npos : comma - start);
    const std::string shown_item =
        item.size() <= 30 ? std::string(item) : std::string(item.substr(0, 27)) + "...";
    const std::string which =
        "parameter " + std::to_string(out.size() + 1) + " '" + shown_item + "'";
    if (out.size() == kMaxShapeParameters) {
      throw InvalidArgument(shown_spec(spec) + ": more than " +
                            std::to_string(kMaxShapeParameters) + " parameters");
    }
    try {
      out.push_back(parse_rational<BigInt>(item));
    } catch (const InvalidArgument&) {
      throw InvalidArgument(shown_spec(spec) + ": " + which +
                            " is not a number of the form 7, -3/4 or 0.125 (shape parameters are "
                            "exact: no exponent, inf or nan)");
    }
    const double d = out.back().to_double();
    if (!std::isfinite(d) || std::abs(d) > kMaxShapeMagnitude ||
        (out.back() != BigRational(0) && std::abs(d) < kMinShapeMagnitude)) {
      throw InvalidArgument(shown_spec(spec) + ": " + which +
                            " is out of range (0, or 1e-9 <= |value| <= 1e9)");
    }
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return out;
}

void expect_count(const std::vector<BigRational>& v, std::size_t lo, std::size_t hi,
                  std::string_view spec, std::string_view syntax) {
  if (v.size() < lo || v.size() > hi) {
    throw InvalidArgument(shown_spec(spec) + ": expected " + std::string(syntax) + ", got " +
                          std::to_string(v.size()) + " parameters");
  }
}

void expect_positive(const BigRational& v, std::string_view name, std::string_view spec) {
  if (v <= BigRational(0)) {
    throw InvalidArgument(shown_spec(spec) + ": " + std::string(name) + " = " + v.str() +
                          " must be > 0");
  }
}

Polynomial quadric(const BigRational& cxx, const BigRational& cxy, const BigRational& cyy,
                   const BigRational& c1) {
  auto X = Polynomial::variable(0, 2), Y = Polynomial::variable(1, 2);
  return Polynomial::constant(cxx, 2) * X * X + Polynomial::constant(cxy, 2) * X * Y +
         Polynomial::constant(cyy, 2) * Y * Y + Polynomial::constant(c1, 2);
}

} // namespace

double ellipse_perimeter(double a, double b) {
  double H = ((a - b) / (a + b)) * ((a - b) / (a + b));
  double sum = 1.0, c = 1.0, hn = 1.0;
  for (int n = 1; n < 2000; ++n) {
    c *= (0.5 - (n - 1)) / n; // binom(1/2, n)
    hn *= H;
    double term = c * c * hn;
    sum += term;
    if (term < 1e-18 * sum) break;
  }
  return kPi * (a + b) * sum;
}

double quadrature_perimeter(const Shape2& shape, int n) {
  const auto* p = dynamic_cast<const ParametricShape*>(&shape);
  if (p == nullptr) throw InvalidArgument("'" + shape.spec() + "' is not a parametric shape");
  return p->quad_perimeter(n);
}

namespace detail {

void register_2d_shapes(std::vector<ShapeKind>& kinds) {
  kinds.push_back({"ball", 2, "ball:R", "disc of radius R centred at the origin (exact)",
                   [](std::string_view args, std::string_view spec) -> std::unique_ptr<Shape> {
                     auto v = rationals(args, spec);
                     expect_count(v, 1, 1, spec, "ball:R");
                     expect_positive(v[0], "R", spec);
                     double r = v[0].to_double();
                     return std::make_unique<Ellipse>(std::string(spec), r, r, 0.0,
                                                      quadric(1, 0, 1, -(v[0] * v[0])));
                   }});
  kinds.push_back(
      {"ellipse", 2, "ellipse:A,B[,THETA]",
       "ellipse with half-axes A, B rotated by THETA radians (exact when THETA = 0)",
       [](std::string_view args, std::string_view spec) -> std::unique_ptr<Shape> {
         auto v = rationals(args, spec);
         expect_count(v, 2, 3, spec, "ellipse:A,B[,THETA]");
         expect_positive(v[0], "A", spec);
         expect_positive(v[1], "B", spec);
         double a = v[0].to_double(), b = v[1].to_double();
         double theta = v.size() > 2 ? v[2].to_double() : 0.0;
         Polynomial f;
         if (theta == 0.0) {
           f = quadric(BigRational(1) / (v[0] * v[0]), 0, BigRational(1) / (v[1] * v[1]), -1);
         } else {
           // ((c x + s y)/a)^2 + ((-s x + c y)/b)^2 - 1 with double coefficients (exact
           // from then on).
           double c = std::cos(theta), s = std::sin(theta);
           double cxx = c * c / (a * a) + s * s / (b * b), cyy = s * s / (a * a) + c * c / (b * b),
                  cxy = 2 * c * s * (1 / (a * a) - 1 / (b * b));
           f = quadric(exact_rational(cxx), exact_rational(cxy), exact_rational(cyy), -1);
         }
         return std::make_unique<Ellipse>(std::string(spec), a, b, theta, std::move(f));
       }});
  kinds.push_back({"flower", 2, "flower:R0,A,K[,PHI]",
                   "star r(t) = R0 + A cos(K t + PHI), K integer, |A| < R0 (double membership)",
                   [](std::string_view args, std::string_view spec) -> std::unique_ptr<Shape> {
                     auto v = rationals(args, spec);
                     expect_count(v, 3, 4, spec, "flower:R0,A,K[,PHI]");
                     expect_positive(v[0], "R0", spec);
                     double r0 = v[0].to_double(), a = v[1].to_double(), k = v[2].to_double();
                     if (v[2].den() != 1 || std::abs(k) > 1000) {
                       throw InvalidArgument(shown_spec(spec) + ": K = " + v[2].str() +
                                             " must be an integer in -1000..1000");
                     }
                     if (std::abs(a) >= r0) {
                       throw InvalidArgument(shown_spec(spec) + ": |A| must be < R0");
                     }
                     return std::make_unique<Flower>(std::string(spec), r0, a, k,
                                                     v.size() > 3 ? v[3].to_double() : 0.0);
                   }});
  kinds.push_back(
      {"accflower", 2, "accflower:R1,R2,P",
       "accelerated flower r(t) = R1 + R2 cos(P t^3), t in [-pi, pi), |R2| < R1; P = 2K/pi^2 is "
       "DGtal's AccFlower2D with K petals (smooth at t = +-pi)",
       [](std::string_view args, std::string_view spec) -> std::unique_ptr<Shape> {
         auto v = rationals(args, spec);
         expect_count(v, 3, 3, spec, "accflower:R1,R2,P");
         expect_positive(v[0], "R1", spec);
         double r1 = v[0].to_double(), r2 = v[1].to_double();
         if (std::abs(r2) >= r1) {
           throw InvalidArgument(shown_spec(spec) + ": |R2| must be < R1");
         }
         return std::make_unique<AccFlower>(std::string(spec), r1, r2, v[2].to_double());
       }});
  kinds.push_back(
      {"polygon", 2, "polygon:X1,Y1,X2,Y2,...",
       "convex polygon with rational vertices, in either orientation (exact)",
       [](std::string_view args, std::string_view spec) -> std::unique_ptr<Shape> {
         auto v = rationals(args, spec);
         if (v.size() < 6 || v.size() % 2 != 0) {
           throw InvalidArgument(shown_spec(spec) +
                                 ": expected polygon:X1,Y1,X2,Y2,X3,Y3,... (at least 3 vertices)");
         }
         std::vector<std::array<BigRational, 2>> pts;
         for (std::size_t i = 0; i < v.size(); i += 2) pts.push_back({v[i], v[i + 1]});
         auto cross = [&](std::size_t i) {
           const auto& a = pts[i];
           const auto& b = pts[(i + 1) % pts.size()];
           const auto& c = pts[(i + 2) % pts.size()];
           return (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]);
         };
         BigRational area2(0);
         for (std::size_t i = 0; i < pts.size(); ++i) {
           const auto& a = pts[i];
           const auto& b = pts[(i + 1) % pts.size()];
           area2 += a[0] * b[1] - b[0] * a[1];
         }
         if (area2 == BigRational(0)) {
           throw InvalidArgument(shown_spec(spec) + ": degenerate polygon");
         }
         if (area2 < BigRational(0)) std::reverse(pts.begin(), pts.end());
         for (std::size_t i = 0; i < pts.size(); ++i) {
           if (cross(i) <= BigRational(0)) {
             throw InvalidArgument(shown_spec(spec) + ": not strictly convex at vertex " +
                                   std::to_string(i + 2));
           }
         }
         return std::make_unique<Polygon>(std::string(spec), std::move(pts));
       }});
  kinds.push_back(
      {"poly", 2, "poly:EXPR", "F(x, y) <= 0, F a polynomial with rational coefficients (exact)",
       [](std::string_view args, std::string_view spec) -> std::unique_ptr<Shape> {
         if (args.find('z') != std::string_view::npos) return nullptr; // 3D
         Polynomial f = Polynomial::parse(args, 2);
         if (f.degree() < 1) {
           throw InvalidArgument(shown_spec(spec) + ": the polynomial must not be constant");
         }
         return std::make_unique<PolyShape>(std::string(spec), std::move(f));
       }});
}

} // namespace detail

} // namespace zdg
