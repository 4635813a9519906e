// The corrected polygonal calculus on a digital surface (#36, item 1): on a digital sphere of
// about 10^6 surfels (radius 235 voxels, lattice step 1), the per-face operators with each quad
// re-embedded orthogonally to the sphere's exact normal at its centre (the constructor), then
// the global Laplacian L = D^T M(lambda) D (lambda = 1) as a sparse matrix (argument 2: the
// worker count), and both together from the mesh (BM_PolygonalLaplacianFromMesh: the issue's
// target, the Laplacian assembled in <= 2 s with 2 threads).
//   build/bin/polygonal_calculus_bench --benchmark_counters_tabular=true
#include <zdg/kernel/calculus/polygonal_calculus.hpp>
#include <zdg/kernel/surfaces/digital_surface.hpp>
#include <zdg/kernel/surfaces/surfel_complex.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <map>

namespace {

struct Sphere {
  zdg::PolygonMesh mesh;
  std::vector<zdg::Point3<double>> normals;
};

// The primal quads of the digital sphere of radius r voxels and the exact normals at the
// surfel centres.
const Sphere& sphere(std::int64_t r) {
  static std::map<std::int64_t, Sphere> cache;
  auto it = cache.find(r);
  if (it != cache.end()) return it->second;
  const std::int64_t r2 = r * r;
  const zdg::VoxelPredicate inside = [r2](const zdg::Voxel& z) {
    return z.x * z.x + z.y * z.y + z.z * z.z <= r2;
  };
  const std::int64_t n = r + 2;
  const auto surfels = zdg::boundary_surfels(inside, zdg::VoxelBox{{-n, -n, -n}, {n, n, n}});
  const zdg::SurfelComplex complex = zdg::surfel_complex(zdg::primal_surface(surfels), 1.0);
  Sphere s;
  s.mesh.face_size = 4;
  s.mesh.vertices = complex.pointels;
  for (const auto& q : complex.surfels)
    s.mesh.indices.insert(s.mesh.indices.end(), q.begin(), q.end());
  for (const auto& c : complex.centres) {
    const double l = std::sqrt(dot(c, c));
    s.normals.push_back((1 / l) * c);
  }
  return cache.emplace(r, std::move(s)).first->second;
}

void BM_PolygonalOperators(benchmark::State& state) {
  const Sphere& s = sphere(state.range(0));
  for (auto _ : state) {
    const zdg::PolygonalCalculus calculus(s.mesh, s.normals);
    benchmark::DoNotOptimize(calculus.face_count());
  }
  state.counters["faces"] = double(s.normals.size());
}
BENCHMARK(BM_PolygonalOperators)->Arg(40)->Arg(235)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_PolygonalLaplacianAssembly(benchmark::State& state) {
  const Sphere& s = sphere(state.range(0));
  const zdg::PolygonalCalculus calculus(s.mesh, s.normals);
  for (auto _ : state) {
    const zdg::SparseMatrix l = calculus.laplacian(1.0, unsigned(state.range(1)));
    if (l.rows != calculus.vertex_count()) std::abort();
    benchmark::DoNotOptimize(l.value.data());
  }
  state.counters["faces"] = double(s.normals.size());
}
BENCHMARK(BM_PolygonalLaplacianAssembly)
    ->Args({40, 1})
    ->Args({235, 1})
    ->Args({235, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_PolygonalLaplacianFromMesh(benchmark::State& state) {
  const Sphere& s = sphere(state.range(0));
  for (auto _ : state) {
    const zdg::PolygonalCalculus calculus(s.mesh, s.normals);
    const zdg::SparseMatrix l = calculus.laplacian(1.0, unsigned(state.range(1)));
    if (l.rows != calculus.vertex_count()) std::abort();
    benchmark::DoNotOptimize(l.value.data());
  }
  state.counters["faces"] = double(s.normals.size());
}
BENCHMARK(BM_PolygonalLaplacianFromMesh)
    ->Args({235, 1})
    ->Args({235, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

} // namespace

BENCHMARK_MAIN();
