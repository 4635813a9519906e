#include <zdg/operations/arith_operations.hpp>

#include <zdg/arith/christoffel.hpp>
#include <zdg/arith/continued_fraction.hpp>
#include <zdg/arith/error.hpp>
#include <zdg/arith/floor_sum.hpp>
#include <zdg/arith/stern_brocot.hpp>
#include <zdg/arith/sturmian.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <span>

namespace zdg {

namespace {

BigInt parse_big(const std::string& text, const std::string& what) {
  try {
    return parse_integer<BigInt>(text);
  } catch (const InvalidArgument&) {
    throw InvalidArgument(what + ": '" + text + "' is not an integer");
  }
}

std::vector<std::string> strings(const std::vector<BigInt>& v) {
  std::vector<std::string> out;
  out.reserve(v.size());
  for (const auto& x : v) out.push_back(x.str());
  return out;
}

nlohmann::json pair_json(const BigInt& a, const BigInt& b) {
  return nlohmann::json::array({a.str(), b.str()});
}

} // namespace

Fraction<BigInt> parse_fraction(const std::string& text) {
  const auto slash = text.find('/');
  if (slash == std::string::npos) return {parse_big(text, "fraction"), BigInt(1)};
  const std::string ps = text.substr(0, slash), qs = text.substr(slash + 1);
  if (ps.empty() || qs.empty()) throw InvalidArgument("'" + text + "' is not a fraction P/Q");
  Fraction<BigInt> f{parse_big(ps, "numerator of '" + text + "'"),
                     parse_big(qs, "denominator of '" + text + "'")};
  if (f.q == 0) throw InvalidArgument("zero denominator in '" + text + "'");
  return f;
}

ContinuedFractionResult continued_fraction_operation(const Fraction<BigInt>& f) {
  if (f.q == 0) throw InvalidArgument("cf: zero denominator");
  ContinuedFractionResult out;
  out.p = f.p;
  out.q = f.q;
  struct Terms {
    std::vector<BigInt> terms;
    std::vector<std::pair<BigInt, BigInt>> conv;
  };
  auto r = escalate([&]<class I>(std::type_identity<I>) {
    const auto terms = continued_fraction<I>(int_cast<I>(f.p), int_cast<I>(f.q));
    Terms t;
    for (const auto& a : terms) t.terms.push_back(to_bigint(a));
    for (const auto& [a, b] : convergents<I>(std::span<const I>(terms)))
      t.conv.emplace_back(to_bigint(a), to_bigint(b));
    return t;
  });
  out.terms = std::move(r.value.terms);
  out.convergents = std::move(r.value.conv);
  out.served = r.served;
  return out;
}

nlohmann::json to_json(const ContinuedFractionResult& r) {
  nlohmann::json conv = nlohmann::json::array();
  for (const auto& [a, b] : r.convergents) conv.push_back(pair_json(a, b));
  return {{"p", r.p.str()},
          {"q", r.q.str()},
          {"terms", strings(r.terms)},
          {"convergents", conv},
          {"integer_type", std::string(to_string(r.served))}};
}

ChristoffelResult christoffel_operation(const ChristoffelOptions& o) {
  const Fraction<BigInt>& s = o.slope;
  if (s.p < 0 || s.q <= 0) {
    throw InvalidArgument("christoffel: slope " + s.p.str() + "/" + s.q.str() +
                          " must satisfy p >= 0 and q > 0");
  }
  const BigInt g = gcd(s.p, s.q);
  ChristoffelResult out;
  out.p = s.p / g;
  out.q = s.q / g;
  out.upper = o.upper;
  out.word = o.word;
  auto r = escalate([&]<class I>(std::type_identity<I>) {
    const I pi = int_cast<I>(out.p), qi = int_cast<I>(out.q);
    ChristoffelResult w;
    if (o.word)
      w.letters = o.upper ? upper_christoffel_word(pi, qi) : lower_christoffel_word(pi, qi);
    if (pi > 0) {
      const auto par = stern_brocot_parents(pi, qi);
      w.parents = std::pair{Fraction<BigInt>{to_bigint(par.left.p), to_bigint(par.left.q)},
                            Fraction<BigInt>{to_bigint(par.right.p), to_bigint(par.right.q)}};
      if (o.word) {
        const auto sf = standard_factorization(pi, qi);
        // The upper word is the reverse: its standard factorization is rev(v) rev(u).
        w.factorization = o.upper ? std::pair{std::string(sf.v.rbegin(), sf.v.rend()),
                                              std::string(sf.u.rbegin(), sf.u.rend())}
                                  : std::pair{sf.u, sf.v};
      }
    }
    return w;
  });
  out.letters = std::move(r.value.letters);
  out.factorization = std::move(r.value.factorization);
  out.parents = std::move(r.value.parents);
  out.served = r.served;
  return out;
}

nlohmann::json to_json(const ChristoffelResult& r) {
  nlohmann::json j{{"p", r.p.str()}, {"q", r.q.str()}, {"upper", r.upper}};
  if (r.word) {
    j["word"] = r.letters;
    j["standard_factorization"] =
        r.factorization ? nlohmann::json::array({r.factorization->first, r.factorization->second})
                        : nlohmann::json::array();
  }
  j["parents"] = r.parents
                     ? nlohmann::json::array({pair_json(r.parents->first.p, r.parents->first.q),
                                              pair_json(r.parents->second.p, r.parents->second.q)})
                     : nlohmann::json::array();
  j["integer_type"] = std::string(to_string(r.served));
  return j;
}

FloorSumResult floor_sum_operation(const FloorSumOptions& o) {
  if (o.n < 0) throw InvalidArgument("floor-sum: N = " + o.n.str() + " must be >= 0");
  if (o.m == 0) throw InvalidArgument("floor-sum: M must not be 0");
  auto r = floor_sum_exact(o.n, o.m, o.a, o.b);
  return {r.value, r.served};
}

nlohmann::json to_json(const FloorSumResult& r) {
  return {{"value", r.value.str()}, {"integer_type", std::string(to_string(r.served))}};
}

SturmianResult sturmian_operation(const SturmianOptions& o) {
  if (o.length > 100'000'000) {
    throw InvalidArgument("sturmian: length " + std::to_string(o.length) +
                          " is past the 10^8 letters a word may have here");
  }
  auto r = escalate([&]<class I>(std::type_identity<I>) {
    const auto x =
        make_surd(int_cast<I>(o.a), int_cast<I>(o.b), int_cast<I>(o.d), int_cast<I>(o.c));
    const auto cf = periodic_continued_fraction(x, static_cast<std::size_t>(o.max_terms));
    const I f = floor_multiple(x, I(1));
    const QuadraticSurd<I> alpha = fractional_part(x);
    // alpha = x - a_0 = [0; a_1, a_2, ...]: x's expansion with its first term replaced by 0 (a
    // purely periodic x = [(b_1, ..., b_m)] gives [0; (b_2, ..., b_m, b_1)]).
    auto acf = cf;
    if (acf.preperiod.empty()) {
      std::rotate(acf.period.begin(), acf.period.begin() + 1, acf.period.end());
      acf.preperiod.push_back(I(0));
    } else {
      acf.preperiod.front() = I(0);
    }
    SturmianResult w;
    w.P = to_bigint(x.P);
    w.D = to_bigint(x.D);
    w.Q = to_bigint(x.Q);
    for (const auto& t : cf.preperiod) w.preperiod.push_back(to_bigint(t));
    for (const auto& t : cf.period) w.period.push_back(to_bigint(t));
    w.floor = to_bigint(f);
    w.alpha_P = to_bigint(alpha.P);
    w.word = standard_word_prefix(acf, static_cast<std::size_t>(o.length));
    // The convergents p/q of alpha with 2 <= q <= length + 2: the lower Christoffel words of
    // slopes p/(q - p) are 0 w 1 with w the word's prefix of length q - 2.
    const BigInt limit = BigInt(o.length) + 2;
    I p2 = 0, q2 = 1, p1 = 1, q1 = 0;
    for (std::size_t k = 0;; ++k) {
      const I& a = acf.term(k);
      I p = a * p1 + p2, q = a * q1 + q2;
      if (to_bigint(q) > limit) break;
      if (q >= 2 && p >= 1) w.christoffel.emplace_back(to_bigint(p), to_bigint(q) - to_bigint(p));
      p2 = std::move(p1);
      q2 = std::move(q1);
      p1 = std::move(p);
      q1 = std::move(q);
    }
    return w;
  });
  r.value.served = r.served;
  return r.value;
}

nlohmann::json to_json(const SturmianResult& r) {
  nlohmann::json conv = nlohmann::json::array();
  for (const auto& [p, q] : r.christoffel) conv.push_back(pair_json(p, q));
  auto surd = [&](const BigInt& p) {
    std::string t = "(";
    t.append(p.str()).append(" + sqrt(").append(r.D.str()).append("))/").append(r.Q.str());
    return t;
  };
  return {{"surd", surd(r.P)},
          {"preperiod", strings(r.preperiod)},
          {"period", strings(r.period)},
          {"floor", r.floor.str()},
          {"slope", surd(r.alpha_P)},
          {"word", r.word},
          {"christoffel_convergents", conv},
          {"integer_type", std::string(to_string(r.served))}};
}

} // namespace zdg
