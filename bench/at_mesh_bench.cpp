// Ambrosio-Tortorelli on a triangle mesh (estimators/ambrosio_tortorelli_mesh.hpp; issue #36's
// target: <= 30 s on a 10^6-face mesh with 2 threads). The mesh: the cube [-1, 1]^3 with each
// face an n x n grid of squares cut into two triangles (12 n^2 triangles: n = 289 gives
// 1,002,252), vertices moved by a Gaussian noise of 0.15 grid steps, the noisy face normals as
// g; the parameters of `zdg mesh at` (alpha 0.05, lambda 0.05, eps 2 -> 0.25), conjugate
// gradients on 2 threads, and Cholesky at the smaller sizes for comparison. Timed: the calculus
// (at_mesh) and the minimisation, separately.
//   build/bin/at_mesh_bench --benchmark_counters_tabular=true
#include <zdg/estimators/ambrosio_tortorelli_mesh.hpp>

#include "tests/support/triangle_meshes.hpp"

#include <benchmark/benchmark.h>

#include <map>

namespace {

struct Noisy {
  zdg::PolygonMesh mesh;
  std::vector<zdg::Point3<double>> g;
};

const Noisy& noisy_cube(int n) {
  static std::map<int, Noisy> cache;
  auto it = cache.find(n);
  if (it != cache.end()) return it->second;
  auto m = zdg::test::cube_mesh(n);
  zdg::test::add_vertex_noise(m.mesh, 0.15 * 2.0 / n, 1);
  Noisy s;
  s.g = zdg::mesh_face_normals(m.mesh);
  s.mesh = std::move(m.mesh);
  return cache.emplace(n, std::move(s)).first->second;
}

void BM_ATMeshCalculus(benchmark::State& state) {
  const auto& s = noisy_cube(int(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(zdg::at_mesh(s.mesh));
  state.counters["faces"] = double(s.mesh.face_count());
}

void run(benchmark::State& state, zdg::ATLinearSolver solver) {
  const auto& s = noisy_cube(int(state.range(0)));
  const zdg::ATMesh cx = zdg::at_mesh(s.mesh);
  zdg::ATMeshOptions o;
  o.solver = solver;
  o.threads = 2;
  zdg::ATParameters p; // the defaults of zdg mesh at
  p.alpha = 0.05;
  p.lambda = 0.05;
  zdg::ATMeshResult r;
  for (auto _ : state) r = zdg::at_mesh_normals(cx, s.g, p, o);
  state.counters["faces"] = double(cx.face_count());
  state.counters["iterations"] = r.iterations;
  state.counters["cg_iterations"] = double(r.cg_iterations);
  state.counters["segments"] = double(r.segments);
}

void BM_ATMeshCG(benchmark::State& state) {
  run(state, zdg::ATLinearSolver::conjugate_gradient);
}
void BM_ATMeshCholesky(benchmark::State& state) {
  run(state, zdg::ATLinearSolver::cholesky);
}

} // namespace

BENCHMARK(BM_ATMeshCalculus)->Arg(289)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_ATMeshCG)->Arg(32)->Arg(91)->Arg(289)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(BM_ATMeshCholesky)->Arg(32)->Arg(91)->Unit(benchmark::kSecond)->Iterations(1);

BENCHMARK_MAIN();
