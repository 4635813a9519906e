// Digital surface regularization (estimators/surface_regularization.hpp, issue #36 item 4): the
// sphere of radius 1 digitized at step h (voxel z inside iff |h z| <= 1), its primal surface's
// vertices moved with the default energy (alpha 0.001, beta 1, gamma 0.05) and the box
// constraint, the exact sphere normal at each surfel centre standing for the estimate (the
// benchmark times the regularization, not the II). Argument: h in 1/100000; the last size is
// about 10^6 surfels (radius 235 voxels: h = 0.00426). Counters: surfels, MPRGP
// iterations, the relative KKT residual reached, max displacement in h. Run with 2 threads:
//   build/bin/surface_regularization_bench --benchmark_counters_tabular=true
#include <zdg/estimators/surface_regularization.hpp>
#include <zdg/kernel/surfaces/digital_surface.hpp>
#include <zdg/kernel/surfaces/surfel_complex.hpp>

#include <benchmark/benchmark.h>

#include <cmath>

namespace {

struct Sphere {
  zdg::PolygonMesh mesh;
  std::vector<zdg::Point3<double>> normals;
};

Sphere sphere(double h) {
  const double r2 = 1 / (h * h);
  const zdg::VoxelPredicate inside = [r2](const zdg::Voxel& z) {
    return double(z.x * z.x + z.y * z.y + z.z * z.z) <= r2;
  };
  const auto n = static_cast<std::int64_t>(std::ceil(1 / h)) + 2;
  const auto surfels = zdg::boundary_surfels(inside, zdg::VoxelBox{{-n, -n, -n}, {n, n, n}});
  zdg::SurfelComplex cx = zdg::surfel_complex(zdg::primal_surface(surfels), h);
  Sphere s;
  s.mesh.face_size = 4;
  s.mesh.vertices = std::move(cx.pointels);
  for (const auto& q : cx.surfels) s.mesh.indices.insert(s.mesh.indices.end(), q.begin(), q.end());
  for (const auto& c : cx.centres) {
    const double l = std::sqrt(dot(c, c));
    s.normals.push_back((1 / l) * c);
  }
  return s;
}

void BM_RegularizeSphere(benchmark::State& state) {
  const double h = double(state.range(0)) / 100000.0;
  const Sphere s = sphere(h);
  zdg::RegularizationParameters p;
  p.threads = 2;
  zdg::RegularizationResult r;
  for (auto _ : state) {
    r = zdg::regularize_surface(s.mesh, s.normals, h, p);
    benchmark::DoNotOptimize(r.positions.data());
  }
  state.counters["surfels"] = double(s.mesh.face_count());
  state.counters["iterations"] = r.iterations;
  state.counters["kkt"] = r.kkt_residual;
  state.counters["max_disp_h"] = r.max_displacement;
  state.SetLabel(r.solver);
}
BENCHMARK(BM_RegularizeSphere)
    ->Arg(2500)
    ->Arg(1000)
    ->Arg(426)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

} // namespace

BENCHMARK_MAIN();
