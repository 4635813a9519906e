// The plane family of zdg check: plane-probing algorithms on standard digital planes, against
// the theorem that they recover the normal exactly.
#include <zdg/convergence/check/property.hpp>
#include <zdg/kernel/surfaces/plane_probing.hpp>

#include <array>
#include <numeric>
#include <string>
#include <vector>

namespace zdg::check {

namespace {

// --- plane.probe.normal ------------------------------------------------------------------------

// A primitive normal with nonzero components of magnitude <= max size and random signs, and an
// algorithm (h or r).
Record probe_generate(Rng& rng, const Params& params) {
  const auto m = static_cast<std::int64_t>(params.max_size);
  std::int64_t n[3];
  do {
    for (auto& x : n) {
      x = rng.chance(1, 4) ? rng.range(1, std::min<std::int64_t>(m, 4)) : rng.range(1, m);
      if (rng.chance(1, 2)) x = -x;
    }
  } while (std::gcd(std::gcd(n[0], n[1]), n[2]) != 1);
  return Record()
      .integer("a", BigInt(n[0]), Shrink::toward_zero)
      .integer("b", BigInt(n[1]), Shrink::toward_zero)
      .integer("c", BigInt(n[2]), Shrink::toward_zero)
      .text("algorithm", rng.chance(1, 2) ? "h" : "r");
}

bool probe_valid(const Record& c, const Params& params) {
  const BigInt bound(static_cast<std::int64_t>(params.max_size));
  std::int64_t g = 0;
  for (const char* k : {"a", "b", "c"}) {
    const BigInt& x = c.int_of(k);
    if (x == 0 || abs(x) > bound) return false;
    g = std::gcd(g, x.convert_to<std::int64_t>());
  }
  const auto& alg = c.at("algorithm").texts.at(0);
  return g == 1 && (alg == "h" || alg == "r");
}

BigInt l1_norm(const Record& c) {
  return abs(c.int_of("a")) + abs(c.int_of("b")) + abs(c.int_of("c"));
}

// The normal is the input itself; the step count is judged against the bound ||N||_1 - 3
// (each step lowers sum_k N . m_k, from ||N||_1, by at least one, and it stays >= 3).
Record probe_oracle(const Record& c) {
  Record r;
  r.array("normal", {3}, {c.int_of("a"), c.int_of("b"), c.int_of("c")});
  r.integer("steps", l1_norm(c) - 3);
  r.at("steps").judged = true;
  return r;
}

Record probe_compute(const Record& c, IntKind type) {
  const auto alg = c.at("algorithm").texts.at(0) == "h" ? ProbingAlgorithm::h : ProbingAlgorithm::r;
  auto r = escalate_from(type, [&]<class I>(std::type_identity<I>) {
    const Point3<I> n{int_cast<I>(c.int_of("a")), int_cast<I>(c.int_of("b")),
                      int_cast<I>(c.int_of("c"))};
    const auto p = probe_standard_plane<I>(n, alg);
    return std::array<BigInt, 4>{to_bigint(p.normal.x), to_bigint(p.normal.y),
                                 to_bigint(p.normal.z), BigInt(static_cast<std::int64_t>(p.steps))};
  });
  Record out;
  out.array("normal", {3}, {r.value[0], r.value[1], r.value[2]});
  out.integer("steps", r.value[3]);
  return out.text("integer_type", std::string(to_string(r.served)));
}

std::optional<std::string> probe_judge(const Record&, const Record& expected, const Record& got) {
  if (!got.has("steps")) return std::nullopt;
  const BigInt& steps = got.int_of("steps");
  if (steps < 0) return "steps is negative";
  if (steps > expected.int_of("steps")) {
    return "steps = " + steps.str() +
           " exceeds the bound ||N||_1 - 3 = " + expected.int_of("steps").str();
  }
  return std::nullopt;
}

} // namespace

void add_plane_properties(std::vector<Property>& out) {
  Property p;
  p.name = "plane.probe.normal";
  p.theorem = "the H- and R-algorithms probing the standard plane 0 <= N . x < ||N||_1 from the "
              "origin return the primitive normal N exactly, in at most ||N||_1 - 3 steps";
  p.source = "theorem: Lachaud, Provencal and Roussillon, JMIV 59 (2017); Lachaud, Meyron and "
             "Roussillon, JMIV 62 (2020)";
  p.operation = "plane probe";
  p.sizes = "|components| <= max-size, any signs; bits unused (the computation starts on "
            "--type and escalates)";
  p.cost = Cost::moderate;
  p.uses_bits = false;
  p.default_max_size = 300;
  p.max_max_size = 100000;
  p.generate = probe_generate;
  p.valid = probe_valid;
  p.oracle = probe_oracle;
  p.compute = probe_compute;
  p.judge = probe_judge;
  out.push_back(std::move(p));
}

} // namespace zdg::check
