// zdg surface / zdg contour: the boundary of the object of a user's 3D / 2D image, its
// topology, estimators on it, a mesh or a drawing, and a JSON summary.
//
//   zdg surface INPUT [selection] [--adjacency 6,26] [--component largest|all|K]
//               [--estimate ii-mean,ii-k1,...] [--radius R|Rv] [--mesh primal|marching-cubes]
//               [-o OUT.ply|OUT.png] [--csv F] [--threads N] [--json] [--quiet] [--force]
//   zdg contour INPUT [selection] [--adjacency 4,8] [--component ...]
//               [--estimate ii-curvature,...] [--radius R|Rv] [-o OUT.svg] [--csv F] ...
//
// The command parses, calls the library and prints; the algorithms are in kernel/
// (image_surfels, image_surfaces, primal_surface_mesh, marching_cubes, image_contours,
// connected_components, betti_numbers) and estimators/ (volume_ii, contour_estimators).
// Outputs are declared to an OutputSet before the input is read (a missing folder or an
// existing file without --force fails at once) and renamed into place at the end.
#include <zdg/arith/error.hpp>
#include <zdg/convergence/cli/commands.hpp>
#include <zdg/convergence/cli/volume_input.hpp>
#include <zdg/estimators/contour_estimators.hpp>
#include <zdg/estimators/volume_ii.hpp>
#include <zdg/kernel/adjacency.hpp>
#include <zdg/kernel/betti_numbers.hpp>
#include <zdg/kernel/connected_components.hpp>
#include <zdg/kernel/contour_svg.hpp>
#include <zdg/kernel/image_contours.hpp>
#include <zdg/kernel/image_surfaces.hpp>
#include <zdg/kernel/image_surfels.hpp>
#include <zdg/kernel/marching_cubes.hpp>
#include <zdg/kernel/output_files.hpp>
#include <zdg/kernel/parallel_for.hpp>
#include <zdg/kernel/primal_surface_mesh.hpp>
#include <zdg/kernel/render_mesh.hpp>

#include <fmt/core.h>
#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
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

// Progress on stderr when it is a terminal (and not --quiet): one line per step.
class Progress {
public:
  explicit Progress(bool enabled) : on_(enabled && ::isatty(2) == 1) {}
  void start(const std::string& what) {
    what_ = what;
    t0_ = Clock::now();
    if (on_) fmt::print(stderr, "zdg: {} ...\n", what);
  }
  /// Ends the step; returns its seconds.
  double done(const std::string& detail = "") {
    const double s = since(t0_);
    if (on_)
      fmt::print(stderr, "zdg: {} done{}{} ({:.2f} s)\n", what_, detail.empty() ? "" : ": ", detail,
                 s);
    return s;
  }

private:
  bool on_;
  std::string what_;
  Clock::time_point t0_;
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

// Until the shared mesh writers land: binary little-endian PLY, float coordinates, int32
// indices, optional per-face normals and scalars (named with '_' for '-').
void write_ply_file(const std::string& path, const PolygonMesh& m) {
  m.validate();
  if (m.vertex_count() > std::numeric_limits<std::int32_t>::max())
    throw IoError(path + ": more than 2^31 - 1 vertices for a PLY file");
  std::ofstream f(path, std::ios::binary);
  if (!f) throw IoError(path + ": cannot be written");
  std::string h = "ply\nformat binary_little_endian 1.0\ncomment zdg\n";
  h += "element vertex " + str(m.vertex_count()) +
       "\nproperty float x\nproperty float y\n"
       "property float z\n";
  if (!m.vertex_normals.empty()) h += "property float nx\nproperty float ny\nproperty float nz\n";
  h += "element face " + str(m.face_count()) + "\nproperty list uchar int vertex_indices\n";
  if (!m.face_normals.empty()) h += "property float nx\nproperty float ny\nproperty float nz\n";
  for (const auto& [name, values] : m.face_scalars) {
    std::string n = name;
    for (char& c : n)
      if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    h += "property float " + n + "\n";
  }
  h += "end_header\n";
  f << h;
  std::vector<char> buf;
  auto put_f = [&](double v) {
    const float x = static_cast<float>(v);
    const char* p = reinterpret_cast<const char*>(&x);
    buf.insert(buf.end(), p, p + 4);
  };
  auto flush = [&](bool force) {
    if (force || buf.size() > (std::size_t{1} << 22)) {
      f.write(buf.data(), std::streamsize(buf.size()));
      buf.clear();
    }
  };
  for (std::int64_t v = 0; v < m.vertex_count(); ++v) {
    const auto& p = m.vertices[std::size_t(v)];
    put_f(p.x);
    put_f(p.y);
    put_f(p.z);
    if (!m.vertex_normals.empty()) {
      const auto& n = m.vertex_normals[std::size_t(v)];
      put_f(n.x);
      put_f(n.y);
      put_f(n.z);
    }
    flush(false);
  }
  for (std::int64_t fi = 0; fi < m.face_count(); ++fi) {
    buf.push_back(static_cast<char>(m.face_size));
    for (auto idx : m.face(fi)) {
      const std::int32_t x = static_cast<std::int32_t>(idx);
      const char* p = reinterpret_cast<const char*>(&x);
      buf.insert(buf.end(), p, p + 4);
    }
    if (!m.face_normals.empty()) {
      const auto& n = m.face_normals[std::size_t(fi)];
      put_f(n.x);
      put_f(n.y);
      put_f(n.z);
    }
    for (const auto& [name, values] : m.face_scalars) put_f(values[std::size_t(fi)]);
    flush(false);
  }
  flush(true);
  if (!f) throw IoError(path + ": write failed");
}

// .ply: the mesh itself; .png: a picture of it (kernel/render_mesh.hpp), coloured by the
// first estimate when there is one, grey otherwise.
void write_mesh_file(const std::string& staging, const std::string& final_path,
                     const PolygonMesh& m, unsigned threads) {
  std::string e = std::filesystem::path(final_path).extension().string();
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (e == ".png") {
    MeshRenderOptions opt;
    opt.threads = threads;
    render_mesh_png(staging, m, m.face_scalars.empty() ? "" : m.face_scalars.front().first, opt);
    return;
  }
  if (e != ".ply") throw IoError(final_path + ": unknown mesh format '" + e + "' (.ply, .png)");
  write_ply_file(staging, m);
}

void check_mesh_extension(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (e != ".ply" && e != ".png")
    throw IoError(path + ": unknown mesh format '" + e + "' (.ply, .png)");
}

void refuse_input_as_output(const std::string& input, const std::string& output) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!output.empty() && fs::exists(output, ec) && fs::equivalent(input, output, ec))
    throw InvalidArgument(output + ": is the input file; refusing to overwrite it");
}

// ------------------------------------------------------------------------------------------
// zdg surface

const std::vector<std::string> kSurfaceEstimates = {"ii-mean", "ii-gaussian", "ii-k1",
                                                    "ii-k2",   "ii-normal",   "ii-directions"};

struct SurfaceArgs {
  VolumeInputArgs in;
  std::string adjacency = "6,26", component = "all", estimate, radius, mesh = "primal";
  std::string output, csv;
  unsigned threads = 0;
  bool json = false, quiet = false, force = false;
};

struct SurfaceEstimates {
  std::vector<double> mean;
  std::vector<IIPrincipalCurvatures> principal;
  std::set<std::string> names;
  double R = 0, h = 1;
};

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
             n = est.names.count("ii-normal") != 0, d = est.names.count("ii-directions") != 0;
  std::string out = "surfel,surface,x,y,z,voxel_x,voxel_y,voxel_z,direction";
  if (m) out += ",ii_mean";
  if (g) out += ",ii_gaussian";
  if (k1) out += ",ii_k1";
  if (k2) out += ",ii_k2";
  if (n) out += ",nx,ny,nz";
  if (d) out += ",d1x,d1y,d1z,d2x,d2y,d2z";
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
                            "' (ii-mean, ii-gaussian, ii-k1, ii-k2, ii-normal, ii-directions)");
    est.names.insert(e);
  }
  const Radius radius = parse_radius(a.radius.empty() ? "5v" : a.radius);
  if (a.mesh != "primal" && a.mesh != "marching-cubes")
    throw InvalidArgument("--mesh '" + a.mesh + "': expected primal or marching-cubes");
  if (!a.output.empty()) check_mesh_extension(a.output);
  refuse_input_as_output(a.in.path, a.output);
  refuse_input_as_output(a.in.path, a.csv);
  OutputSet outputs(a.force ? Existing::replace : Existing::refuse);
  const std::string mesh_staging = a.output.empty() ? "" : outputs.add(a.output).string();
  const std::string csv_staging = a.csv.empty() ? "" : outputs.add(a.csv).string();

  Progress progress(!a.quiet);
  nlohmann::json seconds = nlohmann::json::object();
  LoadedObject obj = load_object(a.in, 3, a.threads, !a.quiet);
  seconds["read"] = obj.read_seconds;
  seconds["select"] = obj.select_seconds;
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
      throw InvalidArgument(a.in.path + ": --radius " + a.radius + " is " + fmt::format("{}", rv) +
                            " voxels, larger than the volume (" + str(vol.array.shape[2]) + " x " +
                            str(vol.array.shape[1]) + " x " + str(vol.array.shape[0]) + " voxels)");
    if (rv > 256)
      throw InvalidArgument("--radius " + a.radius + " is " + fmt::format("{}", rv) +
                            " voxels; the integral invariants take at most 256");
  }
  // Grey values for marching cubes: the threshold's level (positions interpolated).
  const bool grey = a.mesh == "marching-cubes" && !a.in.threshold.empty();
  Image<std::uint8_t> mask = std::move(obj.mask);
  if (!grey) obj.volume.array.bytes = {}; // the values are not needed any more

  progress.start("components");
  ComponentSelection comps = select_components(mask, pair.object, which, a.threads, a.in.path);
  seconds["components"] = progress.done(str(comps.count) + " component(s)");

  progress.start("Betti numbers");
  const BettiNumbers betti = betti_numbers(mask, pair, a.threads);
  seconds["betti"] = progress.done();

  progress.start("boundary surfels");
  const ImageSurfels sf = image_surfels(mask, a.threads);
  seconds["surfels"] = progress.done(str(sf.size()) + " surfels");
  progress.start("closed surfaces");
  const ImageSurfaces ss = image_surfaces(mask, sf, conv, a.threads);
  seconds["surfaces"] = progress.done(str(std::int64_t(ss.surfaces.size())) + " surfaces");
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
    seconds["estimates"] = progress.done();
  }

  nlohmann::json mesh_json;
  if (!a.output.empty()) {
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
    }
    // Per-face fields: the surfel's estimates (primal: face = surfel; marching cubes: the
    // mean over the triangle's surfel vertices).
    std::vector<std::pair<std::string, std::vector<double>>> fields;
    if (est.names.count("ii-mean")) fields.emplace_back("ii-mean", est.mean);
    for (const char* n : {"ii-gaussian", "ii-k1", "ii-k2"})
      if (est.names.count(n)) fields.emplace_back(n, principal_field(est, n));
    std::vector<Point3<double>> normals(static_cast<std::size_t>(sf.size()));
    for (std::int64_t i = 0; i < sf.size(); ++i) {
      if (!est.principal.empty()) {
        normals[std::size_t(i)] = est.principal[std::size_t(i)].normal;
      } else {
        const auto t = trivial_normal(sf.surfel(i));
        normals[std::size_t(i)] = {double(t.x), double(t.y), double(t.z)};
      }
    }
    if (a.mesh == "primal") {
      mesh.face_scalars = std::move(fields);
      mesh.face_normals = std::move(normals);
    } else {
      const std::int64_t n = sf.size();
      for (auto& [name, values] : fields) {
        std::vector<double> per_face(static_cast<std::size_t>(mesh.face_count()));
        for (std::int64_t f = 0; f < mesh.face_count(); ++f) {
          double s = 0;
          int k = 0;
          for (auto v : mesh.face(f))
            if (v < n) {
              s += values[std::size_t(v)];
              ++k;
            }
          per_face[std::size_t(f)] = s / k;
        }
        mesh.face_scalars.emplace_back(name, std::move(per_face));
      }
      // Vertex normals: the surfels' (II or elementary), the centres' the mean of their
      // neighbours'.
      mesh.vertex_normals.assign(mesh.vertices.size(), Point3<double>{0, 0, 0});
      for (std::int64_t i = 0; i < n; ++i)
        mesh.vertex_normals[std::size_t(i)] = normals[std::size_t(i)];
      for (std::int64_t f = 0; f < mesh.face_count(); ++f) {
        const auto t = mesh.face(f);
        for (std::size_t c = 0; c < 3; ++c)
          if (t[c] >= n)
            for (std::size_t d = 0; d < 3; ++d)
              if (t[d] < n)
                mesh.vertex_normals[std::size_t(t[c])] =
                    mesh.vertex_normals[std::size_t(t[c])] + normals[std::size_t(t[d])];
      }
      for (auto& v : mesh.vertex_normals) {
        const double l = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
        if (l > 0) v = {v.x / l, v.y / l, v.z / l};
      }
    }
    seconds["mesh"] = progress.done(str(mesh.face_count()) + " faces");
    mesh_json = {{"kind", a.mesh},
                 {"path", a.output},
                 {"vertices", str(mesh.vertex_count())},
                 {"faces", str(mesh.face_count())},
                 {"edges", str(edges)},
                 {"euler", str(mesh.vertex_count() - edges + mesh.face_count())}};
    progress.start("writing " + a.output);
    write_mesh_file(mesh_staging, a.output, mesh, a.threads);
    seconds["write_mesh"] = progress.done();
  }
  if (!a.csv.empty()) {
    progress.start("writing " + a.csv);
    write_surface_csv(csv_staging, sf, ss, place, est);
    seconds["write_csv"] = progress.done();
  }
  outputs.commit();
  seconds["total"] = since(t_total);

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
                        {"threads", worker_count(a.threads, std::int64_t{1} << 30)}};
    if (!mesh_json.is_null()) j["mesh"] = mesh_json;
    if (!a.csv.empty()) j["csv"] = a.csv;
    print_json(j);
    return;
  }
  fmt::print("{}: {} component(s) under ({}), {} surfels in {} closed surface(s); "
             "Betti numbers {} {} {} (Euler characteristic {})\n",
             a.in.path, comps.count, pair.name(), sf.size(), ss.surfaces.size(), betti.b[0],
             betti.b[1], betti.b[2], betti.euler);
  if (ss.pinched_pointels > 0 || ss.pinched_linels > 0)
    fmt::print("  {} pinched pointel(s), {} pinched linel(s) (see zdg surface --help)\n",
               ss.pinched_pointels, ss.pinched_linels);
  if (!mesh_json.is_null())
    fmt::print("  {} mesh: {} vertices, {} faces -> {}\n", a.mesh,
               mesh_json["vertices"].get<std::string>(), mesh_json["faces"].get<std::string>(),
               a.output);
  if (est.names.count("ii-mean")) {
    const auto s = stats(est.mean);
    if (s.contains("mean"))
      fmt::print("  ii-mean: min {:.6g}, max {:.6g}, mean {:.6g} (R = {} = {} voxels)\n",
                 s["min"].get<double>(), s["max"].get<double>(), s["mean"].get<double>(), est.R,
                 est.R / est.h);
  }
  if (!a.csv.empty()) fmt::print("  per-surfel values -> {}\n", a.csv);
}

// ------------------------------------------------------------------------------------------
// zdg contour

const std::vector<std::string> kContourEstimates = {"ii-curvature", "bc-tangent", "lmst-tangent",
                                                    "mlp-length", "gauss-area"};

struct ContourArgs {
  VolumeInputArgs in;
  std::string adjacency = "4,8", component = "all", estimate, radius;
  std::string output, csv;
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
  refuse_input_as_output(a.in.path, a.output);
  refuse_input_as_output(a.in.path, a.csv);
  OutputSet outputs(a.force ? Existing::replace : Existing::refuse);
  const std::string svg_staging = a.output.empty() ? "" : outputs.add(a.output).string();
  const std::string csv_staging = a.csv.empty() ? "" : outputs.add(a.csv).string();

  Progress progress(!a.quiet);
  nlohmann::json seconds = nlohmann::json::object();
  LoadedObject obj = load_object(a.in, 2, a.threads, !a.quiet);
  seconds["read"] = obj.read_seconds;
  seconds["select"] = obj.select_seconds;
  const auto& vol = obj.volume;
  const double h = isotropic_step(vol.spacing, a.in.path);
  const double R = radius.voxels ? radius.value * h : radius.value;
  const std::int64_t extent = std::max(vol.array.shape[0], vol.array.shape[1]);
  if ((req.ii_curvature || req.bc_tangent) && R / h > double(extent))
    throw InvalidArgument(a.in.path + ": --radius " + a.radius + " is " + fmt::format("{}", R / h) +
                          " pixels, larger than the image (" + str(vol.array.shape[1]) + " x " +
                          str(vol.array.shape[0]) + " pixels)");
  Image<std::uint8_t> mask = std::move(obj.mask);
  obj.volume.array.bytes = {};

  progress.start("components");
  ComponentSelection comps = select_components(mask, pair.object, which, a.threads, a.in.path);
  comps.labels.reset();
  seconds["components"] = progress.done(str(comps.count) + " component(s)");
  progress.start("Betti numbers");
  const BettiNumbers betti = betti_numbers(mask, pair, a.threads);
  seconds["betti"] = progress.done();
  progress.start("contours");
  const ImageContours cs = image_contours(mask, pair.object, pair.background);
  seconds["contours"] = progress.done(str(std::int64_t(cs.contours.size())) + " contours");
  if (cs.b0 != betti.b[0] || cs.b1 != betti.b[1])
    throw Error("internal: the contours give b0, b1 = " + str(cs.b0) + ", " + str(cs.b1) +
                " but the components give " + str(betti.b[0]) + ", " + str(betti.b[1]));

  ContourEstimates e;
  if (!names.empty()) {
    progress.start("estimates");
    e = contour_estimates(mask, cs, req, h, R, a.threads);
    seconds["estimates"] = progress.done();
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
    seconds["write_svg"] = progress.done();
  }
  if (!a.csv.empty()) {
    progress.start("writing " + a.csv);
    write_contour_csv(csv_staging, cs, h, origin_pixel, origin, req, e);
    seconds["write_csv"] = progress.done();
  }
  outputs.commit();
  seconds["total"] = since(t_total);

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
                        {"threads", worker_count(a.threads, std::int64_t{1} << 30)}};
    if (!a.output.empty()) j["svg"] = a.output;
    if (!a.csv.empty()) j["csv"] = a.csv;
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
}

template <class Args>
void add_common_options(CLI::App* cmd, Args& a, const char* pairs, const char* mesh_help) {
  add_volume_input_options(*cmd, a.in);
  cmd->add_option("--adjacency", a.adjacency, pairs);
  cmd->add_option("--component", a.component,
                  "largest, all (default), or K: the K-th largest component");
  cmd->add_option("--radius", a.radius,
                  "kernel radius of the estimators: R in physical units, or Rv in voxels "
                  "(default 5v)");
  cmd->add_option("-o,--output", a.output, mesh_help);
  cmd->add_option("--csv", a.csv, "write one row per boundary element with its estimates");
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
      "marching-cubes mesh. Under (6,26) and (26,6) the object's continuous analog may join two "
      "sheets at a pointel (pinched pointels) and, under any pair, a surface may pass twice along "
      "a linel (pinched linels, an edge of four quads in the primal mesh; marching cubes stays "
      "a manifold): the JSON counts them; the Betti numbers are exact in every case");
  add_common_options(surface, *s,
                     "adjacency pair (object, background): 6,26 (default), 26,6, 6,18, 18,6",
                     "mesh output (.ply), or a picture of it (.png)");
  surface->add_option("--estimate", s->estimate,
                      "comma-separated estimators: ii-mean, ii-gaussian, ii-k1, ii-k2, ii-normal, "
                      "ii-directions");
  surface->add_option("--mesh", s->mesh, "primal (one quad per surfel, default) or marching-cubes");
  surface->callback([s] { run_surface(*s); });

  auto c = std::make_shared<ContourArgs>();
  auto* contour = app.add_subcommand(
      "contour", "the contours of a 2D object under an adjacency pair, its Betti numbers, 2D "
                 "estimators along the contours, an SVG drawing");
  add_common_options(contour, *c, "adjacency pair (object, background): 4,8 (default) or 8,4",
                     "drawing of the contours (.svg)");
  contour->add_option("--estimate", c->estimate,
                      "comma-separated estimators: ii-curvature, bc-tangent, lmst-tangent, "
                      "mlp-length, gauss-area");
  contour->callback([c] { run_contour(*c); });
}

} // namespace zdg::cli
