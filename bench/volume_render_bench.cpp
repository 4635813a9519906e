// Direct volume rendering (kernel/render/volume_render.hpp, issue 37 item 5): a synthetic CT-like
// n^3 int16 volume (a shell of "bone" at 1000 HU around "soft tissue" at 40 HU in air at
// -1000 HU, with a ramp of noise), rendered at 512 x 512 from the default view by compositing
// through the ct-bone preset (Composite) or by the maximum intensity projection over exact
// digital rays (Mip). Arguments: n, threads (0 = all cores).
//
//   build/bin/volume_render_bench --benchmark_counters_tabular=true
#include <zdg/kernel/render/volume_render.hpp>

#include <benchmark/benchmark.h>

#include <cstring>
#include <vector>

namespace {

zdg::ScalarVolume ct_phantom(std::int64_t n) {
  zdg::NpyArray a;
  a.dtype = zdg::DType::I16;
  a.shape = {n, n, n};
  std::vector<std::int16_t> v(static_cast<std::size_t>(n * n * n));
  const double c = (n - 1) / 2.0, r2 = (0.45 * n) * (0.45 * n), s2 = (0.38 * n) * (0.38 * n);
  for (std::int64_t z = 0; z < n; ++z)
    for (std::int64_t y = 0; y < n; ++y)
      for (std::int64_t x = 0; x < n; ++x) {
        const double d2 = (x - c) * (x - c) + (y - c) * (y - c) + (z - c) * (z - c);
        const auto i = static_cast<std::size_t>((z * n + y) * n + x);
        const int noise = static_cast<int>((i * 2654435761u) % 41) - 20;
        v[i] = static_cast<std::int16_t>((d2 > r2 ? -1000 : d2 > s2 ? 1000 : 40) + noise);
      }
  a.bytes.resize(v.size() * 2);
  std::memcpy(a.bytes.data(), v.data(), a.bytes.size());
  return zdg::make_scalar_volume(std::move(a));
}

void run(benchmark::State& state, bool mip) {
  const auto vol = ct_phantom(state.range(0));
  zdg::VolumeRenderOptions o;
  o.width = o.height = 512;
  o.mip = mip;
  o.threads = static_cast<unsigned>(state.range(1));
  const auto tf = zdg::transfer_function_preset("ct-bone", -1000, 1000);
  std::int64_t samples = 0;
  for (auto _ : state) {
    const auto r = zdg::render_volume(vol, tf, o);
    samples = r.samples;
    benchmark::DoNotOptimize(r.picture.rgb.data());
  }
  state.counters["samples"] = static_cast<double>(samples);
  state.counters["samples_per_s"] = benchmark::Counter(
      static_cast<double>(samples), benchmark::Counter::kIsIterationInvariantRate);
}

void Composite(benchmark::State& state) {
  run(state, false);
}
void Mip(benchmark::State& state) {
  run(state, true);
}

BENCHMARK(Composite)->Args({128, 0})->Args({256, 0})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Mip)->Args({128, 0})->Args({256, 0})->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
