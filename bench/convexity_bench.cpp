// Digital convexity (kernel/hulls/digital_convexity.hpp): full convexity of the lattice points of
// a digital ball (H-convex, and fully convex) of radius R = 40, 62, 100 (62: about 10^6 points,
// the #39 target is <= 2 s), the H-convexity test alone, and the ellipsoid x^2/a^2 + y^2/b^2 +
// z^2/c^2 <= 1 with (a, b, c) = (120, 80, 30) (about 1.2 10^6 points). Counters: the points,
// and whether the set was fully convex (a digital ball need not be: the answer is reported,
// the time is the same work either way when no witness stops the sweep early).
#include <zdg/kernel/hulls/digital_convexity.hpp>

#include <benchmark/benchmark.h>

#include <array>
#include <cstdint>
#include <vector>

namespace {

using namespace zdg;

std::vector<std::array<Int64, 3>> ellipsoid(std::int64_t a, std::int64_t b, std::int64_t c) {
  // x^2 b^2 c^2 + y^2 a^2 c^2 + z^2 a^2 b^2 <= a^2 b^2 c^2, in order (x, y, z).
  std::vector<std::array<Int64, 3>> pts;
  const std::int64_t abc = a * a * b * b * c * c;
  for (std::int64_t x = -a; x <= a; ++x)
    for (std::int64_t y = -b; y <= b; ++y)
      for (std::int64_t z = -c; z <= c; ++z)
        if (x * x * b * b * c * c + y * y * a * a * c * c + z * z * a * a * b * b <= abc)
          pts.push_back({Int64(x), Int64(y), Int64(z)});
  return pts;
}

void BM_FullConvexityBall(benchmark::State& state) {
  const auto r = state.range(0);
  const auto pts = ellipsoid(r, r, r);
  bool convex = false;
  for (auto _ : state) {
    auto w = full_convexity_witness<3, Int64>(std::span<const std::array<Int64, 3>>(pts));
    convex = !w;
    benchmark::DoNotOptimize(w);
  }
  state.counters["points"] = static_cast<double>(pts.size());
  state.counters["fully_convex"] = convex ? 1 : 0;
}
BENCHMARK(BM_FullConvexityBall)->Arg(40)->Arg(62)->Arg(100)->Unit(benchmark::kMillisecond);

void BM_HullConvexityBall(benchmark::State& state) {
  const auto r = state.range(0);
  const auto pts = ellipsoid(r, r, r);
  bool convex = false;
  for (auto _ : state) {
    auto w = hull_convexity_witness<3, Int64>(std::span<const std::array<Int64, 3>>(pts));
    convex = !w;
    benchmark::DoNotOptimize(w);
  }
  state.counters["points"] = static_cast<double>(pts.size());
  state.counters["h_convex"] = convex ? 1 : 0;
}
BENCHMARK(BM_HullConvexityBall)->Arg(62)->Unit(benchmark::kMillisecond);

void BM_FullConvexityEllipsoid(benchmark::State& state) {
  const auto pts = ellipsoid(120, 80, 30);
  bool convex = false;
  for (auto _ : state) {
    auto w = full_convexity_witness<3, Int64>(std::span<const std::array<Int64, 3>>(pts));
    convex = !w;
    benchmark::DoNotOptimize(w);
  }
  state.counters["points"] = static_cast<double>(pts.size());
  state.counters["fully_convex"] = convex ? 1 : 0;
}
BENCHMARK(BM_FullConvexityEllipsoid)->Unit(benchmark::kMillisecond);

void BM_Envelope2dSegment(benchmark::State& state) {
  // The digital segment from (0, 0) to (n, n * 2 / 3 + 1): one envelope of two points.
  const std::int64_t n = state.range(0);
  std::size_t size = 0;
  for (auto _ : state) {
    auto s = digital_segment<2, Int64>({Int64(0), Int64(0)}, {Int64(n), Int64(n * 2 / 3 + 1)});
    size = s.size();
    benchmark::DoNotOptimize(s);
  }
  state.counters["points"] = static_cast<double>(size);
}
BENCHMARK(BM_Envelope2dSegment)->Arg(1000)->Arg(100000)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
