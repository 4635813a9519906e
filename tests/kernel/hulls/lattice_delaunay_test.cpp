#include <zdg/kernel/hulls/lattice_delaunay.hpp>

#include "tests/support/tower.hpp"
#include <zdg/arith/error.hpp>
#include <zdg/kernel/transforms/voronoi_map.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <vector>

namespace zdg {
namespace {

using Q = Rational<BigInt>;

// Random lattice points: general ones, or a full grid (every 4 cocircular, 8 cospherical), or a
// grid with random holes, or collinear / coplanar ones.
std::vector<std::int64_t> random_points(int dim) {
  const int kind = *rc::gen::inRange(0, 4);
  std::vector<std::int64_t> c;
  if (kind == 1 || kind == 2) {
    const std::int64_t n = *rc::gen::inRange<std::int64_t>(2, dim == 2 ? 6 : 4);
    const std::int64_t total = dim == 2 ? n * n : n * n * n;
    for (std::int64_t i = 0; i < total; ++i) {
      if (kind == 2 && *rc::gen::inRange(0, 3) == 0) continue;
      c.push_back(i % n);
      c.push_back(i / n % n);
      if (dim == 3) c.push_back(i / (n * n));
    }
    if (c.empty()) c.assign(static_cast<std::size_t>(dim), 0);
    return c;
  }
  const int n = *rc::gen::inRange(1, 25);
  const std::int64_t span = *rc::gen::element<std::int64_t>(3, 10, 1000);
  for (int i = 0; i < n; ++i) {
    const std::int64_t t = *rc::gen::inRange<std::int64_t>(-span, span + 1);
    for (int k = 0; k < dim; ++k) {
      // kind 3: on the line / plane x_{dim-1} = t along a fixed direction.
      c.push_back(kind == 3 && k == 0 ? t : *rc::gen::inRange<std::int64_t>(-span, span + 1));
    }
    if (kind == 3) c[c.size() - 1] = 2 * c[c.size() - static_cast<std::size_t>(dim)] + 1;
  }
  return c;
}

Q dist2(const std::vector<Q>& u, const LatticeDelaunay& t, std::size_t v) {
  Q s(0);
  for (int k = 0; k < t.dim; ++k) {
    const Q e =
        u[static_cast<std::size_t>(k)] -
        Q(BigInt(t.points[v * static_cast<std::size_t>(t.dim) + static_cast<std::size_t>(k)]));
    s = s + e * e;
  }
  return s;
}

BigInt orient(const LatticeDelaunay& t, const std::vector<std::size_t>& f, std::size_t p) {
  auto x = [&](std::size_t v, int k) {
    return BigInt(t.points[v * static_cast<std::size_t>(t.dim) + static_cast<std::size_t>(k)]);
  };
  if (t.dim == 2) {
    return (x(f[1], 0) - x(f[0], 0)) * (x(p, 1) - x(f[0], 1)) -
           (x(f[1], 1) - x(f[0], 1)) * (x(p, 0) - x(f[0], 0));
  }
  BigInt a[3][3];
  for (int k = 0; k < 3; ++k) {
    a[0][k] = x(f[1], k) - x(f[0], k);
    a[1][k] = x(f[2], k) - x(f[0], k);
    a[2][k] = x(p, k) - x(f[0], k);
  }
  return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
         a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
         a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

// Delaunay's empty-sphere property, exactly: no point strictly inside the circumcircle /
// circumsphere of any cell; the cells are positively oriented; the facets met by one cell only
// are hull facets (every point on their inner side), so the cells tile the convex hull; every
// cell edge is a Delaunay-graph edge; and in 2D Euler's count T = 2n - h - 2.
TEST(LatticeDelaunay, EmptySpheresTileTheHull) {
  test::check_property([] {
    const int dim = *rc::gen::inRange(2, 4);
    const auto pts = random_points(dim);
    const LatticeDelaunay t = lattice_delaunay(pts, dim);
    RC_ASSERT(t.vertex_of_input.size() * static_cast<std::size_t>(dim) == pts.size());
    if (t.affine_dim < dim) {
      RC_ASSERT(t.cells.empty());
      return;
    }
    const std::size_t vpc = static_cast<std::size_t>(dim) + 1;
    std::map<std::vector<std::size_t>, int> facets;
    for (std::size_t c = 0; c < t.cells.size(); ++c) {
      const auto u = circumcentre(t, c);
      const Q r2 = dist2(u, t, t.cells[c][0]);
      for (std::size_t v = 0; v < t.vertex_count(); ++v) RC_ASSERT(dist2(u, t, v) >= r2);
      std::vector<std::size_t> cell(t.cells[c].begin(),
                                    t.cells[c].begin() + static_cast<std::ptrdiff_t>(vpc));
      std::vector<std::size_t> base(cell.begin(), cell.end() - 1);
      RC_ASSERT(orient(t, base, cell.back()) > 0);
      for (std::size_t i = 0; i < vpc; ++i) {
        for (std::size_t j = i + 1; j < vpc; ++j) {
          const auto& n = t.neighbours[cell[i]];
          RC_ASSERT(std::binary_search(n.begin(), n.end(), cell[j]));
        }
        // The facet opposite vertex i.
        std::vector<std::size_t> key;
        for (std::size_t j = 0; j < vpc; ++j)
          if (j != i) key.push_back(cell[j]);
        std::sort(key.begin(), key.end());
        ++facets[key];
      }
    }
    std::int64_t hull_vertices = 0;
    for (bool h : t.on_hull) hull_vertices += h;
    for (const auto& [key, count] : facets) {
      RC_ASSERT(count == 1 || count == 2);
      if (count == 2) continue;
      // A boundary facet: all points on one side (the hull's).
      int pos = 0, neg = 0;
      for (std::size_t v = 0; v < t.vertex_count(); ++v) {
        const BigInt o = orient(t, key, v);
        pos += o > 0;
        neg += o < 0;
      }
      RC_ASSERT(pos == 0 || neg == 0);
      for (auto v : key) RC_ASSERT(t.on_hull[v]);
    }
    if (dim == 2) {
      RC_ASSERT(static_cast<std::int64_t>(t.cells.size()) ==
                2 * static_cast<std::int64_t>(t.vertex_count()) - hull_vertices - 2);
    }
  });
}

// The Voronoi map of zdg transform voronoi against the triangulation of its sites: at every grid
// point the map's site is at the exact minimum squared distance (brute force over the sites),
// and the Delaunay certificate accepts it (no Delaunay neighbour strictly closer), on random
// images whose background points are the sites.
TEST(LatticeDelaunay, VoronoiMapSitesAreDelaunayNearest) {
  test::check_property([] {
    const int dim = *rc::gen::inRange(2, 4);
    std::vector<std::int64_t> ext;
    for (int k = 0; k < dim; ++k)
      ext.push_back(*rc::gen::inRange<std::int64_t>(2, dim == 2 ? 14 : 7));
    Image<std::uint8_t> img{Domain(ext), 1};
    const int sites = *rc::gen::inRange(1, 12);
    std::vector<std::int64_t> coords;
    for (int s = 0; s < sites; ++s) {
      const auto i = *rc::gen::inRange<std::int64_t>(0, img.size());
      img[i] = 0;
    }
    std::vector<std::int64_t> p(static_cast<std::size_t>(dim));
    std::map<std::int64_t, std::size_t> input_of;
    for (std::int64_t i = 0; i < img.size(); ++i) {
      if (img[i] != 0) continue;
      img.domain().point(i, p);
      input_of[i] = coords.size() / static_cast<std::size_t>(dim);
      coords.insert(coords.end(), p.begin(), p.end());
    }
    const LatticeDelaunay t = lattice_delaunay(coords, dim);
    const VoronoiMap vm = voronoi_map(img);
    // The squared distance from vertex v to the point p.
    const auto squared_distance = [](const LatticeDelaunay& tr, std::size_t v,
                                     const std::vector<std::int64_t>& x) {
      std::int64_t d = 0;
      for (std::size_t k = 0; k < x.size(); ++k) {
        const std::int64_t e = x[k] - tr.points[v * x.size() + k];
        d += e * e;
      }
      return d;
    };
    for (std::int64_t i = 0; i < img.size(); ++i) {
      img.domain().point(i, p);
      const std::size_t s = t.vertex_of_input[input_of.at(vm.site[static_cast<std::size_t>(i)])];
      std::int64_t best = -1, mine = 0;
      for (std::size_t v = 0; v < t.vertex_count(); ++v) {
        const std::int64_t d = squared_distance(t, v, p);
        if (best < 0 || d < best) best = d;
        if (v == s) mine = d;
      }
      RC_ASSERT(mine == best);
      RC_ASSERT(delaunay_nearest(t, s, p));
      // And the certificate refuses a site that is not nearest.
      for (std::size_t v = 0; v < t.vertex_count(); ++v) {
        const std::int64_t d = squared_distance(t, v, p);
        if (d > best) RC_ASSERT(!delaunay_nearest(t, v, p));
      }
    }
  });
}

// The Voronoi vertices of a site are equidistant from it and at least dim other sites, and no
// site is closer (the empty spheres again, seen from the cells).
TEST(LatticeDelaunay, VoronoiVerticesAreEquidistant) {
  test::check_property([] {
    const int dim = *rc::gen::inRange(2, 4);
    const LatticeDelaunay t = lattice_delaunay(random_points(dim), dim);
    RC_PRE(t.affine_dim == dim);
    for (const VoronoiCell& cell : voronoi_cells(t)) {
      RC_ASSERT(cell.bounded == !t.on_hull[cell.site]);
      RC_ASSERT(!cell.vertices.empty());
      for (const auto& u : cell.vertices) {
        const Q r2 = dist2(u, t, cell.site);
        int ties = 0;
        for (std::size_t v = 0; v < t.vertex_count(); ++v) {
          const Q d = dist2(u, t, v);
          RC_ASSERT(d >= r2);
          ties += d == r2;
        }
        RC_ASSERT(ties >= dim + 1);
      }
    }
  });
}

// Worked examples: the 3 x 3 grid (every square cocircular) has 8 triangles (2n - h - 2 with
// h = 8), and the centre's Voronoi cell is the unit square about it, its 4 vertices once each;
// in the 3 x 3 x 3 grid the centre's cell is the unit cube (8 vertices).
TEST(LatticeDelaunay, GridsAndTheirVoronoiCells) {
  std::vector<std::int64_t> g2;
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x) g2.insert(g2.end(), {x, y});
  const LatticeDelaunay t2 = lattice_delaunay(g2, 2);
  EXPECT_EQ(t2.cells.size(), 8u);
  const auto c2 = voronoi_cells(t2);
  const std::size_t centre2 = t2.vertex_of_input[4];
  EXPECT_TRUE(c2[centre2].bounded);
  ASSERT_EQ(c2[centre2].vertices.size(), 4u);
  std::set<std::vector<Q>> want2 = {
      {Q(1, 2), Q(1, 2)}, {Q(3, 2), Q(1, 2)}, {Q(3, 2), Q(3, 2)}, {Q(1, 2), Q(3, 2)}};
  EXPECT_EQ(std::set<std::vector<Q>>(c2[centre2].vertices.begin(), c2[centre2].vertices.end()),
            want2);
  std::vector<std::int64_t> g3;
  for (int z = 0; z < 3; ++z)
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 3; ++x) g3.insert(g3.end(), {x, y, z});
  const LatticeDelaunay t3 = lattice_delaunay(g3, 3);
  const auto c3 = voronoi_cells(t3);
  const auto& centre3 = c3[t3.vertex_of_input[13]];
  EXPECT_TRUE(centre3.bounded);
  EXPECT_EQ(centre3.vertices.size(), 8u);
  // Duplicates are merged; collinear points have edges and no cell; bad input is refused.
  const LatticeDelaunay dup = lattice_delaunay({0, 0, 0, 0, 1, 0}, 2);
  EXPECT_EQ(dup.vertex_count(), 2u);
  EXPECT_EQ(dup.vertex_of_input, (std::vector<std::size_t>{0, 0, 1}));
  EXPECT_EQ(dup.affine_dim, 1);
  EXPECT_TRUE(dup.cells.empty());
  EXPECT_EQ(dup.neighbours[0], (std::vector<std::size_t>{1}));
  EXPECT_THROW(voronoi_cells(dup), InvalidArgument);
  EXPECT_THROW(lattice_delaunay({0, 0}, 4), InvalidArgument);
  EXPECT_THROW(lattice_delaunay({}, 2), InvalidArgument);
  EXPECT_THROW(lattice_delaunay({std::int64_t{1} << 54, 0}, 2), InvalidArgument);
}

} // namespace
} // namespace zdg
