// zdg normals: normals of a point cloud from its k nearest neighbours
// (estimators/point_normals.hpp: PCA, Hoppe et al. SIGGRAPH 1992, or the osculating jet),
// oriented over the minimum spanning tree of the Riemannian graph.
//
//   zdg normals POINTS -o OUT [--k K] [--method pca|jet] [--orient mst|none] [--threads T]
//               [--force] [--json]
//
// POINTS: .ply (a PLY without faces, or a mesh's vertices), .xyz, .off, .npy
// (kernel/io/point_cloud_io.hpp; normals in the input are replaced). OUT: .ply, .xyz or .npy,
// the points with their unit normals. Bad input (an unknown extension, an empty cloud, a
// coordinate that is not finite, a point given twice, k < 3 or k > N - 1, an existing output
// without --force): one line, exit 2, nothing written.
#include <zdg/arith/error.hpp>
#include <zdg/cli/commands.hpp>
#include <zdg/estimators/point_normals.hpp>
#include <zdg/kernel/io/output_files.hpp>
#include <zdg/kernel/io/point_cloud_io.hpp>

#include <fmt/core.h>

#include <chrono>
#include <memory>
#include <string>

namespace zdg::cli {

namespace {

struct NormalsArgs {
  std::string input, output, method = "pca", orient = "mst";
  std::size_t k = 10;
  unsigned threads = 0;
  bool force = false, json = false;
};

void run_normals(const NormalsArgs& a) {
  const auto t0 = std::chrono::steady_clock::now();
  // Options and file names first: nothing is read when one is wrong.
  PointNormalsOptions o;
  o.k = a.k;
  o.method = point_normal_method_from_name(a.method);
  o.orientation = point_normal_orientation_from_name(a.orient);
  o.threads = a.threads;
  (void)point_cloud_format_of(a.input);
  const PointCloudFormat out_format = point_cloud_format_of(a.output);
  if (out_format == PointCloudFormat::off)
    throw IoError(a.output + ": zdg normals writes .ply, .xyz or .npy (not .off)");
  check_not_input(a.input, a.output);
  OutputSet out(a.force ? Existing::replace : Existing::refuse);
  const auto staging = out.add(a.output); // checked before the input is read

  PointCloud cloud = read_point_cloud(a.input);
  const PointNormals r = point_normals(cloud, o, a.input);
  cloud.normals = r.normals;
  write_point_cloud(staging.string(), cloud, out_format);
  out.commit();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (a.json) {
    print_json({{"points", cloud.size()},
                {"k", o.k},
                {"method", point_normal_method_name(o.method)},
                {"oriented", r.oriented},
                {"components", r.components},
                {"seconds", seconds}});
  } else {
    fmt::print("{} -> {}: {} points, k = {}, {} normals, {}\n", a.input, a.output, cloud.size(),
               o.k, point_normal_method_name(o.method),
               r.oriented ? fmt::format("oriented over the MST ({} component{})", r.components,
                                        r.components == 1 ? "" : "s")
                          : std::string("not oriented"));
  }
}

} // namespace

void add_points_commands(CLI::App& app, Context& /*ctx*/) {
  auto a = std::make_shared<NormalsArgs>();
  auto* cmd = app.add_subcommand(
      "normals", "normals of a point cloud from its k nearest neighbours (PCA or jet), oriented "
                 "over the minimum spanning tree of the Riemannian graph");
  cmd->add_option("POINTS", a->input, "the point cloud (.ply, .xyz, .off, .npy)")->required();
  cmd->add_option("-o,--output", a->output, "the points with their normals (.ply, .xyz, .npy)")
      ->required();
  cmd->add_option("--k", a->k,
                  "neighbours of each point, itself not counted (default 10; "
                  "3 <= k <= N - 1, k >= 5 for jet)");
  cmd->add_option("--method", a->method,
                  "pca (smallest eigenvector of the neighbours' covariance, default) or jet "
                  "(osculating quadric)");
  cmd->add_option("--orient", a->orient,
                  "mst (propagation over the Riemannian graph's minimum spanning tree, default) "
                  "or none (each normal in the half-space z > 0)");
  cmd->add_option("--threads", a->threads, "threads (default: all cores)");
  cmd->add_flag("--force", a->force, "replace an existing output");
  cmd->add_flag("--json", a->json, "print a JSON summary");
  cmd->callback([a] { run_normals(*a); });
}

} // namespace zdg::cli
