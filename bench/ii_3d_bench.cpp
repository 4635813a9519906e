// The target case of the 3D integral invariants: sphere1 (the unit sphere, box
// [-1.25, 1.25]^3) at h = 0.025 with R = 3 h^{1/3} (R/h ~ 35 voxels, ~30,000 surfels).
// The unit sphere at h = 1/40 is digitized exactly by the integer predicate |z|^2 <= 40^2.
//   build/bin/ii_3d_bench --benchmark_counters_tabular=true
#include <zdg/estimators/ii_3d.hpp>

#include <benchmark/benchmark.h>

#include <cmath>

namespace {

constexpr std::int64_t kN = 40; // h = 1 / kN
const double kH = 1.0 / double(kN);
const double kR = 3.0 * std::cbrt(kH);
const zdg::VoxelBox kBox{{-50, -50, -50}, {50, 50, 50}};

const zdg::VoxelPredicate& sphere1() {
  static const zdg::VoxelPredicate in = [](const zdg::Voxel& z) {
    return z.x * z.x + z.y * z.y + z.z * z.z <= kN * kN;
  };
  return in;
}

const std::vector<zdg::Surfel>& surface() {
  static const auto s =
      zdg::track_surface(sphere1(), kBox, zdg::find_boundary_surfel(sphere1(), kBox, {0, 0, 0}));
  return s;
}

void BM_TrackSurface(benchmark::State& state) {
  for (auto _ : state) {
    const auto s =
        zdg::track_surface(sphere1(), kBox, zdg::find_boundary_surfel(sphere1(), kBox, {0, 0, 0}));
    benchmark::DoNotOptimize(s.data());
    state.counters["surfels"] = double(s.size());
  }
}

void BM_ScanSurface(benchmark::State& state) {
  for (auto _ : state) {
    const auto s = zdg::boundary_surfels(sphere1(), kBox);
    benchmark::DoNotOptimize(s.data());
  }
}

void BM_IIMeanCurvature(benchmark::State& state) {
  const int threads = int(state.range(0));
  double max_err = 0;
  for (auto _ : state) {
    const auto H = zdg::ii_mean_curvature(sphere1(), kBox, surface(), kH, kR, threads);
    max_err = 0;
    for (const double v : H) max_err = std::max(max_err, std::abs(v - 1.0));
  }
  const auto m = zdg::ii_surfel_moments(sphere1(), kBox, surface(), zdg::ii_digital_radius2(kR, kH),
                                        threads, false);
  state.counters["surfels"] = double(surface().size());
  state.counters["r"] = kR / kH;
  state.counters["centres"] = double(m.stats.voxels);
  state.counters["full"] = double(m.stats.full_counts);
  state.counters["moves"] = double(m.stats.unit_moves);
  state.counters["evals"] = double(m.stats.predicate_evaluations);
  state.counters["linf_err"] = max_err;
}

void BM_IIPrincipalCurvatures(benchmark::State& state) {
  const int threads = int(state.range(0));
  double max_err = 0;
  for (auto _ : state) {
    const auto P = zdg::ii_principal_curvatures(sphere1(), kBox, surface(), kH, kR, threads);
    max_err = 0;
    for (const auto& p : P)
      max_err = std::max({max_err, std::abs(p.k1 - 1.0), std::abs(p.k2 - 1.0)});
  }
  state.counters["surfels"] = double(surface().size());
  state.counters["linf_err"] = max_err;
}

BENCHMARK(BM_TrackSurface)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ScanSurface)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_IIMeanCurvature)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_IIPrincipalCurvatures)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
