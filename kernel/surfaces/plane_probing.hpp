// Plane-probing normal estimation: the H- and R-algorithms on a digital plane.
//
//   Given a predicate InPlane(x) on Z^3 and a starting point o, a plane-probing algorithm
//   deforms a tetrahedron (q - m_0, q - m_1, q - m_2; q), q = o + m_0 + m_1 + m_2, whose base
//   triangle is in the set and whose apex q is not, asking InPlane as locally as possible,
//   until one face is parallel to the set; its normal (m_1 - m_0) x (m_2 - m_0) is the
//   estimate. On the standard plane P(N) = {x : 0 <= N . x < ||N||_1} of a primitive N with
//   positive components, started at o = 0 with m = (e_x, e_y, e_z), both algorithms return N
//   exactly, the R-algorithm with a reduced basis of the plane's lattice (Lachaud, Provencal,
//   Roussillon, "Two plane-probing algorithms for the computation of the normal vector to a
//   digital plane", JMIV 59, 2017; Lachaud, Meyron, Roussillon, "An optimized framework for
//   plane-probing algorithms", JMIV 62, 2020).
//
// One step: the candidates are the points q - m_s0 + m_s1 + lambda m_s2 for the six
//   permutations s of (0, 1, 2): lambda = 0 only (H: a hexagon around q), or for the
//   R-algorithm the point of each ray {lambda >= 0} that is in the set and closest in the
//   sense below (found by an exponential then a quaternary search along the ray, the R1
//   optimisation of JMIV 2020). When the in-set hexagon points are one, or two or three that
//   are neither opposite nor separated by exactly one out-of-set point ("planar" state), the
//   closest candidate x replaces the vertex q - m_s0 (m_s0 <- m_s0 - m_s1 - lambda m_s2);
//   otherwise (no candidate, or a "non-convex"/"non-planar" hexagon) the algorithm stops.
//   Closest: x beats y unless y lies strictly inside the sphere through the triangle and x
//   (an exact 5 x 5 in-sphere determinant, oriented by the 4 x 4 orientation determinant);
//   on the sphere the lexicographically smaller relative point wins (the tie rule of
//   DGtal's PlaneProbingNeighborhood, so step counts compare with DGtal's).
//
// Complexity: each step lowers sum_k N.m_k (from ||N||_1, staying >= 3) by at least 1, so
//   H makes at most ||N||_1 - 3 steps of 6 predicate calls; R makes O(log) calls per ray and
//   far fewer steps on typical normals (about 200 for random 70-bit components, 575 for
//   140-bit ones), but not logarithmically many in general: (2^35 + 1, -(2^35/3 + 7), 12345)
//   takes 9.3e5 steps, and normals close to a multiple of a small vector, such as
//   (2^64 + 1, 2^64 + 3, 2^65 + 1), take minutes (measured). Each step is O(1) exact
//   arithmetic.
// Width: the in-sphere determinant is of degree 5 in the frame's coordinates, which are at
//   most ||N||_1 (H can build long frames) and near sqrt(||N||) for the reduced frames of R:
//   Int64 serves ||N||_1 < 2^11 for sure and R on random normals up to about 2^25, Int128 up
//   to about 2^50 (measured: 70-bit normals already need Int128). probe_standard_plane<I>
//   throws OverflowError past I; probe_standard_plane_exact escalates Int64 -> Int128 ->
//   BigInt.
// Input (probe_standard_plane): a primitive normal with three nonzero components of any
//   signs (the octant is brought to the positive one by reflecting the axes, and the result
//   reflected back); InvalidArgument otherwise, or when max_steps steps do not end it.
//
// General form (probe_plane): any predicate in_set(x) on Z^3, a starting point o and an
//   initial frame (m_0, m_1, m_2) with det = +-1; the apex is q = o + m_0 + m_1 + m_2, the base
//   triangle q - m_k must be in the set and q not (checked at entry: InvalidArgument). The
//   updates m_s0 <- m_s0 - m_s1 - lambda m_s2 keep det(m) and the invariant (base in, apex
//   out). The returned normal is det(m) (m_1 - m_0) x (m_2 - m_0): its dot product with every
//   m_k is 1, so it points from the base triangle to the apex (out of the set).
//   probe_standard_plane is probe_plane on {0 <= |N| . x < ||N||_1} from o = 0 and the unit
//   frame, reflected back. On a digital half-space {x : N . x < c} (N primitive, nonzero
//   components), or on its inner 26-boundary {c - ||N||_1 <= N . x < c}, from an apex q on the
//   first outside layer (N . q = c) and m_k = sign(N_k) e_k, the run is the run on the standard
//   plane of normal N from its lowest layer (every probed point lies above the lowest base
//   vertex, where the lower bound is never reached), so it returns N. From an apex higher up
//   (c < N . q < c + min |N_k|, still a valid tetrahedron) it need not: N = (14, 14, 15),
//   N . q = c + 1 gives (1, 1, 1). The predicate is called O(steps) times (H: 6 per step; R: O(log)
//   per ray).
#pragma once

#include <zdg/arith/error.hpp>
#include <zdg/arith/escalate.hpp>
#include <zdg/arith/integer.hpp>
#include <zdg/arith/point.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

namespace zdg {

enum class ProbingAlgorithm { h, r };

/// The default step budget of every front end (command line, `zdg serve`, Python): about a
/// second of work at most on the widest normals measured (see above).
inline constexpr std::uint64_t kPlaneProbingMaxSteps = 1'000'000;

constexpr std::string_view to_string(ProbingAlgorithm a) {
  return a == ProbingAlgorithm::h ? "h" : "r";
}

template <TowerInt I>
struct PlaneProbingResult {
  Point3<I> normal{};               // (m_1 - m_0) x (m_2 - m_0) at the end
  std::array<Point3<I>, 3> frame{}; // m_0, m_1, m_2 at the end
  Point3<I> apex{};                 // q
  std::uint64_t steps = 0;          // tetrahedron updates
  std::uint64_t predicate_calls = 0;
  bool reduced_basis = false; // the two shortest of m_1 - m_0, m_2 - m_1, m_0 - m_2 are
                              // Lagrange-Gauss reduced
};

namespace detail::plane_probing {

// The six rays of the hexagon around q, in cyclic order: (s0, s1, s2) is the point
// q - m_s0 + m_s1 + lambda m_s2.
inline constexpr std::array<std::array<int, 3>, 6> kRays = {{
    {0, 1, 2},
    {0, 2, 1},
    {1, 2, 0},
    {1, 0, 2},
    {2, 0, 1},
    {2, 1, 0},
}};

template <TowerInt I>
I squared_norm(const Point3<I>& p) {
  return dot(p, p);
}

template <TowerInt I>
I det3(const Point3<I>& a, const Point3<I>& b, const Point3<I>& c) {
  return dot(a, cross(b, c));
}

// Orientation of (a, b, c, d): det [[a 1] [b 1] [c 1] [d 1]] = -det3(b - a, c - a, d - a).
template <TowerInt I>
I orient4(const Point3<I>& a, const Point3<I>& b, const Point3<I>& c, const Point3<I>& d) {
  return -det3(b - a, c - a, d - a);
}

// det of the 5 x 5 matrix of rows (p, |p|^2, 1), by translating to e (row of e becomes
// (0, 0, 0, 0, 1)) and expanding: det4 of rows (p - e, |p - e|^2) for p = a, b, c, d, up to
// the sign of the expansion, which is +1 for the last row and column.
template <TowerInt I>
I insphere5(const std::array<Point3<I>, 5>& p) {
  std::array<Point3<I>, 4> t;
  std::array<I, 4> w;
  for (int i = 0; i < 4; ++i) {
    t[i] = p[i] - p[4];
    w[i] = squared_norm(t[i]);
  }
  // det4 of rows (t_i, w_i), expansion along the last column.
  I det{0};
  for (int i = 0; i < 4; ++i) {
    std::array<Point3<I>, 3> r;
    int k = 0;
    for (int j = 0; j < 4; ++j) {
      if (j != i) r[k++] = t[j];
    }
    I minor = det3(r[0], r[1], r[2]);
    // cofactor sign of entry (i, 3): (-1)^(i + 3)
    if ((i + 3) % 2 == 0) {
      det += w[i] * minor;
    } else {
      det -= w[i] * minor;
    }
  }
  return det;
}

template <TowerInt I>
int sign_of(const I& v) {
  return v > I(0) ? 1 : (v < I(0) ? -1 : 0);
}

template <TowerInt I, class InSet>
class Prober {
public:
  Prober(InSet& in_set, const Point3<I>& origin, const std::array<Point3<I>, 3>& frame,
         ProbingAlgorithm alg)
      : in_set_(in_set), alg_(alg), m_(frame), q_(origin + frame[0] + frame[1] + frame[2]) {}

  // note: what the message adds about the steps the input needs.
  PlaneProbingResult<I> run(std::uint64_t max_steps, const std::string& note = "") {
    PlaneProbingResult<I> res;
    while (step()) {
      if (++res.steps > max_steps) {
        throw InvalidArgument("plane probing: not ended after " + std::to_string(max_steps) +
                              " steps" + note + " (raise max_steps, --max-steps)");
      }
    }
    res.frame = m_;
    res.apex = q_;
    res.normal = cross(m_[1] - m_[0], m_[2] - m_[0]);
    if (det3(m_[0], m_[1], m_[2]) < I(0)) res.normal = -res.normal;
    res.predicate_calls = calls_;
    res.reduced_basis = reduced();
    return res;
  }

private:
  bool in_plane(const Point3<I>& x) {
    ++calls_;
    return static_cast<bool>(in_set_(x));
  }

  Point3<I> relative(const std::array<int, 3>& s, const I& lambda) const {
    return m_[s[1]] - m_[s[0]] + lambda * m_[s[2]];
  }

  bool on_plane_at(const std::array<int, 3>& s, const I& lambda) {
    return in_plane(q_ + relative(s, lambda));
  }

  // True when y beats x: y strictly inside the sphere through the triangle and x, or on it
  // and lexicographically smaller (relative points).
  bool beaten_by(const Point3<I>& x, const Point3<I>& y) const {
    const Point3<I> a = -m_[0], b = -m_[1], c = -m_[2];
    I o = orient4(a, b, c, x);
    if (o == I(0)) throw Error("plane probing: internal error, a flat tetrahedron");
    I s = insphere5<I>({a, b, c, x, y});
    if (s == I(0)) {
      if (y.x != x.x) return y.x < x.x;
      if (y.y != x.y) return y.y < x.y;
      return y.z < x.z;
    }
    return sign_of(s) * sign_of(o) > 0;
  }

  // The closest in-plane point on ray s, whose base (lambda = 0) is in the plane.
  I closest_on_ray(const std::array<int, 3>& s) {
    auto beats = [&](const I& from, const I& to) {
      return beaten_by(relative(s, from), relative(s, to));
    };
    I k{0}, l{1};
    while (on_plane_at(s, k) && beats(k, l)) {
      I d = l - k;
      k = l;
      l = l + I(2) * d;
    }
    k = k - (l - k) / I(2);
    I d = l - k;
    while (d > I(4)) {
      I alpha = k + d / I(4), beta = k + d / I(2), gamma = k + (I(3) * d) / I(4);
      if (on_plane_at(s, beta) && beats(beta, gamma)) {
        k = beta;
      } else if (!on_plane_at(s, alpha) || beats(beta, alpha)) {
        l = beta;
      } else {
        k = alpha;
        l = gamma;
      }
      d = l - k;
    }
    I prev = k, cur = k + I(1);
    while (on_plane_at(s, cur) && beats(prev, cur)) {
      prev = cur;
      cur = prev + I(1);
    }
    return prev;
  }

  bool step() {
    std::array<bool, 6> state{};
    int inside = 0;
    for (int i = 0; i < 6; ++i) {
      state[i] = on_plane_at(kRays[i], I(0));
      inside += state[i] ? 1 : 0;
    }
    if (!planar(state, inside)) return false;
    std::optional<std::pair<int, I>> best;
    for (int i = 0; i < 6; ++i) {
      if (!state[i]) continue;
      I lambda = alg_ == ProbingAlgorithm::r ? closest_on_ray(kRays[i]) : I(0);
      if (!best ||
          beaten_by(relative(kRays[best->first], best->second), relative(kRays[i], lambda))) {
        best = std::pair<int, I>{i, lambda};
      }
    }
    const auto& s = kRays[best->first];
    m_[s[0]] = m_[s[0]] - m_[s[1]] - best->second * m_[s[2]];
    return true;
  }

  // DGtal's hexagon classification (JMIV 2017, Sect. 4): one in-set point, or two or three
  // with no opposite pair and no in-out-in pattern, is planar.
  static bool planar(const std::array<bool, 6>& st, int inside) {
    if (inside == 0 || inside > 3) return false;
    if (inside == 1) return true;
    for (int i = 0; i < 3; ++i) {
      if (st[i] && st[i + 3]) return false;
    }
    for (int i = 0; i < 6; ++i) {
      if (st[i] && !st[(i + 1) % 6] && st[(i + 2) % 6]) return false;
    }
    return true;
  }

  bool reduced() const {
    std::array<Point3<I>, 3> e = {m_[1] - m_[0], m_[2] - m_[1], m_[0] - m_[2]};
    // The two shortest edges.
    std::array<int, 3> idx = {0, 1, 2};
    for (int i = 0; i < 3; ++i) {
      for (int j = i + 1; j < 3; ++j) {
        if (squared_norm(e[idx[j]]) < squared_norm(e[idx[i]])) std::swap(idx[i], idx[j]);
      }
    }
    const auto &u = e[idx[0]], &v = e[idx[1]];
    I nu = squared_norm(u), nv = squared_norm(v), np = squared_norm(u + v),
      nm = squared_norm(u - v);
    return nu <= np && nu <= nm && nv <= np && nv <= nm;
  }

  InSet& in_set_;
  ProbingAlgorithm alg_;
  std::array<Point3<I>, 3> m_;
  Point3<I> q_;
  std::uint64_t calls_ = 0;
};

} // namespace detail::plane_probing

/// Probes the set {x : in_set(x)} from the tetrahedron (q - m_0, q - m_1, q - m_2; q),
/// q = origin + m_0 + m_1 + m_2 (see above), computed on I. Throws InvalidArgument when the
/// frame is not unimodular, the base triangle is not in the set, the apex is, or max_steps
/// steps do not end it; OverflowError past I.
template <TowerInt I, class InSet>
PlaneProbingResult<I> probe_plane(InSet&& in_set, const Point3<I>& origin,
                                  const std::array<Point3<I>, 3>& frame, ProbingAlgorithm algorithm,
                                  std::uint64_t max_steps = kPlaneProbingMaxSteps,
                                  const std::string& note = "") {
  const I d = detail::plane_probing::det3(frame[0], frame[1], frame[2]);
  if (d != I(1) && d != I(-1)) {
    throw InvalidArgument("plane probing: the initial frame has determinant " + to_string(d) +
                          " (it must be +1 or -1)");
  }
  const Point3<I> q = origin + frame[0] + frame[1] + frame[2];
  if (static_cast<bool>(in_set(q))) {
    throw InvalidArgument("plane probing: the apex of the initial tetrahedron is in the set");
  }
  for (const auto& m : frame) {
    if (!static_cast<bool>(in_set(q - m))) {
      throw InvalidArgument(
          "plane probing: a vertex of the initial base triangle is not in the set");
    }
  }
  detail::plane_probing::Prober<I, std::remove_reference_t<InSet>> prober(in_set, origin, frame,
                                                                          algorithm);
  return prober.run(max_steps, note);
}

/// Probes the standard plane {x : 0 <= N . x < ||N||_1} from the origin (computed on I).
/// The run ends within ||N||_1 - 3 steps (the proven bound); when that bound exceeds
/// max_steps, the H-algorithm, which takes a sizeable fraction of it (7% to 100% of ||N||_1 on
/// the normals measured), is refused before any work, and the R-algorithm runs until it ends or
/// max_steps steps are done (InvalidArgument naming the proven bound).
template <TowerInt I>
PlaneProbingResult<I> probe_standard_plane(const Point3<I>& normal, ProbingAlgorithm algorithm,
                                           std::uint64_t max_steps = kPlaneProbingMaxSteps);

/// The same for normals of any size, exact by escalation (results as BigInt).
template <TowerInt I>
Escalated<PlaneProbingResult<BigInt>>
probe_standard_plane_exact(const Point3<I>& normal, ProbingAlgorithm algorithm,
                           std::uint64_t max_steps = kPlaneProbingMaxSteps);

} // namespace zdg
