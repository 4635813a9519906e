#include <zdg/convergence/laplacian_spectrum.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/convergence/digitized_3d.hpp>
#include <zdg/estimators/heat_laplace_beltrami.hpp>
#include <zdg/kernel/linalg/cotan_laplacian.hpp>
#include <zdg/kernel/linalg/generalized_eigen.hpp>
#include <zdg/kernel/linalg/principal_angles.hpp>
#include <zdg/kernel/surfaces/digital_surface.hpp>
#include <zdg/kernel/surfaces/marching_cubes.hpp>
#include <zdg/kernel/surfaces/surfel_complex.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace zdg {

std::string spectrum_operator_name(SpectrumOperator op) {
  switch (op) {
  case SpectrumOperator::cotan:
    return "cotan";
  case SpectrumOperator::cotan_mc:
    return "cotan-mc";
  case SpectrumOperator::heat:
    return "heat";
  }
  return "?";
}

SpectrumOperator parse_spectrum_operator(const std::string& name) {
  for (auto op : {SpectrumOperator::cotan, SpectrumOperator::cotan_mc, SpectrumOperator::heat}) {
    if (spectrum_operator_name(op) == name) return op;
  }
  throw InvalidArgument("unknown Laplacian '" +
                        (name.size() <= 40 ? name : name.substr(0, 37) + "...") +
                        "' (known: cotan, cotan-mc, heat)");
}

std::vector<double> sphere_laplacian_eigenvalues(double r, std::int64_t count) {
  if (!(r > 0) || !std::isfinite(r) || count < 0) {
    throw InvalidArgument("sphere eigenvalues: need r > 0 and count >= 0");
  }
  std::vector<double> out;
  for (std::int64_t l = 1; std::int64_t(out.size()) < count; ++l) {
    for (std::int64_t m = 0; m < 2 * l + 1 && std::int64_t(out.size()) < count; ++m) {
      out.push_back(double(l * (l + 1)) / (r * r));
    }
  }
  return out;
}

double sphere_radius(const Shape& shape, const std::string& who) {
  if (shape.dimension() != 3 || !shape.shape_class().umbilic) {
    throw InvalidArgument(who + ": '" + shape.spec() +
                          "' is not a sphere (the closed-form spectrum is known on sphere1 and "
                          "sphere9 only)");
  }
  // A sphere centred at the origin: |xi(p)| for any p is its radius.
  const SurfacePoint3 q = detail::as_3d(shape).project({1.0, 0.0, 0.0});
  return std::sqrt(q.point.x * q.point.x + q.point.y * q.point.y + q.point.z * q.point.z);
}

std::vector<double> quad_corner_mass(const SurfelComplex& complex) {
  std::vector<double> mass(complex.pointels.size(), 0.0);
  for (std::size_t f = 0; f < complex.surfels.size(); ++f) {
    for (const auto v : complex.surfels[f]) mass[std::size_t(v)] += complex.areas[f] / 4;
  }
  return mass;
}

namespace {

struct Problem {
  SparseMatrix stiffness;
  std::vector<double> mass;
  std::vector<Point3<double>> nodes;
};

Problem from_cotan(const CotanLaplacian& l, std::vector<Point3<double>> nodes) {
  Problem p;
  p.stiffness = l.stiffness;
  for (double& v : p.stiffness.value) v = -v;
  p.mass = l.mass;
  p.nodes = std::move(nodes);
  return p;
}

Problem assemble(const RunInput& in, SpectrumOperator op) {
  const std::string who = "lb-spectrum (" + spectrum_operator_name(op) + ")";
  const detail::Digitized3 d = detail::whole_surface(in, who);
  switch (op) {
  case SpectrumOperator::cotan: {
    const SurfelComplex complex = surfel_complex(primal_surface(d.surfels), in.h);
    const CotanLaplacian l = cotan_laplacian(complex.pointels, triangulate_quads(complex.surfels));
    Problem p = from_cotan(l, complex.pointels);
    // The split diagonal of a planar square has weight 0 (its opposite angles are right), so S
    // does not depend on the split; the triangles' lumped mass does (A/3 at the diagonal's
    // ends, A/6 elsewhere), which would break the cube's symmetries: a quarter of each quad's
    // area at each corner instead (the mean of both splits).
    p.mass = quad_corner_mass(complex);
    return p;
  }
  case SpectrumOperator::cotan_mc: {
    const PolygonMesh mesh = marching_cubes(d.inside, d.box, in.h, 1);
    return from_cotan(cotan_laplacian(mesh), mesh.vertices);
  }
  case SpectrumOperator::heat: {
    const SurfelComplex complex = surfel_complex(primal_surface(d.surfels), in.h);
    const auto w = detail::ii_surfel_weights(d, in.h, 2.0 * std::cbrt(in.h));
    for (std::size_t i = 0; i < w.size(); ++i) {
      if (!(w[i] > 0)) {
        throw InvalidArgument(who + ": surfel " + std::to_string(i) +
                              " has a non-positive weight h^2 n_II . n_elem: the mass is not "
                              "positive definite");
      }
    }
    const HeatLaplaceBeltrami heat(complex.centres, w, heat_kernel_time(in.h, 0.4), 5.0, 1);
    Problem p;
    p.stiffness = heat.matrix(); // row s scaled by -w(s): -W L, symmetric
    for (std::int64_t s = 0; s < p.stiffness.rows; ++s) {
      for (auto q = p.stiffness.row_start[std::size_t(s)];
           q < p.stiffness.row_start[std::size_t(s) + 1]; ++q) {
        p.stiffness.value[std::size_t(q)] *= -w[std::size_t(s)];
      }
    }
    p.mass = w;
    p.nodes = complex.centres;
    return p;
  }
  }
  throw InvalidArgument(who + ": unknown operator");
}

// Nearest node of a point set: a uniform grid of cell `cell`, rings of cells searched outward
// until a ring beyond the best distance.
class NearestNode {
public:
  NearestNode(const std::vector<Point3<double>>& nodes, double cell) : nodes_(nodes), cell_(cell) {
    for (std::size_t i = 0; i < nodes.size(); ++i) grid_[key(index(nodes[i]))].push_back(i);
  }
  std::size_t operator()(Point3<double> p) const {
    const auto c = index(p);
    double best = std::numeric_limits<double>::infinity();
    std::size_t arg = 0;
    for (std::int64_t ring = 0; ring < 64; ++ring) {
      for (std::int64_t dx = -ring; dx <= ring; ++dx)
        for (std::int64_t dy = -ring; dy <= ring; ++dy)
          for (std::int64_t dz = -ring; dz <= ring; ++dz) {
            if (std::max({std::abs(dx), std::abs(dy), std::abs(dz)}) != ring) continue;
            const auto it = grid_.find(key({c[0] + dx, c[1] + dy, c[2] + dz}));
            if (it == grid_.end()) continue;
            for (std::size_t i : it->second) {
              const auto& q = nodes_[i];
              const double d2 =
                  (q.x - p.x) * (q.x - p.x) + (q.y - p.y) * (q.y - p.y) + (q.z - p.z) * (q.z - p.z);
              if (d2 < best) best = d2, arg = i;
            }
          }
      // Points of later rings are farther than ring * cell.
      if (best < std::numeric_limits<double>::infinity() && std::sqrt(best) <= double(ring) * cell_)
        return arg;
    }
    if (best < std::numeric_limits<double>::infinity()) return arg;
    throw InvalidArgument("eigenspace angles: no node near (" + std::to_string(p.x) + ", " +
                          std::to_string(p.y) + ", " + std::to_string(p.z) + ")");
  }

private:
  std::array<std::int64_t, 3> index(Point3<double> p) const {
    return {std::int64_t(std::floor(p.x / cell_)), std::int64_t(std::floor(p.y / cell_)),
            std::int64_t(std::floor(p.z / cell_))};
  }
  static std::uint64_t key(std::array<std::int64_t, 3> c) {
    return (std::uint64_t(c[0] & 0x1fffff) << 42) | (std::uint64_t(c[1] & 0x1fffff) << 21) |
           std::uint64_t(c[2] & 0x1fffff);
  }
  const std::vector<Point3<double>>& nodes_;
  double cell_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> grid_;
};

// A grid cell of the order of the node spacing of a closed surface in the nodes' bounding box
// (area at most 6 extent^2): extent sqrt(6 / n).
double cell_size(const std::vector<Point3<double>>& nodes) {
  Point3<double> lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
                    std::numeric_limits<double>::max()};
  Point3<double> hi{-lo.x, -lo.y, -lo.z};
  for (const auto& p : nodes) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 1e-300});
  return extent / std::max(1.0, std::sqrt(double(nodes.size()) / 6.0));
}

std::vector<std::vector<double>> cluster(const SurfaceSpectrum& s, int l, const char* name) {
  const auto first = std::size_t(l) * std::size_t(l),
             last = std::size_t(l + 1) * std::size_t(l + 1);
  if (l < 0 || s.vectors.size() < last) {
    throw InvalidArgument(std::string("eigenspace angles: cluster l = ") + std::to_string(l) +
                          " needs " + std::to_string(last) + " eigenpairs, " + name + " has " +
                          std::to_string(s.vectors.size()));
  }
  return {s.vectors.begin() + std::ptrdiff_t(first), s.vectors.begin() + std::ptrdiff_t(last)};
}

// The vectors sampled at the points: v(p) = u(nearest node of p).
std::vector<std::vector<double>> sampled(const std::vector<std::vector<double>>& vectors,
                                         const NearestNode& nearest,
                                         const std::vector<Point3<double>>& points) {
  std::vector<std::size_t> at;
  at.reserve(points.size());
  for (const auto& p : points) at.push_back(nearest(p));
  std::vector<std::vector<double>> out;
  for (const auto& u : vectors) {
    std::vector<double> v;
    v.reserve(at.size());
    for (std::size_t i : at) v.push_back(u[i]);
    out.push_back(std::move(v));
  }
  return out;
}

} // namespace

SurfaceSpectrum surface_spectrum(const RunInput& in, SpectrumOperator op, std::int64_t k) {
  Problem p = assemble(in, op);
  const auto pairs =
      smallest_generalized_eigenpairs(p.stiffness, SparseMatrix::diagonal(p.mass), k);
  SurfaceSpectrum out;
  const Point3<double> t{in.translation.at(0), in.translation.at(1), in.translation.at(2)};
  for (auto& q : p.nodes) q = {q.x - t.x, q.y - t.y, q.z - t.z};
  out.nodes = std::move(p.nodes);
  out.mass = std::move(p.mass);
  out.values = pairs.values;
  out.vectors = pairs.vectors;
  return out;
}

std::vector<CubeSymmetry> cube_symmetries() {
  std::vector<CubeSymmetry> out;
  std::array<int, 3> axis{0, 1, 2};
  do {
    for (int s = 0; s < 8; ++s) {
      out.push_back({axis, {s & 1 ? -1 : 1, s & 2 ? -1 : 1, s & 4 ? -1 : 1}});
    }
  } while (std::next_permutation(axis.begin(), axis.end()));
  return out;
}

std::vector<double> cluster_angles(const SurfaceSpectrum& a, const SurfaceSpectrum& b, int l) {
  const auto ua = cluster(a, l, "the first spectrum");
  const auto ub = cluster(b, l, "the second spectrum");
  const NearestNode nearest(b.nodes, cell_size(b.nodes));
  return principal_angles(ua, sampled(ub, nearest, a.nodes), a.mass);
}

std::vector<double> cluster_angles(const SurfaceSpectrum& a, const CubeSymmetry& g, int l) {
  const auto ua = cluster(a, l, "the spectrum");
  std::vector<Point3<double>> moved;
  moved.reserve(a.nodes.size());
  for (const auto& p : a.nodes) {
    const double x[3] = {p.x, p.y, p.z};
    moved.push_back({g.sign[0] * x[g.axis[0]], g.sign[1] * x[g.axis[1]], g.sign[2] * x[g.axis[2]]});
  }
  const NearestNode nearest(a.nodes, cell_size(a.nodes));
  return principal_angles(ua, sampled(ua, nearest, moved), a.mass);
}

} // namespace zdg
