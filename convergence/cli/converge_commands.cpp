// zdg converge and zdg paper: multigrid convergence experiments on the command line.
//
//   zdg converge --shape ellipse:20,7 --estimator ii-curvature --h 0.1:0.01:6 --k 5 -o DIR
//   zdg converge CONFIG.toml -o DIR          (same keys as the flags: shape, estimator, h,
//                                            k, alpha, translations, seed, box, fit_levels,
//                                            threads, tolerance, title)
//   zdg converge --list
//   zdg paper cviu2014-ii2d -o DIR [--quick]
//
// Outputs in DIR: results.csv, summary.json (fits, verdicts, provenance), convergence.png
// and .svg (papers/plot_convergence.py, run with /usr/bin/python3). Exit status 1 when a
// theory check fails, 2 for bad input.
#include <zdg/arith/error.hpp>
#include <zdg/convergence/cli/commands.hpp>
#include <zdg/convergence/estimator.hpp>
#include <zdg/convergence/experiment.hpp>
#include <zdg/convergence/shape.hpp>

#include <toml++/toml.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <unistd.h>

namespace zdg::cli {

namespace {

namespace fs = std::filesystem;

struct ConvergeOptions {
  std::string config_file;
  std::vector<std::string> shapes, estimators;
  std::string h, k, alpha, box, title;
  int translations = -1, fit_levels = -1, threads = -1;
  long long seed = -1;
  double tolerance = -1;
  std::string output;
  bool json = false, quiet = false, list = false, force = false, no_plot = false;
};

std::string source_dir() {
  if (const char* env = std::getenv("ZDG_SOURCE_DIR")) return env;
#ifdef ZDG_SOURCE_DIR
  return ZDG_SOURCE_DIR;
#else
  return ".";
#endif
}

std::string git_commit() {
  std::string cmd = "git -C '" + source_dir() + "' rev-parse HEAD 2>/dev/null";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.c_str(), "r"), pclose);
  if (!pipe) return "unknown";
  std::array<char, 128> buf{};
  std::string out;
  while (fgets(buf.data(), buf.size(), pipe.get()) != nullptr) out += buf.data();
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out.empty() ? "unknown" : out;
}

std::string compiler() {
#if defined(__clang__)
  return "clang " __clang_version__;
#elif defined(__GNUC__)
  return "gcc " __VERSION__;
#else
  return "unknown";
#endif
}

// TOML value -> string (strings as is, numbers printed exactly enough).
std::string toml_text(const toml::node& n, const std::string& key, const std::string& file) {
  if (auto s = n.value<std::string>()) return *s;
  if (n.is_integer()) return std::to_string(*n.value<std::int64_t>());
  if (n.is_floating_point()) {
    std::ostringstream o;
    o << std::setprecision(17) << *n.value<double>();
    return o.str();
  }
  if (const auto* arr = n.as_array()) {
    std::string out;
    for (const auto& e : *arr) out += (out.empty() ? "" : ",") + toml_text(e, key, file);
    return out;
  }
  throw IoError(file + ": key '" + key + "' has an unsupported value type");
}

std::vector<std::string> toml_list(const toml::node& n, const std::string& key,
                                   const std::string& file) {
  std::vector<std::string> out;
  if (const auto* arr = n.as_array()) {
    for (const auto& e : *arr) out.push_back(toml_text(e, key, file));
  } else {
    out.push_back(toml_text(n, key, file));
  }
  return out;
}

// Fills the options that were not given on the command line from the TOML file.
void load_toml(ConvergeOptions& o, const std::string& file) {
  toml::table t;
  try {
    t = toml::parse_file(file);
  } catch (const toml::parse_error& e) {
    std::ostringstream msg;
    msg << file << ":" << e.source().begin.line << ": " << e.description();
    throw IoError(msg.str());
  }
  for (const auto& [key_view, node] : t) {
    std::string key(key_view.str());
    auto text = [&] { return toml_text(node, key, file); };
    auto int_value = [&]() -> long long {
      auto v = node.value<std::int64_t>();
      if (!v || *v < 0 || *v > 1000000000) {
        throw IoError(file + ": key '" + key + "' must be an integer in 0..1e9");
      }
      return *v;
    };
    if (key == "shape" || key == "shapes") {
      if (o.shapes.empty()) o.shapes = toml_list(node, key, file);
    } else if (key == "estimator" || key == "estimators") {
      if (o.estimators.empty()) o.estimators = toml_list(node, key, file);
    } else if (key == "h") {
      if (o.h.empty()) o.h = text();
    } else if (key == "k") {
      if (o.k.empty()) o.k = text();
    } else if (key == "alpha") {
      if (o.alpha.empty()) o.alpha = text();
    } else if (key == "box") {
      if (o.box.empty()) o.box = text();
    } else if (key == "title") {
      if (o.title.empty()) o.title = text();
    } else if (key == "translations") {
      if (o.translations < 0) o.translations = static_cast<int>(int_value());
    } else if (key == "seed") {
      if (o.seed < 0) o.seed = int_value();
    } else if (key == "fit_levels" || key == "fit-levels") {
      if (o.fit_levels < 0) o.fit_levels = static_cast<int>(int_value());
    } else if (key == "threads") {
      if (o.threads < 0) o.threads = static_cast<int>(int_value());
    } else if (key == "tolerance") {
      if (o.tolerance < 0) {
        auto v = node.value<double>();
        if (!v) throw IoError(file + ": key 'tolerance' must be a number");
        o.tolerance = *v;
      }
    } else {
      throw IoError(file + ": unknown key '" + key + "'");
    }
  }
}

ExperimentConfig make_config(const ConvergeOptions& o) {
  ExperimentConfig c;
  c.shapes = o.shapes;
  c.estimators = o.estimators;
  if (o.h.empty()) throw InvalidArgument("no grid steps given (--h)");
  c.hs = parse_grid_steps(o.h);
  c.h_text = o.h;
  if (!o.k.empty()) c.k_text = o.k;
  if (!o.alpha.empty()) c.alpha_text = o.alpha;
  if (!o.box.empty()) c.box = parse_box(o.box);
  c.translations = o.translations < 0 ? 0 : o.translations;
  c.seed = o.seed < 0 ? 0 : static_cast<std::uint64_t>(o.seed);
  c.fit_levels = o.fit_levels < 0 ? 0 : o.fit_levels;
  c.threads = o.threads < 0 ? 1 : o.threads;
  c.tolerance = o.tolerance < 0 ? 0.1 : o.tolerance;
  // Validate the parameters before any work.
  if (c.k_text) parse_k_per_shape(*c.k_text, c.shapes.size());
  if (c.alpha_text) parse_parameter(*c.alpha_text, "--alpha");
  return c;
}

nlohmann::json json_number(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

nlohmann::json runs_json(const ExperimentResult& r) {
  nlohmann::json runs = nlohmann::json::array();
  for (const auto& x : r.runs) {
    runs.push_back({{"shape", x.shape},
                    {"estimator", x.estimator},
                    {"h", x.h},
                    {"translation", x.translation},
                    {"offset", x.offset},
                    {"k", x.k},
                    {"alpha", x.alpha},
                    {"linf", json_number(x.errors.linf)},
                    {"l2", json_number(x.errors.l2)},
                    {"mean", json_number(x.errors.mean)},
                    {"n", x.errors.n},
                    {"seconds", x.seconds}});
  }
  return runs;
}

nlohmann::json fits_json(const ExperimentResult& r) {
  nlohmann::json fits = nlohmann::json::array();
  for (const auto& f : r.fits) {
    nlohmann::json j{{"shape", f.shape},
                     {"estimator", f.estimator},
                     {"norm", f.norm},
                     {"slope", json_number(f.fit.slope)},
                     {"stderr", json_number(f.fit.stderr_slope)},
                     {"intercept", json_number(f.fit.intercept)},
                     {"levels", f.fit.n},
                     {"h_min", f.hs.empty() ? 0.0 : f.hs.back()},
                     {"h_max", f.hs.empty() ? 0.0 : f.hs.front()},
                     {"expected", f.expected ? nlohmann::json(*f.expected) : nlohmann::json()},
                     {"pass", f.pass ? nlohmann::json(*f.pass) : nlohmann::json()}};
    if (f.expected) {
      j["theory"] = f.theory;
      j["source"] = f.source;
    }
    fits.push_back(j);
  }
  return fits;
}

nlohmann::json config_json(const ExperimentConfig& c, const ConvergeOptions& o) {
  return {{"shapes", c.shapes},
          {"estimators", c.estimators},
          {"h", c.h_text},
          {"hs", c.hs},
          {"k", c.k_text ? nlohmann::json(*c.k_text) : nlohmann::json()},
          {"alpha", c.alpha_text ? nlohmann::json(*c.alpha_text) : nlohmann::json()},
          {"translations", c.translations},
          {"seed", c.seed},
          {"box", c.box ? nlohmann::json({c.box->first, c.box->second}) : nlohmann::json()},
          {"fit_levels", c.fit_levels},
          {"tolerance", c.tolerance},
          {"threads", c.threads},
          {"title", o.title},
          {"config_file", o.config_file}};
}

// Writes text to path through a temporary file and a rename.
void write_atomic(const fs::path& path, const std::string& text) {
  fs::path tmp = path;
  tmp += ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw IoError("cannot write '" + tmp.string() + "'");
    out << text;
    if (!out) throw IoError("cannot write '" + tmp.string() + "'");
  }
  fs::rename(tmp, path);
}

void print_list() {
  std::cout << "shapes:\n";
  for (const auto& k : shape_kinds()) {
    std::cout << "  " << std::left << std::setw(26) << k.syntax << k.dimension << "D  "
              << k.description << '\n';
  }
  std::cout << "estimators:\n";
  for (const auto& e : estimators()) {
    std::cout << "  " << std::left << std::setw(14) << e.name
              << (e.dimension == 0 ? std::string("any ") : std::to_string(e.dimension) + "D  ")
              << e.description << "\n"
              << std::string(21, ' ') << "parameters: " << e.parameters << "; error: " << e.quantity
              << '\n';
  }
}

void list_json() {
  nlohmann::json shapes = nlohmann::json::array(), ests = nlohmann::json::array();
  for (const auto& k : shape_kinds()) {
    shapes.push_back({{"name", k.name},
                      {"dimension", k.dimension},
                      {"syntax", k.syntax},
                      {"description", k.description}});
  }
  for (const auto& e : estimators()) {
    ests.push_back({{"name", e.name},
                    {"dimension", e.dimension},
                    {"description", e.description},
                    {"parameters", e.parameters},
                    {"error", e.quantity}});
  }
  print_json({{"shapes", shapes}, {"estimators", ests}});
}

void run_converge(ConvergeOptions o, Context& ctx) {
  if (o.list) {
    if (o.json) {
      list_json();
    } else {
      print_list();
    }
    return;
  }
  if (!o.config_file.empty()) load_toml(o, o.config_file);
  ExperimentConfig config = make_config(o);
  if (o.output.empty() && !o.json) throw InvalidArgument("no output directory given (-o DIR)");
  fs::path dir(o.output);
  if (!o.output.empty()) {
    if (fs::exists(dir) && !fs::is_directory(dir)) {
      throw IoError("'" + o.output + "' exists and is not a directory");
    }
    if (!o.force && (fs::exists(dir / "results.csv") || fs::exists(dir / "summary.json"))) {
      throw IoError("'" + o.output +
                    "' already holds results.csv or summary.json (use --force to replace)");
    }
    fs::create_directories(dir);
  }
  const bool show = !o.quiet && isatty(2) != 0;
  ProgressFn progress;
  if (show) {
    progress = [](std::size_t done, std::size_t total, const RunRecord& r) {
      std::cerr << "\r[" << done << "/" << total << "] " << r.shape << " " << r.estimator
                << " h=" << std::setprecision(4) << r.h << " t=" << r.translation << "   "
                << std::flush;
      if (done == total) std::cerr << '\n';
    };
  }
  ExperimentResult result = run_experiment(config, progress);

  nlohmann::json summary{
      {"config", config_json(config, o)},
      {"fits", fits_json(result)},
      {"all_pass", result.all_pass},
      {"provenance",
       {{"commit", git_commit()},
        {"compiler", compiler()},
        {"integer_types", {"int64 (checked)", "int128 (checked)", "bigint (GMP mpz)"}},
        {"grid_step", "the double nearest to each h, used as an exact dyadic rational"},
        {"seed", config.seed}}}};
  if (!o.output.empty()) {
    std::ostringstream csv;
    write_results_csv(result, csv);
    write_atomic(dir / "results.csv", csv.str());
    write_atomic(dir / "summary.json", summary.dump(2) + "\n");
    if (!o.no_plot) {
      std::string script = source_dir() + "/papers/plot_convergence.py";
      std::string cmd = "/usr/bin/python3 '" + script + "' '" + dir.string() + "' >/dev/null 2>&1";
      if (!fs::exists(script) || std::system(cmd.c_str()) != 0) {
        std::cerr << "zdg: warning: the plot could not be drawn (" << script
                  << " with /usr/bin/python3 and matplotlib)\n";
      }
    }
  }
  if (o.json) {
    print_json({{"runs", runs_json(result)}, {"fits", fits_json(result)}});
  } else {
    int width = 6;
    for (const auto& f : result.fits) width = std::max(width, static_cast<int>(f.shape.size()) + 2);
    std::cout << std::left << std::setw(width) << "shape" << std::setw(15) << "estimator"
              << std::setw(6) << "norm" << std::setw(18) << "slope" << std::setw(10) << "expected"
              << "verdict\n";
    for (const auto& f : result.fits) {
      std::ostringstream slope, expected;
      slope << std::fixed << std::setprecision(3) << f.fit.slope << " +- " << f.fit.stderr_slope;
      if (f.expected) expected << std::fixed << std::setprecision(3) << *f.expected;
      std::cout << std::left << std::setw(width) << f.shape << std::setw(15) << f.estimator
                << std::setw(6) << f.norm << std::setw(18) << slope.str() << std::setw(10)
                << (f.expected ? expected.str() : "-")
                << (f.pass ? (*f.pass ? "PASS" : "FAIL") : "-") << '\n';
    }
    if (!o.output.empty()) {
      std::cout << "results: " << (dir / "results.csv").string()
                << "\nsummary: " << (dir / "summary.json").string()
                << "\nplot:    " << (dir / "convergence.png").string() << '\n';
    }
  }
  if (!result.all_pass) ctx.exit_code = 1;
}

CLI::Validator non_negative_integer() {
  return CLI::Validator(
      [](std::string& text) {
        bool ok = !text.empty() && text.size() <= 18 &&
                  text.find_first_not_of("0123456789") == std::string::npos;
        return ok ? std::string() : "'" + text + "' is not a non-negative integer";
      },
      "INT>=0");
}

void add_run_options(CLI::App* cmd, ConvergeOptions& o) {
  cmd->add_option("-o,--output", o.output, "Output directory (results.csv, summary.json, plot)");
  cmd->add_option("--threads", o.threads, "Worker threads (runs in parallel)")
      ->check(CLI::Range(1, 1024));
  cmd->add_flag("--json", o.json, "Print runs and fits as JSON on stdout");
  cmd->add_flag("--quiet", o.quiet, "No progress on stderr");
  cmd->add_flag("--force", o.force, "Replace results already in the output directory");
  cmd->add_flag("--no-plot", o.no_plot, "Do not draw convergence.png/.svg");
}

} // namespace

void add_converge_commands(CLI::App& app, Context& ctx) {
  {
    auto o = std::make_shared<ConvergeOptions>();
    auto* cmd = app.add_subcommand(
        "converge", "Multigrid convergence experiment: errors against h, fitted rates, checks");
    cmd->add_option("config", o->config_file, "TOML file with the same keys as the flags")
        ->check(CLI::ExistingFile);
    cmd->add_option("--shape", o->shapes, "Shape, e.g. ellipse:20,7 (repeatable; see --list)");
    cmd->add_option("--estimator", o->estimators, "Estimator name (repeatable; see --list)");
    cmd->add_option("--h", o->h, "Grid steps: HMAX:HMIN:N, exp:I0:I1[:STEP] or h1,h2,...");
    cmd->add_option(
        "--k", o->k,
        "Parameter k (R = k h^alpha, mask factor), rational; or one per shape: K1,K2,...");
    cmd->add_option("--alpha", o->alpha, "Exponent alpha of R = k h^alpha, rational");
    cmd->add_option("--translations", o->translations,
                    "Random sub-pixel translations per h (0: untranslated)")
        ->check(non_negative_integer());
    cmd->add_option("--seed", o->seed, "Seed of the translations")->check(non_negative_integer());
    cmd->add_option("--box", o->box, "Digitization domain [LO,HI]^d as LO:HI");
    cmd->add_option("--fit-levels", o->fit_levels, "Fit on the L finest levels (0: all)")
        ->check(non_negative_integer());
    cmd->add_option("--tolerance", o->tolerance, "Slope tolerance of the theory check (0.1)")
        ->check(CLI::Range(0.0, 10.0));
    cmd->add_option("--title", o->title, "Plot title");
    cmd->add_flag("--list", o->list, "List shapes and estimators with their parameters");
    add_run_options(cmd, *o);
    cmd->callback([o, &ctx] { run_converge(*o, ctx); });
  }
  {
    auto o = std::make_shared<ConvergeOptions>();
    auto name = std::make_shared<std::string>();
    auto quick = std::make_shared<bool>(false);
    auto* cmd = app.add_subcommand("paper", "Reproduce one figure of papers/NAME");
    cmd->add_option("name", *name,
                    "cviu2014-ii2d, gauss-area, tangent-2d, cviu2014-ii3d, hausdorff")
        ->required();
    cmd->add_flag("--quick", *quick, "The reduced sweep (papers/NAME/quick.toml)");
    add_run_options(cmd, *o);
    cmd->callback([o, name, quick, &ctx] {
      fs::path dir = fs::path(source_dir()) / "papers" / *name;
      fs::path file = dir / (*quick ? "quick.toml" : "config.toml");
      if (!fs::exists(file)) {
        std::string known;
        if (fs::exists(fs::path(source_dir()) / "papers")) {
          for (const auto& e : fs::directory_iterator(fs::path(source_dir()) / "papers")) {
            if (e.is_directory())
              known += (known.empty() ? "" : ", ") + e.path().filename().string();
          }
        }
        throw InvalidArgument("unknown paper '" + *name + "' (no " + file.string() +
                              "; known: " + known + ")");
      }
      ConvergeOptions opts = *o;
      opts.config_file = file.string();
      run_converge(opts, ctx);
    });
  }
}

} // namespace zdg::cli
