// Calculus on digital surfaces (#14): the speed targets of the issue, on the unit sphere
// digitized at step h (sphere1 at h = 0.025: about 30,000 surfels) and on a sphere of about
// 10^6 surfels (radius 235 voxels).
//   build/bin/calculus_bench --benchmark_counters_tabular=true
// Steps: the heat-kernel Laplace-Beltrami operator applied to one function (t = h^0.4,
// truncation 5 sqrt(2t); 2 threads), the heat-method geodesic distance from one source
// (assembly, two factorizations, two solves; CHOLMOD when built with it), the
// Ambrosio-Tortorelli normals with 3 epsilon levels. The weights are h^2 n .
// n_elem with the unit sphere's exact normal at the surfel centre (the benchmark times the
// operators, not the II).
#include <zdg/estimators/ambrosio_tortorelli.hpp>
#include <zdg/estimators/heat_geodesics.hpp>
#include <zdg/estimators/heat_laplace_beltrami.hpp>
#include <zdg/kernel/surfaces/digital_surface.hpp>
#include <zdg/kernel/surfaces/surfel_complex.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <map>

namespace {

struct Sphere {
  zdg::SurfelComplex complex;
  std::vector<zdg::Point3<double>> normals;
  std::vector<double> weights;
};

// The sphere of radius 1 at step h (voxel z inside iff |h z| <= 1), with its exact normals.
const Sphere& sphere(double h) {
  static std::map<double, Sphere> cache;
  auto it = cache.find(h);
  if (it != cache.end()) return it->second;
  Sphere s;
  const double r2 = 1 / (h * h);
  const zdg::VoxelPredicate inside = [r2](const zdg::Voxel& z) {
    return double(z.x * z.x + z.y * z.y + z.z * z.z) <= r2;
  };
  const auto n = static_cast<std::int64_t>(std::ceil(1 / h)) + 2;
  const auto surfels = zdg::boundary_surfels(inside, zdg::VoxelBox{{-n, -n, -n}, {n, n, n}});
  s.complex = zdg::surfel_complex(zdg::primal_surface(surfels), h);
  for (std::int64_t i = 0; i < s.complex.surfel_count(); ++i) {
    const auto c = s.complex.centres[std::size_t(i)];
    const double l = std::sqrt(c.x * c.x + c.y * c.y + c.z * c.z);
    const zdg::Point3<double> nn{c.x / l, c.y / l, c.z / l};
    const auto e = s.complex.normals[std::size_t(i)];
    s.normals.push_back(nn);
    s.weights.push_back(h * h * (nn.x * e.x + nn.y * e.y + nn.z * e.z));
  }
  return cache.emplace(h, std::move(s)).first->second;
}

// h as the benchmark argument in 1/10000.
double step(const benchmark::State& state) {
  return double(state.range(0)) / 10000.0;
}

void BM_HeatLaplaceBeltramiApply(benchmark::State& state) {
  const double h = step(state);
  const Sphere& s = sphere(h);
  const zdg::HeatLaplaceBeltrami L(s.complex.centres, s.weights, zdg::heat_kernel_time(h, 0.4), 5.0,
                                   2);
  std::vector<double> u;
  for (const auto& p : s.complex.centres) u.push_back(p.x * p.x - p.y * p.y);
  for (auto _ : state) benchmark::DoNotOptimize(L.apply(u));
  state.counters["surfels"] = double(s.complex.surfel_count());
  state.counters["pairs_per_s"] =
      benchmark::Counter(double(L.pair_count()), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_HeatLaplaceBeltramiApply)
    ->Arg(500)
    ->Arg(250)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// 10^6 surfels: a sphere of radius 235 voxels (h = 1/235), the kernel at t = 4 voxels^2 (the
// scale of a user's volume, zdg surface at one voxel: truncated 14 voxels away, about 900
// surfels per kernel).
void BM_HeatLaplaceBeltramiMillion(benchmark::State& state) {
  const double h = 1.0 / 235;
  const Sphere& s = sphere(h);
  const zdg::HeatLaplaceBeltrami L(s.complex.centres, s.weights, 4 * h * h, 5.0, 2);
  std::vector<double> u;
  for (const auto& p : s.complex.centres) u.push_back(std::exp(p.z));
  for (auto _ : state) benchmark::DoNotOptimize(L.apply(u));
  state.counters["surfels"] = double(s.complex.surfel_count());
  state.counters["pairs"] = double(L.pair_count());
}
BENCHMARK(BM_HeatLaplaceBeltramiMillion)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

void BM_HeatGeodesics(benchmark::State& state) {
  const double h = step(state);
  const Sphere& s = sphere(h);
  for (auto _ : state) {
    const zdg::HeatGeodesics geo(s.complex, s.normals, s.weights);
    benchmark::DoNotOptimize(geo.distance(0));
  }
  state.counters["surfels"] = double(s.complex.surfel_count());
}
BENCHMARK(BM_HeatGeodesics)->Arg(500)->Arg(250)->Unit(benchmark::kMillisecond)->UseRealTime();

// Ambrosio-Tortorelli normals with 3 epsilon levels (2, 1, 0.5), at most 10 alternating steps
// each, from the exact normals plus a deterministic perturbation (so that there is work).
void BM_ATNormals(benchmark::State& state) {
  const double h = step(state);
  const Sphere& s = sphere(h);
  std::vector<zdg::Point3<double>> g;
  for (std::size_t i = 0; i < s.normals.size(); ++i) {
    const auto n = s.normals[i];
    const double e = 0.1 * std::sin(double(i) * 12.9898);
    zdg::Point3<double> p{n.x + e, n.y - e, n.z + 0.5 * e};
    const double l = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
    g.push_back({p.x / l, p.y / l, p.z / l});
  }
  zdg::ATParameters p;
  p.epsilon1 = 2;
  p.epsilon2 = 0.5;
  int iterations = 0;
  for (auto _ : state) {
    const auto r = zdg::at_normals(s.complex, g, p);
    iterations = r.iterations;
    benchmark::DoNotOptimize(r.normals.data());
  }
  state.counters["surfels"] = double(s.complex.surfel_count());
  state.counters["iterations"] = iterations;
}
BENCHMARK(BM_ATNormals)->Arg(500)->Arg(250)->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
