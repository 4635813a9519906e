// Exact mesh voxelization (kernel/digitization/voxelize.hpp), issue #38's target: 10^6 triangles
// at 1024^3 in <= 10 s on 2 threads.
//
// The mesh: the cube [-1, 1]^3 with faces cut into n x n squares of two triangles, projected onto
// the unit sphere (tests/support/triangle_meshes.hpp, 12 n^2 triangles; n = 289: 1,002,252). The
// grid: h = 1 / 508 with the default origin (two voxels of margin), 1022^3 voxels. Arguments:
// n, mode (0 conservative, 1 six, 2 twenty_six, 3 solid), threads. Counters: triangles, voxels
// (the set's size), grid (voxels of the grid).
//
//   build/bin/voxelize_bench --benchmark_filter='Voxelize/289/0/2'
#include <zdg/kernel/digitization/voxelize.hpp>

#include "tests/support/triangle_meshes.hpp"

#include <benchmark/benchmark.h>

#include <cstdint>

namespace {

using zdg::VoxelizationMode;

void Voxelize(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto mode = static_cast<VoxelizationMode>(state.range(1));
  const auto threads = static_cast<unsigned>(state.range(2));
  const zdg::PolygonMesh mesh = zdg::test::sphere_mesh(n).mesh;
  const zdg::VoxelizationGrid grid = zdg::voxel_grid_for(mesh, 1.0 / 508);
  std::int64_t voxels = 0;
  for (auto _ : state) {
    const auto img = zdg::voxelize(mesh, grid, mode, threads);
    voxels = 0;
    for (auto x : img.values()) voxels += x;
    benchmark::DoNotOptimize(voxels);
  }
  state.counters["triangles"] = static_cast<double>(mesh.face_count());
  state.counters["voxels"] = static_cast<double>(voxels);
  state.counters["grid"] = static_cast<double>(grid.extents[0] * grid.extents[1] * grid.extents[2]);
  state.SetLabel(zdg::voxelization_mode_name(mode));
}

BENCHMARK(Voxelize)
    ->ArgsProduct({{289}, {0, 1, 2, 3}, {1, 2}})
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime();

} // namespace

BENCHMARK_MAIN();
