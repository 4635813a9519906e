// The 3D integral invariants, old counter against new, per surfel.
//
//  * sphere1 (the unit sphere, box [-1.25, 1.25]^3) at h = 0.025 with R = 3 h^{1/3} (R/h ~ 35
//    voxels, ~30,000 surfels), digitized exactly by the integer predicate |z|^2 <= 40^2;
//  * the published protocol of CVIU 2014 (papers/cviu2014-ii3d): sphere9, rcube and goursat
//    digitized by their exact polynomial predicates at h = exp(-i/10), R = 9 h^{1/3}, on a
//    patch of the surface (the surfels within distance 2 of a point of the surface, a few
//    thousand, contiguous so that the incremental walk moves by unit steps as on the whole
//    surface). Counters: `columns` (ii_surfel_moments, from the column runs) and `walk`
//    (ii_surfel_moments_incremental); both give the same integers (checked here too);
//  * the same shapes, whole surfaces (every boundary surfel, as in a run of the paper's
//    sweep, translation (0.1, 0.2, 0.3)), one thread, one iteration: the per-surfel cost of
//    the sweep, old counter against new (Surface/...).
//  * the ball sums of a whole surface (goursat, i = 26), the AVX-512 and AVX2 forms against
//    the portable loop (BallSums/...).
//   build/bin/ii_3d_bench --benchmark_counters_tabular=true
#include <zdg/convergence/shapes_3d.hpp>
#include <zdg/estimators/ii_3d.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <stdexcept>
#include <unordered_set>

namespace {

constexpr std::int64_t kN = 40; // h = 1 / kN
const double kH = 1.0 / double(kN);
const double kR = 3.0 * std::cbrt(kH);
const zdg::VoxelBox kBox{{-50, -50, -50}, {50, 50, 50}};

const zdg::VoxelPredicate& sphere1() {
  static const zdg::VoxelPredicate in = [](const zdg::Voxel& z) {
    return z.x * z.x + z.y * z.y + z.z * z.z <= kN * kN;
  };
  return in;
}

const std::vector<zdg::Surfel>& surface() {
  static const auto s =
      zdg::track_surface(sphere1(), kBox, zdg::find_boundary_surfel(sphere1(), kBox, {0, 0, 0}));
  return s;
}

void BM_TrackSurface(benchmark::State& state) {
  for (auto _ : state) {
    const auto s =
        zdg::track_surface(sphere1(), kBox, zdg::find_boundary_surfel(sphere1(), kBox, {0, 0, 0}));
    benchmark::DoNotOptimize(s.data());
    state.counters["surfels"] = double(s.size());
  }
}

template <bool Columns>
void BM_Sphere1Moments(benchmark::State& state) {
  const int threads = int(state.range(0));
  const auto r2 = zdg::ii_digital_radius2(kR, kH);
  zdg::IISurfelMoments m;
  for (auto _ : state) {
    m = Columns ? zdg::ii_surfel_moments(sphere1(), kBox, surface(), r2, threads, true)
                : zdg::ii_surfel_moments_incremental(sphere1(), kBox, surface(), r2, threads, true);
    benchmark::DoNotOptimize(m.moments.data());
  }
  state.counters["surfels"] = double(surface().size());
  state.counters["r"] = kR / kH;
  state.counters["us/surfel"] = benchmark::Counter(double(surface().size()) * 1e-6,
                                                   benchmark::Counter::kIsIterationInvariantRate |
                                                       benchmark::Counter::kInvert);
  state.counters["evals"] = double(m.stats.predicate_evaluations);
}

struct Patch {
  zdg::VoxelPredicate inside;
  zdg::VoxelBox box;
  std::vector<zdg::Surfel> surfels;
  double h = 0, R = 0;
};

// The surfels of the digitized shape within distance 2 of its surface point nearest to
// (1, 2, 9), at h = exp(-i/10), R = 9 h^{1/3}.
const Patch& patch(const std::string& shape, int i) {
  static std::map<std::pair<std::string, int>, Patch> cache;
  auto it = cache.find({shape, i});
  if (it != cache.end()) return it->second;
  Patch p;
  p.h = std::exp(-i / 10.0);
  p.R = 9.0 * std::cbrt(p.h);
  const auto s = zdg::parse_shape(shape);
  const auto& s3 = dynamic_cast<const zdg::Shape3&>(*s);
  p.inside = s3.digitize(p.h, {0.1, 0.2, 0.3});
  const std::int64_t n = std::int64_t(std::ceil(10.5 / p.h));
  p.box = {{-n, -n, -n}, {n, n, n}};
  const auto q = s3.project({1, 2, 9}).point;
  // Scan a box around q; keep the surfels between two voxels of that box.
  const std::int64_t m = std::int64_t(std::ceil(2.5 / p.h));
  const zdg::Voxel c0{std::int64_t(std::floor((q.x + 0.1) / p.h)),
                      std::int64_t(std::floor((q.y + 0.2) / p.h)),
                      std::int64_t(std::floor((q.z + 0.3) / p.h))};
  const zdg::VoxelBox near{{c0.x - m, c0.y - m, c0.z - m}, {c0.x + m, c0.y + m, c0.z + m}};
  for (const auto& sf : zdg::boundary_surfels(p.inside, near)) {
    if (!near.contains(zdg::outer_voxel(sf)) || !near.contains(zdg::inner_voxel(sf))) continue;
    const auto c = zdg::surfel_centre(sf, p.h);
    const double dx = c.x - 0.1 - q.x, dy = c.y - 0.2 - q.y, dz = c.z - 0.3 - q.z;
    if (dx * dx + dy * dy + dz * dz <= 4.0) p.surfels.push_back(sf);
  }
  return cache.emplace(std::pair{shape, i}, std::move(p)).first->second;
}

template <bool Columns>
void BM_PaperPatch(benchmark::State& state, const std::string& shape) {
  const Patch& p = patch(shape, int(state.range(0)));
  const auto r2 = zdg::ii_digital_radius2(p.R, p.h);
  zdg::IISurfelMoments m;
  for (auto _ : state) {
    m = Columns ? zdg::ii_surfel_moments(p.inside, p.box, p.surfels, r2, 1, true)
                : zdg::ii_surfel_moments_incremental(p.inside, p.box, p.surfels, r2, 1, true);
    benchmark::DoNotOptimize(m.moments.data());
  }
  if (Columns) {
    const auto w = zdg::ii_surfel_moments_incremental(p.inside, p.box, p.surfels, r2, 1, true);
    for (std::size_t k = 0; k < p.surfels.size(); ++k)
      if (!(w.moments[k].inner == m.moments[k].inner) ||
          !(w.moments[k].outer == m.moments[k].outer))
        throw std::logic_error("the counters disagree");
  }
  state.counters["surfels"] = double(p.surfels.size());
  state.counters["r"] = p.R / p.h;
  state.counters["us/surfel"] = benchmark::Counter(double(p.surfels.size()) * 1e-6,
                                                   benchmark::Counter::kIsIterationInvariantRate |
                                                       benchmark::Counter::kInvert);
  state.counters["evals/surfel"] = double(m.stats.predicate_evaluations) / double(p.surfels.size());
}

void BM_PatchColumns(benchmark::State& state, const std::string& shape) {
  BM_PaperPatch<true>(state, shape);
}
void BM_PatchWalk(benchmark::State& state, const std::string& shape) {
  BM_PaperPatch<false>(state, shape);
}

// The whole surface of the digitized shape at h = exp(-i/10), R = 9 h^{1/3}.
struct WholeSurface {
  zdg::VoxelPredicate inside;
  zdg::VoxelBox box;
  std::vector<zdg::Surfel> surfels;
  double h = 0, R = 0;
};

WholeSurface whole_surface(const std::string& shape, int i) {
  WholeSurface w;
  w.h = std::exp(-i / 10.0);
  w.R = 9.0 * std::cbrt(w.h);
  const auto s = zdg::parse_shape(shape);
  const auto& s3 = dynamic_cast<const zdg::Shape3&>(*s);
  w.inside = s3.digitize(w.h, {0.1, 0.2, 0.3});
  const std::int64_t n = std::int64_t(std::ceil(10.5 / w.h));
  w.box = {{-n, -n, -n}, {n, n, n}};
  w.surfels =
      zdg::track_surface(w.inside, w.box, zdg::find_boundary_surfel(w.inside, w.box, {0, 0, 0}));
  return w;
}

template <bool Columns>
void BM_WholeSurface(benchmark::State& state, const std::string& shape) {
  const WholeSurface w = whole_surface(shape, int(state.range(0)));
  const auto r2 = zdg::ii_digital_radius2(w.R, w.h);
  zdg::IISurfelMoments m;
  for (auto _ : state) {
    m = Columns ? zdg::ii_surfel_moments(w.inside, w.box, w.surfels, r2, 1, true)
                : zdg::ii_surfel_moments_incremental(w.inside, w.box, w.surfels, r2, 1, true);
    benchmark::DoNotOptimize(m.moments.data());
  }
  state.counters["surfels"] = double(w.surfels.size());
  state.counters["r"] = w.R / w.h;
  state.counters["us/surfel"] = benchmark::Counter(double(w.surfels.size()) * 1e-6,
                                                   benchmark::Counter::kIsIterationInvariantRate |
                                                       benchmark::Counter::kInvert);
  state.counters["evals/surfel"] = double(m.stats.predicate_evaluations) / double(w.surfels.size());
}

void BM_SurfaceColumns(benchmark::State& state, const std::string& shape) {
  BM_WholeSurface<true>(state, shape);
}
void BM_SurfaceWalk(benchmark::State& state, const std::string& shape) {
  BM_WholeSurface<false>(state, shape);
}

// The ball moments at the inner and outer voxels of a whole surface, the AVX-512 and AVX2
// forms of the sums against the portable loop (BallSums/avx512_goursat/..., avx2_goursat,
// portable_goursat; where the CPU lacks a form the next narrower one runs: the counter
// `lanes` says which ran).
void BM_BallSums(benchmark::State& state, const std::string& shape, int lanes) {
  const WholeSurface w = whole_surface(shape, int(state.range(0)));
  const auto r2 = zdg::ii_digital_radius2(w.R, w.h);
  std::vector<zdg::Voxel> centres;
  {
    std::unordered_set<zdg::Voxel, zdg::KPointHash> seen;
    for (const auto& s : w.surfels)
      for (const auto& v : {zdg::inner_voxel(s), zdg::outer_voxel(s)})
        if (seen.insert(v).second) centres.push_back(v);
  }
  zdg::ColumnMoments m;
  for (auto _ : state) {
    m = zdg::detail::ball_moments_by_columns(w.inside, w.box, centres, r2, 1, true, lanes);
    benchmark::DoNotOptimize(m.moments.data());
  }
  const double segments = double(m.stats.segments + m.stats.layer_segments);
  state.counters["centres"] = double(centres.size());
  state.counters["lanes"] = m.stats.simd_lanes;
  state.counters["ns/segment"] = benchmark::Counter(
      segments * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

BENCHMARK(BM_TrackSurface)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_BallSums, avx512_goursat, std::string("goursat"), 16)
    ->Arg(26)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_BallSums, avx2_goursat, std::string("goursat"), 8)
    ->Arg(26)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_BallSums, portable_goursat, std::string("goursat"), 0)
    ->Arg(26)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Sphere1Moments<true>)
    ->Name("Sphere1/columns")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_Sphere1Moments<false>)
    ->Name("Sphere1/walk")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_PatchColumns, rcube, std::string("rcube"))
    ->Arg(10)
    ->Arg(20)
    ->Arg(26)
    ->Arg(32)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_PatchWalk, rcube, std::string("rcube"))
    ->Arg(10)
    ->Arg(20)
    ->Arg(26)
    ->Arg(32)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_PatchColumns, goursat, std::string("goursat"))
    ->Arg(20)
    ->Arg(32)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_PatchWalk, goursat, std::string("goursat"))
    ->Arg(20)
    ->Arg(32)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Whole surfaces: one iteration each (the walk at i = 26 takes about a minute per shape).
BENCHMARK_CAPTURE(BM_SurfaceColumns, sphere9, std::string("sphere9"))
    ->Arg(20)
    ->Arg(26)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SurfaceWalk, sphere9, std::string("sphere9"))
    ->Arg(20)
    ->Arg(26)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SurfaceColumns, rcube, std::string("rcube"))
    ->Arg(20)
    ->Arg(26)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SurfaceWalk, rcube, std::string("rcube"))
    ->Arg(20)
    ->Arg(26)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SurfaceColumns, goursat, std::string("goursat"))
    ->Arg(20)
    ->Arg(26)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SurfaceWalk, goursat, std::string("goursat"))
    ->Arg(20)
    ->Arg(26)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
