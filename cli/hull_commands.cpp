// zdg hull points|disc|ellipse|halfplanes|delaunay: lattice convex hulls and Delaunay
// triangulations on the command line.
// Numbers are read as BigInt (integers) or BigInt rationals ("7", "-3/4", "1000.5"; decimal
// whatever the leading zeros) and the work runs exact by escalation (int64 first).
//
// The report goes to stdout, or with -o FILE to a file written atomically (refused when it
// exists, unless --force). Disc and ellipse hulls are streamed: each vertex is written as the
// walk finds it (memory independent of the vertex count), after a check that the proven
// bound on the vertex count stays under --max-vertices (default 10^8); on a terminal a
// progress line (the angle turned so far) shows on stderr unless --quiet.
#include <zdg/arith/escalate.hpp>
#include <zdg/arith/rational.hpp>
#include <zdg/cli/commands.hpp>
#include <zdg/kernel/hulls/convex_body_hull.hpp>
#include <zdg/kernel/hulls/lattice_delaunay.hpp>
#include <zdg/kernel/hulls/lattice_hull_2d.hpp>
#include <zdg/kernel/hulls/lattice_hull_3d.hpp>
#include <zdg/kernel/hulls/lattice_polygon.hpp>
#include <zdg/kernel/io/halfplane_file.hpp>
#include <zdg/kernel/io/output_files.hpp>
#include <zdg/kernel/io/point_file.hpp>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace zdg::cli {

namespace {

struct HullOptions {
  std::string output;
  bool json = false, force = false, quiet = false;
  std::uint64_t max_vertices = kHullMaxVertices;
};

// Buffered output to stdout or to the staging file of -o: fast enough for millions of
// vertices (std::to_chars straight into a 1 MiB buffer, one fwrite per MiB).
class Writer {
public:
  explicit Writer(const HullOptions& o)
      : set_(o.force ? Existing::replace : Existing::refuse), buf_(new char[kBuffer + kSlack]) {
    if (o.output.empty()) {
      file_ = stdout;
      name_ = "stdout";
    } else {
      staging_ = set_.add(o.output);
      file_ = std::fopen(staging_.c_str(), "wb");
      if (file_ == nullptr) {
        throw IoError(o.output + ": cannot write (" + std::strerror(errno) + ")");
      }
      owned_ = true;
      name_ = o.output;
    }
  }
  ~Writer() {
    if (owned_ && file_ != nullptr) std::fclose(file_);
  }
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;

  Writer& operator<<(std::string_view s) {
    while (!s.empty()) {
      const std::size_t n = std::min(s.size(), kBuffer + kSlack - pos_);
      std::memcpy(buf_.get() + pos_, s.data(), n);
      pos_ += n;
      s.remove_prefix(n);
      if (pos_ >= kBuffer) flush();
    }
    return *this;
  }
  Writer& operator<<(const std::string& s) { return *this << std::string_view(s); }
  Writer& operator<<(const char* s) { return *this << std::string_view(s); }
  Writer& operator<<(char c) { return *this << std::string_view(&c, 1); }
  // A string literal, copied without strlen (the hot path of the vertex lines).
  template <std::size_t N>
  Writer& literal(const char (&s)[N]) {
    std::memcpy(buf_.get() + pos_, s, N - 1);
    pos_ += N - 1;
    return *this;
  }
  Writer& integer(std::int64_t v) {
    pos_ = static_cast<std::size_t>(
        std::to_chars(buf_.get() + pos_, buf_.get() + kBuffer + kSlack, v).ptr - buf_.get());
    return *this;
  }
  Writer& integer(const BigInt& v) { return *this << v.str(); }
  // Called after each small piece: the slack past kBuffer holds one vertex line.
  void maybe_flush() {
    if (pos_ >= kBuffer) flush();
  }
  void flush() {
    if (pos_ > 0 && std::fwrite(buf_.get(), 1, pos_, file_) != pos_) {
      throw IoError(name_ + ": write failed (" + std::strerror(errno) + ")");
    }
    pos_ = 0;
  }
  /// Flushes, and for -o closes the file and moves it in place.
  void finish() {
    flush();
    if (std::fflush(file_) != 0)
      throw IoError(name_ + ": write failed (" + std::strerror(errno) + ")");
    if (owned_) {
      const int rc = std::fclose(file_);
      file_ = nullptr;
      if (rc != 0) throw IoError(name_ + ": write failed (" + std::strerror(errno) + ")");
      set_.commit();
    }
  }

private:
  static constexpr std::size_t kBuffer = 1 << 20, kSlack = 4096;
  OutputSet set_;
  std::unique_ptr<char[]> buf_;
  std::size_t pos_ = 0;
  std::filesystem::path staging_;
  std::FILE* file_ = nullptr;
  bool owned_ = false;
  std::string name_;
};

Rational<BigInt> arg_rational(const std::string& name, const std::string& text) {
  try {
    return parse_rational<BigInt>(text);
  } catch (const InvalidArgument&) {
    throw InvalidArgument(name + ": '" + text + "' is not a rational number (7, -3/4, 1000.5)");
  }
}

// The 2D report of a hull given as a whole: vertices, twice the area, boundary and interior
// lattice point counts.
void print_polygon(Writer& out, const std::vector<Point2<BigInt>>& v, const std::string& what,
                   const std::string& served, bool json, const std::string& region = "") {
  auto m = lattice_polygon_measures_exact(std::span<const Point2<BigInt>>(v)).value;
  if (json) {
    nlohmann::json verts = nlohmann::json::array();
    for (const auto& p : v) verts.push_back({p.x.str(), p.y.str()});
    nlohmann::json j{{"vertices", verts},
                     {"area2", m.area2.str()},
                     {"boundary_points", m.boundary.str()},
                     {"interior_points", m.interior.str()}};
    if (!region.empty()) j["region"] = region;
    out << j.dump(2) << '\n';
    return;
  }
  out << what << ": " << std::to_string(v.size())
      << " vertices (counterclockwise from the lowest)\n";
  for (const auto& p : v) out << "  " << p.x.str() << ' ' << p.y.str() << '\n';
  out << "area2 " << m.area2.str() << ", boundary points " << m.boundary.str()
      << ", interior points " << m.interior.str();
  if (!served.empty()) out << " (computed on " << served << ")";
  out << '\n';
}

// Streams the vertices of a disc or ellipse hull to the writer (JSON or text) while the walk
// finds them; measures accumulated on the way.
class StreamPrinter : public HullVertexSink {
public:
  StreamPrinter(Writer& out, bool json, bool progress, std::string what, double cx, double cy)
      : out_(out), json_(json), progress_(progress), what_(std::move(what)), cx_(cx), cy_(cy) {}

  void begin() {
    if (json_) {
      out_ << "{\n  \"vertices\": [";
    } else {
      out_ << what_ << ", vertices counterclockwise from the lowest:\n";
    }
  }
  void vertex(std::int64_t x, std::int64_t y) override {
    meter_.add(x, y);
    if (json_) {
      if (meter_.count() == 1) {
        out_.literal("\n    [\"");
      } else {
        out_.literal(",\n    [\"");
      }
      out_.integer(x).literal("\", \"");
      out_.integer(y).literal("\"]");
    } else {
      out_.literal("  ");
      out_.integer(x).literal(" ");
      out_.integer(y).literal("\n");
    }
    out_.maybe_flush();
    if (progress_ && (meter_.count() & 0xffff) == 0)
      show(static_cast<double>(x), static_cast<double>(y));
  }
  void vertex(const BigInt& x, const BigInt& y) override {
    meter_.add(x, y);
    if (json_) {
      out_ << (meter_.count() == 1 ? "\n    [\"" : ",\n    [\"") << x.str() << "\", \"" << y.str()
           << "\"]";
    } else {
      out_ << "  " << x.str() << ' ' << y.str() << '\n';
    }
    out_.maybe_flush();
    if (progress_ && (meter_.count() & 0xffff) == 0) show(to_double(x), to_double(y));
  }
  void end(const StreamedHull& h) {
    if (progress_) std::fprintf(stderr, "\r%*s\r", 60, "");
    const auto m = meter_.finish();
    if (json_) {
      out_ << (h.vertices == 0 ? "],\n" : "\n  ],\n") << "  \"area2\": \"" << m.area2.str()
           << "\",\n  \"boundary_points\": \"" << m.boundary.str()
           << "\",\n  \"interior_points\": \"" << m.interior.str() << "\"\n}\n";
    } else {
      out_ << std::to_string(h.vertices) << " vertices, area2 " << m.area2.str()
           << ", boundary points " << m.boundary.str() << ", interior points " << m.interior.str()
           << " (computed on " << std::string(to_string(h.served)) << ")\n";
    }
  }

private:
  Writer& out_;
  bool json_, progress_;
  std::string what_;
  double cx_, cy_;
  LatticePolygonMeter meter_;

  // Progress: the angle of the vertex around the centre, from the bottom, counterclockwise.
  void show(double x, double y) {
    double a = std::atan2(y - cy_, x - cx_) + std::numbers::pi / 2; // 0 at the bottom
    if (a < 0) a += 2 * std::numbers::pi;
    std::fprintf(stderr, "\rzdg: %s: %llu vertices, %.0f%% of the turn", what_.c_str(),
                 static_cast<unsigned long long>(meter_.count()), 100 * a / (2 * std::numbers::pi));
    std::fflush(stderr);
  }
};

void run_disc(const std::vector<std::string>& args, const HullOptions& o) {
  auto cx = arg_rational("CX", args[0]), cy = arg_rational("CY", args[1]),
       r = arg_rational("R", args[2]);
  // The vertex bound before the output is opened (the walk checks it again).
  check_disc_hull_vertices(r, o.max_vertices);
  Writer out(o);
  StreamPrinter p(out, o.json, !o.quiet && isatty(2) != 0, "disc hull", cx.to_double(),
                  cy.to_double());
  p.begin();
  auto h = disc_hull_stream(cx, cy, r, p, o.max_vertices);
  p.end(h);
  out.finish();
}

void run_ellipse(const std::vector<std::string>& args, const HullOptions& o) {
  auto cx = arg_rational("CX", args[0]), cy = arg_rational("CY", args[1]),
       a = arg_rational("A", args[2]), b = arg_rational("B", args[3]);
  ellipse_body(cx, cy, a, b); // A, B > 0
  check_ellipse_hull_vertices(a, b, o.max_vertices);
  Writer out(o);
  StreamPrinter p(out, o.json, !o.quiet && isatty(2) != 0, "ellipse hull", cx.to_double(),
                  cy.to_double());
  p.begin();
  auto h = ellipse_hull_stream(cx, cy, a, b, p, o.max_vertices);
  p.end(h);
  out.finish();
}

void run_points(const std::string& path, const HullOptions& o) {
  Writer out(o); // the output is checked before the input is read
  auto pts = read_point_file(path, {2, 3});
  const std::size_t n = pts.size();
  if (pts.dim == 2) {
    std::vector<Point2<BigInt>> big;
    big.reserve(n);
    for (std::size_t k = 0; k < n; ++k) big.push_back({pts.coords[2 * k], pts.coords[2 * k + 1]});
    auto r = escalate([&]<class I>(std::type_identity<I>) {
      std::vector<Point2<I>> q;
      q.reserve(big.size());
      for (const auto& p : big) q.push_back({int_cast<I>(p.x), int_cast<I>(p.y)});
      auto idx = lattice_hull_2d_indices<I>(std::span<const Point2<I>>(q));
      std::vector<Point2<BigInt>> v;
      for (auto i : idx) v.push_back(big[i]);
      return v;
    });
    print_polygon(out, r.value, "hull of " + std::to_string(n) + " points",
                  std::string(to_string(r.served)), o.json);
    out.finish();
    return;
  }
  std::vector<Point3<BigInt>> big;
  big.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    big.push_back({pts.coords[3 * k], pts.coords[3 * k + 1], pts.coords[3 * k + 2]});
  }
  auto r = lattice_hull_3d_exact(std::span<const Point3<BigInt>>(big));
  const auto& h = r.value;
  if (o.json) {
    nlohmann::json verts = nlohmann::json::array(), facets = nlohmann::json::array();
    for (const auto& p : h.vertices) verts.push_back({p.x.str(), p.y.str(), p.z.str()});
    for (const auto& f : h.facets) facets.push_back(f);
    out << nlohmann::json{{"vertices", verts}, {"facets", facets}, {"volume6", h.volume6.str()}}
               .dump(2)
        << '\n';
    out.finish();
    return;
  }
  std::ostringstream s;
  s << "hull of " << n << " points: dimension " << h.dimension << ", " << h.vertices.size()
    << " vertices, " << h.facets.size() << " facets, volume6 " << h.volume6 << " (computed on "
    << to_string(r.served) << ")\n";
  for (const auto& p : h.vertices) s << "  v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
  for (std::size_t i = 0; i < h.facets.size(); ++i) {
    s << "  f";
    for (auto k : h.facets[i]) s << ' ' << k;
    s << "   normal " << h.normals[i].x << ' ' << h.normals[i].y << ' ' << h.normals[i].z << '\n';
  }
  out << s.str();
  out.finish();
}

void run_halfplanes(const std::string& path, const HullOptions& o) {
  Writer out(o);
  auto hs = read_halfplane_file(path);
  auto r = halfplane_hull_exact(std::span<const HalfPlane<BigInt>>(hs));
  if (r.value.region != RegionKind::bounded) {
    if (o.json) {
      out << nlohmann::json{{"region", to_string(r.value.region)}}.dump(2) << '\n';
    } else {
      out << "the region of the " << std::to_string(hs.size()) << " half-planes is "
          << to_string(r.value.region) << '\n';
    }
    out.finish();
    return;
  }
  print_polygon(out, r.value.vertices,
                "integer hull of " + std::to_string(hs.size()) + " half-planes",
                std::string(to_string(r.served)), o.json, "bounded");
  out.finish();
}

// zdg hull delaunay FILE [--voronoi]: the Delaunay triangulation of lattice points
// (kernel/hulls/lattice_delaunay.hpp) with exact predicates; --voronoi adds each site's Voronoi
// cell (exact rational vertices, bounded or not).
void run_delaunay(const std::string& path, const HullOptions& o, bool voronoi) {
  Writer out(o); // the output is checked before the input is read
  const auto pts = read_point_file(path, {2, 3});
  std::vector<std::int64_t> coords;
  coords.reserve(pts.coords.size());
  for (std::size_t i = 0; i < pts.coords.size(); ++i) {
    const BigInt& c = pts.coords[i];
    if (c > (BigInt(1) << 53) || c < -(BigInt(1) << 53)) {
      throw InvalidArgument(path + ":" + std::to_string(pts.lines[i / std::size_t(pts.dim)]) +
                            ": coordinate " + c.str() +
                            " is past 2^53 (the Delaunay predicates take exact doubles)");
    }
    coords.push_back(static_cast<std::int64_t>(c));
  }
  const LatticeDelaunay t = lattice_delaunay(coords, pts.dim);
  const int vpc = t.dim + 1;
  std::size_t edges = 0, hull = 0;
  for (const auto& n : t.neighbours) edges += n.size();
  edges /= 2;
  for (bool h : t.on_hull) hull += h;
  if (!o.json) {
    out << "Delaunay triangulation of " << std::to_string(pts.size()) << " points ("
        << std::to_string(t.vertex_count()) << " distinct, affine dimension "
        << std::to_string(t.affine_dim) << "): " << std::to_string(t.cells.size())
        << (t.dim == 2 ? " triangles, " : " tetrahedra, ") << std::to_string(edges) << " edges, "
        << std::to_string(hull) << " on the hull\n";
    for (const auto& c : t.cells) {
      for (int i = 0; i < vpc; ++i) out << (i ? " " : "") << std::to_string(c[std::size_t(i)]);
      out << "\n";
    }
    out.finish();
    return;
  }
  nlohmann::json verts = nlohmann::json::array(), cells = nlohmann::json::array();
  for (std::size_t v = 0; v < t.vertex_count(); ++v) {
    nlohmann::json p = nlohmann::json::array();
    for (int k = 0; k < t.dim; ++k) {
      p.push_back(std::to_string(t.points[v * std::size_t(t.dim) + std::size_t(k)]));
    }
    verts.push_back(p);
  }
  for (const auto& c : t.cells) {
    cells.push_back(std::vector<std::size_t>(c.begin(), c.begin() + vpc));
  }
  nlohmann::json j = {{"points", std::to_string(pts.size())},
                      {"dim", t.dim},
                      {"affine_dim", t.affine_dim},
                      {"vertices", verts},
                      {"cells", cells},
                      {"edges", std::to_string(edges)},
                      {"hull_vertices", std::to_string(hull)},
                      {"vertex_of_input", t.vertex_of_input}};
  if (voronoi) {
    nlohmann::json jv = nlohmann::json::array();
    for (const VoronoiCell& c : voronoi_cells(t)) {
      nlohmann::json vs = nlohmann::json::array();
      for (const auto& u : c.vertices) {
        nlohmann::json q = nlohmann::json::array();
        for (const auto& x : u) q.push_back(x.str());
        vs.push_back(q);
      }
      jv.push_back({{"site", c.site}, {"bounded", c.bounded}, {"vertices", vs}});
    }
    j["voronoi"] = jv;
  }
  out << j.dump() << "\n";
  out.finish();
}

void add_output_options(CLI::App* cmd, HullOptions& o) {
  cmd->add_flag("--json", o.json, "Machine-readable output");
  cmd->add_option("-o,--output", o.output,
                  "Write the report to this file (atomically) instead of stdout");
  cmd->add_flag("--force", o.force, "Replace the output file if it exists");
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
    auto o = std::make_shared<HullOptions>();
    cmd->add_option("FILE", *file, "Points, one per line ('#' starts a comment)")->required();
    add_output_options(cmd, *o);
    cmd->callback([=] { run_points(*file, *o); });
  }
  {
    auto* cmd = hull->add_subcommand(
        "delaunay", "Delaunay triangulation of a file of lattice points (2D/3D, exact "
                    "predicates), with --voronoi the exact Voronoi cells");
    auto file = std::make_shared<std::string>();
    auto o = std::make_shared<HullOptions>();
    auto voronoi = std::make_shared<bool>(false);
    cmd->add_option("FILE", *file, "Points, one per line ('#' starts a comment)")->required();
    add_output_options(cmd, *o);
    cmd->add_flag("--voronoi", *voronoi,
                  "Add each site's Voronoi cell (\"voronoi\": site, bounded, rational vertices; "
                  "--json only; needs points spanning the plane / space)");
    cmd->callback([=] { run_delaunay(*file, *o, *voronoi); });
  }
  auto add_body_options = [](CLI::App* cmd, HullOptions& o) {
    add_output_options(cmd, o);
    cmd->add_option("--max-vertices", o.max_vertices,
                    "Refuse a hull that could have more vertices than this (a proven bound, "
                    "checked before any work)")
        ->capture_default_str();
    cmd->add_flag("--quiet", o.quiet, "No progress line on stderr");
  };
  {
    auto* cmd = hull->add_subcommand(
        "disc", "Hull of the lattice points of the closed disc of centre (CX, CY) and radius R");
    auto args = std::make_shared<std::vector<std::string>>();
    auto o = std::make_shared<HullOptions>();
    cmd->add_option("CX CY R", *args, "Rationals: 7, -3/4 or 1000.5 (use -- before negatives)")
        ->required()
        ->expected(3);
    add_body_options(cmd, *o);
    cmd->callback([=] { run_disc(*args, *o); });
  }
  {
    auto* cmd = hull->add_subcommand(
        "ellipse", "Hull of the lattice points of ((x-CX)/A)^2 + ((y-CY)/B)^2 <= 1");
    auto args = std::make_shared<std::vector<std::string>>();
    auto o = std::make_shared<HullOptions>();
    cmd->add_option("CX CY A B", *args, "Rationals, A > 0 and B > 0")->required()->expected(4);
    add_body_options(cmd, *o);
    cmd->callback([=] { run_ellipse(*args, *o); });
  }
  {
    auto* cmd = hull->add_subcommand(
        "halfplanes", "Integer hull of the polygon of the half-planes 'a b c' (a x + b y <= c)");
    auto file = std::make_shared<std::string>();
    auto o = std::make_shared<HullOptions>();
    cmd->add_option("FILE", *file, "One half-plane a line: rationals a b c")->required();
    add_output_options(cmd, *o);
    cmd->callback([=] { run_halfplanes(*file, *o); });
  }
}

} // namespace zdg::cli
