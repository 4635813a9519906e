#include <zdg/kernel/hulls/lattice_delaunay.hpp>

#include <zdg/arith/error.hpp>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

namespace zdg {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb2 = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>;
using Tds2 = CGAL::Triangulation_data_structure_2<Vb2>;
using Dt2 = CGAL::Delaunay_triangulation_2<K, Tds2>;
using Vb3 = CGAL::Triangulation_vertex_base_with_info_3<std::size_t, K>;
using Tds3 = CGAL::Triangulation_data_structure_3<Vb3>;
using Dt3 = CGAL::Delaunay_triangulation_3<K, Tds3>;

constexpr std::int64_t kMaxCoordinate = std::int64_t{1} << 53;

void finish_neighbours(LatticeDelaunay& t) {
  for (auto& n : t.neighbours) {
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
  }
}

template <class Dt, class Point>
void build(LatticeDelaunay& t, std::vector<std::pair<Point, std::size_t>>& pts) {
  Dt dt;
  dt.insert(pts.begin(), pts.end());
  const std::size_t nv = t.vertex_count();
  t.affine_dim = dt.dimension();
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    std::size_t a = 0, b = 0;
    if constexpr (std::is_same_v<Dt, Dt2>) {
      a = e->first->vertex(Dt::cw(e->second))->info();
      b = e->first->vertex(Dt::ccw(e->second))->info();
    } else {
      a = e->first->vertex(e->second)->info();
      b = e->first->vertex(e->third)->info();
    }
    t.neighbours[a].push_back(b);
    t.neighbours[b].push_back(a);
  }
  if (dt.dimension() == t.dim) {
    if constexpr (std::is_same_v<Dt, Dt2>) {
      for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
        t.cells.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info(), 0});
      }
      // The hull: the vertices of the infinite faces.
      auto c = dt.incident_vertices(dt.infinite_vertex()), done = c;
      if (c != nullptr) {
        do {
          t.on_hull[c->info()] = true;
        } while (++c != done);
      }
    } else {
      for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) {
        std::array<std::size_t, 4> v{c->vertex(0)->info(), c->vertex(1)->info(),
                                     c->vertex(2)->info(), c->vertex(3)->info()};
        t.cells.push_back(v);
      }
      std::vector<typename Dt::Vertex_handle> hull;
      dt.adjacent_vertices(dt.infinite_vertex(), std::back_inserter(hull));
      for (const auto& v : hull) t.on_hull[v->info()] = true;
    }
  } else {
    t.on_hull.assign(nv, true);
  }
}

BigInt coord(const LatticeDelaunay& t, std::size_t v, int k) {
  return BigInt(t.points[v * static_cast<std::size_t>(t.dim) + static_cast<std::size_t>(k)]);
}

} // namespace

LatticeDelaunay lattice_delaunay(const std::vector<std::int64_t>& coords, int dim) {
  if (dim != 2 && dim != 3) {
    throw InvalidArgument("Delaunay: dimension " + std::to_string(dim) + " (2 or 3 only)");
  }
  const auto d = static_cast<std::size_t>(dim);
  if (coords.empty() || coords.size() % d != 0) {
    throw InvalidArgument("Delaunay: " + std::to_string(coords.size()) + " coordinates for " +
                          std::to_string(dim) + "D points (at least one point)");
  }
  for (std::size_t i = 0; i < coords.size(); ++i) {
    if (coords[i] > kMaxCoordinate || coords[i] < -kMaxCoordinate) {
      throw InvalidArgument("Delaunay: coordinate " + std::to_string(coords[i]) + " of point " +
                            std::to_string(i / d) + " is past 2^53 (not exact as a double)");
    }
  }
  LatticeDelaunay t;
  t.dim = dim;
  const std::size_t n = coords.size() / d;
  std::map<std::vector<std::int64_t>, std::size_t> index;
  t.vertex_of_input.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<std::int64_t> p(coords.begin() + static_cast<std::ptrdiff_t>(i * d),
                                coords.begin() + static_cast<std::ptrdiff_t>(i * d + d));
    const auto [it, fresh] = index.emplace(p, t.on_hull.size());
    if (fresh) {
      t.points.insert(t.points.end(), p.begin(), p.end());
      t.on_hull.push_back(false);
    }
    t.vertex_of_input[i] = it->second;
  }
  const std::size_t nv = t.vertex_count();
  t.neighbours.resize(nv);
  if (dim == 2) {
    std::vector<std::pair<K::Point_2, std::size_t>> pts;
    for (std::size_t v = 0; v < nv; ++v) {
      pts.emplace_back(K::Point_2(static_cast<double>(t.points[2 * v]),
                                  static_cast<double>(t.points[2 * v + 1])),
                       v);
    }
    build<Dt2>(t, pts);
  } else {
    std::vector<std::pair<K::Point_3, std::size_t>> pts;
    for (std::size_t v = 0; v < nv; ++v) {
      pts.emplace_back(K::Point_3(static_cast<double>(t.points[3 * v]),
                                  static_cast<double>(t.points[3 * v + 1]),
                                  static_cast<double>(t.points[3 * v + 2])),
                       v);
    }
    build<Dt3>(t, pts);
  }
  finish_neighbours(t);
  return t;
}

std::vector<Rational<BigInt>> circumcentre(const LatticeDelaunay& t, std::size_t c) {
  const auto& cell = t.cells.at(c);
  const int d = t.dim;
  // Solve 2 (p_i - p_0) . u = |p_i - p_0|^2 for u = centre - p_0 (Cramer's rule).
  std::vector<std::vector<BigInt>> m(static_cast<std::size_t>(d),
                                     std::vector<BigInt>(static_cast<std::size_t>(d)));
  std::vector<BigInt> rhs(static_cast<std::size_t>(d));
  for (int i = 0; i < d; ++i) {
    const auto iu = static_cast<std::size_t>(i);
    BigInt s = 0;
    for (int k = 0; k < d; ++k) {
      const BigInt e = coord(t, cell[iu + 1], k) - coord(t, cell[0], k);
      m[iu][static_cast<std::size_t>(k)] = 2 * e;
      s += e * e;
    }
    rhs[iu] = s;
  }
  auto det = [d](const std::vector<std::vector<BigInt>>& a) -> BigInt {
    if (d == 2) return a[0][0] * a[1][1] - a[0][1] * a[1][0];
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  };
  const BigInt den = det(m);
  if (den == 0) throw std::logic_error("circumcentre: a flat Delaunay cell");
  std::vector<Rational<BigInt>> u;
  for (int k = 0; k < d; ++k) {
    auto mk = m;
    for (int i = 0; i < d; ++i)
      mk[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)] =
          rhs[static_cast<std::size_t>(i)];
    u.push_back(Rational<BigInt>(det(mk), den) + Rational<BigInt>(coord(t, cell[0], k)));
  }
  return u;
}

std::vector<VoronoiCell> voronoi_cells(const LatticeDelaunay& t) {
  if (t.affine_dim != t.dim) {
    throw InvalidArgument("Voronoi cells: the points span " + std::to_string(t.affine_dim) +
                          " dimension(s) of " + std::to_string(t.dim) +
                          " (the cells are unbounded slabs)");
  }
  std::vector<VoronoiCell> cells(t.vertex_count());
  std::vector<std::vector<std::size_t>> around(t.vertex_count());
  const int vpc = t.dim + 1;
  for (std::size_t c = 0; c < t.cells.size(); ++c) {
    for (int i = 0; i < vpc; ++i) around[t.cells[c][static_cast<std::size_t>(i)]].push_back(c);
  }
  for (std::size_t s = 0; s < t.vertex_count(); ++s) {
    VoronoiCell& cell = cells[s];
    cell.site = s;
    cell.bounded = !t.on_hull[s];
    std::vector<std::pair<double, std::vector<Rational<BigInt>>>> vs;
    for (const std::size_t c : around[s]) {
      auto u = circumcentre(t, c);
      double angle = 0;
      if (t.dim == 2) {
        const double dx =
            to_double(u[0].num()) / to_double(u[0].den()) - static_cast<double>(t.points[2 * s]);
        const double dy = to_double(u[1].num()) / to_double(u[1].den()) -
                          static_cast<double>(t.points[2 * s + 1]);
        angle = std::atan2(dy, dx);
      }
      vs.emplace_back(angle, std::move(u));
    }
    if (t.dim == 2) {
      std::stable_sort(vs.begin(), vs.end(),
                       [](const auto& a, const auto& b) { return a.first < b.first; });
    } else {
      std::sort(vs.begin(), vs.end(),
                [](const auto& a, const auto& b) { return a.second < b.second; });
    }
    for (auto& [angle, u] : vs) {
      if (std::find(cell.vertices.begin(), cell.vertices.end(), u) == cell.vertices.end()) {
        cell.vertices.push_back(std::move(u));
      }
    }
  }
  return cells;
}

bool delaunay_nearest(const LatticeDelaunay& t, std::size_t s, const std::vector<std::int64_t>& x) {
  if (static_cast<int>(x.size()) != t.dim) {
    throw InvalidArgument("Delaunay nearest: a point of dimension " + std::to_string(x.size()));
  }
  auto dist2 = [&](std::size_t v) {
    Int128 sum = 0;
    for (int k = 0; k < t.dim; ++k) {
      const Int128 e =
          Int128(x[static_cast<std::size_t>(k)]) -
          Int128(t.points[v * static_cast<std::size_t>(t.dim) + static_cast<std::size_t>(k)]);
      sum += e * e;
    }
    return sum;
  };
  const Int128 ds = dist2(s);
  for (const std::size_t n : t.neighbours.at(s)) {
    if (dist2(n) < ds) return false;
  }
  return true;
}

} // namespace zdg
