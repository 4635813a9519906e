// Sparse voxel DAGs (kernel/images/voxel_dag.hpp), issue #38 item 2's targets: the DAG of a
// 2048^3 scene from its voxelization with peak memory <= 4 GiB; 10^6 exact ray traversals
// (first hits) through the DAG <= 2 s.
//
// The scene: tests/support's cube mesh (n = 289: 1,002,252 triangles) projected onto the unit
// sphere, its vertices moved by Gaussian noise of sigma = 2^-noise (0: none; the noise breaks
// the sphere's symmetries, as in a scanned model), voxelized exactly (conservative) at
// h = 2.04 / (side - 4), streamed by slabs of 64 layers into a DAG and an SSVDAG builder (the
// dense volume never exists). Counters: voxels, the bytes and bits per voxel of the SVO, the DAG
// and the SSVDAG (32-bit headers and pointers, 64-bit leaves), peak_rss_gib (the process's high
// water mark, VmHWM).
//   build/bin/dag_bench --benchmark_filter='DagBuild/2048/'
// FirstHits: 10^6 rays of random directions (numerators in [-2^20, 2^20], den 2^20) through
// random points of the scene's box, their first hits in the SSVDAG of the side^3 scene, on 2
// threads (the DAG built once, untimed). Counter: hits.
//   build/bin/dag_bench --benchmark_filter='FirstHits/1024'
#include <zdg/kernel/digitization/voxelize.hpp>
#include <zdg/kernel/images/voxel_dag.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>

#include "tests/support/peak_memory.hpp"
#include "tests/support/triangle_meshes.hpp"

#include <benchmark/benchmark.h>

#include <atomic>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <random>

namespace {

using zdg::VoxelDag;
using zdg::VoxelDagKind;

zdg::PolygonMesh scene_mesh(int noise) {
  zdg::PolygonMesh mesh = zdg::test::sphere_mesh(289).mesh;
  if (noise > 0) zdg::test::add_vertex_noise(mesh, std::ldexp(1.0, -noise), 7);
  return mesh;
}

std::vector<VoxelDag> build(std::int64_t side, int noise, unsigned threads) {
  const zdg::PolygonMesh mesh = scene_mesh(noise);
  const zdg::VoxelizationGrid grid =
      zdg::voxel_grid_for(mesh, 2.04 / double(side - 4), std::nullopt, std::int64_t{1} << 40);
  zdg::VoxelDagBuilder dag(grid.extents, VoxelDagKind::dag);
  zdg::VoxelDagBuilder ss(grid.extents, VoxelDagKind::ssvdag);
  zdg::voxelize_by_slabs(
      mesh, grid, zdg::VoxelizationMode::conservative, 64,
      [&](std::int64_t, std::int64_t n, const std::uint8_t* data) {
        dag.add_slices(data, n);
        ss.add_slices(data, n);
      },
      threads);
  std::vector<VoxelDag> out;
  out.push_back(dag.finish());
  out.push_back(ss.finish());
  return out;
}

void DagBuild(benchmark::State& state) {
  const std::int64_t side = state.range(0);
  const int noise = static_cast<int>(state.range(1));
  std::vector<VoxelDag> g;
  for (auto _ : state) g = build(side, noise, 2);
  const auto d = g[0].stats(), s = g[1].stats();
  state.counters["voxels"] = double(d.voxels);
  state.counters["svo_bytes"] = double(d.svo_bytes);
  state.counters["dag_bytes"] = double(d.bytes);
  state.counters["ssvdag_bytes"] = double(s.bytes);
  state.counters["svo_bpv"] = 8.0 * double(d.svo_bytes) / double(d.voxels);
  state.counters["dag_bpv"] = d.bits_per_voxel();
  state.counters["ssvdag_bpv"] = s.bits_per_voxel();
  state.counters["extent"] = double(g[0].extent()[0]);
  state.counters["peak_rss_gib"] = double(zdg::test::proc_status_kib("VmHWM")) / (1024.0 * 1024.0);
}

BENCHMARK(DagBuild)
    ->ArgsProduct({{512, 1024, 2048}, {0, 9}})
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime();

void FirstHits(benchmark::State& state) {
  const std::int64_t side = state.range(0);
  static std::map<std::int64_t, VoxelDag> cache;
  if (!cache.count(side)) cache[side] = std::move(build(side, 9, 2)[1]);
  const VoxelDag& g = cache[side];
  const std::int64_t rays = 1000000;
  std::vector<zdg::DigitalRay> r(static_cast<std::size_t>(rays));
  std::mt19937_64 rng(11);
  const std::int64_t den = std::int64_t{1} << 20;
  std::uniform_int_distribution<std::int64_t> dir(-den, den);
  const auto& e = g.extent();
  for (auto& x : r) {
    x.denominator = den;
    for (std::size_t a = 0; a < 3; ++a) {
      x.origin[a] = std::uniform_int_distribution<std::int64_t>(0, e[a] * den - 1)(rng);
      x.direction[a] = dir(rng);
    }
    if (x.direction == std::array<std::int64_t, 3>{0, 0, 0}) x.direction[0] = 1;
  }
  std::atomic<std::int64_t> hits{0};
  for (auto _ : state) {
    hits = 0;
    zdg::parallel_for(rays / 1000, 2, [&](std::int64_t block) {
      std::int64_t h = 0;
      for (std::int64_t i = block * 1000; i < (block + 1) * 1000; ++i)
        h += g.first_hit(r[static_cast<std::size_t>(i)]).has_value();
      hits += h;
    });
  }
  state.counters["hits"] = double(hits.load());
  state.counters["rays"] = double(rays);
}

BENCHMARK(FirstHits)
    ->Arg(512)
    ->Arg(1024)
    ->Arg(2048)
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime();

} // namespace

BENCHMARK_MAIN();
