// Reading users' volumes (issue 12): a random smooth foam of n^3 voxels (a cubic B-spline
// through random values on a coarse periodic grid, thresholded at 0: about half solid,
// features of n / 32 voxels, about 10^7 boundary surfels at n = 512), written once as a .vol
// Version 3 file in the temporary folder, then read (VolV3Read), read and selected
// (ReadSelect: read_volume + --threshold 128), and written (VolV3Write). Counters: voxels per
// second, surfels (6-neighbour pairs inside/outside, counted once), file size.
//
//   build/bin/volume_io_bench --benchmark_filter='VolV3Read/512'
#include <zdg/kernel/images/object_selection.hpp>
#include <zdg/kernel/io/vol_io.hpp>
#include <zdg/kernel/io/volume_io.hpp>

#include <benchmark/benchmark.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <random>
#include <string>
#include <unistd.h>

namespace {

using zdg::Domain;
using zdg::Image;

// Values 0 / 255 of the foam.
Image<std::uint8_t> foam(std::int64_t n, std::int64_t cells = 32) {
  const std::int64_t f = n / cells; // voxels per coarse cell
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::vector<float> g(static_cast<std::size_t>(cells * cells * cells));
  for (auto& v : g) v = u(rng);
  auto wrap = [cells](std::int64_t i) { return ((i % cells) + cells) % cells; };
  // Cubic B-spline weights for the f positions inside a cell.
  std::vector<std::array<float, 4>> w(static_cast<std::size_t>(f));
  for (std::int64_t k = 0; k < f; ++k) {
    const float t = (static_cast<float>(k) + 0.5f) / static_cast<float>(f);
    w[static_cast<std::size_t>(k)] = {(1 - t) * (1 - t) * (1 - t) / 6,
                                      (3 * t * t * t - 6 * t * t + 4) / 6,
                                      (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6, t * t * t / 6};
  }
  auto interp = [&](auto&& at, std::int64_t x) { // along one axis, x in [0, n)
    const std::int64_t c = x / f;
    const auto& ww = w[static_cast<std::size_t>(x % f)];
    float s = 0;
    for (int k = 0; k < 4; ++k) s += ww[static_cast<std::size_t>(k)] * at(wrap(c + k - 1));
    return s;
  };
  std::vector<float> a(static_cast<std::size_t>(cells * cells * n)); // (zc, yc, x)
  for (std::int64_t zc = 0; zc < cells; ++zc)
    for (std::int64_t yc = 0; yc < cells; ++yc)
      for (std::int64_t x = 0; x < n; ++x)
        a[static_cast<std::size_t>((zc * cells + yc) * n + x)] = interp(
            [&](std::int64_t xc) {
              return g[static_cast<std::size_t>((zc * cells + yc) * cells + xc)];
            },
            x);
  std::vector<float> b(static_cast<std::size_t>(cells * n * n)); // (zc, y, x)
  for (std::int64_t zc = 0; zc < cells; ++zc)
    for (std::int64_t y = 0; y < n; ++y)
      for (std::int64_t x = 0; x < n; ++x)
        b[static_cast<std::size_t>((zc * n + y) * n + x)] = interp(
            [&](std::int64_t yc) { return a[static_cast<std::size_t>((zc * cells + yc) * n + x)]; },
            y);
  Image<std::uint8_t> img(Domain({n, n, n}));
  for (std::int64_t z = 0; z < n; ++z)
    for (std::int64_t y = 0; y < n; ++y)
      for (std::int64_t x = 0; x < n; ++x)
        img[(z * n + y) * n + x] =
            interp(
                [&](std::int64_t zc) { return b[static_cast<std::size_t>((zc * n + y) * n + x)]; },
                z) > 0
                ? 255
                : 0;
  return img;
}

std::int64_t surfels(const Image<std::uint8_t>& img) {
  const std::int64_t n = img.domain().extent(0);
  std::int64_t s = 0;
  for (std::int64_t z = 0; z < n; ++z)
    for (std::int64_t y = 0; y < n; ++y)
      for (std::int64_t x = 0; x < n; ++x) {
        const bool in = img[(z * n + y) * n + x] != 0;
        const bool nb[3] = {x + 1 < n && img[(z * n + y) * n + x + 1] != 0,
                            y + 1 < n && img[(z * n + y + 1) * n + x] != 0,
                            z + 1 < n && img[((z + 1) * n + y) * n + x] != 0};
        for (bool o : nb) s += in != o ? 1 : 0;
        // the faces on the box's far sides
        s += in && x + 1 == n ? 1 : 0;
        s += in && y + 1 == n ? 1 : 0;
        s += in && z + 1 == n ? 1 : 0;
        s += in && x == 0 ? 1 : 0;
        s += in && y == 0 ? 1 : 0;
        s += in && z == 0 ? 1 : 0;
      }
  return s;
}

struct Sample {
  std::string path;
  std::int64_t surfels = 0, bytes = 0;
  Image<std::uint8_t> image;
};

const Sample& sample(std::int64_t n) {
  static std::map<std::int64_t, Sample> cache;
  auto it = cache.find(n);
  if (it != cache.end()) return it->second;
  Sample s;
  s.image = foam(n);
  s.surfels = surfels(s.image);
  s.path = (std::filesystem::temp_directory_path() /
            ("zdg_bench_foam_" + std::to_string(n) + "_" + std::to_string(::getpid()) + ".vol"))
               .string();
  zdg::write_vol(s.path, s.image, 3);
  s.bytes = static_cast<std::int64_t>(std::filesystem::file_size(s.path));
  return cache.emplace(n, std::move(s)).first->second;
}

void counters(benchmark::State& state, const Sample& s, std::int64_t n) {
  state.counters["voxels_per_s"] = benchmark::Counter(
      static_cast<double>(n * n * n), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["surfels"] = static_cast<double>(s.surfels);
  state.counters["file_MB"] = static_cast<double>(s.bytes) / 1e6;
}

void VolV3Read(benchmark::State& state) {
  const std::int64_t n = state.range(0);
  const Sample& s = sample(n);
  for (auto _ : state) {
    auto img = zdg::read_vol(s.path);
    benchmark::DoNotOptimize(img.values().data());
  }
  counters(state, s, n);
}

void ReadSelect(benchmark::State& state) {
  const std::int64_t n = state.range(0);
  const Sample& s = sample(n);
  zdg::ObjectSelection sel;
  sel.rule = zdg::ObjectSelection::Rule::at_least;
  sel.low = 128;
  for (auto _ : state) {
    auto v = zdg::read_volume(s.path);
    auto obj = zdg::select_object(v, sel);
    benchmark::DoNotOptimize(obj.voxels);
  }
  counters(state, s, n);
}

void VolV3Write(benchmark::State& state) {
  const std::int64_t n = state.range(0);
  const Sample& s = sample(n);
  const std::string out = s.path + ".out.vol";
  for (auto _ : state) zdg::write_vol(out, s.image, 3);
  std::filesystem::remove(out);
  counters(state, s, n);
}

BENCHMARK(VolV3Read)->Arg(128)->Arg(512)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(ReadSelect)->Arg(512)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(VolV3Write)->Arg(512)->Unit(benchmark::kMillisecond)->Iterations(2);

} // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  for (std::int64_t n : {128, 512}) {
    const auto p =
        std::filesystem::temp_directory_path() /
        ("zdg_bench_foam_" + std::to_string(n) + "_" + std::to_string(::getpid()) + ".vol");
    std::filesystem::remove(p);
  }
  return 0;
}
