#include <zdg/kernel/calculus/exterior_derivative.hpp>

#include <zdg/arith/error.hpp>

#include <string>
#include <vector>

namespace zdg {

int side_sign(const SurfelComplex& c, std::int64_t s, int i) {
  const auto& q = c.surfels[std::size_t(s)];
  const auto p0 = q[std::size_t(i)], p1 = q[std::size_t((i + 1) % 4)];
  const auto& e = c.linels[std::size_t(c.surfel_linels[std::size_t(s)][std::size_t(i)])];
  if (e.a == p0 && e.b == p1) return 1;
  if (e.a == p1 && e.b == p0) return -1;
  throw InvalidArgument("surfel complex: side " + std::to_string(i) + " of surfel " +
                        std::to_string(s) + " is not its linel");
}

IncidenceMatrix primal_d0(const SurfelComplex& c) {
  std::vector<IntegerTriplet> t;
  t.reserve(2 * c.linels.size());
  for (std::size_t e = 0; e < c.linels.size(); ++e) {
    t.push_back({std::int64_t(e), c.linels[e].a, -1});
    t.push_back({std::int64_t(e), c.linels[e].b, 1});
  }
  return IncidenceMatrix::from_triplets(c.linel_count(), c.pointel_count(), std::move(t));
}

IncidenceMatrix primal_d1(const SurfelComplex& c) {
  std::vector<IntegerTriplet> t;
  t.reserve(4 * c.surfels.size());
  for (std::int64_t s = 0; s < c.surfel_count(); ++s)
    for (int i = 0; i < 4; ++i)
      t.push_back({s, c.surfel_linels[std::size_t(s)][std::size_t(i)], side_sign(c, s, i)});
  return IncidenceMatrix::from_triplets(c.surfel_count(), c.linel_count(), std::move(t));
}

IncidenceMatrix dual_d0(const SurfelComplex& c) {
  return primal_d1(c).transpose();
}

IncidenceMatrix dual_d1(const SurfelComplex& c) {
  return primal_d0(c).transpose().negated();
}

} // namespace zdg
