// zdg dag INPUT [--h H] [--origin X,Y,Z] [--mode M] [--slab N] [--ray O,D[,DEN]] [--kind K]
//         [--max-hits N] [--threads N] [--json]
// zdg render dag INPUT -o OUT.png [--h H] [--origin X,Y,Z] [--mode M] [--slab N] [--kind K]
//         [--view AZ,EL] [--png-size WxH] [--threads N] [--force] [--json]
//
// Sparse voxel octrees and DAGs (kernel/images/voxel_dag.hpp) of a binary volume (any volume
// format, its object selected as by every command: --threshold, --range, --label, --invert) or
// of a mesh (.ply, .obj, .off) voxelized exactly at step --h (kernel/digitization/voxelize.hpp,
// --mode conservative by default) and streamed by slabs of --slab z-layers (default 64) into the
// builders, so that the dense volume never exists. `zdg dag` prints the node counts and bytes of
// the SVO, the DAG and the SSVDAG and, with --ray OX,OY,OZ,DX,DY,DZ[,DEN] (integers: the line
// (O + t D) / DEN in voxel coordinates x, y, z), the set voxels the line crosses in order (at
// most --max-hits, default 16) with the axis of the face each is entered by. `zdg render dag`
// ray-casts the --kind DAG (default ssvdag) into a PNG (kernel/render/dag_render.hpp).
// Bad input (an unknown kind or mode, --h with a volume or a mesh without --h, a malformed
// ray, the bounds of digital rays): one line, exit 2, nothing written.
#include <zdg/arith/error.hpp>
#include <zdg/arith/integer.hpp>
#include <zdg/cli/commands.hpp>
#include <zdg/cli/volume_input.hpp>
#include <zdg/kernel/digitization/voxelize.hpp>
#include <zdg/kernel/images/voxel_dag.hpp>
#include <zdg/kernel/io/mesh_read.hpp>
#include <zdg/kernel/io/output_files.hpp>
#include <zdg/kernel/render/dag_render.hpp>

#include <fmt/core.h>

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

namespace zdg::cli {

namespace {

struct DagArgs {
  VolumeInputArgs in;
  std::string h, origin, mode = "conservative", slab = "64", ray, kind = "ssvdag", max_hits = "16",
                         output, view, size;
  unsigned threads = 0;
  bool json = false, force = false;
};

bool is_mesh(const std::string& path) {
  const std::string e = lower_extension(path);
  return e == ".ply" || e == ".obj" || e == ".off";
}

DigitalRay parse_ray(const std::string& text) {
  const auto parts = split_commas(text);
  if (parts.size() != 6 && parts.size() != 7)
    throw InvalidArgument("--ray: '" + text + "' is not OX,OY,OZ,DX,DY,DZ[,DEN]");
  DigitalRay r;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    std::int64_t v = 0;
    try {
      v = parse_integer<std::int64_t>(parts[k]);
    } catch (const Error& e) {
      throw InvalidArgument(std::string("--ray: ") + e.what());
    }
    if (k < 3)
      r.origin[k] = v;
    else if (k < 6)
      r.direction[k - 3] = v;
    else
      r.denominator = v;
  }
  return r;
}

struct Scene {
  std::vector<VoxelDag> dags; // one per kind asked
  nlohmann::json input;
  double seconds = 0;
};

// Options and names checked before anything is read.
struct Plan {
  bool mesh = false;
  double h = 0;
  std::optional<Point3<double>> origin;
  VoxelizationMode mode = VoxelizationMode::conservative;
  std::int64_t slab = 64;
};

Plan make_plan(const DagArgs& a) {
  Plan p;
  p.mesh = is_mesh(a.in.path);
  if (!p.mesh) {
    if (!a.h.empty())
      throw InvalidArgument("--h " + a.h + ": the step of a mesh's voxelization ('" + a.in.path +
                            "' is read as a volume)");
    if (!a.origin.empty()) throw InvalidArgument("--origin: an option of a mesh's voxelization");
    return p;
  }
  if (has_selection(a.in))
    throw InvalidArgument(a.in.path + ": --threshold, --range, --label and --invert select the "
                                      "object of a volume, not of a mesh");
  if (a.h.empty()) throw InvalidArgument(a.in.path + ": a mesh needs the grid step --h");
  p.h = parse_number(a.h, "--h");
  if (!(p.h > 0)) throw InvalidArgument("--h: " + a.h + " is not positive");
  if (!a.origin.empty()) {
    const auto o = parse_xyz(a.origin, "--origin");
    p.origin = Point3<double>{o[0], o[1], o[2]};
  }
  try {
    p.mode = parse_voxelization_mode(a.mode);
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(std::string("--mode: ") + e.what());
  }
  p.slab = parse_integer<std::int64_t>(a.slab);
  if (p.slab < 4 || p.slab % 4 != 0)
    throw InvalidArgument("--slab: " + a.slab + " is not a positive multiple of 4");
  return p;
}

Scene build_scene(const DagArgs& a, const Plan& p, const std::vector<VoxelDagKind>& kinds) {
  const auto t0 = std::chrono::steady_clock::now();
  Scene s;
  if (p.mesh) {
    const PolygonMesh mesh = read_mesh(a.in.path);
    if (mesh.face_count() == 0) throw InvalidArgument(a.in.path + ": the mesh has no faces");
    VoxelizationGrid grid;
    try {
      grid = voxel_grid_for(mesh, p.h, p.origin, std::int64_t{1} << 40);
      std::vector<std::unique_ptr<VoxelDagBuilder>> b;
      for (auto k : kinds) b.push_back(std::make_unique<VoxelDagBuilder>(grid.extents, k));
      voxelize_by_slabs(
          mesh, grid, p.mode, p.slab,
          [&](std::int64_t, std::int64_t n, const std::uint8_t* data) {
            for (auto& x : b) x->add_slices(data, n);
          },
          a.threads);
      for (auto& x : b) s.dags.push_back(x->finish());
    } catch (const InvalidArgument& e) {
      throw InvalidArgument(a.in.path + ": " + e.what());
    }
    s.input = {{"path", a.in.path},
               {"format", "mesh"},
               {"faces", mesh.face_count()},
               {"h", p.h},
               {"mode", voxelization_mode_name(p.mode)},
               {"origin", {grid.origin.x, grid.origin.y, grid.origin.z}},
               {"slab", p.slab}};
  } else {
    const LoadedObject obj = load_object(a.in, 3, a.threads, !a.json);
    try {
      for (auto k : kinds) s.dags.push_back(build_voxel_dag(obj.mask, k));
    } catch (const InvalidArgument& e) {
      throw InvalidArgument(a.in.path + ": " + e.what());
    }
    s.input = obj.json;
  }
  s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return s;
}

nlohmann::json stats_json(const VoxelDagStats& s) {
  return {{"nodes", s.inner_nodes},
          {"leaves", s.leaves},
          {"pointers", s.pointers},
          {"bytes", s.bytes},
          {"bits_per_voxel", s.bits_per_voxel()},
          {"nodes_per_level", s.nodes_per_level}};
}

VoxelDagKind kind_option(const std::string& text) {
  try {
    return parse_voxel_dag_kind(text);
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(std::string("--kind: ") + e.what());
  }
}

void run_dag(const DagArgs& a) {
  const Plan p = make_plan(a);
  const VoxelDagKind kind = kind_option(a.kind);
  std::optional<DigitalRay> ray;
  if (!a.ray.empty()) ray = parse_ray(a.ray);
  const auto max_hits = parse_integer<std::int64_t>(a.max_hits);
  if (max_hits < 0) throw InvalidArgument("--max-hits: " + a.max_hits + " is negative");
  const Scene s = build_scene(a, p, {VoxelDagKind::dag, VoxelDagKind::ssvdag});
  const VoxelDagStats d = s.dags[0].stats(), ss = s.dags[1].stats();
  VoxelDagStats svo = d; // the tree's figures, counted by the DAG's build
  svo.kind = VoxelDagKind::svo;
  svo.inner_nodes = d.svo_inner_nodes;
  svo.leaves = d.svo_leaves;
  svo.pointers = d.svo_pointers;
  svo.bytes = d.svo_bytes;
  const auto& e = s.dags[0].extent();
  nlohmann::json j = {{"command", "dag"},
                      {"input", s.input},
                      {"extent", {e[0], e[1], e[2]}},
                      {"depth", d.depth},
                      {"voxels", std::to_string(d.voxels)},
                      {"svo", stats_json(svo)},
                      {"dag", stats_json(d)},
                      {"ssvdag", stats_json(ss)},
                      {"seconds", s.seconds}};
  j["svo"].erase("nodes_per_level");
  std::vector<DagRayHit> hits;
  if (ray) {
    const VoxelDag& g = s.dags[kind == VoxelDagKind::ssvdag ? 1 : 0];
    // The SVO answers as the DAG does (the same tree); it is not built a third time.
    hits = g.ray_hits(*ray, static_cast<std::size_t>(max_hits));
    nlohmann::json h = nlohmann::json::array();
    for (const auto& x : hits)
      h.push_back({{"voxel", {x.voxel[0], x.voxel[1], x.voxel[2]}}, {"axis", x.axis}});
    j["ray"] = {{"origin", {ray->origin[0], ray->origin[1], ray->origin[2]}},
                {"direction", {ray->direction[0], ray->direction[1], ray->direction[2]}},
                {"denominator", ray->denominator},
                {"kind", voxel_dag_kind_name(kind)},
                {"hits", h}};
  }
  if (a.json) {
    print_json(j);
    return;
  }
  fmt::print("{}: {} voxels in {} x {} x {} (depth {})\n", a.in.path, d.voxels, e[0], e[1], e[2],
             d.depth);
  for (const VoxelDagStats* x : std::initializer_list<const VoxelDagStats*>{&svo, &d, &ss})
    fmt::print("  {:6} {:>12} nodes {:>12} leaves {:>14} bytes {:10.4f} bits/voxel\n",
               voxel_dag_kind_name(x->kind), x->inner_nodes, x->leaves, x->bytes,
               x->bits_per_voxel());
  if (ray) {
    fmt::print("  ray: {} hit(s)", hits.size());
    for (const auto& x : hits) fmt::print(" ({},{},{})", x.voxel[0], x.voxel[1], x.voxel[2]);
    fmt::print("\n");
  }
}

void run_render_dag(const DagArgs& a) {
  const auto t0 = std::chrono::steady_clock::now();
  const Plan p = make_plan(a);
  const VoxelDagKind kind = kind_option(a.kind);
  VolumeRenderOptions o;
  o.threads = a.threads;
  if (!a.view.empty()) std::tie(o.azimuth, o.elevation) = parse_view(a.view);
  if (!a.size.empty()) std::tie(o.width, o.height) = parse_picture_size(a.size);
  o.validate();
  if (lower_extension(a.output) != ".png")
    throw IoError(a.output + ": the picture is a .png file (got '" + lower_extension(a.output) +
                  "')");
  check_not_input(a.in.path, a.output);
  OutputSet out(a.force ? Existing::replace : Existing::refuse);
  const auto staging = out.add(a.output);
  const Scene s = build_scene(a, p, {kind});
  const auto t1 = std::chrono::steady_clock::now();
  const DagRendering r = render_dag(s.dags[0], o);
  const double render_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  write_png(staging.string(), r.picture);
  out.commit();
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const VoxelDagStats st = s.dags[0].stats();
  const auto& e = s.dags[0].extent();
  if (a.json) {
    print_json({{"command", "render dag"},
                {"input", s.input},
                {"output", a.output},
                {"kind", voxel_dag_kind_name(kind)},
                {"extent", {e[0], e[1], e[2]}},
                {"voxels", std::to_string(st.voxels)},
                {"bytes", st.bytes},
                {"bits_per_voxel", st.bits_per_voxel()},
                {"view", {o.azimuth, o.elevation}},
                {"size", {o.width, o.height}},
                {"rays", r.rays},
                {"hits", r.hits},
                {"seconds", {{"build", s.seconds}, {"render", render_seconds}, {"total", total}}}});
    return;
  }
  fmt::print("{} -> {}: {} of {} voxels ({} x {} pixels, view {},{}), {} of {} rays hit\n",
             a.in.path, a.output, voxel_dag_kind_name(kind), st.voxels, o.width, o.height,
             o.azimuth, o.elevation, r.hits, r.rays);
}

void add_scene_options(CLI::App& cmd, DagArgs& a) {
  add_volume_input_options(cmd, a.in, VolumeOptionSet{true, false});
  cmd.add_option("--h", a.h, "grid step of a mesh's voxelization (INPUT .ply, .obj, .off)");
  cmd.add_option("--origin", a.origin, "grid origin X,Y,Z of a mesh's voxelization");
  cmd.add_option("--mode", a.mode, "voxelization: conservative (default), 6, 26 or solid");
  cmd.add_option("--slab", a.slab, "z-layers voxelized at a time (a multiple of 4; default 64)");
  cmd.add_option("--threads", a.threads, "threads (default: all cores)");
  cmd.add_flag("--json", a.json, "print a JSON summary");
}

} // namespace

void add_dag_commands(CLI::App& app, Context& /*ctx*/) {
  auto a = std::make_shared<DagArgs>();
  auto* cmd = app.add_subcommand(
      "dag", "sparse voxel octree, DAG and symmetry-aware DAG of a volume or a voxelized mesh: "
             "sizes, and the exact ray queries");
  add_scene_options(*cmd, *a);
  cmd->add_option("--ray", a->ray, "a line OX,OY,OZ,DX,DY,DZ[,DEN]: its set voxels in order");
  cmd->add_option("--kind", a->kind, "the structure the ray queries: svo, dag or ssvdag (default)");
  cmd->add_option("--max-hits", a->max_hits, "at most this many hits (default 16)");
  cmd->callback([a] { run_dag(*a); });

  auto r = std::make_shared<DagArgs>();
  auto* render = app.get_subcommand("render");
  auto* rc = render->add_subcommand(
      "dag", "ray casting of a sparse voxel DAG (exact first hits), as a PNG");
  add_scene_options(*rc, *r);
  rc->add_option("-o,--output", r->output, "the picture (.png)")->required();
  rc->add_option("--kind", r->kind, "svo, dag or ssvdag (default)");
  rc->add_option("--view", r->view, "azimuth,elevation in degrees (default -60,30)");
  rc->add_option("--png-size", r->size, "picture size WIDTHxHEIGHT (default 800x800)");
  rc->add_flag("--force", r->force, "replace an existing output");
  rc->callback([r] { run_render_dag(*r); });
}

} // namespace zdg::cli
