// The arithmetic operations of the front ends (zdg cf | christoffel | floor-sum, the same
// operations of zdg serve and the Python functions cf, christoffel, floor_sum): options in,
// result out, one JSON form. Every number is a BigInt; the work is exact by escalation (int64,
// then int128, then BigInt: arith/escalate.hpp) and the result says which type served.
//
//   continued_fraction_operation   P/Q -> the terms [a0; a1, ...] and the convergents
//                                  (arith/continued_fraction.hpp), O(log min(|P|, |Q|)) terms
//   christoffel_operation          the lower (or upper) Christoffel word of slope P/Q reduced,
//                                  its standard factorization and Stern-Brocot parents
//                                  (arith/christoffel.hpp, arith/stern_brocot.hpp); the word
//                                  has P + Q letters: ask for it only where that fits
//   floor_sum_operation            sum_{i=0}^{N-1} floor((A i + B) / M) in O(log M)
//                                  (arith/floor_sum.hpp)
//   sturmian_operation             the periodic continued fraction of x = (A + B sqrt D) / C,
//                                  and the characteristic (Sturmian) word of its fractional
//                                  part with its Christoffel convergents (arith/sturmian.hpp);
//                                  the work grows with the period (O(sqrt(D) log D) terms, at
//                                  most max_terms) and the word's length (at most 10^8)
//
// Errors: InvalidArgument for a zero denominator, a slope with P < 0 or Q <= 0, N < 0, M = 0,
// and for text that is not a decimal integer (parse_fraction).
#pragma once

#include <zdg/arith/escalate.hpp>
#include <zdg/arith/integer.hpp>
#include <zdg/arith/stern_brocot.hpp>

#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace zdg {

/// "P/Q" or "P" (= P/1), decimal; InvalidArgument naming the text when it is not, or when Q = 0.
Fraction<BigInt> parse_fraction(const std::string& text);

struct ContinuedFractionResult {
  BigInt p, q;                                        // as given
  std::vector<BigInt> terms;                          // [a0; a1, ..., an]
  std::vector<std::pair<BigInt, BigInt>> convergents; // p_k / q_k
  IntKind served = IntKind::int64;
};
ContinuedFractionResult continued_fraction_operation(const Fraction<BigInt>& f);
/// {"p","q","terms","convergents":[[p,q],...],"integer_type"} (integers as decimal strings).
nlohmann::json to_json(const ContinuedFractionResult& r);

struct ChristoffelOptions {
  Fraction<BigInt> slope; // P >= 0, Q > 0; reduced by the operation
  bool upper = false;     // the upper word (the reverse of the lower one)
  bool word = true;       // false: neither the word nor its factors (for huge slopes)
};
struct ChristoffelResult {
  BigInt p, q; // reduced
  bool upper = false, word = true;
  std::string letters;                                                  // the word (when asked)
  std::optional<std::pair<std::string, std::string>> factorization;     // word asked and P > 0
  std::optional<std::pair<Fraction<BigInt>, Fraction<BigInt>>> parents; // P > 0 (0/1 is a root)
  IntKind served = IntKind::int64;
};
ChristoffelResult christoffel_operation(const ChristoffelOptions& o);
/// {"p","q","upper",("word","standard_factorization":[u,v] or [],) "parents":[[p,q],[p,q]] or
/// [], "integer_type"}.
nlohmann::json to_json(const ChristoffelResult& r);

struct FloorSumOptions {
  BigInt n, m, a, b; // N >= 0, M != 0
};
struct FloorSumResult {
  BigInt value;
  IntKind served = IntKind::int64;
};
FloorSumResult floor_sum_operation(const FloorSumOptions& o);
/// {"value","integer_type"}.
nlohmann::json to_json(const FloorSumResult& r);

struct SturmianOptions {
  BigInt a, b, d, c;                 // x = (a + b sqrt d) / c: b != 0, c != 0, d > 0 not a square
  std::uint64_t length = 64;         // letters of the characteristic word (at most 10^8)
  std::uint64_t max_terms = 1000000; // bound on the preperiod and period together
};
struct SturmianResult {
  BigInt P, D, Q;                        // x = (P + sqrt D) / Q, Q | D - P^2
  std::vector<BigInt> preperiod, period; // x = [preperiod; (period)]
  BigInt floor;                          // floor(x)
  BigInt alpha_P;                        // alpha = x - floor(x) = (alpha_P + sqrt D) / Q
  std::string word;                      // the first `length` letters of c_alpha
  std::vector<std::pair<BigInt, BigInt>> christoffel; // slopes p/(q - p), q <= length + 2
  IntKind served = IntKind::int64;
};
SturmianResult sturmian_operation(const SturmianOptions& o);
/// {"surd","preperiod","period","floor","slope","word","christoffel_convergents":[[p,q],...],
/// "integer_type"} (integers as decimal strings; "slope" the text of alpha).
nlohmann::json to_json(const SturmianResult& r);

} // namespace zdg
