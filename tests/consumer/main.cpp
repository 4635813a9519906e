// Uses the installed zdg: a continued fraction computed exactly by escalation.
#include <zdg/arith/continued_fraction.hpp>
#include <zdg/arith/escalate.hpp>
#include <zdg/arith/floor_sum.hpp>

#include <iostream>

int main() {
  auto terms = zdg::continued_fraction<zdg::Int64>(415, 93);
  // 415/93 = [4; 2, 6, 7]
  bool ok = terms.size() == 4 && terms[0] == 4 && terms[1] == 2 && terms[2] == 6 && terms[3] == 7;
  auto s = zdg::floor_sum_exact(zdg::BigInt(10), zdg::BigInt(3), zdg::BigInt(2), zdg::BigInt(1));
  ok = ok && s.value == 30 && s.served == zdg::IntKind::int64;
  std::cout << (ok ? "consumer: ok" : "consumer: WRONG") << '\n';
  return ok ? 0 : 1;
}
