// Uses the installed zdg: a continued fraction computed exactly by escalation, the same as an
// operation with its JSON form, and an experiment description read by the library (which links
// toml++ privately: the package config must bring it).
#include <zdg/arith/continued_fraction.hpp>
#include <zdg/arith/escalate.hpp>
#include <zdg/arith/floor_sum.hpp>
#include <zdg/convergence/config.hpp>
#include <zdg/operations/arith_operations.hpp>

#include <nlohmann/json.hpp>

#include <iostream>

int main() {
  auto terms = zdg::continued_fraction<zdg::Int64>(415, 93);
  // 415/93 = [4; 2, 6, 7]
  bool ok = terms.size() == 4 && terms[0] == 4 && terms[1] == 2 && terms[2] == 6 && terms[3] == 7;
  // f<I> computes on I; f_exact escalates and says which type served.
  auto s = zdg::floor_sum_exact(zdg::BigInt(10), zdg::BigInt(3), zdg::BigInt(2), zdg::BigInt(1));
  ok = ok && s.value == 30 && s.served == zdg::IntKind::int64;
  auto c = zdg::parse_experiment_config("shape = \"ellipse:20,7\"\n"
                                        "estimators = [\"ii-curvature:k=5\", \"bc-curvature\"]\n"
                                        "h = \"exp:30:60:3\"\n",
                                        "consumer.toml");
  ok = ok && c.estimators.size() == 2 && c.hs.size() == 11;
  // An operation and its JSON form (the package config brings nlohmann-json).
  const auto cf = zdg::continued_fraction_operation(zdg::parse_fraction("415/93"));
  ok = ok && to_json(cf)["terms"].size() == 4;
  std::cout << (ok ? "consumer: ok" : "consumer: WRONG") << '\n';
  return ok ? 0 : 1;
}
