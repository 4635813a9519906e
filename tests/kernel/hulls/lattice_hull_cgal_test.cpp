// CGAL's exact hulls as the oracle for lattice_hull_2d and lattice_hull_3d (the one test file
// that includes CGAL): random integer point sets, degenerate ones included (all collinear,
// all coplanar, duplicates), compared on Exact_predicates_exact_constructions_kernel.
#include <zdg/kernel/hulls/lattice_hull_2d.hpp>
#include <zdg/kernel/hulls/lattice_hull_3d.hpp>

#include "tests/support/tower.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <set>
#include <tuple>
#include <vector>

namespace {

using namespace zdg;
using K = CGAL::Exact_predicates_exact_constructions_kernel;

// Point sets: general, on a random line, on a random plane, with duplicates.
std::vector<std::array<std::int64_t, 3>> random_points(int dim) {
  int kind = *rc::gen::inRange(0, 4);
  int n = *rc::gen::inRange(1, 60);
  // 3D spans keep 6 * volume below 2^53 (the comparison goes through double).
  std::int64_t span = dim == 2 ? *rc::gen::element<std::int64_t>(2, 5, 100, 1000000)
                               : *rc::gen::element<std::int64_t>(2, 5, 100, 10000);
  auto coord = [&] { return *rc::gen::inRange<std::int64_t>(-span, span + 1); };
  std::vector<std::array<std::int64_t, 3>> p;
  std::array<std::int64_t, 3> o{coord(), coord(), coord()}, u{coord(), coord(), coord()},
      v{coord(), coord(), coord()};
  if (dim == 2) o[2] = u[2] = v[2] = 0;
  for (int i = 0; i < n; ++i) {
    std::int64_t s = *rc::gen::inRange<std::int64_t>(-6, 7),
                 t = *rc::gen::inRange<std::int64_t>(-6, 7);
    if (kind == 0 || kind == 3) {
      p.push_back({coord(), coord(), dim == 2 ? 0 : coord()});
    } else if (kind == 1) { // collinear
      p.push_back({o[0] + s * u[0], o[1] + s * u[1], o[2] + s * u[2]});
    } else { // coplanar
      p.push_back(
          {o[0] + s * u[0] + t * v[0], o[1] + s * u[1] + t * v[1], o[2] + s * u[2] + t * v[2]});
    }
  }
  if (kind == 3) { // duplicates
    std::size_t m = p.size();
    for (std::size_t i = 0; i < m; ++i) p.push_back(p[i]);
  }
  return p;
}

template <class I>
class LatticeHullVsCgal : public ::testing::Test {};
TYPED_TEST_SUITE(LatticeHullVsCgal, test::TowerTypes, test::TowerNames);

// Oracle: CGAL::convex_hull_2 (exact kernel): the same vertex cycle, from the same start.
TYPED_TEST(LatticeHullVsCgal, Hull2dMatchesCgalConvexHull2) {
  using I = TypeParam;
  test::check_property([] {
    auto raw = random_points(2);
    std::vector<Point2<I>> pts;
    std::vector<K::Point_2> cp;
    for (auto [x, y, z] : raw) {
      pts.push_back({I(x), I(y)});
      cp.emplace_back(x, y);
    }
    auto ours = lattice_hull_2d<I>(std::span<const Point2<I>>(pts));
    std::vector<K::Point_2> theirs;
    CGAL::convex_hull_2(cp.begin(), cp.end(), std::back_inserter(theirs));
    RC_ASSERT(ours.size() == theirs.size());
    if (theirs.empty()) return;
    auto low = std::min_element(theirs.begin(), theirs.end(), [](const auto& a, const auto& b) {
      return std::make_pair(a.y(), a.x()) < std::make_pair(b.y(), b.x());
    });
    std::rotate(theirs.begin(), low, theirs.end());
    for (std::size_t i = 0; i < ours.size(); ++i) {
      RC_ASSERT(K::FT(to_double(ours[i].x)) == theirs[i].x());
      RC_ASSERT(K::FT(to_double(ours[i].y)) == theirs[i].y());
    }
  });
}

// Oracle: CGAL::extreme_points_3 (the vertex set) and CGAL::convex_hull_3 (6 * volume from
// its triangulated polyhedron, and the set of facet planes as primitive normals).
TYPED_TEST(LatticeHullVsCgal, Hull3dMatchesCgalConvexHull3) {
  using I = TypeParam;
  test::check_property([] {
    auto raw = random_points(3);
    std::vector<Point3<I>> pts;
    std::vector<K::Point_3> cp;
    for (auto [x, y, z] : raw) {
      pts.push_back({I(x), I(y), I(z)});
      cp.emplace_back(x, y, z);
    }
    auto h = lattice_hull_3d<I>(std::span<const Point3<I>>(pts));
    std::set<std::tuple<double, double, double>> ours, theirs;
    for (const auto& v : h.vertices) ours.insert({to_double(v.x), to_double(v.y), to_double(v.z)});
    if (h.dimension == 3) {
      std::vector<K::Point_3> ext;
      CGAL::extreme_points_3(cp, std::back_inserter(ext));
      for (const auto& e : ext) {
        theirs.insert({CGAL::to_double(e.x()), CGAL::to_double(e.y()), CGAL::to_double(e.z())});
      }
      RC_ASSERT(ours == theirs);
      CGAL::Polyhedron_3<K> poly;
      CGAL::convex_hull_3(cp.begin(), cp.end(), poly);
      K::FT vol6 = 0;
      const auto o = poly.vertices_begin()->point();
      std::set<std::tuple<double, double, double>> planes;
      for (auto f = poly.facets_begin(); f != poly.facets_end(); ++f) {
        auto hcirc = f->facet_begin();
        auto a = hcirc->vertex()->point();
        ++hcirc;
        auto b = hcirc->vertex()->point();
        ++hcirc;
        auto c = hcirc->vertex()->point();
        vol6 += CGAL::determinant(a - o, b - o, c - o);
        // The primitive integer normal, from the (integer, exactly stored) coordinates.
        auto big = [](const K::Point_3& q) {
          return std::array<BigInt, 3>{BigInt(CGAL::to_double(q.x())),
                                       BigInt(CGAL::to_double(q.y())),
                                       BigInt(CGAL::to_double(q.z()))};
        };
        auto A = big(a), B = big(b), C = big(c);
        std::array<BigInt, 3> u{B[0] - A[0], B[1] - A[1], B[2] - A[2]},
            w{C[0] - A[0], C[1] - A[1], C[2] - A[2]};
        BigInt nx = u[1] * w[2] - u[2] * w[1], ny = u[2] * w[0] - u[0] * w[2],
               nz = u[0] * w[1] - u[1] * w[0];
        BigInt g = gcd(gcd(nx, ny), nz);
        planes.insert({(nx / g).template convert_to<double>(),
                       (ny / g).template convert_to<double>(),
                       (nz / g).template convert_to<double>()});
      }
      RC_ASSERT(K::FT(to_double(h.volume6)) == vol6);
      std::set<std::tuple<double, double, double>> our_planes;
      for (const auto& n : h.normals)
        our_planes.insert({to_double(n.x), to_double(n.y), to_double(n.z)});
      RC_ASSERT(our_planes == planes);
      RC_ASSERT(h.normals.size() == planes.size());
    } else if (h.dimension == 2) {
      // Coplanar: CGAL's convex_hull_2 of the projection along a coordinate axis that is not
      // parallel to the plane (injective on it) gives the vertex set.
      RC_ASSERT(h.volume6 == 0);
      RC_ASSERT(h.facets.size() == 2u);
      const auto& n = h.normals[0];
      int drop = n.z != 0 ? 2 : (n.y != 0 ? 1 : 0);
      std::vector<K::Point_2> proj;
      for (auto [x, y, z] : raw) {
        proj.emplace_back(drop == 0 ? y : x, drop == 2 ? y : z);
      }
      std::vector<K::Point_2> hull2;
      CGAL::convex_hull_2(proj.begin(), proj.end(), std::back_inserter(hull2));
      std::set<std::pair<double, double>> a, b;
      for (const auto& v : h.vertices) {
        a.insert({to_double(drop == 0 ? v.y : v.x), to_double(drop == 2 ? v.y : v.z)});
      }
      for (const auto& q : hull2) b.insert({CGAL::to_double(q.x()), CGAL::to_double(q.y())});
      RC_ASSERT(a == b);
    } else {
      // A point or a segment: the lexicographic extremes.
      RC_ASSERT(h.volume6 == 0);
      RC_ASSERT(h.facets.empty());
      auto lo = *std::min_element(raw.begin(), raw.end()),
           hi = *std::max_element(raw.begin(), raw.end());
      RC_ASSERT(to_double(h.vertices.front().x) == static_cast<double>(lo[0]));
      RC_ASSERT(to_double(h.vertices.back().z) == static_cast<double>(hi[2]));
      RC_ASSERT(h.vertices.size() == (lo == hi ? 1u : 2u));
    }
  });
}

} // namespace
