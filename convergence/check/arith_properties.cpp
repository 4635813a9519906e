// The arithmetic family of zdg check: floor sums, continued fractions, Christoffel words.
// Every oracle here is written from the definition, independently of arith/.
#include <zdg/arith/christoffel.hpp>
#include <zdg/arith/continued_fraction.hpp>
#include <zdg/arith/floor_sum.hpp>
#include <zdg/arith/stern_brocot.hpp>
#include <zdg/convergence/check/property.hpp>

#include <numeric>
#include <span>
#include <string>
#include <vector>

namespace zdg::check {

namespace {

// --- floor_sum.oracle ------------------------------------------------------------------------

Record floor_sum_generate(Rng& rng, const Params& params) {
  Record c;
  c.integer("n", BigInt(rng.range(0, static_cast<std::int64_t>(params.max_size))),
            Shrink::toward_zero);
  BigInt m = rng.chance(1, 3) ? BigInt(rng.range(1, 12)) : rng.edgy(params.bits);
  if (m == 0) m = 1;
  if (rng.chance(1, 4)) m = -m;
  c.integer("m", m, Shrink::toward_zero);
  c.integer("a", rng.edgy(params.bits), Shrink::toward_zero);
  c.integer("b", rng.edgy(params.bits), Shrink::toward_zero);
  return c;
}

bool floor_sum_valid(const Record& c, const Params& params) {
  const BigInt& n = c.int_of("n");
  return n >= 0 && n <= BigInt(params.max_size) && c.int_of("m") != 0;
}

Record floor_sum_oracle(const Record& c) {
  const BigInt &m = c.int_of("m"), &a = c.int_of("a"), &b = c.int_of("b");
  const std::int64_t n = c.i64_of("n");
  BigInt s = 0;
  for (std::int64_t i = 0; i < n; ++i) s += floor_div(BigInt(a * i + b), m);
  return Record().integer("value", s);
}

Record floor_sum_compute(const Record& c, IntKind type) {
  auto r = escalate_from(type, [&]<class I>(std::type_identity<I>) {
    return to_bigint(floor_sum<I>(int_cast<I>(c.int_of("n")), int_cast<I>(c.int_of("m")),
                                  int_cast<I>(c.int_of("a")), int_cast<I>(c.int_of("b"))));
  });
  return Record().integer("value", r.value).text("integer_type", std::string(to_string(r.served)));
}

// --- cf.roundtrip ------------------------------------------------------------------------------

Record cf_generate(Rng& rng, const Params& params) {
  Record c;
  BigInt p = rng.edgy(params.bits), q = rng.edgy(params.bits);
  if (q == 0) q = 1;
  if (rng.chance(1, 8)) { // consecutive Fibonacci numbers: the longest expansions (Lame)
    BigInt f0 = 0, f1 = 1;
    const BigInt lim = BigInt(1) << (params.bits - 1);
    while (f1 + f0 < lim && rng.chance(15, 16)) {
      BigInt t = f1 + f0;
      f0 = f1;
      f1 = t;
    }
    p = f1;
    q = f0 == 0 ? BigInt(1) : f0;
  }
  c.integer("p", p, Shrink::toward_zero);
  c.integer("q", q, Shrink::toward_zero);
  return c;
}

bool cf_valid(const Record& c, const Params&) {
  return c.int_of("q") != 0;
}

Record cf_request(const Record& c) {
  return Record().text("fraction", c.int_of("p").str() + "/" + c.int_of("q").str());
}

Record cf_record(const std::vector<BigInt>& terms,
                 const std::vector<std::pair<BigInt, BigInt>>& conv) {
  std::vector<BigInt> flat;
  for (const auto& [a, b] : conv) {
    flat.push_back(a);
    flat.push_back(b);
  }
  return Record()
      .array("terms", {terms.size()}, terms)
      .array("convergents", {conv.size(), 2}, std::move(flat));
}

// Euclid's algorithm with floor division, written from the definition.
Record cf_oracle(const Record& c) {
  BigInt p = c.int_of("p"), q = c.int_of("q");
  if (q < 0) {
    p = -p;
    q = -q;
  }
  std::vector<BigInt> terms;
  while (q != 0) {
    BigInt a = floor_div(p, q);
    terms.push_back(a);
    BigInt r = p - a * q;
    p = q;
    q = r;
  }
  std::vector<std::pair<BigInt, BigInt>> conv;
  BigInt p1 = 1, q1 = 0, p2 = 0, q2 = 1; // p_{k-1}/q_{k-1}, p_{k-2}/q_{k-2}
  for (const auto& a : terms) {
    BigInt pk = a * p1 + p2, qk = a * q1 + q2;
    conv.emplace_back(pk, qk);
    p2 = p1;
    q2 = q1;
    p1 = pk;
    q1 = qk;
  }
  return cf_record(terms, conv);
}

Record cf_compute(const Record& c, IntKind type) {
  struct Out {
    std::vector<BigInt> terms;
    std::vector<std::pair<BigInt, BigInt>> conv;
  };
  auto r = escalate_from(type, [&]<class I>(std::type_identity<I>) {
    auto terms = continued_fraction<I>(int_cast<I>(c.int_of("p")), int_cast<I>(c.int_of("q")));
    auto conv = convergents<I>(std::span<const I>(terms));
    Out o;
    for (const auto& t : terms) o.terms.push_back(to_bigint(t));
    for (const auto& [a, b] : conv) o.conv.emplace_back(to_bigint(a), to_bigint(b));
    return o;
  });
  return cf_record(r.value.terms, r.value.conv)
      .text("integer_type", std::string(to_string(r.served)));
}

// The theorem on any answer: the terms are canonical and evaluate back to p/q, the convergents
// follow the recurrence and end at p/q reduced.
std::optional<std::string> cf_judge(const Record& c, const Record&, const Record& got) {
  if (!got.has("terms") || got.at("terms").kind != FieldKind::array) return std::nullopt;
  const auto& t = got.at("terms").ints;
  if (t.empty()) return "no terms";
  for (std::size_t i = 1; i < t.size(); ++i) {
    if (t[i] < 1) return "term a" + std::to_string(i) + " = " + t[i].str() + " is not >= 1";
  }
  if (t.size() > 1 && t.back() < 2) return "the last term is 1: the expansion is not canonical";
  BigInt num = t.back(), den = 1; // evaluate [a0; a1, ..., an] from the back
  for (std::size_t i = t.size() - 1; i-- > 0;) {
    BigInt nn = t[i] * num + den;
    den = num;
    num = nn;
  }
  BigInt p = c.int_of("p"), q = c.int_of("q");
  // num/den == p/q  <=>  num q == p den (den > 0 for canonical terms)
  if (num * q != p * den) {
    return "the terms evaluate to " + num.str() + "/" + den.str() + ", not " + p.str() + "/" +
           q.str();
  }
  return std::nullopt;
}

// --- christoffel.factorization --------------------------------------------------------------

std::string word_by_definition(std::int64_t p, std::int64_t q) {
  // letter k (1-based) = floor(k p / n) - floor((k - 1) p / n), n = p + q; 1/0 is "1".
  const std::int64_t n = p + q;
  std::string w;
  for (std::int64_t k = 1; k <= n; ++k) w += ((k * p) / n - ((k - 1) * p) / n) == 1 ? '1' : '0';
  return w;
}

Record christoffel_generate(Rng& rng, const Params& params) {
  const auto max = static_cast<std::int64_t>(params.max_size);
  std::int64_t p = 1, q = 1;
  for (int tries = 0; tries < 64; ++tries) {
    p = rng.range(1, std::max<std::int64_t>(1, max - 1));
    q = rng.range(1, std::max<std::int64_t>(1, max - p));
    if (std::gcd(p, q) == 1) break;
    p = q = 1;
  }
  return Record()
      .integer("p", BigInt(p), Shrink::toward_zero)
      .integer("q", BigInt(q), Shrink::toward_zero);
}

bool christoffel_valid(const Record& c, const Params& params) {
  const BigInt &p = c.int_of("p"), &q = c.int_of("q");
  return p >= 1 && q >= 1 && p + q <= BigInt(params.max_size) && gcd(p, q) == 1;
}

Record christoffel_request(const Record& c) {
  return Record().text("slope", c.int_of("p").str() + "/" + c.int_of("q").str());
}

// Parents by search: the left parent a/b has p b - q a = 1 with 1 <= b <= q, the right one is
// (p - a)/(q - b).
Record christoffel_oracle(const Record& c) {
  const std::int64_t p = c.i64_of("p"), q = c.i64_of("q");
  std::int64_t a = -1, b = -1;
  for (std::int64_t bb = 1; bb <= q; ++bb) {
    if ((p * bb - 1) % q == 0) {
      b = bb;
      a = (p * bb - 1) / q;
      break;
    }
  }
  const std::int64_t cc = p - a, d = q - b;
  std::string u = word_by_definition(a, b),
              v = d == 0 ? std::string("1") : word_by_definition(cc, d);
  return Record()
      .text("word", word_by_definition(p, q))
      .texts("standard_factorization", {u, v})
      .array("parents", {2, 2}, {BigInt(a), BigInt(b), BigInt(cc), BigInt(d)});
}

Record christoffel_compute(const Record& c, IntKind type) {
  struct Out {
    std::string word, u, v;
    std::vector<BigInt> parents;
  };
  auto r = escalate_from(type, [&]<class I>(std::type_identity<I>) {
    I p = int_cast<I>(c.int_of("p")), q = int_cast<I>(c.int_of("q"));
    Out o;
    o.word = lower_christoffel_word(p, q);
    auto sf = standard_factorization(p, q);
    o.u = sf.u;
    o.v = sf.v;
    auto par = stern_brocot_parents(p, q);
    o.parents = {to_bigint(par.left.p), to_bigint(par.left.q), to_bigint(par.right.p),
                 to_bigint(par.right.q)};
    return o;
  });
  return Record()
      .text("word", r.value.word)
      .texts("standard_factorization", {r.value.u, r.value.v})
      .array("parents", {2, 2}, r.value.parents)
      .text("integer_type", std::string(to_string(r.served)));
}

// The theorem on any answer: the two factors concatenate to the word.
std::optional<std::string> christoffel_judge(const Record&, const Record&, const Record& got) {
  if (!got.has("word") || !got.has("standard_factorization")) return std::nullopt;
  const auto& f = got.at("standard_factorization").texts;
  const auto& w = got.at("word").texts;
  if (f.size() != 2 || w.size() != 1) return "standard_factorization is not a pair of words";
  if (f[0] + f[1] != w[0]) return "the factors do not concatenate to the word";
  return std::nullopt;
}

} // namespace

void add_arith_properties(std::vector<Property>& out) {
  {
    Property p;
    p.name = "floor_sum.oracle";
    p.theorem = "floor_sum(n, m, a, b) = sum_{i=0}^{n-1} floor((a i + b) / m) for every sign of "
                "m != 0, a, b (Euclid-like reduction, exact by escalation)";
    p.source = "oracle: the sum itself (brute force in BigInt); algorithm: AtCoder Library "
               "floor_sum, Knuth TAOCP vol. 1, 1.2.4 ex. 37";
    p.operation = "floor-sum";
    p.sizes = "n <= max-size; m, a, b of up to --bits bits";
    p.cost = Cost::cheap;
    p.default_max_size = 200;
    p.max_max_size = 1000000;
    p.generate = floor_sum_generate;
    p.valid = floor_sum_valid;
    p.oracle = floor_sum_oracle;
    p.compute = floor_sum_compute;
    out.push_back(std::move(p));
  }
  {
    Property p;
    p.name = "cf.roundtrip";
    p.theorem = "the continued fraction of p/q is canonical (a_i >= 1, last term >= 2), "
                "evaluates back to p/q, and its convergents follow p_k = a_k p_{k-1} + p_{k-2}";
    p.source = "oracle: Euclid's algorithm with floor division (BigInt); Khinchin, Continued "
               "Fractions (1964); Graham, Knuth, Patashnik, Concrete Mathematics 6.7";
    p.operation = "cf";
    p.sizes = "p, q of up to --bits bits (q != 0); max-size unused";
    p.cost = Cost::cheap;
    p.default_max_size = 1;
    p.max_max_size = 1000000;
    p.generate = cf_generate;
    p.valid = cf_valid;
    p.request = cf_request;
    p.oracle = cf_oracle;
    p.compute = cf_compute;
    p.judge = cf_judge;
    out.push_back(std::move(p));
  }
  {
    Property p;
    p.name = "christoffel.factorization";
    p.theorem = "the lower Christoffel word of p/q has letter k = floor(k p/n) - floor((k-1) p/n) "
                "and is u v with u, v the words of the Stern-Brocot parents of p/q";
    p.source = "oracle: the definition letter by letter, parents by search of p b - q a = 1; "
               "Berstel, Lauve, Reutenauer, Saliola, Combinatorics on Words (CRM 2008), ch. 1-3";
    p.operation = "christoffel";
    p.sizes = "p + q <= max-size (the word is materialized); bits unused";
    p.cost = Cost::cheap;
    p.uses_bits = false;
    p.default_max_size = 64;
    p.max_max_size = 100000;
    p.generate = christoffel_generate;
    p.valid = christoffel_valid;
    p.request = christoffel_request;
    p.oracle = christoffel_oracle;
    p.compute = christoffel_compute;
    p.judge = christoffel_judge;
    out.push_back(std::move(p));
  }
}

} // namespace zdg::check
