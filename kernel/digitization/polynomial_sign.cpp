#include <zdg/kernel/digitization/polynomial_sign.hpp>

#include <zdg/arith/error.hpp>

#include <algorithm>
#include <limits>

namespace zdg {

namespace {

// |c~| as the magnitude of a coefficient in the bound, at least the smallest normal double: a
// coefficient that rounds to a subnormal (or to 0) has an absolute error below 2^-1075, which
// is u times that (the relative error analysis then holds).
double magnitude_of(double c) {
  return std::max(std::abs(c), std::numeric_limits<double>::min());
}

constexpr int kPowerTable = 16;
constexpr std::size_t kColumnTerms = 64;

double pow_int(double b, int e) {
  double r = 1.0;
  for (int i = 0; i < e; ++i) r *= b;
  return r;
}

} // namespace

PolynomialSign::PolynomialSign(Polynomial f) : f_(std::move(f)) {
  quadric_ = f_.nvars() == 2 && f_.degree() <= 2;
  if (quadric_) {
    for (const auto& m : f_.terms()) {
      const int ex = m.exponent[0], ey = m.exponent[1];
      const std::size_t idx = ex == 2              ? 0
                              : ex == 1 && ey == 1 ? 1
                              : ey == 2            ? 2
                              : ex == 1            ? 3
                              : ey == 1            ? 4
                                                   : 5;
      q_[idx] = m.coefficient_double;
      aq_[idx] = magnitude_of(m.coefficient_double);
    }
  }
  for (const auto& m : f_.terms()) abs_.push_back(magnitude_of(m.coefficient_double));
  const double terms = static_cast<double>(f_.terms().size());
  gamma_ = 8.0 * (f_.degree() + terms + 2.0) * std::numeric_limits<double>::epsilon();
  ops_ = terms * (f_.degree() + 2.0);
}

double PolynomialSign::value(const double* p) const {
  if (quadric_) {
    const double x = p[0], y = p[1];
    return ((q_[0] * x + q_[1] * y + q_[3]) * x + (q_[2] * y + q_[4]) * y) + q_[5];
  }
  return f_.value(p);
}

// #ops * 2^-1022 * max(1, X)^deg: each rounding of a product chain loses at most half the
// smallest subnormal (2^-1074), later multiplied by factors of magnitude <= X; the smallest
// normal 2^-1022 in its place keeps every operand of this bound normal (a product with a
// subnormal result takes a microcode assist: 7% of a 3D II sweep's time went here) and only
// loosens the bound below 2^-1000, where no filter decision of a grid point falls.
double PolynomialSign::underflow_slack(const double* magnitude) const {
  double x = 1.0;
  for (int i = 0; i < f_.nvars(); ++i) x = std::max(x, magnitude[i]);
  return ops_ * std::numeric_limits<double>::min() * pow_int(x, f_.degree());
}

double PolynomialSign::error_bound(const double* magnitude) const {
  double mag = 0.0;
  if (quadric_) {
    const double mx = magnitude[0], my = magnitude[1];
    mag = ((aq_[0] * mx + aq_[1] * my + aq_[3]) * mx + (aq_[2] * my + aq_[4]) * my) + aq_[5];
  } else {
    for (std::size_t k = 0; k < abs_.size(); ++k) {
      const auto& m = f_.terms()[k];
      double a = abs_[k];
      for (int i = 0; i < f_.nvars(); ++i) {
        a *= pow_int(magnitude[i], m.exponent[static_cast<std::size_t>(i)]);
      }
      mag += a;
    }
  }
  return gamma_ * mag + underflow_slack(magnitude);
}

double PolynomialSign::value_and_bound(const double* p, const double* magnitude,
                                       double& bound) const {
  if (quadric_) {
    bound = error_bound(magnitude);
    return value(p);
  }
  double v = 0.0, mag = 0.0;
  const int nv = f_.nvars(), deg = f_.degree();
  if (deg < kPowerTable) {
    // The powers of each variable once (the same products as pow_int, so the same doubles).
    double pp[3][kPowerTable], pm[3][kPowerTable];
    for (int i = 0; i < nv; ++i) {
      pp[i][0] = pm[i][0] = 1.0;
      for (int e = 1; e <= deg; ++e) {
        pp[i][e] = pp[i][e - 1] * p[i];
        pm[i][e] = pm[i][e - 1] * magnitude[i];
      }
    }
    for (std::size_t k = 0; k < abs_.size(); ++k) {
      const auto& m = f_.terms()[k];
      double t = m.coefficient_double, a = abs_[k];
      for (int i = 0; i < nv; ++i) {
        const int e = m.exponent[static_cast<std::size_t>(i)];
        t *= pp[i][e];
        a *= pm[i][e];
      }
      v += t;
      mag += a;
    }
    bound = gamma_ * mag + underflow_slack(magnitude);
    return v;
  }
  for (std::size_t k = 0; k < abs_.size(); ++k) {
    const auto& m = f_.terms()[k];
    double t = m.coefficient_double, a = abs_[k];
    for (int i = 0; i < nv; ++i) {
      const int e = m.exponent[static_cast<std::size_t>(i)];
      t *= pow_int(p[i], e);
      a *= pow_int(magnitude[i], e);
    }
    v += t;
    mag += a;
  }
  bound = gamma_ * mag + underflow_slack(magnitude);
  return v;
}

void PolynomialSign::column_inside(const GridFrame& frame, std::int64_t x, std::int64_t y,
                                   std::int64_t z0, std::int64_t z1, std::uint8_t* out) const {
  if (f_.nvars() != 3 || frame.dimension() != 3)
    throw InvalidArgument("polynomial sign: column_inside needs three variables");
  const int deg = f_.degree();
  const std::size_t nt = abs_.size();
  if (deg >= kPowerTable || nt > kColumnTerms) {
    for (std::int64_t z = z0; z <= z1; ++z) {
      const std::int64_t p[3] = {x, y, z};
      out[z - z0] = frame.sign(*this, p) <= 0;
    }
    return;
  }
  // The x and y parts of the approximate point and of the magnitudes (GridFrame::approximate).
  double p[3], mag[3];
  {
    const std::int64_t q[3] = {x, y, z0};
    frame.approximate(q, p, mag);
  }
  // Each term's chain as in value_and_bound: coefficient * x^e0 * y^e1 (here, once), then
  // * z^e2 (per point): the same products in the same order.
  double pp[2][kPowerTable], pm[2][kPowerTable];
  for (int i = 0; i < 2; ++i) {
    pp[i][0] = pm[i][0] = 1.0;
    for (int e = 1; e <= deg; ++e) {
      pp[i][e] = pp[i][e - 1] * p[i];
      pm[i][e] = pm[i][e - 1] * mag[i];
    }
  }
  double txy[kColumnTerms], axy[kColumnTerms];
  int ez[kColumnTerms];
  for (std::size_t k = 0; k < nt; ++k) {
    const auto& m = f_.terms()[k];
    txy[k] = m.coefficient_double * pp[0][m.exponent[0]] * pp[1][m.exponent[1]];
    axy[k] = abs_[k] * pm[0][m.exponent[0]] * pm[1][m.exponent[1]];
    ez[k] = m.exponent[2];
  }
  for (std::int64_t z = z0; z <= z1; ++z) {
    const std::int64_t q[3] = {x, y, z};
    frame.approximate(q, p, mag); // p[2], mag[2]: z's part (x and y as above)
    double pz[kPowerTable], mz[kPowerTable];
    pz[0] = mz[0] = 1.0;
    for (int e = 1; e <= deg; ++e) {
      pz[e] = pz[e - 1] * p[2];
      mz[e] = mz[e - 1] * mag[2];
    }
    double v = 0.0, a = 0.0;
    for (std::size_t k = 0; k < nt; ++k) {
      v += txy[k] * pz[ez[k]];
      a += axy[k] * mz[ez[k]];
    }
    const double bound = gamma_ * a + underflow_slack(mag);
    int sgn;
    if (std::isfinite(v) && std::isfinite(bound) && (v > bound || v < -bound)) {
      sgn = v > bound ? 1 : -1;
    } else {
      const auto e = frame.exact(q);
      sgn = f_.sign_exact(e.data());
    }
    out[z - z0] = sgn <= 0;
  }
}

void PolynomialDigitization::column(std::int64_t x, std::int64_t y, std::int64_t z0,
                                    std::int64_t z1, std::uint8_t* out) const {
  if (f_->nvars() == 3 && frame_->dimension() == 3) {
    f_->column_inside(*frame_, x, y, z0, z1, out);
    return;
  }
  for (std::int64_t z = z0; z <= z1; ++z) out[z - z0] = (*this)({x, y, z});
}

GridFrame::GridFrame(double h, std::span<const double> t)
    : d_(static_cast<int>(t.size())), h_(h), hx_(exact_rational(h)) {
  if (d_ < 1 || d_ > 3) throw InvalidArgument("grid frame: dimension must be 1, 2 or 3");
  for (std::size_t i = 0; i < t.size(); ++i) {
    t_[i] = t[i];
    tx_[i] = exact_rational(t[i]);
  }
}

std::array<BigRational, 3> GridFrame::exact(const std::int64_t* z) const {
  std::array<BigRational, 3> q;
  for (std::size_t i = 0; i < static_cast<std::size_t>(d_); ++i) {
    q[i] = hx_ * BigRational(BigInt(z[i])) - tx_[i];
  }
  return q;
}

} // namespace zdg
