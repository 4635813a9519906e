// zdg hull points|disc|ellipse|halfplanes: lattice convex hulls on the command line.
// Numbers are read as BigInt (integers) or BigInt rationals ("7", "-3/4", "1000.5") and the
// work runs exact by escalation (int64 first).
#include <zdg/arith/escalate.hpp>
#include <zdg/arith/rational.hpp>
#include <zdg/convergence/cli/commands.hpp>
#include <zdg/kernel/convex_body_hull.hpp>
#include <zdg/kernel/lattice_hull_2d.hpp>
#include <zdg/kernel/lattice_hull_3d.hpp>
#include <zdg/kernel/lattice_polygon.hpp>

#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace zdg::cli {

namespace {

// Whitespace-separated fields of each non-blank line that is not a '#' comment, with line
// numbers.
struct Line {
  std::size_t number;
  std::vector<std::string> fields;
};

std::vector<Line> read_lines(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw IoError(path + ": cannot open");
  std::vector<Line> out;
  std::string text;
  for (std::size_t n = 1; std::getline(in, text); ++n) {
    if (auto hash = text.find('#'); hash != std::string::npos) text.resize(hash);
    std::istringstream s(text);
    Line l{n, {}};
    for (std::string f; s >> f;) l.fields.push_back(f);
    if (!l.fields.empty()) out.push_back(std::move(l));
  }
  if (in.bad()) throw IoError(path + ": read error");
  if (out.empty()) throw IoError(path + ": no data (empty file)");
  return out;
}

BigInt field_integer(const std::string& path, const Line& l, const std::string& f) {
  try {
    return parse_integer<BigInt>(f);
  } catch (const InvalidArgument&) {
    throw IoError(path + ":" + std::to_string(l.number) + ": '" + f + "' is not an integer");
  }
}

Rational<BigInt> field_rational(const std::string& path, const Line& l, const std::string& f) {
  try {
    return parse_rational<BigInt>(f);
  } catch (const InvalidArgument&) {
    throw IoError(path + ":" + std::to_string(l.number) + ": '" + f +
                  "' is not a rational number (7, -3/4, 1000.5)");
  }
}

Rational<BigInt> arg_rational(const std::string& name, const std::string& text) {
  try {
    return parse_rational<BigInt>(text);
  } catch (const InvalidArgument&) {
    throw InvalidArgument(name + ": '" + text + "' is not a rational number (7, -3/4, 1000.5)");
  }
}

// The 2D report: vertices, twice the area, boundary and interior lattice point counts.
nlohmann::json polygon_json(const std::vector<Point2<BigInt>>& v) {
  auto m = lattice_polygon_measures_exact(std::span<const Point2<BigInt>>(v)).value;
  nlohmann::json verts = nlohmann::json::array();
  for (const auto& p : v) verts.push_back({p.x.str(), p.y.str()});
  return {{"vertices", verts},
          {"area2", m.area2.str()},
          {"boundary_points", m.boundary.str()},
          {"interior_points", m.interior.str()}};
}

void print_polygon(const std::vector<Point2<BigInt>>& v, const std::string& what,
                   const std::string& served, bool json, const std::string& region = "") {
  nlohmann::json j = polygon_json(v);
  if (!region.empty()) j["region"] = region;
  if (json) {
    print_json(j);
    return;
  }
  std::cout << what << ": " << v.size() << " vertices (counterclockwise from the lowest)\n";
  for (const auto& p : v) std::cout << "  " << p.x << ' ' << p.y << '\n';
  std::cout << "area2 " << j["area2"].get<std::string>() << ", boundary points "
            << j["boundary_points"].get<std::string>() << ", interior points "
            << j["interior_points"].get<std::string>();
  if (!served.empty()) std::cout << " (computed on " << served << ")";
  std::cout << '\n';
}

void run_points(const std::string& path, bool json) {
  auto lines = read_lines(path);
  const std::size_t dim = lines.front().fields.size();
  if (dim != 2 && dim != 3) {
    throw IoError(path + ":" + std::to_string(lines.front().number) +
                  ": expected 2 or 3 integers, got " + std::to_string(dim) + " fields");
  }
  std::vector<std::vector<BigInt>> pts;
  pts.reserve(lines.size());
  for (const auto& l : lines) {
    if (l.fields.size() != dim) {
      throw IoError(path + ":" + std::to_string(l.number) + ": " + std::to_string(l.fields.size()) +
                    " fields in a file of " + std::to_string(dim) + "D points (mixed dimensions)");
    }
    std::vector<BigInt> p;
    for (const auto& f : l.fields) p.push_back(field_integer(path, l, f));
    pts.push_back(std::move(p));
  }
  if (dim == 2) {
    std::vector<Point2<BigInt>> big;
    big.reserve(pts.size());
    for (auto& p : pts) big.push_back({p[0], p[1]});
    auto r = lattice_hull_2d_exact(std::span<const Point2<BigInt>>(big));
    print_polygon(r.value, "hull of " + std::to_string(pts.size()) + " points",
                  std::string(to_string(r.served)), json);
    return;
  }
  std::vector<Point3<BigInt>> big;
  big.reserve(pts.size());
  for (auto& p : pts) big.push_back({p[0], p[1], p[2]});
  auto r = lattice_hull_3d_exact(std::span<const Point3<BigInt>>(big));
  const auto& h = r.value;
  if (json) {
    nlohmann::json verts = nlohmann::json::array(), facets = nlohmann::json::array();
    for (const auto& p : h.vertices) verts.push_back({p.x.str(), p.y.str(), p.z.str()});
    for (const auto& f : h.facets) facets.push_back(f);
    print_json({{"vertices", verts}, {"facets", facets}, {"volume6", h.volume6.str()}});
    return;
  }
  std::cout << "hull of " << pts.size() << " points: dimension " << h.dimension << ", "
            << h.vertices.size() << " vertices, " << h.facets.size() << " facets, volume6 "
            << h.volume6 << " (computed on " << to_string(r.served) << ")\n";
  for (const auto& p : h.vertices) std::cout << "  v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
  for (std::size_t i = 0; i < h.facets.size(); ++i) {
    std::cout << "  f";
    for (auto k : h.facets[i]) std::cout << ' ' << k;
    std::cout << "   normal " << h.normals[i].x << ' ' << h.normals[i].y << ' ' << h.normals[i].z
              << '\n';
  }
}

void run_halfplanes(const std::string& path, bool json) {
  auto lines = read_lines(path);
  std::vector<HalfPlane<BigInt>> hs;
  for (const auto& l : lines) {
    if (l.fields.size() != 3) {
      throw IoError(path + ":" + std::to_string(l.number) +
                    ": expected 'a b c' (a x + b y <= c), got " + std::to_string(l.fields.size()) +
                    " fields");
    }
    hs.push_back({field_rational(path, l, l.fields[0]), field_rational(path, l, l.fields[1]),
                  field_rational(path, l, l.fields[2])});
  }
  auto r = halfplane_hull_exact(std::span<const HalfPlane<BigInt>>(hs));
  if (r.value.region != RegionKind::bounded) {
    if (json) {
      print_json({{"region", to_string(r.value.region)}});
    } else {
      std::cout << "the region of the " << hs.size() << " half-planes is "
                << to_string(r.value.region) << '\n';
    }
    return;
  }
  print_polygon(r.value.vertices, "integer hull of " + std::to_string(hs.size()) + " half-planes",
                std::string(to_string(r.served)), json, "bounded");
}

} // namespace

void add_hull_commands(CLI::App& app, Context& /*ctx*/) {
  auto* hull = app.add_subcommand(
      "hull",
      "Lattice convex hulls: point files (2D/3D), Z^2 inside a disc, ellipse or half-planes");
  hull->require_subcommand(1);
  {
    auto* cmd =
        hull->add_subcommand("points", "Exact hull of a file of points, 2 or 3 integers a line");
    auto file = std::make_shared<std::string>();
    auto json = std::make_shared<bool>(false);
    cmd->add_option("FILE", *file, "Points, one per line ('#' starts a comment)")->required();
    cmd->add_flag("--json", *json, "Machine-readable output");
    cmd->callback([=] { run_points(*file, *json); });
  }
  {
    auto* cmd = hull->add_subcommand(
        "disc", "Hull of the lattice points of the closed disc of centre (CX, CY) and radius R");
    auto args = std::make_shared<std::vector<std::string>>();
    auto json = std::make_shared<bool>(false);
    cmd->add_option("CX CY R", *args, "Rationals: 7, -3/4 or 1000.5 (use -- before negatives)")
        ->required()
        ->expected(3);
    cmd->add_flag("--json", *json, "Machine-readable output");
    cmd->callback([=] {
      auto r = disc_hull_exact(arg_rational("CX", (*args)[0]), arg_rational("CY", (*args)[1]),
                               arg_rational("R", (*args)[2]));
      print_polygon(r.value.vertices, "disc hull", std::string(to_string(r.served)), *json);
    });
  }
  {
    auto* cmd = hull->add_subcommand(
        "ellipse", "Hull of the lattice points of ((x-CX)/A)^2 + ((y-CY)/B)^2 <= 1");
    auto args = std::make_shared<std::vector<std::string>>();
    auto json = std::make_shared<bool>(false);
    cmd->add_option("CX CY A B", *args, "Rationals, A > 0 and B > 0")->required()->expected(4);
    cmd->add_flag("--json", *json, "Machine-readable output");
    cmd->callback([=] {
      auto r = ellipse_hull_exact(arg_rational("CX", (*args)[0]), arg_rational("CY", (*args)[1]),
                                  arg_rational("A", (*args)[2]), arg_rational("B", (*args)[3]));
      print_polygon(r.value.vertices, "ellipse hull", std::string(to_string(r.served)), *json);
    });
  }
  {
    auto* cmd = hull->add_subcommand(
        "halfplanes", "Integer hull of the polygon of the half-planes 'a b c' (a x + b y <= c)");
    auto file = std::make_shared<std::string>();
    auto json = std::make_shared<bool>(false);
    cmd->add_option("FILE", *file, "One half-plane a line: rationals a b c")->required();
    cmd->add_flag("--json", *json, "Machine-readable output");
    cmd->callback([=] { run_halfplanes(*file, *json); });
  }
}

} // namespace zdg::cli
