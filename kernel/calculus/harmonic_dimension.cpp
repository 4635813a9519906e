#include <zdg/kernel/calculus/harmonic_dimension.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/calculus/exterior_derivative.hpp>

#include <string>

namespace zdg {

namespace {

HarmonicDimension of_matrices(std::int64_t v, std::int64_t e, std::int64_t f,
                              const IncidenceMatrix& d0, const IncidenceMatrix& d1) {
  HarmonicDimension h;
  h.pointels = v;
  h.linels = e;
  h.surfels = f;
  h.d0 = exact_rank(d0);
  h.d1 = exact_rank(d1);
  h.dimension = e - h.d0.rank - h.d1.rank;
  return h;
}

} // namespace

HarmonicDimension harmonic_dimension(const SurfelComplex& c) {
  return of_matrices(c.pointel_count(), c.linel_count(), c.surfel_count(), primal_d0(c),
                     primal_d1(c));
}

std::vector<HarmonicDimension> harmonic_dimensions(const SurfelComplex& c,
                                                   std::span<const std::uint64_t> surface_of,
                                                   std::int64_t surfaces) {
  const auto nf = std::size_t(c.surfel_count());
  if (surface_of.size() != nf)
    throw InvalidArgument("harmonic dimensions: " + std::to_string(surface_of.size()) +
                          " labels for " + std::to_string(nf) + " surfels");
  if (surfaces < 0) throw InvalidArgument("harmonic dimensions: a negative number of surfaces");
  const auto ns = std::size_t(surfaces);
  constexpr std::int64_t none = -1;
  // Local indices of the cells of each surface.
  std::vector<std::int64_t> nv(ns, 0), ne(ns, 0), nfs(ns, 0);
  std::vector<std::int64_t> local_f(nf), local_e(std::size_t(c.linel_count()));
  std::vector<std::int64_t> local_v(std::size_t(c.pointel_count()), none);
  std::vector<std::int64_t> surface_v(std::size_t(c.pointel_count()), none);
  for (std::size_t s = 0; s < nf; ++s) {
    const auto l = surface_of[s];
    if (l >= ns)
      throw InvalidArgument("harmonic dimensions: surfel " + std::to_string(s) + " is on surface " +
                            std::to_string(l) + " of " + std::to_string(ns));
    local_f[s] = nfs[l]++;
    for (auto p : c.surfels[s]) {
      auto& sv = surface_v[std::size_t(p)];
      if (sv == none) {
        sv = std::int64_t(l);
        local_v[std::size_t(p)] = nv[l]++;
      } else if (sv != std::int64_t(l)) {
        throw InvalidArgument("harmonic dimensions: pointel " + std::to_string(p) +
                              " is on surfaces " + std::to_string(sv) + " and " +
                              std::to_string(l));
      }
    }
  }
  std::vector<std::vector<IntegerTriplet>> t0(ns), t1(ns);
  for (std::size_t e = 0; e < local_e.size(); ++e) {
    const auto& l = c.linels[e];
    const auto s = surface_of[std::size_t(l.face[0])];
    if (surface_of[std::size_t(l.face[1])] != s)
      throw InvalidArgument("harmonic dimensions: linel " + std::to_string(e) + " joins surfaces " +
                            std::to_string(s) + " and " +
                            std::to_string(surface_of[std::size_t(l.face[1])]));
    local_e[e] = ne[s]++;
    t0[s].push_back({local_e[e], local_v[std::size_t(l.a)], -1});
    t0[s].push_back({local_e[e], local_v[std::size_t(l.b)], 1});
  }
  for (std::size_t f = 0; f < nf; ++f)
    for (int i = 0; i < 4; ++i)
      t1[surface_of[f]].push_back({local_f[f],
                                   local_e[std::size_t(c.surfel_linels[f][std::size_t(i)])],
                                   side_sign(c, std::int64_t(f), i)});
  std::vector<HarmonicDimension> out;
  out.reserve(ns);
  for (std::size_t s = 0; s < ns; ++s) {
    const auto d0 = IncidenceMatrix::from_triplets(ne[s], nv[s], std::move(t0[s]));
    const auto d1 = IncidenceMatrix::from_triplets(nfs[s], ne[s], std::move(t1[s]));
    out.push_back(of_matrices(nv[s], ne[s], nfs[s], d0, d1));
  }
  return out;
}

} // namespace zdg
