// zdg plane recognize|probe: digital planes on the command line, exact for any size.
//
//   zdg plane recognize POINTS [--json]   is the point set (3 integers a line) a naive digital
//                                         plane segment?
//                                         (kernel/surfaces/digital_plane_recognition.hpp)
//   zdg plane probe A B C [--algorithm h|r] [--max-steps K] [--json]
//                                         probes the standard plane of normal (A, B, C) from the
//                                         origin with the H- or R-algorithm
//                                         (kernel/surfaces/plane_probing.hpp)
// Both run exact by escalation (int64 first) and say which integer type served.
#include <zdg/arith/escalate.hpp>
#include <zdg/cli/commands.hpp>
#include <zdg/kernel/io/point_file.hpp>
#include <zdg/kernel/surfaces/digital_plane_recognition.hpp>
#include <zdg/kernel/surfaces/plane_probing.hpp>

#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace zdg::cli {

namespace {

nlohmann::json point_json(const Point3<BigInt>& p) {
  return nlohmann::json::array({p.x.str(), p.y.str(), p.z.str()});
}

void run_recognize(const std::string& path, bool json) {
  auto pts = read_point_file(path, {3});
  std::vector<Point3<BigInt>> big;
  big.reserve(pts.size());
  for (std::size_t k = 0; k < pts.size(); ++k) {
    big.push_back({pts.coords[3 * k], pts.coords[3 * k + 1], pts.coords[3 * k + 2]});
  }
  auto r = recognize_naive_plane_exact(std::span<const Point3<BigInt>>(big));
  const auto& p = r.value;
  if (json) {
    nlohmann::json j{{"is_plane", p.is_plane},
                     {"points", pts.size()},
                     {"served", std::string(to_string(r.served))}};
    if (p.is_plane) {
      j["normal"] = point_json(p.normal);
      j["mu"] = p.mu.str();
      j["omega"] = p.omega.str();
    }
    print_json(j);
    return;
  }
  if (p.is_plane) {
    std::cout << "the " << pts.size() << " points are a naive digital plane segment: " << p.mu
              << " <= " << p.normal.x << " x + " << p.normal.y << " y + " << p.normal.z << " z < "
              << p.mu + p.omega << " (computed on " << to_string(r.served) << ")\n";
  } else {
    std::cout << "the " << pts.size()
              << " points are not a naive digital plane segment (computed on "
              << to_string(r.served) << ")\n";
  }
}

BigInt parse_component(const std::string& text, const char* name) {
  try {
    return parse_integer<BigInt>(text);
  } catch (const InvalidArgument&) {
    throw InvalidArgument(std::string("plane probe: ") + name + " = '" + text +
                          "' is not an integer");
  }
}

void run_probe(const std::vector<std::string>& args, const std::string& algorithm,
               std::uint64_t max_steps, bool json) {
  const Point3<BigInt> n{parse_component(args[0], "A"), parse_component(args[1], "B"),
                         parse_component(args[2], "C")};
  const auto alg = algorithm == "h" ? ProbingAlgorithm::h : ProbingAlgorithm::r;
  auto r = probe_standard_plane_exact(n, alg, max_steps);
  const auto& p = r.value;
  if (json) {
    nlohmann::json frame = nlohmann::json::array();
    for (const auto& m : p.frame) frame.push_back(point_json(m));
    print_json({{"normal", point_json(p.normal)},
                {"input", point_json(n)},
                {"plane", "standard"},
                {"algorithm", std::string(to_string(alg))},
                {"steps", p.steps},
                {"predicate_calls", p.predicate_calls},
                {"reduced_basis", p.reduced_basis},
                {"frame", frame},
                {"apex", point_json(p.apex)},
                {"served", std::string(to_string(r.served))}});
    return;
  }
  std::cout << "normal " << p.normal.x << ' ' << p.normal.y << ' ' << p.normal.z << " after "
            << p.steps << " steps of the " << (alg == ProbingAlgorithm::h ? "H" : "R")
            << "-algorithm (" << p.predicate_calls << " predicate calls, "
            << (p.reduced_basis ? "reduced" : "non-reduced") << " basis, computed on "
            << to_string(r.served) << ")\n";
}

} // namespace

void add_plane_commands(CLI::App& app, Context& /*ctx*/) {
  auto* plane = app.add_subcommand("plane", "Digital planes: recognition and plane probing");
  plane->require_subcommand(1);
  {
    auto* cmd = plane->add_subcommand(
        "recognize", "Is a set of points of Z^3 a naive digital plane segment? (exact, chords)");
    auto file = std::make_shared<std::string>();
    auto json = std::make_shared<bool>(false);
    cmd->add_option("POINTS", *file, "Points, 3 integers a line ('#' starts a comment)")
        ->required();
    cmd->add_flag("--json", *json, "Machine-readable output");
    cmd->callback([=] { run_recognize(*file, *json); });
  }
  {
    auto* cmd = plane->add_subcommand(
        "probe", "Probe the standard plane 0 <= A x + B y + C z < |A| + |B| + |C| from the "
                 "origin and print the normal found (H- or R-algorithm)");
    auto args = std::make_shared<std::vector<std::string>>();
    auto algorithm = std::make_shared<std::string>("r");
    auto max_steps = std::make_shared<std::uint64_t>(kPlaneProbingMaxSteps);
    auto json = std::make_shared<bool>(false);
    cmd->add_option("A B C", *args,
                    "Primitive normal, three nonzero integers of any size and sign (use -- "
                    "before negatives)")
        ->required()
        ->expected(3);
    cmd->add_option("--algorithm", *algorithm, "h (hexagon) or r (rays, reduced basis)")
        ->check(CLI::IsMember({"h", "r"}))
        ->capture_default_str();
    cmd->add_option("--max-steps", *max_steps, "Refuse to run more steps than this")
        ->capture_default_str();
    cmd->add_flag("--json", *json, "Machine-readable output");
    cmd->callback([=] { run_probe(*args, *algorithm, *max_steps, *json); });
  }
}

} // namespace zdg::cli
