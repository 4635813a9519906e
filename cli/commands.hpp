// The zdg command line: one program, subcommands registered by add_*_commands(). Only the
// files of cli/ include CLI11 and nlohmann-json (precompiled once for them).
//
// Conventions every subcommand follows (ARCHITECTURE.md, "Command line"):
// - `--json` prints machine-readable output on stdout; integers that may exceed 64 bits are
//   decimal strings;
// - bad input throws zdg::Error (or a CLI11 parse error): main() prints one line
//   "zdg: <what was wrong>" on stderr and exits with status 2 (also for the standard
//   exceptions of the environment: filesystem and system errors, out of memory); any other
//   exception is a bug: "zdg: internal error: ..." and status 3 (main.cpp);
// - numbers are read by zdg::parse_integer / parse_rational (decimal; main() routes every
//   integer option through parse_integer);
// - every file a command writes goes through an OutputSet (kernel/io/output_files.hpp): checked
//   before any work, refused when it exists unless --force, staged and renamed at the end;
// - bad-input rows for a new command go to tests/cli/contract_test.cpp;
// - a subcommand that finishes but whose checks fail (a theory check, for instance) sets
//   Context::exit_code to 1.
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <array>
#include <cctype>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace zdg::cli {

struct Context {
  int exit_code = 0;
};

void add_arith_commands(CLI::App& app, Context& ctx);
void add_dss_commands(CLI::App& app, Context& ctx);
void add_converge_commands(CLI::App& app, Context& ctx);
void add_transform_commands(CLI::App& app, Context& ctx);
void add_hull_commands(CLI::App& app, Context& ctx);
void add_convert_commands(CLI::App& app, Context& ctx);
void add_topology_commands(CLI::App& app, Context& ctx);
void add_surface_commands(CLI::App& app, Context& ctx);
void add_plane_commands(CLI::App& app, Context& ctx);
void add_check_commands(CLI::App& app, Context& ctx);
void add_serve_commands(CLI::App& app, Context& ctx);
void add_view_commands(CLI::App& app, Context& ctx);
void add_mesh_commands(CLI::App& app, Context& ctx);
void add_reconstruct_commands(CLI::App& app, Context& ctx);
void add_points_commands(CLI::App& app, Context& ctx);
void add_render_commands(CLI::App& app, Context& ctx);
void add_csg_commands(CLI::App& app, Context& ctx);
void add_convex_commands(CLI::App& app, Context& ctx);
void add_motion_commands(CLI::App& app, Context& ctx);
/// zdg topology persistence (cli/topology_persistence_command.cpp), added by add_topology_commands.
void add_topology_persistence_command(CLI::App& topology);
void add_voxelize_commands(CLI::App& app, Context& ctx);
/// zdg dag, and zdg render dag (added to the render command: after add_render_commands).
void add_dag_commands(CLI::App& app, Context& ctx);

/// The extension of a path in lower case ("a/B.PLY" -> ".ply"), for the checks of the
/// output and input formats.
inline std::string lower_extension(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

/// Prints j on stdout (two-space indent), followed by a newline.
void print_json(const nlohmann::json& j);

/// A finite number in `text`, all of it (InvalidArgument "OPTION: 'TEXT' is not a number").
double parse_number(const std::string& text, const std::string& option);
/// The comma-separated fields of `text` ("1,,2" -> "1", "", "2"; "" -> one empty field).
std::vector<std::string> split_commas(const std::string& text);
/// X,Y,Z: three finite numbers (InvalidArgument "OPTION: 'TEXT' is not X,Y,Z", or parse_number's).
std::array<double, 3> parse_xyz(const std::string& text, const std::string& option);
/// --view AZ,EL in degrees, the elevation in [-90, 90].
std::pair<double, double> parse_view(const std::string& text);
/// --png-size WIDTHxHEIGHT, a size check_picture_size accepts.
std::pair<int, int> parse_picture_size(const std::string& text);

} // namespace zdg::cli
