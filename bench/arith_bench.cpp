// Speed of the arithmetic core: continued fractions, floor_sum, Christoffel generation
// (letters per second), on each tower type.
#include <zdg/arith/christoffel.hpp>
#include <zdg/arith/continued_fraction.hpp>
#include <zdg/arith/floor_sum.hpp>

#include <benchmark/benchmark.h>

namespace {

using namespace zdg;

// Consecutive Fibonacci numbers: the longest expansion for their size (Lame).
template <class I>
std::pair<I, I> fibonacci_pair(int n) {
  I a = 1, b = 1;
  for (int i = 0; i < n; ++i) {
    I c = a + b;
    a = b;
    b = c;
  }
  return {b, a};
}

template <class I>
void BM_ContinuedFraction(benchmark::State& state) {
  auto [p, q] = fibonacci_pair<I>(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(continued_fraction(p, q));
  state.SetLabel(std::to_string(state.range(0) + 1) + " terms");
}
BENCHMARK_TEMPLATE(BM_ContinuedFraction, Int64)->Arg(88);
BENCHMARK_TEMPLATE(BM_ContinuedFraction, Int128)->Arg(88)->Arg(180);
BENCHMARK_TEMPLATE(BM_ContinuedFraction, BigInt)->Arg(88)->Arg(180)->Arg(1000);

template <class I>
void BM_FloorSum(benchmark::State& state) {
  I n = 1'000'000'000, m = 998'244'353, a = 123'456'789, b = -987'654'321;
  for (auto _ : state) benchmark::DoNotOptimize(floor_sum(n, m, a, b));
}
BENCHMARK_TEMPLATE(BM_FloorSum, Int128);
BENCHMARK_TEMPLATE(BM_FloorSum, BigInt);

void BM_FloorSumExact(benchmark::State& state) {
  BigInt n = 1'000'000, m = 998'244'353, a = 123'456'789, b = -987'654'321;
  for (auto _ : state) benchmark::DoNotOptimize(floor_sum_exact(n, m, a, b));
  state.SetLabel("served by int64");
}
BENCHMARK(BM_FloorSumExact);

template <class I>
void BM_ChristoffelWord(benchmark::State& state) {
  const std::int64_t q = state.range(0), p = q - 1; // coprime
  for (auto _ : state) benchmark::DoNotOptimize(lower_christoffel_word(I(p), I(q)));
  state.SetItemsProcessed(state.iterations() * (p + q)); // letters
}
BENCHMARK_TEMPLATE(BM_ChristoffelWord, Int64)->Arg(1 << 20);
BENCHMARK_TEMPLATE(BM_ChristoffelWord, Int128)->Arg(1 << 20);
BENCHMARK_TEMPLATE(BM_ChristoffelWord, BigInt)->Arg(1 << 16);

} // namespace

BENCHMARK_MAIN();
