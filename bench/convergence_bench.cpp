// Multigrid convergence benchmarks: contour tracking and the binomial convolver on the
// ellipse (20, 7) (the integral-invariant curvature, both counters, is in ii_2d_bench.cpp);
// the ground truth: project vs project_chain (warm start with a reach
// certificate) on 1e5 points near the boundary in chain order.
#include <zdg/convergence/shape.hpp>
#include <zdg/estimators/binomial_convolver.hpp>
#include <zdg/kernel/curves/digital_contour.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <vector>

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

// 1e5 points near the boundary of flower:20,7,6 (arg 0) or ellipse:20,7 (arg 1), in
// chain order, pushed off radially by up to 1e-3.
std::vector<zdg::Point2<double>> boundary_chain(int which, int n) {
  std::vector<zdg::Point2<double>> pts;
  for (int i = 0; i < n; ++i) {
    double t = -std::numbers::pi + 2 * std::numbers::pi * i / n;
    double f = 1 + 1e-3 * std::sin(1.7 * i) / 20;
    if (which == 0) {
      double r = (20 + 7 * std::cos(6 * t)) * f;
      pts.push_back({r * std::cos(t), r * std::sin(t)});
    } else {
      pts.push_back({20 * f * std::cos(t), 7 * f * std::sin(t)});
    }
  }
  return pts;
}

const char* const kChainShapes[] = {"flower:20,7,6", "ellipse:20,7"};

void BM_Project(benchmark::State& state) {
  auto shape = zdg::parse_shape(kChainShapes[state.range(0)]);
  const auto& s = dynamic_cast<const zdg::Shape2&>(*shape);
  auto pts = boundary_chain(static_cast<int>(state.range(0)), 100000);
  for (auto _ : state) {
    for (const auto& p : pts) {
      auto q = s.project(p);
      benchmark::DoNotOptimize(q);
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pts.size()));
  state.SetLabel(kChainShapes[state.range(0)]);
}
BENCHMARK(BM_Project)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_ProjectChain(benchmark::State& state) {
  auto shape = zdg::parse_shape(kChainShapes[state.range(0)]);
  const auto& s = dynamic_cast<const zdg::Shape2&>(*shape);
  auto pts = boundary_chain(static_cast<int>(state.range(0)), 100000);
  benchmark::DoNotOptimize(s.reach_lower_bound()); // the lazy reach is not timed
  for (auto _ : state) {
    auto q = s.project_chain(pts);
    benchmark::DoNotOptimize(q.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pts.size()));
  state.SetLabel(kChainShapes[state.range(0)]);
}
BENCHMARK(BM_ProjectChain)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// The linel midpoints of the digitized flower:20,7,6 at h = 1/arg, in contour order (what
// the estimators project).
void BM_ProjectChainFlowerContour(benchmark::State& state) {
  const double h = 1.0 / static_cast<double>(state.range(0));
  auto shape = zdg::parse_shape("flower:20,7,6");
  const auto& s = dynamic_cast<const zdg::Shape2&>(*shape);
  auto n = static_cast<std::int64_t>(std::ceil(28.0 / h));
  auto set = s.digitize(h, {0.0, 0.0}, zdg::Box2{{-n, -n}, {n, n}});
  auto contour = zdg::digital_contours(*set, {0}, {}).at(0);
  zdg::ContourEmbedding e{h};
  std::vector<zdg::Point2<double>> pts;
  zdg::Pixel p = contour.start;
  for (auto c : contour.codes) {
    pts.push_back(e.linel_midpoint(p, c));
    auto d = zdg::freeman_step(c);
    p = {p.x + d.x, p.y + d.y};
  }
  benchmark::DoNotOptimize(s.reach_lower_bound());
  for (auto _ : state) {
    auto q = s.project_chain(pts);
    benchmark::DoNotOptimize(q.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pts.size()));
}
BENCHMARK(BM_ProjectChainFlowerContour)
    ->Arg(3)
    ->Arg(10)
    ->Arg(100)
    ->Arg(1000)
    ->Unit(benchmark::kMillisecond);

void BM_ReachLowerBoundFlower(benchmark::State& state) {
  for (auto _ : state) {
    auto shape = zdg::parse_shape("flower:20,7,6");
    benchmark::DoNotOptimize(dynamic_cast<const zdg::Shape2&>(*shape).reach_lower_bound());
  }
}
BENCHMARK(BM_ReachLowerBoundFlower)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
