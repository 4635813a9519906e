// Lattice hulls: the output-sensitive disc hull for r = 10^3 .. 10^9 (vertex counts and the
// growth exponent of the time), the exact 2D hull of the lattice points of a disc of radius
// 1000 given as a point set (3.1e6 points) against CGAL's convex_hull_2, and the exact 3D
// hull of the lattice points of a ball of radius 50 (523,305 points) against CGAL's
// convex_hull_3, each on CGAL's exact-constructions kernel (Epeck) and on its
// exact-predicates kernel (Epick, the faster peer).
#include <zdg/kernel/hulls/convex_body_hull.hpp>
#include <zdg/kernel/hulls/lattice_hull_2d.hpp>
#include <zdg/kernel/hulls/lattice_hull_3d.hpp>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/convex_hull_3.h>
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace {

using namespace zdg;

void BM_DiscHull(benchmark::State& state) {
  const std::int64_t r = state.range(0);
  std::size_t v = 0;
  for (auto _ : state) {
    auto h = disc_hull_exact(Rational<BigInt>(0), Rational<BigInt>(0), Rational<BigInt>(r));
    v = h.value.vertices.size();
    benchmark::DoNotOptimize(h);
  }
  state.counters["vertices"] = static_cast<double>(v);
}
BENCHMARK(BM_DiscHull)
    ->Arg(1000)
    ->Arg(10000)
    ->Arg(100000)
    ->Arg(1000000)
    ->Arg(10000000)
    ->Arg(100000000)
    ->Arg(1000000000)
    ->Unit(benchmark::kMillisecond);

// The disc hull computed directly on a fixed type (no escalation attempt).
template <class I>
void BM_DiscHullOn(benchmark::State& state) {
  const std::int64_t r = state.range(0);
  for (auto _ : state) {
    auto h = disc_hull<I>(Rational<I>(I(0)), Rational<I>(I(0)), Rational<I>(I(r)));
    benchmark::DoNotOptimize(h);
  }
}
BENCHMARK(BM_DiscHullOn<Int64>)
    ->Arg(1000)
    ->Arg(1000000)
    ->Arg(1000000000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DiscHullOn<Int128>)->Arg(1000000)->Arg(1000000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DiscHullOn<BigInt>)->Arg(1000000)->Unit(benchmark::kMillisecond);

std::vector<Point2<Int64>> disc_points(std::int64_t r) {
  std::vector<Point2<Int64>> p;
  for (std::int64_t y = -r; y <= r; ++y) {
    for (std::int64_t x = -r; x <= r; ++x) {
      if (x * x + y * y <= r * r) p.push_back({x, y});
    }
  }
  return p;
}

void BM_PointHull2_Zdg(benchmark::State& state) {
  auto pts = disc_points(1000);
  for (auto _ : state) {
    auto h = lattice_hull_2d<Int64>(std::span<const Point2<Int64>>(pts));
    benchmark::DoNotOptimize(h);
  }
  state.counters["points"] = static_cast<double>(pts.size());
}
BENCHMARK(BM_PointHull2_Zdg)->Unit(benchmark::kMillisecond);

template <class K>
void BM_PointHull2_Cgal(benchmark::State& state) {
  auto pts = disc_points(1000);
  std::vector<typename K::Point_2> cp;
  for (const auto& p : pts) cp.emplace_back(p.x.value(), p.y.value());
  for (auto _ : state) {
    std::vector<typename K::Point_2> out;
    CGAL::convex_hull_2(cp.begin(), cp.end(), std::back_inserter(out));
    benchmark::DoNotOptimize(out);
  }
}
BENCHMARK(BM_PointHull2_Cgal<CGAL::Exact_predicates_exact_constructions_kernel>)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PointHull2_Cgal<CGAL::Exact_predicates_inexact_constructions_kernel>)
    ->Unit(benchmark::kMillisecond);

std::vector<Point3<Int64>> ball_points(std::int64_t r) {
  std::vector<Point3<Int64>> p;
  for (std::int64_t z = -r; z <= r; ++z) {
    for (std::int64_t y = -r; y <= r; ++y) {
      for (std::int64_t x = -r; x <= r; ++x) {
        if (x * x + y * y + z * z <= r * r) p.push_back({x, y, z});
      }
    }
  }
  return p;
}

void BM_BallHull3_Zdg(benchmark::State& state) {
  auto pts = ball_points(50);
  std::size_t v = 0, f = 0;
  for (auto _ : state) {
    auto h = lattice_hull_3d<Int64>(std::span<const Point3<Int64>>(pts));
    v = h.vertices.size();
    f = h.facets.size();
    benchmark::DoNotOptimize(h);
  }
  state.counters["points"] = static_cast<double>(pts.size());
  state.counters["vertices"] = static_cast<double>(v);
  state.counters["facets"] = static_cast<double>(f);
}
BENCHMARK(BM_BallHull3_Zdg)->Unit(benchmark::kMillisecond);

template <class K>
void BM_BallHull3_Cgal(benchmark::State& state) {
  auto pts = ball_points(50);
  std::vector<typename K::Point_3> cp;
  for (const auto& p : pts) cp.emplace_back(p.x.value(), p.y.value(), p.z.value());
  for (auto _ : state) {
    CGAL::Polyhedron_3<K> poly;
    CGAL::convex_hull_3(cp.begin(), cp.end(), poly);
    benchmark::DoNotOptimize(poly);
  }
}
BENCHMARK(BM_BallHull3_Cgal<CGAL::Exact_predicates_exact_constructions_kernel>)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BallHull3_Cgal<CGAL::Exact_predicates_inexact_constructions_kernel>)
    ->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
