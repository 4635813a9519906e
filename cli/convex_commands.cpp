// zdg convex check|envelope: digital convexity of a point file
// (kernel/hulls/digital_convexity.hpp).
//
//   zdg convex check POINTS [--definition full|hull] [--max-columns N] [--json]
//   zdg convex envelope POINTS -o OUT [--max-points N] [--force] [--json]
//
// POINTS: a point file (kernel/io/point_file.hpp), 2 or 3 integers of any size a line, a set
// (duplicates count once). check prints whether the set is fully convex (full, the default) or
// H-convex (hull: Cvxh(X) cap Z^d = X) and, when it is not, a witness: a cell whose closure meets
// the convex hull and has no vertex in the set (a lattice point of the hull for hull). JSON:
// operations/convex_operations.hpp (to_json: "convex", "definition", "witness", ...). envelope
// writes the fully convex envelope FC*(X) as a point file (OUT replaced only with --force).
#include <zdg/arith/error.hpp>
#include <zdg/cli/commands.hpp>
#include <zdg/kernel/hulls/digital_convexity.hpp>
#include <zdg/kernel/io/output_files.hpp>
#include <zdg/kernel/io/point_file.hpp>
#include <zdg/operations/convex_operations.hpp>

#include <fmt/core.h>

#include <algorithm>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

namespace zdg::cli {

namespace {

struct ConvexArgs {
  std::string input, output, definition = "full";
  std::uint64_t max_columns = kConvexityMaxColumns, max_points = kEnvelopeMaxPoints;
  bool force = false, json = false;
};

std::string cell_text(const ConvexityCheck& r) {
  std::string s;
  for (std::size_t i = 0; i < r.witness_khalimsky.size(); ++i) {
    const BigInt& k = r.witness_khalimsky[i];
    const BigInt z = (k - (k % 2 != 0 ? 1 : 0)) / 2;
    s += i == 0 ? "" : " x ";
    s += k % 2 != 0 ? "(" + z.str() + ", " + BigInt(z + 1).str() + ")" : "{" + z.str() + "}";
  }
  return s;
}

void run_check(const ConvexArgs& a) {
  ConvexCheckOptions o;
  o.definition = convexity_definition_from_name(a.definition, "--definition");
  if (a.max_columns == 0) throw InvalidArgument("--max-columns: 0 (at least 1)");
  o.max_columns = a.max_columns;
  auto pts = read_point_file(a.input, {2, 3});
  o.dim = pts.dim;
  o.coords = std::move(pts.coords);
  const auto r = convex_check_operation(o);
  if (a.json) {
    print_json(to_json(r));
    return;
  }
  const auto& c = r.check;
  const bool full = o.definition == ConvexityDefinition::full;
  const std::string what = full ? "fully convex" : "H-convex";
  if (c.convex) {
    fmt::print("{}: {} points in Z^{}, {} (computed on {})\n", a.input, r.points, r.dim, what,
               to_string(r.served));
    return;
  }
  fmt::print("{}: {} points in Z^{}, not {}: the {}-cell {} {}\n", a.input, r.points, r.dim, what,
             c.witness_dimension, cell_text(c),
             full ? "meets the convex hull and has no vertex in the set"
                  : "is in the convex hull and not in the set");
}

void run_envelope(const ConvexArgs& a) {
  if (a.max_points == 0) throw InvalidArgument("--max-points: 0 (at least 1)");
  check_not_input(a.input, a.output);
  OutputSet out(a.force ? Existing::replace : Existing::refuse);
  const auto staging = out.add(a.output); // checked before the input is read
  const auto pts = read_point_file(a.input, {2, 3});
  const auto r = fully_convex_envelope_exact(pts.dim, pts.coords, a.max_points);
  const auto d = static_cast<std::size_t>(pts.dim);
  const std::size_t m = r.value.coords.size() / d;
  std::string text = fmt::format("# fully convex envelope FC*(X) of {}: {} points\n", a.input, m);
  for (std::size_t k = 0; k < m; ++k) {
    for (std::size_t i = 0; i < d; ++i) {
      text += r.value.coords[k * d + i].str();
      text += i + 1 < d ? ' ' : '\n';
    }
  }
  {
    std::ofstream f(staging, std::ios::binary);
    f << text;
    f.close();
    if (!f) throw IoError(a.output + ": write failed");
  }
  out.commit();
  const std::size_t n = distinct_point_count(pts.dim, pts.coords);
  if (a.json) {
    print_json({{"points", m},
                {"input_points", n},
                {"iterations", r.value.iterations},
                {"dimension", pts.dim},
                {"integer_type", std::string(to_string(r.served))}});
  } else {
    fmt::print("{} -> {}: {} points in Z^{}, envelope of {} points after {} step{} (computed "
               "on {})\n",
               a.input, a.output, m, pts.dim, n, r.value.iterations,
               r.value.iterations == 1 ? "" : "s", to_string(r.served));
  }
}

} // namespace

void add_convex_commands(CLI::App& app, Context& /*ctx*/) {
  auto* convex = app.add_subcommand(
      "convex", "Digital convexity of lattice sets: full convexity (Lachaud 2022), H-convexity, "
                "the fully convex envelope");
  convex->require_subcommand(1);
  {
    auto a = std::make_shared<ConvexArgs>();
    auto* cmd = convex->add_subcommand(
        "check", "Whether a point file is fully convex (or H-convex), with a witness when not");
    cmd->add_option("POINTS", a->input, "Points, 2 or 3 integers a line ('#' starts a comment)")
        ->required();
    cmd->add_option("--definition", a->definition,
                    "full: every cell meeting the convex hull has a vertex in the set; hull: "
                    "Cvxh(X) cap Z^d = X")
        ->capture_default_str();
    cmd->add_option("--max-columns", a->max_columns,
                    "hull: refuse to sweep more lattice columns than this")
        ->capture_default_str();
    cmd->add_flag("--json", a->json, "Machine-readable output");
    cmd->callback([a] { run_check(*a); });
  }
  {
    auto a = std::make_shared<ConvexArgs>();
    auto* cmd = convex->add_subcommand(
        "envelope", "The fully convex envelope FC*(X) of a point file, written as a point file");
    cmd->add_option("POINTS", a->input, "Points, 2 or 3 integers a line ('#' starts a comment)")
        ->required();
    cmd->add_option("-o,--output", a->output, "The envelope's point file")->required();
    cmd->add_option("--max-points", a->max_points,
                    "Refuse an envelope whose hulls hold more lattice points than this")
        ->capture_default_str();
    cmd->add_flag("--force", a->force, "Replace the output file if it exists");
    cmd->add_flag("--json", a->json, "Machine-readable output");
    cmd->callback([a] { run_envelope(*a); });
  }
}

} // namespace zdg::cli
