// Digitized rigid motions (kernel/images/rigid_motion.hpp): the bijectivity certificate over one
// period (c points, additions only) for periods up to 2^28, and the motion of a ball of radius
// 0.45 n in n^3 by the quaternion (5, 1, 2, 3) about the volume's centre (one thread).
//
//   build/bin/motion_bench
#include <zdg/kernel/images/rigid_motion.hpp>

#include <benchmark/benchmark.h>

#include <cstdint>
#include <numeric>
#include <vector>

namespace {

using zdg::BigInt;
using Q = zdg::Rational<zdg::BigInt>;

// A primitive triple with c near 2^k: (m^2 - n^2, 2 m n, m^2 + n^2) with m = 2^(k/2) / 1.2 + 1
// (odd) and n = m / 2 (even), adjusted to be coprime.
zdg::RigidMotion triple_near(int k) {
  std::int64_t m = static_cast<std::int64_t>(static_cast<double>(std::int64_t{1} << (k / 2)) / 1.2);
  m |= 1;
  std::int64_t n = (m / 2) & ~std::int64_t{1};
  while (std::gcd(m, n) != 1) n -= 2;
  return zdg::rotation_2d(BigInt(m * m - n * n), BigInt(2 * m * n), BigInt(m * m + n * n));
}

void LatticeCertificate(benchmark::State& state) {
  const zdg::RigidMotion m = triple_near(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    auto r = zdg::lattice_bijectivity(m);
    benchmark::DoNotOptimize(r.bijective);
  }
  state.counters["period"] = zdg::to_double(m.n);
  state.counters["ns_per_point"] =
      benchmark::Counter(zdg::to_double(m.n) * 1e-9, benchmark::Counter::kIsIterationInvariantRate |
                                                         benchmark::Counter::kInvert);
}
BENCHMARK(LatticeCertificate)->Arg(20)->Arg(24)->Arg(28)->Unit(benchmark::kMillisecond);

void ApplyToBall(benchmark::State& state) {
  const std::int64_t n = state.range(0);
  zdg::Image<std::uint8_t> img{zdg::Domain({n, n, n})};
  const std::int64_t c = n / 2, r2 = (45 * n / 100) * (45 * n / 100);
  std::vector<std::int64_t> p(3);
  for (std::int64_t i = 0; i < img.size(); ++i) {
    img.domain().point(i, p);
    img[i] = (p[0] - c) * (p[0] - c) + (p[1] - c) * (p[1] - c) + (p[2] - c) * (p[2] - c) <= r2;
  }
  const Q h(BigInt(n - 1), BigInt(2));
  const zdg::RigidMotion m = zdg::motion_about(zdg::rotation_3d(5, 1, 2, 3), {h, h, h}, {0, 0, 0});
  for (auto _ : state) {
    auto r = zdg::apply_motion(img, m, true);
    benchmark::DoNotOptimize(r.images);
  }
  state.counters["ns_per_voxel"] = benchmark::Counter(
      static_cast<double>(img.size()) * 1e-9,
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(ApplyToBall)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
