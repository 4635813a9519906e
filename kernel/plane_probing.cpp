#include <zdg/arith/error.hpp>
#include <zdg/kernel/plane_probing.hpp>

#include <array>
#include <optional>
#include <string>

namespace zdg {

namespace {

// The six rays of the hexagon around q, in cyclic order: (s0, s1, s2) is the point
// q - m_s0 + m_s1 + lambda m_s2.
constexpr std::array<std::array<int, 3>, 6> kRays = {{
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

template <TowerInt I>
class Prober {
public:
  Prober(const Point3<I>& n, ProbingAlgorithm alg) : n_(n), omega_(n.x + n.y + n.z), alg_(alg) {
    m_ = {Point3<I>{I(1), I(0), I(0)}, Point3<I>{I(0), I(1), I(0)}, Point3<I>{I(0), I(0), I(1)}};
    q_ = m_[0] + m_[1] + m_[2];
  }

  PlaneProbingResult<I> run(std::uint64_t max_steps) {
    PlaneProbingResult<I> res;
    while (step()) {
      if (++res.steps > max_steps) {
        throw InvalidArgument("plane probing: not ended after " + std::to_string(max_steps) +
                              " steps (raise --max-steps)");
      }
    }
    res.frame = m_;
    res.apex = q_;
    res.normal = cross(m_[1] - m_[0], m_[2] - m_[0]);
    res.predicate_calls = calls_;
    res.reduced_basis = reduced();
    return res;
  }

private:
  bool in_plane(const Point3<I>& x) {
    ++calls_;
    I h = dot(n_, x);
    return I(0) <= h && h < omega_;
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

  Point3<I> n_;
  I omega_;
  ProbingAlgorithm alg_;
  std::array<Point3<I>, 3> m_;
  Point3<I> q_;
  std::uint64_t calls_ = 0;
};

template <TowerInt I>
I reflect(const I& v, const I& s) {
  return s < I(0) ? -v : v;
}

template <TowerInt I>
Point3<I> reflect(const Point3<I>& p, const Point3<I>& s) {
  return {reflect(p.x, s.x), reflect(p.y, s.y), reflect(p.z, s.z)};
}

} // namespace

template <TowerInt I>
PlaneProbingResult<I> probe_standard_plane(const Point3<I>& normal, ProbingAlgorithm algorithm,
                                           std::uint64_t max_steps) {
  if (normal.x == I(0) || normal.y == I(0) || normal.z == I(0)) {
    throw InvalidArgument("plane probing: the normal needs three nonzero components (got " +
                          to_string(normal.x) + " " + to_string(normal.y) + " " +
                          to_string(normal.z) + ")");
  }
  if (gcd(gcd(normal.x, normal.y), normal.z) != I(1)) {
    throw InvalidArgument("plane probing: the normal " + to_string(normal.x) + " " +
                          to_string(normal.y) + " " + to_string(normal.z) +
                          " is not primitive (its components have a common divisor)");
  }
  const Point3<I> s = normal; // the signs of the octant
  const Point3<I> n{abs(normal.x), abs(normal.y), abs(normal.z)};
  Prober<I> prober(n, algorithm);
  auto r = prober.run(max_steps);
  r.normal = reflect(r.normal, s);
  for (auto& m : r.frame) m = reflect(m, s);
  r.apex = reflect(r.apex, s);
  return r;
}

template <TowerInt I>
Escalated<PlaneProbingResult<BigInt>> probe_standard_plane_exact(const Point3<I>& normal,
                                                                 ProbingAlgorithm algorithm,
                                                                 std::uint64_t max_steps) {
  return escalate([&]<class J>(std::type_identity<J>) {
    Point3<J> n{int_cast<J>(normal.x), int_cast<J>(normal.y), int_cast<J>(normal.z)};
    auto r = probe_standard_plane<J>(n, algorithm, max_steps);
    auto big = [](const Point3<J>& p) {
      return Point3<BigInt>{to_bigint(p.x), to_bigint(p.y), to_bigint(p.z)};
    };
    PlaneProbingResult<BigInt> out;
    out.normal = big(r.normal);
    for (int i = 0; i < 3; ++i) out.frame[i] = big(r.frame[i]);
    out.apex = big(r.apex);
    out.steps = r.steps;
    out.predicate_calls = r.predicate_calls;
    out.reduced_basis = r.reduced_basis;
    return out;
  });
}

#define ZDG_INSTANTIATE(I)                                                                         \
  template PlaneProbingResult<I> probe_standard_plane<I>(const Point3<I>&, ProbingAlgorithm,       \
                                                         std::uint64_t);                           \
  template Escalated<PlaneProbingResult<BigInt>> probe_standard_plane_exact<I>(                    \
      const Point3<I>&, ProbingAlgorithm, std::uint64_t);
ZDG_INSTANTIATE(Int64)
ZDG_INSTANTIATE(Int128)
ZDG_INSTANTIATE(BigInt)
#undef ZDG_INSTANTIATE

} // namespace zdg
