#include <zdg/kernel/calculus/sharp_flat.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/calculus/exterior_derivative.hpp>

#include <cmath>
#include <string>

namespace zdg {

std::vector<double> flat(const SurfelComplex& c, std::span<const Point3<double>> field) {
  if (field.size() != std::size_t(c.surfel_count()))
    throw InvalidArgument("flat: " + std::to_string(field.size()) + " vectors for " +
                          std::to_string(c.surfel_count()) + " surfels");
  std::vector<double> w(std::size_t(c.linel_count()));
  for (std::size_t e = 0; e < w.size(); ++e) {
    const auto& l = c.linels[e];
    const auto d = c.pointels[std::size_t(l.b)] - c.pointels[std::size_t(l.a)];
    const auto m = 0.5 * (field[std::size_t(l.face[0])] + field[std::size_t(l.face[1])]);
    w[e] = dot(m, d);
  }
  return w;
}

std::vector<Point3<double>> sharp(const SurfelComplex& c, std::span<const double> form,
                                  std::span<const Point3<double>> normals) {
  const auto nf = std::size_t(c.surfel_count());
  if (form.size() != std::size_t(c.linel_count()))
    throw InvalidArgument("sharp: a 1-form of " + std::to_string(form.size()) + " values for " +
                          std::to_string(c.linel_count()) + " linels");
  if (!normals.empty() && normals.size() != nf)
    throw InvalidArgument("sharp: " + std::to_string(normals.size()) + " normals for " +
                          std::to_string(nf) + " surfels");
  std::vector<Point3<double>> out(nf);
  for (std::size_t s = 0; s < nf; ++s) {
    double a[4];
    for (int i = 0; i < 4; ++i)
      a[i] =
          side_sign(c, std::int64_t(s), i) * form[std::size_t(c.surfel_linels[s][std::size_t(i)])];
    const double au = (a[0] - a[2]) / 2, av = (a[1] - a[3]) / 2;
    const auto& q = c.surfels[s];
    const auto u = c.pointels[std::size_t(q[1])] - c.pointels[std::size_t(q[0])];
    const auto v = c.pointels[std::size_t(q[3])] - c.pointels[std::size_t(q[0])];
    const auto n = normals.empty() ? c.normals[s] : normals[s];
    // Rows u, v, n; V = (au (v x n) + av (n x u)) / det, det = u . (v x n).
    const auto vn = cross(v, n), nu = cross(n, u);
    const double det = dot(u, vn);
    if (det == 0 || !std::isfinite(det))
      throw InvalidArgument("sharp: the normal of surfel " + std::to_string(s) +
                            " lies in its plane");
    out[s] = (1 / det) * (au * vn + av * nu);
  }
  return out;
}

} // namespace zdg
