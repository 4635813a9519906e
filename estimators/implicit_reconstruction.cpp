#include <zdg/arith/error.hpp>
#include <zdg/estimators/implicit_reconstruction.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>
#include <zdg/kernel/surfaces/image_surfaces.hpp>
#include <zdg/kernel/surfaces/image_surfels.hpp>
#include <zdg/kernel/surfaces/marching_cubes.hpp>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

namespace zdg {
namespace {

using P3 = Point3<double>;

double norm(const P3& v) {
  return std::sqrt(dot(v, v));
}

std::vector<P3> unit_normals(const PointCloud& cloud) {
  std::vector<P3> n(cloud.normals);
  for (auto& v : n) v = v * (1 / norm(v));
  return n;
}

void check_input(const PointCloud& cloud, const ReconstructionOptions& o) {
  validate_point_cloud(cloud, "reconstruct");
  if (!cloud.has_normals())
    throw InvalidArgument("reconstruct: the points have no normals (estimate them first: zdg "
                          "normals, or estimators/point_normals.hpp)");
  if (o.k < 1 || o.k + 1 > cloud.size())
    throw InvalidArgument("reconstruct: k = " + std::to_string(o.k) +
                          " neighbours needs at least " + std::to_string(o.k + 1) + " points (" +
                          std::to_string(cloud.size()) + " given)");
  if (!(o.winding_beta > 0) || !std::isfinite(o.winding_beta))
    throw InvalidArgument("reconstruct: winding beta " + std::to_string(o.winding_beta) +
                          " is not positive and finite");
  if (o.rbf_centers < 1) throw InvalidArgument("reconstruct: rbf centers must be at least 1");
  if (!(o.rbf_offset >= 0) || !std::isfinite(o.rbf_offset))
    throw InvalidArgument("reconstruct: rbf offset must be finite and >= 0");
  if (!(o.imls_radius >= 0) || !std::isfinite(o.imls_radius))
    throw InvalidArgument("reconstruct: imls radius must be finite and >= 0");
}

template <class Fn>
ImplicitField sample(const SampleGrid& grid, unsigned threads, Fn&& fn) {
  ImplicitField f{grid, std::vector<double>(static_cast<std::size_t>(grid.size()))};
  const std::int64_t rows = grid.ny * grid.nz;
  parallel_for(rows, threads, [&](std::int64_t r) {
    const std::int64_t j = r % grid.ny, k = r / grid.ny;
    double* out = f.values.data() + r * grid.nx;
    for (std::int64_t i = 0; i < grid.nx; ++i) out[i] = fn(grid.at(i, j, k));
  });
  return f;
}

// --- Hoppe -----------------------------------------------------------------------------------

ImplicitField hoppe_field(const PointCloud& cloud, const KdTree& tree, const SampleGrid& grid,
                          const ReconstructionOptions& o) {
  const auto n = unit_normals(cloud);
  std::vector<P3> centre(cloud.size());
  parallel_chunks(std::int64_t(cloud.size()), o.threads, [&](std::int64_t b, std::int64_t e) {
    std::vector<Neighbour> nb;
    for (std::int64_t i = b; i < e; ++i) {
      tree.nearest(cloud.points[std::size_t(i)], o.k, nb);
      P3 c{};
      for (const auto& x : nb) c += cloud.points[x.index];
      centre[std::size_t(i)] = c * (1.0 / double(nb.size()));
    }
  });
  const KdTree centres(centre);
  return sample(grid, o.threads, [&](const P3& q) {
    thread_local std::vector<Neighbour> nb;
    centres.nearest(q, 1, nb);
    const std::size_t j = nb[0].index;
    return dot(q - centre[j], n[j]);
  });
}

// --- IMLS --------------------------------------------------------------------------------------

double median_kth_distance(const PointCloud& cloud, const KdTree& tree, std::size_t k,
                           unsigned threads) {
  std::vector<double> d(cloud.size());
  parallel_chunks(std::int64_t(cloud.size()), threads, [&](std::int64_t b, std::int64_t e) {
    std::vector<Neighbour> nb;
    for (std::int64_t i = b; i < e; ++i) {
      tree.nearest(cloud.points[std::size_t(i)], k + 1, nb);
      d[std::size_t(i)] = std::sqrt(nb.back().distance2);
    }
  });
  auto mid = d.begin() + std::ptrdiff_t(d.size() / 2);
  std::nth_element(d.begin(), mid, d.end());
  return *mid;
}

ImplicitField imls_field(const PointCloud& cloud, const KdTree& tree, const SampleGrid& grid,
                         const ReconstructionOptions& o) {
  const auto n = unit_normals(cloud);
  double rho = o.imls_radius;
  if (rho == 0) rho = median_kth_distance(cloud, tree, o.k, o.threads);
  if (!(rho > 0)) throw InvalidArgument("reconstruct: the imls radius is 0 (the points coincide)");
  const double inv = 1 / (rho * rho);
  return sample(grid, o.threads, [&](const P3& q) {
    thread_local std::vector<Neighbour> nb;
    tree.within(q, 4 * rho, nb);
    if (nb.empty()) {
      tree.nearest(q, 1, nb);
      return dot(q - cloud.points[nb[0].index], n[nb[0].index]);
    }
    // Weights relative to the nearest point's (exp(-(d^2 - d0^2) / rho^2)): the same ratio.
    const double d0 = nb[0].distance2;
    double num = 0, den = 0;
    for (const auto& x : nb) {
      const double t = std::exp(-(x.distance2 - d0) * inv);
      num += t * dot(q - cloud.points[x.index], n[x.index]);
      den += t;
    }
    return num / den;
  });
}

// --- RBF ---------------------------------------------------------------------------------------

ImplicitField rbf_field(const PointCloud& cloud, const KdTree& tree, const SampleGrid& grid,
                        const ReconstructionOptions& o) {
  const auto n = unit_normals(cloud);
  const PointBounds b = point_bounds(cloud);
  const double diag = b.diagonal();
  const double eps0 = o.rbf_offset > 0 ? o.rbf_offset : diag / 100;
  const std::size_t stride = (cloud.size() + o.rbf_centers - 1) / o.rbf_centers;
  // Normalized coordinates (centre of the box, unit diagonal) for the conditioning.
  const P3 mid = (b.lo + b.hi) * 0.5;
  const double scale = diag > 0 ? 1 / diag : 1;
  std::vector<P3> centres;
  std::vector<double> rhs;
  std::vector<Neighbour> nb;
  for (std::size_t i = 0; i < cloud.size(); i += stride) {
    const P3& p = cloud.points[i];
    centres.push_back((p - mid) * scale);
    rhs.push_back(0);
    for (const double s : {1.0, -1.0}) {
      double e = eps0;
      for (int t = 0; t < 6; ++t, e /= 2) {
        const P3 q = p + n[i] * (s * e);
        tree.nearest(q, 1, nb);
        if (nb[0].index == i) {
          centres.push_back((q - mid) * scale);
          rhs.push_back(s * e * scale);
          break;
        }
      }
    }
  }
  const auto m = static_cast<Eigen::Index>(centres.size());
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(m + 4, m + 4);
  Eigen::VectorXd r = Eigen::VectorXd::Zero(m + 4);
  for (Eigen::Index i = 0; i < m; ++i) {
    const P3& ci = centres[std::size_t(i)];
    for (Eigen::Index j = 0; j < i; ++j) {
      const double d = norm(ci - centres[std::size_t(j)]);
      a(i, j) = a(j, i) = d * d * d;
    }
    const double poly[4] = {1, ci.x, ci.y, ci.z};
    for (int c = 0; c < 4; ++c) a(i, m + c) = a(m + c, i) = poly[c];
    r(i) = rhs[std::size_t(i)];
  }
  const Eigen::VectorXd w = a.partialPivLu().solve(r);
  if (!w.allFinite())
    throw InvalidArgument("reconstruct: the RBF system is singular (points in a plane or on a "
                          "line?)");
  return sample(grid, o.threads, [&](const P3& q0) {
    const P3 q = (q0 - mid) * scale;
    double f = w(m) + w(m + 1) * q.x + w(m + 2) * q.y + w(m + 3) * q.z;
    for (Eigen::Index j = 0; j < m; ++j) {
      const double d = norm(q - centres[std::size_t(j)]);
      f += w(j) * d * d * d;
    }
    return f / scale;
  });
}

// --- point areas ------------------------------------------------------------------------------

struct V2 {
  double x, y;
};

// The area of {x in [-s, s]^2 : x . d <= |d|^2 / 2 for every d}, by clipping the square.
double voronoi_cell_area(const std::vector<V2>& sites, double s) {
  std::vector<V2> poly{{-s, -s}, {s, -s}, {s, s}, {-s, s}}, next;
  for (const V2& d : sites) {
    const double c = (d.x * d.x + d.y * d.y) / 2;
    if (c == 0) continue;
    next.clear();
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const V2 u = poly[i], v = poly[(i + 1) % poly.size()];
      const double fu = u.x * d.x + u.y * d.y - c, fv = v.x * d.x + v.y * d.y - c;
      if (fu <= 0) next.push_back(u);
      if ((fu < 0 && fv > 0) || (fu > 0 && fv < 0)) {
        const double t = fu / (fu - fv);
        next.push_back({u.x + t * (v.x - u.x), u.y + t * (v.y - u.y)});
      }
    }
    poly.swap(next);
    if (poly.size() < 3) return 0;
  }
  double area = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const V2 u = poly[i], v = poly[(i + 1) % poly.size()];
    area += u.x * v.y - u.y * v.x;
  }
  return area / 2;
}

} // namespace

std::string to_string(ReconstructionMethod method) {
  return reconstruction_method_names()[static_cast<std::size_t>(method)];
}

const std::vector<std::string>& reconstruction_method_names() {
  static const std::vector<std::string> names{"hoppe", "winding", "poisson", "rbf", "imls"};
  return names;
}

ReconstructionMethod reconstruction_method_of(std::string_view name) {
  const auto& names = reconstruction_method_names();
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<ReconstructionMethod>(i);
  throw InvalidArgument("reconstruct: unknown method '" + std::string(name) +
                        "' (hoppe, winding, poisson, rbf, imls)");
}

SampleGrid grid_around(const PointCloud& cloud, double h, int margin, std::int64_t max_samples) {
  if (!(h > 0) || !std::isfinite(h))
    throw InvalidArgument("reconstruct: grid step h = " + std::to_string(h) +
                          " is not positive and finite");
  if (margin < 0) throw InvalidArgument("reconstruct: negative grid margin");
  const PointBounds b = point_bounds(cloud);
  SampleGrid g;
  g.h = h;
  const double lo[3] = {b.lo.x, b.lo.y, b.lo.z}, hi[3] = {b.hi.x, b.hi.y, b.hi.z};
  std::int64_t n[3];
  double total = 1;
  for (int a = 0; a < 3; ++a) {
    const double l = std::floor(lo[a] / h) - margin, u = std::ceil(hi[a] / h) + margin;
    if (!(std::fabs(l) < 4e15 && std::fabs(u) < 4e15))
      throw InvalidArgument("reconstruct: the points' box divided by h = " + std::to_string(h) +
                            " leaves the integers of double precision");
    g.lower[std::size_t(a)] = static_cast<std::int64_t>(l);
    n[a] = static_cast<std::int64_t>(u - l) + 1;
    total *= double(n[a]);
  }
  if (total > double(max_samples))
    throw InvalidArgument("reconstruct: a grid of step h = " + std::to_string(h) + " has " +
                          std::to_string(n[0]) + " x " + std::to_string(n[1]) + " x " +
                          std::to_string(n[2]) + " samples, more than " +
                          std::to_string(max_samples) + " (use a larger h)");
  g.nx = n[0];
  g.ny = n[1];
  g.nz = n[2];
  return g;
}

std::vector<double> point_areas(const PointCloud& cloud, const KdTree& tree, std::size_t k,
                                unsigned threads) {
  if (!cloud.has_normals()) throw InvalidArgument("point areas: the points have no normals");
  const auto n = unit_normals(cloud);
  std::vector<double> area(cloud.size());
  parallel_chunks(std::int64_t(cloud.size()), threads, [&](std::int64_t b, std::int64_t e) {
    std::vector<Neighbour> nb;
    std::vector<V2> sites;
    for (std::int64_t i = b; i < e; ++i) {
      const P3& p = cloud.points[std::size_t(i)];
      const P3& nn = n[std::size_t(i)];
      // An orthonormal frame (u, v) of the tangent plane.
      const P3 t = std::fabs(nn.x) < 0.9 ? P3{1, 0, 0} : P3{0, 1, 0};
      P3 u = cross(nn, t);
      u = u * (1 / norm(u));
      const P3 v = cross(nn, u);
      tree.nearest(p, k + 1, nb);
      sites.clear();
      for (const auto& x : nb) {
        if (x.index == std::size_t(i)) continue;
        const P3 d = cloud.points[x.index] - p;
        sites.push_back({dot(d, u), dot(d, v)});
      }
      const double s = nb.empty() ? 0 : std::sqrt(nb.back().distance2);
      area[std::size_t(i)] = voronoi_cell_area(sites, s);
    }
  });
  return area;
}

double winding_number_exact(const PointCloud& cloud, std::span<const double> areas,
                            const Point3<double>& q) {
  double w = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const P3 r = cloud.points[i] - q;
    const double d2 = dot(r, r);
    if (d2 == 0) continue;
    const P3& nn = cloud.normals[i];
    w += areas[i] * dot(r, nn) / (norm(nn) * d2 * std::sqrt(d2));
  }
  return w / (4 * std::numbers::pi);
}

// --- the winding-number tree -----------------------------------------------------------------

struct WindingTree::Impl {
  struct Node {
    P3 c;               // area-weighted centre
    double r2 = 0;      // squared radius
    P3 m;               // sum a_i n_i
    double mm[9] = {};  // sum a_i (p_i - c) n_i^T, row-major
    double t3[27] = {}; // T_ijk = sum a_i n_i (p_i - c)_j (p_i - c)_k, index 9 i + 3 j + k
    std::uint32_t begin = 0, end = 0;
    std::int32_t left = -1, right = -1;
  };
  std::vector<P3> p, an; // points in tree order, a_i n_i (unit n)
  std::vector<Node> nodes;

  std::int32_t build(std::vector<std::uint32_t>& order, std::uint32_t b, std::uint32_t e,
                     const PointCloud& cloud, std::span<const double> areas) {
    Node node;
    node.begin = b;
    node.end = e;
    double a = 0;
    P3 c{}, lo = cloud.points[order[b]], hi = lo;
    for (std::uint32_t i = b; i < e; ++i) {
      const P3& x = cloud.points[order[i]];
      const double w = std::fabs(areas[order[i]]) + 1e-300;
      c += x * w;
      a += w;
      lo = {std::min(lo.x, x.x), std::min(lo.y, x.y), std::min(lo.z, x.z)};
      hi = {std::max(hi.x, x.x), std::max(hi.y, x.y), std::max(hi.z, x.z)};
    }
    node.c = c * (1 / a);
    const auto id = static_cast<std::int32_t>(nodes.size());
    nodes.push_back(node);
    if (e - b > 8) {
      const P3 ext = hi - lo;
      const int axis = ext.x >= ext.y && ext.x >= ext.z ? 0 : (ext.y >= ext.z ? 1 : 2);
      const std::uint32_t mid = b + (e - b) / 2;
      auto key = [&](std::uint32_t i) {
        const P3& x = cloud.points[i];
        return axis == 0 ? x.x : (axis == 1 ? x.y : x.z);
      };
      std::nth_element(order.begin() + b, order.begin() + mid, order.begin() + e,
                       [&](std::uint32_t u, std::uint32_t v) {
                         return key(u) < key(v) || (key(u) == key(v) && u < v);
                       });
      const std::int32_t l = build(order, b, mid, cloud, areas);
      const std::int32_t r = build(order, mid, e, cloud, areas);
      nodes[std::size_t(id)].left = l;
      nodes[std::size_t(id)].right = r;
    }
    return id;
  }

  double eval(const P3& q, double beta2) const {
    double w = 0;
    std::int32_t stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& nd = nodes[std::size_t(stack[--top])];
      const P3 r = nd.c - q;
      const double d2 = dot(r, r);
      if (d2 > beta2 * nd.r2) {
        // g(r) = r / |r|^3 expanded about r = c - q to second order in d = p - c:
        //   g_i(r + d) ~ g_i + dg_i/dr_j d_j + 1/2 d2g_i/dr_j dr_k d_j d_k, with
        //   dg_i/dr_j = delta_ij / |r|^3 - 3 r_i r_j / |r|^5 and
        //   d2g_i/dr_j dr_k = -3 (delta_ij r_k + delta_ik r_j + delta_jk r_i) / |r|^5
        //                     + 15 r_i r_j r_k / |r|^7.
        const double inv = 1 / std::sqrt(d2), inv3 = inv * inv * inv, inv5 = inv3 * inv * inv,
                     inv7 = inv5 * inv * inv;
        double t = dot(nd.m, r) * inv3;
        const double* M = nd.mm;
        const double rr[3] = {r.x, r.y, r.z};
        double tr = M[0] + M[4] + M[8], rmr = 0;
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) rmr += rr[i] * M[3 * i + j] * rr[j];
        t += tr * inv3 - 3 * rmr * inv5;
        const double* T = nd.t3;
        double tiij = 0, tijj = 0, trrr = 0;
        for (int i = 0; i < 3; ++i) {
          tiij += T[9 * i + 3 * i + 0] * rr[0] + T[9 * i + 3 * i + 1] * rr[1] +
                  T[9 * i + 3 * i + 2] * rr[2];
          tijj += (T[9 * i + 0] + T[9 * i + 4] + T[9 * i + 8]) * rr[i];
          for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) trrr += T[9 * i + 3 * j + k] * rr[i] * rr[j] * rr[k];
        }
        t += 0.5 * (-3 * (2 * tiij + tijj) * inv5 + 15 * trrr * inv7);
        w += t;
        continue;
      }
      if (nd.left < 0) {
        for (std::uint32_t i = nd.begin; i < nd.end; ++i) {
          const P3 s = p[i] - q;
          const double e2 = dot(s, s);
          if (e2 == 0) continue;
          w += dot(s, an[i]) / (e2 * std::sqrt(e2));
        }
        continue;
      }
      stack[top++] = nd.right;
      stack[top++] = nd.left;
    }
    return w / (4 * std::numbers::pi);
  }
};

WindingTree::WindingTree(const PointCloud& cloud, std::span<const double> areas)
    : impl_(std::make_unique<Impl>()) {
  if (!cloud.has_normals() || areas.size() != cloud.size() || cloud.size() == 0)
    throw InvalidArgument("winding tree: needs points with normals and one area per point");
  if (cloud.size() >= (std::size_t{1} << 31))
    throw InvalidArgument("winding tree: more than 2^31 points");
  std::vector<std::uint32_t> order(cloud.size());
  std::iota(order.begin(), order.end(), 0u);
  impl_->build(order, 0, std::uint32_t(cloud.size()), cloud, areas);
  impl_->p.resize(cloud.size());
  impl_->an.resize(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const P3& nn = cloud.normals[order[i]];
    impl_->p[i] = cloud.points[order[i]];
    impl_->an[i] = nn * (areas[order[i]] / norm(nn));
  }
  // Moments bottom-up (children after parents in the array: reverse order).
  for (std::size_t id = impl_->nodes.size(); id-- > 0;) {
    auto& nd = impl_->nodes[id];
    nd.m = {};
    std::fill(std::begin(nd.mm), std::end(nd.mm), 0.0);
    std::fill(std::begin(nd.t3), std::end(nd.t3), 0.0);
    double r2 = 0;
    for (std::uint32_t i = nd.begin; i < nd.end; ++i) {
      const P3 d = impl_->p[i] - nd.c;
      const P3& a = impl_->an[i];
      nd.m += a;
      const double dd[3] = {d.x, d.y, d.z}, aa[3] = {a.x, a.y, a.z};
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) nd.mm[3 * r + c] += dd[r] * aa[c];
      for (int u = 0; u < 3; ++u)
        for (int v = 0; v < 3; ++v)
          for (int w = 0; w < 3; ++w) nd.t3[9 * u + 3 * v + w] += aa[u] * dd[v] * dd[w];
      r2 = std::max(r2, dot(d, d));
    }
    nd.r2 = r2;
  }
}

WindingTree::~WindingTree() = default;
WindingTree::WindingTree(WindingTree&&) noexcept = default;
WindingTree& WindingTree::operator=(WindingTree&&) noexcept = default;

double WindingTree::operator()(const Point3<double>& q, double beta) const {
  return impl_->eval(q, beta * beta);
}

ImplicitField reconstruct_field(const PointCloud& cloud, const SampleGrid& grid,
                                const ReconstructionOptions& o) {
  check_input(cloud, o);
  if (o.method == ReconstructionMethod::poisson) return poisson_field(cloud, grid, o.threads);
  const KdTree tree(cloud.points);
  switch (o.method) {
  case ReconstructionMethod::hoppe:
    return hoppe_field(cloud, tree, grid, o);
  case ReconstructionMethod::imls:
    return imls_field(cloud, tree, grid, o);
  case ReconstructionMethod::rbf:
    return rbf_field(cloud, tree, grid, o);
  case ReconstructionMethod::winding: {
    const auto areas = point_areas(
        cloud, tree, std::min(std::max<std::size_t>(o.k, 20), cloud.size() - 1), o.threads);
    if (o.winding_exact)
      return sample(grid, o.threads,
                    [&](const P3& q) { return 0.5 - winding_number_exact(cloud, areas, q); });
    const WindingTree wt(cloud, areas);
    return sample(grid, o.threads, [&](const P3& q) { return 0.5 - wt(q, o.winding_beta); });
  }
  case ReconstructionMethod::poisson:
    break;
  }
  throw InvalidArgument("reconstruct: unknown method");
}

Reconstruction reconstruct(const PointCloud& cloud, double h, const ReconstructionOptions& o,
                           int margin) {
  check_input(cloud, o);
  Reconstruction r;
  const SampleGrid g = grid_around(cloud, h, margin);
  r.field = reconstruct_field(cloud, g, o);
  const std::int64_t n = g.size();
  std::vector<std::uint8_t> mask(static_cast<std::size_t>(n));
  for (std::int64_t i = 0; i < n; ++i) mask[std::size_t(i)] = r.field.values[std::size_t(i)] < 0;
  r.inside_count = std::count(mask.begin(), mask.end(), std::uint8_t{1});
  r.inside = Image<std::uint8_t>(Domain({g.nz, g.ny, g.nx}, {g.lower[2], g.lower[1], g.lower[0]}),
                                 std::move(mask));
  const AdjacencyPair pair = make_adjacency_pair(3, 6, 26);
  r.betti = betti_numbers(r.inside, pair, o.threads);
  const ImageSurfels surfels = image_surfels(r.inside, o.threads);
  const VoxelPlacement place{
      {h, h, h}, {h * double(g.lower[0]), h * double(g.lower[1]), h * double(g.lower[2])}};
  // marching_cubes interpolates value(v) to the level; inside is f < 0, so value = -f.
  const IsoLevel grey{[&](std::int64_t v) { return -r.field.values[std::size_t(v)]; }, 0.0};
  r.mesh = marching_cubes(r.inside, surfels, SurfaceConvention::of(6, 26), place, &grey, o.threads);
  return r;
}

} // namespace zdg
