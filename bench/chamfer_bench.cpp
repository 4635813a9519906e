// Chamfer transforms (kernel/transforms/chamfer_transform.hpp) beside the exact l2 transform on
// the same inputs: a disc of radius 0.45 n in n^2 (masks <3,4> and <5,7,11>) and a ball of
// radius 0.45 n in n^3 (<3,4,5>). Arguments: n, mask (0: <3,4> / <3,4,5>; 1: <5,7,11>, 2D only).
// The chamfer transform runs on one thread; the l2 transform (Dt*L2) is given 1 thread too, so
// the counter "ns_per_voxel" compares the algorithms, not the thread counts (Google Benchmark
// prints it with an "s", as every inverted rate: "22.4s" is 22.4 ns per voxel).
//
//   build/bin/chamfer_bench --benchmark_filter='3d'
#include <zdg/kernel/transforms/chamfer_transform.hpp>
#include <zdg/kernel/transforms/distance_transform.hpp>

#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

namespace {

using zdg::Domain;
using zdg::Image;

Image<std::uint8_t> ball(int dim, std::int64_t n) {
  std::vector<std::int64_t> ext(static_cast<std::size_t>(dim), n);
  Domain dom(ext);
  Image<std::uint8_t> img(dom);
  const std::int64_t c = n / 2, r2 = (45 * n / 100) * (45 * n / 100);
  std::vector<std::int64_t> p(static_cast<std::size_t>(dim));
  for (std::int64_t i = 0; i < dom.size(); ++i) {
    dom.point(i, p);
    std::int64_t s = 0;
    for (auto x : p) s += (x - c) * (x - c);
    img[i] = s <= r2 ? 1 : 0;
  }
  return img;
}

// The nanoseconds per voxel of the timed loop (an inverted rate of size * 1e-9 voxels).
void count_voxels(benchmark::State& state, std::int64_t voxels) {
  state.counters["ns_per_voxel"] = benchmark::Counter(
      static_cast<double>(voxels) * 1e-9,
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void Chamfer(benchmark::State& state, const zdg::ChamferMask& mask) {
  const auto img = ball(mask.dim(), state.range(0));
  for (auto _ : state) {
    auto dt = zdg::chamfer_transform<std::uint32_t>(img, mask);
    benchmark::DoNotOptimize(dt.values().data());
  }
  state.SetLabel(mask.name());
  count_voxels(state, img.size());
}

void Chamfer2d(benchmark::State& state) {
  Chamfer(state,
          state.range(1) == 1 ? zdg::ChamferMask(2, {5, 7, 11}) : zdg::ChamferMask(2, {3, 4}));
}
void Chamfer3d(benchmark::State& state) {
  Chamfer(state, zdg::ChamferMask::borgefors(3));
}

void DtL2(benchmark::State& state, int dim) {
  const auto img = ball(dim, state.range(0));
  zdg::TransformOptions opt;
  opt.threads = 1;
  for (auto _ : state) {
    auto dt = zdg::distance_transform<std::uint32_t>(img, opt);
    benchmark::DoNotOptimize(dt.values().data());
  }
  state.SetLabel("l2, 1 thread");
  count_voxels(state, img.size());
}

void Dt2dL2(benchmark::State& state) {
  DtL2(state, 2);
}
void Dt3dL2(benchmark::State& state) {
  DtL2(state, 3);
}

BENCHMARK(Chamfer2d)->Args({4096, 0})->Args({4096, 1})->Unit(benchmark::kMillisecond);
BENCHMARK(Dt2dL2)->Arg(4096)->Unit(benchmark::kMillisecond);
BENCHMARK(Chamfer3d)->Arg(256)->Arg(512)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(Dt3dL2)->Arg(256)->Arg(512)->Unit(benchmark::kMillisecond)->Iterations(1);

} // namespace

BENCHMARK_MAIN();
