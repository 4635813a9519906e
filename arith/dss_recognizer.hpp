// Online recognition of digital straight segments (DSS), at both ends, with retraction.
//
// A path of distinct points p_0 .. p_{n-1}, consecutive points 8-adjacent (or 4-adjacent), is
// a DSS when its points lie in one naive (resp. standard) digital straight line
// D(a, b, mu) = { mu <= a x - b y < mu + omega } (arith/digital_straight_line.hpp).
// Minimal characteristics: among the lines containing the DSS, the one of smallest period
// omega is unique up to orientation; we orient it by the path, so that (b, a) points from p_0
// towards p_{n-1}, and mu is then determined (the DSS has an upper leaning point, r = mu, and a
// lower one, r = mu + omega - 1). For one point, where every line of period 1 contains it, the
// canonical answer is (a, b, mu) = (0, 1, -y). With two or more points, a = b = 0 never occurs,
// gcd(a, b) = 1, and (b, a) is the direction of the segment.
//
// Algorithm (Debled-Rennesson and Reveilles 1995, in the octant-free formulation with steps and
// shift vector used by DGtal's ArithmeticalDSS, Roussillon 2013): the recognizer keeps (a, b, mu),
// the two steps the path uses, and the first and last upper (Uf, Ul) and lower (Lf, Ll) leaning
// points. Adding a point M at the front: r(M) in [mu, mu + omega) keeps the line; r(M) = mu - 1
// (weakly exterior above) gives (b, a) = M - Uf; r(M) = mu + omega (below) gives (b, a) = M - Lf;
// anything else, or a third step, means the path is no longer a DSS (extend_* returns false and
// changes nothing). Removing the first point F: if F = Uf and Lf = Ll, the new direction is Lf -
// (Uf + shift), else Uf moves on by (b, a) (and symmetrically for F = Lf); the back end works on
// the reversed segment. Each operation is O(1) (two integer divisions at most for a retraction).
//
// Width: the recognizer stores coordinates relative to its first point, so its arithmetic only
// involves |a|, |b| <= n and local coordinates <= n: Int64 serves any path shorter than about
// 2^31 points whatever the coordinates (near 2^62 included) as long as the local differences
// fit. Only mu in absolute coordinates needs a x0 - b y0: mu() computes it in I (it may throw
// OverflowError), characteristics() in BigInt. recognize_dss<I>() runs on I (OverflowError when a
// point or a local quantity leaves I); recognize_dss_exact() escalates Int64 -> Int128 -> BigInt
// when checked arithmetic overflows (re-feeding the points) and says which type served. After an
// OverflowError a recognizer's state is unspecified: discard it and re-run on a wider type.
//
// Sources: Debled-Rennesson and Reveilles, A linear algorithm for segmentation of digital
// curves, IJPRAI 9(4), 1995 (extension, minimality by leaning points); Lachaud, Vialard and de
// Vieilleville, Image Vis. Comput. 25(10), 2007 (retraction, tangential cover).
//
// Extension with a point that is not adjacent to the end (including the same point) throws
// InvalidArgument: a DSS test only answers for paths.
#pragma once

#include <zdg/arith/digital_straight_line.hpp>
#include <zdg/arith/escalate.hpp>
#include <zdg/arith/integer.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <utility>

namespace zdg {

enum class Connectivity { four = 4, eight = 8 };

/// Characteristics in absolute coordinates, exact.
struct DssCharacteristics {
  BigInt a, b, mu, omega;
  friend bool operator==(const DssCharacteristics&, const DssCharacteristics&) = default;
};

template <TowerInt I>
class DssRecognizer {
public:
  using Point = Point2<I>;

  /// A segment of one point.
  explicit DssRecognizer(const Point& p, Connectivity c = Connectivity::eight)
      : conn_(c), origin_(p) {}

  /// Restarts from one point (same connectivity).
  void reset(const Point& p) { *this = DssRecognizer(p, conn_); }

  /// Adds p after the last point when the path stays a DSS (true); otherwise false and no
  /// change. p not adjacent to the last point: InvalidArgument.
  bool extend_front(const Point& p) {
    Point q = local(p);
    Step s = step_to(L_, q);
    return extend_front_step(s, q);
  }
  /// Adds p before the first point; same contract.
  bool extend_back(const Point& p) {
    Point q = local(p);
    Step s = step_to(F_, q);
    negate();
    bool ok = extend_front_step(s, q);
    negate();
    return ok;
  }
  /// Removes the last (first) point; false when only one point is left.
  bool retract_front() {
    if (n_ == 1) return false;
    negate();
    retract_back_impl();
    negate();
    return true;
  }
  bool retract_back() {
    if (n_ == 1) return false;
    retract_back_impl();
    return true;
  }

  std::size_t size() const { return n_; }
  Connectivity connectivity() const { return conn_; }
  Point front() const { return global(L_); }
  Point back() const { return global(F_); }
  /// First and last upper / lower leaning points (in the order of the path).
  Point first_upper() const { return global(Uf_); }
  Point last_upper() const { return global(Ul_); }
  Point first_lower() const { return global(Lf_); }
  Point last_lower() const { return global(Ll_); }

  /// Minimal characteristics (see the header comment).
  I a() const { return n_ == 1 ? I(0) : a_; }
  I b() const { return n_ == 1 ? I(1) : b_; }
  I omega() const { return n_ == 1 ? I(1) : I(hi_ - lo_ + 1); }
  I mu() const {
    if (n_ == 1) return -(origin_.y + F_.y);
    return lo_ + a_ * origin_.x - b_ * origin_.y;
  }
  /// The local origin (the first point the recognizer was built or reset with) and mu relative
  /// to it: mu = mu_local() + a ox - b oy, to be evaluated in a wide enough type.
  const Point& origin() const { return origin_; }
  I mu_local() const { return n_ == 1 ? I(-F_.y) : lo_; }
  /// The same, exact in BigInt (never overflows).
  DssCharacteristics characteristics() const {
    if (n_ == 1)
      return {BigInt(0), BigInt(1), BigInt(-(to_bigint(origin_.y) + to_bigint(F_.y))), BigInt(1)};
    BigInt A = to_bigint(a_), B = to_bigint(b_);
    return {A, B, BigInt(to_bigint(lo_) + A * to_bigint(origin_.x) - B * to_bigint(origin_.y)),
            to_bigint(I(hi_ - lo_ + 1))};
  }
  /// Remainder a x - b y of p for the current (a, b) in absolute coordinates.
  I remainder(const Point& p) const { return rem(local(p)) + a_ * origin_.x - b_ * origin_.y; }

private:
  Connectivity conn_;
  Point origin_;                                // absolute coordinates of the local origin
  Point F_{}, L_{}, Uf_{}, Ul_{}, Lf_{}, Ll_{}; // local coordinates
  I a_{0}, b_{0}, lo_{0}, hi_{0};               // lo = mu, hi = mu + omega - 1 (local)
  Step s1_{}, s2_{}, shift_{};                  // s1 = 0: one point; s2 = 0: one step so far
  I rF_{0}, rL_{0}, rs1_{0}, rs2_{0};           // remainders of F, L, s1, s2
  std::size_t n_ = 1;

  static int small(const I& v) {
    if constexpr (std::same_as<I, BigInt>) {
      return v.template convert_to<int>();
    } else {
      return static_cast<int>(v.value());
    }
  }
  Point local(const Point& p) const { return p - origin_; }
  Point global(const Point& p) const { return p + origin_; }
  I rem(const Point& p) const { return a_ * p.x - b_ * p.y; }
  I rem(Step s) const { return a_ * I(s.x) - b_ * I(s.y); }
  static Point plus(const Point& p, Step s) { return {p.x + s.x, p.y + s.y}; }
  I norm(const Point& v) const {
    I ax = abs(v.x), ay = abs(v.y);
    if (conn_ == Connectivity::eight) return ax > ay ? ax : ay;
    return ax + ay;
  }
  int norm(Step s) const {
    int ax = s.x < 0 ? -s.x : s.x, ay = s.y < 0 ? -s.y : s.y;
    return conn_ == Connectivity::eight ? (ax > ay ? ax : ay) : ax + ay;
  }
  // Two steps can alternate in a DSS when they differ by one step of the other adjacency.
  bool compatible(Step s, Step t) const {
    int dx = t.x - s.x, dy = t.y - s.y;
    int ax = dx < 0 ? -dx : dx, ay = dy < 0 ? -dy : dy;
    return conn_ == Connectivity::eight ? ax + ay == 1 : (ax > ay ? ax : ay) == 1;
  }

  Step step_to(const Point& from, const Point& to) const {
    I dx = to.x - from.x, dy = to.y - from.y;
    if (dx < -1 || dx > 1 || dy < -1 || dy > 1) throw_not_adjacent(from, to);
    Step s{small(dx), small(dy)};
    if (norm(s) != 1) throw_not_adjacent(from, to);
    return s;
  }
  [[noreturn]] void throw_not_adjacent(const Point& from, const Point& to) const {
    Point f = global(from), t = global(to);
    throw InvalidArgument("DSS recognition: point (" + to_string(t.x) + ", " + to_string(t.y) +
                          ") is not " + (conn_ == Connectivity::eight ? "8" : "4") +
                          "-adjacent to (" + to_string(f.x) + ", " + to_string(f.y) + ")");
  }

  // The segment read backwards: (a, b, mu) -> (-a, -b, -mu - omega + 1).
  void negate() {
    a_ = -a_;
    b_ = -b_;
    I lo = -hi_;
    hi_ = -lo_;
    lo_ = std::move(lo);
    std::swap(F_, L_);
    I rf = -rL_;
    rL_ = -rF_;
    rF_ = std::move(rf);
    std::swap(Uf_, Ll_);
    std::swap(Ul_, Lf_);
    s1_ = {-s1_.x, -s1_.y};
    s2_ = {-s2_.x, -s2_.y};
    shift_ = {-shift_.x, -shift_.y};
  }

  // After a change of (a, b) with the leaning points set: bounds, step remainders, shift.
  void update_parameters() {
    lo_ = rem(Uf_);
    hi_ = rem(Lf_);
    if (lo_ == hi_) { // one step left: the direction itself
      s1_ = {small(b_), small(a_)};
      s2_ = {};
      shift_ = {};
      rs1_ = 0;
      rs2_ = 0;
    } else {
      rs1_ = rem(s1_);
      rs2_ = rem(s2_);
      shift_ =
          rs1_ > rs2_ ? Step{s1_.x - s2_.x, s1_.y - s2_.y} : Step{s2_.x - s1_.x, s2_.y - s1_.y};
    }
    rF_ = rem(F_);
    rL_ = rem(L_);
  }

  bool extend_front_step(Step s, const Point& q) {
    if (n_ == 1) { // first step: the direction of the segment
      s1_ = s;
      a_ = s.y;
      b_ = s.x;
      lo_ = hi_ = rem(F_);
      rs1_ = 0;
      rF_ = rL_ = lo_;
      L_ = Ul_ = Ll_ = q;
      ++n_;
      return true;
    }
    if (s2_.x == 0 && s2_.y == 0) { // one step so far
      if (s == s1_) {
        L_ = Ul_ = Ll_ = q;
        ++n_;
        return true;
      }
      if (!compatible(s1_, s)) return false;
      I r = rL_ + rem(s);
      if (r < lo_) { // r = mu - 1: above
        a_ = q.y - Uf_.y;
        b_ = q.x - Uf_.x;
        Lf_ = Ll_;
        Ul_ = q;
      } else { // r = mu + omega: below
        a_ = q.y - Lf_.y;
        b_ = q.x - Lf_.x;
        Uf_ = Ul_;
        Ll_ = q;
      }
      s2_ = s;
      L_ = q;
      ++n_;
      update_parameters();
      return true;
    }
    I r;
    if (s == s1_) {
      r = rL_ + rs1_;
    } else if (s == s2_) {
      r = rL_ + rs2_;
    } else {
      return false;
    }
    if (r >= lo_ && r <= hi_) {
      if (r == lo_) Ul_ = q;
      if (r == hi_) Ll_ = q;
      L_ = q;
      rL_ = std::move(r);
      ++n_;
      return true;
    }
    if (r == lo_ - 1) { // weakly exterior above
      a_ = q.y - Uf_.y;
      b_ = q.x - Uf_.x;
      Ul_ = q;
      Lf_ = Ll_;
    } else if (r == hi_ + 1) { // weakly exterior below
      a_ = q.y - Lf_.y;
      b_ = q.x - Lf_.x;
      Ll_ = q;
      Uf_ = Ul_;
    } else {
      return false;
    }
    L_ = q;
    ++n_;
    update_parameters();
    return true;
  }

  void retract_back_impl() {
    // The point after F in the line.
    Point next;
    I rnext;
    if (s2_.x == 0 && s2_.y == 0) {
      next = plus(F_, s1_);
      rnext = rF_;
    } else {
      rnext = rF_ + rs1_;
      if (rnext >= lo_ && rnext <= hi_) {
        next = plus(F_, s1_);
      } else {
        next = plus(F_, s2_);
        rnext = rF_ + rs2_;
      }
    }
    if (n_ == 2) {
      Point keep = global(next);
      Connectivity c = conn_;
      // Keep the same origin so that local coordinates stay small.
      Point o = origin_;
      *this = DssRecognizer(o, c);
      F_ = L_ = Uf_ = Ul_ = Lf_ = Ll_ = local(keep);
      return;
    }
    if (s2_.x == 0 && s2_.y == 0) { // straight: every point is leaning on both sides
      F_ = Uf_ = Lf_ = next;
      --n_;
      return;
    }
    bool changed = false;
    const Point period{b_, a_};
    if (F_ == Uf_) {
      if (Lf_ == Ll_) {
        Point dir = Lf_ - plus(Uf_, shift_);
        I nd = norm(dir);
        Uf_ = Ul_ - dir * I(norm(Ul_ - next) / nd);
        Ll_ = Lf_ + dir * I(norm(L_ - Lf_) / nd);
        a_ = dir.y;
        b_ = dir.x;
        changed = true;
      } else {
        Uf_ += period;
      }
    } else if (F_ == Lf_) { // (F cannot be both when omega > 1)
      if (Uf_ == Ul_) {
        Point dir = Uf_ - (Lf_ - Point{I(shift_.x), I(shift_.y)});
        I nd = norm(dir);
        Lf_ = Ll_ - dir * I(norm(Ll_ - next) / nd);
        Ul_ = Uf_ + dir * I(norm(L_ - Uf_) / nd);
        a_ = dir.y;
        b_ = dir.x;
        changed = true;
      } else {
        Lf_ += period;
      }
    }
    F_ = next;
    --n_;
    if (changed) {
      update_parameters();
    } else {
      rF_ = std::move(rnext);
    }
  }
};

extern template class DssRecognizer<Int64>;
extern template class DssRecognizer<Int128>;
extern template class DssRecognizer<BigInt>;

/// Result of recognize_dss: whether the whole path is a DSS, how many first points are one,
/// and the minimal characteristics of that longest prefix.
struct DssRecognition {
  bool is_dss = false;
  std::size_t longest_prefix = 0;
  Connectivity connectivity = Connectivity::eight;
  DssCharacteristics characteristics;
};

/// 4 when every step of the path is an axis step, else 8; a step that is not 8-adjacent
/// (or a repeated point) throws InvalidArgument naming its index.
Connectivity path_connectivity(std::span<const Point2<std::int64_t>> path);
Connectivity path_connectivity(std::span<const Point2<BigInt>> path);

/// Recognizes the path (non-empty) with the given connectivity, computed on I (throws
/// OverflowError when I is too narrow).
template <TowerInt I>
DssRecognition recognize_dss(std::span<const Point2<I>> path, Connectivity c);
/// The same, exact by escalation (Int64 -> Int128 -> BigInt), with the type that served.
Escalated<DssRecognition> recognize_dss_exact(std::span<const Point2<std::int64_t>> path,
                                              Connectivity c);
Escalated<DssRecognition> recognize_dss_exact(std::span<const Point2<BigInt>> path, Connectivity c);

} // namespace zdg
