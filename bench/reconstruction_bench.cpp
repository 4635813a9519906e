// Implicit reconstruction from oriented points (estimators/implicit_reconstruction.hpp, issue
// #37 item 3): points uniform on the unit sphere with their exact normals.
//   BM_WindingGrid/N/G    the generalized winding numbers of N points on a G^3 grid by the tree
//                         (beta 2), point areas and tree included; the #37 target is G = 256
//                         in <= 10 s on 2 threads
//   BM_Poisson/N          CGAL's Poisson field of N points sampled on a 64^3 grid
//   BM_Method/M/N         each method's field of N points at h = 1/32 (a 70^3 grid)
// Run with 2 threads:
//   build/bin/reconstruction_bench --benchmark_counters_tabular=true
#include <zdg/estimators/implicit_reconstruction.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

namespace {

zdg::PointCloud sphere(std::size_t n) {
  std::mt19937_64 rng(1);
  std::normal_distribution<double> g;
  zdg::PointCloud c;
  while (c.size() < n) {
    zdg::Point3<double> u{g(rng), g(rng), g(rng)};
    const double l = std::sqrt(dot(u, u));
    if (l < 1e-9) continue;
    u = u * (1 / l);
    c.points.push_back(u);
    c.normals.push_back(u);
  }
  return c;
}

zdg::SampleGrid cube_grid(std::int64_t g) {
  zdg::SampleGrid grid;
  grid.h = 2.4 / double(g);
  const std::int64_t lo = -g / 2;
  grid.lower = {lo, lo, lo};
  grid.nx = grid.ny = grid.nz = g;
  return grid;
}

void BM_WindingGrid(benchmark::State& state) {
  const auto cloud = sphere(std::size_t(state.range(0)));
  const auto grid = cube_grid(state.range(1));
  zdg::ReconstructionOptions o;
  o.method = zdg::ReconstructionMethod::winding;
  o.threads = 2;
  double inside = 0;
  for (auto _ : state) {
    const auto f = zdg::reconstruct_field(cloud, grid, o);
    inside = 0;
    for (double v : f.values) inside += v < 0;
    benchmark::DoNotOptimize(f.values.data());
  }
  state.counters["samples"] = double(grid.size());
  state.counters["inside"] = inside;
}
BENCHMARK(BM_WindingGrid)
    ->Args({100000, 64})
    ->Args({100000, 256})
    ->Args({1000000, 256})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

void BM_Poisson(benchmark::State& state) {
  const auto cloud = sphere(std::size_t(state.range(0)));
  const auto grid = cube_grid(64);
  zdg::ReconstructionOptions o;
  o.method = zdg::ReconstructionMethod::poisson;
  for (auto _ : state) {
    const auto f = zdg::reconstruct_field(cloud, grid, o);
    benchmark::DoNotOptimize(f.values.data());
  }
}
BENCHMARK(BM_Poisson)
    ->Arg(10000)
    ->Arg(100000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

void BM_Method(benchmark::State& state) {
  const auto cloud = sphere(std::size_t(state.range(1)));
  zdg::ReconstructionOptions o;
  o.method = static_cast<zdg::ReconstructionMethod>(state.range(0));
  o.threads = 2;
  const auto grid = zdg::grid_around(cloud, 1.0 / 32);
  for (auto _ : state) {
    const auto f = zdg::reconstruct_field(cloud, grid, o);
    benchmark::DoNotOptimize(f.values.data());
  }
  state.SetLabel(zdg::to_string(o.method));
}
BENCHMARK(BM_Method)
    ->ArgsProduct({{0, 1, 3, 4}, {10000}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

} // namespace

BENCHMARK_MAIN();
