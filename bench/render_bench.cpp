// Pictures and mesh files of large surfaces (issue 12: a PNG of 10^7 faces in <= 3 s): a
// torus of nu x nv quads coloured by its exact mean curvature, rendered at 1200 x 900 with
// 2 x 2 samples per pixel (RenderPng), written as binary PLY (WritePly), as the viewer page
// (WriteHtml; issue 35: <= 2x WritePly at 10^7 faces) and read back from the PLY (ReadPly).
// Arguments: nu, nv, threads (0 = all cores).
//
//   build/bin/render_bench --benchmark_filter='RenderPng/5000/2000'
#include <zdg/kernel/io/mesh_io.hpp>
#include <zdg/kernel/io/ply_read.hpp>
#include <zdg/kernel/render/mesh_html.hpp>
#include <zdg/kernel/render/render_mesh.hpp>

#include "tests/support/voxel_mesh.hpp"

#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>
#include <unistd.h>

namespace {

std::string temp(const std::string& name) {
  return (std::filesystem::temp_directory_path() /
          ("zdg_render_bench_" + std::to_string(::getpid()) + "_" + name))
      .string();
}

void RenderPng(benchmark::State& state) {
  const auto mesh = zdg::test::torus_mesh(3.0, 1.0, state.range(0), state.range(1));
  zdg::MeshRenderOptions opt;
  opt.threads = static_cast<unsigned>(state.range(2));
  const std::string out = temp("torus.png");
  for (auto _ : state) zdg::render_mesh_png(out, mesh, "mean-curvature", opt);
  std::filesystem::remove(out);
  state.counters["faces"] = static_cast<double>(mesh.face_count());
  state.counters["faces_per_s"] = benchmark::Counter(static_cast<double>(mesh.face_count()),
                                                     benchmark::Counter::kIsIterationInvariantRate);
}

void WritePly(benchmark::State& state) {
  const auto mesh = zdg::test::torus_mesh(3.0, 1.0, state.range(0), state.range(1));
  const std::string out = temp("torus.ply");
  for (auto _ : state) zdg::write_ply(out, mesh);
  state.counters["MB"] = static_cast<double>(std::filesystem::file_size(out)) / 1e6;
  std::filesystem::remove(out);
  state.counters["faces"] = static_cast<double>(mesh.face_count());
}

void WriteHtml(benchmark::State& state) {
  const auto mesh = zdg::test::torus_mesh(3.0, 1.0, state.range(0), state.range(1));
  const std::string out = temp("torus.html");
  zdg::MeshHtmlOptions opt;
  opt.max_faces = mesh.face_count();
  for (auto _ : state) zdg::write_mesh_html(out, mesh, opt);
  state.counters["MB"] = static_cast<double>(std::filesystem::file_size(out)) / 1e6;
  std::filesystem::remove(out);
  state.counters["faces"] = static_cast<double>(mesh.face_count());
}

void ReadPly(benchmark::State& state) {
  const auto mesh = zdg::test::torus_mesh(3.0, 1.0, state.range(0), state.range(1));
  const std::string out = temp("torus_read.ply");
  zdg::write_ply(out, mesh);
  for (auto _ : state) benchmark::DoNotOptimize(zdg::read_ply(out));
  std::filesystem::remove(out);
  state.counters["faces"] = static_cast<double>(mesh.face_count());
}

BENCHMARK(RenderPng)
    ->Args({1000, 1000, 0})
    ->Args({5000, 2000, 0})
    ->Args({5000, 2000, 1})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(2);
BENCHMARK(WritePly)->Args({5000, 2000})->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK(WriteHtml)->Args({5000, 2000})->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK(ReadPly)->Args({1000, 1000})->Unit(benchmark::kMillisecond)->Iterations(2);

} // namespace

BENCHMARK_MAIN();
