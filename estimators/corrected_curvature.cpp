// Interpolated corrected curvature measures (see the header).
#include <zdg/arith/error.hpp>
#include <zdg/estimators/corrected_curvature.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <unordered_map>

namespace zdg {

namespace {

using P3 = Point3<double>;

double coord(const P3& p, int i) {
  return i == 0 ? p.x : (i == 1 ? p.y : p.z);
}

P3 normalised(const P3& v) {
  const double n = std::sqrt(dot(v, v));
  return n > 0 ? (1.0 / n) * v : v;
}

void check_inputs(std::span<const Surfel> surfels, std::span<const P3> normals, double h) {
  if (normals.size() != surfels.size()) {
    throw InvalidArgument("corrected curvature: " + std::to_string(normals.size()) +
                          " normals for " + std::to_string(surfels.size()) + " surfels");
  }
  if (!(h > 0) || !std::isfinite(h)) {
    std::ostringstream msg;
    msg << "corrected curvature: the grid step h = " << h << " must be positive";
    throw InvalidArgument(msg.str());
  }
  for (std::size_t i = 0; i < normals.size(); ++i) {
    const double n2 = dot(normals[i], normals[i]);
    if (!(std::abs(n2 - 1) < 1e-6)) {
      std::ostringstream msg;
      msg << "corrected curvature: normal " << i << " " << normals[i] << " is not a unit vector";
      throw InvalidArgument(msg.str());
    }
  }
}

} // namespace

CorrectedMeasures& CorrectedMeasures::add(const CorrectedMeasures& m, double weight) {
  mu0 += weight * m.mu0;
  mu1 += weight * m.mu1;
  mu2 += weight * m.mu2;
  for (std::size_t i = 0; i < 9; ++i) muxy[i] += weight * m.muxy[i];
  return *this;
}

CorrectedMeasures quad_corrected_measures(const std::array<P3, 4>& x, const std::array<P3, 4>& u) {
  // Corners x00 = x[0], x10 = x[1], x11 = x[2], x01 = x[3]; 2 x 2 Gauss-Legendre on [0, 1]^2
  // (nodes (1 -+ 1/sqrt 3) / 2, weights 1/2 x 1/2): exact for the bidegree-(2, 2) integrands.
  static const double g[2] = {0.5 - 0.5 / std::sqrt(3.0), 0.5 + 0.5 / std::sqrt(3.0)};
  CorrectedMeasures m;
  for (const double s : g) {
    for (const double t : g) {
      const double w0 = (1 - s) * (1 - t), w1 = s * (1 - t), w2 = s * t, w3 = (1 - s) * t;
      const P3 uu = w0 * u[0] + w1 * u[1] + w2 * u[2] + w3 * u[3];
      const P3 xs = (1 - t) * (x[1] - x[0]) + t * (x[2] - x[3]);
      const P3 xt = (1 - s) * (x[3] - x[0]) + s * (x[2] - x[1]);
      const P3 us = (1 - t) * (u[1] - u[0]) + t * (u[2] - u[3]);
      const P3 ut = (1 - s) * (u[3] - u[0]) + s * (u[2] - u[1]);
      m.mu0 += 0.25 * dot(uu, cross(xs, xt));
      m.mu1 += 0.25 * dot(uu, cross(us, xt) + cross(xs, ut));
      m.mu2 += 0.25 * dot(uu, cross(us, ut));
      // <u, e_i x v> = (v x u)_i.
      const P3 a = cross(xs, uu), b = cross(xt, uu);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          m.muxy[std::size_t(3 * i + j)] +=
              0.25 * (coord(ut, j) * coord(a, i) - coord(us, j) * coord(b, i));
    }
  }
  return m;
}

CorrectedCurvatures corrected_curvatures(const CorrectedMeasures& ball, const P3& n) {
  CorrectedCurvatures c;
  if (!(ball.mu0 != 0)) return c;
  c.mean = ball.mu1 / (2 * ball.mu0);
  c.gaussian = ball.mu2 / ball.mu0;
  Eigen::Matrix3d M;
  const double nn[3] = {n.x, n.y, n.z};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      M(i, j) = 0.5 * (ball.muxy[std::size_t(3 * i + j)] + ball.muxy[std::size_t(3 * j + i)]) +
                1000.0 * ball.mu0 * nn[i] * nn[j];
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(M);
  c.k1 = -es.eigenvalues()(1) / ball.mu0;
  c.k2 = -es.eigenvalues()(0) / ball.mu0;
  const auto v1 = es.eigenvectors().col(1), v0 = es.eigenvectors().col(0);
  c.d1 = {v1(0), v1(1), v1(2)};
  c.d2 = {v0(0), v0(1), v0(2)};
  return c;
}

std::vector<std::array<P3, 4>> corner_normals(std::span<const Surfel> surfels,
                                              std::span<const P3> normals) {
  if (normals.size() != surfels.size()) {
    throw InvalidArgument("corrected curvature: " + std::to_string(normals.size()) +
                          " normals for " + std::to_string(surfels.size()) + " surfels");
  }
  std::unordered_map<KPoint, P3, KPointHash> sum;
  sum.reserve(surfels.size());
  for (std::size_t f = 0; f < surfels.size(); ++f)
    for (const auto& p : surfel_pointels(surfels[f])) sum[p] += normals[f];
  for (auto& [p, v] : sum) v = normalised(v);
  std::vector<std::array<P3, 4>> out(surfels.size());
  for (std::size_t f = 0; f < surfels.size(); ++f) {
    const auto ps = surfel_pointels(surfels[f]);
    for (std::size_t i = 0; i < 4; ++i) out[f][i] = sum.at(ps[i]);
  }
  return out;
}

std::vector<CorrectedMeasures> face_corrected_measures(std::span<const Surfel> surfels,
                                                       std::span<const P3> normals, double h,
                                                       unsigned threads) {
  check_inputs(surfels, normals, h);
  const auto un = corner_normals(surfels, normals);
  std::vector<CorrectedMeasures> out(surfels.size());
  parallel_chunks(std::int64_t(surfels.size()), threads, [&](std::int64_t b, std::int64_t e) {
    for (auto f = std::size_t(b); f < std::size_t(e); ++f) {
      const auto ps = surfel_pointels(surfels[f]);
      std::array<P3, 4> x;
      for (std::size_t i = 0; i < 4; ++i) x[i] = embed_cell(ps[i], h);
      out[f] = quad_corrected_measures(x, un[f]);
    }
  });
  return out;
}

std::vector<CorrectedCurvatures> cnc_curvatures(std::span<const Surfel> surfels,
                                                std::span<const P3> normals, double h, double R,
                                                std::span<const std::size_t> queries,
                                                unsigned threads) {
  check_inputs(surfels, normals, h);
  if (!(R > 0) || !std::isfinite(R)) {
    std::ostringstream msg;
    msg << "corrected curvature: the ball radius R = " << R << " must be positive";
    throw InvalidArgument(msg.str());
  }
  for (const auto q : queries)
    if (q >= surfels.size())
      throw InvalidArgument("corrected curvature: query " + std::to_string(q) + " is not one of " +
                            std::to_string(surfels.size()) + " surfels");
  const auto measures = face_corrected_measures(surfels, normals, h, threads);
  // Faces hashed by the cell of side R + h of their centre: a face reaching the ball around
  // c has its centre within R + h / sqrt 2 of c, so in one of the 27 cells around c's.
  const double side = R + h;
  auto cell_of = [side](const P3& c) {
    return KPoint{std::int64_t(std::floor(c.x / side)), std::int64_t(std::floor(c.y / side)),
                  std::int64_t(std::floor(c.z / side))};
  };
  std::unordered_map<KPoint, std::vector<std::uint32_t>, KPointHash> cells;
  for (std::size_t f = 0; f < surfels.size(); ++f)
    cells[cell_of(surfel_centre(surfels[f], h))].push_back(std::uint32_t(f));
  std::vector<CorrectedCurvatures> out(queries.size());
  parallel_chunks(std::int64_t(queries.size()), threads, [&](std::int64_t b, std::int64_t e) {
    for (auto qi = std::size_t(b); qi < std::size_t(e); ++qi) {
      const std::size_t q = queries[qi];
      const P3 c = surfel_centre(surfels[q], h);
      const KPoint k = cell_of(c);
      CorrectedMeasures ball;
      for (std::int64_t dz = -1; dz <= 1; ++dz)
        for (std::int64_t dy = -1; dy <= 1; ++dy)
          for (std::int64_t dx = -1; dx <= 1; ++dx) {
            const auto it = cells.find({k.x + dx, k.y + dy, k.z + dz});
            if (it == cells.end()) continue;
            for (const auto f : it->second) {
              // DGtal's faceInclusionRatio over the centroid and the four corners.
              const P3 fc = surfel_centre(surfels[f], h);
              double dmin = std::sqrt(dot(fc - c, fc - c)), dmax = dmin;
              for (const auto& p : surfel_pointels(surfels[f])) {
                const P3 v = embed_cell(p, h) - c;
                const double d = std::sqrt(dot(v, v));
                dmin = std::min(dmin, d);
                dmax = std::max(dmax, d);
              }
              double w = 0;
              if (dmax <= R) {
                w = 1;
              } else if (dmin < R) {
                w = (R - dmin) / (dmax - dmin);
              }
              if (w > 0) ball.add(measures[f], w);
            }
          }
      out[qi] = corrected_curvatures(ball, normals[q]);
    }
  });
  return out;
}

std::vector<CorrectedCurvatures> cnc_curvatures(std::span<const Surfel> surfels,
                                                std::span<const P3> normals, double h, double R,
                                                unsigned threads) {
  std::vector<std::size_t> all(surfels.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
  return cnc_curvatures(surfels, normals, h, R, all, threads);
}

} // namespace zdg
