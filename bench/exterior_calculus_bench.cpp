// Discrete exterior calculus on a digital surface (#36, item 2): on a digital sphere of about
// 10^6 surfels (radius 235 voxels, lattice step 1), the assembly of the exterior derivatives
// d0 and d1 (integer incidence matrices), of the Hodge stars with the corrected measures (the
// sphere's exact normal at each surfel centre), and the exact ranks of d0 and d1 modulo two
// primes that give the harmonic dimension (0 on a sphere). One thread.
//   build/bin/exterior_calculus_bench --benchmark_counters_tabular=true
#include <zdg/kernel/calculus/exterior_derivative.hpp>
#include <zdg/kernel/calculus/harmonic_dimension.hpp>
#include <zdg/kernel/calculus/hodge_star.hpp>
#include <zdg/kernel/surfaces/digital_surface.hpp>
#include <zdg/kernel/surfaces/surfel_complex.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <map>

namespace {

struct Sphere {
  zdg::SurfelComplex complex;
  std::vector<zdg::Point3<double>> normals;
};

// The digital sphere of radius r voxels and its exact normals at the surfel centres.
const Sphere& sphere(std::int64_t r) {
  static std::map<std::int64_t, Sphere> cache;
  auto it = cache.find(r);
  if (it != cache.end()) return it->second;
  Sphere s;
  const std::int64_t r2 = r * r;
  const zdg::VoxelPredicate inside = [r2](const zdg::Voxel& z) {
    return z.x * z.x + z.y * z.y + z.z * z.z <= r2;
  };
  const std::int64_t n = r + 2;
  const auto surfels = zdg::boundary_surfels(inside, zdg::VoxelBox{{-n, -n, -n}, {n, n, n}});
  s.complex = zdg::surfel_complex(zdg::primal_surface(surfels), 1.0);
  for (const auto& c : s.complex.centres) {
    const double l = std::sqrt(dot(c, c));
    s.normals.push_back((1 / l) * c);
  }
  return cache.emplace(r, std::move(s)).first->second;
}

void counters(benchmark::State& state, const Sphere& s) {
  state.counters["surfels"] = double(s.complex.surfel_count());
  state.counters["linels"] = double(s.complex.linel_count());
  state.counters["pointels"] = double(s.complex.pointel_count());
}

void BM_ExteriorDerivatives(benchmark::State& state) {
  const Sphere& s = sphere(state.range(0));
  for (auto _ : state) {
    const auto d0 = zdg::primal_d0(s.complex);
    const auto d1 = zdg::primal_d1(s.complex);
    benchmark::DoNotOptimize(d0.column.data());
    benchmark::DoNotOptimize(d1.column.data());
  }
  counters(state, s);
}
BENCHMARK(BM_ExteriorDerivatives)->Arg(40)->Arg(235)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_HodgeStarsCorrected(benchmark::State& state) {
  const Sphere& s = sphere(state.range(0));
  for (auto _ : state) {
    const auto h = zdg::hodge_stars(s.complex, zdg::CellMeasure::corrected_absolute, s.normals);
    benchmark::DoNotOptimize(h.star1.data());
  }
  counters(state, s);
}
BENCHMARK(BM_HodgeStarsCorrected)->Arg(40)->Arg(235)->Unit(benchmark::kMillisecond)->UseRealTime();

// Assembly of d0, d1 and the two exact ranks of each (two primes): the harmonic dimension.
void BM_HarmonicDimensionExact(benchmark::State& state) {
  const Sphere& s = sphere(state.range(0));
  std::int64_t dim = -1;
  for (auto _ : state) dim = zdg::harmonic_dimension(s.complex).dimension;
  if (dim != 0) std::abort(); // a sphere: no harmonic 1-form
  counters(state, s);
  state.counters["harmonic_dim"] = double(dim);
}
BENCHMARK(BM_HarmonicDimensionExact)
    ->Arg(40)
    ->Arg(235)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

} // namespace

BENCHMARK_MAIN();
