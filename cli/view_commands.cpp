// zdg view INPUT.ply -o OUT.html: the viewer page (kernel/render/mesh_html.hpp) of a mesh file,
// such as the PLY that `zdg surface` writes with its per-face estimates (kernel/io/ply_read.hpp
// says what is read). Every per-face scalar is a field of the page; a per-vertex scalar becomes
// the per-face field "NAME (vertex mean)" (the mean of its values at the face's vertices).
// Faces of several sizes are split into triangles (said on the output line and in the JSON).
// Past --max-faces the command refuses with one line, before writing anything.
//
//   zdg view ball.ply -o ball.html [--field ii-mean] [--title T] [--max-faces N] [--force]
#include <zdg/arith/error.hpp>
#include <zdg/cli/commands.hpp>
#include <zdg/kernel/io/output_files.hpp>
#include <zdg/kernel/io/ply_read.hpp>
#include <zdg/kernel/render/mesh_html.hpp>

#include <fmt/core.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <string>

namespace zdg::cli {

namespace {

struct ViewArgs {
  std::string input, output, field, title;
  std::int64_t max_faces = 2'000'000;
  bool force = false, json = false;
};

void run_view(const ViewArgs& a) {
  namespace fs = std::filesystem;
  using clock = std::chrono::steady_clock;
  if (lower_extension(a.input) != ".ply")
    throw IoError(a.input + ": zdg view reads a .ply mesh (got '" + lower_extension(a.input) +
                  "')");
  if (lower_extension(a.output) != ".html")
    throw IoError(a.output + ": the viewer is an .html file (got '" + lower_extension(a.output) +
                  "')");
  if (a.max_faces < 1) throw InvalidArgument("--max-faces must be at least 1");
  check_not_input(a.input, a.output);
  OutputSet out(a.force ? Existing::replace : Existing::refuse);
  const fs::path staging = out.add(a.output); // checked before the input is read
  const auto t0 = clock::now();
  PlyMesh ply = read_ply(a.input);
  PolygonMesh& mesh = ply.mesh;
  // Each per-vertex scalar as the mean over the face's vertices.
  const auto fs_ = static_cast<std::size_t>(mesh.face_size);
  for (const auto& [name, values] : ply.vertex_scalars) {
    std::vector<double> mean(static_cast<std::size_t>(mesh.face_count()));
    for (std::size_t f = 0; f < mean.size(); ++f) {
      double s = 0;
      for (std::size_t k = 0; k < fs_; ++k)
        s += values[static_cast<std::size_t>(mesh.indices[f * fs_ + k])];
      mean[f] = s / static_cast<double>(fs_);
    }
    mesh.face_scalars.emplace_back(name + " (vertex mean)", std::move(mean));
  }
  const double read_s = std::chrono::duration<double>(clock::now() - t0).count();
  MeshHtmlOptions page;
  page.title = a.title.empty() ? fs::path(a.input).filename().string() : a.title;
  page.field = a.field;
  page.max_faces = a.max_faces;
  const auto t1 = clock::now();
  write_mesh_html(staging.string(), mesh, page);
  out.commit();
  const double write_s = std::chrono::duration<double>(clock::now() - t1).count();
  std::error_code ec;
  const auto bytes = fs::file_size(a.output, ec);
  if (a.json) {
    nlohmann::json fields = nlohmann::json::array();
    for (const auto& f : mesh.face_scalars) fields.push_back(f.first);
    print_json({{"input",
                 {{"path", a.input},
                  {"format", ply.format},
                  {"vertices", mesh.vertex_count()},
                  {"faces", ply.file_faces},
                  {"triangulated", ply.triangulated},
                  {"ignored", ply.other}}},
                {"output", {{"path", a.output}, {"faces", mesh.face_count()}, {"bytes", bytes}}},
                {"fields", fields},
                {"seconds", {{"read", read_s}, {"write", write_s}}}});
  } else {
    fmt::print("{} -> {} ({} faces{}, {} field{}, {} bytes)\n", a.input, a.output,
               mesh.face_count(),
               ply.triangulated ? " after splitting " + std::to_string(ply.file_faces) +
                                      " faces of several sizes into triangles"
                                : "",
               mesh.face_scalars.size(), mesh.face_scalars.size() == 1 ? "" : "s", bytes);
  }
}

} // namespace

void add_view_commands(CLI::App& app, Context& /*ctx*/) {
  auto a = std::make_shared<ViewArgs>();
  auto* cmd = app.add_subcommand(
      "view", "write a self-contained HTML viewer page (WebGL, no network) of a .ply mesh: "
              "its per-face and per-vertex scalars as colour fields, picking, normals");
  cmd->add_option("INPUT", a->input, "the mesh (.ply: ascii or binary, e.g. zdg surface -o)")
      ->required();
  cmd->add_option("-o,--output", a->output, "the page (.html)")->required();
  cmd->add_option("--field", a->field, "the field shown first (default: the first)");
  cmd->add_option("--title", a->title, "the page's title (default: the input's file name)");
  cmd->add_option("--max-faces", a->max_faces,
                  "refuse a mesh of more faces (default 2000000; a browser must open the page)");
  cmd->add_flag("--force", a->force, "replace an existing page");
  cmd->add_flag("--json", a->json, "print a JSON summary");
  cmd->callback([a] { run_view(*a); });
}

} // namespace zdg::cli
