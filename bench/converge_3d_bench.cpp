// 3D multigrid convergence benchmarks, the parts the driver adds around the II estimators
// (estimators/ii_3d.hpp has its own benchmark): exact membership of the polynomial shapes,
// digitization with seeds and surface tracking, the ground truth (projection and curvatures)
// per surfel, and one whole ii-mean run of the registry (sphere9, goursat).
#include <zdg/convergence/digitized_3d.hpp>
#include <zdg/convergence/estimator.hpp>

#include <benchmark/benchmark.h>

#include <cmath>

namespace {

zdg::RunInput input(const zdg::Shape& s, double h, double t) {
  return zdg::RunInput{s, h, {t, -t / 2, t / 3}, *s.bounding_box(), 3.0, 1.0 / 3.0};
}

void BM_Membership(benchmark::State& state, const char* spec) {
  auto shape = zdg::parse_shape(spec);
  auto pred = zdg::detail::as_3d(*shape).digitize(0.05, {0.01, 0.02, 0.03});
  std::int64_t n = 0, i = 0;
  for (auto _ : state) {
    zdg::Voxel z{(i * 37) % 400 - 200, (i * 11) % 400 - 200, (i * 5) % 400 - 200};
    n += pred(z) ? 1 : 0;
    ++i;
  }
  benchmark::DoNotOptimize(n);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK_CAPTURE(BM_Membership, sphere9, "sphere9");
BENCHMARK_CAPTURE(BM_Membership, goursat, "goursat");
BENCHMARK_CAPTURE(BM_Membership, torus, "torus");

void BM_DigitizeAndTrack(benchmark::State& state, const char* spec) {
  auto shape = zdg::parse_shape(spec);
  const double h = 1.0 / static_cast<double>(state.range(0));
  std::size_t n = 0;
  for (auto _ : state) {
    auto d = zdg::detail::digitize_3d(input(*shape, h, 0.01));
    n = d.surfels.size();
  }
  state.counters["surfels"] = static_cast<double>(n);
}
BENCHMARK_CAPTURE(BM_DigitizeAndTrack, sphere9, "sphere9")->Arg(10)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_DigitizeAndTrack, goursat, "goursat")->Arg(10)->Unit(benchmark::kMillisecond);

void BM_GroundTruth(benchmark::State& state, const char* spec) {
  auto shape = zdg::parse_shape(spec);
  const auto& s3 = zdg::detail::as_3d(*shape);
  auto d = zdg::detail::digitize_3d(input(*shape, 0.25, 0.01));
  std::size_t i = 0;
  double sum = 0;
  for (auto _ : state) {
    auto c = zdg::surfel_centre(d.surfels[i++ % d.surfels.size()], 0.25);
    sum += s3.project(c).mean;
  }
  benchmark::DoNotOptimize(sum);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK_CAPTURE(BM_GroundTruth, sphere9, "sphere9");
BENCHMARK_CAPTURE(BM_GroundTruth, goursat, "goursat");

// A whole registry run (digitize, track, ball moments, ground truth, errors); each
// iteration uses a new translation so that the shared II cache never answers.
void BM_IIMeanRun(benchmark::State& state, const char* spec) {
  auto shape = zdg::parse_shape(spec);
  const double h = 1.0 / static_cast<double>(state.range(0));
  const auto& est = zdg::find_estimator("ii-mean");
  int i = 0;
  std::int64_t n = 0;
  for (auto _ : state) {
    n = est.run(input(*shape, h, 0.001 * ++i)).n;
  }
  state.counters["surfels"] = static_cast<double>(n);
}
BENCHMARK_CAPTURE(BM_IIMeanRun, sphere9, "sphere9")->Arg(10)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_IIMeanRun, goursat, "goursat")->Arg(10)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
