// zdg cf, zdg christoffel, zdg floor-sum: the arithmetic core on the command line. Every
// number is read as a BigInt and the work is done "exact by escalation" (int64 first).
#include <zdg/arith/christoffel.hpp>
#include <zdg/arith/continued_fraction.hpp>
#include <zdg/arith/escalate.hpp>
#include <zdg/arith/floor_sum.hpp>
#include <zdg/arith/stern_brocot.hpp>
#include <zdg/cli/commands.hpp>

#include <iostream>
#include <string>
#include <vector>

namespace zdg::cli {

namespace {

struct BigFraction {
  BigInt p, q;
};

BigInt parse_big(const std::string& text, const std::string& what) {
  try {
    return parse_integer<BigInt>(text);
  } catch (const InvalidArgument&) {
    throw InvalidArgument(what + ": '" + text + "' is not an integer");
  }
}

// "P/Q" or "P" (= P/1); Q must not be zero.
BigFraction parse_fraction(const std::string& text) {
  auto slash = text.find('/');
  if (slash == std::string::npos) return {parse_big(text, "fraction"), BigInt(1)};
  std::string ps = text.substr(0, slash), qs = text.substr(slash + 1);
  if (ps.empty() || qs.empty()) throw InvalidArgument("'" + text + "' is not a fraction P/Q");
  BigFraction f{parse_big(ps, "numerator of '" + text + "'"),
                parse_big(qs, "denominator of '" + text + "'")};
  if (f.q == 0) throw InvalidArgument("zero denominator in '" + text + "'");
  return f;
}

std::vector<std::string> strings(const std::vector<BigInt>& v) {
  std::vector<std::string> out;
  for (const auto& x : v) out.push_back(x.str());
  return out;
}

void run_cf(const std::string& text, bool json) {
  BigFraction f = parse_fraction(text);
  struct Out {
    std::vector<BigInt> terms;
    std::vector<std::pair<BigInt, BigInt>> conv;
  };
  auto r = escalate([&]<class I>(std::type_identity<I>) {
    auto terms = continued_fraction<I>(int_cast<I>(f.p), int_cast<I>(f.q));
    auto conv = convergents<I>(std::span<const I>(terms));
    Out o;
    for (const auto& t : terms) o.terms.push_back(to_bigint(t));
    for (const auto& [p, q] : conv) o.conv.emplace_back(to_bigint(p), to_bigint(q));
    return o;
  });
  if (json) {
    nlohmann::json conv = nlohmann::json::array();
    for (const auto& [p, q] : r.value.conv) conv.push_back({p.str(), q.str()});
    print_json({{"p", f.p.str()},
                {"q", f.q.str()},
                {"terms", strings(r.value.terms)},
                {"convergents", conv},
                {"integer_type", std::string(to_string(r.served))}});
    return;
  }
  std::cout << f.p << "/" << f.q << " = [";
  for (std::size_t i = 0; i < r.value.terms.size(); ++i) {
    std::cout << (i == 0 ? "" : (i == 1 ? "; " : ", ")) << r.value.terms[i];
  }
  std::cout << "]\nconvergents:";
  for (const auto& [p, q] : r.value.conv) std::cout << ' ' << p << '/' << q;
  std::cout << "\n(computed on " << to_string(r.served) << ")\n";
}

void run_christoffel(const std::string& text, bool upper, bool no_word, bool json) {
  BigFraction f = parse_fraction(text);
  if (f.p < 0 || f.q < 0) {
    throw InvalidArgument("christoffel: slope '" + text + "' must satisfy P >= 0 and Q > 0");
  }
  BigInt g = gcd(f.p, f.q);
  BigInt p = f.p / g, q = f.q / g;
  struct Out {
    std::string word, u, v;
    bool has_parents = false;
    BigInt lp, lq, rp, rq;
  };
  auto r = escalate([&]<class I>(std::type_identity<I>) {
    I pi = int_cast<I>(p), qi = int_cast<I>(q);
    Out o;
    if (!no_word) o.word = upper ? upper_christoffel_word(pi, qi) : lower_christoffel_word(pi, qi);
    if (pi > 0) {
      auto par = stern_brocot_parents(pi, qi);
      o.has_parents = true;
      o.lp = to_bigint(par.left.p);
      o.lq = to_bigint(par.left.q);
      o.rp = to_bigint(par.right.p);
      o.rq = to_bigint(par.right.q);
      if (!no_word) {
        auto sf = standard_factorization(pi, qi);
        o.u = sf.u;
        o.v = sf.v;
        // The upper word is the reverse: its standard factorization is rev(v) rev(u).
        if (upper) {
          o.u.assign(sf.v.rbegin(), sf.v.rend());
          o.v.assign(sf.u.rbegin(), sf.u.rend());
        }
      }
    }
    return o;
  });
  const Out& o = r.value;
  if (json) {
    nlohmann::json j{{"p", p.str()}, {"q", q.str()}, {"upper", upper}};
    if (!no_word) {
      j["word"] = o.word;
      j["standard_factorization"] =
          o.has_parents ? nlohmann::json::array({o.u, o.v}) : nlohmann::json::array();
    }
    j["parents"] = o.has_parents
                       ? nlohmann::json::array({nlohmann::json::array({o.lp.str(), o.lq.str()}),
                                                nlohmann::json::array({o.rp.str(), o.rq.str()})})
                       : nlohmann::json::array();
    j["integer_type"] = std::string(to_string(r.served));
    print_json(j);
    return;
  }
  std::cout << (upper ? "upper" : "lower") << " Christoffel word of slope " << p << "/" << q;
  if (!no_word) std::cout << ":\n" << o.word;
  std::cout << '\n';
  if (o.has_parents) {
    std::cout << "Stern-Brocot parents: " << o.lp << "/" << o.lq << " and " << o.rp << "/" << o.rq
              << '\n';
    if (!no_word) std::cout << "standard factorization: (" << o.u << ")(" << o.v << ")\n";
  } else {
    std::cout << "0/1 is a root of the Stern-Brocot tree: no parents, no factorization\n";
  }
}

void run_floor_sum(const std::vector<std::string>& args, bool json) {
  BigInt n = parse_big(args[0], "N"), m = parse_big(args[1], "M"), a = parse_big(args[2], "A"),
         b = parse_big(args[3], "B");
  if (n < 0) throw InvalidArgument("floor-sum: N = " + args[0] + " must be >= 0");
  if (m == 0) throw InvalidArgument("floor-sum: M must not be 0");
  auto r = floor_sum_exact(n, m, a, b);
  if (json) {
    print_json({{"value", r.value.str()}, {"integer_type", std::string(to_string(r.served))}});
  } else {
    std::cout << r.value << '\n';
  }
}

} // namespace

void add_arith_commands(CLI::App& app, Context& /*ctx*/) {
  {
    auto* cmd = app.add_subcommand("cf", "Continued fraction and convergents of P/Q (any size)");
    auto text = std::make_shared<std::string>();
    auto json = std::make_shared<bool>(false);
    cmd->add_option("fraction", *text, "P/Q with Q != 0 (or an integer P)")->required();
    cmd->add_flag("--json", *json, "Machine-readable output");
    cmd->callback([text, json] { run_cf(*text, *json); });
  }
  {
    auto* cmd =
        app.add_subcommand("christoffel", "Christoffel word of slope P/Q, standard factorization");
    auto text = std::make_shared<std::string>();
    auto upper = std::make_shared<bool>(false), no_word = std::make_shared<bool>(false),
         json = std::make_shared<bool>(false);
    cmd->add_option("slope", *text, "P/Q with P >= 0, Q > 0 (reduced first)")->required();
    cmd->add_flag("--upper", *upper, "The upper word (the reverse of the lower one)");
    cmd->add_flag("--no-word", *no_word, "Omit the word and its factors (for huge slopes)");
    cmd->add_flag("--json", *json, "Machine-readable output");
    cmd->callback([=] { run_christoffel(*text, *upper, *no_word, *json); });
  }
  {
    auto* cmd =
        app.add_subcommand("floor-sum", "sum_{i=0}^{N-1} floor((A i + B) / M), exact, in O(log M)");
    auto args = std::make_shared<std::vector<std::string>>();
    auto json = std::make_shared<bool>(false);
    cmd->add_option("N M A B", *args, "N >= 0, M != 0, any A and B")->required()->expected(4);
    cmd->add_flag("--json", *json, "Machine-readable output");
    cmd->callback([=] { run_floor_sum(*args, *json); });
  }
}

} // namespace zdg::cli
