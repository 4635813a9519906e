#include <zdg/kernel/surfaces/surfel_complex.hpp>

#include <zdg/arith/error.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

namespace zdg {

SurfelComplex surfel_complex(std::vector<Point3<double>> pointels,
                             std::vector<std::array<std::int64_t, 4>> quads) {
  SurfelComplex c;
  c.pointels = std::move(pointels);
  c.surfels = std::move(quads);
  const auto nf = c.surfels.size();
  const auto nv = static_cast<std::int64_t>(c.pointels.size());
  c.centres.resize(nf);
  c.normals.resize(nf);
  c.areas.resize(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    const auto& q = c.surfels[f];
    for (auto v : q)
      if (v < 0 || v >= nv)
        throw InvalidArgument("surfel complex: quad " + std::to_string(f) + " uses pointel " +
                              std::to_string(v) + " of " + std::to_string(nv));
    const auto& p0 = c.pointels[std::size_t(q[0])];
    const auto& p1 = c.pointels[std::size_t(q[1])];
    const auto& p2 = c.pointels[std::size_t(q[2])];
    const auto& p3 = c.pointels[std::size_t(q[3])];
    c.centres[f] = 0.25 * (p0 + p1 + p2 + p3);
    const auto n = cross(p2 - p0, p3 - p1);
    const double len = std::sqrt(dot(n, n));
    if (!(len > 0))
      throw InvalidArgument("surfel complex: quad " + std::to_string(f) + " is degenerate");
    c.normals[f] = (1.0 / len) * n;
    c.areas[f] = 0.5 * len;
  }
  // Directed sides (min, max, face, side, forward), sorted: the two directions of one pointel
  // pair are then contiguous, forward ones (a < b run a -> b) paired in order with backward.
  struct Side {
    std::int64_t lo, hi, face;
    int side;
    bool forward;
  };
  std::vector<Side> sides;
  sides.reserve(4 * nf);
  for (std::size_t f = 0; f < nf; ++f) {
    for (int i = 0; i < 4; ++i) {
      const auto a = c.surfels[f][std::size_t(i)], b = c.surfels[f][std::size_t((i + 1) % 4)];
      sides.push_back({std::min(a, b), std::max(a, b), std::int64_t(f), i, a < b});
    }
  }
  std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) {
    return std::tie(x.lo, x.hi, x.forward, x.face, x.side) <
           std::tie(y.lo, y.hi, y.forward, y.face, y.side);
  });
  c.surfel_linels.assign(nf, {-1, -1, -1, -1});
  c.linels.reserve(2 * nf);
  for (std::size_t k = 0; k < sides.size();) {
    std::size_t e = k;
    while (e < sides.size() && sides[e].lo == sides[k].lo && sides[e].hi == sides[k].hi) ++e;
    std::size_t backward = k;
    while (backward < e && !sides[backward].forward) ++backward;
    // [k, backward): b -> a (a < b) ... sorted with forward = false first.
    const std::size_t nback = backward - k, nfwd = e - backward;
    if (nback != nfwd)
      throw InvalidArgument("surfel complex: the side (" + std::to_string(sides[k].lo) + ", " +
                            std::to_string(sides[k].hi) + ") is run " + std::to_string(nfwd) +
                            " times one way and " + std::to_string(nback) +
                            " times the other (the quads do not form a closed oriented surface)");
    for (std::size_t j = 0; j < nfwd; ++j) {
      const Side& f0 = sides[backward + j]; // runs lo -> hi
      const Side& f1 = sides[k + j];        // runs hi -> lo
      const auto id = std::int64_t(c.linels.size());
      c.linels.push_back({f0.lo, f0.hi, {f0.face, f1.face}});
      c.surfel_linels[std::size_t(f0.face)][std::size_t(f0.side)] = id;
      c.surfel_linels[std::size_t(f1.face)][std::size_t(f1.side)] = id;
    }
    k = e;
  }
  return c;
}

SurfelComplex surfel_complex(const QuadSurface& surface, double h, Point3<double> translation) {
  std::vector<Point3<double>> p;
  p.reserve(surface.vertices.size());
  for (const auto& k : surface.vertices) p.push_back(embed_cell(k, h) + translation);
  std::vector<std::array<std::int64_t, 4>> q;
  q.reserve(surface.quads.size());
  for (const auto& quad : surface.quads) q.push_back({quad[0], quad[1], quad[2], quad[3]});
  return surfel_complex(std::move(p), std::move(q));
}

SurfelComplex surfel_complex(const PolygonMesh& mesh) {
  if (mesh.face_size != 4)
    throw InvalidArgument("surfel complex: faces of " + std::to_string(mesh.face_size) +
                          " vertices (quads expected)");
  std::vector<std::array<std::int64_t, 4>> q(static_cast<std::size_t>(mesh.face_count()));
  for (std::size_t f = 0; f < q.size(); ++f)
    for (std::size_t i = 0; i < 4; ++i) q[f][i] = mesh.indices[4 * f + i];
  return surfel_complex(mesh.vertices, std::move(q));
}

} // namespace zdg
