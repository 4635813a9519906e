// Separable l_p transforms on the inputs of issue 4: a disc of radius 1800 in 4096^2, a ball of
// radius 0.45 n in n^3 (n = 256, 512). Arguments: n, p (0 = linf), threads. Reports the time
// and ns per voxel (counter "ns_per_voxel"). Peers: bench/compare_transforms.py.
//
// The bandwidth bound (issue #15, part 4): a STREAM triad a[i] = b[i] + s c[i] (McCalpin,
// "Memory bandwidth and machine balance", IEEE TCCA newsletter 1995) on three arrays of 2^25
// doubles, best of 5, measured in the same run with the same threads (benchmark Triad; bytes
// counted as STREAM does, 24 per element). Dt3d's counter "x_bound" is the transform's time
// over the time its data movement takes at that bandwidth: the mask pass reads 1 byte and
// writes 4 per voxel (int32 engine, uint32 output), each of the two other passes reads and
// writes 4: 1 + 4 + 2 x 8 = 21 bytes per voxel (l2 on 512^3 uses the int32 engine).
//
// Each case runs 1 s untimed first (MinWarmUpTime): the first fault of a process's fresh
// memory costs the VM's hypervisor more than every later one, and a 512^3 case runs one
// iteration.
//
// OutputWrite: what `zdg transform dt` adds to the transform to write its .npy output, n^3
// uint32 values from memory into a new file reserved on the disk (kernel/io/mapped_file.hpp
// ReservedFile, in the folder of TMPDIR) by the command's own write_values_max (the largest
// value and the write, in pieces by the workers): the floor of the command's time over its
// transform's (issue #15, part 1).
//
// CommandDt (issue #40 item 3): `zdg transform dt BALL.npy -o OUT.npy --quiet` (the binary
// beside this one, or $ZDG_BIN) on a ball n^3 .npy written once into TMPDIR, timed from the
// spawn to the exit, each iteration followed by the transform into a buffer allocated once (as
// Dt3d) and the output's write (as OutputWrite), and a `zdg --help` (the start of the
// process): the four side by side in one run, so that the machine's load and the state of its
// page cache move them together. Counters: the medians over the iterations of each (ms), and
// of the command's excess over its floor, command - transform - write (the target:
// at most 30 ms). ZDG_BENCH_VERBOSE=1 prints each iteration's four times on stderr.
//
//   build/bin/transform_bench --benchmark_filter='Dt3d/256/2/2'
#include <zdg/kernel/transforms/distance_transform.hpp>
#include <zdg/kernel/transforms/reduced_medial_axis.hpp>
#include <zdg/kernel/transforms/reverse_distance_transform.hpp>
#include <zdg/kernel/transforms/separable_engine.hpp>
#include <zdg/kernel/transforms/voronoi_map.hpp>

#include <benchmark/benchmark.h>

#include <zdg/kernel/io/mapped_file.hpp>
#include <zdg/kernel/io/npy_io.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>
#include <zdg/kernel/parallel/populate_pages.hpp>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <map>
#include <spawn.h>
#include <string>
#include <sys/wait.h>
#include <type_traits>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace {

using zdg::Domain;
using zdg::Image;

Image<std::uint8_t> disc(std::int64_t n, std::int64_t r) {
  Image<std::uint8_t> img(Domain({n, n}), std::uint8_t{0});
  const std::int64_t c = n / 2;
  for (std::int64_t y = 0; y < n; ++y) {
    for (std::int64_t x = 0; x < n; ++x) {
      img[y * n + x] = (x - c) * (x - c) + (y - c) * (y - c) < r * r ? 1 : 0;
    }
  }
  return img;
}

// A volume in memory mapped like the transforms' own buffers (zdg::assign_populated: huge
// pages where offered). On the development VM a mask in 4 KiB pages makes the mask pass of
// 512^3 1.5-2x slower (shadow paging: TLB refills trap to the hypervisor).
Image<std::uint8_t> volume(std::int64_t n) {
  std::vector<std::uint8_t> v;
  zdg::assign_populated(v, static_cast<std::size_t>(n * n * n), 0);
  return Image<std::uint8_t>(Domain({n, n, n}), std::move(v));
}

Image<std::uint8_t> ball(std::int64_t n) {
  Image<std::uint8_t> img = volume(n);
  const std::int64_t c = n / 2, r2 = (45 * n / 100) * (45 * n / 100);
  std::int64_t i = 0;
  for (std::int64_t z = 0; z < n; ++z) {
    for (std::int64_t y = 0; y < n; ++y) {
      for (std::int64_t x = 0; x < n; ++x, ++i) {
        img[i] = (x - c) * (x - c) + (y - c) * (y - c) + (z - c) * (z - c) < r2 ? 1 : 0;
      }
    }
  }
  return img;
}

// Each voxel foreground with probability 1/2 (fixed seed): the branchy case of the first pass.
Image<std::uint8_t> random_half(std::int64_t n) {
  Image<std::uint8_t> img = volume(n);
  std::uint64_t x = 0x9E3779B97F4A7C15ULL; // xorshift64
  for (std::int64_t i = 0; i < img.size(); ++i) {
    x ^= x << 13;
    x ^= x >> 7;
    x ^= x << 17;
    img[i] = static_cast<std::uint8_t>(x >> 63);
  }
  return img;
}

zdg::TransformOptions options(const benchmark::State& st) {
  zdg::TransformOptions opt;
  opt.metric = zdg::Metric{static_cast<int>(st.range(1))};
  opt.threads = static_cast<unsigned>(st.range(2));
  return opt;
}

// Whether the transform's values fit uint32 (the narrowest output, as `zdg transform dt` picks).
bool fits_uint32(const Image<std::uint8_t>& img, const zdg::TransformOptions& opt) {
  return zdg::distance_transform_max_value(img.domain(), opt) <= zdg::BigInt(4294967295ULL);
}

// The distance transform in the narrowest output type (as `zdg transform dt` does).
void run_dt(const Image<std::uint8_t>& img, const zdg::TransformOptions& opt) {
  if (fits_uint32(img, opt)) {
    benchmark::DoNotOptimize(zdg::distance_transform<std::uint32_t>(img, opt));
  } else {
    benchmark::DoNotOptimize(zdg::distance_transform<std::uint64_t>(img, opt));
  }
}

// STREAM triad bandwidth in bytes per second with `threads` threads (cached per count).
double triad_bandwidth(unsigned threads) {
  static std::map<unsigned, double> cache;
  if (auto it = cache.find(threads); it != cache.end()) return it->second;
  const std::int64_t n = std::int64_t{1} << 25;
  // Mapped like the transforms' buffers (huge pages where offered: the same memory kind).
  std::vector<double> a, b, c;
  zdg::assign_populated(a, static_cast<std::size_t>(n), threads);
  zdg::assign_populated(b, static_cast<std::size_t>(n), threads, 1.0);
  zdg::assign_populated(c, static_cast<std::size_t>(n), threads, 2.0);
  double best = 1e30;
  for (int rep = 0; rep < 5; ++rep) {
    const auto t0 = std::chrono::steady_clock::now();
    zdg::parallel_chunks(n, threads, [&](std::int64_t lo, std::int64_t hi) {
      for (std::int64_t i = lo; i < hi; ++i) {
        const auto k = static_cast<std::size_t>(i);
        a[k] = b[k] + 3.0 * c[k];
      }
    });
    benchmark::DoNotOptimize(a.data());
    best = std::min(best,
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return cache[threads] = 24.0 * static_cast<double>(n) / best;
}

void Triad(benchmark::State& st) {
  const auto threads = static_cast<unsigned>(st.range(0));
  double bw = 0;
  for (auto _ : st) {
    bw = triad_bandwidth(threads);
    benchmark::DoNotOptimize(bw);
  }
  st.counters["GB_per_s"] = bw * 1e-9;
}

void report(benchmark::State& st, std::int64_t voxels) {
  st.counters["ns_per_voxel"] = benchmark::Counter(static_cast<double>(voxels) * 1e-9,
                                                   benchmark::Counter::kIsIterationInvariantRate |
                                                       benchmark::Counter::kInvert);
}

void Dt2d(benchmark::State& st) {
  auto img = disc(st.range(0), 1800 * st.range(0) / 4096);
  auto opt = options(st);
  for (auto _ : st) run_dt(img, opt);
  report(st, img.size());
}

// The transform of img with its time per voxel and as a multiple of the bandwidth bound: the
// transform proper, into an output buffer allocated once (distance_transform_into, what `zdg
// transform` runs on a mapped .npy). The allocating form is Dt3dNew: on the development VM a
// fresh 512 MB buffer costs 0.05-1.2 s of page faults before the first value is written.
template <class T>
void dt_into_against_bound(benchmark::State& st, const Image<std::uint8_t>& img) {
  auto opt = options(st);
  const double bound = 21.0 * static_cast<double>(img.size()) / triad_bandwidth(opt.threads);
  std::vector<T> out;
  zdg::assign_populated(out, static_cast<std::size_t>(img.size()), opt.threads);
  for (auto _ : st) {
    zdg::distance_transform_into<T>(img.domain(), img.values().data(), 1, opt, out.data());
    benchmark::DoNotOptimize(out.data());
  }
  report(st, img.size());
  st.counters["x_bound"] = benchmark::Counter(bound, benchmark::Counter::kIsIterationInvariantRate |
                                                         benchmark::Counter::kInvert);
}

void dt_against_bound(benchmark::State& st, const Image<std::uint8_t>& img) {
  if (fits_uint32(img, options(st))) {
    dt_into_against_bound<std::uint32_t>(st, img);
  } else {
    dt_into_against_bound<std::uint64_t>(st, img);
  }
}

void Dt3d(benchmark::State& st) {
  dt_against_bound(st, ball(st.range(0)));
}

// The portable passes (set_envelope_simd(false)): what a CPU without AVX-512F runs, and the
// int64 and wider engines everywhere.
void portable_against_bound(benchmark::State& st, const Image<std::uint8_t>& img) {
  const bool was = zdg::detail::set_envelope_simd(false);
  dt_against_bound(st, img);
  zdg::detail::set_envelope_simd(was);
}

void Dt3dPortable(benchmark::State& st) {
  portable_against_bound(st, ball(st.range(0)));
}

void Random3dPortable(benchmark::State& st) {
  portable_against_bound(st, random_half(st.range(0)));
}

// The engine widths side by side (issue #40 item 4). Arguments: d (2: a disc of radius
// 1800 n / 4096 in n^2, 3: a ball of radius 0.45 n in n^3), n, p (0 = linf), threads, the
// narrowest engine (min_engine_bits: 0 = the narrowest that holds the values, 64 = int64 at
// least), vectorized passes allowed (1) or not (0: the portable loop). The transform into a
// buffer allocated once, uint32 where the values fit it and the engine is int32, uint64
// otherwise (so that the int64 engine works in place, as int32 does in uint32). Counter
// "int64": whether the engine ran on int64.
void DtWidth(benchmark::State& st) {
  const auto img =
      st.range(0) == 2 ? disc(st.range(1), 1800 * st.range(1) / 4096) : ball(st.range(1));
  zdg::TransformOptions opt;
  opt.metric = zdg::Metric{static_cast<int>(st.range(2))};
  opt.threads = static_cast<unsigned>(st.range(3));
  opt.min_engine_bits = static_cast<unsigned>(st.range(4));
  const bool was = zdg::detail::set_envelope_simd(st.range(5) != 0);
  const auto width = zdg::detail::envelope_bounds(img.domain(), opt, zdg::BigInt(0)).width;
  const auto run = [&]<class T>(std::type_identity<T>) {
    std::vector<T> out;
    zdg::assign_populated(out, static_cast<std::size_t>(img.size()), opt.threads);
    for (auto _ : st) {
      zdg::distance_transform_into<T>(img.domain(), img.values().data(), 1, opt, out.data());
      benchmark::DoNotOptimize(out.data());
    }
  };
  if (width == zdg::detail::ValueWidth::I32) {
    run(std::type_identity<std::uint32_t>{});
  } else {
    run(std::type_identity<std::uint64_t>{});
  }
  zdg::detail::set_envelope_simd(was);
  report(st, img.size());
  st.counters["int64"] = width == zdg::detail::ValueWidth::I64 ? 1 : 0;
}

void Dt3dNew(benchmark::State& st) {
  auto img = ball(st.range(0));
  auto opt = options(st);
  for (auto _ : st) run_dt(img, opt);
  report(st, img.size());
}

void Random3d(benchmark::State& st) {
  dt_against_bound(st, random_half(st.range(0)));
}

void OutputWrite(benchmark::State& st) {
  const std::int64_t n = st.range(0) * st.range(0) * st.range(0);
  const auto threads = static_cast<unsigned>(st.range(1));
  std::vector<std::uint32_t> values;
  zdg::assign_populated(values, static_cast<std::size_t>(n), threads, std::uint32_t{7});
  const auto path = (std::filesystem::temp_directory_path() /
                     ("zdg-bench-write-" + std::to_string(::getpid()) + ".bin"))
                        .string();
  for (auto _ : st) {
    zdg::ReservedFile out(path, static_cast<std::uint64_t>(n) * 4);
    benchmark::DoNotOptimize(zdg::write_values_max(out, 0, values.data(), n, threads));
    out.finish();
    st.PauseTiming();
    std::filesystem::remove(path);
    st.ResumeTiming();
  }
  st.counters["GB_per_s"] = benchmark::Counter(static_cast<double>(n) * 4e-9,
                                               benchmark::Counter::kIsIterationInvariantRate);
}

// Seconds from the spawn of argv to its exit (the benchmark fails on a nonzero status).
double run_process(benchmark::State& st, const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const auto t0 = std::chrono::steady_clock::now();
  pid_t pid = 0;
  posix_spawn_file_actions_t quiet; // stdout to /dev/null (the JSON, the help)
  ::posix_spawn_file_actions_init(&quiet);
  ::posix_spawn_file_actions_addopen(&quiet, 1, "/dev/null", O_WRONLY, 0);
  const int err = ::posix_spawn(&pid, argv[0], &quiet, nullptr, argv.data(), environ);
  ::posix_spawn_file_actions_destroy(&quiet);
  if (err != 0) {
    st.SkipWithError(("cannot start " + args[0]).c_str());
    return 0;
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    st.SkipWithError((args[0] + " " + args[1] + " failed").c_str());
  }
  return s;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

void CommandDt(benchmark::State& st) {
  const std::int64_t n = st.range(0);
  const auto threads = static_cast<unsigned>(st.range(1));
  std::string zdg;
  if (const char* e = std::getenv("ZDG_BIN")) {
    zdg = e;
  } else {
    zdg = (std::filesystem::read_symlink("/proc/self/exe").parent_path() / "zdg").string();
  }
  const auto folder = std::filesystem::temp_directory_path();
  const std::string tag = std::to_string(::getpid());
  const std::string in = (folder / ("zdg-bench-ball-" + tag + ".npy")).string();
  const std::string out = (folder / ("zdg-bench-dt-" + tag + ".npy")).string();
  const std::string raw = (folder / ("zdg-bench-write-" + tag + ".bin")).string();
  const auto img = ball(n);
  {
    std::vector<std::int64_t> shape{n, n, n};
    const std::string header = zdg::npy_header_bytes(zdg::DType::U8, shape);
    zdg::ReservedFile f(in, header.size() + static_cast<std::uint64_t>(img.size()));
    f.write(0, header.data(), header.size());
    f.write(header.size(), img.values().data(), static_cast<std::uint64_t>(img.size()));
    f.finish();
  }
  zdg::TransformOptions opt;
  opt.threads = threads;
  std::vector<std::uint32_t> values;
  zdg::assign_populated(values, static_cast<std::size_t>(img.size()), threads);
  const std::vector<std::string> command{
      zdg, "transform", "dt", in, "-o", out, "--quiet", "--threads", std::to_string(threads)};
  std::vector<double> cmd, tr, wr, start, excess;
  for (auto _ : st) {
    const double c = run_process(st, command);
    std::filesystem::remove(out);
    auto t0 = std::chrono::steady_clock::now();
    zdg::distance_transform_into<std::uint32_t>(img.domain(), img.values().data(), 1, opt,
                                                values.data());
    benchmark::DoNotOptimize(values.data());
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    t0 = std::chrono::steady_clock::now();
    {
      zdg::ReservedFile f(raw, static_cast<std::uint64_t>(img.size()) * 4);
      benchmark::DoNotOptimize(zdg::write_values_max(f, 0, values.data(), img.size(), threads));
      f.finish();
    }
    const double w = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::filesystem::remove(raw);
    const double s = run_process(st, {zdg, "--help"});
    cmd.push_back(c);
    tr.push_back(t);
    wr.push_back(w);
    start.push_back(s);
    excess.push_back(c - t - w);
    st.SetIterationTime(c);
    if (std::getenv("ZDG_BENCH_VERBOSE"))
      std::fprintf(stderr, "cmd %.1f tr %.1f wr %.1f start %.1f\n", 1e3 * c, 1e3 * t, 1e3 * w,
                   1e3 * s);
  }
  std::filesystem::remove(in);
  st.counters["command_ms"] = 1e3 * median(cmd);
  st.counters["transform_ms"] = 1e3 * median(tr);
  st.counters["write_ms"] = 1e3 * median(wr);
  st.counters["start_ms"] = 1e3 * median(start);
  st.counters["excess_ms"] = 1e3 * median(excess);
}

void Voronoi3d(benchmark::State& st) {
  auto img = ball(st.range(0));
  auto opt = options(st);
  for (auto _ : st) benchmark::DoNotOptimize(zdg::voronoi_map(img, opt));
  report(st, img.size());
}

void Rdt3d(benchmark::State& st) {
  auto img = ball(st.range(0));
  auto opt = options(st);
  auto dt = zdg::distance_transform<std::int64_t>(img, opt);
  for (auto _ : st) benchmark::DoNotOptimize(zdg::reverse_distance_transform(dt, opt));
  report(st, img.size());
}

void Rma3d(benchmark::State& st) {
  auto img = ball(st.range(0));
  auto opt = options(st);
  for (auto _ : st) benchmark::DoNotOptimize(zdg::reduced_medial_axis(img, opt));
  report(st, img.size());
}

BENCHMARK(Triad)->Arg(1)->Arg(2)->Iterations(1)->UseRealTime();
BENCHMARK(Dt2d)
    ->Args({4096, 2, 1})
    ->Args({4096, 2, 2})
    ->Args({4096, 1, 2})
    ->Args({4096, 0, 2})
    ->Args({4096, 3, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(Dt3d)
    ->Args({256, 2, 1})
    ->Args({256, 2, 2})
    ->Args({256, 3, 2})
    ->Args({256, 1, 2})
    ->Args({256, 0, 2})
    ->Args({512, 2, 1})
    ->Args({512, 2, 2})
    ->Args({512, 3, 2})
    ->MinWarmUpTime(1.0)
    ->MinTime(2.0)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(DtWidth)
    ->Args({2, 4096, 2, 2, 0, 1})
    ->Args({2, 4096, 2, 2, 64, 1})
    ->Args({2, 4096, 3, 2, 0, 1})
    ->Args({2, 4096, 3, 2, 0, 0})
    ->Args({3, 512, 2, 2, 0, 1})
    ->Args({3, 512, 2, 2, 64, 1})
    ->Args({3, 512, 3, 2, 0, 1})
    ->Args({3, 512, 3, 2, 64, 1})
    ->Args({3, 512, 3, 2, 64, 0})
    ->Args({3, 672, 2, 2, 0, 1})
    ->Args({3, 672, 3, 2, 0, 1})
    ->Args({3, 672, 3, 2, 0, 0})
    ->MinWarmUpTime(1.0)
    ->MinTime(2.0)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(Dt3dNew)
    ->Args({256, 2, 1})
    ->Args({256, 2, 2})
    ->Args({512, 2, 1})
    ->Args({512, 2, 2})
    ->MinWarmUpTime(1.0)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(Random3d)
    ->Args({256, 2, 2})
    ->MinWarmUpTime(1.0)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(Dt3dPortable)
    ->Args({256, 2, 2})
    ->Args({256, 3, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(Random3dPortable)->Args({256, 2, 2})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(OutputWrite)
    ->Args({512, 1})
    ->Args({512, 2})
    ->MinWarmUpTime(1.0)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(CommandDt)->Args({512, 2})->Iterations(7)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(Voronoi3d)->Args({256, 2, 2})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Rdt3d)->Args({256, 2, 2})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Rma3d)->Args({256, 2, 2})->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
