// The l_p metrics of the separable transforms and the options they share.
//
// d_p(x, y) = (sum_k |x_k - y_k|^p)^(1/p) for an integer p >= 1, d_inf(x, y) = max_k |x_k - y_k|.
// The transforms never take roots: for finite p they work with the exact integer d_p^p (the
// "p-th power distance", squared for l_2), for l_inf with d_inf itself. On a torus axis of
// extent n the coordinate difference is the periodic one, min(|t| mod n, n - |t| mod n).
//
// Supported exponents: 1 <= p <= kMaxMetricP (1000), and a transform further needs
// L^p < 2^kMaxMetricBits (2^4096), L the longest line of the domain (3 n on a torus axis):
// p <= 4096 / log2(L), for instance p <= 410 on a 1000-wide image. The values are exact
// integers of about p log2(L) bits, so a larger p would cost time and memory in proportion to
// p (an unbounded p once cost minutes: bench/README.md); within these limits every
// integer has at most 4096 bits and the cost of a transform is at most a constant factor
// (about 64 machine words an operation) above the int64 one, whatever p. For p near the
// limits, l_inf is the limit of l_p and costs O(N d).
#pragma once

#include <zdg/arith/error.hpp>
#include <zdg/arith/integer.hpp>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace zdg {

/// The largest supported exponent p of an l_p metric, and the bit budget of the p-th powers
/// of a transform (see above).
inline constexpr int kMaxMetricP = 1000;
inline constexpr int kMaxMetricBits = 4096;

struct Metric {
  /// The exponent p >= 1; 0 stands for l_inf.
  int p = 2;

  bool is_inf() const { return p == 0; }
  std::string name() const { return is_inf() ? "linf" : "l" + std::to_string(p); }
  friend bool operator==(const Metric&, const Metric&) = default;

  static Metric l1() { return {1}; }
  static Metric l2() { return {2}; }
  static Metric linf() { return {0}; }
  /// l_p; InvalidArgument for p < 1 or p > kMaxMetricP.
  static Metric lp(long long p) {
    if (p < 1) {
      throw InvalidArgument("metric: p = " + std::to_string(p) + " is not an integer >= 1");
    }
    if (p > kMaxMetricP) {
      throw InvalidArgument("metric: l" + std::to_string(p) + " is beyond the supported l1 .. l" +
                            std::to_string(kMaxMetricP) +
                            " (values are exact p-th powers; use linf, the limit of l_p)");
    }
    return {static_cast<int>(p)};
  }
};

/// "l1", "l2", "linf", "lP" (P a decimal integer, 1 <= P <= kMaxMetricP; "l0" is an error).
inline Metric parse_metric(const std::string& text) {
  if (text == "linf" || text == "Linf" || text == "inf") return Metric::linf();
  if (text.size() >= 2 && (text[0] == 'l' || text[0] == 'L') && text[1] >= '0' && text[1] <= '9') {
    long long p = 0;
    try {
      p = parse_integer<long long>(std::string_view(text).substr(1));
    } catch (const OverflowError&) {
      p = kMaxMetricP + 1; // beyond the range: the message of Metric::lp
    } catch (const InvalidArgument&) {
      p = -1;
    }
    if (p >= 0) return Metric::lp(p);
  }
  throw InvalidArgument(
      "metric: '" + text.substr(0, 40) +
      "' is not one of l1, l2, linf, lP (1 <= P <= " + std::to_string(kMaxMetricP) + ")");
}

/// The "length" of a coordinate difference t >= 0 in the metric: t^p, or t for l_inf
/// (square-and-multiply: O(log p) products).
inline BigInt metric_power(const Metric& m, std::int64_t t) {
  if (m.is_inf()) return BigInt(t);
  return boost::multiprecision::pow(BigInt(t), static_cast<unsigned>(m.p));
}

struct TransformOptions {
  Metric metric = Metric::l2();
  /// torus[k]: axis k is periodic. Empty = no periodic axis; otherwise one flag per axis.
  std::vector<bool> torus;
  /// Worker threads; 0 = all cores. The result does not depend on it.
  unsigned threads = 0;
  /// Forces an engine integer of at least this many bits (0: the narrowest that the proven
  /// bound allows; 64, 128, or more for GMP). Results never depend on it; tests use it to
  /// run every width.
  unsigned min_engine_bits = 0;

  bool periodic(int k) const { return !torus.empty() && torus[static_cast<std::size_t>(k)]; }
};

} // namespace zdg
