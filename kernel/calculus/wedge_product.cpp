#include <zdg/kernel/calculus/wedge_product.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/calculus/exterior_derivative.hpp>

#include <string>

namespace zdg {

std::vector<double> wedge_product(const SurfelComplex& c, std::span<const double> a,
                                  std::span<const double> b) {
  const auto ne = std::size_t(c.linel_count());
  if (a.size() != ne || b.size() != ne)
    throw InvalidArgument("wedge product: 1-forms of " + std::to_string(a.size()) + " and " +
                          std::to_string(b.size()) + " values for " + std::to_string(ne) +
                          " linels");
  std::vector<double> w(std::size_t(c.surfel_count()));
  for (std::int64_t s = 0; s < c.surfel_count(); ++s) {
    double as[4], bs[4];
    for (int i = 0; i < 4; ++i) {
      const auto e = std::size_t(c.surfel_linels[std::size_t(s)][std::size_t(i)]);
      const int sign = side_sign(c, s, i);
      as[i] = sign * a[e];
      bs[i] = sign * b[e];
    }
    const double au = (as[0] - as[2]) / 2, av = (as[1] - as[3]) / 2;
    const double bu = (bs[0] - bs[2]) / 2, bv = (bs[1] - bs[3]) / 2;
    w[std::size_t(s)] = au * bv - av * bu;
  }
  return w;
}

} // namespace zdg
