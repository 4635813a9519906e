// Cubical persistence (kernel/topology/cubical_persistence.hpp) of a grey-level volume: smoothed
// Gaussian noise, n^3 (issue #39: persistence of a 256^3 grey-level volume faster than GUDHI in
// the same run; the GUDHI side is bench/compare_persistence.py, which runs zdg's command and
// gudhi.CubicalComplex on one array).
//
// The volume: standard normal values (seeded), then a box blur of radius 2 along each axis, three
// times (close to a Gaussian of sigma 2.4): a landscape with many minima, loops and voids at all
// scales. Counters: the number of pairs in each dimension.
//
//   build/bin/persistence_bench --benchmark_filter='Persistence/256'
#include <zdg/kernel/topology/cubical_persistence.hpp>

#include <benchmark/benchmark.h>

#include <cstdint>
#include <random>
#include <vector>

namespace {

using zdg::Domain;
using zdg::Image;

Image<double> smoothed_noise(std::int64_t n) {
  Image<double> img(Domain({n, n, n}));
  std::mt19937_64 rng(39);
  std::normal_distribution<double> normal;
  for (auto& v : img.values()) v = normal(rng);
  const std::int64_t stride[3] = {n * n, n, 1};
  std::vector<double> line(static_cast<std::size_t>(n));
  for (int pass = 0; pass < 3; ++pass) {
    for (int axis = 0; axis < 3; ++axis) {
      const std::int64_t s = stride[axis];
      for (std::int64_t start = 0; start < n * n * n; ++start) {
        if ((start / s) % n != 0) continue; // one line per start on this axis
        for (std::int64_t i = 0; i < n; ++i) {
          double sum = 0;
          for (std::int64_t j = i - 2; j <= i + 2; ++j) {
            const std::int64_t c = j < 0 ? 0 : (j >= n ? n - 1 : j);
            sum += img[start + c * s];
          }
          line[static_cast<std::size_t>(i)] = sum / 5;
        }
        for (std::int64_t i = 0; i < n; ++i) img[start + i * s] = line[static_cast<std::size_t>(i)];
      }
    }
  }
  // float32 values, as the peer script's array.
  for (auto& v : img.values()) v = static_cast<double>(static_cast<float>(v));
  return img;
}

void Persistence(benchmark::State& state) {
  const auto img = smoothed_noise(state.range(0));
  zdg::PersistenceDiagrams d;
  for (auto _ : state) {
    d = zdg::cubical_persistence(img);
    benchmark::DoNotOptimize(d);
  }
  for (std::size_t k = 0; k < d.diagrams.size(); ++k) {
    state.counters["pairs" + std::to_string(k)] = static_cast<double>(d.diagrams[k].size());
  }
  state.counters["voxels"] = static_cast<double>(img.size());
}
BENCHMARK(Persistence)->Arg(64)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond)->Iterations(1);

} // namespace

BENCHMARK_MAIN();
