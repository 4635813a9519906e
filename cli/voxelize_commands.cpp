// zdg voxelize MESH --h H [--origin X,Y,Z] [--mode 6|26|conservative|solid] [--winding T] -o OUT
//              [--max-voxels N] [--threads N] [--json] [--force]
//
// The exact voxelization of a triangle or polygon mesh (kernel/digitization/voxelize.hpp) on
// the grid of step H whose voxel (i, j, k) is the cube origin + H [i, i+1] x [j, j+1] x [k, k+1]
// (default origin: a margin of two voxels below the mesh's bounding box), written as a uint8 0/1
// volume (.npy, .vol, .nii, .nii.gz, .vdb; NIfTI and OpenVDB with spacing H and the first
// voxel's centre as their origin) through an OutputSet. The mesh is read from a .ply, .obj or
// .off (kernel/io/mesh_read.hpp). --winding T (solid only) takes the centres whose
// generalized winding number is >= T instead of the exact parity, for meshes that are not closed.
// Bad input (a mesh with a non-finite coordinate, a face using a vertex twice or out of range,
// no faces, a grid of more than --max-voxels voxels, a non-closed mesh in solid mode, a bad
// number): one line, exit 2, nothing written.
#include <zdg/arith/error.hpp>
#include <zdg/cli/commands.hpp>
#include <zdg/kernel/digitization/voxelize.hpp>
#include <zdg/kernel/images/scalar_volume.hpp>
#include <zdg/kernel/io/mesh_read.hpp>
#include <zdg/kernel/io/output_files.hpp>
#include <zdg/kernel/io/volume_io.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>

#include <charconv>
#include <chrono>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

namespace zdg::cli {

namespace {

struct VoxelizeArgs {
  std::string input, output, h, origin, winding, mode = "conservative", max_voxels = "4294967296";
  unsigned threads = 0;
  bool json = false, force = false;
};

std::string shortest(double v) {
  char b[32];
  const auto r = std::to_chars(b, b + sizeof b, v);
  return std::string(b, r.ptr);
}

void run(const VoxelizeArgs& a) {
  const VolumeFormat format = volume_format_of(a.output);
  if (format == VolumeFormat::pgm || format == VolumeFormat::raw)
    throw IoError(a.output + ": a voxelization is written as .npy, .vol, .nii, .nii.gz or .vdb");
  const double h = parse_number(a.h, "--h");
  if (!(h > 0)) throw InvalidArgument("--h: " + a.h + " is not positive");
  std::optional<Point3<double>> origin;
  if (!a.origin.empty()) {
    const auto o = parse_xyz(a.origin, "--origin");
    origin = Point3<double>{o[0], o[1], o[2]};
  }
  VoxelizationMode mode = VoxelizationMode::conservative;
  try {
    mode = parse_voxelization_mode(a.mode);
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(std::string("--mode: ") + e.what());
  }
  const double max_voxels_value = parse_number(a.max_voxels, "--max-voxels");
  if (!(max_voxels_value >= 1 && max_voxels_value <= 0x1p62))
    throw InvalidArgument("--max-voxels: " + a.max_voxels + " is not in 1 .. 2^62");
  const auto max_voxels = static_cast<std::int64_t>(max_voxels_value);
  std::optional<double> winding;
  if (!a.winding.empty()) {
    if (mode != VoxelizationMode::solid)
      throw InvalidArgument("--winding " + a.winding + ": a threshold of the solid (--mode solid)");
    winding = parse_number(a.winding, "--winding");
  }
  const std::string in_ext = lower_extension(a.input);
  if (in_ext != ".ply" && in_ext != ".obj" && in_ext != ".off")
    throw IoError(a.input + ": zdg voxelize reads a .ply, .obj or .off mesh (got '" + in_ext +
                  "')");
  check_not_input(a.input, a.output);
  OutputSet out(a.force ? Existing::replace : Existing::refuse);
  const std::string staged = out.add(a.output).string();
  const auto t0 = std::chrono::steady_clock::now();
  const PolygonMesh mesh = read_mesh(a.input);
  if (mesh.face_count() == 0) throw InvalidArgument(a.input + ": the mesh has no faces");
  VoxelizationGrid grid;
  try {
    grid = voxel_grid_for(mesh, h, origin, max_voxels);
    if (mode == VoxelizationMode::solid && !winding) check_closed_mesh(mesh);
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(a.input + ": " + e.what());
  }
  Image<std::uint8_t> vox;
  try {
    vox = winding ? voxelize_winding(mesh, grid, *winding, a.threads)
                  : voxelize(mesh, grid, mode, a.threads);
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(a.input + ": " + e.what());
  }
  std::int64_t count = 0;
  for (auto x : vox.values()) count += x;
  ScalarVolume vol = make_scalar_volume(vox);
  vol.spacing = {h, h, h};
  vol.origin = {grid.origin.z + h / 2, grid.origin.y + h / 2, grid.origin.x + h / 2};
  VolumeWriteOptions wo;
  wo.format = format;
  write_volume(staged, vol, wo);
  out.commit();
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto& e = grid.extents;
  if (a.json) {
    print_json(
        {{"command", "voxelize"},
         {"input", a.input},
         {"output", a.output},
         {"mode", voxelization_mode_name(mode)},
         {"h", h},
         {"h_text", shortest(h)},
         {"origin", {shortest(grid.origin.x), shortest(grid.origin.y), shortest(grid.origin.z)}},
         {"dims", {e[0], e[1], e[2]}},
         {"shape", {e[2], e[1], e[0]}},
         {"faces", mesh.face_count()},
         {"voxels", std::to_string(count)},
         {"winding", winding ? nlohmann::json(*winding) : nlohmann::json(nullptr)},
         {"threads", worker_count(a.threads, e[2])},
         {"seconds", secs}});
    return;
  }
  std::cout << "zdg voxelize: " << count << " voxels (" << voxelization_mode_name(mode) << ") of "
            << e[0] << " x " << e[1] << " x " << e[2] << ", h = " << shortest(h) << ", origin "
            << shortest(grid.origin.x) << "," << shortest(grid.origin.y) << ","
            << shortest(grid.origin.z) << " -> " << a.output << " (" << secs << " s)\n";
}

} // namespace

void add_voxelize_commands(CLI::App& app, Context& /*ctx*/) {
  auto args = std::make_shared<VoxelizeArgs>();
  auto* cmd = app.add_subcommand(
      "voxelize", "Exact voxelization of a triangle mesh: surface (6, 26, conservative) or solid");
  cmd->add_option("MESH", args->input, "input mesh (.ply, .obj, .off)")->required();
  cmd->add_option("--h", args->h, "grid step (voxel edge), a positive number")->required();
  cmd->add_option("--origin", args->origin,
                  "X,Y,Z: the corner of voxel (0, 0, 0) (default: two voxels below the mesh)");
  cmd->add_option("--mode", args->mode,
                  "6 (6-separating, Huang et al.), 26 (26-separating), conservative (every voxel "
                  "the surface touches), solid (centres inside a closed mesh)")
      ->capture_default_str();
  cmd->add_option("--winding", args->winding,
                  "T: solid of a mesh that need not be closed, the centres whose generalized "
                  "winding number is >= T (floating point; O(faces x voxels), bounded)");
  cmd->add_option("-o,--output", args->output,
                  "output volume, uint8 0/1 (.npy, .vol, .nii, .nii.gz)")
      ->required();
  cmd->add_option("--max-voxels", args->max_voxels, "refuse grids of more voxels")
      ->capture_default_str();
  cmd->add_option("--threads", args->threads, "worker threads, 0..1024 (0 = all cores)")
      ->check(CLI::Range(0u, 1024u))
      ->capture_default_str();
  cmd->add_flag("--force", args->force, "replace the output file if it exists");
  cmd->add_flag("--json", args->json, "print a JSON summary on stdout");
  cmd->callback([args] { run(*args); });
}

} // namespace zdg::cli
