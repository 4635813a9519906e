// Digital Voronoi covariance measure normals (see the header).
#include <zdg/arith/error.hpp>
#include <zdg/estimators/vcm_normal.hpp>
#include <zdg/kernel/images/image.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>
#include <zdg/kernel/transforms/distance_transform.hpp>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>

namespace zdg {

namespace {

using P3 = Point3<double>;

std::int64_t checked_ratio2(double radius, double h, const char* name, double scale) {
  if (!(radius > 0) || !std::isfinite(radius) || !(radius / h <= 256)) {
    std::ostringstream msg;
    msg << "VCM normals: the radius " << name << " = " << radius
        << " must be positive and at most 256 h (h = " << h << ")";
    throw InvalidArgument(msg.str());
  }
  return static_cast<std::int64_t>(std::floor(scale * (radius / h) * (radius / h)));
}

} // namespace

std::vector<P3> vcm_normals(std::span<const Surfel> surfels, double h, double R, double r,
                            unsigned threads) {
  if (!(h > 0) || !std::isfinite(h)) {
    std::ostringstream msg;
    msg << "VCM normals: the grid step h = " << h << " must be positive";
    throw InvalidArgument(msg.str());
  }
  if (surfels.empty()) throw InvalidArgument("VCM normals: no surfel");
  const std::int64_t R2 = checked_ratio2(R, h, "R", 1.0);
  const std::int64_t r2x4 = checked_ratio2(r, h, "r", 4.0); // doubled coordinates
  const auto Rv = static_cast<std::int64_t>(std::ceil(R / h));
  const auto rv = static_cast<std::int64_t>(std::ceil(r / h));
  const unsigned nthreads = threads;

  // K: the pointels, as lattice points q = k / 2 (k the even Khalimsky point).
  std::vector<KPoint> K;
  K.reserve(surfels.size() * 4);
  for (const auto& s : surfels)
    for (const auto& k : surfel_pointels(s)) K.push_back({k.x / 2, k.y / 2, k.z / 2});
  std::sort(K.begin(), K.end());
  K.erase(std::unique(K.begin(), K.end()), K.end());

  KPoint lo = K.front(), hi = K.front();
  for (const auto& q : K) {
    lo = {std::min(lo.x, q.x), std::min(lo.y, q.y), std::min(lo.z, q.z)};
    hi = {std::max(hi.x, q.x), std::max(hi.y, q.y), std::max(hi.z, q.z)};
  }
  const std::int64_t grow = Rv + 1;
  lo = {lo.x - grow, lo.y - grow, lo.z - grow};
  hi = {hi.x + grow, hi.y + grow, hi.z + grow};
  const std::int64_t nx = hi.x - lo.x + 1, ny = hi.y - lo.y + 1, nz = hi.z - lo.z + 1;
  const Domain dom({nx, ny, nz}, {lo.x, lo.y, lo.z});
  auto index = [&](const KPoint& q) {
    return ((q.x - lo.x) * ny + (q.y - lo.y)) * nz + (q.z - lo.z);
  };

  TransformOptions opt;
  opt.metric = Metric::l2();
  opt.threads = nthreads;
  if (distance_transform_max_value(dom, opt) > BigInt(std::numeric_limits<std::uint32_t>::max())) {
    throw InvalidArgument("VCM normals: the surface's box (" + std::to_string(nx) + " x " +
                          std::to_string(ny) + " x " + std::to_string(nz) +
                          ") is too large for 32-bit squared distances");
  }
  std::vector<std::int32_t> id(std::size_t(dom.size()), -1);
  Image<std::uint8_t> img(dom, std::uint8_t{1});
  for (std::size_t i = 0; i < K.size(); ++i) {
    img[index(K[i])] = 0;
    id[std::size_t(index(K[i]))] = std::int32_t(i);
  }
  const Image<std::uint32_t> dt = distance_transform<std::uint32_t>(img, opt);

  // Offsets of the R-ball (the R-offset is the union of these balls around K).
  std::vector<std::array<std::int64_t, 4>> offsets; // o, |o|^2
  for (std::int64_t a = -Rv; a <= Rv; ++a)
    for (std::int64_t b = -Rv; b <= Rv; ++b)
      for (std::int64_t c = -Rv; c <= Rv; ++c)
        if (const auto n2 = a * a + b * b + c * c; n2 > 0 && n2 <= R2)
          offsets.push_back({a, b, c, n2});
  const std::int64_t dstride = ny * nz;

  // Number of nearest points of K of every lattice point of the offset.
  std::vector<std::uint32_t> m(std::size_t(dom.size()), 0);
  for (const auto& q : K) {
    const std::int64_t base = index(q);
    for (const auto& o : offsets) {
      const std::int64_t x = base + o[0] * dstride + o[1] * nz + o[2];
      if (std::int64_t(dt[x]) == o[3]) ++m[std::size_t(x)];
    }
  }
  // Cell matrices (xx, yy, zz, xy, xz, yz) in voxel units.
  std::vector<std::array<double, 6>> cell(K.size());
  parallel_chunks(std::int64_t(K.size()), nthreads, [&](std::int64_t b, std::int64_t e) {
    for (auto i = std::size_t(b); i < std::size_t(e); ++i) {
      const std::int64_t base = index(K[i]);
      std::array<double, 6> acc{};
      for (const auto& o : offsets) {
        const std::int64_t x = base + o[0] * dstride + o[1] * nz + o[2];
        if (std::int64_t(dt[x]) != o[3]) continue;
        const double w = 1.0 / double(m[std::size_t(x)]);
        const double ox = double(o[0]), oy = double(o[1]), oz = double(o[2]);
        acc[0] += w * ox * ox;
        acc[1] += w * oy * oy;
        acc[2] += w * oz * oz;
        acc[3] += w * ox * oy;
        acc[4] += w * ox * oz;
        acc[5] += w * oy * oz;
      }
      cell[i] = acc;
    }
  });

  // Per surfel: the cells of the points of K within r of its centre (doubled coordinates:
  // the centre is k_s, the point q is 2 q).
  std::vector<P3> out(surfels.size());
  parallel_chunks(std::int64_t(surfels.size()), nthreads, [&](std::int64_t b, std::int64_t e) {
    for (auto f = std::size_t(b); f < std::size_t(e); ++f) {
      const KPoint ks = surfels[f].k;
      std::array<double, 6> v{};
      const KPoint c{ks.x >> 1, ks.y >> 1, ks.z >> 1}; // floor(k / 2)
      for (std::int64_t x = std::max(c.x - rv - 1, lo.x); x <= std::min(c.x + rv + 1, hi.x); ++x)
        for (std::int64_t y = std::max(c.y - rv - 1, lo.y); y <= std::min(c.y + rv + 1, hi.y); ++y)
          for (std::int64_t z = std::max(c.z - rv - 1, lo.z); z <= std::min(c.z + rv + 1, hi.z);
               ++z) {
            const std::int64_t dx = 2 * x - ks.x, dy = 2 * y - ks.y, dz = 2 * z - ks.z;
            if (dx * dx + dy * dy + dz * dz > r2x4) continue;
            const std::int32_t i = id[std::size_t(index({x, y, z}))];
            if (i < 0) continue;
            for (std::size_t j = 0; j < 6; ++j) v[j] += cell[std::size_t(i)][j];
          }
      Eigen::Matrix3d M;
      M << v[0], v[3], v[4], v[3], v[1], v[5], v[4], v[5], v[2];
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(M);
      Eigen::Vector3d n = es.eigenvectors().col(2);
      const auto t = trivial_normal(surfels[f]);
      if (n.dot(Eigen::Vector3d(t.x, t.y, t.z)) < 0) n = -n;
      out[f] = {n(0), n(1), n(2)};
    }
  });
  return out;
}

} // namespace zdg
