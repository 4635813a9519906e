// zdg converge and zdg paper: multigrid convergence experiments on the command line.
//
//   zdg converge --shape ellipse:20,7 --estimator ii-curvature --h 0.1:0.01:6 --k 5 -o DIR
//   zdg converge --shape flower:20,7,6 --estimator ii-curvature:k=5
//                --estimator bc-curvature:alpha=14/9 --h exp:30:60:3 -o DIR
//   zdg converge --shape sphere9 --estimator lb-heat --function 'x^2-y^2' --h 2:0.5:3
//   zdg converge CONFIG.toml -o DIR          (same keys as the flags: shape, estimator, h,
//                                            samples, k, alpha, translations, seed, box,
//                                            fit_levels, threads, tolerance, title;
//                                            convergence/config.hpp)
//   zdg converge --shape sphere1 --estimator recon-hausdorff:method=imls
//                --samples exp:60:90:5 -o DIR   (a samples sweep: N points sampled on the
//                                               shape, errors against N; sampled estimators)
//   zdg converge --list
//   mpirun -np P zdg converge ... --mpi   (the runs on P MPI ranks, largest first, gathered
//                                         by rank 0: the same outputs; cli/mpi_sweep.hpp)
//
// Flags and TOML files are read into the same settings and validated by one function
// (validate_experiment_settings): a flag given on the command line overrides the file.
//   zdg paper cviu2014-ii2d -o DIR [--quick] [--mpi]
//   zdg laplacians [--shape sphere1] [--h 0.1] [--operator NAME]... [--cube 20] [--json]
//     (the property table of the Laplacians, convergence/laplacian_comparison.hpp: a markdown
//     table on stdout, or JSON; papers/laplacian-comparison/run.py reads it)
//
// Outputs in DIR: results.csv, summary.json (fits, verdicts, provenance), convergence.png,
// .svg and .html (the interactive page: curves per series, toggles, tooltips, verdicts), all
// three drawn by papers/plot_convergence.py run with /usr/bin/python3; --no-plot skips them.
// When the config file's directory holds a published.csv (papers/NAME/published.csv), its
// curves that match the run are drawn too. Exit status 1 when a theory check fails, 2 for
// bad input.
#include <zdg/arith/error.hpp>
#include <zdg/cli/commands.hpp>
#include <zdg/cli/mpi_session.hpp>
#include <zdg/cli/mpi_sweep.hpp>
#include <zdg/convergence/config.hpp>
#include <zdg/convergence/estimator.hpp>
#include <zdg/convergence/experiment.hpp>
#include <zdg/convergence/laplacian_comparison.hpp>
#include <zdg/convergence/number_text.hpp>
#include <zdg/convergence/shape.hpp>
#include <zdg/kernel/io/output_files.hpp>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <new>
#include <optional>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace zdg::cli {

namespace {

namespace fs = std::filesystem;

// The flags as written (text; checked with the TOML values by validate_experiment_settings).
struct ConvergeOptions {
  std::string config_file;
  std::vector<std::string> shapes, estimators, functions;
  std::optional<std::string> h, samples, k, alpha, box, title, translations, fit_levels, threads,
      seed, tolerance;
  std::string output;
  bool json = false, quiet = false, list = false, force = false, no_plot = false, mpi = false;
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

// The flags as settings, then the file's settings for what the flags do not give, then the
// one validation.
ExperimentConfig make_config(const ConvergeOptions& o) {
  ExperimentSettings s;
  for (const auto& x : o.shapes) s.shapes.push_back({x, "--shape"});
  for (const auto& x : o.estimators) s.estimators.push_back({x, "--estimator"});
  for (const auto& x : o.functions) s.functions.push_back({x, "--function"});
  const std::pair<const std::optional<std::string>*, std::optional<Setting> ExperimentSettings::*>
      flags[] = {{&o.h, &ExperimentSettings::h},
                 {&o.samples, &ExperimentSettings::samples},
                 {&o.k, &ExperimentSettings::k},
                 {&o.alpha, &ExperimentSettings::alpha},
                 {&o.box, &ExperimentSettings::box},
                 {&o.title, &ExperimentSettings::title},
                 {&o.translations, &ExperimentSettings::translations},
                 {&o.seed, &ExperimentSettings::seed},
                 {&o.fit_levels, &ExperimentSettings::fit_levels},
                 {&o.threads, &ExperimentSettings::threads},
                 {&o.tolerance, &ExperimentSettings::tolerance}};
  const char* names[] = {"--h",        "--samples",      "--k",    "--alpha",      "--box",
                         "--title",    "--translations", "--seed", "--fit-levels", "--threads",
                         "--tolerance"};
  for (std::size_t i = 0; i < std::size(flags); ++i) {
    if (*flags[i].first) s.*flags[i].second = Setting{**flags[i].first, names[i]};
  }
  if (!o.config_file.empty()) {
    std::ifstream in(o.config_file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in) throw IoError("cannot read '" + o.config_file + "'");
    s.fill_from(parse_experiment_toml(text.str(), o.config_file));
  }
  return validate_experiment_settings(s);
}

nlohmann::json json_number(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

nlohmann::json runs_json(const ExperimentResult& r) {
  nlohmann::json runs = nlohmann::json::array();
  for (const auto& x : r.runs) {
    nlohmann::json run{{"shape", x.shape},
                       {"estimator", x.estimator},
                       {"h", x.samples > 0 ? nlohmann::json() : nlohmann::json(x.h)},
                       {"translation", x.translation},
                       {"offset", x.offset},
                       {"k", x.k},
                       {"alpha", x.alpha},
                       {"linf", json_number(x.errors.linf)},
                       {"l2", json_number(x.errors.l2)},
                       {"mean", json_number(x.errors.mean)},
                       {"n", x.errors.n},
                       {"seconds", x.seconds}};
    if (x.samples > 0) run["samples"] = x.samples; // a samples sweep (h is then null)
    runs.push_back(std::move(run));
  }
  return runs;
}

// A samples sweep's fits are against log(N): they give samples_min and samples_max (the
// counts of the levels used) in place of h_min and h_max, and `variable` "N" (else "h").
nlohmann::json fits_json(const ExperimentResult& r, bool samples_sweep) {
  nlohmann::json fits = nlohmann::json::array();
  for (const auto& f : r.fits) {
    nlohmann::json j{{"shape", f.shape},
                     {"estimator", f.estimator},
                     {"norm", f.norm},
                     {"slope", json_number(f.fit.slope)},
                     {"stderr", json_number(f.fit.stderr_slope)},
                     {"intercept", json_number(f.fit.intercept)},
                     {"levels", f.fit.n},
                     {"expected", f.expected ? nlohmann::json(*f.expected) : nlohmann::json()},
                     {"pass", f.pass ? nlohmann::json(*f.pass) : nlohmann::json()}};
    if (samples_sweep) {
      j["variable"] = "N";
      j["samples_min"] = f.hs.empty() ? 0 : static_cast<std::int64_t>(f.hs.front());
      j["samples_max"] = f.hs.empty() ? 0 : static_cast<std::int64_t>(f.hs.back());
    } else {
      j["h_min"] = f.hs.empty() ? 0.0 : f.hs.back();
      j["h_max"] = f.hs.empty() ? 0.0 : f.hs.front();
    }
    if (!f.reason.empty()) j["reason"] = f.reason;
    if (f.expected) {
      j["theory"] = f.theory;
      j["hypotheses"] = f.hypotheses;
      j["source"] = f.source;
    }
    fits.push_back(j);
  }
  return fits;
}

// Each estimator entry: its label (the name in results.csv and the fits), the registry
// estimator and the parameters it ran with.
nlohmann::json entries_json(const ExperimentResult& r) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& e : r.entries) {
    nlohmann::json params = nlohmann::json::object();
    for (const auto& p : e.estimator->parameters) {
      if (p.check_text) {
        params[p.name] = p.name == "u" ? e.parameters.function : e.parameters.choice;
      } else {
        params[p.name] = p.name == "k"        ? e.parameters.k
                         : p.name == "degree" ? e.parameters.degree
                         : p.name == "n"      ? e.parameters.count
                         : p.name == "sigma"  ? e.parameters.sigma
                                              : e.parameters.alpha;
      }
    }
    out.push_back({{"label", e.label}, {"estimator", e.estimator->name}, {"parameters", params}});
  }
  return out;
}

nlohmann::json config_json(const ExperimentConfig& c, const ExperimentResult& r,
                           const ConvergeOptions& o) {
  nlohmann::json j{
      {"shapes", c.shapes},
      {"estimators", c.estimators},
      {"functions", c.functions},
      {"entries", entries_json(r)},
      {"h", c.h_text},
      {"hs", c.hs},
      {"k", c.k_text ? nlohmann::json(*c.k_text) : nlohmann::json()},
      {"alpha", c.alpha_text ? nlohmann::json(*c.alpha_text) : nlohmann::json()},
      {"translations", c.translations},
      {"seed", c.seed},
      {"box", c.box ? nlohmann::json({c.box->first, c.box->second}) : nlohmann::json()},
      {"fit_levels", c.fit_levels},
      {"tolerance", c.tolerance},
      {"threads", r.threads},
      {"threads_requested", c.threads},
      {"title", c.title},
      {"config_file", o.config_file}};
  if (c.samples_sweep()) { // the counts of a samples sweep (h and hs are then empty)
    j["samples"] = c.samples_text;
    j["sample_counts"] = c.samples;
  }
  return j;
}

// Writes text to a staging file of an OutputSet.
void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw IoError("cannot write '" + path.string() + "'");
  out << text;
  out.flush();
  if (!out) throw IoError("cannot write '" + path.string() + "' (disk full?)");
}

std::string parameters_text(const Estimator& e) {
  if (e.parameters.empty()) return "none";
  std::string out;
  for (const auto& p : e.parameters) {
    out += (out.empty() ? "" : ", ") + p.name + " = " + p.default_text + " (" + p.meaning + ")";
  }
  return out;
}

// The outputs of a run in DIR (results.csv, summary.json, convergence.png, .svg and .html):
// checked before any work, written to staging files, moved in place together at the end
// (kernel/io/output_files.hpp). A DIR created for the run is removed again when the run fails.
// published: a published.csv whose matching curves the plot and the page draw (none: empty).
class ConvergeOutputs {
public:
  ConvergeOutputs(const std::string& output, bool force, bool plot, fs::path published)
      : dir_(output), published_(std::move(published)) {
    if (fs::exists(dir_) && !fs::is_directory(dir_)) {
      throw IoError("'" + output + "' exists and is not a directory");
    }
    if (!fs::exists(dir_)) {
      // The first missing ancestor is what this run creates (and removes on failure).
      fs::path top = dir_;
      while (top.has_parent_path() && !top.parent_path().empty() && !fs::exists(top.parent_path()))
        top = top.parent_path();
      fs::create_directories(dir_);
      created_ = top;
    }
    try {
      set_ = std::make_unique<OutputSet>(force ? Existing::replace : Existing::refuse);
      csv_ = set_->add(dir_ / "results.csv");
      json_ = set_->add(dir_ / "summary.json");
      if (plot) {
        png_ = set_->add(dir_ / "convergence.png");
        svg_ = set_->add(dir_ / "convergence.svg");
        html_ = set_->add(dir_ / "convergence.html");
      }
    } catch (...) {
      discard();
      throw;
    }
  }
  ~ConvergeOutputs() {
    if (!committed_) discard();
  }
  ConvergeOutputs(const ConvergeOutputs&) = delete;
  ConvergeOutputs& operator=(const ConvergeOutputs&) = delete;

  const fs::path& dir() const { return dir_; }

  // Writes everything to the staging files, draws the plot and the page from them, then
  // commits. A plot that cannot be drawn is a warning: its three outputs are left as they
  // were. Returns whether the plot was drawn.
  bool write(const std::string& csv, const std::string& summary) {
    write_text(csv_, csv);
    write_text(json_, summary);
    if (!png_.empty()) {
      const std::string script = source_dir() + "/papers/plot_convergence.py";
      auto q = [](const fs::path& p) { // a shell word: '...' with each ' as '\''
        std::string w = "'";
        for (char c : p.string()) w += c == '\'' ? std::string("'\\''") : std::string(1, c);
        return w + "'";
      };
      const std::string cmd =
          "/usr/bin/python3 " + q(script) + " --csv " + q(csv_) + " --summary " + q(json_) +
          " --png " + q(png_) + " --svg " + q(svg_) + " --html " + q(html_) +
          (published_.empty() ? std::string() : " --published " + q(published_)) +
          " >/dev/null 2>&1";
      if (!fs::exists(script) || std::system(cmd.c_str()) != 0 || !fs::exists(png_) ||
          !fs::exists(svg_) || !fs::exists(html_)) {
        std::cerr << "zdg: warning: the plot could not be drawn (" << script
                  << " with /usr/bin/python3 and matplotlib"
                  << (published_.empty() ? std::string() : ", " + published_.string())
                  << "); convergence.png, .svg and .html left as they were\n";
        set_->drop(dir_ / "convergence.png");
        set_->drop(dir_ / "convergence.svg");
        set_->drop(dir_ / "convergence.html");
      }
    }
    set_->commit();
    committed_ = true;
    return !png_.empty() && fs::exists(dir_ / "convergence.png");
  }

private:
  fs::path dir_, created_, published_;

  void discard() {
    set_.reset(); // the staging files first
    if (!created_.empty()) {
      std::error_code ec;
      fs::remove_all(created_, ec);
    }
  }
  std::unique_ptr<OutputSet> set_;
  fs::path csv_, json_, png_, svg_, html_;
  bool committed_ = false;
};

// The published curves of a run: the published.csv beside its config file (papers/NAME/),
// none for a run from flags alone.
fs::path published_csv(const ConvergeOptions& o) {
  if (o.config_file.empty()) return {};
  const fs::path p = fs::path(o.config_file).parent_path() / "published.csv";
  return fs::is_regular_file(p) ? p : fs::path();
}

void print_list() {
  std::cout << "shapes:\n";
  for (const auto& k : shape_kinds()) {
    std::cout << "  " << std::left << std::setw(26) << k.syntax << k.dimension << "D  "
              << k.description << '\n';
  }
  std::cout << "estimators (NAME[:KEY=VALUE,...], e.g. bc-curvature:k=1,alpha=14/9):\n";
  for (const auto& e : estimators()) {
    std::cout << "  " << std::left << std::setw(14) << e.name
              << (e.dimension == 0 ? std::string("any ") : std::to_string(e.dimension) + "D  ")
              << e.description << "\n"
              << std::string(21, ' ') << "parameters: " << parameters_text(e)
              << "; error: " << e.quantity << "\n"
              << std::string(21, ' ') << "theory: " << e.theory.summary << '\n';
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
    nlohmann::json params = nlohmann::json::array();
    for (const auto& p : e.parameters) {
      params.push_back({{"name", p.name},
                        {"default", p.default_text},
                        {"range", {p.lo, p.hi}},
                        {"meaning", p.meaning}});
    }
    ests.push_back({{"name", e.name},
                    {"dimension", e.dimension},
                    {"description", e.description},
                    {"parameters", params},
                    {"theory", e.theory.summary},
                    {"error", e.quantity}});
  }
  print_json({{"shapes", shapes}, {"estimators", ests}});
}

// The progress line on stderr (a terminal only, not with --quiet); none otherwise.
ProgressFn progress_line(const ConvergeOptions& o) {
  if (o.quiet || isatty(2) == 0) return {};
  return [](std::size_t done, std::size_t total, const RunRecord& r) {
    std::cerr << "\r[" << done << "/" << total << "] " << r.shape << " " << r.estimator;
    if (r.samples > 0) {
      std::cerr << " N=" << r.samples;
    } else {
      std::cerr << " h=" << std::setprecision(4) << r.h;
    }
    std::cerr << " t=" << r.translation << "   " << std::flush;
    if (done == total) std::cerr << '\n';
  };
}

// Writes the outputs of a finished experiment (results.csv, summary.json, the plot: committed
// together) and prints its fits (text or --json). Returns the exit status: 1 when a theory
// check failed, 0 otherwise.
int report_converge(const ConvergeOptions& o, const ExperimentConfig& config,
                    const ExperimentResult& result, ConvergeOutputs* outputs) {
  const fs::path dir(o.output);
  nlohmann::json summary{
      {"config", config_json(config, result, o)},
      {"fits", fits_json(result, config.samples_sweep())},
      {"all_pass", result.all_pass},
      {"provenance",
       {{"commit", git_commit()},
        {"compiler", compiler()},
        {"integer_types", {"int64 (checked)", "int128 (checked)", "bigint (GMP mpz)"}},
        {"grid_step", "the double nearest to each h, used as an exact dyadic rational"},
        {"seed", config.seed}}}};
  bool plotted = false; // the plot line is printed only for a plot that was drawn
  if (outputs != nullptr) {
    std::ostringstream csv;
    write_results_csv(result, csv);
    plotted = outputs->write(csv.str(), summary.dump(2) + "\n");
  }
  if (o.json) {
    print_json({{"runs", runs_json(result)}, {"fits", fits_json(result, config.samples_sweep())}});
  } else {
    int width = 6;
    int ewidth = 15;
    for (const auto& f : result.fits) {
      width = std::max(width, static_cast<int>(f.shape.size()) + 2);
      ewidth = std::max(ewidth, static_cast<int>(f.estimator.size()) + 2);
    }
    std::cout << std::left << std::setw(width) << "shape" << std::setw(ewidth) << "estimator"
              << std::setw(6) << "norm" << std::setw(18) << "slope" << std::setw(10) << "expected"
              << "verdict\n";
    for (const auto& f : result.fits) {
      std::ostringstream slope, expected;
      slope << std::fixed << std::setprecision(3) << f.fit.slope << " +- " << f.fit.stderr_slope;
      if (f.expected) expected << std::fixed << std::setprecision(3) << *f.expected;
      std::cout << std::left << std::setw(width) << f.shape << std::setw(ewidth) << f.estimator
                << std::setw(6) << f.norm << std::setw(18) << slope.str() << std::setw(10)
                << (f.expected ? expected.str() : "-")
                << (f.pass ? (*f.pass ? "PASS" : "FAIL") : "-")
                << (f.reason.empty() ? "" : " (" + f.reason + ")") << '\n';
    }
    if (!o.output.empty()) {
      std::cout << "results: " << (dir / "results.csv").string()
                << "\nsummary: " << (dir / "summary.json").string() << '\n';
      if (plotted) {
        std::cout << "plot:    " << (dir / "convergence.png").string()
                  << "\npage:    " << (dir / "convergence.html").string() << '\n';
      }
    }
  }
  return result.all_pass ? 0 : 1;
}

// A failure's one line, as cli/main.cpp prints an error (for the MPI ranks, which print their
// own: a rank that fails must not leave the others waiting).
std::string error_line(const std::string& what) {
  std::string line = "zdg: " + (what.empty() ? std::string("unknown error") : what);
  for (char& c : line) {
    if (c == '\n' || c == '\r' || c == '\t') c = ' ';
  }
  return line;
}

// `zdg converge|paper ... --mpi` (issue #40, cli/mpi_sweep.hpp): one rank of an MPI job. Every
// rank validates the experiment (the same flags and files: the same plan) and rank 0 checks its
// outputs (creating DIR); a failure there is agreed on and reported once, by the lowest rank
// that met it. The runs are handed out by rank 0 and gathered there; rank 0 alone writes the
// outputs (staged, committed together) and prints. A rank's failure in a run: rank 0 prints
// its line, removes the staged outputs (and a DIR it created), then every rank exits with 2.
void run_converge_mpi(const ConvergeOptions& o, Context& ctx) {
  MpiSession mpi; // refuses a zdg built without MPI, or a process not started by mpirun
  const int rank = mpi.rank(), P = mpi.size();
  if (o.list) {
    if (rank == 0) {
      if (o.json) {
        list_json();
      } else {
        print_list();
      }
    }
    return;
  }
  std::string failure;
  ExperimentConfig config;
  std::optional<ExperimentPlan> plan;
  std::unique_ptr<ConvergeOutputs> outputs;
  try {
    config = make_config(o);
    if (o.output.empty() && !o.json) throw InvalidArgument("no output directory given (-o DIR)");
    plan.emplace(plan_experiment(config));
    if (rank == 0 && !o.output.empty()) {
      outputs = std::make_unique<ConvergeOutputs>(o.output, o.force, !o.no_plot, published_csv(o));
    }
  } catch (const std::bad_alloc&) {
    failure = "out of memory";
  } catch (const std::exception& e) {
    failure = e.what();
    if (failure.empty()) failure = "unknown error";
  }
  const auto first_failed = static_cast<int>(mpi.min_over_ranks(failure.empty() ? P : rank));
  if (first_failed < P) {
    if (rank == first_failed) std::cerr << error_line(failure) << std::endl;
    outputs.reset(); // rank 0's staged files and created DIR, before any rank exits
    mpi.max_over_ranks(0);
    ctx.exit_code = 2;
    return;
  }
  RankSweep sweep =
      run_plan_on_ranks(mpi, *plan, config, rank == 0 ? progress_line(o) : ProgressFn());
  int status = 0;
  if (rank == 0) {
    try {
      if (!sweep.failure.empty()) throw Error(sweep.failure);
      status = report_converge(
          o, config, experiment_result(*plan, config, std::move(sweep.runs), sweep.threads),
          outputs.get());
    } catch (const std::bad_alloc&) {
      std::cerr << error_line("out of memory") << std::endl;
      status = 2;
    } catch (const std::exception& e) {
      std::cerr << error_line(e.what()) << std::endl;
      status = 2;
    }
    outputs.reset(); // (committed, or removed with a DIR it created)
    std::cout.flush();
  }
  ctx.exit_code = finish_on_ranks(mpi, status);
}

void run_converge(ConvergeOptions o, Context& ctx) {
  if (o.mpi) {
    run_converge_mpi(o, ctx);
    return;
  }
  if (o.list) {
    if (o.json) {
      list_json();
    } else {
      print_list();
    }
    return;
  }
  ExperimentConfig config = make_config(o);
  if (o.output.empty() && !o.json) throw InvalidArgument("no output directory given (-o DIR)");
  // Every output is checked (and DIR created) before any work.
  std::unique_ptr<ConvergeOutputs> outputs;
  if (!o.output.empty()) {
    outputs = std::make_unique<ConvergeOutputs>(o.output, o.force, !o.no_plot, published_csv(o));
  }
  const ExperimentResult result = run_experiment(config, progress_line(o));
  if (report_converge(o, config, result, outputs.get()) != 0) ctx.exit_code = 1;
}

// A flag kept as text when given (its value is checked with the TOML values).
void add_text_option(CLI::App* cmd, const std::string& name, std::optional<std::string>& target,
                     const std::string& help) {
  cmd->add_option_function<std::string>(
      name, [&target](const std::string& v) { target = v; }, help);
}

void add_run_options(CLI::App* cmd, ConvergeOptions& o) {
  cmd->add_option("-o,--output", o.output,
                  "Output directory (results.csv, summary.json, plot, page)");
  add_text_option(cmd, "--threads", o.threads,
                  "Worker threads (runs in parallel), 0..1024 (default 0: all cores)");
  cmd->add_flag("--json", o.json, "Print runs and fits as JSON on stdout");
  cmd->add_flag("--quiet", o.quiet, "No progress on stderr");
  cmd->add_flag("--force", o.force, "Replace results already in the output directory");
  cmd->add_flag("--no-plot", o.no_plot, "Do not draw convergence.png/.svg/.html");
  cmd->add_flag("--mpi", o.mpi,
                "One rank of an MPI job (mpirun -np P zdg ... --mpi): the runs handed out to "
                "the ranks, largest first; rank 0 writes the same outputs (--threads: per rank, "
                "0: the cores shared among the ranks of a machine)");
}

} // namespace

namespace {

// A figure whose study is not a sweep of `zdg converge` (papers/NAME/run.py: it runs zdg's
// commands on volumes it makes itself, as a user would) runs its script with this zdg:
//   /usr/bin/python3 papers/NAME/run.py -o DIR [--quick] --zdg <this executable>
// The output folder is checked as converge checks its own (given, and refused when it holds a
// summary.json unless --force); the script's exit status is the command's.
void run_paper_script(const fs::path& script, const std::string& output, bool quick, bool force) {
  if (output.empty())
    throw InvalidArgument("zdg paper " + script.parent_path().filename().string() +
                          " needs -o DIR (its script writes its figure and summary there)");
  if (fs::exists(fs::path(output) / "summary.json") && !force)
    throw IoError((fs::path(output) / "summary.json").string() + ": exists (use --force)");
  auto q = [](const std::string& w0) { // a shell word: '...' with each ' as '\''
    std::string w = "'";
    for (char c : w0) w += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return w + "'";
  };
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  const std::string cmd = "/usr/bin/python3 " + q(script.string()) + " -o " + q(output) +
                          (quick ? " --quick" : "") +
                          (ec ? std::string() : " --zdg " + q(self.string()));
  std::cout.flush();
  const int status = std::system(cmd.c_str());
  if (status != 0)
    throw Error(script.string() + " failed (exit status " +
                std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : status) + ")");
}

} // namespace

namespace {

struct LaplaciansOptions {
  std::string shape = "sphere1", h = "0.1", cube = "20";
  std::vector<std::string> operators;
  bool json = false;
};

void run_laplacians(const LaplaciansOptions& o) {
  LaplacianComparisonSettings s;
  s.shape = o.shape;
  s.h = parse_real_in(o.h, "--h", 0, 1e6);
  s.cube_half_side = parse_real_in(o.cube, "--cube", 0, 1000);
  s.operators = o.operators;
  const auto rows = measure_laplacian_properties(s);
  if (o.json) {
    nlohmann::json ops = nlohmann::json::array();
    for (const auto& r : rows) {
      ops.push_back({{"operator", r.op},
                     {"estimator", r.estimator},
                     {"elements", r.elements},
                     {"size", r.size},
                     {"constants", r.constants},
                     {"asymmetry", r.asymmetry},
                     {"mean_row_entries", r.mean_row_entries},
                     {"max_row_entries", r.max_row_entries},
                     {"support_radius", r.support_radius},
                     {"negative_fraction", r.negative_fraction},
                     {"min_weight", r.min_weight},
                     {"linear_defect", r.linear_defect},
                     {"linear_points", r.linear_points}});
    }
    print_json({{"shape", s.shape},
                {"h", s.h},
                {"cube",
                 {{"half_side", s.cube_half_side},
                  {"h", 1},
                  {"rotation", "0.5 rad about (1, 2, 3)"},
                  {"gradient", {0.48, -0.6, 0.64}}}},
                {"operators", ops}});
    return;
  }
  std::cout
      << "shape " << s.shape << ", h = " << s.h << "; linear u on the faces of a rotated cube"
      << " of half-side " << s.cube_half_side << " at h = 1\n\n"
      << "| operator | rows | max abs(L 1) | asymmetry of W L | entries per row (mean, max) | "
         "support / h | negative weights | min weight | linear u: max abs(L u) |\n"
      << "|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows) {
    char line[512];
    std::snprintf(line, sizeof line,
                  "| %s | %lld | %.1e | %.1e | %.2f, %lld | %.3g | %.3g | %.2e | %.3g |\n",
                  r.op.c_str(), static_cast<long long>(r.size), r.constants, r.asymmetry,
                  r.mean_row_entries, static_cast<long long>(r.max_row_entries), r.support_radius,
                  r.negative_fraction, r.min_weight, r.linear_defect);
    std::cout << line;
  }
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
    cmd->add_option("--estimator", o->estimators,
                    "Estimator with its own parameters, NAME[:KEY=VALUE,...], e.g. "
                    "bc-curvature:k=1,alpha=14/9 (repeatable; see --list)");
    cmd->add_option("--function", o->functions,
                    "Test function u(x, y, z) of the estimators that take one (lb-heat, "
                    "lb-cotan, lb-combinatorial), e.g. 'x^2-y^2' (repeatable; default: x, "
                    "x^2-y^2, exp(z))");
    add_text_option(cmd, "--h", o->h, "Grid steps: HMAX:HMIN:N, exp:I0:I1[:STEP] or h1,h2,...");
    add_text_option(cmd, "--samples", o->samples,
                    "Sample counts N in place of --h (the sampled estimators, recon-*): "
                    "exp:I0:I1[:STEP] (N = round(exp(i/10))), NMIN:NMAX:COUNT (geometric) or "
                    "n1,n2,...; the fit is against log(N)");
    add_text_option(
        cmd, "--k", o->k,
        "Default k of every estimator that has one (R = k h^alpha, mask factor); or one "
        "per shape, K1,K2,... in the order of --shape");
    add_text_option(cmd, "--alpha", o->alpha,
                    "Default alpha of every estimator that has one (R = k h^alpha, mask exponent)");
    add_text_option(cmd, "--translations", o->translations,
                    "Random sub-pixel translations per h (0: untranslated), 0..100000");
    add_text_option(cmd, "--seed", o->seed, "Seed of the translations");
    add_text_option(cmd, "--box", o->box, "Digitization domain [LO,HI]^d as LO:HI");
    add_text_option(cmd, "--fit-levels", o->fit_levels, "Fit on the L finest levels (0: all)");
    add_text_option(cmd, "--tolerance", o->tolerance,
                    "Slope tolerance of the theory check, in [0, 10] (0.1)");
    add_text_option(cmd, "--title", o->title, "Plot title");
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
                    "a folder of papers/: cviu2014-ii2d, cviu2014-compare, gauss-area, "
                    "tangent-2d, cviu2014-ii3d, hausdorff, lb-digital, at-normals, "
                    "laplacian-comparison, reconstruction (scripts: "
                    "needs -o DIR)")
        ->required();
    cmd->add_flag("--quick", *quick, "The reduced sweep (papers/NAME/quick.toml)");
    add_run_options(cmd, *o);
    cmd->callback([o, name, quick, &ctx] {
      fs::path dir = fs::path(source_dir()) / "papers" / *name;
      fs::path file = dir / (*quick ? "quick.toml" : "config.toml");
      if (!fs::exists(file) && fs::exists(dir / "run.py")) {
        if (o->mpi) { // refused once, by rank 0
          MpiSession mpi;
          if (mpi.rank() != 0) {
            ctx.exit_code = 2;
            return;
          }
          throw InvalidArgument("--mpi: zdg paper " + *name + " runs a script (papers/" + *name +
                                "/run.py), not a sweep; run it without --mpi");
        }
        run_paper_script(dir / "run.py", o->output, *quick, o->force);
        return;
      }
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
  {
    auto o = std::make_shared<LaplaciansOptions>();
    auto* cmd = app.add_subcommand(
        "laplacians",
        "Property table of the Laplacians on a digital surface (Wardetzky et al. 2007)");
    cmd->add_option("--shape", o->shape, "Closed 3D shape of zdg converge (default sphere1)");
    cmd->add_option("--h", o->h, "Grid step of the shape (default 0.1)");
    cmd->add_option("--operator", o->operators,
                    "cotan, cotan-mc, meanvalue, idt, polygonal, heat, combinatorial "
                    "(repeatable; default: all)");
    cmd->add_option("--cube", o->cube,
                    "Half-side in voxels of the rotated cube whose faces measure linear "
                    "precision (default 20)");
    cmd->add_flag("--json", o->json, "Print the table as JSON");
    cmd->callback([o] { run_laplacians(*o); });
  }
}

} // namespace zdg::cli
