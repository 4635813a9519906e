// zdg mesh at: Ambrosio-Tortorelli on a triangle or polygon mesh read from a PLY
// (estimators/ambrosio_tortorelli_mesh.hpp: u per face, v per vertex; Coeurjolly, Foare,
// Gueth, Lachaud, CGF 2016): normal denoising, inpainting of a masked region, and the
// segmentation given by v.
//
//   zdg mesh at INPUT.ply -o OUT.ply [--alpha A] [--lambda L] [--epsilon E1,E2]
//               [--inpaint FIELD] [--threshold T] [--solver cg|cholesky] [--threads N]
//               [--json] [--force]
//
// The input normals g are the PLY's face normals (nx, ny, nz of the face element) when it has
// them, else the faces' own (their vector area, normalised). With --inpaint FIELD, the faces
// whose FIELD is nonzero get the data weight 0: their normals are filled from the others'.
// OUT.ply is the input mesh (its fields kept) with the face normals replaced by AT's and the
// per-face fields at-nx, at-ny, at-nz, at-v (the minimum of v over the face's vertices) and
// segment (the label of the face's segment, 0 = the largest).
// Defaults: alpha 0.05, lambda 0.05, eps 2 -> 0.25 (the per-face regime of raw face normals,
// measured in papers/at-normals/README.md; zdg surface's AT starts from the smoother II
// normals and keeps alpha 2, lambda 0.015).
// Bad input (not a .ply, a mesh that is empty or not a manifold, a missing field, parameters
// out of range): one line, exit 2, nothing written.
#include <zdg/arith/error.hpp>
#include <zdg/cli/commands.hpp>
#include <zdg/estimators/ambrosio_tortorelli_mesh.hpp>
#include <zdg/kernel/io/mesh_io.hpp>
#include <zdg/kernel/io/output_files.hpp>
#include <zdg/kernel/io/ply_read.hpp>

#include <fmt/core.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace zdg::cli {

namespace {

// The defaults of zdg mesh at: raw face normals are noisy at the scale of one face, so a
// smoothing length of 1 / sqrt(alpha) = 4.5 faces and a dearer discontinuity than on the II
// normals of a digital surface (papers/at-normals/README.md, "On triangle meshes").
ATParameters mesh_at_defaults() {
  ATParameters p;
  p.alpha = 0.05;
  p.lambda = 0.05;
  return p;
}

struct MeshAtArgs {
  std::string input, output, alpha, lambda, epsilon, inpaint, threshold, solver = "cg";
  unsigned threads = 0;
  bool force = false, json = false;
};

double parse_positive_real(const std::string& text, const std::string& option) {
  const double v = parse_number(text, option);
  if (!(v > 0)) throw InvalidArgument(option + " '" + text + "': a positive number is needed");
  return v;
}

void set_field(PolygonMesh& mesh, const std::string& name, std::vector<double> values) {
  for (auto& [n, v] : mesh.face_scalars)
    if (n == name) {
      v = std::move(values);
      return;
    }
  mesh.face_scalars.emplace_back(name, std::move(values));
}

void run_mesh_at(const MeshAtArgs& a) {
  using clock = std::chrono::steady_clock;
  // Options first: nothing is read when one is wrong.
  if (lower_extension(a.input) != ".ply")
    throw IoError(a.input + ": zdg mesh at reads a .ply mesh (got '" + lower_extension(a.input) +
                  "')");
  if (lower_extension(a.output) != ".ply")
    throw IoError(a.output + ": zdg mesh at writes a .ply mesh (got '" + lower_extension(a.output) +
                  "')");
  ATParameters p = mesh_at_defaults();
  if (!a.alpha.empty()) p.alpha = parse_positive_real(a.alpha, "--alpha");
  if (!a.lambda.empty()) p.lambda = parse_positive_real(a.lambda, "--lambda");
  if (!a.epsilon.empty()) {
    const auto comma = a.epsilon.find(',');
    if (comma == std::string::npos || a.epsilon.find(',', comma + 1) != std::string::npos)
      throw InvalidArgument("--epsilon '" + a.epsilon + "': expected E1,E2 (E1 >= E2 > 0)");
    p.epsilon1 = parse_positive_real(a.epsilon.substr(0, comma), "--epsilon");
    p.epsilon2 = parse_positive_real(a.epsilon.substr(comma + 1), "--epsilon");
    if (p.epsilon1 < p.epsilon2)
      throw InvalidArgument("--epsilon '" + a.epsilon + "': E1 must be at least E2");
  }
  ATMeshOptions o;
  o.threads = a.threads;
  if (!a.threshold.empty()) {
    o.threshold = parse_number(a.threshold, "--threshold");
    if (!(o.threshold >= 0 && o.threshold <= 1))
      throw InvalidArgument("--threshold '" + a.threshold + "': a number in [0, 1] is needed");
  }
  if (a.solver == "cg")
    o.solver = ATLinearSolver::conjugate_gradient;
  else if (a.solver == "cholesky")
    o.solver = ATLinearSolver::cholesky;
  else
    throw InvalidArgument("--solver '" + a.solver + "': expected cg or cholesky");
  check_not_input(a.input, a.output);
  OutputSet out(a.force ? Existing::replace : Existing::refuse);
  const auto staging = out.add(a.output); // checked before the input is read

  const auto t0 = clock::now();
  PlyMesh ply = read_ply(a.input);
  PolygonMesh& mesh = ply.mesh;
  if (mesh.face_count() == 0) throw InvalidArgument(a.input + ": the mesh has no faces");
  std::vector<double> weights;
  if (!a.inpaint.empty()) {
    const auto it = std::find_if(mesh.face_scalars.begin(), mesh.face_scalars.end(),
                                 [&](const auto& f) { return f.first == a.inpaint; });
    if (it == mesh.face_scalars.end()) {
      std::string names;
      for (const auto& f : mesh.face_scalars) names += (names.empty() ? "" : ", ") + f.first;
      throw InvalidArgument("--inpaint " + a.inpaint + ": " + a.input + " has no face field '" +
                            a.inpaint + "' (" + (names.empty() ? "none" : names) + ")");
    }
    weights.resize(it->second.size());
    for (std::size_t f = 0; f < weights.size(); ++f) weights[f] = it->second[f] != 0 ? 0.0 : 1.0;
  }
  const bool file_normals = !mesh.face_normals.empty();
  std::vector<Point3<double>> g = file_normals ? mesh.face_normals : mesh_face_normals(mesh);
  for (std::size_t f = 0; f < g.size(); ++f) {
    const double l = std::sqrt(dot(g[f], g[f]));
    if (!(l > 0) || !std::isfinite(l))
      throw InvalidArgument(a.input + ": the normal of face " + std::to_string(f) +
                            " is zero or not finite");
    g[f] = (1 / l) * g[f];
  }
  const ATMesh cx = at_mesh(mesh);
  const double read_s = std::chrono::duration<double>(clock::now() - t0).count();

  const auto t1 = clock::now();
  const ATMeshResult r = at_mesh_normals(cx, g, p, o, weights);
  const double at_s = std::chrono::duration<double>(clock::now() - t1).count();

  const auto t2 = clock::now();
  std::vector<double> nx(g.size()), ny(g.size()), nz(g.size()), seg(g.size());
  for (std::size_t f = 0; f < g.size(); ++f) {
    nx[f] = r.normals[f].x;
    ny[f] = r.normals[f].y;
    nz[f] = r.normals[f].z;
    seg[f] = static_cast<double>(r.segment[f]);
  }
  set_field(mesh, "at-nx", std::move(nx));
  set_field(mesh, "at-ny", std::move(ny));
  set_field(mesh, "at-nz", std::move(nz));
  set_field(mesh, "at-v", at_face_values(cx, r.v, ATSurfelPolicy::minimum));
  set_field(mesh, "segment", std::move(seg));
  mesh.face_normals = r.normals;
  write_mesh(staging.string(), mesh, MeshFormat::ply, a.threads);
  out.commit();
  const double write_s = std::chrono::duration<double>(clock::now() - t2).count();

  const auto [vlo, vhi] = std::minmax_element(r.v.begin(), r.v.end());
  std::int64_t inpainted = 0;
  for (const double w : weights) inpainted += w == 0 ? 1 : 0;
  if (a.json) {
    print_json({{"input",
                 {{"path", a.input},
                  {"vertices", mesh.vertex_count()},
                  {"faces", mesh.face_count()},
                  {"edges", cx.edge_count()},
                  {"triangulated", ply.triangulated},
                  {"normals", file_normals ? "file" : "faces"}}},
                {"output", {{"path", a.output}}},
                {"parameters",
                 {{"alpha", p.alpha},
                  {"lambda", p.lambda},
                  {"epsilon1", p.epsilon1},
                  {"epsilon2", p.epsilon2},
                  {"threshold", o.threshold},
                  {"unit", cx.unit}}},
                {"inpainted", inpainted},
                {"iterations", r.iterations},
                {"solver", r.solver},
                {"cg_iterations", r.cg_iterations},
                {"v", {{"min", *vlo}, {"max", *vhi}}},
                {"segments", r.segments},
                {"seconds", {{"read", read_s}, {"at", at_s}, {"write", write_s}}}});
  } else {
    fmt::print("{} -> {}: {} faces, {} iterations ({}), v in [{:.4g}, {:.4g}], {} segment{}{}\n",
               a.input, a.output, mesh.face_count(), r.iterations, r.solver, *vlo, *vhi, r.segments,
               r.segments == 1 ? "" : "s",
               inpainted > 0 ? ", " + std::to_string(inpainted) + " faces inpainted" : "");
  }
}

} // namespace

void add_mesh_commands(CLI::App& app, Context& /*ctx*/) {
  auto* mesh = app.add_subcommand("mesh", "estimators on a triangle or polygon mesh (.ply)");
  mesh->require_subcommand(1);
  auto a = std::make_shared<MeshAtArgs>();
  auto* cmd = mesh->add_subcommand(
      "at", "Ambrosio-Tortorelli piecewise-smooth face normals (u per face, v per vertex): "
            "normal denoising, inpainting of the faces of a field (--inpaint), and the "
            "segmentation given by v; writes the mesh with the fields at-nx, at-ny, at-nz, "
            "at-v, segment");
  cmd->add_option("INPUT", a->input,
                  "the mesh (.ply, a manifold; its face normals nx, ny, nz are the input when "
                  "present, else the faces' own)")
      ->required();
  cmd->add_option("-o,--output", a->output, "the mesh with AT's fields (.ply)")->required();
  cmd->add_option("--alpha", a->alpha,
                  fmt::format("data fidelity alpha > 0 per unit area (default {}; larger: "
                              "closer to the input normals)",
                              mesh_at_defaults().alpha));
  cmd->add_option("--lambda", a->lambda,
                  fmt::format("discontinuity cost lambda > 0 per unit length (default {}; "
                              "smaller: more edges)",
                              mesh_at_defaults().lambda));
  cmd->add_option("--epsilon", a->epsilon,
                  fmt::format("the first and last eps, E1,E2 (default {},{}; halved between "
                              "levels), in units of the mean edge length",
                              ATParameters{}.epsilon1, ATParameters{}.epsilon2));
  cmd->add_option("--inpaint", a->inpaint,
                  "a face field of the input: the faces where it is nonzero get no data term "
                  "(their normals are filled in from the others)");
  cmd->add_option("--threshold", a->threshold,
                  "segmentation: faces are joined across an edge unless v < T at both of its "
                  "ends (default 0.5)");
  cmd->add_option("--solver", a->solver,
                  "linear solver: cg (Jacobi-preconditioned conjugate gradients, default) or "
                  "cholesky (sparse factorization)");
  cmd->add_option("--threads", a->threads, "threads of the solver's products (default: all)");
  cmd->add_flag("--force", a->force, "replace an existing output");
  cmd->add_flag("--json", a->json, "print a JSON summary");
  cmd->callback([a] { run_mesh_at(*a); });
}

} // namespace zdg::cli
