#include <zdg/convergence/experiment.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/convergence/number_text.hpp>
#include <zdg/convergence/scalar_field.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <numeric>
#include <ostream>
#include <sstream>

namespace zdg {

namespace {

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (;;) {
    auto pos = s.find(sep, start);
    out.push_back(s.substr(start, pos == std::string::npos ? std::string::npos : pos - start));
    if (pos == std::string::npos) return out;
    start = pos + 1;
  }
}

std::string csv_field(const std::string& text) {
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + '"';
}

std::string shown(const std::string& text) {
  return "'" + (text.size() <= 60 ? text : text.substr(0, 57) + "...") + "'";
}

} // namespace

std::vector<double> parse_grid_steps(const std::string& text, const std::string& what) {
  std::vector<double> hs;
  auto parts = split(text, ':');
  if (!parts.empty() && parts[0] == "exp") {
    if (parts.size() < 3 || parts.size() > 4) {
      throw InvalidArgument(what + " " + shown(text) + ": expected exp:I0:I1[:STEP]");
    }
    const auto i0 = parse_integer_in(parts[1], what + " I0", 0, 400);
    const auto i1 = parse_integer_in(parts[2], what + " I1", i0, 400);
    const auto step = parts.size() == 4 ? parse_integer_in(parts[3], what + " STEP", 1, 400) : 1;
    for (auto i = i0; i <= i1; i += step) hs.push_back(std::exp(-static_cast<double>(i) / 10));
  } else if (parts.size() == 3) {
    const double hmax = parse_real_in(parts[0], what + " HMAX", 0.0, 1e6),
                 hmin = parse_real_in(parts[1], what + " HMIN", 0.0, 1e6);
    const auto n = parse_integer_in(parts[2], what + " N", 1, 10000);
    if (hmin > hmax) throw InvalidArgument(what + " " + shown(text) + ": HMIN must be <= HMAX");
    for (std::int64_t i = 0; i < n; ++i) {
      hs.push_back(n == 1 ? hmax : hmax * std::pow(hmin / hmax, double(i) / double(n - 1)));
    }
  } else if (parts.size() == 1) {
    auto items = split(text, ',');
    if (items.size() > 10000) throw InvalidArgument(what + ": more than 10000 grid steps");
    for (const auto& item : items) hs.push_back(parse_real_in(item, what, 0.0, 1e6));
  } else {
    throw InvalidArgument(what + " " + shown(text) +
                          ": expected HMAX:HMIN:N, exp:I0:I1[:STEP] or h1,h2,...");
  }
  for (double h : hs) {
    if (!(h > 0) || h > 1e6)
      throw InvalidArgument(what + " " + shown(text) + ": steps must be > 0");
  }
  return hs;
}

std::vector<std::int64_t> parse_sample_counts(const std::string& text, const std::string& what) {
  constexpr std::int64_t max_count = 100000000;
  std::vector<std::int64_t> ns;
  auto parts = split(text, ':');
  if (!parts.empty() && parts[0] == "exp") {
    if (parts.size() < 3 || parts.size() > 4) {
      throw InvalidArgument(what + " " + shown(text) + ": expected exp:I0:I1[:STEP]");
    }
    const auto i0 = parse_integer_in(parts[1], what + " I0", 0, 180);
    const auto i1 = parse_integer_in(parts[2], what + " I1", i0, 180);
    const auto step = parts.size() == 4 ? parse_integer_in(parts[3], what + " STEP", 1, 180) : 1;
    for (auto i = i0; i <= i1; i += step) {
      ns.push_back(static_cast<std::int64_t>(std::llround(std::exp(static_cast<double>(i) / 10))));
    }
  } else if (parts.size() == 3) {
    const auto lo = parse_integer_in(parts[0], what + " NMIN", 1, max_count),
               hi = parse_integer_in(parts[1], what + " NMAX", lo, max_count);
    const auto n = parse_integer_in(parts[2], what + " COUNT", 1, 10000);
    for (std::int64_t i = 0; i < n; ++i) {
      ns.push_back(
          n == 1 ? lo
                 : static_cast<std::int64_t>(std::llround(
                       double(lo) * std::pow(double(hi) / double(lo), double(i) / double(n - 1)))));
    }
  } else if (parts.size() == 1) {
    auto items = split(text, ',');
    if (items.size() > 10000) throw InvalidArgument(what + ": more than 10000 sample counts");
    for (const auto& item : items) ns.push_back(parse_integer_in(item, what, 1, max_count));
  } else {
    throw InvalidArgument(what + " " + shown(text) +
                          ": expected exp:I0:I1[:STEP], NMIN:NMAX:COUNT or n1,n2,...");
  }
  std::sort(ns.begin(), ns.end());
  ns.erase(std::unique(ns.begin(), ns.end()), ns.end());
  return ns;
}

std::vector<std::string> k_texts_per_shape(const std::string& text, std::size_t shapes,
                                           const std::string& what) {
  std::vector<std::string> ks = split(text, ',');
  for (const auto& item : ks) parse_parameter(item, what);
  if (ks.size() == 1) ks.assign(std::max<std::size_t>(shapes, 1), ks[0]);
  if (ks.size() != shapes) {
    throw InvalidArgument(what + " " + shown(text) + ": expected one value or one per shape (" +
                          std::to_string(shapes) + ")");
  }
  return ks;
}

std::vector<double> parse_k_per_shape(const std::string& text, std::size_t shapes,
                                      const std::string& what) {
  std::vector<double> out;
  for (const auto& k : k_texts_per_shape(text, shapes, what))
    out.push_back(parse_parameter(k, what));
  return out;
}

std::pair<double, double> parse_box(const std::string& text, const std::string& what) {
  auto parts = split(text, ':');
  if (parts.size() != 2) throw InvalidArgument(what + " " + shown(text) + ": expected LO:HI");
  const double lo = parse_real(parts[0], what + " LO"), hi = parse_real(parts[1], what + " HI");
  if (!(lo < hi)) throw InvalidArgument(what + " " + shown(text) + ": LO must be < HI");
  if (std::abs(lo) > 1e9 || std::abs(hi) > 1e9) {
    throw InvalidArgument(what + " " + shown(text) + ": |LO| and |HI| must be at most 1e9");
  }
  return {lo, hi};
}

// --- validation ------------------------------------------------------------------------------

ExperimentPlan plan_experiment(const ExperimentConfig& config) {
  if (config.shapes.empty()) throw InvalidArgument("no shape given (--shape)");
  if (config.estimators.empty()) throw InvalidArgument("no estimator given (--estimator)");
  if (config.hs.empty() && config.samples.empty()) {
    throw InvalidArgument("no grid step given (--h, or --samples for a sampled estimator)");
  }
  if (!config.hs.empty() && !config.samples.empty()) {
    throw InvalidArgument("grid steps (--h) and sample counts (--samples) given together: a "
                          "sweep is over one of them");
  }
  for (auto n : config.samples) {
    if (n < 1 || n > 100000000) throw InvalidArgument("sample counts must be in 1..10^8");
  }
  if (config.translations < 0 || config.translations > 100000) {
    throw InvalidArgument("translations must be in 0..100000");
  }
  if (config.threads > 1024) {
    throw InvalidArgument("threads must be in 0..1024 (0: all cores)");
  }
  if (config.fit_levels < 0 || config.fit_levels == 1 || config.fit_levels > 100000) {
    throw InvalidArgument("fit levels must be 0 (all) or in 2..100000");
  }
  if (!(config.tolerance >= 0 && config.tolerance <= 10)) {
    throw InvalidArgument("tolerance must be a number in [0, 10]");
  }
  for (double h : config.hs) {
    if (!(h > 0 && h <= 1e6)) throw InvalidArgument("grid steps must be in (0, 1e6]");
  }
  ExperimentPlan plan;
  for (const auto& s : config.shapes) {
    auto shape = parse_shape(s);
    for (const auto& other : plan.shapes) {
      if (other->spec() == shape->spec())
        throw InvalidArgument("shape " + shown(s) + " given twice");
    }
    plan.shapes.push_back(std::move(shape));
  }
  const std::vector<std::string> ks = config.k_text
                                          ? k_texts_per_shape(*config.k_text, plan.shapes.size())
                                          : std::vector<std::string>{};
  // An estimator that takes a test function (a text parameter: the Laplace-Beltrami ones) and
  // is given none runs once per function of --function (default: default_test_functions()),
  // as the entries NAME:...,u=F.
  std::vector<std::string> texts;
  bool takes_function = false;
  for (const auto& text : config.estimators) {
    const EstimatorSpec spec = parse_estimator_spec(text);
    const Estimator& e = find_estimator(spec.name);
    const EstimatorParameter* u = nullptr;
    for (const auto& p : e.parameters) {
      if (p.check_text && p.name == "u") u = &p;
    }
    if (u == nullptr) {
      texts.push_back(text);
      continue;
    }
    takes_function = true;
    if (spec.value(u->name)) {
      texts.push_back(text);
      continue;
    }
    const auto functions = config.functions.empty() ? default_test_functions() : config.functions;
    for (const auto& f : functions) {
      texts.push_back(text + (text.find(':') == std::string::npos ? ":" : ",") + u->name + "=" + f);
    }
  }
  if (!config.functions.empty() && !takes_function) {
    throw InvalidArgument("--function is given but no estimator of the experiment takes a test "
                          "function (lb-heat, lb-cotan, lb-combinatorial do)");
  }
  for (const auto& text : texts) {
    EstimatorSpec spec = parse_estimator_spec(text);
    EstimatorEntry entry;
    entry.estimator = &find_estimator(spec.name);
    entry.label = spec.label();
    for (std::size_t i = 0; i < plan.shapes.size(); ++i) {
      entry.shape_parameters.push_back(resolve_parameters(
          spec, ks.empty() ? std::nullopt : std::optional<std::string>(ks[i]), config.alpha_text));
    }
    entry.parameters = entry.shape_parameters.front();
    for (const auto& other : plan.entries) {
      if (other.label == entry.label) {
        throw InvalidArgument("estimator " + shown(entry.label) + " given twice");
      }
    }
    plan.entries.push_back(std::move(entry));
  }
  for (const auto& s : plan.shapes) {
    for (const auto& e : plan.entries) {
      const int d = e.estimator->dimension;
      if (d != 0 && s->dimension() != d) { // 0: any dimension
        throw InvalidArgument("estimator '" + e.label + "' is " + std::to_string(d) +
                              "D but shape '" + s->spec() + "' is " +
                              std::to_string(s->dimension()) + "D");
      }
    }
  }
  for (const auto& e : plan.entries) {
    if (e.estimator->sampled && !config.samples_sweep()) {
      throw InvalidArgument("estimator '" + e.label +
                            "' samples points: it needs sample counts (--samples), not grid "
                            "steps (--h)");
    }
    if (!e.estimator->sampled && config.samples_sweep()) {
      throw InvalidArgument("estimator '" + e.label +
                            "' works on a digitization: it needs grid steps (--h), not sample "
                            "counts (--samples)");
    }
  }
  plan.samples = config.samples;
  std::sort(plan.samples.begin(), plan.samples.end());
  plan.samples.erase(std::unique(plan.samples.begin(), plan.samples.end()), plan.samples.end());
  plan.hs = config.hs;
  std::sort(plan.hs.begin(), plan.hs.end(), std::greater<>());
  plan.hs.erase(std::unique(plan.hs.begin(), plan.hs.end()), plan.hs.end());
  plan.runs_per_level = std::max(1, config.translations);
  return plan;
}

// --- scheduling ------------------------------------------------------------------------------

namespace {

// The digitization domain of one run: --box, else the shape's bounding box (translated, with a
// margin of two steps), else its default domain.
std::vector<std::pair<double, double>> run_box(const ExperimentConfig& config, const Shape& shape,
                                               const std::vector<double>& offset, double h) {
  const auto d = static_cast<std::size_t>(shape.dimension());
  std::vector<std::pair<double, double>> box;
  if (config.box) {
    box.assign(d, *config.box);
  } else if (auto bb = shape.bounding_box()) {
    box = *bb;
    for (std::size_t a = 0; a < box.size(); ++a) {
      box[a].first += offset[a] - 2 * h;
      box[a].second += offset[a] + 2 * h;
    }
  } else {
    box.assign(d, shape.default_domain());
  }
  return box;
}

// The seed of the sampling of repetition `index` (splitmix64 of the pair): reproducible on
// every platform.
std::uint64_t sampling_seed(std::uint64_t seed, int index) {
  std::uint64_t z = seed + 0x9e3779b97f4a7c15ULL * (static_cast<std::uint64_t>(index) + 1);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

bool record_order(const RunRecord& a, const RunRecord& b) {
  if (a.shape_index != b.shape_index) return a.shape_index < b.shape_index;
  if (a.entry_index != b.entry_index) return a.entry_index < b.entry_index;
  if (a.h != b.h) return a.h > b.h;
  if (a.samples != b.samples) return a.samples < b.samples;
  return a.translation < b.translation;
}

} // namespace

std::vector<ExperimentJob> plan_jobs(const ExperimentPlan& plan, const ExperimentConfig& config) {
  // One job per run, except that the entries whose estimators share a computation (the 3D
  // integral invariants) run as one job per (h, shape, translation), one after the other on
  // one thread: their cache then computes the shared part once. As separate jobs (the
  // translations of one entry in a row), a computation of the finest levels of the CVIU 2014
  // 3D sweep (up to 420 MB) was evicted before the next entry needed it and made again.
  std::vector<ExperimentJob> jobs;
  // The levels (h, N), finest first: the smallest h, or the largest N.
  std::vector<std::pair<double, std::int64_t>> levels;
  for (auto it = plan.hs.rbegin(); it != plan.hs.rend(); ++it) levels.emplace_back(*it, 0);
  for (auto it = plan.samples.rbegin(); it != plan.samples.rend(); ++it)
    levels.emplace_back(0.0, *it);
  for (const auto& [h, samples] : levels) {
    for (std::size_t s = 0; s < plan.shapes.size(); ++s) {
      const Shape& shape = *plan.shapes[s];
      double points = static_cast<double>(samples);
      if (samples == 0) {
        points = 1;
        const std::vector<double> origin(static_cast<std::size_t>(shape.dimension()), 0.0);
        for (const auto& [lo, hi] : run_box(config, shape, origin, h)) points *= (hi - lo) / h + 1;
      }
      std::vector<std::vector<std::size_t>> groups; // one entry, or the entries sharing a tag
      for (std::size_t e = 0; e < plan.entries.size(); ++e) {
        const std::string& tag = plan.entries[e].estimator->shared_computation;
        auto group = std::find_if(groups.begin(), groups.end(), [&](const auto& g) {
          return !tag.empty() && plan.entries[g.front()].estimator->shared_computation == tag;
        });
        if (group == groups.end()) {
          groups.push_back({e});
        } else {
          group->push_back(e);
        }
      }
      for (const auto& group : groups) {
        for (int t = 0; t < plan.runs_per_level; ++t) {
          jobs.push_back({s, group, h, samples, t, points * static_cast<double>(group.size())});
        }
      }
    }
  }
  std::stable_sort(jobs.begin(), jobs.end(),
                   [](const ExperimentJob& a, const ExperimentJob& b) { return a.size > b.size; });
  return jobs;
}

std::vector<RunRecord> job_records(const ExperimentPlan& plan, const ExperimentConfig& config,
                                   const ExperimentJob& job) {
  const Shape& shape = *plan.shapes[job.shape];
  std::vector<RunRecord> records;
  for (const std::size_t e : job.entries) {
    const EstimatorEntry& entry = plan.entries[e];
    RunRecord r;
    r.shape_index = job.shape;
    r.entry_index = e;
    r.shape = shape.spec();
    r.estimator = entry.label;
    r.h = job.h;
    r.samples = job.samples;
    r.translation = job.translation;
    r.offset = config.translations == 0 || job.samples > 0
                   ? std::vector<double>(static_cast<std::size_t>(shape.dimension()), 0.0)
                   : random_translation(config.seed, job.translation, shape.dimension(), job.h);
    r.k = entry.on_shape(job.shape).k;
    r.alpha = entry.on_shape(job.shape).alpha;
    records.push_back(std::move(r));
  }
  return records;
}

std::vector<RunRecord> run_job(const ExperimentPlan& plan, const ExperimentConfig& config,
                               const ExperimentJob& job) {
  const Shape& shape = *plan.shapes[job.shape];
  std::vector<RunRecord> records = job_records(plan, config, job);
  for (auto& r : records) {
    const EstimatorParameters& p = plan.entries[r.entry_index].on_shape(job.shape);
    RunInput in{shape,   job.h,    r.offset,    run_box(config, shape, r.offset, job.h),
                r.k,     r.alpha,  p.degree,    p.function,
                p.count, p.choice, job.samples, sampling_seed(config.seed, job.translation),
                p.sigma};
    auto t0 = std::chrono::steady_clock::now();
    r.errors = plan.entries[r.entry_index].estimator->run(in);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!std::isfinite(r.errors.linf) || !std::isfinite(r.errors.l2)) {
      throw Error("estimator '" + r.estimator + "' produced a non-finite error on '" + r.shape +
                  (job.samples > 0 ? "' at N = " + std::to_string(job.samples)
                                   : "' at h = " + std::to_string(job.h)) +
                  " (translation " + std::to_string(job.translation) + ")");
    }
  }
  return records;
}

void sort_runs(std::vector<RunRecord>& runs) {
  std::sort(runs.begin(), runs.end(), record_order);
}

std::vector<RunRecord> run_plan(const ExperimentPlan& plan, const ExperimentConfig& config,
                                const ProgressFn& progress, unsigned* workers) {
  const std::vector<ExperimentJob> jobs = plan_jobs(plan, config);
  std::size_t total = 0;
  for (const auto& job : jobs) total += job.entries.size();
  std::vector<std::vector<RunRecord>> done_jobs(jobs.size());
  std::atomic<std::size_t> done{0};
  std::mutex mutex;
  if (workers != nullptr) *workers = worker_count(config.threads, std::int64_t(jobs.size()));
  parallel_for(std::int64_t(jobs.size()), config.threads, [&](std::int64_t ji) {
    const auto j = static_cast<std::size_t>(ji);
    done_jobs[j] = run_job(plan, config, jobs[j]);
    for (const auto& r : done_jobs[j]) {
      const std::size_t n = done.fetch_add(1) + 1;
      if (progress) {
        std::lock_guard<std::mutex> lock(mutex);
        progress(n, total, r);
      }
    }
  });
  std::vector<RunRecord> records;
  records.reserve(total);
  for (auto& job : done_jobs) {
    for (auto& r : job) records.push_back(std::move(r));
  }
  sort_runs(records);
  return records;
}

// --- aggregation -----------------------------------------------------------------------------

std::vector<LevelErrors> aggregate_levels(std::vector<RunRecord> runs) {
  std::sort(runs.begin(), runs.end(), record_order); // O(n log n); a no-op on run_plan's order
  std::vector<LevelErrors> out;
  for (std::size_t i = 0; i < runs.size();) {
    LevelErrors level;
    level.shape_index = runs[i].shape_index;
    level.entry_index = runs[i].entry_index;
    level.h = runs[i].h;
    level.samples = runs[i].samples;
    double l2 = 0, mean = 0;
    level.elements = runs[i].errors.n;
    std::size_t j = i;
    for (; j < runs.size() && runs[j].shape_index == level.shape_index &&
           runs[j].entry_index == level.entry_index && runs[j].h == level.h &&
           runs[j].samples == level.samples;
         ++j) {
      // The maximum, a NaN included (std::max would drop a NaN that comes second).
      if (!(runs[j].errors.linf <= level.linf)) level.linf = runs[j].errors.linf;
      level.elements = std::min(level.elements, runs[j].errors.n);
      l2 += runs[j].errors.l2;
      mean += runs[j].errors.mean;
    }
    level.runs = static_cast<int>(j - i);
    level.l2 = l2 / level.runs;
    level.mean = mean / level.runs;
    out.push_back(level);
    i = j;
  }
  return out;
}

// --- fitting ---------------------------------------------------------------------------------

std::vector<FitRecord> fit_experiment(const ExperimentPlan& plan,
                                      const std::vector<LevelErrors>& levels, int fit_levels,
                                      double tolerance, bool& all_pass) {
  std::vector<FitRecord> fits;
  // levels are grouped by (shape, entry) with h decreasing (N increasing in a samples sweep):
  // the finest levels are each group's tail.
  for (std::size_t i = 0; i < levels.size();) {
    std::size_t j = i;
    while (j < levels.size() && levels[j].shape_index == levels[i].shape_index &&
           levels[j].entry_index == levels[i].entry_index) {
      ++j;
    }
    const std::size_t n = j - i;
    const std::size_t used = fit_levels == 0 ? n : std::min(n, std::size_t(fit_levels));
    const std::size_t first = j - used;
    const Shape& shape = *plan.shapes[levels[i].shape_index];
    const EstimatorEntry& entry = plan.entries[levels[i].entry_index];
    const auto rate = entry.estimator->proven_rate(shape, entry.on_shape(levels[i].shape_index));
    std::vector<double> hs, linf, l2, mean;
    std::vector<FitLevel> checked;
    const bool sampled = levels[i].samples > 0;
    for (std::size_t k = first; k < j; ++k) {
      const double x = sampled ? static_cast<double>(levels[k].samples) : levels[k].h;
      hs.push_back(x);
      linf.push_back(levels[k].linf);
      l2.push_back(levels[k].l2);
      mean.push_back(levels[k].mean);
      checked.push_back({x, levels[k].linf, levels[k].elements});
    }
    const std::pair<const char*, const std::vector<double>*> norms[] = {
        {"linf", &linf}, {"l2", &l2}, {"mean", &mean}};
    for (const auto& [name, values] : norms) {
      FitRecord f;
      f.shape = shape.spec();
      f.estimator = entry.label;
      f.norm = name;
      f.hs = hs;
      f.fit = fit_loglog(hs, *values);
      if (rate) {
        f.expected = rate->slope;
        f.theory = rate->statement;
        f.hypotheses = rate->hypotheses;
        f.source = rate->source;
        if (std::string(name) == "linf") {
          const RateVerdict v = sampled ? check_rate_in_samples(checked, rate->slope, tolerance)
                                        : check_rate(checked, rate->slope, tolerance);
          f.pass = v.pass;
          f.reason = v.reason;
          all_pass = all_pass && v.pass;
        }
      }
      fits.push_back(std::move(f));
    }
    i = j;
  }
  return fits;
}

ExperimentResult experiment_result(const ExperimentPlan& plan, const ExperimentConfig& config,
                                   std::vector<RunRecord> runs, unsigned threads) {
  ExperimentResult result;
  result.entries = plan.entries;
  sort_runs(runs);
  result.runs = std::move(runs);
  result.threads = threads;
  result.fits = fit_experiment(plan, aggregate_levels(result.runs), config.fit_levels,
                               config.tolerance, result.all_pass);
  return result;
}

ExperimentResult run_experiment(const ExperimentConfig& config, const ProgressFn& progress) {
  const ExperimentPlan plan = plan_experiment(config);
  unsigned threads = 1;
  std::vector<RunRecord> runs = run_plan(plan, config, progress, &threads);
  return experiment_result(plan, config, std::move(runs), threads);
}

void write_results_csv(const ExperimentResult& result, std::ostream& out) {
  const bool sampled = std::any_of(result.runs.begin(), result.runs.end(),
                                   [](const RunRecord& r) { return r.samples > 0; });
  out << "shape,estimator,h,translation,offset,k,alpha,linf,l2,mean,n,seconds"
      << (sampled ? ",samples\n" : "\n");
  out.precision(17);
  for (const auto& r : result.runs) {
    std::ostringstream offset;
    offset.precision(17);
    for (std::size_t i = 0; i < r.offset.size(); ++i) offset << (i > 0 ? " " : "") << r.offset[i];
    // Shapes and entry labels may hold commas: quoted (RFC 4180).
    out << csv_field(r.shape) << ',' << csv_field(r.estimator) << ',';
    if (!sampled) out << r.h;
    out << ',' << r.translation << ",\"" << offset.str() << "\"," << r.k << ',' << r.alpha << ','
        << r.errors.linf << ',' << r.errors.l2 << ',' << r.errors.mean << ',' << r.errors.n << ','
        << r.seconds;
    if (sampled) out << ',' << r.samples;
    out << '\n';
  }
}

} // namespace zdg
