// zdg check: property campaigns over the registry of convergence/check/property.hpp, on zdg's
// own answers or on a user's command (--against, the line-JSON protocol of
// cli/external_command.hpp). Exit 0: every property held; 1: a counterexample was
// found or the external command crashed, hung or answered garbage; 2: bad usage.
#include <zdg/arith/error.hpp>
#include <zdg/cli/commands.hpp>
#include <zdg/cli/external_command.hpp>
#include <zdg/convergence/check/property.hpp>

#include <fmt/core.h>

#include <chrono>
#include <csignal>
#include <iostream>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <unistd.h>
#include <vector>

namespace zdg::cli {

namespace {

struct CheckArgs {
  std::vector<std::string> names;
  bool list = false, json = false, quiet = false;
  std::int64_t runs = 1000;
  std::optional<std::uint64_t> seed;
  std::optional<int> bits;
  std::string type = "all";
  std::optional<std::size_t> max_size;
  std::string time_budget, request_timeout = "10s";
  unsigned threads = 1;
  std::string replay, against;
};

/// "90", "1.5s", "500ms", "10m", "2h": seconds (> 0).
double parse_duration(const std::string& option, const std::string& text) {
  std::size_t k = 0;
  while (k < text.size() && ((text[k] >= '0' && text[k] <= '9') || text[k] == '.')) ++k;
  const std::string num = text.substr(0, k), unit = text.substr(k);
  double scale = 0;
  if (unit.empty() || unit == "s") {
    scale = 1;
  } else if (unit == "ms") {
    scale = 1e-3;
  } else if (unit == "m" || unit == "min") {
    scale = 60;
  } else if (unit == "h") {
    scale = 3600;
  }
  const bool digits = !num.empty() && num != "." && num.find('.') == num.rfind('.');
  if (scale == 0 || !digits) {
    throw InvalidArgument(option + ": '" + text.substr(0, 40) +
                          "' is not a duration (90, 1.5s, 500ms, 10m, 2h)");
  }
  const double v = std::stod(num) * scale;
  if (!(v > 0) || v > 1e9) {
    throw InvalidArgument(option + ": '" + text.substr(0, 40) + "' is not a positive duration");
  }
  return v;
}

std::string types_of(const check::Property& p) {
  std::string t;
  for (auto k : p.types) {
    if (!t.empty()) t += ',';
    t += to_string(k);
  }
  return t;
}

void print_list(const std::vector<const check::Property*>& props, bool json) {
  if (json) {
    nlohmann::json arr = nlohmann::json::array();
    for (const auto* p : props) {
      nlohmann::json types = nlohmann::json::array();
      for (auto k : p->types) types.push_back(std::string(to_string(k)));
      arr.push_back({{"name", p->name},
                     {"theorem", p->theorem},
                     {"source", p->source},
                     {"operation", p->operation},
                     {"types", types},
                     {"uses_bits", p->uses_bits},
                     {"sizes", p->sizes},
                     {"default_max_size", p->default_max_size},
                     {"max_max_size", p->max_max_size},
                     {"cost", to_string(p->cost)}});
    }
    print_json({{"properties", arr}});
    return;
  }
  for (const auto* p : props) {
    std::cout << p->name << "  [" << to_string(p->cost) << "; types " << types_of(*p)
              << "; max-size " << p->default_max_size << "]"
              << (p->operation.empty() ? "" : "  --against: answers of 'zdg " + p->operation + "'")
              << "\n  " << p->theorem << "\n  source: " << p->source << "\n  sizes: " << p->sizes
              << "\n";
  }
}

struct Campaign {
  const check::Property* property;
  check::Params params;
};

std::string replay_command(const CheckArgs& a, const check::Property& p, const std::string& token) {
  std::string cmd = "zdg check " + p.name + " --replay " + token;
  if (!a.against.empty()) {
    cmd += " --against " + shell_quote(a.against);
    if (a.request_timeout != "10s") cmd += " --request-timeout " + a.request_timeout;
  }
  return cmd;
}

std::string campaign_command(const CheckArgs& a, const Campaign& c, std::uint64_t seed) {
  std::string cmd = "zdg check " + c.property->name + " --type " +
                    std::string(to_string(c.params.type)) + " --bits " +
                    std::to_string(c.params.bits) + " --max-size " +
                    std::to_string(c.params.max_size) + " --runs " + std::to_string(a.runs) +
                    " --seed " + std::to_string(seed);
  if (!a.against.empty()) cmd += " --against " + shell_quote(a.against);
  return cmd;
}

nlohmann::json served_json(const check::Report& r) {
  return {{"int64", r.served[0]}, {"int128", r.served[1]}, {"bigint", r.served[2]}};
}

nlohmann::json report_json(const CheckArgs& a, const Campaign& c, const check::Report& r) {
  nlohmann::json j{{"property", r.property},
                   {"type", std::string(to_string(r.params.type))},
                   {"bits", r.params.bits},
                   {"max_size", r.params.max_size},
                   {"seed", std::to_string(r.seed)},
                   {"runs", r.runs},
                   {"requested", r.requested},
                   {"seconds", r.seconds},
                   {"budget_exhausted", r.budget_exhausted},
                   {"served", served_json(r)},
                   {"holds", !r.failure.has_value()}};
  if (r.failure) {
    const auto& f = *r.failure;
    nlohmann::json fj{{"run", f.index},
                      {"token", f.token},
                      {"replay", replay_command(a, *c.property, f.token)},
                      {"external_error", f.external_error},
                      {"why", f.verdict.why},
                      {"case", to_json_value(f.shrunk)},
                      {"original_case", to_json_value(f.original)},
                      {"shrink_steps", f.shrink_steps},
                      {"shrink_attempts", f.shrink_attempts},
                      {"shrink_note", f.shrink_note}};
    if (c.property->is_operation()) {
      fj["request"] = to_json_value(c.property->request_of(f.shrunk));
    }
    if (f.verdict.expected) fj["expected"] = to_json_value(*f.verdict.expected);
    if (f.verdict.got) fj["answer"] = to_json_value(*f.verdict.got);
    j["failure"] = fj;
  }
  return j;
}

void print_report(const CheckArgs& a, const Campaign& c, const check::Report& r) {
  const auto& p = *c.property;
  std::string head = p.name + " on " + std::string(to_string(r.params.type)) + " (bits " +
                     std::to_string(r.params.bits) + ", max size " +
                     std::to_string(r.params.max_size) + ")";
  if (!r.failure) {
    std::cout << head << ": " << r.runs << (r.runs == 1 ? " run holds" : " runs hold");
    if (r.budget_exhausted) std::cout << " (of " << r.requested << ": time budget spent)";
    std::cout << fmt::format(" in {:.2f} s", r.seconds);
    if (r.served[0] + r.served[1] + r.served[2] > 0) {
      std::cout << "; served by int64 " << r.served[0] << ", int128 " << r.served[1] << ", bigint "
                << r.served[2];
    }
    std::cout << '\n';
    return;
  }
  const auto& f = *r.failure;
  if (f.external_error) {
    std::cout << head << ": EXTERNAL COMMAND FAILED";
  } else {
    std::cout << head << ": COUNTEREXAMPLE";
  }
  if (f.index >= 0) std::cout << " at run " << f.index + 1 << " of " << r.requested;
  std::cout << fmt::format(" ({:.2f} s)\n", r.seconds);
  std::cout << "  theorem:  " << p.theorem << '\n';
  std::cout << "  " << (f.external_error ? "failure:  " : "why:      ") << f.verdict.why << '\n';
  std::cout << "  case:     " << check::to_json(f.shrunk);
  if (!f.external_error) {
    std::cout << "  (shrunk in " << f.shrink_steps << " steps, " << f.shrink_attempts << " attempts"
              << (f.shrink_note.empty() ? "" : "; " + f.shrink_note) << ")";
  }
  std::cout << '\n';
  if (p.is_operation()) {
    std::cout << "  request:  " << check::to_json(p.request_of(f.shrunk)) << '\n';
  }
  if (f.verdict.expected)
    std::cout << "  oracle:   " << check::to_json(*f.verdict.expected) << '\n';
  if (f.verdict.got) {
    std::cout << "  " << (a.against.empty() ? "zdg:      " : "answer:   ")
              << check::to_json(*f.verdict.got) << '\n';
  }
  if (!(f.shrunk == f.original)) std::cout << "  original: " << check::to_json(f.original) << '\n';
  std::cout << "  replay:   " << replay_command(a, p, f.token) << '\n';
  if (f.index >= 0) std::cout << "  campaign: " << campaign_command(a, c, r.seed) << '\n';
}

void run_check_command(const CheckArgs& a, Context& ctx) {
  std::vector<const check::Property*> props;
  for (const auto& n : a.names) props.push_back(&check::find_property(n));
  if (a.list) {
    if (props.empty()) {
      for (const auto& p : check::registry()) props.push_back(&p);
    }
    print_list(props, a.json);
    return;
  }
  if (props.empty()) {
    throw InvalidArgument("check: name the properties to check (zdg check --list shows them)");
  }
  if (a.runs < 1) throw InvalidArgument("check: --runs " + std::to_string(a.runs) + " is not >= 1");
  if (a.threads > 1024) {
    throw InvalidArgument("check: --threads " + std::to_string(a.threads) + " is above 1024");
  }
  if (!a.replay.empty() && props.size() != 1) {
    throw InvalidArgument("check: --replay replays one property: name exactly one");
  }
  if (!a.against.empty()) {
    for (const auto* p : props) {
      if (p->is_operation()) continue;
      std::string ops;
      for (const auto& q : check::registry()) {
        if (!q.is_operation()) continue;
        if (!ops.empty()) ops += ", ";
        ops += q.name;
      }
      throw InvalidArgument("check: property " + p->name +
                            " checks no operation, so --against has nothing to ask (properties "
                            "with an operation: " +
                            ops + ")");
    }
  }
  std::optional<IntKind> type;
  if (a.type == "int64") {
    type = IntKind::int64;
  } else if (a.type == "int128") {
    type = IntKind::int128;
  } else if (a.type == "bigint") {
    type = IntKind::bigint;
  } else if (a.type != "all") {
    throw InvalidArgument("check: --type '" + a.type.substr(0, 40) +
                          "' is not one of int64, int128, bigint, all");
  }
  const double budget = a.time_budget.empty() ? 0 : parse_duration("--time-budget", a.time_budget);
  const double timeout = parse_duration("--request-timeout", a.request_timeout);

  check::Options opt;
  opt.runs = a.runs;
  opt.threads = a.threads;
  if (a.seed) {
    opt.seed = *a.seed;
  } else {
    std::random_device rd;
    opt.seed = (static_cast<std::uint64_t>(rd()) << 32) ^ rd();
  }
  if (!a.against.empty()) {
    std::signal(SIGPIPE, SIG_IGN); // a dead command is reported, not fatal
    const std::string cmd = a.against;
    opt.external = [cmd, timeout]() -> std::unique_ptr<check::AnswerSource> {
      return std::make_unique<ExternalCommand>(cmd, timeout);
    };
  }

  // Every campaign is checked before the first one runs (bad usage: nothing is run).
  std::vector<Campaign> campaigns;
  if (!a.replay.empty()) {
    auto params = check::parse_token(a.replay).first;
    check::validate_params(*props[0], params);
    campaigns.push_back({props[0], params});
  } else {
    for (const auto* p : props) {
      std::vector<IntKind> types = type ? std::vector<IntKind>{*type} : p->types;
      for (auto t : types) {
        check::Params params;
        params.type = t;
        params.bits = a.bits ? *a.bits : check::default_bits(t);
        params.max_size = a.max_size ? *a.max_size : p->default_max_size;
        check::validate_params(*p, params);
        campaigns.push_back({p, params});
      }
    }
  }

  const bool progress = !a.quiet && !a.json && ::isatty(2) != 0;
  const auto t0 = std::chrono::steady_clock::now();
  nlohmann::json results = nlohmann::json::array();
  std::size_t failed = 0;
  for (std::size_t k = 0; k < campaigns.size(); ++k) {
    const auto& c = campaigns[k];
    check::Options o = opt;
    if (budget > 0) {
      const double spent =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      o.time_budget_s =
          std::max(1e-3, (budget - spent) / static_cast<double>(campaigns.size() - k));
      o.max_shrink_s = std::min(o.max_shrink_s, std::max(5.0, o.time_budget_s));
    }
    if (progress) {
      const std::string label = c.property->name + " on " + std::string(to_string(c.params.type));
      o.progress = [label, runs = a.runs](std::int64_t done) {
        fmt::print(stderr, "\r{}: {} / {} runs", label, done, runs);
        std::fflush(stderr);
      };
    }
    check::Report r = a.replay.empty() ? check::run_check(*c.property, c.params, o)
                                       : check::replay_check(*c.property, a.replay, o);
    if (progress) fmt::print(stderr, "\r\033[K");
    if (r.failure) ++failed;
    if (a.json) {
      results.push_back(report_json(a, c, r));
    } else {
      print_report(a, c, r);
      std::cout.flush();
    }
  }
  if (a.json) {
    print_json({{"seed", std::to_string(opt.seed)},
                {"holds", failed == 0},
                {"campaigns", campaigns.size()},
                {"failed", failed},
                {"results", results}});
  } else if (campaigns.size() > 1 || failed > 0) {
    std::cout << "zdg check: " << campaigns.size() - failed << " of " << campaigns.size()
              << " campaigns hold (seed " << opt.seed << ")\n";
  }
  if (failed > 0) ctx.exit_code = 1;
}

} // namespace

void add_check_commands(CLI::App& app, Context& ctx) {
  auto a = std::make_shared<CheckArgs>();
  auto* cmd = app.add_subcommand(
      "check",
      "Property campaigns: run zdg's theorem batteries at any scale, replay counterexamples, "
      "or check your own implementation of an operation against zdg's exact oracles "
      "(--against)");
  cmd->footer(
      "Exit status: 0 every property held, 1 a counterexample (or a crash, hang or malformed "
      "answer of the --against command), 2 bad usage.\n\n"
      "--against 'COMMAND': COMMAND is started once (per thread) with /bin/sh -c; zdg writes "
      "one JSON object per line on its stdin, the arguments of the operation under the "
      "lowercase names of 'zdg OPERATION --help' (integers as decimal strings, images as "
      "nested lists), e.g. for floor-sum {\"n\":\"5\",\"m\":\"7\",\"a\":\"-3\",\"b\":\"12\"}; "
      "COMMAND answers one JSON object per line with the fields of 'zdg OPERATION --json' "
      "(e.g. {\"value\":\"-1\"}). 'zdg serve OPERATION' is such a command. Failing inputs are "
      "shrunk and printed with both answers and the command that replays them.");
  cmd->add_option("NAME", a->names, "properties (zdg check --list)");
  cmd->add_flag("--list", a->list, "List the properties (with --json: machine-readable)");
  cmd->add_option("--runs", a->runs, "Cases per property and type (default 1000)");
  cmd->add_option("--seed", a->seed, "Campaign seed (default: random, printed)");
  cmd->add_option("--bits", a->bits,
                  "Magnitude of the generated integers (default 64, 128, 256 by --type)");
  cmd->add_option("--type", a->type,
                  "Integer type the computation starts on: int64, int128, bigint or all "
                  "(default: all the property's types)");
  cmd->add_option("--max-size", a->max_size, "Largest case (points, image side, word length)");
  cmd->add_option("--time-budget", a->time_budget,
                  "Stop starting cases after this long (90, 30s, 10m, 2h), shared by the "
                  "campaigns");
  cmd->add_option("--threads", a->threads, "Worker threads (0 = all cores; default 1)");
  cmd->add_option("--replay", a->replay,
                  "Re-run the case of a token printed by a failed campaign (one NAME)");
  cmd->add_option("--against", a->against,
                  "Check the answers of COMMAND (line-JSON protocol, see below)");
  cmd->add_option("--request-timeout", a->request_timeout,
                  "Longest wait for one answer of COMMAND (default 10s)");
  cmd->add_flag("--json", a->json, "Machine-readable output");
  cmd->add_flag("--quiet", a->quiet, "No progress on stderr");
  cmd->callback([a, &ctx, cmd] {
    // An empty value is refused, not taken for an absent option.
    if (cmd->count("--against") > 0 && a->against.find_first_not_of(" \t") == std::string::npos) {
      throw InvalidArgument("check: --against '" + a->against + "' is an empty command");
    }
    if (cmd->count("--replay") > 0 && a->replay.empty()) {
      throw InvalidArgument("check: --replay '' is an empty replay token");
    }
    run_check_command(*a, ctx);
  });
}

} // namespace zdg::cli
