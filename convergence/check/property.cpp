#include <zdg/arith/error.hpp>
#include <zdg/convergence/check/property.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <limits>
#include <mutex>

namespace zdg::check {

int default_bits(IntKind type) {
  switch (type) {
  case IntKind::int64:
    return 64;
  case IntKind::int128:
    return 128;
  case IntKind::bigint:
    return 256;
  }
  return 64;
}

std::string to_string(Cost c) {
  switch (c) {
  case Cost::cheap:
    return "cheap";
  case Cost::moderate:
    return "moderate";
  case Cost::heavy:
    return "heavy";
  }
  return "?";
}

const std::vector<Property>& registry() {
  static const std::vector<Property> all = [] {
    std::vector<Property> v;
    add_arith_properties(v);
    add_dss_properties(v);
    add_hull_properties(v);
    add_image_properties(v);
    add_plane_properties(v);
    std::sort(v.begin(), v.end(),
              [](const Property& a, const Property& b) { return a.name < b.name; });
    return v;
  }();
  return all;
}

const Property& find_property(const std::string& name) {
  for (const auto& p : registry()) {
    if (p.name == name) return p;
  }
  std::string names;
  for (const auto& p : registry()) names += (names.empty() ? "" : ", ") + p.name;
  throw InvalidArgument("check: unknown property '" + name.substr(0, 60) + "' (known: " + names +
                        "; zdg check --list)");
}

void validate_params(const Property& p, const Params& params) {
  if (std::find(p.types.begin(), p.types.end(), params.type) == p.types.end()) {
    std::string types;
    for (auto t : p.types) types += (types.empty() ? "" : ", ") + std::string(to_string(t));
    throw InvalidArgument("check: property " + p.name + " does not run on " +
                          std::string(to_string(params.type)) + " (its types: " + types + ")");
  }
  if (params.bits < 1 || params.bits > 4096) {
    throw InvalidArgument("check: --bits " + std::to_string(params.bits) +
                          " is out of range [1, 4096]");
  }
  if (params.max_size < p.min_max_size || params.max_size > p.max_max_size) {
    throw InvalidArgument("check: --max-size " + std::to_string(params.max_size) + " of " + p.name +
                          " is out of range [" + std::to_string(p.min_max_size) + ", " +
                          std::to_string(p.max_max_size) + "] (" + p.sizes + ")");
  }
}

namespace {

std::optional<std::string> equal_fields(const Record& expected, const Record& got) {
  if (got.has("error") && got.at("error").kind == FieldKind::text) {
    return "the command answered an error: " + got.at("error").texts.at(0);
  }
  for (const auto& f : expected.fields) {
    if (!got.has(f.name)) return "the answer has no field '" + f.name + "'";
    if (f.judged) continue; // the property's judge has checked it
    const Field& g = got.at(f.name);
    if (!(g == f)) {
      return "field '" + f.name + "' is " + to_json(g) + ", the oracle says " + to_json(f);
    }
  }
  return std::nullopt;
}

int served_index(const Record& got) {
  if (!got.has("integer_type")) return -1;
  const std::string& t = got.at("integer_type").texts.at(0);
  if (t == "int64") return 0;
  if (t == "int128") return 1;
  if (t == "bigint") return 2;
  return -1;
}

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// One evaluation where an external failure becomes a failing verdict of its own kind.
struct Outcome {
  Verdict verdict;
  bool external_error = false;
};

Outcome evaluate_caught(const Property& p, const Record& c, IntKind type, AnswerSource* ext) {
  try {
    return {evaluate(p, c, type, ext), false};
  } catch (const ExternalFailure& e) {
    Verdict v;
    v.holds = false;
    v.why = e.what();
    return {v, true};
  }
}

// Greedy shrinking of a failing case (convergence/check/record.hpp).
void shrink(const Property& p, const Params& params, const Options& opt, AnswerSource* ext,
            Failure& f) {
  const auto t0 = Clock::now();
  f.shrunk = f.original;
  bool progress = true;
  while (progress) {
    progress = false;
    for (auto& cand : shrink_candidates(f.shrunk)) {
      if (f.shrink_attempts >= opt.max_shrink_attempts) {
        f.shrink_note = "stopped after " + std::to_string(f.shrink_attempts) + " attempts";
        return;
      }
      if (seconds_since(t0) > opt.max_shrink_s) {
        f.shrink_note = "stopped after " + std::to_string(opt.max_shrink_s) + " s";
        return;
      }
      if (p.valid && !p.valid(cand, params)) continue;
      ++f.shrink_attempts;
      Outcome o = evaluate_caught(p, cand, params.type, ext);
      if (o.external_error && !f.external_error) {
        // The command died on a simpler wrong case: it cannot answer any more.
        f.shrink_note =
            "stopped: the external command failed on a candidate (" + o.verdict.why + ")";
        return;
      }
      if (!o.verdict.holds && o.external_error == f.external_error) {
        f.shrunk = std::move(cand);
        f.verdict = std::move(o.verdict);
        ++f.shrink_steps;
        progress = true;
        break;
      }
      if (o.external_error) {
        f.shrink_note = "stopped: the external command failed (" + o.verdict.why + ")";
        return;
      }
    }
  }
}

} // namespace

void AnswerSource::send_all(const Property&, const std::vector<Record>& requests) {
  kept_.insert(kept_.end(), requests.begin(), requests.end());
}

Answers AnswerSource::receive_all(const Property& p, const std::vector<Record>& schemas) {
  Answers a;
  const std::size_t n = std::min(schemas.size(), kept_.size());
  for (std::size_t j = 0; j < n; ++j) {
    try {
      a.got.push_back(answer(p, kept_[j], schemas[j]));
    } catch (const ExternalFailure& e) {
      a.failure = e.what();
      break;
    }
  }
  kept_.erase(kept_.begin(), kept_.begin() + static_cast<std::ptrdiff_t>(n));
  return a;
}

Verdict judge_answer(const Property& p, const Record& c, Record expected, Record got) {
  Verdict v;
  // The theorem on the answer first (its message says what is wrong), then the oracle.
  std::optional<std::string> why;
  if (p.judge) why = p.judge(c, expected, got);
  if (!why) why = equal_fields(expected, got);
  if (why) {
    v.holds = false;
    v.why = *why;
  }
  v.expected = std::move(expected);
  v.got = std::move(got);
  return v;
}

Verdict evaluate(const Property& p, const Record& c, IntKind type, AnswerSource* external) {
  Verdict v;
  if (p.is_operation()) {
    Record expected;
    try {
      expected = p.oracle(c);
    } catch (const Error& e) {
      throw InvalidArgument("check: the oracle of " + p.name + " refused the case " + to_json(c) +
                            ": " + e.what());
    }
    Record got;
    if (external != nullptr) {
      got = external->answer(p, p.request_of(c), expected);
    } else {
      try {
        got = p.compute(c, type);
      } catch (const Error& e) {
        v.holds = false;
        v.why = std::string("zdg threw: ") + e.what();
        v.expected = std::move(expected);
        return v;
      }
    }
    return judge_answer(p, c, std::move(expected), std::move(got));
  }
  std::optional<std::string> why;
  try {
    why = p.holds(c, type);
  } catch (const Error& e) {
    why = std::string("zdg threw: ") + e.what();
  }
  if (why) {
    v.holds = false;
    v.why = *why;
  }
  return v;
}

std::string make_token(const Params& params, std::uint64_t seed) {
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(seed));
  return std::string(to_string(params.type)) + "." + std::to_string(params.bits) + "." +
         std::to_string(params.max_size) + "." + hex;
}

std::pair<Params, std::uint64_t> parse_token(const std::string& token) {
  auto bad = [&]() -> InvalidArgument {
    return InvalidArgument("check: replay token '" + token.substr(0, 80) +
                           "' is not TYPE.BITS.MAXSIZE.SEED (as printed by a failed zdg check)");
  };
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (;;) {
    auto dot = token.find('.', start);
    parts.push_back(token.substr(start, dot - start));
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  if (parts.size() != 4 || parts[3].size() != 16) throw bad();
  Params params;
  if (parts[0] == "int64") {
    params.type = IntKind::int64;
  } else if (parts[0] == "int128") {
    params.type = IntKind::int128;
  } else if (parts[0] == "bigint") {
    params.type = IntKind::bigint;
  } else {
    throw bad();
  }
  try {
    params.bits = parse_integer<int>(parts[1]);
    params.max_size = parse_integer<std::size_t>(parts[2]);
  } catch (const Error&) {
    throw bad();
  }
  std::uint64_t seed = 0;
  for (char ch : parts[3]) {
    int d = ch >= '0' && ch <= '9' ? ch - '0' : (ch >= 'a' && ch <= 'f' ? ch - 'a' + 10 : -1);
    if (d < 0) throw bad();
    seed = seed * 16 + static_cast<std::uint64_t>(d);
  }
  return {params, seed};
}

Report run_check(const Property& p, const Params& params, const Options& opt) {
  validate_params(p, params);
  if (opt.runs < 0) throw InvalidArgument("check: negative number of runs");
  Report rep;
  rep.property = p.name;
  rep.params = params;
  rep.seed = opt.seed;
  rep.requested = opt.runs;
  const auto t0 = Clock::now();
  const unsigned workers = worker_count(opt.threads, std::max<std::int64_t>(opt.runs, 1));
  std::atomic<std::int64_t> next{0}, done{0};
  std::atomic<std::int64_t> first_fail{std::numeric_limits<std::int64_t>::max()};
  std::atomic<bool> out_of_time{false};
  std::mutex m;
  std::optional<Failure> failure;
  std::array<std::atomic<std::int64_t>, 3> served{};
  std::atomic<unsigned> worker_ids{0};
  parallel_for(workers, workers, [&](std::int64_t) {
    const unsigned id = worker_ids.fetch_add(1);
    std::unique_ptr<AnswerSource> ext;
    if (opt.external) ext = opt.external();
    auto last_progress = Clock::now();
    const std::int64_t block = ext && p.is_operation() ? std::max<std::int64_t>(opt.batch, 1) : 1;
    auto record = [&](std::int64_t k, std::uint64_t s, const Record& c, Outcome o) {
      done.fetch_add(1);
      if (o.verdict.holds) {
        if (o.verdict.got) {
          int i = served_index(*o.verdict.got);
          if (i >= 0) served[static_cast<std::size_t>(i)].fetch_add(1);
        }
        return;
      }
      std::lock_guard<std::mutex> lock(m);
      if (k < first_fail.load()) {
        first_fail = k;
        Failure f;
        f.index = k;
        f.token = make_token(params, s);
        f.original = c;
        f.verdict = std::move(o.verdict);
        f.external_error = o.external_error;
        failure = std::move(f);
      }
    };
    // Batches sent to the external command whose answers are not read yet (at most one).
    struct Batch {
      std::int64_t k0 = 0;
      std::vector<std::uint64_t> seeds;
      std::vector<Record> cases, expected;
    };
    std::optional<Batch> prev;
    // Reads and judges the answers to a batch; false when the command failed.
    auto finish_batch = [&](Batch& b) {
      Answers a = ext->receive_all(p, b.expected);
      for (std::size_t j = 0; j < b.cases.size(); ++j) {
        const auto k = b.k0 + static_cast<std::int64_t>(j);
        if (j < a.got.size()) {
          record(
              k, b.seeds[j], b.cases[j],
              {judge_answer(p, b.cases[j], std::move(b.expected[j]), std::move(a.got[j])), false});
        } else {
          if (a.failure) {
            Verdict v;
            v.holds = false;
            v.why = *a.failure;
            record(k, b.seeds[j], b.cases[j], {std::move(v), true});
          }
          return false;
        }
      }
      return true;
    };
    auto flush = [&]() {
      if (prev) finish_batch(*prev);
      prev.reset();
    };
    for (;;) {
      const std::int64_t k0 = next.fetch_add(block);
      if (k0 >= opt.runs || k0 > first_fail.load()) return flush();
      if (opt.time_budget_s > 0 && seconds_since(t0) > opt.time_budget_s) {
        out_of_time = true;
        return flush();
      }
      const std::int64_t k1 = std::min(opt.runs, k0 + block);
      if (block == 1) {
        const std::uint64_t s = case_seed(opt.seed, static_cast<std::uint64_t>(k0));
        Rng rng(s);
        Record c = p.generate(rng, params);
        record(k0, s, c, evaluate_caught(p, c, params.type, ext.get()));
      } else {
        // Two batches in flight: batch k + 1 is sent before the answers to batch k are read
        // and judged, so that the command is never idle while zdg generates, parses and judges
        // (the oracle of a batch runs while the command answers it).
        Batch b;
        b.k0 = k0;
        std::vector<Record> requests;
        for (std::int64_t k = k0; k < k1; ++k) {
          b.seeds.push_back(case_seed(opt.seed, static_cast<std::uint64_t>(k)));
          Rng rng(b.seeds.back());
          b.cases.push_back(p.generate(rng, params));
          requests.push_back(p.request_of(b.cases.back()));
        }
        ext->send_all(p, requests);
        if (prev && !finish_batch(*prev)) {
          prev.reset();
          return; // the command is gone: the later cases are not run
        }
        for (const auto& c : b.cases) {
          try {
            b.expected.push_back(p.oracle(c));
          } catch (const Error& e) {
            throw InvalidArgument("check: the oracle of " + p.name + " refused the case " +
                                  to_json(c) + ": " + e.what());
          }
        }
        prev = std::move(b);
      }
      if (id == 0 && opt.progress && seconds_since(last_progress) > 0.25) {
        last_progress = Clock::now();
        opt.progress(done.load());
      }
    }
  });
  rep.runs = done.load();
  rep.budget_exhausted = out_of_time.load();
  for (std::size_t i = 0; i < 3; ++i) rep.served[i] = served[i].load();
  if (failure) {
    // The runs after the first failing one do not count.
    if (!failure->external_error) {
      std::unique_ptr<AnswerSource> ext;
      if (opt.external) ext = opt.external();
      shrink(p, params, opt, ext.get(), *failure);
    } else {
      failure->shrunk = failure->original;
      failure->shrink_note = "the external command failed: not shrunk";
    }
    rep.failure = std::move(failure);
  }
  rep.seconds = seconds_since(t0);
  return rep;
}

Report replay_check(const Property& p, const std::string& token, const Options& opt) {
  auto [params, s] = parse_token(token);
  validate_params(p, params);
  Report rep;
  rep.property = p.name;
  rep.params = params;
  rep.requested = 1;
  const auto t0 = Clock::now();
  std::unique_ptr<AnswerSource> ext;
  if (opt.external) ext = opt.external();
  Rng rng(s);
  Record c = p.generate(rng, params);
  Outcome o = evaluate_caught(p, c, params.type, ext.get());
  rep.runs = 1;
  if (!o.verdict.holds) {
    Failure f;
    f.token = token;
    f.original = c;
    f.verdict = o.verdict;
    f.external_error = o.external_error;
    if (!f.external_error) {
      shrink(p, params, opt, ext.get(), f);
    } else {
      f.shrunk = c;
      f.shrink_note = "the external command failed: not shrunk";
    }
    rep.failure = std::move(f);
  } else if (o.verdict.got) {
    int i = served_index(*o.verdict.got);
    if (i >= 0) rep.served[static_cast<std::size_t>(i)] = 1;
  }
  rep.seconds = seconds_since(t0);
  return rep;
}

} // namespace zdg::check
