// zdg dss recognize | cover | subsegment: digital straight segments on the command line.
// Input files hold one point "x y" per line ('#' starts a comment, blank lines are skipped) or,
// on their first data line, a Freeman chain "x0 y0 0123..." (kernel/io/point_file.hpp). Integers
// are read exactly, in decimal; errors name the file and line and exit with status 2.
#include <zdg/arith/dsl_subsegment.hpp>
#include <zdg/arith/dss_recognizer.hpp>
#include <zdg/arith/escalate.hpp>
#include <zdg/cli/commands.hpp>
#include <zdg/kernel/curves/freeman_chain.hpp>
#include <zdg/kernel/curves/maximal_segments.hpp>
#include <zdg/kernel/io/point_file.hpp>
#include <zdg/operations/dss_operations.hpp>

#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace zdg::cli {

namespace {

// The path of a file: its points (BigInt) and the line of each.
struct PointFile {
  std::vector<Point2<BigInt>> pts;
  std::vector<std::size_t> lines; // line number of each point (the chain's line for all)
  bool freeman = false;
};

PointFile read_points(const std::string& path) {
  DigitalPathFile file = read_digital_path_file(path);
  PointFile f;
  if (file.chain) {
    for (const auto& p : freeman_points(*file.chain)) {
      f.pts.push_back({BigInt(p.x), BigInt(p.y)});
      f.lines.push_back(file.chain_line);
    }
    f.freeman = true;
  } else {
    f.pts = std::move(file.points);
    f.lines = std::move(file.lines);
  }
  return f;
}

// The path of a file for the dss operations: its points, each named FILE:LINE in messages.
DssPathOptions path_options(const std::string& path, int connectivity) {
  auto f = std::make_shared<PointFile>(read_points(path));
  DssPathOptions o;
  o.points = f->pts;
  o.connectivity = connectivity;
  o.where = [f, path](std::size_t k) { return path + ":" + std::to_string(f->lines[k]); };
  return o;
}

int connectivity_number(Connectivity c) {
  return c == Connectivity::four ? 4 : 8;
}

void run_recognize(const std::string& path, int forced, bool json) {
  const DssRecognizeResult r = dss_recognize_operation(path_options(path, forced));
  if (json) return print_json(to_json(r));
  const auto& rec = r.recognition;
  const auto& ch = rec.characteristics;
  const int c = connectivity_number(rec.connectivity);
  std::string line = "a = " + ch.a.str() + ", b = " + ch.b.str() + ", mu = " + ch.mu.str() +
                     ", omega = " + ch.omega.str();
  if (rec.is_dss) {
    std::cout << "DSS (" << c << "-connected, " << r.points << " points): " << line << '\n';
  } else {
    std::cout << "not a DSS (" << c << "-connected): the first " << rec.longest_prefix << " of "
              << r.points << " points are, with " << line << '\n';
  }
}

void run_cover(const std::string& path, bool closed, bool greedy, int forced, bool json) {
  const DssCoverResult r = dss_cover_operation({path_options(path, forced), closed, greedy});
  if (json) return print_json(to_json(r));
  std::cout << (greedy ? "greedy segmentation" : "maximal segments") << " of "
            << (closed ? "closed" : "open") << " " << connectivity_number(r.connectivity)
            << "-connected curve (" << r.points << " points): " << r.segments.size()
            << " segments\n";
  for (const auto& s : r.segments) {
    std::cout << "[" << s.begin << ", " << s.end << "] a = " << s.a << ", b = " << s.b
              << ", mu = " << to_string(Int128(s.mu)) << '\n';
  }
}

BigInt parse_arg(const std::string& text, const std::string& what) {
  try {
    return parse_integer<BigInt>(text);
  } catch (const InvalidArgument&) {
    throw InvalidArgument("dss subsegment: " + what + " = '" + text + "' is not an integer");
  }
}

void run_subsegment(const std::vector<std::string>& args, const std::string& algorithm, bool json) {
  BigInt a = parse_arg(args[0], "A"), b = parse_arg(args[1], "B"), mu = parse_arg(args[2], "MU"),
         x0 = parse_arg(args[3], "X0"), x1 = parse_arg(args[4], "X1");
  if (b <= 0) throw InvalidArgument("dss subsegment: B = " + b.str() + " must be > 0");
  if (a < 0 || a >= b) {
    throw InvalidArgument("dss subsegment: A = " + a.str() +
                          " must satisfy 0 <= A < B = " + b.str());
  }
  if (x1 < x0) {
    throw InvalidArgument("dss subsegment: X1 = " + x1.str() + " is smaller than X0 = " + x0.str());
  }
  auto r = dsl_subsegment_exact(a, b, mu, x0, x1,
                                algorithm == "smart" ? DslSubsegmentAlgorithm::smart_dss
                                                     : DslSubsegmentAlgorithm::reversed_smart_dss);
  if (json) {
    print_json({{"a", r.value.a.str()}, {"b", r.value.b.str()}, {"mu", r.value.mu.str()}});
    return;
  }
  std::cout << "a = " << r.value.a << ", b = " << r.value.b << ", mu = " << r.value.mu
            << "  (computed on " << to_string(r.served) << ")\n";
}

} // namespace

void add_dss_commands(CLI::App& app, Context& /*ctx*/) {
  auto* dss = app.add_subcommand(
      "dss", "Digital straight segments: recognition, maximal segments, DSL subsegments");
  dss->require_subcommand(1);
  {
    auto* cmd = dss->add_subcommand(
        "recognize", "Is a path (one point 'x y' per line, or a Freeman chain) a DSS? Its minimal "
                     "characteristics (a, b, mu, omega)");
    auto file = std::make_shared<std::string>();
    auto conn = std::make_shared<int>(0);
    auto json = std::make_shared<bool>(false);
    cmd->add_option("FILE", *file, "Points 'x y', one per line, consecutive points adjacent")
        ->required();
    cmd->add_option("--connectivity", *conn,
                    "4 (standard DSS) or 8 (naive DSS); default: 4 when every step is an axis "
                    "step, else 8")
        ->check(CLI::IsMember({4, 8}));
    cmd->add_flag("--json", *json, "Machine-readable output");
    cmd->callback([=] { run_recognize(*file, *conn, *json); });
  }
  {
    auto* cmd = dss->add_subcommand(
        "cover", "Maximal segments (tangential cover) of a digital curve, in O(n)");
    auto file = std::make_shared<std::string>();
    auto conn = std::make_shared<int>(0);
    auto closed = std::make_shared<bool>(false), greedy = std::make_shared<bool>(false),
         json = std::make_shared<bool>(false);
    cmd->add_option("FILE", *file, "Points 'x y', one per line, or a Freeman chain 'x0 y0 0123...'")
        ->required();
    cmd->add_flag("--closed", *closed, "The curve is closed (last point adjacent to the first)");
    cmd->add_flag("--greedy", *greedy, "Greedy segmentation instead of the maximal segments");
    cmd->add_option("--connectivity", *conn, "4 or 8 (default: from the steps)")
        ->check(CLI::IsMember({4, 8}));
    cmd->add_flag("--json", *json, "Machine-readable output");
    cmd->callback([=] { run_cover(*file, *closed, *greedy, *conn, *json); });
  }
  {
    auto* cmd = dss->add_subcommand(
        "subsegment", "Minimal characteristics of the naive DSL 0 <= A x - B y - MU < B restricted "
                      "to X0 <= x <= X1 (ReversedSmartDSS or SmartDSS, O(log B) time)");
    auto args = std::make_shared<std::vector<std::string>>();
    auto algorithm = std::make_shared<std::string>("reversed");
    auto json = std::make_shared<bool>(false);
    cmd->add_option("A B MU X0 X1", *args, "0 <= A < B, any MU, X0 <= X1 (any size)")
        ->required()
        ->expected(5)
        ->allow_extra_args(false);
    cmd->add_option("--algorithm", *algorithm,
                    "reversed (bottom-up ReversedSmartDSS, default) or smart (top-down SmartDSS); "
                    "same answer")
        ->check(CLI::IsMember({"reversed", "smart"}));
    cmd->add_flag("--json", *json, "Machine-readable output");
    cmd->callback([=] { run_subsegment(*args, *algorithm, *json); });
  }
}

} // namespace zdg::cli
