#include <zdg/arith/error.hpp>
#include <zdg/kernel/surfaces/plane_probing.hpp>

#include <array>
#include <string>

namespace zdg {

namespace {

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
  const I omega = n.x + n.y + n.z;
  auto in_plane = [&](const Point3<I>& x) {
    I h = dot(n, x);
    return I(0) <= h && h < omega;
  };
  const std::array<Point3<I>, 3> unit = {Point3<I>{I(1), I(0), I(0)}, Point3<I>{I(0), I(1), I(0)},
                                         Point3<I>{I(0), I(0), I(1)}};
  // Each step lowers sum_k N . m_k from ||N||_1 and keeps it >= 3 (see the header).
  const BigInt bound = int_cast<BigInt>(omega) - 3;
  const std::string note =
      " (the proven bound for this normal is ||N||_1 - 3 = " + bound.str().substr(0, 60) +
      " steps)";
  if (algorithm == ProbingAlgorithm::h && bound > BigInt(max_steps)) {
    throw InvalidArgument(
        "plane probing: the H-algorithm needs up to ||N||_1 - 3 = " + bound.str().substr(0, 60) +
        " steps on this normal, more than max_steps " + std::to_string(max_steps) +
        " (use the R-algorithm, or raise max_steps, --max-steps)");
  }
  auto r = probe_plane<I>(in_plane, Point3<I>{I(0), I(0), I(0)}, unit, algorithm, max_steps,
                          bound > BigInt(max_steps) ? note : std::string());
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
