// Digital topology on a foam-like volume: smooth random noise (three passes of a box blur of
// radius 3 over uniform noise, fixed seed) thresholded at its 80th percentile, about 20% of
// the voxels in the object, n^3 voxels. Arguments: n, threads. Counters: voxels per second of
// the object.
//
//   build/bin/topology_bench --benchmark_filter='CurveSkeleton/256/1'
// Peer comparison (scikit-image's skeletonize, Lee et al. 1994): bench/compare_skeletons.py.
#include <zdg/kernel/topology/betti_numbers.hpp>
#include <zdg/kernel/topology/connected_components.hpp>
#include <zdg/kernel/topology/critical_kernel_thinning.hpp>
#include <zdg/kernel/topology/homotopic_thinning.hpp>
#include <zdg/kernel/topology/simple_points.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <random>
#include <vector>

namespace {

using zdg::Domain;
using zdg::Image;

// One pass of a box blur of radius r along an axis of an n^3 float volume (clamped ends).
void box_blur(std::vector<float>& v, std::int64_t n, int axis, int r) {
  const std::int64_t stride = axis == 0 ? n * n : (axis == 1 ? n : 1);
  std::vector<float> line(static_cast<std::size_t>(n)), out(static_cast<std::size_t>(n));
  for (std::int64_t a = 0; a < n; ++a) {
    for (std::int64_t b = 0; b < n; ++b) {
      // The start of the line: the two other coordinates are a and b.
      const std::int64_t base =
          axis == 0 ? a * n + b : (axis == 1 ? a * n * n + b : (a * n + b) * n);
      for (std::int64_t i = 0; i < n; ++i)
        line[static_cast<std::size_t>(i)] = v[static_cast<std::size_t>(base + i * stride)];
      double s = 0;
      for (std::int64_t i = -r; i <= r; ++i)
        s += line[static_cast<std::size_t>(std::clamp<std::int64_t>(i, 0, n - 1))];
      for (std::int64_t i = 0; i < n; ++i) {
        out[static_cast<std::size_t>(i)] = static_cast<float>(s / (2 * r + 1));
        s += line[static_cast<std::size_t>(std::min(i + r + 1, n - 1))] -
             line[static_cast<std::size_t>(std::max<std::int64_t>(i - r, 0))];
      }
      for (std::int64_t i = 0; i < n; ++i)
        v[static_cast<std::size_t>(base + i * stride)] = out[static_cast<std::size_t>(i)];
    }
  }
}

const Image<std::uint8_t>& foam(std::int64_t n) {
  static std::map<std::int64_t, Image<std::uint8_t>> cache;
  auto it = cache.find(n);
  if (it != cache.end()) return it->second;
  std::mt19937_64 rng(20240613);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<float> v(static_cast<std::size_t>(n * n * n));
  for (auto& x : v) x = u(rng);
  for (int pass = 0; pass < 3; ++pass) {
    for (int axis = 0; axis < 3; ++axis) box_blur(v, n, axis, 3);
  }
  std::vector<float> sorted = v;
  auto k = sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() * 8 / 10);
  std::nth_element(sorted.begin(), k, sorted.end());
  const float t = *k;
  Image<std::uint8_t> img(Domain({n, n, n}), std::uint8_t{0});
  for (std::size_t i = 0; i < v.size(); ++i) img[static_cast<std::int64_t>(i)] = v[i] > t ? 1 : 0;
  return cache.emplace(n, std::move(img)).first->second;
}

std::int64_t object_size(const Image<std::uint8_t>& img) {
  std::int64_t c = 0;
  for (auto x : img.values()) c += x;
  return c;
}

void CurveSkeleton(benchmark::State& st) {
  const auto& img = foam(st.range(0));
  zdg::ThinningOptions opt;
  opt.skeleton = zdg::SkeletonKind::curve;
  opt.threads = static_cast<unsigned>(st.range(1));
  std::int64_t kept = 0;
  for (auto _ : st) kept = object_size(zdg::homotopic_thinning(img, opt).skeleton);
  st.counters["object"] = static_cast<double>(object_size(img));
  st.counters["skeleton"] = static_cast<double>(kept);
  st.counters["voxels_per_s"] = benchmark::Counter(static_cast<double>(object_size(img)),
                                                   benchmark::Counter::kIsIterationInvariantRate);
}

void CriticalKernelCurveSkeleton(benchmark::State& st) {
  const auto& img = foam(st.range(0));
  zdg::ThinningOptions opt;
  opt.skeleton = zdg::SkeletonKind::curve;
  opt.threads = static_cast<unsigned>(st.range(1));
  std::int64_t kept = 0, passes = 0;
  for (auto _ : st) {
    auto r = zdg::critical_kernel_thinning(img, opt);
    kept = object_size(r.skeleton);
    passes = r.passes;
  }
  st.counters["skeleton"] = static_cast<double>(kept);
  st.counters["passes"] = static_cast<double>(passes);
  st.counters["voxels_per_s"] = benchmark::Counter(static_cast<double>(object_size(img)),
                                                   benchmark::Counter::kIsIterationInvariantRate);
}

void Components(benchmark::State& st) {
  const auto& img = foam(st.range(0));
  zdg::ComponentOptions opt;
  opt.threads = static_cast<unsigned>(st.range(1));
  for (auto _ : st) benchmark::DoNotOptimize(zdg::connected_components(img, 26, opt));
  st.counters["voxels_per_s"] = benchmark::Counter(static_cast<double>(img.size()),
                                                   benchmark::Counter::kIsIterationInvariantRate);
}

void Betti(benchmark::State& st) {
  const auto& img = foam(st.range(0));
  for (auto _ : st) {
    benchmark::DoNotOptimize(
        zdg::betti_numbers(img, {3, 26, 6}, static_cast<unsigned>(st.range(1))));
  }
  st.counters["voxels_per_s"] = benchmark::Counter(static_cast<double>(img.size()),
                                                   benchmark::Counter::kIsIterationInvariantRate);
}

void SimplePointTableBuild(benchmark::State& st) {
  for (auto _ : st) {
    benchmark::DoNotOptimize(zdg::SimplePointTable({3, 26, 6}, static_cast<unsigned>(st.range(0))));
  }
}

} // namespace

BENCHMARK(CurveSkeleton)
    ->Args({128, 1})
    ->Args({256, 1})
    ->Args({512, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(CriticalKernelCurveSkeleton)
    ->Args({128, 1})
    ->Args({256, 1})
    ->Args({256, 2})
    ->Args({256, 4})
    ->Args({512, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(Components)
    ->Args({256, 1})
    ->Args({256, 2})
    ->Args({512, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(Betti)->Args({256, 1})->Args({256, 2})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(SimplePointTableBuild)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
