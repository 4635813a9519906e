// zdg surface / zdg contour: the boundary of the object of a user's 3D / 2D image, its
// topology, estimators on it, a mesh or a drawing, and a JSON summary.
//
//   zdg surface INPUT [selection] [--adjacency 6,26] [--component largest|all|K]
//               [--estimate ii-mean,ii-k1,...,geodesic,at-normal] [--source SURFEL|X,Y,Z]
//               [--at-alpha A] [--at-lambda L] [--radius R|Rv]
//               [--mesh primal|marching-cubes]
//               [-o OUT.ply|.obj|.off] [--csv F] [--png F [--color E] [--view AZ,EL]
//               [--png-size WxH]] [--threads N] [--json] [--quiet] [--force]
//   zdg contour INPUT [selection] [--adjacency 4,8] [--component ...]
//               [--estimate ii-curvature,...] [--radius R|Rv] [-o OUT.svg] [--csv F]
//               [--png F [--color ii-curvature] [--png-size WxH]] ...
//
// The command parses, calls the library and prints; the algorithms are in kernel/
// (image_surfels, image_surfaces, primal_surface_mesh, marching_cubes, image_contours,
// connected_components, betti_numbers, mesh_io, render_mesh, render_contours) and
// estimators/ (volume_ii, contour_estimators, digital_integration, heat_geodesics,
// ambrosio_tortorelli).
// Outputs are declared to an OutputSet before the input is read (a missing folder or an
// existing file without --force fails at once) and renamed into place at the end.
#include <zdg/arith/error.hpp>
#include <zdg/cli/commands.hpp>
#include <zdg/cli/volume_input.hpp>
#include <zdg/estimators/ambrosio_tortorelli.hpp>
#include <zdg/estimators/contour_estimators.hpp>
#include <zdg/estimators/digital_integration.hpp>
#include <zdg/estimators/heat_geodesics.hpp>
#include <zdg/estimators/volume_ii.hpp>
#include <zdg/kernel/curves/image_contours.hpp>
#include <zdg/kernel/io/mesh_io.hpp>
#include <zdg/kernel/io/output_files.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>
#include <zdg/kernel/render/contour_svg.hpp>
#include <zdg/kernel/render/picture.hpp>
#include <zdg/kernel/render/render_contours.hpp>
#include <zdg/kernel/render/render_mesh.hpp>
#include <zdg/kernel/surfaces/image_surfaces.hpp>
#include <zdg/kernel/surfaces/image_surfels.hpp>
#include <zdg/kernel/surfaces/marching_cubes.hpp>
#include <zdg/kernel/surfaces/primal_surface_mesh.hpp>
#include <zdg/kernel/surfaces/surfel_complex.hpp>
#include <zdg/kernel/topology/adjacency.hpp>
#include <zdg/kernel/topology/betti_numbers.hpp>
#include <zdg/kernel/topology/connected_components.hpp>

#include <fmt/core.h>
#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <unistd.h>
#include <vector>

namespace zdg::cli {

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::string str(std::int64_t v) {
  return std::to_string(v);
}

// CPU seconds of the process (all threads): with the wall-clock seconds, the time of a step
// on a machine shared with other work.
double process_cpu_seconds() {
  timespec t{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// Progress on stderr when it is a terminal (and not --quiet): one line per step. Records the
// wall-clock and CPU seconds of each step for --json ("seconds", "cpu_seconds").
class Progress {
public:
  explicit Progress(bool enabled) : on_(enabled && ::isatty(2) == 1) {}
  void start(const std::string& what) {
    what_ = what;
    t0_ = Clock::now();
    cpu0_ = process_cpu_seconds();
    if (on_) fmt::print(stderr, "zdg: {} ...\n", what);
  }
  /// Ends the step, recorded as `key`.
  void done(const std::string& key, const std::string& detail = "") {
    const double s = since(t0_);
    seconds[key] = s;
    cpu_seconds[key] = process_cpu_seconds() - cpu0_;
    if (on_)
      fmt::print(stderr, "zdg: {} done{}{} ({:.2f} s)\n", what_, detail.empty() ? "" : ": ", detail,
                 s);
  }
  nlohmann::json seconds = nlohmann::json::object(), cpu_seconds = nlohmann::json::object();

private:
  bool on_;
  std::string what_;
  Clock::time_point t0_;
  double cpu0_ = 0;
};

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    const auto comma = text.find(',', pos);
    std::string part =
        text.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
    while (!part.empty() && part.front() == ' ') part.erase(part.begin());
    while (!part.empty() && part.back() == ' ') part.pop_back();
    if (!part.empty()) out.push_back(part);
    if (comma == std::string::npos) break;
    pos = comma + 1;
  }
  return out;
}

// --component: 0 = all, -1 = largest, K >= 1 = the K-th largest.
std::int64_t parse_component(const std::string& text) {
  if (text == "all") return 0;
  if (text == "largest") return 1;
  std::int64_t k = 0;
  const char* b = text.data();
  const auto [p, ec] = std::from_chars(b, b + text.size(), k);
  if (text.empty() || ec != std::errc() || p != b + text.size() || k < 1)
    throw InvalidArgument("--component '" + text +
                          "': expected largest, all, or a rank K >= 1 (by decreasing size)");
  return k;
}

struct Radius {
  double value = 5;
  bool voxels = true;
};

// "R" (physical units) or "Rv" (voxels / pixels).
Radius parse_radius(const std::string& text) {
  Radius r;
  std::string t = text;
  r.voxels = !t.empty() && t.back() == 'v';
  if (r.voxels) t.pop_back();
  double v = 0;
  const auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (t.empty() || ec != std::errc() || p != t.data() + t.size() || !std::isfinite(v) || v <= 0)
    throw InvalidArgument("--radius '" + text +
                          "': expected a positive number, in physical units (R) or in voxels "
                          "(Rv, e.g. 5v)");
  r.value = v;
  return r;
}

// The --radius as given, or the default's text.
std::string radius_text(const std::string& given) {
  return given.empty() ? "5v (the default)" : given;
}

// The grid step of an isotropic image (the estimators need square pixels / cubic voxels).
double isotropic_step(const std::vector<double>& spacing, const std::string& path) {
  const double h = spacing.at(0);
  for (double s : spacing) {
    if (std::abs(s - h) > 1e-9 * std::max(std::abs(s), std::abs(h))) {
      std::string all;
      for (double x : spacing) {
        if (!all.empty()) all += ',';
        all += fmt::format("{}", x);
      }
      throw InvalidArgument(path + ": the estimators need isotropic voxels (spacing " + all +
                            "); resample, or give --spacing");
    }
  }
  return h;
}

// min / max / mean of finite values (as doubles; "count" as a string).
nlohmann::json stats(const std::vector<double>& v) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo, sum = 0;
  std::int64_t n = 0;
  for (double x : v) {
    if (!std::isfinite(x)) continue;
    lo = std::min(lo, x);
    hi = std::max(hi, x);
    sum += x;
    ++n;
  }
  if (n == 0) return {{"count", "0"}};
  return {{"min", lo}, {"max", hi}, {"mean", sum / double(n)}, {"count", str(n)}};
}

// Components of the object under k, and the mask of the selected ones.
struct ComponentSelection {
  std::int64_t count = 0;                     ///< components of the object
  std::vector<std::int64_t> chosen;           ///< their labels (1-based, by decreasing size)
  std::vector<std::int64_t> sizes;            ///< sizes of all components
  std::optional<Image<std::uint32_t>> labels; ///< kept when every component is selected
};

ComponentSelection select_components(Image<std::uint8_t>& mask, int k, std::int64_t which,
                                     unsigned threads, const std::string& path) {
  ComponentOptions opt;
  opt.order = ComponentOrder::by_size;
  opt.threads = threads;
  Components c = connected_components(mask, k, opt);
  ComponentSelection s;
  s.count = c.count();
  s.sizes = c.sizes;
  if (which == 0) {
    for (std::int64_t l = 1; l <= s.count; ++l) s.chosen.push_back(l);
    s.labels = std::move(c.labels);
    return s;
  }
  if (which > s.count)
    throw InvalidArgument(path + ": --component " + str(which) + " but the object has " +
                          str(s.count) + " component" + (s.count == 1 ? "" : "s") + " under " +
                          str(k) + "-adjacency");
  s.chosen = {which};
  const auto& lab = c.labels.values();
  parallel_chunks(mask.size(), threads, [&](std::int64_t b, std::int64_t e) {
    for (auto i = b; i < e; ++i) mask[i] = lab[std::size_t(i)] == std::uint32_t(which) ? 1 : 0;
  });
  return s;
}

std::string component_text(std::int64_t which) {
  return which == 0 ? "all" : (which == 1 ? "largest" : str(which));
}

void refuse_input_as_output(const std::string& input, const std::string& output) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!output.empty() && fs::exists(output, ec) && fs::equivalent(input, output, ec))
    throw InvalidArgument(output + ": is the input file; refusing to overwrite it");
}

// The picture options shared by surface and contour.
struct PictureArgs {
  std::string png, color, view, size, range;
};

std::string lower_extension(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

double parse_number(const std::string& text, const std::string& option) {
  double v = 0;
  const auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || p != text.data() + text.size() || !std::isfinite(v))
    throw InvalidArgument(option + ": '" + text + "' is not a number");
  return v;
}

// Checks the picture options (before any work) and returns the size: "WxH" (default
// default_w x default_h), the PNG extension, and that --color / --view / --png-size come
// with --png.
std::pair<int, int> picture_size(const PictureArgs& p, int default_w, int default_h) {
  if (p.png.empty()) {
    for (const auto& [value, name] : {std::pair{p.color, "--color"},
                                      {p.view, "--view"},
                                      {p.size, "--png-size"},
                                      {p.range, "--color-range"}})
      if (!value.empty()) throw InvalidArgument(std::string(name) + " needs --png FILE");
    return {default_w, default_h};
  }
  if (lower_extension(p.png) != ".png")
    throw IoError(p.png + ": the picture is a .png file (got '" + lower_extension(p.png) + "')");
  if (p.size.empty()) return {default_w, default_h};
  const auto x = p.size.find('x');
  int wh[2] = {0, 0};
  const std::string parts[2] = {p.size.substr(0, x),
                                x == std::string::npos ? "" : p.size.substr(x + 1)};
  for (int k = 0; k < 2; ++k) {
    const char* b = parts[k].data();
    const auto [q, ec] = std::from_chars(b, b + parts[k].size(), wh[k]);
    if (parts[k].empty() || ec != std::errc() || q != b + parts[k].size())
      throw InvalidArgument("--png-size '" + p.size + "': expected WIDTHxHEIGHT, e.g. 1200x900");
  }
  check_picture_size(wh[0], wh[1], "--png-size " + p.size);
  return {wh[0], wh[1]};
}

// --color-range LO:HI (LO < HI), or none when empty.
std::optional<std::pair<double, double>> parse_color_range(const std::string& text) {
  if (text.empty()) return std::nullopt;
  const auto colon = text.find(':');
  if (colon == std::string::npos)
    throw InvalidArgument("--color-range '" + text + "': expected LO:HI, e.g. -0.2:0.2");
  const double lo = parse_number(text.substr(0, colon), "--color-range");
  const double hi = parse_number(text.substr(colon + 1), "--color-range");
  if (!(lo < hi)) throw InvalidArgument("--color-range '" + text + "': LO must be below HI");
  return std::pair{lo, hi};
}

// --view AZ,EL in degrees (elevation in [-90, 90]).
std::pair<double, double> parse_view(const std::string& text) {
  const auto comma = text.find(',');
  if (comma == std::string::npos)
    throw InvalidArgument("--view '" + text + "': expected AZIMUTH,ELEVATION in degrees");
  const double az = parse_number(text.substr(0, comma), "--view");
  const double el = parse_number(text.substr(comma + 1), "--view");
  if (el < -90 || el > 90)
    throw InvalidArgument("--view '" + text + "': the elevation is between -90 and 90 degrees");
  return {az, el};
}

nlohmann::json picture_json(const std::string& path, const std::string& field, int w, int h,
                            double lo, double hi, ColorMap map) {
  nlohmann::json j = {{"path", path}, {"width", w}, {"height", h}};
  if (!field.empty()) {
    j["field"] = field;
    j["color_map"] = color_map_name(map);
    j["range"] = {lo, hi};
  }
  return j;
}

void print_picture_line(const nlohmann::json& picture) {
  if (picture.contains("field")) {
    fmt::print("  picture coloured by {} ({}, {:.4g} to {:.4g}) -> {}\n",
               picture["field"].get<std::string>(), picture["color_map"].get<std::string>(),
               picture["range"][0].get<double>(), picture["range"][1].get<double>(),
               picture["path"].get<std::string>());
  } else {
    fmt::print("  picture -> {}\n", picture["path"].get<std::string>());
  }
}

// ------------------------------------------------------------------------------------------
// zdg surface

const std::vector<std::string> kSurfaceEstimates = {"ii-mean",  "ii-gaussian", "ii-k1",
                                                    "ii-k2",    "ii-normal",   "ii-directions",
                                                    "geodesic", "at-normal"};
// The estimates that can colour the picture (one value per surfel).
const std::vector<std::string> kSurfaceColors = {"ii-mean", "ii-gaussian", "ii-k1",
                                                 "ii-k2",   "geodesic",    "at-v"};

struct SurfaceArgs {
  VolumeInputArgs in;
  std::string adjacency = "6,26", component = "all", estimate, radius, mesh = "primal";
  std::string output, csv, source, at_alpha, at_lambda;
  PictureArgs picture;
  unsigned threads = 0;
  bool json = false, quiet = false, force = false;
};

struct SurfaceEstimates {
  std::vector<double> mean;
  std::vector<IIPrincipalCurvatures> principal;
  std::vector<double> geodesic; // heat-method distance to the source (NaN on other surfaces)
  std::int64_t source = -1;     // its surfel
  double geodesic_time = 0;
  std::string solver;
  std::vector<Point3<double>> at_normal; // Ambrosio-Tortorelli normals
  std::vector<double> at_v;              // its discontinuity function, per surfel (min of sides)
  ATParameters at;
  std::string at_solver;
  int at_iterations = 0;
  std::set<std::string> names;
  double R = 0, h = 1;
};

// --source: a surfel index, or a point X,Y,Z in physical units (the nearest surfel centre,
// within two voxels).
struct SourceArg {
  std::optional<std::int64_t> surfel;
  Point3<double> point;
};

SourceArg parse_source(const std::string& text) {
  SourceArg out;
  if (text.find(',') == std::string::npos) {
    std::int64_t v = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size() || v < 0)
      throw InvalidArgument("--source '" + text +
                            "': expected a surfel index (0, 1, ...) or a point X,Y,Z");
    out.surfel = v;
    return out;
  }
  const auto parts = split_list(text);
  if (parts.size() != 3 || std::count(text.begin(), text.end(), ',') != 2)
    throw InvalidArgument("--source '" + text + "': expected X,Y,Z (three numbers)");
  out.point = {parse_number(parts[0], "--source"), parse_number(parts[1], "--source"),
               parse_number(parts[2], "--source")};
  return out;
}

// The cell complex of the primal surface (one surfel per face, in the order of the surfels)
// and the II normals: what the calculus estimates (geodesic, at-normal) start from, built once.
struct CalculusInput {
  SurfelComplex complex;
  std::vector<Point3<double>> normals;
};

CalculusInput calculus_input(const SurfaceEstimates& est, const PolygonMesh& quads) {
  CalculusInput in{surfel_complex(quads), {}};
  in.normals.reserve(est.principal.size());
  for (const auto& p : est.principal) in.normals.push_back(p.normal);
  return in;
}

// The Ambrosio-Tortorelli piecewise-smooth normals (estimators/ambrosio_tortorelli.hpp) from the
// II normals on the primal surface's surfels, and v brought to the surfels (the minimum over
// their four sides: 0 on a sharp edge).
void compute_at_normals(SurfaceEstimates& est, const CalculusInput& in) {
  const SurfelComplex& cx = in.complex;
  const ATResult r = at_normals(cx, in.normals, est.at);
  est.at_normal = r.normals;
  est.at_v = at_surfel_v(cx, r.v, ATSurfelPolicy::minimum);
  est.at_solver = r.backend;
  est.at_iterations = r.iterations;
}

// --at-alpha, --at-lambda: positive numbers.
double parse_positive(const std::string& text, const std::string& option) {
  const double v = parse_number(text, option);
  if (!(v > 0) || !std::isfinite(v))
    throw InvalidArgument(option + " '" + text + "': a positive number is needed");
  return v;
}

// The heat-method distance on the primal surface's surfels (estimators/heat_geodesics.hpp),
// with the II normals and the surfel measure; surfels on other closed surfaces than the
// source's (ImageSurfaces::surface_of) get NaN.
void compute_geodesic(SurfaceEstimates& est, const CalculusInput& in, const ImageSurfaces& ss,
                      const SourceArg& source, const std::string& path) {
  const SurfelComplex& cx = in.complex;
  const auto& normals = in.normals;
  const auto w = surfel_weights(surfel_measure(normals, cx.normals), cx.areas);
  std::int64_t s = 0;
  if (source.surfel) {
    s = *source.surfel;
    if (s >= cx.surfel_count())
      throw InvalidArgument("--source " + str(s) + ": the surface has " + str(cx.surfel_count()) +
                            " surfels (0.." + str(cx.surfel_count() - 1) + ")");
  } else {
    const auto [nearest, gap] = nearest_surfel(cx, source.point);
    if (gap > 2 * est.h)
      throw InvalidArgument(fmt::format("--source {},{},{}: {:.6g} from the nearest surfel centre "
                                        "of {}, more than two voxels: not on the surface",
                                        source.point.x, source.point.y, source.point.z, gap, path));
    s = nearest;
  }
  const HeatGeodesics geo(cx, normals, w);
  est.geodesic = geo.distance(s);
  est.source = s;
  est.geodesic_time = geo.time();
  est.solver = spd_backend_name(geo.backend());
  const auto own = ss.surface_of[std::size_t(s)];
  for (std::size_t i = 0; i < est.geodesic.size(); ++i)
    if (ss.surface_of[i] != own) est.geodesic[i] = std::numeric_limits<double>::quiet_NaN();
}

std::vector<double> principal_field(const SurfaceEstimates& e, const std::string& name) {
  std::vector<double> v(e.principal.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    const auto& p = e.principal[i];
    v[i] = name == "ii-gaussian" ? p.gaussian() : (name == "ii-k1" ? p.k1 : p.k2);
  }
  return v;
}

void write_surface_csv(const std::string& path, const ImageSurfels& sf, const ImageSurfaces& ss,
                       const VoxelPlacement& place, const SurfaceEstimates& est) {
  std::ofstream f(path);
  if (!f) throw IoError(path + ": cannot be written");
  const bool m = est.names.count("ii-mean") != 0, g = est.names.count("ii-gaussian") != 0,
             k1 = est.names.count("ii-k1") != 0, k2 = est.names.count("ii-k2") != 0,
             n = est.names.count("ii-normal") != 0, d = est.names.count("ii-directions") != 0,
             geo = est.names.count("geodesic") != 0, at = est.names.count("at-normal") != 0;
  std::string out = "surfel,surface,x,y,z,voxel_x,voxel_y,voxel_z,direction";
  if (m) out += ",ii_mean";
  if (g) out += ",ii_gaussian";
  if (k1) out += ",ii_k1";
  if (k2) out += ",ii_k2";
  if (n) out += ",nx,ny,nz";
  if (d) out += ",d1x,d1y,d1z,d2x,d2y,d2z";
  if (geo) out += ",geodesic";
  if (at) out += ",at_nx,at_ny,at_nz,at_v";
  out += "\n";
  static const char* dirs[6] = {"-x", "+x", "-y", "+y", "-z", "+z"};
  const VoxelGrid& gr = sf.grid;
  for (std::int64_t i = 0; i < sf.size(); ++i) {
    const auto code = sf.codes[std::size_t(i)];
    const std::int64_t v = code_voxel(code);
    const std::int64_t c[3] = {v % gr.nx, (v / gr.nx) % gr.ny, v / (gr.nx * gr.ny)};
    double p[3] = {double(c[0]), double(c[1]), double(c[2])};
    p[code_axis(code)] += code_positive(code) ? 0.5 : -0.5;
    const auto x = place.at(p[0], p[1], p[2]);
    fmt::format_to(std::back_inserter(out), "{},{},{},{},{},{},{},{},{}", i,
                   ss.surface_of[std::size_t(i)], x.x, x.y, x.z, c[0] + gr.lower.x,
                   c[1] + gr.lower.y, c[2] + gr.lower.z, dirs[code & 7]);
    if (m) fmt::format_to(std::back_inserter(out), ",{}", est.mean[std::size_t(i)]);
    if (g || k1 || k2 || n || d) {
      const auto& pc = est.principal[std::size_t(i)];
      if (g) fmt::format_to(std::back_inserter(out), ",{}", pc.gaussian());
      if (k1) fmt::format_to(std::back_inserter(out), ",{}", pc.k1);
      if (k2) fmt::format_to(std::back_inserter(out), ",{}", pc.k2);
      if (n)
        fmt::format_to(std::back_inserter(out), ",{},{},{}", pc.normal.x, pc.normal.y, pc.normal.z);
      if (d)
        fmt::format_to(std::back_inserter(out), ",{},{},{},{},{},{}", pc.d1.x, pc.d1.y, pc.d1.z,
                       pc.d2.x, pc.d2.y, pc.d2.z);
    }
    if (geo) fmt::format_to(std::back_inserter(out), ",{}", est.geodesic[std::size_t(i)]);
    if (at) {
      const auto& q = est.at_normal[std::size_t(i)];
      fmt::format_to(std::back_inserter(out), ",{},{},{},{}", q.x, q.y, q.z,
                     est.at_v[std::size_t(i)]);
    }
    out += "\n";
    if (out.size() > (std::size_t{1} << 22)) {
      f << out;
      out.clear();
    }
  }
  f << out;
  if (!f) throw IoError(path + ": write failed");
}

void run_surface(const SurfaceArgs& a) {
  const auto t_total = Clock::now();
  // Options first: nothing is read when one is wrong.
  const AdjacencyPair pair = parse_adjacency_pair(a.adjacency, 3);
  const SurfaceConvention conv = SurfaceConvention::of(pair);
  const std::int64_t which = parse_component(a.component);
  SurfaceEstimates est;
  for (const auto& e : split_list(a.estimate)) {
    if (std::find(kSurfaceEstimates.begin(), kSurfaceEstimates.end(), e) == kSurfaceEstimates.end())
      throw InvalidArgument("--estimate: unknown estimator '" + e +
                            "' (ii-mean, ii-gaussian, ii-k1, ii-k2, ii-normal, ii-directions, "
                            "geodesic, at-normal)");
    est.names.insert(e);
  }
  std::optional<SourceArg> source;
  if (!a.source.empty()) source = parse_source(a.source);
  if (!a.at_alpha.empty()) est.at.alpha = parse_positive(a.at_alpha, "--at-alpha");
  if (!a.at_lambda.empty()) est.at.lambda = parse_positive(a.at_lambda, "--at-lambda");
  // The picture's colour: --color (computed when not in --estimate), else the first scalar
  // estimate, else none (a grey surface).
  const auto [png_w, png_h] = picture_size(a.picture, 1200, 900);
  std::string color = a.picture.color;
  if (!color.empty() && color != "none") {
    if (std::find(kSurfaceColors.begin(), kSurfaceColors.end(), color) == kSurfaceColors.end())
      throw InvalidArgument("--color '" + color +
                            "': expected ii-mean, ii-gaussian, ii-k1, ii-k2, geodesic, at-v or "
                            "none");
    est.names.insert(color == "at-v" ? "at-normal" : color);
  }
  if ((!a.at_alpha.empty() || !a.at_lambda.empty()) && est.names.count("at-normal") == 0)
    throw InvalidArgument("--at-alpha and --at-lambda are only read by --estimate at-normal");
  if (est.names.count("geodesic") != 0 && !source)
    throw InvalidArgument("--estimate geodesic needs --source SURFEL or --source X,Y,Z");
  if (source && est.names.count("geodesic") == 0)
    throw InvalidArgument("--source is only read by --estimate geodesic");
  if (color.empty() && !a.picture.png.empty())
    for (const auto& c : kSurfaceColors)
      if (color.empty() && est.names.count(c == "at-v" ? "at-normal" : c) != 0) color = c;
  if (color == "none") color.clear();
  MeshRenderOptions render;
  render.width = png_w;
  render.height = png_h;
  render.threads = a.threads;
  if (!a.picture.view.empty())
    std::tie(render.azimuth, render.elevation) = parse_view(a.picture.view);
  if (const auto r = parse_color_range(a.picture.range)) {
    render.value_min = r->first;
    render.value_max = r->second;
  }
  const Radius radius = parse_radius(a.radius.empty() ? "5v" : a.radius);
  if (a.mesh != "primal" && a.mesh != "marching-cubes")
    throw InvalidArgument("--mesh '" + a.mesh + "': expected primal or marching-cubes");
  std::optional<MeshFormat> mesh_format;
  if (!a.output.empty()) mesh_format = mesh_format_of(a.output);
  for (const auto* out : {&a.output, &a.csv, &a.picture.png})
    refuse_input_as_output(a.in.path, *out);
  OutputSet outputs(a.force ? Existing::replace : Existing::refuse);
  const std::string mesh_staging = a.output.empty() ? "" : outputs.add(a.output).string();
  const std::string csv_staging = a.csv.empty() ? "" : outputs.add(a.csv).string();
  const std::string png_staging = a.picture.png.empty() ? "" : outputs.add(a.picture.png).string();

  Progress progress(!a.quiet);
  auto& seconds = progress.seconds;
  const double cpu_read = process_cpu_seconds();
  LoadedObject obj = load_object(a.in, 3, a.threads, !a.quiet);
  seconds["read"] = obj.read_seconds;
  seconds["select"] = obj.select_seconds;
  progress.cpu_seconds["read_select"] = process_cpu_seconds() - cpu_read;
  const auto& vol = obj.volume;
  const VoxelPlacement place{{vol.spacing[2], vol.spacing[1], vol.spacing[0]},
                             {vol.origin[2], vol.origin[1], vol.origin[0]}};
  const std::int64_t extent =
      std::max({vol.array.shape[0], vol.array.shape[1], vol.array.shape[2]});
  if (!est.names.empty()) {
    est.h = isotropic_step(vol.spacing, a.in.path);
    est.R = radius.voxels ? radius.value * est.h : radius.value;
    const double rv = est.R / est.h;
    if (rv > double(extent))
      throw InvalidArgument(a.in.path + ": --radius " + radius_text(a.radius) + " is " +
                            fmt::format("{}", rv) + " voxels, larger than the volume (" +
                            str(vol.array.shape[2]) + " x " + str(vol.array.shape[1]) + " x " +
                            str(vol.array.shape[0]) + " voxels)");
    if (rv > 256)
      throw InvalidArgument("--radius " + radius_text(a.radius) + " is " + fmt::format("{}", rv) +
                            " voxels; the integral invariants take at most 256");
  }
  // Grey values for marching cubes: the threshold's level (positions interpolated).
  const bool grey = a.mesh == "marching-cubes" && !a.in.threshold.empty();
  Image<std::uint8_t> mask = std::move(obj.mask);
  // The values are not needed any more: free them (assigning {} would keep the capacity).
  if (!grey) std::vector<unsigned char>().swap(obj.volume.array.bytes);

  progress.start("components");
  ComponentSelection comps = select_components(mask, pair.object, which, a.threads, a.in.path);
  progress.done("components", str(comps.count) + " component(s)");

  progress.start("Betti numbers");
  const BettiNumbers betti = betti_numbers(mask, pair, a.threads);
  progress.done("betti");

  progress.start("boundary surfels");
  const ImageSurfels sf = image_surfels(mask, a.threads);
  progress.done("surfels", str(sf.size()) + " surfels");
  progress.start("closed surfaces");
  ImageSurfaces ss = image_surfaces(mask, sf, conv, a.threads);
  progress.done("surfaces", str(std::int64_t(ss.surfaces.size())) + " surfaces");
  if (ss.object_euler() != betti.euler)
    throw Error("internal: the surfaces give chi = " + str(ss.object_euler()) +
                " but the block table gives " + str(betti.euler));

  // Per selected component: voxels, surfels, surfaces, Euler characteristic and genus of its
  // boundary (the genus is the sum of its surfaces' genera).
  struct ComponentStats {
    std::int64_t voxels = 0, surfels = 0, surfaces = 0, euler = 0, genus = 0;
  };
  std::map<std::int64_t, ComponentStats> per;
  for (auto l : comps.chosen) per[l].voxels = comps.sizes[std::size_t(l - 1)];
  for (const auto& s : ss.surfaces) {
    std::int64_t l = comps.chosen.front();
    if (comps.labels) l = (*comps.labels)[code_voxel(sf.codes[std::size_t(s.first)])];
    auto& c = per[l];
    c.surfels += s.surfels;
    c.surfaces += 1;
    c.euler += s.euler;
    c.genus += s.genus;
  }
  comps.labels.reset();

  if (!est.names.empty()) {
    progress.start("estimates");
    const bool principal = est.names.size() > (est.names.count("ii-mean") ? 1u : 0u);
    if (est.names.count("ii-mean"))
      est.mean = volume_ii_mean_curvature(mask, sf, est.h, est.R, a.threads);
    if (principal)
      est.principal = volume_ii_principal_curvatures(mask, sf, est.h, est.R, a.threads);
    progress.done("estimates");
  }
  if (est.names.count("geodesic") || est.names.count("at-normal")) {
    const CalculusInput calculus =
        calculus_input(est, primal_surface_mesh(mask, sf, conv, place, a.threads));
    if (est.names.count("geodesic")) {
      progress.start("geodesic distance (heat method)");
      compute_geodesic(est, calculus, ss, *source, a.in.path);
      progress.done("geodesic");
    }
    if (est.names.count("at-normal")) {
      progress.start("Ambrosio-Tortorelli normals");
      compute_at_normals(est, calculus);
      progress.done("at-normal");
    }
  }

  // The surface of each surfel (8 bytes per surfel) serves the CSV only from here on.
  if (a.csv.empty()) std::vector<std::uint64_t>().swap(ss.surface_of);

  nlohmann::json mesh_json, picture;
  if (!a.output.empty() || !a.picture.png.empty()) {
    progress.start(a.mesh + " mesh");
    PolygonMesh mesh;
    std::int64_t edges = 0;
    if (a.mesh == "primal") {
      mesh = primal_surface_mesh(mask, sf, conv, place, a.threads);
      edges = 2 * mesh.face_count() - ss.pinched_linels;
    } else {
      std::optional<IsoLevel> level;
      if (grey) {
        level.emplace();
        const ScalarVolume* v = &obj.volume;
        level->value = [v](std::int64_t i) { return v->value(i); };
        level->level = obj.selection.low;
      }
      mesh = marching_cubes(mask, sf, conv, place, level ? &*level : nullptr, a.threads);
      edges = 3 * mesh.face_count() / 2;
      if (grey) std::vector<unsigned char>().swap(obj.volume.array.bytes); // the grey values
    }
    { const Image<std::uint8_t> freed = std::move(mask); } // no later step reads the mask
    // Per-face fields: the surfel's estimates (primal: face = surfel; marching cubes: the
    // mean over the triangle's surfel vertices).
    std::vector<std::pair<std::string, std::vector<double>>> fields;
    if (est.names.count("ii-mean")) fields.emplace_back("ii-mean", est.mean);
    for (const char* n : {"ii-gaussian", "ii-k1", "ii-k2"})
      if (est.names.count(n)) fields.emplace_back(n, principal_field(est, n));
    if (est.names.count("geodesic")) fields.emplace_back("geodesic", est.geodesic);
    if (est.names.count("at-normal")) {
      std::vector<double> c[3];
      for (const auto& q : est.at_normal) {
        c[0].push_back(q.x);
        c[1].push_back(q.y);
        c[2].push_back(q.z);
      }
      fields.emplace_back("at-nx", std::move(c[0]));
      fields.emplace_back("at-ny", std::move(c[1]));
      fields.emplace_back("at-nz", std::move(c[2]));
      fields.emplace_back("at-v", est.at_v);
    }
    // The surfels' normals (II, or the elementary ones), written where the mesh keeps them:
    // the face normals of the primal mesh, the first vertex normals of marching cubes.
    auto surfel_normals = [&](Point3<double>* out) {
      parallel_chunks(sf.size(), a.threads, [&](std::int64_t b, std::int64_t e) {
        for (std::int64_t i = b; i < e; ++i) {
          if (!est.principal.empty()) {
            out[i] = est.principal[std::size_t(i)].normal;
          } else {
            const auto t = trivial_normal(sf.surfel(i));
            out[i] = {double(t.x), double(t.y), double(t.z)};
          }
        }
      });
    };
    if (a.mesh == "primal") {
      mesh.face_scalars = std::move(fields);
      mesh.face_normals.resize(static_cast<std::size_t>(sf.size()));
      surfel_normals(mesh.face_normals.data());
    } else {
      const std::int64_t n = sf.size();
      for (auto& [name, values] : fields) {
        std::vector<double> per_face(static_cast<std::size_t>(mesh.face_count()));
        parallel_chunks(mesh.face_count(), a.threads, [&](std::int64_t b, std::int64_t e) {
          for (std::int64_t f = b; f < e; ++f) {
            double s = 0;
            int k = 0;
            for (auto v : mesh.face(f))
              if (v < n) {
                s += values[std::size_t(v)];
                ++k;
              }
            per_face[std::size_t(f)] = s / k;
          }
        });
        mesh.face_scalars.emplace_back(name, std::move(per_face));
      }
      // Vertex normals: the surfels' (vertices 0 .. n - 1), the centres' the mean of their
      // surfel neighbours' (the surfel normals are not changed while the centres sum them).
      auto& vn = mesh.vertex_normals;
      vn.assign(mesh.vertices.size(), Point3<double>{0, 0, 0});
      surfel_normals(vn.data());
      for (std::int64_t f = 0; f < mesh.face_count(); ++f) {
        const auto t = mesh.face(f);
        for (std::size_t c = 0; c < 3; ++c)
          if (t[c] >= n)
            for (std::size_t d = 0; d < 3; ++d)
              if (t[d] < n) vn[std::size_t(t[c])] = vn[std::size_t(t[c])] + vn[std::size_t(t[d])];
      }
      parallel_chunks(std::int64_t(vn.size()), a.threads, [&](std::int64_t b, std::int64_t e) {
        for (std::int64_t i = b; i < e; ++i) {
          auto& v = vn[std::size_t(i)];
          const double l = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
          if (l > 0) v = {v.x / l, v.y / l, v.z / l};
        }
      });
    }
    progress.done("mesh", str(mesh.face_count()) + " faces");
    mesh_json = {{"kind", a.mesh},
                 {"vertices", str(mesh.vertex_count())},
                 {"faces", str(mesh.face_count())},
                 {"edges", str(edges)},
                 {"euler", str(mesh.vertex_count() - edges + mesh.face_count())}};
    if (!a.output.empty()) {
      mesh_json["path"] = a.output;
      progress.start("writing " + a.output);
      write_mesh(mesh_staging, mesh, mesh_format, a.threads);
      progress.done("write_mesh");
    }
    if (!a.picture.png.empty()) {
      progress.start("picture " + a.picture.png);
      const auto r = render_mesh_png(png_staging, mesh, color, render);
      progress.done("picture");
      picture =
          picture_json(a.picture.png, color, png_w, png_h, r.value_min, r.value_max, r.color_map);
    }
  }
  if (!a.csv.empty()) {
    progress.start("writing " + a.csv);
    write_surface_csv(csv_staging, sf, ss, place, est);
    progress.done("write_csv");
  }
  outputs.commit();
  seconds["total"] = since(t_total);
  progress.cpu_seconds["total"] = process_cpu_seconds();

  if (a.json) {
    nlohmann::json components = nlohmann::json::array();
    for (const auto& [l, c] : per)
      components.push_back({{"rank", str(l)},
                            {"voxels", str(c.voxels)},
                            {"surfels", str(c.surfels)},
                            {"surfaces", str(c.surfaces)},
                            {"euler", str(c.euler)},
                            {"genus", str(c.genus)}});
    nlohmann::json estimates = nlohmann::json::object();
    if (est.names.count("ii-mean")) estimates["ii-mean"] = stats(est.mean);
    for (const char* n : {"ii-gaussian", "ii-k1", "ii-k2"})
      if (est.names.count(n)) estimates[n] = stats(principal_field(est, n));
    for (const char* n : {"ii-normal", "ii-directions"})
      if (est.names.count(n)) estimates[n] = {{"count", str(std::int64_t(est.principal.size()))}};
    if (est.names.count("geodesic")) {
      estimates["geodesic"] = stats(est.geodesic);
      estimates["geodesic"]["source"] = str(est.source);
      estimates["geodesic"]["time"] = est.geodesic_time;
      estimates["geodesic"]["solver"] = est.solver;
    }
    if (est.names.count("at-normal")) {
      estimates["at-normal"] = {{"count", str(std::int64_t(est.at_normal.size()))},
                                {"alpha", est.at.alpha},
                                {"lambda", est.at.lambda},
                                {"epsilon1", est.at.epsilon1},
                                {"epsilon2", est.at.epsilon2},
                                {"iterations", est.at_iterations},
                                {"solver", est.at_solver}};
      estimates["at-v"] = stats(est.at_v);
    }
    if (!est.names.empty()) {
      estimates["radius"] = est.R;
      estimates["radius_voxels"] = est.R / est.h;
    }
    nlohmann::json j = {{"command", "surface"},
                        {"input", obj.json},
                        {"adjacency", pair.name()},
                        {"component", component_text(which)},
                        {"object_components", str(comps.count)},
                        {"components", components},
                        {"surfaces", str(std::int64_t(ss.surfaces.size()))},
                        {"surfels", str(sf.size())},
                        {"euler", str(betti.euler)},
                        {"betti", {str(betti.b[0]), str(betti.b[1]), str(betti.b[2])}},
                        {"pinched_pointels", str(ss.pinched_pointels)},
                        {"pinched_linels", str(ss.pinched_linels)},
                        {"estimates", estimates},
                        {"seconds", seconds},
                        {"cpu_seconds", progress.cpu_seconds},
                        {"threads", worker_count(a.threads, std::int64_t{1} << 30)}};
    if (!mesh_json.is_null()) j["mesh"] = mesh_json;
    if (!picture.is_null()) j["picture"] = picture;
    if (!a.csv.empty()) j["csv"] = a.csv;
    print_json(j);
    return;
  }
  fmt::print("{}: {} component(s) under ({}), {} surfels in {} closed surface(s); "
             "Betti numbers {} {} {} (Euler characteristic {})\n",
             a.in.path, comps.count, pair.name(), sf.size(), ss.surfaces.size(), betti.b[0],
             betti.b[1], betti.b[2], betti.euler);
  std::size_t shown = 0;
  for (const auto& [l, c] : per) {
    if (++shown > 5) {
      fmt::print("  ... {} more component(s) (--json lists them all)\n", per.size() - 5);
      break;
    }
    fmt::print("  component {}: {} voxels, {} surfels in {} surface(s), Euler characteristic {}, "
               "genus {}\n",
               l, c.voxels, c.surfels, c.surfaces, c.euler, c.genus);
  }
  if (ss.pinched_pointels > 0 || ss.pinched_linels > 0)
    fmt::print("  {} pinched pointel(s), {} pinched linel(s) (see zdg surface --help)\n",
               ss.pinched_pointels, ss.pinched_linels);
  if (!mesh_json.is_null())
    fmt::print("  {} mesh: {} vertices, {} faces{}{}\n", a.mesh,
               mesh_json["vertices"].get<std::string>(), mesh_json["faces"].get<std::string>(),
               a.output.empty() ? "" : " -> ", a.output);
  if (est.names.count("ii-mean")) {
    const auto s = stats(est.mean);
    if (s.contains("mean"))
      fmt::print("  ii-mean: min {:.6g}, max {:.6g}, mean {:.6g} (R = {} = {} voxels)\n",
                 s["min"].get<double>(), s["max"].get<double>(), s["mean"].get<double>(), est.R,
                 est.R / est.h);
  }
  if (!a.csv.empty()) fmt::print("  per-surfel values -> {}\n", a.csv);
  if (!picture.is_null()) print_picture_line(picture);
}

// ------------------------------------------------------------------------------------------
// zdg contour

const std::vector<std::string> kContourEstimates = {"ii-curvature", "bc-tangent", "lmst-tangent",
                                                    "mlp-length", "gauss-area"};

struct ContourArgs {
  VolumeInputArgs in;
  std::string adjacency = "4,8", component = "all", estimate, radius;
  std::string output, csv;
  PictureArgs picture;
  unsigned threads = 0;
  bool json = false, quiet = false, force = false;
};

void write_contour_csv(const std::string& path, const ImageContours& cs, double h,
                       const Pixel& origin_pixel, const Point2<double>& origin,
                       const ContourEstimateRequest& req, const ContourEstimates& e) {
  std::ofstream f(path);
  if (!f) throw IoError(path + ": cannot be written");
  std::string out = "contour,linel,pointel_x,pointel_y,code,midpoint_x,midpoint_y,inner_x,inner_y";
  if (req.ii_curvature) out += ",ii_curvature";
  if (req.bc_tangent) out += ",bc_tx,bc_ty";
  if (req.lmst_tangent) out += ",lmst_tx,lmst_ty";
  out += "\n";
  for (std::size_t c = 0; c < cs.contours.size(); ++c) {
    const auto& k = cs.contours[c];
    Pixel p = k.start;
    for (std::size_t i = 0; i < k.size(); ++i) {
      const int code = k.codes[i];
      const Pixel d = freeman_step(code);
      const Pixel in = DigitalContour::inner_pixel(p, code);
      // Physical position of the lattice point q: origin + h (q - origin_pixel).
      const double mx = origin.x + h * (double(p.x - origin_pixel.x) + 0.5 * double(d.x) - 0.5);
      const double my = origin.y + h * (double(p.y - origin_pixel.y) + 0.5 * double(d.y) - 0.5);
      fmt::format_to(std::back_inserter(out), "{},{},{},{},{},{},{},{},{}", c, i, p.x, p.y, code,
                     mx, my, in.x, in.y);
      if (req.ii_curvature) fmt::format_to(std::back_inserter(out), ",{}", e.ii_curvature[c][i]);
      if (req.bc_tangent)
        fmt::format_to(std::back_inserter(out), ",{},{}", e.bc_tangent[c][i].x,
                       e.bc_tangent[c][i].y);
      if (req.lmst_tangent)
        fmt::format_to(std::back_inserter(out), ",{},{}", e.lmst_tangent[c][i].x,
                       e.lmst_tangent[c][i].y);
      out += "\n";
      p = p + d;
      if (out.size() > (std::size_t{1} << 22)) {
        f << out;
        out.clear();
      }
    }
  }
  f << out;
  if (!f) throw IoError(path + ": write failed");
}

void run_contour(const ContourArgs& a) {
  const auto t_total = Clock::now();
  const AdjacencyPair pair = parse_adjacency_pair(a.adjacency, 2);
  const std::int64_t which = parse_component(a.component);
  ContourEstimateRequest req;
  std::set<std::string> names;
  for (const auto& e : split_list(a.estimate)) {
    if (std::find(kContourEstimates.begin(), kContourEstimates.end(), e) == kContourEstimates.end())
      throw InvalidArgument("--estimate: unknown estimator '" + e +
                            "' (ii-curvature, bc-tangent, lmst-tangent, mlp-length, gauss-area)");
    names.insert(e);
  }
  // The picture's colour: --color ii-curvature (computed when not in --estimate), the default
  // when ii-curvature is estimated; otherwise the contours are drawn in black.
  const auto [png_w, png_h] = picture_size(a.picture, 1000, 800);
  std::string color = a.picture.color;
  if (!color.empty() && color != "none") {
    if (color != "ii-curvature")
      throw InvalidArgument("--color '" + color + "': expected ii-curvature or none");
    names.insert(color);
  }
  if (color.empty() && !a.picture.png.empty() && names.count("ii-curvature") != 0)
    color = "ii-curvature";
  if (color == "none") color.clear();
  ContourRenderOptions render;
  render.width = png_w;
  render.height = png_h;
  if (const auto r = parse_color_range(a.picture.range)) {
    render.value_min = r->first;
    render.value_max = r->second;
  }
  req.ii_curvature = names.count("ii-curvature") != 0;
  req.bc_tangent = names.count("bc-tangent") != 0;
  req.lmst_tangent = names.count("lmst-tangent") != 0;
  req.mlp_length = names.count("mlp-length") != 0;
  req.gauss_area = names.count("gauss-area") != 0;
  const Radius radius = parse_radius(a.radius.empty() ? "5v" : a.radius);
  if (!a.output.empty()) {
    std::string e = std::filesystem::path(a.output).extension().string();
    for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (e != ".svg")
      throw IoError(a.output + ": the contour drawing is an .svg file (got '" + e + "')");
  }
  for (const auto* out : {&a.output, &a.csv, &a.picture.png})
    refuse_input_as_output(a.in.path, *out);
  OutputSet outputs(a.force ? Existing::replace : Existing::refuse);
  const std::string svg_staging = a.output.empty() ? "" : outputs.add(a.output).string();
  const std::string csv_staging = a.csv.empty() ? "" : outputs.add(a.csv).string();
  const std::string png_staging = a.picture.png.empty() ? "" : outputs.add(a.picture.png).string();

  Progress progress(!a.quiet);
  auto& seconds = progress.seconds;
  const double cpu_read = process_cpu_seconds();
  LoadedObject obj = load_object(a.in, 2, a.threads, !a.quiet);
  seconds["read"] = obj.read_seconds;
  seconds["select"] = obj.select_seconds;
  progress.cpu_seconds["read_select"] = process_cpu_seconds() - cpu_read;
  const auto& vol = obj.volume;
  const double h = isotropic_step(vol.spacing, a.in.path);
  const double R = radius.voxels ? radius.value * h : radius.value;
  const std::int64_t extent = std::max(vol.array.shape[0], vol.array.shape[1]);
  if ((req.ii_curvature || req.bc_tangent) && R / h > double(extent))
    throw InvalidArgument(a.in.path + ": --radius " + radius_text(a.radius) + " is " +
                          fmt::format("{}", R / h) + " pixels, larger than the image (" +
                          str(vol.array.shape[1]) + " x " + str(vol.array.shape[0]) + " pixels)");
  Image<std::uint8_t> mask = std::move(obj.mask);
  std::vector<unsigned char>().swap(obj.volume.array.bytes); // frees (= {} keeps the capacity)

  progress.start("components");
  ComponentSelection comps = select_components(mask, pair.object, which, a.threads, a.in.path);
  comps.labels.reset();
  progress.done("components", str(comps.count) + " component(s)");
  progress.start("Betti numbers");
  const BettiNumbers betti = betti_numbers(mask, pair, a.threads);
  progress.done("betti");
  progress.start("contours");
  const ImageContours cs = image_contours(mask, pair.object, pair.background);
  progress.done("contours", str(std::int64_t(cs.contours.size())) + " contours");
  if (cs.b0 != betti.b[0] || cs.b1 != betti.b[1])
    throw Error("internal: the contours give b0, b1 = " + str(cs.b0) + ", " + str(cs.b1) +
                " but the components give " + str(betti.b[0]) + ", " + str(betti.b[1]));

  ContourEstimates e;
  if (!names.empty()) {
    progress.start("estimates");
    e = contour_estimates(mask, cs, req, h, R, a.threads);
    progress.done("estimates");
  }
  const Pixel origin_pixel{vol.lower[1], vol.lower[0]};
  const Point2<double> origin{vol.origin[1], vol.origin[0]};
  if (!a.output.empty()) {
    progress.start("writing " + a.output);
    ContourDrawing drawing;
    drawing.box =
        Box2{{vol.lower[1], vol.lower[0]},
             {vol.lower[1] + vol.array.shape[1] - 1, vol.lower[0] + vol.array.shape[0] - 1}};
    if (req.ii_curvature) {
      drawing.field_name = "ii-curvature";
      drawing.field = &e.ii_curvature;
    }
    write_contour_svg(svg_staging, cs.contours, drawing);
    progress.done("write_svg");
  }
  if (!a.csv.empty()) {
    progress.start("writing " + a.csv);
    write_contour_csv(csv_staging, cs, h, origin_pixel, origin, req, e);
    progress.done("write_csv");
  }
  nlohmann::json picture;
  if (!a.picture.png.empty()) {
    progress.start("picture " + a.picture.png);
    // Each contour through its pointels and linel midpoints (lattice coordinates): a linel's
    // value at its midpoint, the mean of the two linels' at a pointel.
    std::vector<ContourPolyline> lines(cs.contours.size());
    const ContourEmbedding lattice{1.0};
    for (std::size_t c = 0; c < cs.contours.size(); ++c) {
      const auto& k = cs.contours[c];
      auto& line = lines[c];
      const std::size_t n = k.size();
      const std::vector<double>* v = color.empty() ? nullptr : &e.ii_curvature[c];
      Pixel p = k.start;
      for (std::size_t i = 0; i < n; ++i) {
        line.points.push_back(lattice.pointel(p));
        line.points.push_back(lattice.linel_midpoint(p, k.codes[i]));
        if (v != nullptr) {
          const double before = (*v)[(i + n - 1) % n], here = (*v)[i];
          line.values.push_back(std::isnan(before) ? here
                                : std::isnan(here) ? before
                                                   : (before + here) / 2);
          line.values.push_back(here);
        }
        p = p + freeman_step(k.codes[i]);
      }
    }
    const auto r = render_contours_png(png_staging, mask, lines, color, render);
    progress.done("picture");
    picture =
        picture_json(a.picture.png, color, png_w, png_h, r.value_min, r.value_max, r.color_map);
  }
  outputs.commit();
  seconds["total"] = since(t_total);
  progress.cpu_seconds["total"] = process_cpu_seconds();

  if (a.json) {
    nlohmann::json contours = nlohmann::json::array();
    for (std::size_t c = 0; c < cs.contours.size(); ++c) {
      const auto area2 = cs.contours[c].twice_signed_area();
      nlohmann::json k = {{"linels", str(std::int64_t(cs.contours[c].size()))},
                          {"pixels", str(area2 / 2)},
                          {"kind", area2 > 0 ? "outer" : "hole"}};
      if (req.mlp_length) k["mlp-length"] = e.mlp_length[c];
      contours.push_back(k);
    }
    nlohmann::json estimates = nlohmann::json::object();
    if (req.ii_curvature) {
      std::vector<double> all;
      for (const auto& v : e.ii_curvature) all.insert(all.end(), v.begin(), v.end());
      estimates["ii-curvature"] = stats(all);
    }
    if (req.bc_tangent)
      estimates["bc-tangent"] = {{"mask_order", str(e.bc_mask_order)},
                                 {"lowered", str(e.bc_lowered)},
                                 {"skipped", str(e.bc_skipped)}};
    if (req.lmst_tangent) estimates["lmst-tangent"] = {{"count", str(cs.linels())}};
    if (req.mlp_length) {
      double total = 0;
      for (double l : e.mlp_length) total += l;
      estimates["mlp-length"] = {{"total", total}};
    }
    if (req.gauss_area) estimates["gauss-area"] = {{"area", e.gauss_area}};
    if (req.ii_curvature || req.bc_tangent) {
      estimates["radius"] = R;
      estimates["radius_pixels"] = R / h;
    }
    nlohmann::json j = {{"command", "contour"},
                        {"input", obj.json},
                        {"adjacency", pair.name()},
                        {"component", component_text(which)},
                        {"object_components", str(comps.count)},
                        {"contours", contours},
                        {"linels", str(cs.linels())},
                        {"euler", str(betti.euler)},
                        {"betti", {str(betti.b[0]), str(betti.b[1])}},
                        {"estimates", estimates},
                        {"seconds", seconds},
                        {"cpu_seconds", progress.cpu_seconds},
                        {"threads", worker_count(a.threads, std::int64_t{1} << 30)}};
    if (!a.output.empty()) j["svg"] = a.output;
    if (!a.csv.empty()) j["csv"] = a.csv;
    if (!picture.is_null()) j["picture"] = picture;
    print_json(j);
    return;
  }
  fmt::print("{}: {} contour(s) of {} linels under ({}); Betti numbers {} {}\n", a.in.path,
             cs.contours.size(), cs.linels(), pair.name(), betti.b[0], betti.b[1]);
  if (req.gauss_area) fmt::print("  gauss-area: {}\n", e.gauss_area);
  if (req.mlp_length) {
    double total = 0;
    for (double l : e.mlp_length) total += l;
    fmt::print("  mlp-length: {} (all contours)\n", total);
  }
  if (!a.output.empty()) fmt::print("  drawing -> {}\n", a.output);
  if (!a.csv.empty()) fmt::print("  per-linel values -> {}\n", a.csv);
  if (!picture.is_null()) print_picture_line(picture);
}

template <class Args>
void add_common_options(CLI::App* cmd, Args& a, const char* pairs, const char* mesh_help,
                        const char* png_help) {
  add_volume_input_options(*cmd, a.in);
  cmd->add_option("--adjacency", a.adjacency, pairs);
  cmd->add_option("--component", a.component,
                  "largest, all (default), or K: the K-th largest component");
  cmd->add_option("--radius", a.radius,
                  "kernel radius of the estimators: R in physical units, or Rv in voxels "
                  "(default 5v)");
  cmd->add_option("-o,--output", a.output, mesh_help);
  cmd->add_option("--csv", a.csv, "write one row per boundary element with its estimates");
  cmd->add_option("--png", a.picture.png, png_help);
  cmd->add_option("--png-size", a.picture.size,
                  "picture size WIDTHxHEIGHT in pixels (200x150 .. 8192x8192)");
  cmd->add_option("--color-range", a.picture.range,
                  "the values at the ends of the colour map, LO:HI (default: the 1st and 99th "
                  "percentiles; symmetric about 0 with the diverging map when they differ in "
                  "sign)");
  cmd->add_option("--threads", a.threads, "worker threads (0 = all cores)");
  cmd->add_flag("--json", a.json, "print a JSON summary on stdout");
  cmd->add_flag("--quiet", a.quiet, "no progress on stderr");
  cmd->add_flag("--force", a.force, "replace existing outputs");
}

} // namespace

void add_surface_commands(CLI::App& app, Context& /*ctx*/) {
  auto s = std::make_shared<SurfaceArgs>();
  auto* surface = app.add_subcommand(
      "surface",
      "the boundary of a 3D object: closed digital surfaces under an adjacency pair (Euler "
      "characteristic, genus), Betti numbers, integral-invariant curvatures, a primal or "
      "marching-cubes mesh (PLY, OBJ, OFF), a PNG picture coloured by a curvature. Under (6,26) "
      "and (26,6) the object's continuous analog may join two "
      "sheets at a pointel (pinched pointels) and, under any pair, a surface may pass twice along "
      "a linel (pinched linels, an edge of four quads in the primal mesh; marching cubes stays "
      "a manifold): the JSON counts them; the Betti numbers are exact in every case");
  add_common_options(surface, *s,
                     "adjacency pair (object, background): 6,26 (default), 26,6, 6,18, 18,6",
                     "mesh output: .ply (binary, with the estimates per face and the normals), "
                     ".obj or .off",
                     "picture of the mesh coloured by one estimate (--color), with a colour bar "
                     "(default size 1200x900)");
  surface->add_option("--estimate", s->estimate,
                      "comma-separated estimators: ii-mean, ii-gaussian, ii-k1, ii-k2, ii-normal, "
                      "ii-directions, geodesic (heat-method distance to --source on the surfels, "
                      "with the II normals), at-normal (Ambrosio-Tortorelli piecewise-smooth "
                      "normals from the II normals, and their discontinuity field at-v)");
  surface->add_option("--at-alpha", s->at_alpha,
                      fmt::format("Ambrosio-Tortorelli data fidelity alpha > 0 (default {}; "
                                  "larger: closer to the II normals)",
                                  ATParameters{}.alpha));
  surface->add_option("--at-lambda", s->at_lambda,
                      fmt::format("Ambrosio-Tortorelli discontinuity cost lambda > 0 (default "
                                  "{}; smaller: more edges)",
                                  ATParameters{}.lambda));
  surface->add_option("--source", s->source,
                      "source of --estimate geodesic: a surfel index (the row of --csv) or a "
                      "point X,Y,Z in physical units (the nearest surfel, within two voxels)");
  surface->add_option("--color", s->picture.color,
                      "the estimate that colours the picture: ii-mean, ii-gaussian, ii-k1, ii-k2, "
                      "geodesic, at-v (computed if not in --estimate), or none; default: the "
                      "first of these estimated");
  surface->add_option("--view", s->picture.view,
                      "picture view AZIMUTH,ELEVATION in degrees (default -60,30; 90,90 looks "
                      "down the z axis with x to the right)");
  surface->add_option("--mesh", s->mesh, "primal (one quad per surfel, default) or marching-cubes");
  surface->callback([s] { run_surface(*s); });

  auto c = std::make_shared<ContourArgs>();
  auto* contour = app.add_subcommand(
      "contour",
      "the contours of a 2D object under an adjacency pair, its Betti numbers, 2D "
      "estimators along the contours, an SVG drawing, a PNG picture of the image with its "
      "contours coloured by the curvature");
  add_common_options(contour, *c, "adjacency pair (object, background): 4,8 (default) or 8,4",
                     "drawing of the contours (.svg)",
                     "picture of the image with its contours coloured by ii-curvature (--color), "
                     "with a colour bar (default size 1000x800)");
  contour->add_option("--estimate", c->estimate,
                      "comma-separated estimators: ii-curvature, bc-tangent, lmst-tangent, "
                      "mlp-length, gauss-area");
  contour->add_option("--color", c->picture.color,
                      "the estimate that colours the contours in the picture: ii-curvature "
                      "(computed if not in --estimate) or none; default: ii-curvature when "
                      "estimated");
  contour->callback([c] { run_contour(*c); });
}

} // namespace zdg::cli
