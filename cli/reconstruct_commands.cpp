// zdg reconstruct: a surface from a point cloud (operations/reconstruct_operations.hpp).
//
//   zdg reconstruct POINTS --method hoppe|winding|poisson|rbf|imls --h H -o MESH
//                   [--html PAGE] [--k K] [--normals-k K] [--beta B] [--exact]
//                   [--rbf-centers M] [--rbf-offset E] [--imls-radius R] [--margin M]
//                   [--threads T] [--force] [--json] [--quiet]
//
// POINTS: .ply, .xyz, .off, .npy (kernel/io/point_cloud_io.hpp), with normals or without
// (then PCA normals oriented over the MST are estimated). MESH: .ply, .obj or .off, the
// marching-cubes mesh of the digitization of the field's negative set. Outputs are checked
// before the input is read and written atomically; an existing one is replaced only with
// --force. Bad input: one line, exit 2, nothing written.
#include <zdg/arith/error.hpp>
#include <zdg/cli/commands.hpp>
#include <zdg/kernel/io/mesh_io.hpp>
#include <zdg/kernel/io/output_files.hpp>
#include <zdg/kernel/io/point_cloud_io.hpp>
#include <zdg/kernel/render/mesh_html.hpp>
#include <zdg/operations/reconstruct_operations.hpp>

#include <fmt/core.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <string>

namespace zdg::cli {

namespace {

struct ReconstructArgs {
  std::string input, output, html, method = "hoppe";
  double h = 0;
  std::size_t k = 10, normals_k = 10, rbf_centers = 1000;
  double beta = 2, rbf_offset = 0, imls_radius = 0;
  int margin = 3;
  std::int64_t max_faces = 2'000'000;
  bool exact = false;
  unsigned threads = 0;
  bool force = false, json = false, quiet = false;
};

void run_reconstruct(const ReconstructArgs& a) {
  ReconstructOptions o;
  o.method.method = reconstruction_method_of(a.method);
  o.method.k = a.k;
  o.method.winding_beta = a.beta;
  o.method.winding_exact = a.exact;
  o.method.rbf_centers = a.rbf_centers;
  o.method.rbf_offset = a.rbf_offset;
  o.method.imls_radius = a.imls_radius;
  o.method.threads = a.threads;
  o.h = a.h;
  o.margin = a.margin;
  o.normals_k = a.normals_k;
  o.source = a.input;
  if (!(a.h > 0) || !std::isfinite(a.h))
    throw InvalidArgument("--h " + fmt::format("{}", a.h) + ": the grid step must be > 0");
  if (a.margin < 0 || a.margin > 1000)
    throw InvalidArgument("--margin " + std::to_string(a.margin) + ": must be in [0, 1000]");
  (void)point_cloud_format_of(a.input);
  const MeshFormat format = mesh_format_of(a.output);
  check_not_input(a.input, a.output);
  if (!a.html.empty()) check_not_input(a.input, a.html);
  OutputSet out(a.force ? Existing::replace : Existing::refuse);
  const std::string mesh_staging = out.add(a.output).string();
  const std::string html_staging = a.html.empty() ? "" : out.add(a.html).string();

  if (!a.quiet && ::isatty(2) == 1) {
    o.progress = [](const ProgressEvent& e) {
      if (!e.done)
        fmt::print(stderr, "zdg: {} ...\n", e.what);
      else
        fmt::print(stderr, "zdg: {} done{}{} ({:.2f} s)\n", e.what, e.detail.empty() ? "" : ": ",
                   e.detail, e.seconds);
    };
  }
  OperationProgress steps(o.progress);
  steps.start("reading " + a.input);
  PointCloud cloud = read_point_cloud(a.input);
  steps.done("read", std::to_string(cloud.size()) + " points");
  ReconstructResult r = reconstruct_operation(std::move(cloud), o);
  const PolygonMesh& mesh = r.reconstruction.mesh;
  if (!a.html.empty() && mesh.face_count() > a.max_faces)
    throw InvalidArgument("--html: the mesh has " + std::to_string(mesh.face_count()) +
                          " faces, more than --max-faces " + std::to_string(a.max_faces));
  steps.start("writing " + a.output);
  write_mesh(mesh_staging, mesh, format, a.threads);
  if (!a.html.empty()) {
    MeshHtmlOptions page;
    page.title = std::filesystem::path(a.input).filename().string() + " (" + a.method + ")";
    page.max_faces = a.max_faces;
    page.note = "reconstruction by " + a.method + " at h = " + fmt::format("{}", a.h);
    write_mesh_html(html_staging, mesh, page);
  }
  out.commit();
  steps.done("write");
  nlohmann::json j = to_json(r);
  for (const auto& [key, v] : steps.seconds) j["seconds"][key] = v;
  for (const auto& [key, v] : steps.cpu_seconds) j["cpu_seconds"][key] = v;
  j["output"] = a.output;
  if (!a.html.empty()) j["html"] = a.html;
  if (a.json) {
    print_json(j);
    return;
  }
  const auto& b = r.reconstruction.betti;
  fmt::print("{} -> {}: {} points ({} normals), {} at h = {}: {} samples inside, Betti numbers "
             "({}, {}, {}), {} faces\n",
             a.input, a.output, r.points, r.normals_estimated ? "estimated" : "given", a.method,
             a.h, r.reconstruction.inside_count, b.b[0], b.b[1], b.b[2], mesh.face_count());
}

} // namespace

void add_reconstruct_commands(CLI::App& app, Context& /*ctx*/) {
  auto a = std::make_shared<ReconstructArgs>();
  auto* cmd = app.add_subcommand(
      "reconstruct", "a surface from a point cloud: an implicit field on the grid of step h "
                     "(Hoppe, winding numbers, Poisson, RBF, IMLS), the digitization of its "
                     "inside with its Betti numbers, and its marching-cubes mesh");
  cmd->add_option("POINTS", a->input,
                  "the point cloud (.ply, .xyz, .off, .npy), with normals (else PCA normals "
                  "oriented over the MST are estimated)")
      ->required();
  cmd->add_option("--method", a->method,
                  "hoppe (signed distance to the tangent planes, default), winding "
                  "(generalized winding numbers), poisson (CGAL), rbf (triharmonic), imls");
  cmd->add_option("--h", a->h, "grid step, in the points' units")->required();
  cmd->add_option("-o,--output", a->output, "the mesh (.ply, .obj, .off)")->required();
  cmd->add_option("--k", a->k,
                  "neighbours: hoppe's plane centres, the winding areas, imls's default radius "
                  "(default 10)");
  cmd->add_option("--normals-k", a->normals_k,
                  "neighbours of the PCA normals when the points have none (default 10)");
  cmd->add_option("--beta", a->beta,
                  "winding: the tree's accuracy, expansions used beyond beta times a cluster's "
                  "radius (default 2)");
  cmd->add_flag("--exact", a->exact, "winding: the brute-force sum instead of the tree");
  cmd->add_option("--rbf-centers", a->rbf_centers,
                  "rbf: at most this many points as centres (default 1000)");
  cmd->add_option("--rbf-offset", a->rbf_offset,
                  "rbf: off-surface offset (default: 1/100 of the box diagonal)");
  cmd->add_option("--imls-radius", a->imls_radius,
                  "imls: the Gaussian's radius rho (default: the median distance to the k-th "
                  "nearest point)");
  cmd->add_option("--margin", a->margin,
                  "grid samples added around the points' box on each side (default 3)");
  cmd->add_option("--html", a->html, "write a self-contained viewer page of the mesh");
  cmd->add_option("--max-faces", a->max_faces,
                  "the most faces the viewer page holds (default 2000000)");
  cmd->add_option("--threads", a->threads, "threads (default: all cores)");
  cmd->add_flag("--force", a->force, "replace existing outputs");
  cmd->add_flag("--json", a->json, "print a JSON summary");
  cmd->add_flag("--quiet", a->quiet, "no progress lines");
  cmd->callback([a] { run_reconstruct(*a); });
}

} // namespace zdg::cli
