#include <zdg/convergence/config.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/convergence/number_text.hpp>
#include <zdg/convergence/scalar_field.hpp>

#include <toml++/toml.h>

#include <cstdint>
#include <limits>
#include <sstream>

namespace zdg {

void ExperimentSettings::fill_from(const ExperimentSettings& file) {
  if (shapes.empty()) shapes = file.shapes;
  if (estimators.empty()) estimators = file.estimators;
  if (functions.empty()) functions = file.functions;
  for (auto member : {&ExperimentSettings::h, &ExperimentSettings::samples, &ExperimentSettings::k,
                      &ExperimentSettings::alpha, &ExperimentSettings::box,
                      &ExperimentSettings::title, &ExperimentSettings::translations,
                      &ExperimentSettings::seed, &ExperimentSettings::fit_levels,
                      &ExperimentSettings::threads, &ExperimentSettings::tolerance}) {
    if (!(this->*member)) this->*member = file.*member;
  }
}

namespace {

class TomlReader {
public:
  explicit TomlReader(std::string source) : source_(std::move(source)) {}

  ExperimentSettings read(std::string_view text) {
    toml::table table;
    try {
      table = toml::parse(text, source_);
    } catch (const toml::parse_error& e) {
      std::ostringstream msg;
      msg << source_ << ":" << e.source().begin.line << ": " << e.description();
      throw InvalidArgument(one_line(msg.str()));
    }
    ExperimentSettings s;
    for (const auto& [key_view, node] : table) {
      const std::string key(key_view.str());
      if (key == "shape" || key == "shapes") {
        once(key, "shape", !s.shapes.empty(), node);
        s.shapes = list(node, key, false);
      } else if (key == "estimator" || key == "estimators") {
        once(key, "estimator", !s.estimators.empty(), node);
        s.estimators = list(node, key, true);
      } else if (key == "function" || key == "functions") {
        once(key, "function", !s.functions.empty(), node);
        s.functions = list(node, key, false);
      } else if (key == "h") {
        s.h = node.is_array() ? joined(node, key, ",") : value(node, key);
      } else if (key == "samples") {
        s.samples = node.is_array() ? joined(node, key, ",") : value(node, key);
      } else if (key == "k" && node.is_array()) { // one k per shape
        once(key, "k", s.k.has_value(), node);
        s.k = joined(node, key, ",");
      } else if (key == "box") {
        s.box = node.is_array() ? joined(node, key, ":") : value(node, key);
      } else if (key == "fit_levels" || key == "fit-levels") {
        once(key, "fit_levels", s.fit_levels.has_value(), node);
        s.fit_levels = value(node, key);
      } else {
        std::optional<Setting>* slot = key == "k"              ? &s.k
                                       : key == "alpha"        ? &s.alpha
                                       : key == "title"        ? &s.title
                                       : key == "translations" ? &s.translations
                                       : key == "seed"         ? &s.seed
                                       : key == "threads"      ? &s.threads
                                       : key == "tolerance"    ? &s.tolerance
                                                               : nullptr;
        if (slot == nullptr) {
          fail(node, "unknown key '" + shown(key) +
                         "' (known: shape, estimator, function, h, samples, k, alpha, box, "
                         "translations, seed, fit_levels, threads, tolerance, title)");
        }
        *slot = value(node, key);
      }
    }
    return s;
  }

private:
  std::string source_;

  static std::string shown(const std::string& text) {
    return text.size() <= 40 ? text : text.substr(0, 37) + "...";
  }
  static std::string one_line(std::string text) {
    for (char& c : text) {
      if (c == '\n' || c == '\r') c = ' ';
    }
    return text;
  }
  std::string where(const toml::node& node) const {
    return source_ + ":" + std::to_string(node.source().begin.line);
  }
  [[noreturn]] void fail(const toml::node& node, const std::string& what) const {
    throw InvalidArgument(one_line(where(node) + ": " + what));
  }
  void once(const std::string& key, const std::string& name, bool given,
            const toml::node& node) const {
    if (given) fail(node, "key '" + key + "': " + name + " given twice");
  }

  // A scalar as text: strings as written, numbers in the shortest form that reads back.
  std::string scalar(const toml::node& node, const std::string& what) const {
    if (auto s = node.value_exact<std::string>()) return *s;
    if (const auto* i = node.as_integer()) {
      // TOML's 0x.., 0o.., 0b.. integers: zdg's numbers are decimal everywhere.
      // The base is a two-bit field of the flags (binary 1, octal 2, hexadecimal 3).
      const toml::value_flags f = i->flags() & toml::value_flags::format_as_hexadecimal;
      const char* base = f == toml::value_flags::format_as_hexadecimal ? "a hexadecimal"
                         : f == toml::value_flags::format_as_octal     ? "an octal"
                         : f == toml::value_flags::format_as_binary    ? "a binary"
                                                                       : nullptr;
      if (base != nullptr) {
        fail(node, what + " is " + base + " integer: zdg reads decimal numbers only (write " +
                       std::to_string(i->get()) + " if that value is meant)");
      }
      return std::to_string(i->get());
    }
    if (auto d = node.value_exact<double>()) return real_text(*d);
    fail(node, what + " must be a string or a number");
  }
  Setting value(const toml::node& node, const std::string& key) const {
    return {scalar(node, "key '" + key + "'"), where(node) + ": key '" + key + "'"};
  }
  Setting joined(const toml::node& node, const std::string& key, const char* sep) const {
    std::string text;
    const auto& arr = *node.as_array();
    for (std::size_t i = 0; i < arr.size(); ++i) {
      text += (i == 0 ? "" : sep) + scalar(arr[i], "key '" + key + "' element");
    }
    return {text, where(node) + ": key '" + key + "'"};
  }
  // An estimator table { name = "...", k = ..., alpha = ... } as the spec NAME:k=..,alpha=..
  std::string estimator_table(const toml::table& t, const std::string& what) const {
    std::string name, params;
    for (const auto& [k, v] : t) {
      const std::string key(k.str());
      if (key == "name") {
        auto s = v.value_exact<std::string>();
        if (!s) fail(v, what + ": 'name' must be a string");
        name = *s;
      } else if (key == "k" || key == "alpha") {
        params += (params.empty() ? "" : ",") + key + "=" + scalar(v, what + " '" + key + "'");
      } else {
        fail(v, what + ": unknown key '" + shown(key) + "' (name, k, alpha)");
      }
    }
    if (name.empty()) fail(t, what + ": no 'name'");
    return params.empty() ? name : name + ":" + params;
  }
  std::vector<Setting> list(const toml::node& node, const std::string& key, bool tables) const {
    std::vector<Setting> out;
    auto one = [&](const toml::node& n, const std::string& what) {
      if (tables && n.is_table()) {
        out.push_back({estimator_table(*n.as_table(), what), where(n) + ": " + what});
      } else {
        out.push_back({scalar(n, what), where(n) + ": " + what});
      }
    };
    if (const auto* arr = node.as_array()) {
      if (arr->empty()) fail(node, "key '" + key + "' is an empty array");
      for (std::size_t i = 0; i < arr->size(); ++i) {
        one((*arr)[i], "key '" + key + "' element " + std::to_string(i + 1));
      }
    } else {
      one(node, "key '" + key + "'");
    }
    return out;
  }
};

// Runs a check of a shape or estimator text; a file's setting prefixes its origin to the
// message (a flag's message already names the value).
template <class F>
void checked(const Setting& s, F&& f) {
  try {
    f(s.text);
  } catch (const InvalidArgument& e) {
    if (s.origin.rfind("--", 0) == 0) throw;
    throw InvalidArgument(s.origin + ": " + e.what());
  }
}

} // namespace

ExperimentSettings parse_experiment_toml(std::string_view text, const std::string& source) {
  return TomlReader(source).read(text);
}

ExperimentConfig validate_experiment_settings(const ExperimentSettings& s) {
  ExperimentConfig c;
  if (s.shapes.empty()) throw InvalidArgument("no shape given (--shape or key 'shape')");
  if (s.estimators.empty()) {
    throw InvalidArgument("no estimator given (--estimator or key 'estimator')");
  }
  if (!s.h && !s.samples) {
    throw InvalidArgument("no grid steps given (--h or key 'h'; --samples or key 'samples' for "
                          "the sampled estimators)");
  }
  if (s.h && s.samples) {
    throw InvalidArgument(s.h->origin + " and " + s.samples->origin +
                          " given together: a sweep is over grid steps or over sample counts");
  }
  for (const auto& x : s.shapes) c.shapes.push_back(x.text);
  for (const auto& x : s.estimators) c.estimators.push_back(x.text);
  if (s.h) {
    c.hs = parse_grid_steps(s.h->text, s.h->origin);
    c.h_text = s.h->text;
  } else {
    c.samples = parse_sample_counts(s.samples->text, s.samples->origin);
    c.samples_text = s.samples->text;
  }
  if (s.k) {
    // positive and finite, one or one per shape; ranges per entry
    k_texts_per_shape(s.k->text, s.shapes.size(), s.k->origin);
    c.k_text = s.k->text;
  }
  if (s.alpha) {
    parse_parameter(s.alpha->text, s.alpha->origin);
    c.alpha_text = s.alpha->text;
  }
  if (s.box) c.box = parse_box(s.box->text, s.box->origin);
  if (s.translations) {
    c.translations =
        static_cast<int>(parse_integer_in(s.translations->text, s.translations->origin, 0, 100000));
  }
  if (s.seed) {
    c.seed = static_cast<std::uint64_t>(parse_integer_in(s.seed->text, s.seed->origin, 0,
                                                         std::numeric_limits<std::int64_t>::max()));
  }
  if (s.fit_levels) {
    c.fit_levels =
        static_cast<int>(parse_integer_in(s.fit_levels->text, s.fit_levels->origin, 0, 100000));
    if (c.fit_levels == 1) {
      throw InvalidArgument(s.fit_levels->origin + " = 1: a fit needs 0 (all levels) or >= 2");
    }
  }
  if (s.threads) {
    c.threads =
        static_cast<unsigned>(parse_integer_in(s.threads->text, s.threads->origin, 0, 1024));
  }
  if (s.tolerance) {
    c.tolerance = parse_real(s.tolerance->text, s.tolerance->origin);
    if (!(c.tolerance >= 0 && c.tolerance <= 10)) {
      throw InvalidArgument(s.tolerance->origin + " = '" + s.tolerance->text +
                            "' must be in [0, 10]");
    }
  }
  if (s.title) {
    if (s.title->text.size() > 200) {
      throw InvalidArgument(s.title->origin + ": a title of at most 200 characters");
    }
    c.title = s.title->text;
  }
  // Each shape and entry alone (naming its origin), then together (repeats, dimensions).
  for (const auto& x : s.shapes) checked(x, [](const std::string& t) { parse_shape(t); });
  for (const auto& x : s.functions) {
    checked(x, [&](const std::string& t) {
      if (t.find(',') != std::string::npos) {
        throw InvalidArgument("function '" + t + "': no commas (give one function per --function)");
      }
      ScalarField{t};
    });
    c.functions.push_back(x.text);
  }
  for (const auto& x : s.estimators) {
    checked(x, [&](const std::string& t) {
      const auto spec = parse_estimator_spec(t);
      if (!c.k_text) resolve_parameters(spec, std::nullopt, c.alpha_text);
      if (c.k_text) {
        for (const auto& k : k_texts_per_shape(*c.k_text, c.shapes.size()))
          resolve_parameters(spec, k, c.alpha_text);
      }
    });
  }
  plan_experiment(c);
  return c;
}

ExperimentConfig parse_experiment_config(std::string_view text, const std::string& source) {
  return validate_experiment_settings(parse_experiment_toml(text, source));
}

} // namespace zdg
