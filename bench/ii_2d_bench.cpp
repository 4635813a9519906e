// Integral-invariant curvature in 2D along the whole boundary of the ellipse (20, 7) with
// R = 5 h^{1/3} (issue target: h = 0.001 under 2 s on one core): the symmetric-difference counter
// (O(R/h) membership queries per linel) against the contour counter (Green's formula over the
// complete boundary, O(log n) per linel, estimators/contour_ball_count.hpp). Same integers, so the
// same curvatures. With them, the curvature of the most centred maximal digital circular arc
// (estimators/mdca_curvature.hpp, parameter-free) on the same contours, for comparison.
#include <zdg/convergence/shape.hpp>
#include <zdg/estimators/ii_curvature.hpp>
#include <zdg/estimators/mdca_curvature.hpp>
#include <zdg/kernel/curves/digital_contour.hpp>

#include <benchmark/benchmark.h>

#include <cmath>

namespace {

struct Setup {
  std::unique_ptr<zdg::Shape> shape;
  std::unique_ptr<zdg::GaussDigitization2> set;
  std::vector<zdg::DigitalContour> contours;
};

Setup setup(const char* spec, double h) {
  Setup s;
  s.shape = zdg::parse_shape(spec);
  const auto& shape2 = dynamic_cast<const zdg::Shape2&>(*s.shape);
  auto n = static_cast<std::int64_t>(std::ceil(28.0 / h));
  s.set = shape2.digitize(h, {0.0, 0.0}, zdg::Box2{{-n, -n}, {n, n}});
  s.contours = zdg::digital_contours(*s.set, {0}, {});
  return s;
}

template <bool kGreen>
void BM_II(benchmark::State& state, const char* spec) {
  const double h = 1.0 / static_cast<double>(state.range(0));
  Setup s = setup(spec, h);
  const double radius = 5.0 * std::cbrt(h);
  for (auto _ : state) {
    if constexpr (kGreen) {
      zdg::ContourBallCounter counter(*s.set, s.contours, radius / h);
      auto k = zdg::ii_curvature(counter, s.contours.at(0), h, radius);
      benchmark::DoNotOptimize(k.data());
    } else {
      auto k = zdg::ii_curvature(*s.set, s.contours.at(0), h, radius);
      benchmark::DoNotOptimize(k.data());
    }
  }
  state.counters["linels"] = static_cast<double>(s.contours.at(0).size());
  state.counters["ball_radius_px"] = radius / h;
  state.counters["ns_per_linel"] = benchmark::Counter(
      static_cast<double>(s.contours.at(0).size()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_IncrementalII(benchmark::State& state, const char* spec) {
  BM_II<false>(state, spec);
}
void BM_GreenII(benchmark::State& state, const char* spec) {
  BM_II<true>(state, spec);
}

void BM_MDCA(benchmark::State& state, const char* spec) {
  const double h = 1.0 / static_cast<double>(state.range(0));
  Setup s = setup(spec, h);
  for (auto _ : state) {
    auto k = zdg::mdca_curvature(s.contours.at(0), h);
    benchmark::DoNotOptimize(k.data());
  }
  state.counters["linels"] = static_cast<double>(s.contours.at(0).size());
  state.counters["ns_per_linel"] = benchmark::Counter(
      static_cast<double>(s.contours.at(0).size()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

} // namespace

BENCHMARK_CAPTURE(BM_IncrementalII, incremental_ellipse, "ellipse:20,7")
    ->Arg(100)
    ->Arg(1000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_GreenII, green_ellipse, "ellipse:20,7")
    ->Arg(100)
    ->Arg(1000)
    ->Arg(6000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_GreenII, green_flower, "flower:20,7,6")
    ->Arg(1000)
    ->Arg(6000)
    ->Unit(benchmark::kMillisecond);

BENCHMARK_CAPTURE(BM_MDCA, mdca_ellipse, "ellipse:20,7")
    ->Arg(100)
    ->Arg(1000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_MDCA, mdca_flower, "flower:20,7,6")->Arg(1000)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
