// Surfaces of a user-sized volume: a random smooth foam of N^3 voxels (N = 512 by default,
// about 10^7 boundary surfels; set ZDG_SURFACE_BENCH_N to change it), the level set
// { f > 0 } of a sum of 24 random plane waves of wavelength 40 to 80 voxels.
//   build/bin/surface_bench --benchmark_counters_tabular=true
// Steps: boundary surfels, components, closed surfaces (6,26), primal mesh (alone, and written
// as a binary PLY), marching cubes, II mean
// curvature at radius 5 voxels on the first 10^6 surfels (2 threads); peak memory (RSS) is
// reported as a counter, with the input size and the mesh sizes (run one step per process,
// --benchmark_filter=BM_MarchingCubes, for the peak of that step alone).
#include <zdg/estimators/ii_3d.hpp>
#include <zdg/kernel/io/mesh_io.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>
#include <zdg/kernel/surfaces/image_surfaces.hpp>
#include <zdg/kernel/surfaces/image_surfels.hpp>
#include <zdg/kernel/surfaces/marching_cubes.hpp>
#include <zdg/kernel/surfaces/primal_surface_mesh.hpp>
#include <zdg/kernel/topology/connected_components.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <complex>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <random>
#include <string>
#include <sys/resource.h>

namespace {

std::int64_t side() {
  const char* e = std::getenv("ZDG_SURFACE_BENCH_N");
  return e != nullptr ? std::atoll(e) : 512;
}

double peak_rss_mib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_maxrss) / 1024.0;
}

// The foam: f(x) = sum_k cos(k . x + phi_k), separable as products of per-axis exponentials.
const zdg::Image<std::uint8_t>& foam() {
  static const zdg::Image<std::uint8_t> img = [] {
    const std::int64_t n = side();
    constexpr int waves = 24;
    std::mt19937_64 rng(12);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<std::complex<double>> ex(std::size_t(waves * n)), ey(ex.size()), ez(ex.size());
    for (int w = 0; w < waves; ++w) {
      const double lambda = 40 + 40 * u(rng), th = std::acos(2 * u(rng) - 1),
                   ph = 2 * std::numbers::pi * u(rng), phase = 2 * std::numbers::pi * u(rng);
      const double k = 2 * std::numbers::pi / lambda;
      const double kx = k * std::sin(th) * std::cos(ph), ky = k * std::sin(th) * std::sin(ph),
                   kz = k * std::cos(th);
      for (std::int64_t i = 0; i < n; ++i) {
        ex[std::size_t(w * n + i)] = std::polar(1.0, kx * double(i) + phase);
        ey[std::size_t(w * n + i)] = std::polar(1.0, ky * double(i));
        ez[std::size_t(w * n + i)] = std::polar(1.0, kz * double(i));
      }
    }
    zdg::Image<std::uint8_t> out(zdg::Domain({n, n, n}));
    zdg::parallel_for(n * n, 0, [&](std::int64_t r) {
      const std::int64_t j = r % n, k = r / n;
      std::complex<double> yz[waves];
      for (int w = 0; w < waves; ++w)
        yz[w] = ey[std::size_t(w * n + j)] * ez[std::size_t(w * n + k)];
      for (std::int64_t i = 0; i < n; ++i) {
        double f = 0;
        for (int w = 0; w < waves; ++w) f += (ex[std::size_t(w * n + i)] * yz[w]).real();
        out[r * n + i] = f > 0 ? 1 : 0;
      }
    });
    return out;
  }();
  return img;
}

const zdg::ImageSurfels& surfels() {
  static const zdg::ImageSurfels s = zdg::image_surfels(foam(), 2);
  return s;
}

const auto kConvention = zdg::SurfaceConvention::of(6, 26);

void report(benchmark::State& state) {
  state.counters["voxels"] = double(foam().size());
  state.counters["surfels"] = double(surfels().size());
  state.counters["peak_MiB"] = peak_rss_mib();
}

void BM_Surfels(benchmark::State& state) {
  foam();
  for (auto _ : state) {
    auto s = zdg::image_surfels(foam(), unsigned(state.range(0)));
    benchmark::DoNotOptimize(s.codes.data());
  }
  report(state);
}

// The components of the object (6-adjacency, kernel/topology/connected_components.hpp): with the
// surfels and the surfaces, what `zdg surface` computes before any mesh.
void BM_Components(benchmark::State& state) {
  foam();
  std::int64_t count = 0;
  for (auto _ : state) {
    zdg::ComponentOptions opt;
    opt.threads = unsigned(state.range(0));
    auto c = zdg::connected_components(foam(), 6, opt);
    count = c.count();
  }
  state.counters["components"] = double(count);
  report(state);
}

void BM_Surfaces(benchmark::State& state) {
  surfels();
  std::size_t count = 0;
  for (auto _ : state) {
    auto s = zdg::image_surfaces(foam(), surfels(), kConvention, unsigned(state.range(0)));
    count = s.surfaces.size();
  }
  state.counters["surfaces"] = double(count);
  report(state);
}

void BM_PrimalMesh(benchmark::State& state) {
  surfels();
  std::int64_t v = 0;
  for (auto _ : state) {
    auto m = zdg::primal_surface_mesh(foam(), surfels(), kConvention,
                                      zdg::VoxelPlacement::lattice(surfels().grid),
                                      unsigned(state.range(0)));
    v = m.vertex_count();
  }
  state.counters["vertices"] = double(v);
  report(state);
}

// The primal mesh written as a binary PLY (in $TMPDIR, /tmp by default; removed after): the
// "primal PLY written" step of `zdg surface -o OUT.ply --mesh primal`.
void BM_PrimalMeshPly(benchmark::State& state) {
  surfels();
  const char* dir = std::getenv("TMPDIR");
  const std::string path = std::string(dir != nullptr ? dir : "/tmp") + "/zdg_surface_bench.ply";
  double bytes = 0;
  for (auto _ : state) {
    auto m = zdg::primal_surface_mesh(foam(), surfels(), kConvention,
                                      zdg::VoxelPlacement::lattice(surfels().grid),
                                      unsigned(state.range(0)));
    zdg::write_ply(path, m);
    bytes = double(std::filesystem::file_size(path));
  }
  std::filesystem::remove(path);
  state.counters["ply_MB"] = bytes / 1e6;
  report(state);
}

void BM_MarchingCubes(benchmark::State& state) {
  surfels();
  std::int64_t f = 0;
  for (auto _ : state) {
    auto m = zdg::marching_cubes(foam(), surfels(), kConvention,
                                 zdg::VoxelPlacement::lattice(surfels().grid), nullptr,
                                 unsigned(state.range(0)));
    f = m.face_count();
  }
  state.counters["triangles"] = double(f);
  report(state);
}

void BM_IIMean(benchmark::State& state) {
  const auto& s = surfels();
  const std::int64_t m = std::min<std::int64_t>(1000000, s.size());
  std::vector<zdg::Surfel> some(static_cast<std::size_t>(m));
  for (std::int64_t i = 0; i < m; ++i) some[std::size_t(i)] = s.surfel(i);
  const auto& img = foam();
  const zdg::VoxelGrid g = s.grid;
  const zdg::VoxelPredicate inside = [&](const zdg::Voxel& z) {
    return img[g.index(z.x - g.lower.x, z.y - g.lower.y, z.z - g.lower.z)] != 0;
  };
  for (auto _ : state) {
    auto H = zdg::ii_mean_curvature(inside, g.box(), some, 1.0, 5.0, int(state.range(0)));
    benchmark::DoNotOptimize(H.data());
  }
  state.counters["ii_surfels"] = double(m);
  report(state);
}

BENCHMARK(BM_Surfels)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Components)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Surfaces)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_PrimalMesh)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_PrimalMeshPly)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_MarchingCubes)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_IIMean)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(1);

} // namespace

BENCHMARK_MAIN();
