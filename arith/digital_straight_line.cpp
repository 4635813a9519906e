#include <zdg/arith/digital_straight_line.hpp>

#include <zdg/arith/error.hpp>

#include <algorithm>
#include <cstdint>

#include <string>

namespace zdg {

namespace {
template <TowerInt I>
int sign_or_plus(const I& v) {
  return v < 0 ? -1 : 1;
}

template <TowerInt I>
I step_remainder(const I& a, const I& b, Step s) {
  return a * I(s.x) - b * I(s.y);
}

template <TowerInt I>
std::string dsl_name(const I& a, const I& b, const I& mu) {
  return "DSL(a = " + to_string(a) + ", b = " + to_string(b) + ", mu = " + to_string(mu) + ")";
}
} // namespace

template <TowerInt I>
std::pair<Step, Step> dsl_steps(const I& a, const I& b, DslKind kind) {
  int sa = sign_or_plus(a), sb = sign_or_plus(b);
  Step u, v;
  if (kind == DslKind::standard) {
    u = {sb, 0};
    v = {0, sa};
  } else {
    u = abs(b) >= abs(a) ? Step{sb, 0} : Step{0, sa};
    v = {sb, sa};
  }
  if (step_remainder(a, b, u) >= step_remainder(a, b, v)) return {u, v};
  return {v, u};
}

template <TowerInt I>
DigitalStraightLine<I>::DigitalStraightLine(I a, I b, I mu, DslKind kind)
    : a_(std::move(a)), b_(std::move(b)), mu_(std::move(mu)), kind_(kind) {
  if (a_ == 0 && b_ == 0) throw InvalidArgument("digital straight line: (a, b) = (0, 0)");
  if (gcd(a_, b_) != 1) {
    throw InvalidArgument("digital straight line: gcd(a, b) != 1 in " + dsl_name(a_, b_, mu_));
  }
  omega_ = kind_ == DslKind::naive ? std::max(abs(a_), abs(b_)) : I(abs(a_) + abs(b_));
  auto [u, v] = dsl_steps(a_, b_, kind_);
  s0_ = u;
  s1_ = v;
  r0_ = step_remainder(a_, b_, s0_);
  r1_ = step_remainder(a_, b_, s1_);
}

template <TowerInt I>
IntRange<I> DigitalStraightLine<I>::ordinates_at(const I& x) const {
  if (b_ == 0) throw InvalidArgument("ordinates_at: b = 0 in " + dsl_name(a_, b_, mu_));
  I ax = a_ * x;
  if (b_ > 0) {
    // b y in (a x - mu - omega, a x - mu]
    return {I(floor_div(I(ax - mu_ - omega_), b_) + 1), floor_div(I(ax - mu_), b_)};
  }
  I c = -b_; // a x + c y in [mu, mu + omega)
  return {ceil_div(I(mu_ - ax), c), I(ceil_div(I(mu_ - ax + omega_), c) - 1)};
}

template <TowerInt I>
IntRange<I> DigitalStraightLine<I>::abscissas_at(const I& y) const {
  if (a_ == 0) throw InvalidArgument("abscissas_at: a = 0 in " + dsl_name(a_, b_, mu_));
  I t = mu_ + b_ * y; // a x in [t, t + omega)
  if (a_ > 0) return {ceil_div(t, a_), I(ceil_div(I(t + omega_), a_) - 1)};
  I c = -a_; // c x in (-t - omega, -t]
  return {I(floor_div(I(-t - omega_), c) + 1), floor_div(I(-t), c)};
}

template <TowerInt I>
Point2<I> DigitalStraightLine<I>::point_at_abscissa(const I& x) const {
  if (kind_ != DslKind::naive || abs(a_) > abs(b_)) {
    throw InvalidArgument("point_at_abscissa needs a naive line with |a| <= |b|, not " +
                          dsl_name(a_, b_, mu_));
  }
  return {x, ordinates_at(x).lo};
}

template <TowerInt I>
Point2<I> DigitalStraightLine<I>::point_at_ordinate(const I& y) const {
  if (kind_ != DslKind::naive || abs(a_) < abs(b_)) {
    throw InvalidArgument("point_at_ordinate needs a naive line with |a| >= |b|, not " +
                          dsl_name(a_, b_, mu_));
  }
  return {abscissas_at(y).lo, y};
}

template <TowerInt I>
Point2<I> DigitalStraightLine<I>::next(const Point& p) const {
  I r = remainder(p);
  if (r < mu_ || r >= mu_ + omega_) {
    throw InvalidArgument("next: point (" + to_string(p.x) + ", " + to_string(p.y) +
                          ") is not in " + dsl_name(a_, b_, mu_));
  }
  Step s = r + r0_ < mu_ + omega_ ? s0_ : s1_;
  return {p.x + s.x, p.y + s.y};
}

template <TowerInt I>
std::vector<Point2<I>> DigitalStraightLine<I>::points(const Point& start, std::size_t count) const {
  std::vector<Point> out;
  if (count == 0) return out;
  if (!contains(start)) next(start); // throws with the message
  out.reserve(count);
  out.push_back(start);
  I r = remainder(start);
  const I top = mu_ + omega_;
  Point p = start;
  for (std::size_t k = 1; k < count; ++k) {
    if (r + r0_ < top) {
      p = {p.x + s0_.x, p.y + s0_.y};
      r += r0_;
    } else {
      p = {p.x + s1_.x, p.y + s1_.y};
      r += r1_;
    }
    out.push_back(p);
  }
  return out;
}

template <TowerInt I>
Point2<I> DigitalStraightLine<I>::point_with_remainder(const I& r) const {
  // a u + b v = 1, so (x, y) = (r u, -r v) has a x - b y = r; then move by k (b, a).
  auto bz = ext_gcd(a_, b_);
  I x = r * bz.x, y = -(r * bz.y);
  if (b_ == 0) return {I(r / a_), I(0)}; // a = +-1
  I bb = abs(b_);
  I xm = mod(x, bb);
  I k = (xm - x) / b_;
  return {xm, y + k * a_};
}

template <TowerInt I>
std::string DigitalStraightLine<I>::period_word() const {
  if (omega_ > I(std::int64_t{1} << 30)) {
    throw InvalidArgument("period_word: the period of " + dsl_name(a_, b_, mu_) + " has " +
                          to_string(omega_) + " letters, more than 2^30");
  }
  const std::size_t n = static_cast<std::size_t>(to_double(omega_));
  std::string w;
  w.reserve(n);
  I r = mu_;
  const I top = mu_ + omega_;
  for (std::size_t k = 0; k < n; ++k) {
    if (r + r0_ < top) {
      w.push_back('0');
      r += r0_;
    } else {
      w.push_back('1');
      r += r1_;
    }
  }
  return w;
}

template class DigitalStraightLine<Int64>;
template class DigitalStraightLine<Int128>;
template class DigitalStraightLine<BigInt>;
template std::pair<Step, Step> dsl_steps(const Int64&, const Int64&, DslKind);
template std::pair<Step, Step> dsl_steps(const Int128&, const Int128&, DslKind);
template std::pair<Step, Step> dsl_steps(const BigInt&, const BigInt&, DslKind);

} // namespace zdg
