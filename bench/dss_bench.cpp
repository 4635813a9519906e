// Benchmarks of the DSS kernel: recognition of a 10^7-point DSS point by point (target
// <= 0.08 s on one core), the tangential cover of the contour of a digitized disc of radius
// 10^5, and DSL subsegment queries with values near 2^62 (SmartDSS and ReversedSmartDSS).
//
//   build/bin/dss_bench --benchmark_filter=. --benchmark_min_time=1s
#include "tests/support/contours.hpp"
#include <zdg/arith/dsl_subsegment.hpp>
#include <zdg/arith/dss_recognizer.hpp>
#include <zdg/kernel/curves/maximal_segments.hpp>

#include <benchmark/benchmark.h>

#include <array>
#include <cstdint>
#include <random>
#include <vector>

namespace {

using namespace zdg;

std::vector<Point2<std::int64_t>> dss_points(std::size_t n, std::int64_t x0, std::int64_t y0) {
  // A naive line of slope 4142136/10000001 (period longer than the segment), shifted far away.
  DigitalStraightLine<Int64> line(4142136, 10000001, 0);
  auto pts = line.points(line.upper_leaning_point(), n);
  std::vector<Point2<std::int64_t>> out;
  out.reserve(n);
  for (const auto& p : pts) out.push_back({p.x.value() + x0, p.y.value() + y0});
  return out;
}

void BM_RecognizeDss(benchmark::State& state) {
  const std::int64_t off = state.range(1) != 0 ? (std::int64_t{1} << 62) : 0;
  auto pts = dss_points(static_cast<std::size_t>(state.range(0)), off, -off);
  for (auto _ : state) {
    auto r = recognize_dss_exact(pts, Connectivity::eight);
    if (!r.value.is_dss) state.SkipWithError("not a DSS");
    benchmark::DoNotOptimize(r);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_RecognizeDss)->Args({10000000, 0})->Args({10000000, 1})->Unit(benchmark::kMillisecond);

void BM_RecognizerExtendFront(benchmark::State& state) {
  auto pts = dss_points(static_cast<std::size_t>(state.range(0)), 0, 0);
  for (auto _ : state) {
    DssRecognizer<Int64> rec({pts[0].x, pts[0].y});
    for (std::size_t k = 1; k < pts.size(); ++k) {
      if (!rec.extend_front({pts[k].x, pts[k].y})) state.SkipWithError("not a DSS");
    }
    benchmark::DoNotOptimize(rec);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_RecognizerExtendFront)->Arg(10000000)->Unit(benchmark::kMillisecond);

void BM_TangentialCoverDisc(benchmark::State& state) {
  const std::int64_t r = state.range(0);
  auto c = test::disc_contour(0, 0, r * r);
  std::size_t segments = 0;
  for (auto _ : state) {
    auto s = maximal_segments_exact(c, true).value;
    segments = s.size();
    benchmark::DoNotOptimize(s);
  }
  state.counters["points"] = static_cast<double>(c.size());
  state.counters["segments"] = static_cast<double>(segments);
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(c.size()));
}
BENCHMARK(BM_TangentialCoverDisc)
    ->Arg(1000)
    ->Arg(10000)
    ->Arg(100000)
    ->Unit(benchmark::kMillisecond);

// Subsegment queries on a line with a, b, mu near 2^62, window of 2^k points starting near
// -2^62, through the escalating front-end (the reversed climb; BigInt arguments).
void BM_SubsegmentNear2To62(benchmark::State& state) {
  const BigInt b = (BigInt(1) << 62) - 57, a = (BigInt(1) << 61) + 987654321;
  const BigInt mu = -(BigInt(1) << 61) + 12345;
  std::mt19937_64 rng(42);
  std::vector<BigInt> starts;
  for (int i = 0; i < 64; ++i) starts.push_back(-(BigInt(1) << 62) + BigInt(rng() >> 2));
  const BigInt len = BigInt(1) << state.range(0);
  std::size_t i = 0;
  for (auto _ : state) {
    const BigInt& x0 = starts[i++ % starts.size()];
    auto r = dsl_subsegment_exact(a, b, mu, x0, x0 + len);
    benchmark::DoNotOptimize(r);
  }
}
BENCHMARK(BM_SubsegmentNear2To62)->DenseRange(4, 60, 8)->Arg(61)->Unit(benchmark::kMicrosecond);

// The same on Int128: the reversed climb (ReversedSmartDSS) and, for comparison, the two
// floor-sum searches kept as oracles.
template <class F>
void subsegment_int128(benchmark::State& state, F&& algo) {
  const Int128 b = (Int128(1) * (std::int64_t{1} << 62)) - 57;
  const Int128 a = Int128(std::int64_t{1} << 61) + 987654321, mu = 12345;
  const Int128 len = Int128(std::int64_t{1}) * (std::int64_t{1} << state.range(0));
  std::int64_t x0 = -(std::int64_t{1} << 62) + 99991;
  for (auto _ : state) {
    auto r = algo(a, b, mu, Int128(x0), Int128(x0) + len);
    benchmark::DoNotOptimize(r);
    x0 += 7919;
  }
}
void BM_SubsegmentInt128Reversed(benchmark::State& state) {
  subsegment_int128(state, [](const auto&... v) { return subsegment_reversed_smart_dss(v...); });
}
void BM_SubsegmentInt128OracleBottomUp(benchmark::State& state) {
  subsegment_int128(state, [](const auto&... v) { return subsegment_bottom_up(v...); });
}
void BM_SubsegmentInt128OracleTopDown(benchmark::State& state) {
  subsegment_int128(state, [](const auto&... v) { return subsegment_top_down_search(v...); });
}
BENCHMARK(BM_SubsegmentInt128Reversed)
    ->DenseRange(4, 60, 8)
    ->Arg(61)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SubsegmentInt128OracleBottomUp)
    ->Arg(4)
    ->Arg(20)
    ->Arg(40)
    ->Arg(61)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SubsegmentInt128OracleTopDown)
    ->Arg(4)
    ->Arg(20)
    ->Arg(40)
    ->Arg(61)
    ->Unit(benchmark::kMicrosecond);

// SmartDSS (top-down) against the reversed climb on Int128, windows of W points (W = 10 ..
// 2^61) on 64 lines with b near 2^62, random a, mu and x0 near +-2^62, half of the slopes
// close to a simple fraction (long Stern-Brocot runs); the same queries for both.
struct SubsegmentQuery {
  Int128 a, b, mu, x0, x1;
};
std::vector<SubsegmentQuery> subsegment_queries(std::int64_t width) {
  std::mt19937_64 rng(7);
  std::vector<SubsegmentQuery> out;
  for (int i = 0; i < 64; ++i) {
    const std::int64_t b = (std::int64_t{1} << 62) - static_cast<std::int64_t>(rng() >> 40);
    std::int64_t a = static_cast<std::int64_t>(rng() % static_cast<std::uint64_t>(b));
    if (i % 2 == 1) a = b / (2 + i % 5) + static_cast<std::int64_t>(rng() % 7); // long runs
    const auto x0 = static_cast<std::int64_t>(rng() >> 1) - (std::int64_t{1} << 62);
    const auto mu = static_cast<std::int64_t>(rng() >> 1) - (std::int64_t{1} << 62);
    out.push_back({Int128(a), Int128(b), Int128(mu), Int128(x0), Int128(x0) + Int128(width)});
  }
  return out;
}
template <class F>
void subsegment_width(benchmark::State& state, F&& algo) {
  const auto queries = subsegment_queries(state.range(0));
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& q = queries[i++ % queries.size()];
    auto r = algo(q.a, q.b, q.mu, q.x0, q.x1);
    benchmark::DoNotOptimize(r);
  }
}
void BM_SubsegmentWidthInt128Smart(benchmark::State& state) {
  subsegment_width(state, [](const auto&... v) { return subsegment_smart_dss(v...); });
}
void BM_SubsegmentWidthInt128Reversed(benchmark::State& state) {
  subsegment_width(state, [](const auto&... v) { return subsegment_reversed_smart_dss(v...); });
}
void subsegment_widths(benchmark::internal::Benchmark* b) {
  for (std::int64_t w :
       {std::int64_t{10}, std::int64_t{1000}, std::int64_t{1000000}, std::int64_t{1000000000},
        std::int64_t{1000000000000}, std::int64_t{1000000000000000}, std::int64_t{1} << 61}) {
    b->Arg(w);
  }
  b->Unit(benchmark::kMicrosecond);
}
BENCHMARK(BM_SubsegmentWidthInt128Smart)->Apply(subsegment_widths);
BENCHMARK(BM_SubsegmentWidthInt128Reversed)->Apply(subsegment_widths);

// The same queries through the escalating front-end (BigInt arguments), SmartDSS.
void BM_SubsegmentWidthExactSmart(benchmark::State& state) {
  std::vector<std::array<BigInt, 5>> queries;
  for (const auto& q : subsegment_queries(state.range(0))) {
    queries.push_back(
        {to_bigint(q.a), to_bigint(q.b), to_bigint(q.mu), to_bigint(q.x0), to_bigint(q.x1)});
  }
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& q = queries[i++ % queries.size()];
    auto r = dsl_subsegment_exact(q[0], q[1], q[2], q[3], q[4], DslSubsegmentAlgorithm::smart_dss);
    benchmark::DoNotOptimize(r);
  }
}
BENCHMARK(BM_SubsegmentWidthExactSmart)->Apply(subsegment_widths);

} // namespace

BENCHMARK_MAIN();
