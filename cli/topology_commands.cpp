// zdg topology components|betti|simple|thin|skeleton|graph: digital topology of binary images read
// by the volume loader (cli/volume_input.hpp: every format, the selection options): connected
// components, Euler characteristic and Betti numbers, simple points, homotopic thinning and
// skeletons (kernel/topology/adjacency.hpp, connected_components.hpp, betti_numbers.hpp,
// simple_points.hpp, homotopic_thinning.hpp, critical_kernel_thinning.hpp). Outputs go through
// OutputSet (all or nothing, existing files refused without --force).
#include <zdg/arith/error.hpp>
#include <zdg/cli/commands.hpp>
#include <zdg/cli/volume_input.hpp>
#include <zdg/kernel/io/cycles_ply.hpp>
#include <zdg/kernel/io/npy_io.hpp>
#include <zdg/kernel/io/output_files.hpp>
#include <zdg/kernel/io/pgm_io.hpp>
#include <zdg/kernel/io/vol_io.hpp>
#include <zdg/kernel/io/volume_io.hpp>
#include <zdg/kernel/render/mesh_html.hpp>
#include <zdg/kernel/surfaces/image_surfaces.hpp>
#include <zdg/kernel/surfaces/image_surfels.hpp>
#include <zdg/kernel/surfaces/primal_surface_mesh.hpp>
#include <zdg/kernel/topology/betti_numbers.hpp>
#include <zdg/kernel/topology/connected_components.hpp>
#include <zdg/kernel/topology/critical_kernel_thinning.hpp>
#include <zdg/kernel/topology/homology_generators.hpp>
#include <zdg/kernel/topology/homotopic_thinning.hpp>
#include <zdg/kernel/topology/simple_points.hpp>
#include <zdg/kernel/topology/skeleton_graph.hpp>
#include <zdg/kernel/transforms/distance_transform.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <unistd.h>
#include <vector>

namespace zdg::cli {

namespace {

struct TopologyArgs {
  VolumeInputArgs in;
  std::string command, output, adjacency, method = "sequential", skeleton, priority = "dt", anchors;
  std::string html; ///< thin, skeleton: the viewer page of the result's boundary (3D)
  unsigned threads = 0;
  bool json = false, quiet = false, force = false;
  bool generators = false; ///< betti: write representative cycles to -o FILE.ply
};

// A .pgm output holds a 2D image and a .vol output a 3D one: checked before any work.
void check_output_dim(const TopologyArgs& a, int dim) {
  if (a.output.empty()) return;
  const std::string e = lower_extension(a.output);
  if ((e == ".pgm" && dim != 2) || (e == ".vol" && dim != 3)) {
    throw InvalidArgument(a.output + ": a " + e + " image is " + (e == ".pgm" ? "2D" : "3D") +
                          " and " + a.in.path + " is " + std::to_string(dim) + "D; use .npy or " +
                          (dim == 2 ? ".pgm" : ".vol"));
  }
}

// The object of the input (2D or 3D, any format; value != 0 unless a selection option is
// given). An empty object is an error naming the file and the selection.
Image<std::uint8_t> read_object(const TopologyArgs& a) {
  Image<std::uint8_t> mask = load_object(a.in, 0, a.threads).mask;
  check_output_dim(a, mask.dim());
  return mask;
}

// Writes to `path` in the format of the extension of `named` (the output; path is its staging
// file).
void write_image(const std::string& path, const std::string& named, const Domain& dom,
                 const std::vector<std::uint64_t>& v, DType dtype) {
  const std::string e = lower_extension(named);
  if (e == ".pgm") {
    if (dom.dim() != 2) throw IoError(named + ": a .pgm image is 2D; use .npy or .vol");
    write_pgm(path, Image<std::uint64_t>(dom, v));
  } else if (e == ".vol") {
    if (dom.dim() != 3) throw IoError(named + ": a .vol image is 3D; use .npy or .pgm");
    write_vol(path, Image<std::uint64_t>(dom, v));
  } else if (e == ".npy") {
    if (dtype == DType::U32) {
      write_npy(path, make_npy<std::uint32_t>(dom.extents(),
                                              std::vector<std::uint32_t>(v.begin(), v.end())));
    } else {
      write_npy(path, make_npy<std::uint8_t>(dom.extents(),
                                             std::vector<std::uint8_t>(v.begin(), v.end())));
    }
  } else {
    throw IoError(named + ": unknown output format '" + e + "' (.npy, .pgm or .vol)");
  }
}

// The output is checked before any work (existing file refused unless --force, not the input).
std::unique_ptr<OutputSet> plan_output(const TopologyArgs& a, bool required, std::string& staging) {
  if (a.output.empty()) {
    if (required) throw InvalidArgument("no output file (-o OUT.npy|.vol|.pgm)");
    return nullptr;
  }
  const std::string e = lower_extension(a.output);
  if (e != ".npy" && e != ".vol" && e != ".pgm") {
    throw IoError(a.output + ": unknown output format '" + e + "' (.npy, .pgm or .vol)");
  }
  check_not_input(a.in.path, a.output);
  auto out = std::make_unique<OutputSet>(a.force ? Existing::replace : Existing::refuse);
  staging = out->add(a.output).string();
  return out;
}

// --html: an .html file beside the output, in the same OutputSet (all or nothing).
std::string plan_html(const TopologyArgs& a, OutputSet& out) {
  if (a.html.empty()) return "";
  if (lower_extension(a.html) != ".html")
    throw IoError(a.html + ": the viewer is an .html file (got '" + lower_extension(a.html) + "')");
  check_not_input(a.in.path, a.html);
  return out.add(a.html).string();
}

double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The summary of a result set: its points, components and Betti numbers.
void report(const TopologyArgs& a, const AdjacencyPair& pair, const Image<std::uint8_t>& set,
            double seconds, nlohmann::json extra) {
  std::int64_t voxels = 0;
  for (auto x : set.values()) voxels += x != 0;
  const BettiNumbers b = betti_numbers(set, pair, a.threads);
  if (a.json) {
    nlohmann::json betti = nlohmann::json::array();
    for (int k = 0; k < pair.dim; ++k)
      betti.push_back(std::to_string(b.b[static_cast<std::size_t>(k)]));
    nlohmann::json j = {{"command", a.command},
                        {"input", a.in.path},
                        {"adjacency", pair.name()},
                        {"voxels", std::to_string(voxels)},
                        {"components", std::to_string(b.b[0])},
                        {"euler", std::to_string(b.euler)},
                        {"betti", betti},
                        {"seconds", seconds}};
    if (!a.output.empty()) j["output"] = a.output;
    for (auto& [k, v] : extra.items()) j[k] = v;
    print_json(j);
    return;
  }
  std::cout << "zdg topology " << a.command << " (" << pair.name() << "): " << voxels << " points, "
            << b.b[0] << " components, Betti";
  for (int k = 0; k < pair.dim; ++k) std::cout << ' ' << b.b[static_cast<std::size_t>(k)];
  std::cout << ", Euler " << b.euler;
  for (auto& [k, v] : extra.items()) {
    std::cout << ", " << k << ' ' << (v.is_string() ? v.get<std::string>() : v.dump());
  }
  if (!a.output.empty()) std::cout << " -> " << a.output;
  std::cout << " (" << seconds << " s)\n";
}

AdjacencyPair pair_of(const TopologyArgs& a, int dim) {
  return a.adjacency.empty() ? default_adjacency_pair(dim) : parse_adjacency_pair(a.adjacency, dim);
}

void run_components(const TopologyArgs& a) {
  std::string staging;
  auto out = plan_output(a, false, staging);
  const auto mask = read_object(a);
  const auto pair = pair_of(a, mask.dim());
  const auto t0 = std::chrono::steady_clock::now();
  ComponentOptions opt;
  opt.threads = a.threads;
  const Components c = connected_components(mask, pair.object, opt);
  const double secs = since(t0);
  if (out) {
    write_image(staging, a.output, mask.domain(),
                std::vector<std::uint64_t>(c.labels.values().begin(), c.labels.values().end()),
                DType::U32);
    out->commit();
  }
  nlohmann::json sizes = nlohmann::json::array();
  for (std::size_t k = 0; k < c.sizes.size() && k < 10; ++k)
    sizes.push_back(std::to_string(c.sizes[k]));
  report(a, pair, mask, secs, {{"largest_sizes", sizes}});
}

// zdg topology betti --generators -o cycles.ply: representative cycles of each Betti number
// (kernel/topology/homology_generators.hpp), written by kernel/io/cycles_ply.hpp.
void run_betti_generators(const TopologyArgs& a) {
  if (a.output.empty()) throw InvalidArgument("--generators writes the cycles to -o FILE.ply");
  if (lower_extension(a.output) != ".ply") {
    throw IoError(a.output + ": the cycles are a .ply file (got '" + lower_extension(a.output) +
                  "')");
  }
  check_not_input(a.in.path, a.output);
  OutputSet out(a.force ? Existing::replace : Existing::refuse);
  const std::string staging = out.add(a.output).string();
  const auto mask = load_object(a.in, 0, a.threads).mask;
  const auto pair = pair_of(a, mask.dim());
  if (!(pair == default_adjacency_pair(mask.dim()))) {
    throw InvalidArgument("--generators: the cycles are those of the union of the closed voxels "
                          "(--adjacency " +
                          std::string(mask.dim() == 3 ? "26,6" : "8,4") + "; got " + pair.name() +
                          ")");
  }
  const auto t0 = std::chrono::steady_clock::now();
  const HomologyGenerators g = homology_generators(mask);
  const double secs = since(t0);
  write_cycles_ply(staging, g, mask.domain().lowers());
  out.commit();
  nlohmann::json counts = nlohmann::json::array();
  for (const auto& gens : g.generators) counts.push_back(gens.size());
  report(a, pair, mask, secs, {{"generators", counts}});
}

void run_betti(const TopologyArgs& a) {
  if (a.generators) {
    run_betti_generators(a);
    return;
  }
  if (!a.output.empty()) throw InvalidArgument("topology betti writes no file (drop -o)");
  const auto mask = read_object(a);
  const auto pair = pair_of(a, mask.dim());
  const auto t0 = std::chrono::steady_clock::now();
  (void)betti_numbers(mask, pair, a.threads);
  report(a, pair, mask, since(t0), nlohmann::json::object());
}

void run_simple(const TopologyArgs& a) {
  std::string staging;
  auto out = plan_output(a, false, staging);
  const auto mask = read_object(a);
  const auto pair = pair_of(a, mask.dim());
  const auto t0 = std::chrono::steady_clock::now();
  std::int64_t count = 0;
  const Image<std::uint8_t> simple = simple_point_mask(mask, pair, &count);
  const double secs = since(t0);
  if (out) {
    write_image(staging, a.output, mask.domain(),
                std::vector<std::uint64_t>(simple.values().begin(), simple.values().end()),
                DType::U8);
    out->commit();
  }
  // The summary describes the object; "simple" counts its simple points (the output).
  report(a, pair, mask, secs, {{"simple", std::to_string(count)}});
}

void run_thin(const TopologyArgs& a, SkeletonKind default_kind) {
  std::string staging;
  auto out = plan_output(a, true, staging);
  const std::string html_staging = plan_html(a, *out);
  const auto mask = read_object(a);
  if (!a.html.empty() && mask.dim() != 3)
    throw InvalidArgument("--html shows 3D results (" + a.in.path + " is 2D)");
  ThinningOptions opt;
  opt.pair = pair_of(a, mask.dim());
  opt.skeleton = a.skeleton.empty() ? default_kind : parse_skeleton_kind(a.skeleton);
  opt.threads = a.threads;
  const bool critical = a.method == "critical-kernel";
  if (!critical && a.method != "sequential") {
    throw InvalidArgument("--method '" + a.method + "' is not sequential or critical-kernel");
  }
  if (critical && !(opt.pair.object == 26 || opt.pair.object == 8)) {
    throw InvalidArgument("--method critical-kernel needs --adjacency " +
                          std::string(mask.dim() == 3 ? "26,6" : "8,4") + " (got " +
                          opt.pair.name() + ")");
  }
  Image<std::int64_t> priority;
  if (a.priority != "dt") {
    if (critical) throw InvalidArgument("--priority is for --method sequential only");
    priority = read_integer_image(a.priority);
    if (!(priority.domain().extents() == mask.domain().extents())) {
      throw InvalidArgument("--priority " + a.priority + ": an image of another size than " +
                            a.in.path);
    }
    priority = Image<std::int64_t>(mask.domain(), std::move(priority.values()));
    opt.priority = &priority;
  }
  Image<std::uint8_t> anchors;
  if (!a.anchors.empty()) {
    const auto v = read_integer_image(a.anchors);
    if (!(v.domain().extents() == mask.domain().extents())) {
      throw InvalidArgument("--anchors " + a.anchors + ": an image of another size than " +
                            a.in.path);
    }
    anchors = Image<std::uint8_t>(mask.domain(), std::uint8_t{0});
    for (std::int64_t i = 0; i < v.size(); ++i) anchors[i] = v[i] != 0;
    opt.anchors = &anchors;
  }
  const bool progress = !a.quiet && isatty(2) != 0;
  if (progress) {
    opt.progress = [](const ThinningProgress& p) {
      std::fprintf(stderr, "\rzdg topology: %lld points left, %lld deleted, pass %lld   ",
                   static_cast<long long>(p.remaining), static_cast<long long>(p.deleted),
                   static_cast<long long>(p.passes));
      std::fflush(stderr);
    };
  }
  const auto t0 = std::chrono::steady_clock::now();
  const ThinningResult r =
      critical ? critical_kernel_thinning(mask, opt) : homotopic_thinning(mask, opt);
  const double secs = since(t0);
  if (progress) std::fprintf(stderr, "\n");
  write_image(staging, a.output, mask.domain(),
              std::vector<std::uint64_t>(r.skeleton.values().begin(), r.skeleton.values().end()),
              DType::U8);
  if (!html_staging.empty()) {
    // The boundary of the result's voxels: the primal surface, as zdg surface draws it.
    const ImageSurfels sf = image_surfels(r.skeleton, a.threads);
    const PolygonMesh m = primal_surface_mesh(r.skeleton, sf, SurfaceConvention::of(opt.pair),
                                              VoxelPlacement::lattice(sf.grid), a.threads);
    MeshHtmlOptions page;
    page.title = std::filesystem::path(a.in.path).filename().string() + " (" + a.command + ")";
    write_mesh_html(html_staging, m, page);
  }
  out->commit();
  report(a, opt.pair, r.skeleton, secs,
         {{"method", a.method},
          {"skeleton", skeleton_kind_name(opt.skeleton)},
          {"deleted", std::to_string(r.deleted)},
          {"passes", std::to_string(r.passes)}});
}

// zdg topology graph: the curve skeleton of the object (homotopic thinning, --skeleton curve),
// then its graph (kernel/topology/skeleton_graph.hpp) with the radius profiles of its branches
// from the object's squared distance transform.
void run_graph(const TopologyArgs& a) {
  if (!a.output.empty()) throw InvalidArgument("topology graph writes no file (drop -o)");
  const auto mask = read_object(a);
  ThinningOptions opt;
  opt.pair = pair_of(a, mask.dim());
  if (!(opt.pair == default_adjacency_pair(mask.dim()))) {
    throw InvalidArgument("topology graph joins skeleton points by " +
                          std::string(mask.dim() == 3 ? "26,6" : "8,4") +
                          " adjacency (got --adjacency " + opt.pair.name() + ")");
  }
  opt.skeleton = SkeletonKind::curve;
  opt.threads = a.threads;
  const bool critical = a.method == "critical-kernel";
  if (!critical && a.method != "sequential") {
    throw InvalidArgument("--method '" + a.method + "' is not sequential or critical-kernel");
  }
  const auto t0 = std::chrono::steady_clock::now();
  TransformOptions dto;
  dto.threads = a.threads;
  const auto dt = distance_transform<std::int64_t>(mask, dto);
  const ThinningResult r =
      critical ? critical_kernel_thinning(mask, opt) : homotopic_thinning(mask, opt);
  const SkeletonGraph g = skeleton_graph(r.skeleton, &dt);
  const double secs = since(t0);
  const Domain& dom = mask.domain();
  nlohmann::json nodes = nlohmann::json::array(), branches = nlohmann::json::array();
  std::int64_t junctions = 0, ends = 0;
  for (std::size_t k = 0; k < g.nodes.size(); ++k) {
    const auto& n = g.nodes[k];
    junctions += n.kind == SkeletonNodeKind::junction;
    ends += n.kind == SkeletonNodeKind::end;
    std::vector<double> centre(static_cast<std::size_t>(dom.dim()), 0.0);
    for (auto i : n.points) {
      const auto p = dom.point(i);
      for (std::size_t c = 0; c < p.size(); ++c) centre[c] += static_cast<double>(p[c]);
    }
    for (auto& c : centre) c /= static_cast<double>(n.points.size());
    nodes.push_back({{"id", k},
                     {"kind", skeleton_node_kind_name(n.kind)},
                     {"degree", n.degree},
                     {"loops", n.loops},
                     {"voxels", n.points.size()},
                     {"position", centre}});
  }
  double total = 0;
  for (std::size_t k = 0; k < g.branches.size(); ++k) {
    const auto& b = g.branches[k];
    total += b.length;
    std::vector<double> radii;
    for (auto s : b.squared_radii) radii.push_back(std::sqrt(static_cast<double>(s)));
    branches.push_back({{"id", k},
                        {"from", b.from},
                        {"to", b.to},
                        {"voxels", b.points.size()},
                        {"length", b.length},
                        {"radii", radii}});
  }
  if (a.json) {
    report(a, opt.pair, r.skeleton, secs,
           {{"method", a.method},
            {"junctions", junctions},
            {"ends", ends},
            {"loops", g.loops},
            {"total_length", total},
            {"nodes", nodes},
            {"branches", branches}});
    return;
  }
  report(a, opt.pair, r.skeleton, secs,
         {{"nodes", g.nodes.size()},
          {"junctions", junctions},
          {"ends", ends},
          {"branches", g.branches.size()},
          {"loops", g.loops},
          {"total_length", total}});
}

} // namespace

void add_topology_commands(CLI::App& app, Context& /*ctx*/) {
  auto* top = app.add_subcommand(
      "topology", "digital topology of 2D/3D binary images: components, Betti numbers, simple "
                  "points, thinning, skeletons");
  top->require_subcommand(1);
  struct Spec {
    const char* name;
    const char* help;
  };
  static const Spec specs[] = {
      {"components", "connected components: labels (uint32, 1 = largest) in -o, sizes"},
      {"betti", "Euler characteristic and Betti numbers b0 b1 (b2) of the object"},
      {"simple", "simple points of the object (uint8 mask in -o)"},
      {"thin", "homotopic thinning (default --skeleton ultimate): same topology, fewer points"},
      {"skeleton", "skeleton by homotopic thinning (default --skeleton curve)"},
      {"graph", "graph of the curve skeleton: junctions, ends, branches (lengths, radii), loops"},
  };
  for (const auto& s : specs) {
    auto args = std::make_shared<TopologyArgs>();
    args->command = s.name;
    auto* sub = top->add_subcommand(s.name, s.help);
    add_volume_input_options(*sub, args->in, {.selection = true, .spacing = false});
    sub->add_option("-o,--output", args->output, "output image (.npy, .vol, .pgm)");
    sub->add_option("--adjacency", args->adjacency,
                    "pair K,KBAR: 26,6 (default 3D), 6,26, 18,6, 6,18; 8,4 (default 2D), 4,8");
    sub->add_option("--threads", args->threads, "worker threads (0 = all cores)")
        ->capture_default_str();
    sub->add_flag("--json", args->json,
                  "print {\"voxels\",\"components\",\"betti\",\"seconds\",...} on stdout");
    sub->add_flag("--force", args->force, "replace an existing output file");
    sub->add_flag("--quiet", args->quiet, "no progress on stderr");
    const std::string name = s.name;
    if (name == "betti") {
      sub->add_flag("--generators", args->generators,
                    "write representative cycles of each Betti number to -o FILE.ply (26,6 / "
                    "8,4: the union of the closed voxels)");
    }
    if (name == "graph") {
      sub->add_option("--method", args->method,
                      "thinning: sequential or critical-kernel (parallel)")
          ->capture_default_str();
    }
    if (name == "thin" || name == "skeleton") {
      sub->add_option("--method", args->method, "sequential or critical-kernel (parallel)")
          ->capture_default_str();
      sub->add_option("--skeleton", args->skeleton, "ultimate, curve, surface or medial-axis");
      sub->add_option("--priority", args->priority,
                      "dt (squared distance to the background) or an image FILE of the same "
                      "size (smaller first; sequential only)")
          ->capture_default_str();
      sub->add_option("--anchors", args->anchors, "image FILE: nonzero points are never deleted");
      sub->add_option("--html", args->html,
                      "also write a viewer page (.html, 3D) of the result's voxels: their "
                      "boundary surface, to turn and pick in a browser");
    }
    sub->callback([args, name] {
      if (name == "components") run_components(*args);
      if (name == "betti") run_betti(*args);
      if (name == "simple") run_simple(*args);
      if (name == "thin") run_thin(*args, SkeletonKind::ultimate);
      if (name == "skeleton") run_thin(*args, SkeletonKind::curve);
      if (name == "graph") run_graph(*args);
    });
  }
  add_topology_persistence_command(*top);
}

} // namespace zdg::cli
