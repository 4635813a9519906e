// zdg surface / zdg contour: the boundary of the object of a user's 3D / 2D image, its
// topology, estimators on it, a mesh or a drawing, and a JSON summary.
//
//   zdg surface INPUT [selection] [--adjacency 6,26] [--component largest|all|K]
//               [--estimate ii-mean,ii-k1,...,geodesic,at-normal] [--source SURFEL|X,Y,Z]
//               [--at-alpha A] [--at-lambda L] [--at-v linel|pointel] [--radius R|Rv]
//               [--mesh primal|marching-cubes] [--regularize [--alpha A] [--beta B] [--gamma G]]
//               [-o OUT.ply|.obj|.off] [--csv F] [--png F [--color E] [--view AZ,EL]
//               [--png-size WxH]] [--threads N] [--json] [--quiet] [--force]
//   zdg contour INPUT [selection] [--adjacency 4,8] [--component ...]
//               [--estimate ii-curvature,...] [--radius R|Rv] [-o OUT.svg] [--csv F]
//               [--png F [--color ii-curvature] [--png-size WxH]] ...
//
// The command parses, reads the image (cli/volume_input), calls surface_operation /
// contour_operation (operations/surface_operations.hpp: the whole pipeline and its estimator
// registry), writes the outputs and prints.
// Outputs are declared to an OutputSet before the input is read (a missing folder or an
// existing file without --force fails at once) and renamed into place at the end.
#include <zdg/arith/error.hpp>
#include <zdg/cli/commands.hpp>
#include <zdg/cli/volume_input.hpp>
#include <zdg/kernel/io/mesh_io.hpp>
#include <zdg/kernel/io/output_files.hpp>
#include <zdg/kernel/render/mesh_html.hpp>
#include <zdg/kernel/render/picture.hpp>
#include <zdg/kernel/render/render_contours.hpp>
#include <zdg/kernel/render/render_mesh.hpp>
#include <zdg/kernel/surfaces/image_surfels.hpp>
#include <zdg/kernel/surfaces/primal_surface_mesh.hpp>
#include <zdg/kernel/topology/adjacency.hpp>
#include <zdg/kernel/topology/betti_numbers.hpp>
#include <zdg/operations/progress.hpp>
#include <zdg/operations/surface_operations.hpp>

#include <fmt/core.h>
#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
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

// The picture options shared by surface and contour.
struct PictureArgs {
  std::string png, color, view, size, range;
};

// --html names an .html page and --max-faces is positive (checked before any work).
void check_viewer_options(const std::string& html, std::int64_t max_faces) {
  if (!html.empty() && lower_extension(html) != ".html")
    throw IoError(html + ": the viewer is an .html file (got '" + lower_extension(html) + "')");
  if (max_faces < 1) throw InvalidArgument("--max-faces must be at least 1");
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
  return parse_picture_size(p.size);
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

// Progress on stderr when it is a terminal (and not --quiet): one line per step.
ProgressCallback progress_printer(bool quiet) {
  if (quiet || ::isatty(2) != 1) return {};
  return [](const ProgressEvent& e) {
    if (!e.done) {
      fmt::print(stderr, "zdg: {} ...\n", e.what);
      return;
    }
    fmt::print(stderr, "zdg: {} done{}{} ({:.2f} s)\n", e.what, e.detail.empty() ? "" : ": ",
               e.detail, e.seconds);
  };
}

// The operation's JSON with the command's own steps (reading, writing) in "seconds" and
// "cpu_seconds".
void add_steps(nlohmann::json& j, const OperationProgress& steps) {
  for (const auto& [k, v] : steps.seconds) j["seconds"][k] = v;
  for (const auto& [k, v] : steps.cpu_seconds) j["cpu_seconds"][k] = v;
}

// The command's own steps, starting with the input's reading and selection (their CPU
// seconds together: the loader reports wall seconds only).
OperationProgress input_steps(const LoadedObject& obj, double cpu_before,
                              const ProgressCallback& callback) {
  OperationProgress steps(callback);
  steps.seconds["read"] = obj.read_seconds;
  steps.seconds["select"] = obj.select_seconds;
  steps.cpu_seconds["read_select"] = process_cpu_seconds() - cpu_before;
  return steps;
}

// "total": the wall seconds since t0 and the process's CPU seconds.
void record_total(OperationProgress& steps, std::chrono::steady_clock::time_point t0) {
  steps.seconds["total"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  steps.cpu_seconds["total"] = process_cpu_seconds();
}

// The object of the loaded image, as the operations take it.
ObjectImage object_image(LoadedObject& obj, const std::string& path) {
  ObjectImage im;
  im.mask = std::move(obj.mask);
  im.spacing = obj.volume.spacing;
  im.origin = obj.volume.origin;
  im.name = path;
  return im;
}

// ------------------------------------------------------------------------------------------
// zdg surface

struct SurfaceArgs {
  VolumeInputArgs in;
  std::string adjacency = "6,26", component = "all", estimate, radius, mesh = "primal";
  std::string output, csv, source, at_alpha, at_lambda, at_v, html;
  std::string reg_alpha, reg_beta, reg_gamma; // --alpha, --beta, --gamma of --regularize
  bool regularize = false;
  std::int64_t max_faces = 2'000'000;
  PictureArgs picture;
  unsigned threads = 0;
  bool json = false, quiet = false, force = false;
  bool harmonic = false;
  std::string labels; ///< --labels all: the interfaces between the labels of a labelled volume
};

// --source: a surfel index, or a point X,Y,Z in physical units (the nearest surfel centre,
// within two voxels).
GeodesicSource parse_source(const std::string& text) {
  GeodesicSource out;
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

// --at-alpha, --at-lambda: positive numbers.
double parse_positive(const std::string& text, const std::string& option) {
  const double v = parse_number(text, option);
  if (!(v > 0) || !std::isfinite(v))
    throw InvalidArgument(option + " '" + text + "': a positive number is needed");
  return v;
}

using ColorFields = std::vector<std::pair<std::string, std::string>>;

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// The field that colours the picture: --color (its estimator added to `estimates` when not
// asked for; InvalidArgument for a name that is not a colour field), "" for --color none;
// without --color, with --png, the first colour field whose estimator is asked for, else "".
std::string picture_color(const PictureArgs& p, const ColorFields& fields,
                          std::vector<std::string>& estimates) {
  if (p.color == "none") return "";
  if (!p.color.empty()) {
    for (const auto& [f, e] : fields) {
      if (f != p.color) continue;
      if (!contains(estimates, e)) estimates.push_back(e);
      return f;
    }
    std::string names;
    for (const auto& f : fields) names += f.first + ", ";
    names.resize(names.size() - 2);
    throw InvalidArgument("--color '" + p.color + "': expected " + names + " or none");
  }
  if (!p.png.empty())
    for (const auto& [f, e] : fields)
      if (contains(estimates, e)) return f;
  return "";
}

// zdg surface INPUT --labels all: a labelled volume (exact integer values; the background's
// value 0 is a label too, and the label of everything outside the volume): the interfaces
// between every two labels that touch (kernel/surfaces/image_surfels.hpp label_interfaces) and,
// per label but the background, its voxels, surfels, components and Betti numbers under the
// adjacency pair. At most 1000 labels (a labelled volume, not a grey-level one).
void run_labels(const SurfaceArgs& a) {
  const auto t0 = std::chrono::steady_clock::now();
  if (a.labels != "all") {
    throw InvalidArgument("--labels '" + a.labels + "': expected all (every label of the volume)");
  }
  if (!a.csv.empty() || !a.picture.png.empty() || !a.html.empty() || !a.estimate.empty() ||
      a.regularize || a.harmonic) {
    throw InvalidArgument("--labels all reports the interfaces and the topology of each label "
                          "(and -o writes their mesh); --csv, --png, --html, --estimate, "
                          "--regularize and --harmonic are for one object");
  }
  if (has_selection(a.in)) {
    throw InvalidArgument("--labels all reads every value as a label (no --threshold, --range, "
                          "--label or --invert)");
  }
  const AdjacencyPair pair = parse_adjacency_pair(a.adjacency, 3);
  // The mesh (-o): declared before the volume is read.
  std::optional<MeshFormat> mesh_format;
  if (!a.output.empty()) {
    mesh_format = mesh_format_of(a.output);
    check_not_input(a.in.path, a.output);
  }
  OutputSet outputs(a.force ? Existing::replace : Existing::refuse);
  const std::string mesh_staging = a.output.empty() ? "" : outputs.add(a.output).string();
  const Image<std::int64_t> img = read_integer_image(a.in.path, raw_layout(a.in));
  if (img.dim() != 3) {
    throw InvalidArgument(a.in.path + ": a " + std::to_string(img.dim()) +
                          "-D image (zdg surface takes 3D volumes)");
  }
  std::set<std::int64_t> values(img.values().begin(), img.values().end());
  values.insert(0);
  if (values.size() > 1001) {
    throw InvalidArgument(a.in.path + ": " + std::to_string(values.size() - 1) +
                          " labels besides 0; --labels all takes at most 1000 (a labelled "
                          "volume, not a grey-level one)");
  }
  const auto interfaces = label_interfaces(img, 0);
  std::map<std::int64_t, std::int64_t> surfels;
  nlohmann::json jf = nlohmann::json::array();
  for (const auto& f : interfaces) {
    surfels[f.a] += f.surfels;
    surfels[f.b] += f.surfels;
    jf.push_back({{"labels", {std::to_string(f.a), std::to_string(f.b)}},
                  {"surfels", std::to_string(f.surfels)}});
  }
  nlohmann::json jl = nlohmann::json::array();
  Image<std::uint8_t> mask(img.domain());
  for (const std::int64_t L : values) {
    if (L == 0) continue;
    std::int64_t voxels = 0;
    for (std::int64_t i = 0; i < img.size(); ++i) {
      mask[i] = img[i] == L ? 1 : 0;
      voxels += mask[i];
    }
    const BettiNumbers b = betti_numbers(mask, pair, a.threads);
    jl.push_back(
        {{"label", std::to_string(L)},
         {"voxels", std::to_string(voxels)},
         {"surfels", std::to_string(surfels[L])},
         {"components", std::to_string(b.b[0])},
         {"euler", std::to_string(b.euler)},
         {"betti", {std::to_string(b.b[0]), std::to_string(b.b[1]), std::to_string(b.b[2])}}});
  }
  nlohmann::json jmesh = nullptr;
  if (mesh_format) {
    const Domain& d = img.domain();
    const VoxelPlacement placement{{1, 1, 1},
                                   {double(d.lower(2)), double(d.lower(1)), double(d.lower(0))}};
    const PolygonMesh mesh = label_interface_mesh(img, 0, placement);
    write_mesh(mesh_staging, mesh, mesh_format, a.threads);
    outputs.commit();
    jmesh = {{"path", a.output},
             {"vertices", std::to_string(mesh.vertex_count())},
             {"faces", std::to_string(mesh.face_count())}};
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (a.json) {
    print_json({{"command", "surface"},
                {"input", a.in.path},
                {"adjacency", pair.name()},
                {"background", "0"},
                {"labels", jl},
                {"interfaces", jf},
                {"mesh", jmesh},
                {"seconds", secs}});
    return;
  }
  if (mesh_format) {
    std::cout << a.output << ": " << jmesh["faces"].get<std::string>()
              << " interface faces (label_a, label_b on each)\n";
  }
  std::cout << a.in.path << ": " << jl.size() << " label(s) besides the background 0, " << jf.size()
            << " interface(s) (" << pair.name() << ")\n";
  for (const auto& l : jl) {
    std::cout << "  label " << l["label"].get<std::string>() << ": "
              << l["voxels"].get<std::string>() << " voxels, " << l["surfels"].get<std::string>()
              << " surfels, Betti " << l["betti"][0].get<std::string>() << ' '
              << l["betti"][1].get<std::string>() << ' ' << l["betti"][2].get<std::string>()
              << '\n';
  }
  for (const auto& f : jf) {
    std::cout << "  interface " << f["labels"][0].get<std::string>() << " | "
              << f["labels"][1].get<std::string>() << ": " << f["surfels"].get<std::string>()
              << " surfels\n";
  }
}

void run_surface(const SurfaceArgs& a) {
  if (!a.labels.empty()) return run_labels(a);
  const auto t_total = std::chrono::steady_clock::now();
  // Options first: nothing is read when one is wrong.
  SurfaceOptions o;
  o.adjacency = parse_adjacency_pair(a.adjacency, 3);
  o.component = parse_component(a.component);
  o.estimates = split_list(a.estimate);
  check_estimator_names(o.estimates, surface_estimators());
  if (!a.source.empty()) o.source = parse_source(a.source);
  if (!a.at_alpha.empty()) o.at.alpha = parse_positive(a.at_alpha, "--at-alpha");
  if (!a.at_lambda.empty()) o.at.lambda = parse_positive(a.at_lambda, "--at-lambda");
  if (!a.at_v.empty()) {
    if (a.at_v != "linel" && a.at_v != "pointel")
      throw InvalidArgument("--at-v '" + a.at_v + "': expected linel or pointel");
    o.at_v = a.at_v == "pointel" ? ATDiscretization::pointel : ATDiscretization::linel;
  }
  // The picture's colour: --color (computed when not in --estimate), else the first scalar
  // estimate, else none (a grey surface).
  const auto [png_w, png_h] = picture_size(a.picture, 1200, 900);
  const std::string color = picture_color(a.picture, surface_color_fields(), o.estimates);
  if ((!a.at_alpha.empty() || !a.at_lambda.empty() || !a.at_v.empty()) &&
      !contains(o.estimates, "at-normal"))
    throw InvalidArgument(
        "--at-alpha, --at-lambda and --at-v are only read by --estimate at-normal");
  if (a.regularize) {
    RegularizationParameters reg;
    if (!a.reg_alpha.empty()) reg.alpha = parse_positive(a.reg_alpha, "--alpha");
    if (!a.reg_beta.empty()) reg.beta = parse_positive(a.reg_beta, "--beta");
    if (!a.reg_gamma.empty()) reg.gamma = parse_positive(a.reg_gamma, "--gamma");
    o.regularize = reg;
  } else if (!a.reg_alpha.empty() || !a.reg_beta.empty() || !a.reg_gamma.empty()) {
    throw InvalidArgument("--alpha, --beta and --gamma are only read by --regularize");
  }
  check_surface_options(o);
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
  o.radius = parse_estimator_radius(a.radius);
  if (a.mesh != "primal" && a.mesh != "marching-cubes")
    throw InvalidArgument("--mesh '" + a.mesh + "': expected primal or marching-cubes");
  if (!a.output.empty() || !a.picture.png.empty() || !a.html.empty() || a.regularize)
    o.mesh = a.mesh == "primal" ? SurfaceMesh::primal : SurfaceMesh::marching_cubes;
  check_surface_options(o);
  check_viewer_options(a.html, a.max_faces);
  o.keep_surfels = !a.csv.empty();
  o.harmonic = a.harmonic;
  o.threads = a.threads;
  o.progress = progress_printer(a.quiet);
  std::optional<MeshFormat> mesh_format;
  if (!a.output.empty()) mesh_format = mesh_format_of(a.output);
  for (const auto* out : {&a.output, &a.csv, &a.picture.png, &a.html})
    check_not_input(a.in.path, *out);
  OutputSet outputs(a.force ? Existing::replace : Existing::refuse);
  const std::string mesh_staging = a.output.empty() ? "" : outputs.add(a.output).string();
  const std::string html_staging = a.html.empty() ? "" : outputs.add(a.html).string();
  const std::string csv_staging = a.csv.empty() ? "" : outputs.add(a.csv).string();
  const std::string png_staging = a.picture.png.empty() ? "" : outputs.add(a.picture.png).string();

  const double cpu_read = process_cpu_seconds();
  LoadedObject obj = load_object(a.in, 3, a.threads, !a.quiet);
  OperationProgress steps = input_steps(obj, cpu_read, o.progress);
  const nlohmann::json input = std::move(obj.json);
  ObjectImage image = object_image(obj, a.in.path);
  // Grey values for marching cubes: the threshold's level (positions interpolated); otherwise
  // the values are freed now.
  if (o.mesh == SurfaceMesh::marching_cubes && !a.in.threshold.empty()) {
    image.grey = std::move(obj.volume);
    image.grey_level = obj.selection.low;
  } else {
    std::vector<unsigned char>().swap(obj.volume.array.bytes);
  }
  SurfaceResult r = surface_operation(std::move(image), o);

  nlohmann::json picture;
  if (r.mesh) {
    if (!a.output.empty()) {
      steps.start("writing " + a.output);
      write_mesh(mesh_staging, *r.mesh, mesh_format, a.threads);
      steps.done("write_mesh");
    }
    if (!a.picture.png.empty()) {
      steps.start("picture " + a.picture.png);
      const auto p = render_mesh_png(png_staging, *r.mesh, color, render);
      steps.done("picture");
      picture =
          picture_json(a.picture.png, color, png_w, png_h, p.value_min, p.value_max, p.color_map);
    }
  }
  if (r.mesh && !a.html.empty()) {
    steps.start("viewer " + a.html);
    MeshHtmlOptions page;
    page.title = std::filesystem::path(a.in.path).filename().string();
    page.field = color;
    page.max_faces = a.max_faces;
    write_mesh_html(html_staging, *r.mesh, page);
    steps.done("write_html");
  }
  if (!a.csv.empty()) {
    steps.start("writing " + a.csv);
    write_surface_csv(csv_staging, r);
    steps.done("write_csv");
  }
  outputs.commit();
  record_total(steps, t_total);

  if (a.json) {
    nlohmann::json j = to_json(r);
    add_steps(j, steps);
    j["command"] = "surface";
    j["input"] = input;
    if (r.mesh && !a.output.empty()) j["mesh"]["path"] = a.output;
    if (!picture.is_null()) j["picture"] = picture;
    if (!a.csv.empty()) j["csv"] = a.csv;
    if (!a.html.empty()) j["html"] = a.html;
    print_json(j);
    return;
  }
  fmt::print("{}: {} component(s) under ({}), {} surfels in {} closed surface(s); "
             "Betti numbers {} {} {} (Euler characteristic {})\n",
             a.in.path, r.object_components, r.adjacency.name(), r.surfels, r.surfaces,
             r.betti.b[0], r.betti.b[1], r.betti.b[2], r.betti.euler);
  std::size_t shown = 0;
  for (const auto& c : r.components) {
    if (++shown > 5) {
      fmt::print("  ... {} more component(s) (--json lists them all)\n", r.components.size() - 5);
      break;
    }
    fmt::print("  component {}: {} voxels, {} surfels in {} surface(s), Euler characteristic {}, "
               "genus {}{}\n",
               c.rank, c.voxels, c.surfels, c.surfaces, c.euler, c.genus,
               c.harmonic_dim < 0
                   ? std::string()
                   : fmt::format(", harmonic 1-forms of dimension {}", c.harmonic_dim));
  }
  if (r.pinched_pointels > 0 || r.pinched_linels > 0)
    fmt::print("  {} pinched pointel(s), {} pinched linel(s) (see zdg surface --help)\n",
               r.pinched_pointels, r.pinched_linels);
  if (r.mesh)
    fmt::print("  {} mesh: {} vertices, {} faces{}{}\n", a.mesh, r.mesh->vertex_count(),
               r.mesh->face_count(), a.output.empty() ? "" : " -> ", a.output);
  if (r.regularization)
    fmt::print("  regularized: energy {:.6g} -> {:.6g}, max displacement {:.4g} h ({} "
               "iterations, {})\n",
               r.regularization->before.total(), r.regularization->after.total(),
               r.regularization->max_displacement, r.regularization->iterations,
               r.regularization->solver);
  const auto& est = r.estimates;
  if (est.names.count("ii-mean")) {
    const auto s = value_stats(est.mean);
    if (s.contains("mean"))
      fmt::print("  ii-mean: min {:.6g}, max {:.6g}, mean {:.6g} (R = {} = {} voxels)\n",
                 s["min"].get<double>(), s["max"].get<double>(), s["mean"].get<double>(), est.R,
                 est.R / est.h);
  }
  if (!a.csv.empty()) fmt::print("  per-surfel values -> {}\n", a.csv);
  if (!a.html.empty()) fmt::print("  viewer -> {}\n", a.html);
  if (!picture.is_null()) print_picture_line(picture);
}

// ------------------------------------------------------------------------------------------
// zdg contour

struct ContourArgs {
  VolumeInputArgs in;
  std::string adjacency = "4,8", component = "all", estimate, radius;
  std::string output, csv, html;
  std::int64_t max_faces = 2'000'000;
  PictureArgs picture;
  unsigned threads = 0;
  bool json = false, quiet = false, force = false, interpolated = false;
};

void run_contour(const ContourArgs& a) {
  const auto t_total = std::chrono::steady_clock::now();
  ContourOptions o;
  o.adjacency = parse_adjacency_pair(a.adjacency, 2);
  o.component = parse_component(a.component);
  o.estimates = split_list(a.estimate);
  o.interpolated = a.interpolated;
  check_estimator_names(o.estimates, contour_estimators());
  // The picture's colour: --color ii-curvature (computed when not in --estimate), the default
  // when ii-curvature is estimated; otherwise the contours are drawn in black.
  const auto [png_w, png_h] = picture_size(a.picture, 1000, 800);
  const std::string color = picture_color(a.picture, contour_color_fields(), o.estimates);
  ContourRenderOptions render;
  render.width = png_w;
  render.height = png_h;
  if (const auto r = parse_color_range(a.picture.range)) {
    render.value_min = r->first;
    render.value_max = r->second;
  }
  o.radius = parse_estimator_radius(a.radius);
  o.threads = a.threads;
  o.progress = progress_printer(a.quiet);
  if (!a.output.empty()) {
    const std::string e = lower_extension(a.output);
    if (e != ".svg")
      throw IoError(a.output + ": the contour drawing is an .svg file (got '" + e + "')");
  }
  check_viewer_options(a.html, a.max_faces);
  for (const auto* out : {&a.output, &a.csv, &a.picture.png, &a.html})
    check_not_input(a.in.path, *out);
  OutputSet outputs(a.force ? Existing::replace : Existing::refuse);
  const std::string svg_staging = a.output.empty() ? "" : outputs.add(a.output).string();
  const std::string html_staging = a.html.empty() ? "" : outputs.add(a.html).string();
  const std::string csv_staging = a.csv.empty() ? "" : outputs.add(a.csv).string();
  const std::string png_staging = a.picture.png.empty() ? "" : outputs.add(a.picture.png).string();

  const double cpu_read = process_cpu_seconds();
  LoadedObject obj = load_object(a.in, 2, a.threads, !a.quiet);
  OperationProgress steps = input_steps(obj, cpu_read, o.progress);
  const nlohmann::json input = std::move(obj.json);
  ObjectImage image = object_image(obj, a.in.path);
  // Marching squares on the grey values at the threshold's level; otherwise the values are
  // freed now (the interpolated contour is then through the linel midpoints).
  if (a.interpolated && !a.in.threshold.empty()) {
    image.grey = std::move(obj.volume);
    image.grey_level = obj.selection.low;
  } else {
    std::vector<unsigned char>().swap(obj.volume.array.bytes); // frees (= {} keeps the capacity)
  }
  const ContourResult r = contour_operation(std::move(image), o);

  if (!a.output.empty()) {
    steps.start("writing " + a.output);
    write_contour_svg(svg_staging, r);
    steps.done("write_svg");
  }
  if (!a.html.empty()) {
    steps.start("viewer " + a.html);
    MeshHtmlOptions page;
    page.title = std::filesystem::path(a.in.path).filename().string();
    page.field = r.request.ii_curvature ? "ii-curvature" : "contour";
    page.max_faces = a.max_faces;
    page.top_view = true;
    page.note = "each face is a linel (a ribbon along it); centre: its midpoint";
    write_mesh_html(html_staging, contour_mesh(r), page);
    steps.done("write_html");
  }
  if (!a.csv.empty()) {
    steps.start("writing " + a.csv);
    write_contour_csv(csv_staging, r);
    steps.done("write_csv");
  }
  nlohmann::json picture;
  if (!a.picture.png.empty()) {
    steps.start("picture " + a.picture.png);
    const auto p =
        render_contours_png(png_staging, r.mask, contour_polylines(r, color), color, render);
    steps.done("picture");
    picture =
        picture_json(a.picture.png, color, png_w, png_h, p.value_min, p.value_max, p.color_map);
  }
  outputs.commit();
  record_total(steps, t_total);

  if (a.json) {
    nlohmann::json j = to_json(r);
    add_steps(j, steps);
    j["command"] = "contour";
    j["input"] = input;
    if (!a.output.empty()) j["svg"] = a.output;
    if (!a.csv.empty()) j["csv"] = a.csv;
    if (!a.html.empty()) j["html"] = a.html;
    if (!picture.is_null()) j["picture"] = picture;
    print_json(j);
    return;
  }
  const auto& cs = r.contours;
  fmt::print("{}: {} contour(s) of {} linels under ({}); Betti numbers {} {}\n", a.in.path,
             cs.contours.size(), cs.linels(), r.adjacency.name(), r.betti.b[0], r.betti.b[1]);
  if (r.request.gauss_area) fmt::print("  gauss-area: {}\n", r.estimates.gauss_area);
  if (r.request.mlp_length) {
    double total = 0;
    for (double l : r.estimates.mlp_length) total += l;
    fmt::print("  mlp-length: {} (all contours)\n", total);
  }
  if (!a.output.empty()) fmt::print("  drawing -> {}\n", a.output);
  if (!a.csv.empty()) fmt::print("  per-linel values -> {}\n", a.csv);
  if (!a.html.empty()) fmt::print("  viewer -> {}\n", a.html);
  if (!picture.is_null()) print_picture_line(picture);
}

// The --estimate help: the registry's names and summaries.
std::string estimate_help(const std::vector<ImageEstimator>& registry) {
  std::string out = "comma-separated estimators: ";
  for (const auto& e : registry) {
    if (&e != &registry.front()) out += "; ";
    out += e.name;
    out += " (";
    out += e.summary;
    out += ")";
  }
  return out;
}

template <class Args>
void add_viewer_options(CLI::App* cmd, Args& a, const char* help) {
  cmd->add_option("--html", a.html, help);
  cmd->add_option("--max-faces", a.max_faces,
                  "the most faces the viewer page holds (default 2000000); a larger result is "
                  "refused before any output is written");
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
  surface->add_option("--estimate", s->estimate, estimate_help(surface_estimators()));
  surface->add_option("--labels", s->labels,
                      "all: a labelled volume (every value a label, 0 the background and the "
                      "outside): the interfaces between every two labels that touch, and each "
                      "label's voxels, surfels and Betti numbers (--json: \"labels\", "
                      "\"interfaces\"); with -o, the mesh of the interfaces with the face "
                      "properties label_a < label_b");
  surface->add_option("--at-alpha", s->at_alpha,
                      fmt::format("Ambrosio-Tortorelli data fidelity alpha > 0 (default {}; "
                                  "larger: closer to the II normals)",
                                  ATParameters{}.alpha));
  surface->add_option("--at-lambda", s->at_lambda,
                      fmt::format("Ambrosio-Tortorelli discontinuity cost lambda > 0 (default "
                                  "{}; smaller: more edges)",
                                  ATParameters{}.lambda));
  surface->add_option("--at-v", s->at_v,
                      "where Ambrosio-Tortorelli's discontinuity function v lives: linel (a "
                      "dual 1-form, default) or pointel (a primal 0-form, the CGF 2016 paper's "
                      "discretization; conjugate gradients)");
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
  surface->add_flag("--harmonic", s->harmonic,
                    "per component, the dimension of the harmonic 1-forms of its closed surfaces "
                    "(\"harmonic_dim\" in --json), from the exact ranks of the exterior "
                    "derivatives d0 and d1 (2 genus on each closed surface)");
  surface->add_flag("--regularize", s->regularize,
                    "move the primal mesh's vertices so that each quad is orthogonal to the II "
                    "normal of its surfel, each vertex within the cube of side h at its pointel "
                    "(Coeurjolly, Gueth, Lachaud, TVCG 2021); the JSON reports the energies");
  const RegularizationParameters reg_defaults;
  surface->add_option(
      "--alpha", s->reg_alpha,
      fmt::format("--regularize: data weight alpha > 0 (default {})", reg_defaults.alpha));
  surface->add_option(
      "--beta", s->reg_beta,
      fmt::format("--regularize: alignment weight beta > 0 (default {})", reg_defaults.beta));
  surface->add_option(
      "--gamma", s->reg_gamma,
      fmt::format("--regularize: fairness weight gamma > 0 (default {})", reg_defaults.gamma));
  add_viewer_options(surface, *s,
                     "write a self-contained viewer page (WebGL, no network): the mesh coloured "
                     "by any estimate, picking, the normals as glyphs");
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
  contour->add_option("--estimate", c->estimate, estimate_help(contour_estimators()));
  contour->add_flag("--interpolated", c->interpolated,
                    "marching squares beside the linel contours: one vertex a linel, on the grid "
                    "edge between its pixels by linear interpolation of the values at the "
                    "--threshold level (the linel midpoints without --threshold); lengths and "
                    "areas in the JSON, vertices in the CSV (interpolated_x, interpolated_y)");
  contour->add_option("--color", c->picture.color,
                      "the estimate that colours the contours in the picture: ii-curvature "
                      "(computed if not in --estimate) or none; default: ii-curvature when "
                      "estimated");
  add_viewer_options(contour, *c,
                     "write a self-contained viewer page (WebGL, no network): the contours seen "
                     "from above, each linel a face coloured by any estimate, picking");
  contour->callback([c] { run_contour(*c); });
}

} // namespace zdg::cli
