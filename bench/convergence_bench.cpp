// Multigrid convergence benchmarks: integral-invariant curvature on the ellipse (20, 7) with
// R = 5 h^{1/3} (issue target: h = 0.001 under 2 s on one core), contour tracking and the
// binomial convolver.
#include "convergence/shape.hpp"
#include "estimators/binomial_convolver.hpp"
#include "estimators/ii_curvature.hpp"
#include "kernel/digital_contour.hpp"

#include <benchmark/benchmark.h>

#include <cmath>

namespace {

struct Setup {
  std::unique_ptr<zdg::Shape> shape;
  std::unique_ptr<zdg::GaussDigitization2> set;
  zdg::DigitalContour contour;
};

Setup setup(const char* spec, double h) {
  Setup s;
  s.shape = zdg::parse_shape(spec);
  const auto& shape2 = dynamic_cast<const zdg::Shape2&>(*s.shape);
  auto n = static_cast<std::int64_t>(std::ceil(21.0 / h));
  s.set = shape2.digitize(h, {0.0, 0.0}, zdg::Box2{{-n, -n}, {n, n}});
  s.contour = zdg::digital_contours(*s.set, {0}, {}).at(0);
  return s;
}

void BM_IICurvatureEllipse(benchmark::State& state) {
  const double h = 1.0 / static_cast<double>(state.range(0));
  Setup s = setup("ellipse:20,7", h);
  const double radius = 5.0 * std::cbrt(h);
  for (auto _ : state) {
    auto k = zdg::ii_curvature(*s.set, s.contour, h, radius);
    benchmark::DoNotOptimize(k.data());
  }
  state.counters["linels"] = static_cast<double>(s.contour.size());
  state.counters["ball_radius_px"] = radius / h;
}
BENCHMARK(BM_IICurvatureEllipse)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

void BM_ContourTrackingEllipse(benchmark::State& state) {
  const double h = 1.0 / static_cast<double>(state.range(0));
  Setup s = setup("ellipse:20,7", h);
  for (auto _ : state) {
    auto c = zdg::digital_contours(*s.set, {0}, {});
    benchmark::DoNotOptimize(c.data());
  }
}
BENCHMARK(BM_ContourTrackingEllipse)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

void BM_BinomialConvolverEllipse(benchmark::State& state) {
  const double h = 1.0 / static_cast<double>(state.range(0));
  Setup s = setup("ellipse:20,7", h);
  const long n = zdg::binomial_mask_order(h, 1.0);
  for (auto _ : state) {
    auto e = zdg::binomial_convolver(s.contour, h, n);
    benchmark::DoNotOptimize(e.curvature.data());
  }
}
BENCHMARK(BM_BinomialConvolverEllipse)->Arg(1000)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
