// Normals of a point cloud (estimators/point_normals.hpp, issue 37): 10^6 points uniform on the
// unit sphere (a fixed seed), the kd-tree built and the PCA normals of the k = 10 nearest
// computed (no orientation: the target of the issue is the tree and PCA), on 2 threads
// (PcaNormals); the same with the MST orientation (PcaNormalsMst). Counter: points per second.
//
//   build/bin/point_normals_bench --benchmark_filter='PcaNormals/1000000'
#include <zdg/estimators/point_normals.hpp>
#include <zdg/kernel/points/kd_tree.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

namespace {

using zdg::Point3;

std::vector<Point3<double>> sphere(std::int64_t n) {
  std::mt19937_64 rng(2026);
  std::normal_distribution<double> g;
  std::vector<Point3<double>> p;
  p.reserve(static_cast<std::size_t>(n));
  while (static_cast<std::int64_t>(p.size()) < n) {
    const double x = g(rng), y = g(rng), z = g(rng), l = std::sqrt(x * x + y * y + z * z);
    if (l > 1e-9) p.push_back({x / l, y / l, z / l});
  }
  return p;
}

void run(benchmark::State& state, zdg::PointNormalOrientation orientation) {
  const auto points = sphere(state.range(0));
  zdg::PointNormalsOptions o;
  o.k = 10;
  o.orientation = orientation;
  o.threads = static_cast<unsigned>(state.range(1));
  for (auto _ : state) {
    const zdg::KdTree tree(points);
    const zdg::PointNormals r = zdg::point_normals(tree, o);
    benchmark::DoNotOptimize(r.normals.data());
  }
  state.counters["points/s"] = benchmark::Counter(static_cast<double>(points.size()),
                                                  benchmark::Counter::kIsIterationInvariantRate);
}

void PcaNormals(benchmark::State& state) {
  run(state, zdg::PointNormalOrientation::none);
}

void PcaNormalsMst(benchmark::State& state) {
  run(state, zdg::PointNormalOrientation::mst);
}

BENCHMARK(PcaNormals)
    ->Args({100000, 2})
    ->Args({1000000, 1})
    ->Args({1000000, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(PcaNormalsMst)->Args({1000000, 2})->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
