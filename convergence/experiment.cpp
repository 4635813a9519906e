#include <zdg/convergence/experiment.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/arith/rational.hpp>
#include <zdg/convergence/theory.hpp>
#include <zdg/kernel/parallel_for.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <map>
#include <mutex>
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

// A rational (7, -3/4, 0.125) or a decimal in scientific notation (1.7e-4).
double number(const std::string& text, const std::string& what) {
  try {
    return parse_rational<BigInt>(text).to_double();
  } catch (const InvalidArgument&) {
  }
  std::size_t used = 0;
  double v = 0;
  bool ok = text.find_first_of("eE") != std::string::npos &&
            text.find_first_not_of("0123456789.eE+-") == std::string::npos;
  if (ok) {
    try {
      v = std::stod(text, &used);
    } catch (const std::exception&) {
      ok = false;
    }
  }
  if (!ok || used != text.size() || !std::isfinite(v) || (v != 0 && std::abs(v) < 1e-300)) {
    throw InvalidArgument(what + ": '" + text + "' is not a number");
  }
  return v;
}

long integer(const std::string& text, const std::string& what) {
  try {
    return static_cast<long>(parse_integer<Int64>(text).value());
  } catch (const Error&) {
    throw InvalidArgument(what + ": '" + text + "' is not an integer");
  }
}

} // namespace

double parse_parameter(const std::string& text, const std::string& what) {
  double v = number(text, what);
  if (!(v > 0)) throw InvalidArgument(what + " = " + text + " must be > 0");
  return v;
}

std::vector<double> parse_grid_steps(const std::string& text) {
  std::vector<double> hs;
  auto parts = split(text, ':');
  if (!parts.empty() && parts[0] == "exp") {
    if (parts.size() < 3 || parts.size() > 4) {
      throw InvalidArgument("--h '" + text + "': expected exp:I0:I1[:STEP]");
    }
    long i0 = integer(parts[1], "--h I0"), i1 = integer(parts[2], "--h I1");
    long step = parts.size() == 4 ? integer(parts[3], "--h STEP") : 1;
    if (step <= 0 || i1 < i0 || i0 < 0 || i1 > 400) {
      throw InvalidArgument("--h '" + text + "': need 0 <= I0 <= I1 <= 400 and STEP > 0");
    }
    for (long i = i0; i <= i1; i += step) hs.push_back(std::exp(-static_cast<double>(i) / 10));
  } else if (parts.size() == 3) {
    double hmax = parse_parameter(parts[0], "--h HMAX"),
           hmin = parse_parameter(parts[1], "--h HMIN");
    long n = integer(parts[2], "--h N");
    if (n < 1 || n > 10000) throw InvalidArgument("--h '" + text + "': N must be in 1..10000");
    if (hmin > hmax) throw InvalidArgument("--h '" + text + "': HMIN must be <= HMAX");
    for (long i = 0; i < n; ++i) {
      hs.push_back(n == 1 ? hmax : hmax * std::pow(hmin / hmax, double(i) / double(n - 1)));
    }
  } else if (parts.size() == 1) {
    for (const auto& item : split(text, ',')) hs.push_back(parse_parameter(item, "--h"));
  } else {
    throw InvalidArgument("--h '" + text +
                          "': expected HMAX:HMIN:N, exp:I0:I1[:STEP] or h1,h2,...");
  }
  for (double h : hs) {
    if (!(h > 0) || h > 1e6) throw InvalidArgument("--h '" + text + "': steps must be > 0");
  }
  return hs;
}

std::vector<double> parse_k_per_shape(const std::string& text, std::size_t shapes) {
  std::vector<double> ks;
  for (const auto& item : split(text, ',')) ks.push_back(parse_parameter(item, "--k"));
  if (ks.size() == 1) ks.assign(std::max<std::size_t>(shapes, 1), ks[0]);
  if (ks.size() != shapes) {
    throw InvalidArgument("--k '" + text + "': expected one value or one per shape (" +
                          std::to_string(shapes) + ")");
  }
  return ks;
}

std::pair<double, double> parse_box(const std::string& text) {
  auto parts = split(text, ':');
  if (parts.size() != 2) throw InvalidArgument("--box '" + text + "': expected LO:HI");
  double lo = number(parts[0], "--box LO"), hi = number(parts[1], "--box HI");
  if (!(lo < hi)) throw InvalidArgument("--box '" + text + "': LO must be < HI");
  return {lo, hi};
}

ExperimentResult run_experiment(const ExperimentConfig& config, const ProgressFn& progress) {
  if (config.shapes.empty()) throw InvalidArgument("no shape given (--shape)");
  if (config.estimators.empty()) throw InvalidArgument("no estimator given (--estimator)");
  if (config.hs.empty()) throw InvalidArgument("no grid step given (--h)");
  if (config.translations < 0 || config.translations > 100000) {
    throw InvalidArgument("--translations must be in 0..100000");
  }
  if (config.threads < 1 || config.threads > 1024) throw InvalidArgument("--threads must be >= 1");
  if (config.fit_levels < 0 || config.fit_levels == 1) {
    throw InvalidArgument("--fit-levels must be 0 (all) or >= 2");
  }
  std::vector<std::unique_ptr<Shape>> shapes;
  for (const auto& s : config.shapes) shapes.push_back(parse_shape(s));
  const std::vector<double> ks =
      config.k_text ? parse_k_per_shape(*config.k_text, shapes.size()) : std::vector<double>{};
  std::vector<const Estimator*> ests;
  for (const auto& e : config.estimators) ests.push_back(&find_estimator(e));
  for (const auto& s : shapes) {
    for (const auto* e : ests) {
      if (e->dimension != 0 && s->dimension() != e->dimension) { // 0: any dimension
        throw InvalidArgument("estimator '" + e->name + "' is " + std::to_string(e->dimension) +
                              "D but shape '" + s->spec() + "' is " +
                              std::to_string(s->dimension()) + "D");
      }
    }
  }
  std::vector<double> hs = config.hs;
  std::sort(hs.begin(), hs.end(), std::greater<>());
  hs.erase(std::unique(hs.begin(), hs.end()), hs.end());

  // Jobs, finest h first (the longest ones) for load balance.
  struct Job {
    std::size_t shape, est;
    double h;
    int translation;
  };
  std::vector<Job> jobs;
  const int nt = std::max(1, config.translations);
  for (auto it = hs.rbegin(); it != hs.rend(); ++it) {
    for (std::size_t s = 0; s < shapes.size(); ++s) {
      for (std::size_t e = 0; e < ests.size(); ++e) {
        for (int t = 0; t < nt; ++t) jobs.push_back({s, e, *it, t});
      }
    }
  }
  std::vector<RunRecord> records(jobs.size());
  std::atomic<std::size_t> done{0};
  std::mutex mutex;
  parallel_for(
      std::int64_t(jobs.size()), unsigned(std::max(config.threads, 1)), [&](std::int64_t ji) {
        const auto i = std::size_t(ji);
        const Job& job = jobs[i];
        const Shape& shape = *shapes[job.shape];
        const Estimator& est = *ests[job.est];
        const int d = shape.dimension();
        RunRecord r;
        r.shape = shape.spec();
        r.estimator = est.name;
        r.h = job.h;
        r.translation = job.translation;
        r.offset = config.translations == 0
                       ? std::vector<double>(static_cast<std::size_t>(d), 0.0)
                       : random_translation(config.seed, job.translation, d, job.h);
        r.k = config.k_text ? ks[job.shape] : est.default_k;
        r.alpha = config.alpha_text ? number(*config.alpha_text, "--alpha") : est.default_alpha;
        std::vector<std::pair<double, double>> box;
        if (config.box) {
          box.assign(static_cast<std::size_t>(d), *config.box);
        } else if (auto bb = shape.bounding_box()) {
          box = *bb;
          for (std::size_t a = 0; a < box.size(); ++a) {
            box[a].first += r.offset[a] - 2 * job.h;
            box[a].second += r.offset[a] + 2 * job.h;
          }
        } else {
          box.assign(static_cast<std::size_t>(d), shape.default_domain());
        }
        RunInput in{shape, job.h, r.offset, box, r.k, r.alpha};
        auto t0 = std::chrono::steady_clock::now();
        r.errors = est.run(in);
        r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (!std::isfinite(r.errors.linf) || !std::isfinite(r.errors.l2)) {
          throw Error("estimator '" + est.name + "' produced a non-finite error on '" + r.shape +
                      "' at h = " + std::to_string(job.h) + " (translation " +
                      std::to_string(job.translation) + ")");
        }
        records[i] = std::move(r);
        std::size_t n = done.fetch_add(1) + 1;
        if (progress) {
          std::lock_guard<std::mutex> lock(mutex);
          progress(n, jobs.size(), records[i]);
        }
      });

  ExperimentResult result;
  // Rows in the order shape, estimator, h (decreasing), translation.
  for (const auto& s : shapes) {
    for (const auto* e : ests) {
      for (double h : hs) {
        for (int t = 0; t < nt; ++t) {
          for (auto& r : records) {
            if (r.shape == s->spec() && r.estimator == e->name && r.h == h && r.translation == t) {
              result.runs.push_back(r);
            }
          }
        }
      }
      // Fits per norm on the finest levels.
      std::vector<double> lh, linf, l2, mean;
      for (double h : hs) {
        double a = 0, b = 0, c = 0;
        int n = 0;
        for (const auto& r : records) {
          if (r.shape != s->spec() || r.estimator != e->name || r.h != h) continue;
          a = std::max(a, r.errors.linf);
          b += r.errors.l2;
          c += r.errors.mean;
          ++n;
        }
        lh.push_back(h);
        linf.push_back(a);
        l2.push_back(b / n);
        mean.push_back(c / n);
      }
      std::size_t levels = config.fit_levels == 0
                               ? lh.size()
                               : std::min(lh.size(), static_cast<std::size_t>(config.fit_levels));
      auto tail = [&](const std::vector<double>& v) {
        return std::vector<double>(v.end() - static_cast<std::ptrdiff_t>(levels), v.end());
      };
      double alpha = config.alpha_text ? number(*config.alpha_text, "--alpha") : e->default_alpha;
      auto rate = theory_rate(e->name, *s, alpha);
      const std::pair<const char*, const std::vector<double>*> norms[] = {
          {"linf", &linf}, {"l2", &l2}, {"mean", &mean}};
      for (const auto& [name, values] : norms) {
        FitRecord f;
        f.shape = s->spec();
        f.estimator = e->name;
        f.norm = name;
        f.hs = tail(lh);
        f.fit = fit_loglog(f.hs, tail(*values));
        if (rate) {
          f.expected = rate->slope;
          f.theory = rate->statement;
          f.source = rate->source;
          if (std::string(name) == "linf") {
            bool all_zero = std::all_of(values->end() - static_cast<std::ptrdiff_t>(levels),
                                        values->end(), [](double v) { return v == 0; });
            // Fewer than two levels with an error: no slope, hence no verdict (unless the
            // estimator was exact everywhere).
            if (all_zero || f.fit.n >= 2) {
              bool ok = all_zero || f.fit.slope >= rate->slope - config.tolerance;
              f.pass = ok;
              result.all_pass = result.all_pass && ok;
            }
          }
        }
        result.fits.push_back(std::move(f));
      }
    }
  }
  return result;
}

void write_results_csv(const ExperimentResult& result, std::ostream& out) {
  out << "shape,estimator,h,translation,offset,k,alpha,linf,l2,mean,n,seconds\n";
  out.precision(17);
  for (const auto& r : result.runs) {
    std::ostringstream offset;
    offset.precision(17);
    for (std::size_t i = 0; i < r.offset.size(); ++i) offset << (i > 0 ? " " : "") << r.offset[i];
    out << '"' << r.shape << "\"," << r.estimator << ',' << r.h << ',' << r.translation << ",\""
        << offset.str() << "\"," << r.k << ',' << r.alpha << ',' << r.errors.linf << ','
        << r.errors.l2 << ',' << r.errors.mean << ',' << r.errors.n << ',' << r.seconds << '\n';
  }
}

} // namespace zdg
