#include <zdg/convergence/estimator.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/convergence/number_text.hpp>

#include <cmath>
#include <limits>

namespace zdg {

ErrorStats ErrorAccumulator::stats() const {
  ErrorStats s;
  s.n = n_;
  s.linf = linf_;
  if (n_ > 0) {
    s.mean = sum_ / static_cast<double>(n_);
    s.l2 = std::sqrt(sum2_ / static_cast<double>(n_));
  }
  return s;
}

const EstimatorParameter* Estimator::parameter(std::string_view key) const {
  for (const auto& p : parameters) {
    if (p.name == key) return &p;
  }
  return nullptr;
}

std::optional<ProvenRate> Estimator::proven_rate(const Shape& shape,
                                                 const EstimatorParameters& p) const {
  if (!theory.rate) return std::nullopt;
  return theory.rate(shape.shape_class(), p);
}

const std::vector<Estimator>& estimators() {
  static const std::vector<Estimator> all = [] {
    std::vector<Estimator> v;
    detail::register_2d_estimators(v);
    detail::register_3d_estimators(v);
    detail::register_hausdorff_estimators(v);
    detail::register_jet_estimators(v);
    detail::register_calculus_estimators(v);
    detail::register_vcm_cnc_estimators(v);
    detail::register_mdca_estimators(v);
    detail::register_ii_auto_estimators(v);
    detail::register_probing_estimators(v);
    detail::register_spectrum_estimators(v);
    detail::register_reconstruction_estimators(v);
    return v;
  }();
  return all;
}

const Estimator& find_estimator(const std::string& name) {
  std::string names;
  for (const auto& e : estimators()) {
    if (e.name == name) return e;
    names += (names.empty() ? "" : ", ") + e.name;
  }
  throw InvalidArgument("unknown estimator '" +
                        (name.size() <= 40 ? name : name.substr(0, 37) + "...") +
                        "' (known: " + names + ")");
}

double parse_parameter(const std::string& text, const std::string& what) {
  return parse_real_in(text, what, 0.0, std::numeric_limits<double>::max());
}

std::string EstimatorSpec::label() const {
  std::string out = name;
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    out += (i == 0 ? ":" : ",") + parameters[i].first + "=" + parameters[i].second;
  }
  return out;
}

std::optional<std::string> EstimatorSpec::value(std::string_view key) const {
  for (const auto& [k, v] : parameters) {
    if (k == key) return v;
  }
  return std::nullopt;
}

namespace detail {

std::vector<EstimatorParameter> radius_law_parameters() {
  return {{"k", "3", 0.0, 1e6, "radius factor: R = k h^alpha"},
          {"alpha", "1/3", 0.0, 1.0, "exponent of the radius law R = k h^alpha"}};
}

bool is_one_third(double alpha) {
  return std::abs(alpha - 1.0 / 3.0) < 1e-12;
}

} // namespace detail

namespace {

double checked_value(const Estimator& e, const EstimatorParameter& p, const std::string& text,
                     const std::string& origin) {
  const std::string what = origin.empty() ? e.name + " parameter " + p.name : origin;
  if (p.check_text) {
    try {
      p.check_text(text);
    } catch (const InvalidArgument& error) {
      throw InvalidArgument(what + ": " + error.what());
    }
    return 0;
  }
  if (p.closed_below) {
    const double v = parse_real(text, what);
    if (!(v >= p.lo && v <= p.hi)) {
      throw InvalidArgument(what + " = '" + text + "' must be in [" + real_text(p.lo) + ", " +
                            real_text(p.hi) + "]");
    }
    return v;
  }
  const double v = p.open_above ? parse_real(text, what) : parse_real_in(text, what, p.lo, p.hi);
  if (p.open_above && !(v > p.lo && v < p.hi)) {
    throw InvalidArgument(what + " = '" + text + "' must be in (" + real_text(p.lo) + ", " +
                          real_text(p.hi) + ")");
  }
  return v;
}

std::string parameter_names(const Estimator& e) {
  if (e.parameters.empty()) return "it has none";
  std::string out = "its parameters: ";
  for (std::size_t i = 0; i < e.parameters.size(); ++i) {
    out += (i == 0 ? "" : ", ") + e.parameters[i].name;
  }
  return out;
}

} // namespace

EstimatorSpec parse_estimator_spec(std::string_view text) {
  const std::string whole(text);
  const std::string shown =
      "estimator '" + (whole.size() <= 60 ? whole : whole.substr(0, 57) + "...") + "'";
  const auto colon = text.find(':');
  EstimatorSpec spec;
  spec.name = std::string(text.substr(0, colon));
  const Estimator& e = find_estimator(spec.name);
  if (colon == std::string_view::npos) return spec;
  std::string_view rest = text.substr(colon + 1);
  if (rest.empty()) throw InvalidArgument(shown + ": no parameter after ':'");
  std::vector<std::pair<std::string, std::string>> given;
  for (;;) {
    const auto comma = rest.find(',');
    std::string_view item = rest.substr(0, comma);
    const auto eq = item.find('=');
    if (eq == std::string_view::npos || eq == 0 || eq + 1 == item.size()) {
      throw InvalidArgument(shown + ": expected KEY=VALUE, got '" + std::string(item) + "'");
    }
    std::string key(item.substr(0, eq)), value(item.substr(eq + 1));
    const EstimatorParameter* p = e.parameter(key);
    if (p == nullptr) {
      throw InvalidArgument(shown + ": " + e.name + " has no parameter '" + key + "' (" +
                            parameter_names(e) + ")");
    }
    for (const auto& [k, v] : given) {
      if (k == key) throw InvalidArgument(shown + ": parameter '" + key + "' given twice");
    }
    checked_value(e, *p, value, shown + " parameter " + key);
    given.emplace_back(std::move(key), std::move(value));
    if (comma == std::string_view::npos) break;
    rest = rest.substr(comma + 1);
  }
  // The registry's order, so that the label is canonical.
  for (const auto& p : e.parameters) {
    for (auto& kv : given) {
      if (kv.first == p.name) spec.parameters.push_back(std::move(kv));
    }
  }
  return spec;
}

EstimatorParameters resolve_parameters(const EstimatorSpec& spec,
                                       const std::optional<std::string>& default_k,
                                       const std::optional<std::string>& default_alpha) {
  const Estimator& e = find_estimator(spec.name);
  EstimatorParameters out;
  for (const auto& p : e.parameters) {
    std::string text = p.default_text, origin;
    if (auto v = spec.value(p.name)) {
      text = *v;
      origin = "estimator '" + spec.label() + "' parameter " + p.name;
    } else if (p.name == "k" && default_k) {
      text = *default_k;
      origin = "--k (default k of " + e.name + ")";
    } else if (p.name == "alpha" && default_alpha) {
      text = *default_alpha;
      origin = "--alpha (default alpha of " + e.name + ")";
    }
    const double value = checked_value(e, p, text, origin);
    if (p.check_text) {
      (p.name == "u" ? out.function : out.choice) = text;
      continue;
    }
    if (p.name == "k") out.k = value;
    if (p.name == "alpha") out.alpha = value;
    if (p.name == "degree") out.degree = value;
    if (p.name == "n") out.count = value;
    if (p.name == "sigma") out.sigma = value;
  }
  return out;
}

} // namespace zdg
