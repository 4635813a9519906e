// zdg transform dt|voronoi|power|rdt|rma|chamfer|thickness: the separable exact l_p transforms,
// the chamfer transform and the local thickness on images read by the volume loader
// (cli/volume_input.hpp: every format and selection option; an .npy of any dimension); the result
// is written through an OutputSet (checked before any work, staged, renamed at the end), never
// over the input and never over an existing file unless --force.
#include <zdg/arith/error.hpp>
#include <zdg/cli/commands.hpp>
#include <zdg/cli/mpi_session.hpp>
#include <zdg/cli/volume_input.hpp>
#include <zdg/kernel/io/mapped_file.hpp>
#include <zdg/kernel/io/npy_io.hpp>
#include <zdg/kernel/io/output_files.hpp>
#include <zdg/kernel/io/pgm_io.hpp>
#include <zdg/kernel/io/vol_io.hpp>
#include <zdg/kernel/io/volume_io.hpp>
#include <zdg/kernel/transforms/chamfer_transform.hpp>
#include <zdg/kernel/transforms/distance_transform.hpp>
#include <zdg/kernel/transforms/distributed_transform.hpp>
#include <zdg/kernel/transforms/local_thickness.hpp>
#include <zdg/kernel/transforms/out_of_core_transform.hpp>
#include <zdg/kernel/transforms/power_map.hpp>
#include <zdg/kernel/transforms/reduced_medial_axis.hpp>
#include <zdg/kernel/transforms/reverse_distance_transform.hpp>
#include <zdg/kernel/transforms/separable_engine.hpp>
#include <zdg/kernel/transforms/voronoi_map.hpp>
#include <zdg/operations/transform_operations.hpp>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

#include <unistd.h>

namespace zdg::cli {

namespace {

struct TransformArgs {
  VolumeInputArgs in;
  std::string output, metric = "l2", torus, lower, memory, mask;
  unsigned threads = 0;
  bool json = false, force = false, out_of_core = false, quiet = false, mpi = false;
  // The file the result is written to before it is moved onto `output` (set by check_paths).
  std::shared_ptr<OutputSet> outputs;
  std::string staged;
};

std::vector<std::int64_t> parse_int_list(const std::string& text, const std::string& what) {
  std::vector<std::int64_t> out;
  std::string_view rest = text;
  for (;;) {
    const auto comma = rest.find(',');
    const std::string_view item = rest.substr(0, comma);
    try {
      out.push_back(parse_integer<std::int64_t>(item));
    } catch (const Error& e) {
      throw InvalidArgument(what + ": " + e.what() + " (in the list '" + text + "')");
    }
    if (comma == std::string_view::npos) break;
    rest.remove_prefix(comma + 1);
  }
  return out;
}

std::vector<std::int64_t> lower_of(const TransformArgs& a, int dim) {
  auto low = parse_int_list(a.lower, "--lower");
  if (static_cast<int>(low.size()) != dim) {
    throw InvalidArgument("--lower has " + std::to_string(low.size()) + " entries for a " +
                          std::to_string(dim) + "-D image");
  }
  return low;
}

// The image placed at the --lower bounds when given.
template <class T>
Image<T> at_lower(const TransformArgs& a, Image<T> img) {
  if (a.lower.empty()) return img;
  auto low = lower_of(a, img.dim());
  return Image<T>(Domain(img.domain().extents(), low), std::move(img.values()));
}

// The lean, out-of-core and MPI paths map the .npy file itself: C order, no selection.
bool mapped_input(const TransformArgs& a) {
  return !has_selection(a.in) && !raw_layout(a.in).given() && lower_extension(a.in.path) == ".npy";
}

// The input's values as exact integers (power, rdt), in any format (read_integer_image).
Image<std::int64_t> read_values(const TransformArgs& a) {
  return at_lower(a, read_integer_image(a.in.path, raw_layout(a.in)));
}

// The input's object (dt, voronoi, rma): value != 0 by default, else the selection options.
// An .npy of any dimension is read directly; every other input through the volume loader.
Image<std::uint8_t> read_mask(const TransformArgs& a) {
  if (mapped_input(a)) {
    if (!std::filesystem::exists(a.in.path)) throw IoError(a.in.path + ": no such file");
    return at_lower(a, npy_to_mask(read_npy(a.in.path), {}, a.in.path));
  }
  const ObjectSelection selection = object_selection(a.in); // option errors before reading
  return at_lower(a, select_object(load_volume(a.in, 0).volume, selection, a.threads).mask);
}

TransformOptions make_options(const TransformArgs& a, int dim) {
  TransformOptions opt;
  opt.metric = parse_metric(a.metric);
  opt.threads = a.threads;
  if (!a.torus.empty()) {
    opt.torus.assign(static_cast<std::size_t>(dim), false);
    if (a.torus == "all") {
      opt.torus.assign(static_cast<std::size_t>(dim), true);
    } else {
      for (auto k : parse_int_list(a.torus, "--torus")) {
        if (k < 0 || k >= dim) {
          throw InvalidArgument("--torus: axis " + std::to_string(k) + " of a " +
                                std::to_string(dim) + "-D image (axes 0.." +
                                std::to_string(dim - 1) + ")");
        }
        opt.torus[static_cast<std::size_t>(k)] = true;
      }
    }
  }
  return opt;
}

// Checks the output before any work (OutputSet: the folder exists, the output is not a
// folder, an existing file is refused unless --force, the output is not the input) and
// prepares its staging file.
void check_paths(TransformArgs& a) {
  if (a.output.empty()) throw InvalidArgument("no output file (-o OUT)");
  parse_metric(a.metric); // a metric out of the supported range fails before the input is read
  check_not_input(a.in.path, a.output);
  const std::string e = lower_extension(a.output);
  if (e != ".npy" && e != ".pgm" && e != ".vol") {
    throw IoError(a.output + ": unknown output format '" + e + "' (.npy, .pgm or .vol)");
  }
  a.outputs = std::make_shared<OutputSet>(a.force ? Existing::replace : Existing::refuse);
  a.staged = a.outputs->add(a.output).string();
}

void commit(const TransformArgs& a) {
  a.outputs->commit();
}

std::vector<std::int64_t> shape_of(const Domain& d) {
  return d.extents();
}

// Writes an image of unsigned values to the staging file, in the format of the output's
// extension.
void write_unsigned(const TransformArgs& a, const Domain& dom, const std::vector<std::uint64_t>& v,
                    DType dtype) {
  const std::string& path = a.staged;
  std::string e = lower_extension(a.output);
  if (e == ".pgm") {
    write_pgm(path, Image<std::uint64_t>(dom, v));
  } else if (e == ".vol") {
    write_vol(path, Image<std::uint64_t>(dom, v));
  } else if (e == ".npy") {
    std::vector<std::int64_t> s(v.begin(), v.end());
    if (dtype == DType::U64) {
      write_npy(path, make_npy<std::uint64_t>(shape_of(dom), v));
    } else {
      write_npy(path, make_npy(dtype, shape_of(dom), s));
    }
  } else {
    throw IoError(a.output + ": unknown output format '" + e + "' (.npy, .pgm or .vol)");
  }
}

void require_npy(const std::string& path, const char* what) {
  if (lower_extension(path) != ".npy") {
    throw IoError(path + ": " + what + " output is an .npy array (got '" + lower_extension(path) +
                  "')");
  }
}

// Site coordinates (*dims, d) from linear site indices.
NpyArray sites_array(const Domain& dom, const std::vector<std::int64_t>& site) {
  const auto d = static_cast<std::size_t>(dom.dim());
  std::vector<std::int64_t> coords(site.size() * d);
  std::vector<std::int64_t> p(d);
  for (std::size_t i = 0; i < site.size(); ++i) {
    dom.point(site[i], p);
    for (std::size_t k = 0; k < d; ++k) coords[i * d + k] = p[k];
  }
  auto shape = shape_of(dom);
  shape.push_back(dom.dim());
  return make_npy<std::int64_t>(shape, coords);
}

void report(const TransformArgs& a, const std::string& cmd, const Domain& dom,
            const TransformOptions& opt, const std::string& dtype, const std::string& max_value,
            double seconds, nlohmann::json extra = nlohmann::json::object()) {
  if (a.json) {
    nlohmann::json torus = nlohmann::json::array();
    for (int k = 0; k < dom.dim(); ++k) {
      if (opt.periodic(k)) torus.push_back(k);
    }
    nlohmann::json j = {{"command", cmd},
                        {"input", a.in.path},
                        {"output", a.output},
                        {"shape", shape_of(dom)},
                        {"lower", dom.lowers()},
                        {"metric", opt.metric.name()},
                        {"torus", torus},
                        {"dtype", dtype},
                        {"max_value", max_value},
                        {"seconds", seconds},
                        {"threads", detail::resolve_threads(opt.threads, dom.size())}};
    for (auto& [k, v] : extra.items()) j[k] = v;
    print_json(j);
    return;
  }
  std::cout << "zdg transform " << cmd << ": " << a.output << " (" << dtype << ", "
            << (extra.contains("metric") ? extra["metric"].get<std::string>() : opt.metric.name());
  if (!max_value.empty()) std::cout << ", max " << max_value;
  std::cout << ") in " << seconds << " s\n";
}

double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

template <class T>
void run_dt_as(TransformArgs& a, const Image<std::uint8_t>& mask, const TransformOptions& opt,
               DType dtype, std::chrono::steady_clock::time_point t0) {
  auto dt = distance_transform<T>(mask, opt);
  double secs = since(t0);
  std::vector<std::uint64_t> v(dt.values().begin(), dt.values().end());
  std::uint64_t mx = 0;
  for (auto x : v) mx = std::max(mx, x);
  write_unsigned(a, mask.domain(), v, dtype);
  commit(a);
  report(a, "dt", mask.domain(), opt, dtype_name(dtype), std::to_string(mx), secs);
}

// A byte count: an integer with an optional suffix K, M, G, T (powers of 1024; "16G").
std::uint64_t parse_memory(const std::string& text) {
  std::string digits = text;
  std::uint64_t unit = 1;
  if (!digits.empty()) {
    const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(digits.back())));
    const std::string units = "KMGT";
    if (const auto k = units.find(c); k != std::string::npos) {
      unit = std::uint64_t{1} << (10 * (k + 1));
      digits.pop_back();
    }
  }
  std::uint64_t v = 0;
  try {
    v = parse_integer<std::uint64_t>(digits);
  } catch (const Error&) {
    throw InvalidArgument("--memory '" + text + "': a byte count such as 512M, 16G or 1073741824");
  }
  std::uint64_t bytes = 0;
  if (v == 0 || __builtin_mul_overflow(v, unit, &bytes)) {
    throw InvalidArgument("--memory '" + text + "': out of range (1 byte to 2^64 - 1)");
  }
  return bytes;
}

std::string mb(std::uint64_t bytes) {
  return std::to_string((bytes + 500'000) / 1'000'000) + " MB";
}

// Progress of a long run goes to stderr when it is a terminal and --quiet is not given.
bool show_progress(const TransformArgs& a) {
  return !a.quiet && ::isatty(2) != 0;
}

std::function<void(const OutOfCoreProgress&)> progress_printer(const TransformArgs& a) {
  if (!show_progress(a)) return {};
  return [](const OutOfCoreProgress& p) {
    std::cerr << "\rzdg transform dt: " << p.phase << " " << p.done << "/" << p.total << ", read "
              << mb(p.bytes_read) << ", written " << mb(p.bytes_written) << "   "
              << (p.done == p.total ? "\n" : "") << std::flush;
  };
}

// The same for an in-memory transform: the passes done (one per axis) and the seconds so far.
std::function<void(int, int)> pass_printer(const TransformArgs& a) {
  if (!show_progress(a)) return {};
  return [t0 = std::chrono::steady_clock::now()](int done, int total) {
    char secs[32];
    std::snprintf(secs, sizeof secs, "%.1f s", since(t0));
    std::cerr << "\rzdg transform dt: pass " << done << "/" << total << ", " << secs << "   "
              << (done == total ? "\n" : "") << std::flush;
  };
}

// The domain of an .npy input read in place (its shape, --lower): errors for a 0-D or empty
// array and a --lower of the wrong length.
Domain npy_domain(const TransformArgs& a, const NpyLayout& lay) {
  if (lay.shape.empty()) throw IoError(a.in.path + ": a 0-dimensional array is not an image");
  for (auto e : lay.shape) {
    if (e == 0) throw IoError(a.in.path + ": empty array (an extent is 0)");
  }
  std::vector<std::int64_t> low;
  if (!a.lower.empty()) low = lower_of(a, static_cast<int>(lay.shape.size()));
  return Domain(lay.shape, low);
}

bool lean_dt(TransformArgs& a) {
  const bool npy = mapped_input(a) && lower_extension(a.output) == ".npy";
  if (a.out_of_core && !npy) {
    if (lower_extension(a.in.path) == ".npy" && lower_extension(a.output) == ".npy") {
      throw InvalidArgument("--out-of-core maps the object value != 0 of an .npy file (no "
                            "--threshold, --range, --label, --invert or raw options)");
    }
    throw InvalidArgument("--out-of-core reads and writes .npy files (got " + a.in.path + " and " +
                          a.output + ")");
  }
  NpyTransformOptions o;
  // A bad --memory fails before the input is read.
  if (!a.memory.empty()) o.memory_budget = parse_memory(a.memory);
  if (!npy) return false;
  // The lean path (operations/transform_operations.hpp). The options are read here with the
  // array's dimension, as the general path reads them (the same errors on either path); a 0-D
  // or empty array is left to the operation's own message.
  const NpyLayout lay = read_npy_layout(a.in.path);
  o.input = a.in.path;
  o.output = a.staged;
  o.out_of_core = a.out_of_core;
  o.out_of_core_progress = progress_printer(a);
  o.pass_progress = pass_printer(a);
  const int dim = static_cast<int>(lay.shape.size());
  if (dim > 0 && std::find(lay.shape.begin(), lay.shape.end(), 0) == lay.shape.end()) {
    if (!a.lower.empty()) o.lower = lower_of(a, dim);
    o.transform = make_options(a, dim);
  }
  const auto r = npy_distance_transform(o);
  if (!r) return false;
  commit(a);
  nlohmann::json extra = nlohmann::json::object();
  if (r->out_of_core)
    extra = {{"out_of_core", true},
             {"memory_budget", r->memory_budget},
             {"in_memory_bytes", r->in_memory_bytes}};
  report(a, "dt", r->domain, o.transform, dtype_name(r->dtype), std::to_string(r->max_value),
         r->seconds, extra);
  return true;
}

void run_dt(TransformArgs& a) {
  check_paths(a);
  if (lean_dt(a)) return;
  auto mask = read_mask(a);
  auto opt = make_options(a, mask.dim());
  auto t0 = std::chrono::steady_clock::now();
  BigInt bound = distance_transform_max_value(mask.domain(), opt);
  if (const auto dtype = narrowest_unsigned(bound)) {
    with_unsigned(*dtype,
                  [&]<class T>(std::type_identity<T>) { run_dt_as<T>(a, mask, opt, *dtype, t0); });
  } else {
    // Values might exceed 64 bits: compute exactly, then check what was reached.
    auto dt = distance_transform<BigInt>(mask, opt);
    double secs = since(t0);
    BigInt mx = 0;
    for (const auto& x : dt.values()) mx = std::max(mx, x);
    if (mx > BigInt(std::numeric_limits<std::uint64_t>::max())) {
      throw OverflowError("distance transform: the largest value " + mx.str() + " (" +
                          opt.metric.name() + ") does not fit uint64, the widest npy type");
    }
    std::vector<std::uint64_t> v;
    v.reserve(dt.values().size());
    for (const auto& x : dt.values()) v.push_back(x.convert_to<std::uint64_t>());
    write_unsigned(a, mask.domain(), v, DType::U64);
    commit(a);
    report(a, "dt", mask.domain(), opt, "uint64", mx.str(), secs);
  }
}

void run_voronoi(TransformArgs& a) {
  check_paths(a);
  require_npy(a.output, "the Voronoi map");
  auto mask = read_mask(a);
  auto opt = make_options(a, mask.dim());
  auto t0 = std::chrono::steady_clock::now();
  auto map = voronoi_map(mask, opt);
  double secs = since(t0);
  write_npy(a.staged, sites_array(mask.domain(), map.site));
  commit(a);
  report(a, "voronoi", mask.domain(), opt, "int64", "", secs);
}

void run_power(TransformArgs& a) {
  check_paths(a);
  require_npy(a.output, "the power map");
  auto w = read_values(a);
  auto opt = make_options(a, w.dim());
  auto t0 = std::chrono::steady_clock::now();
  auto map = power_map(w, opt);
  double secs = since(t0);
  write_npy(a.staged, sites_array(w.domain(), map.site));
  commit(a);
  report(a, "power", w.domain(), opt, "int64", "", secs);
}

void run_rdt(TransformArgs& a) {
  check_paths(a);
  auto v = read_values(a);
  auto opt = make_options(a, v.dim());
  auto t0 = std::chrono::steady_clock::now();
  auto r = reverse_distance_transform(v, opt);
  double secs = since(t0);
  std::uint64_t count = 0;
  for (auto x : r.values()) count += x;
  write_unsigned(a, r.domain(), std::vector<std::uint64_t>(r.values().begin(), r.values().end()),
                 DType::U8);
  commit(a);
  report(a, "rdt", r.domain(), opt, "uint8", count > 0 ? "1" : "0", secs,
         {{"points", std::to_string(count)}});
}

void run_rma(TransformArgs& a) {
  check_paths(a);
  require_npy(a.output, "the medial axis");
  auto mask = read_mask(a);
  auto opt = make_options(a, mask.dim());
  auto t0 = std::chrono::steady_clock::now();
  auto balls = reduced_medial_axis(mask, opt);
  double secs = since(t0);
  const auto d = static_cast<std::size_t>(mask.dim());
  std::vector<std::int64_t> rows;
  std::int64_t mx = 0;
  for (const auto& b : balls) {
    rows.insert(rows.end(), b.centre.begin(), b.centre.end());
    rows.push_back(b.value);
    mx = std::max(mx, b.value);
  }
  write_npy(a.staged,
            make_npy<std::int64_t>(
                {static_cast<std::int64_t>(balls.size()), static_cast<std::int64_t>(d + 1)}, rows));
  commit(a);
  report(a, "rma", mask.domain(), opt, "int64", std::to_string(mx), secs,
         {{"balls", balls.size()}});
}

// zdg transform chamfer: the exact chamfer transform of a 2D or 3D object with a weighted mask
// (kernel/transforms/chamfer_transform.hpp); the output's dtype is the narrowest unsigned one
// that holds the largest possible value; the JSON gives the mask's error bound against l2.
void run_chamfer(TransformArgs& a) {
  check_paths(a);
  // The weights' syntax and signs fail before the input is read (the classes need its dimension).
  if (!a.mask.empty()) ChamferMask::parse(2, a.mask);
  auto shape = read_mask(a);
  const int d = shape.dim();
  if (d != 2 && d != 3) {
    throw InvalidArgument("chamfer: " + a.in.path + " is a " + std::to_string(d) +
                          "-D image (the masks are 2D or 3D)");
  }
  const ChamferMask mask =
      a.mask.empty() ? ChamferMask::borgefors(d) : ChamferMask::parse(d, a.mask);
  const auto t0 = std::chrono::steady_clock::now();
  const Domain& dom = shape.domain();
  const BigInt bound = chamfer_transform_max_value(dom, mask);
  const BigInt need = bound + mask.max_weight();
  std::vector<std::uint64_t> v;
  if (need <= BigInt(std::numeric_limits<std::uint32_t>::max())) {
    const auto r = chamfer_transform<std::uint32_t>(shape, mask);
    v.assign(r.values().begin(), r.values().end());
  } else if (need <= BigInt(std::numeric_limits<std::uint64_t>::max())) {
    v = chamfer_transform<std::uint64_t>(shape, mask).values();
  } else {
    const auto r = chamfer_transform<BigInt>(shape, mask);
    v.reserve(r.values().size());
    for (const auto& x : r.values()) {
      if (x > BigInt(std::numeric_limits<std::uint64_t>::max())) {
        throw OverflowError("chamfer transform: the value " + x.str() + " (mask " + mask.name() +
                            ") does not fit uint64, the widest npy type");
      }
      v.push_back(x.convert_to<std::uint64_t>());
    }
  }
  const double secs = since(t0);
  std::uint64_t mx = 0;
  for (auto x : v) mx = std::max(mx, x);
  const DType dtype = narrowest_unsigned(bound).value_or(DType::U64);
  write_unsigned(a, dom, v, dtype);
  commit(a);
  const auto e = chamfer_error_bound(mask);
  nlohmann::json extra = {{"metric", "chamfer " + mask.name()},
                          {"mask", mask.weights()},
                          {"error_bound",
                           {{"rho_min_squared", e.rho_min_squared.str()},
                            {"rho_max_squared", e.rho_max_squared.str()},
                            {"rho_min", e.rho_min},
                            {"rho_max", e.rho_max},
                            {"scale", mask.axis_weight()},
                            {"relative_error_below", e.error_below},
                            {"relative_error_above", e.error_above},
                            {"optimal_scale", e.optimal_scale},
                            {"optimal_relative_error", e.optimal_error}}},
                          {"threads", 1}};
  report(a, "chamfer", dom, TransformOptions{}, dtype_name(dtype), std::to_string(mx), secs, extra);
}

// zdg transform thickness: the local thickness (kernel/transforms/local_thickness.hpp), float32
// diameters in voxel units, 0 off the object; l2 without torus axes (no --metric, --torus).
void run_thickness(TransformArgs& a) {
  check_paths(a);
  require_npy(a.output, "the local thickness");
  auto mask = read_mask(a);
  TransformOptions opt;
  opt.threads = a.threads;
  auto t0 = std::chrono::steady_clock::now();
  auto t = local_thickness(mask, opt);
  double secs = since(t0);
  float mx = 0;
  double sum = 0;
  std::int64_t voxels = 0;
  for (std::int64_t i = 0; i < t.size(); ++i) {
    if (mask[i] == 0) continue;
    mx = std::max(mx, t[i]);
    sum += t[i];
    ++voxels;
  }
  write_npy(a.staged, make_npy<float>(shape_of(t.domain()), t.values()));
  commit(a);
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", static_cast<double>(mx));
  report(a, "thickness", t.domain(), opt, "float32", text, secs,
         {{"voxels", std::to_string(voxels)},
          {"mean_thickness", voxels > 0 ? sum / static_cast<double>(voxels) : 0.0}});
}

// A failure on some ranks only: its line, the staged output removed (MPI_Abort kills rank 0
// wherever it is, before its OutputSet could remove it; the ranks share the output's folder;
// empty: nothing staged on this rank), then the whole job ends with status 2.
[[noreturn]] void abort_job(MpiSession& mpi, const std::string& what, const std::string& staged) {
  std::cerr << "zdg: " << what << " (rank " << mpi.rank() << " of " << mpi.size() << ")"
            << std::endl;
  if (!staged.empty()) {
    std::error_code ec;
    std::filesystem::remove(staged, ec);
  }
  mpi.abort(2);
}

// `zdg transform dt|voronoi --mpi` (issue #15, kernel/transforms/distributed_transform.hpp): one
// rank of an MPI job. Rank r reads the slices it owns of the input .npy (MPI-IO), the ranks
// transform their slabs, exchange them, transform whole columns, and write their column blocks into
// the output with one collective MPI-IO write; rank 0 prepares the staged output (header, space
// reserved) and renames it when every rank has written. Failures: what every rank checks
// before any exchange (the input, the options, the output path, the background) is agreed on
// and reported once, by the lowest rank that met it (exit 2, nothing written); a failure after
// (the file system, the memory), on some ranks only, ends the whole job (MPI_Abort, exit 2).
template <class T>
void mpi_transform_as(TransformArgs& a, MpiSession& mpi, const std::string& cmd,
                      const NpyLayout& lay, const Domain& dom, const TransformOptions& opt,
                      DType dtype, std::vector<std::uint8_t>& slab, const std::string& header,
                      std::chrono::steady_clock::time_point t0) {
  const bool voronoi = cmd == "voronoi";
  const int d = dom.dim();
  const DistributedPart part = distributed_part(dom, mpi.rank(), mpi.size());
  const std::int64_t n0 = dom.extent(0), slice = dom.stride(0), w = part.columns.size();
  const std::string staged = mpi.broadcast(mpi.rank() == 0 ? a.staged : std::string(), 0);
  const std::uint64_t out_bytes =
      header.size() + static_cast<std::uint64_t>(dom.size()) *
                          (voronoi ? 8 * static_cast<std::uint64_t>(d) : sizeof(T));
  const bool show = mpi.rank() == 0 && show_progress(a);
  nlohmann::json stages = nlohmann::json::object();
  auto stage = [&](const std::string& name, double seconds) {
    // Each stage's time is the slowest rank's (a collective step: every rank reports it).
    const double slowest =
        static_cast<double>(mpi.max_over_ranks(static_cast<std::uint64_t>(seconds * 1e6))) / 1e6;
    stages[name] = slowest;
    if (!show) return;
    char secs[32];
    std::snprintf(secs, sizeof secs, "%.2f s", slowest);
    std::cerr << "zdg transform " << cmd << " --mpi (" << mpi.size() << " ranks): " << name << " "
              << secs;
    if (name == "read")
      std::cerr << ", " << mb(static_cast<std::uint64_t>(dom.size()) * dtype_size(lay.dtype))
                << " read";
    if (name == "write") std::cerr << ", " << mb(out_bytes) << " written";
    std::cerr << "\n";
  };
  stage("read", since(t0));
  std::string max_text;
  try {
    std::vector<T> out(static_cast<std::size_t>(n0 * w));
    std::vector<std::int64_t> sites;
    const T mx =
        distance_transform_distributed<T>(dom, slab.data(), static_cast<int>(dtype_size(lay.dtype)),
                                          opt, mpi, out.data(), voronoi ? &sites : nullptr, stage);
    std::vector<std::uint8_t>().swap(slab);
    const auto t_write = std::chrono::steady_clock::now();
    if (voronoi) {
      std::vector<T>().swap(out);
      const auto ud = static_cast<std::size_t>(d);
      std::vector<std::int64_t> coords(sites.size() * ud);
      for (std::size_t i = 0; i < sites.size(); ++i)
        dom.point(sites[i], std::span<std::int64_t>(coords.data() + i * ud, ud));
      const std::uint64_t item = 8 * ud;
      mpi.write_rows(staged, header.size() + static_cast<std::uint64_t>(part.columns.begin) * item,
                     static_cast<std::uint64_t>(w) * item, static_cast<std::uint64_t>(slice) * item,
                     n0, coords.data());
    } else {
      max_text = std::to_string(mx);
      mpi.write_rows(staged,
                     header.size() + static_cast<std::uint64_t>(part.columns.begin) * sizeof(T),
                     static_cast<std::uint64_t>(w) * sizeof(T),
                     static_cast<std::uint64_t>(slice) * sizeof(T), n0, out.data());
    }
    stage("write", since(t_write));
  } catch (const std::exception& e) {
    abort_job(mpi, e.what(), staged);
  }
  const double secs = since(t0);
  if (mpi.rank() != 0) return;
  commit(a);
  report(a, cmd, dom, opt, voronoi ? "int64" : dtype_name(dtype), max_text, secs,
         {{"mpi", true}, {"ranks", mpi.size()}, {"stages", stages}});
}

void run_mpi_rank(TransformArgs& a, Context& ctx, const std::string& cmd, MpiSession& mpi) {
  const auto t0 = std::chrono::steady_clock::now();
  const int r = mpi.rank(), P = mpi.size();
  // Checks and reads without any exchange; a failure is agreed on below.
  std::string failure;
  NpyLayout lay;
  Domain dom;
  TransformOptions opt;
  DType dtype = DType::U64;
  std::string header;
  std::vector<std::uint8_t> slab;
  bool background = false;
  try {
    if (a.out_of_core || !a.memory.empty()) {
      throw InvalidArgument("--mpi with --out-of-core or --memory: the ranks hold the volume "
                            "between them in memory (give one or the other)");
    }
    if (lower_extension(a.in.path) != ".npy" || lower_extension(a.output) != ".npy") {
      throw InvalidArgument("--mpi reads and writes .npy files (got " + a.in.path + " and " +
                            a.output + ")");
    }
    if (!mapped_input(a)) {
      throw InvalidArgument("--mpi reads the object value != 0 of an .npy file (no --threshold, "
                            "--range, --label, --invert or raw options)");
    }
    if (!std::filesystem::exists(a.in.path)) throw IoError(a.in.path + ": no such file");
    lay = read_npy_layout(a.in.path);
    if (lay.fortran_order) {
      throw InvalidArgument("--mpi: " + a.in.path +
                            " is a Fortran-order array; the ranks read C-order slices (save it "
                            "with np.ascontiguousarray)");
    }
    if (dtype_is_float(lay.dtype)) {
      throw InvalidArgument("--mpi: " + a.in.path + " holds " + dtype_name(lay.dtype) +
                            " values; the distributed transform reads integer or bool masks");
    }
    dom = npy_domain(a, lay);
    opt = make_options(a, dom.dim());
    // All cores by default: shared among the ranks of this machine.
    if (a.threads == 0) {
      opt.threads = std::max(1u, std::thread::hardware_concurrency() /
                                     static_cast<unsigned>(std::max(1, mpi.local_size())));
    }
    const DistributedPart part = distributed_part(dom, r, P); // d >= 2
    const auto bounds = detail::envelope_bounds(dom, opt, BigInt(0));
    if (bounds.width != detail::ValueWidth::I32 && bounds.width != detail::ValueWidth::I64) {
      throw InvalidArgument("--mpi: the intermediate values of " + opt.metric.name() +
                            " on this domain need more than 64 bits; use the transform without "
                            "--mpi");
    }
    std::vector<std::int64_t> out_shape = lay.shape;
    std::uint64_t out_item = 8;
    if (cmd == "voronoi") {
      dtype = DType::I64;
      out_shape.push_back(dom.dim());
      out_item = 8 * static_cast<std::uint64_t>(dom.dim());
    } else {
      const BigInt bound = distance_transform_max_value(dom, opt);
      dtype = narrowest_unsigned(bound).value_or(DType::U64);
      out_item = dtype_size(dtype);
    }
    if (static_cast<std::uint64_t>(part.columns.size()) * out_item > INT_MAX ||
        dom.extent(0) > INT_MAX) {
      throw InvalidArgument("--mpi: a rank's rows of " + std::to_string(part.columns.size()) +
                            " values pass MPI-IO's int counts: use more ranks");
    }
    header = npy_header_bytes(dtype, out_shape);
    if (r == 0) {
      check_paths(a);
      ReservedFile f(a.staged, header.size() + static_cast<std::uint64_t>(dom.size()) * out_item);
      f.write(0, header.data(), header.size());
      f.finish();
    }
    const auto item = dtype_size(lay.dtype);
    const auto uslice = static_cast<std::uint64_t>(dom.stride(0));
    slab.resize(static_cast<std::size_t>(part.slices.size()) * uslice * item);
    mpi.read(a.in.path,
             lay.data_offset + static_cast<std::uint64_t>(part.slices.begin) * uslice * item,
             slab.data(), slab.size());
    for (std::size_t i = 0; i < slab.size() && !background; i += item) {
      background = std::all_of(slab.begin() + static_cast<std::ptrdiff_t>(i),
                               slab.begin() + static_cast<std::ptrdiff_t>(i + item),
                               [](std::uint8_t b) { return b == 0; });
    }
  } catch (const std::bad_alloc&) {
    failure = "out of memory";
  } catch (const std::exception& e) {
    failure = e.what();
    if (failure.empty()) failure = "unknown error";
  }
  const bool any_background = mpi.max_over_ranks(background ? 1 : 0) != 0; // (every rank)
  if (failure.empty() && !any_background) {
    try {
      detail::throw_no_background(opt);
    } catch (const Error& e) {
      failure = e.what();
    }
  }
  // Reported once, by the lowest failing rank, before any rank exits (mpiexec ends the whole
  // job when a rank exits with a failure: a message still unwritten would be lost).
  const auto first_failed = static_cast<int>(mpi.min_over_ranks(failure.empty() ? P : r));
  if (first_failed < P) {
    if (r == first_failed) std::cerr << "zdg: " << failure << std::endl;
    // Rank 0's staged output goes before the last collective step: once a rank exits with a
    // failure, mpiexec kills the others, and rank 0 could be killed before its OutputSet's
    // destructor runs (1 run in 15 left the staging file behind).
    // (check_paths may itself have failed: then nothing was staged.)
    if (r == 0 && a.outputs && !a.staged.empty()) a.outputs->drop(a.output);
    mpi.max_over_ranks(0);
    ctx.exit_code = 2;
    return;
  }
  with_unsigned(dtype, [&]<class T>(std::type_identity<T>) {
    mpi_transform_as<T>(a, mpi, cmd, lay, dom, opt, dtype, slab, header, t0);
  });
}

void run_mpi(TransformArgs& a, Context& ctx, const std::string& cmd) {
  MpiSession mpi; // refuses a zdg built without MPI, or a process not started by mpirun
  try {
    run_mpi_rank(a, ctx, cmd, mpi);
  } catch (const std::exception& e) {
    // A failure the ranks did not agree on (the agreed ones return): the other ranks may be
    // waiting in a collective step, and this rank's MPI_Finalize would wait for them forever.
    abort_job(mpi, e.what(), a.staged);
  }
}

} // namespace

void add_transform_commands(CLI::App& app, Context& ctx) {
  auto* tr = app.add_subcommand(
      "transform",
      "separable exact l_p transforms of images (n-D .npy; 2D/3D .vol, .nii, .pgm, raw)");
  tr->require_subcommand(1);
  struct Spec {
    const char* name;
    const char* help;
    void (*run)(TransformArgs&);
  };
  static const Spec specs[] = {
      {"dt",
       "distance transform: d^p to the nearest 0 (squared for l2, d for linf); output the "
       "narrowest unsigned dtype holding the largest possible value",
       run_dt},
      {"voronoi", "Voronoi map: coordinates of a nearest background point, int64 (*dims, d)",
       run_voronoi},
      {"power",
       "power map of the sites v > 0 (v = radius^p): coordinates of the site "
       "minimising d^p - v, int64 (*dims, d)",
       run_power},
      {"rdt", "reverse distance transform: uint8 union of the open balls d(c, y)^p < v(c)",
       run_rdt},
      {"rma", "reduced discrete medial axis: int64 (k, d+1) rows centre..., DT value", run_rma},
  };
  for (const auto& s : specs) {
    auto args = std::make_shared<TransformArgs>();
    auto* sub = tr->add_subcommand(s.name, s.help);
    // The values commands read values; the others the object of the selection options.
    const bool values = std::string(s.name) == "power" || std::string(s.name) == "rdt";
    add_volume_input_options(*sub, args->in, {.selection = !values, .spacing = false});
    sub->add_option("-o,--output", args->output, "output file (written atomically)")->required();
    sub->add_option("--metric", args->metric,
                    "l1, l2, linf or lP (1 <= P <= 1000 and L^P < 2^4096, L the longest line)")
        ->capture_default_str();
    sub->add_option("--torus", args->torus, "periodic axes: comma list (0,2) or 'all'");
    sub->add_option("--lower", args->lower, "lower bounds of the domain, comma list (default 0)");
    sub->add_option("--threads", args->threads, "worker threads, 0..1024 (0 = all cores)")
        ->check(CLI::Range(0u, 1024u))
        ->capture_default_str();
    sub->add_flag("--force", args->force, "replace the output file if it exists");
    sub->add_flag("--json", args->json, "print a JSON summary on stdout");
    if (std::string(s.name) == "dt") {
      sub->add_flag("--out-of-core", args->out_of_core,
                    "transform by slabs and column blocks through the mapped .npy files, within "
                    "--memory (default 4G): for volumes larger than the memory");
      sub->add_option("--memory", args->memory,
                      "memory budget (512M, 16G): past it, the transform runs out of core");
    }
    if (std::string(s.name) == "dt" || std::string(s.name) == "voronoi") {
      sub->add_flag("--mpi", args->mpi,
                    "one rank of an MPI job (mpirun -np P zdg transform ... --mpi): slabs of "
                    "slices per rank, .npy in and out through MPI-IO; the same values");
      sub->add_flag("--quiet", args->quiet, "no progress on stderr");
    }
    auto run = s.run;
    const std::string name = s.name;
    sub->callback([args, run, name, &ctx] {
      if (args->mpi) {
        run_mpi(*args, ctx, name);
      } else {
        run(*args);
      }
    });
  }
  {
    auto args = std::make_shared<TransformArgs>();
    auto* sub = tr->add_subcommand(
        "chamfer", "chamfer distance transform of a 2D/3D object with a weighted mask (exact "
                   "shortest paths of mask moves); output the narrowest unsigned dtype");
    add_volume_input_options(*sub, args->in, {.selection = true, .spacing = false});
    sub->add_option("-o,--output", args->output, "output file (written atomically)")->required();
    sub->add_option("--mask", args->mask,
                    "weights as a comma list: 2D a[,b[,c]] (axis, diagonal, knight: 3,4 or "
                    "5,7,11), 3D a[,b[,c]] (face, edge, vertex: 3,4,5); default 3,4 / 3,4,5");
    sub->add_flag("--force", args->force, "replace the output file if it exists");
    sub->add_flag("--json", args->json, "print a JSON summary on stdout");
    sub->callback([args] { run_chamfer(*args); });
  }
  {
    auto args = std::make_shared<TransformArgs>();
    auto* sub = tr->add_subcommand(
        "thickness", "local thickness (Hildebrand-Ruegsegger): float32 diameter of the largest "
                     "inscribed Euclidean ball containing each object point, 0 off the object");
    add_volume_input_options(*sub, args->in, {.selection = true, .spacing = false});
    sub->add_option("-o,--output", args->output, "output .npy file (written atomically)")
        ->required();
    sub->add_option("--threads", args->threads, "worker threads, 0..1024 (0 = all cores)")
        ->check(CLI::Range(0u, 1024u))
        ->capture_default_str();
    sub->add_flag("--force", args->force, "replace the output file if it exists");
    sub->add_flag("--json", args->json, "print a JSON summary on stdout");
    sub->callback([args] { run_thickness(*args); });
  }
}

} // namespace zdg::cli
