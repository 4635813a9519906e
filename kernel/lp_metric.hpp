// The l_p metrics of the separable transforms and the options they share.
//
// d_p(x, y) = (sum_k |x_k - y_k|^p)^(1/p) for an integer p >= 1, d_inf(x, y) = max_k |x_k - y_k|.
// The transforms never take roots: for finite p they work with the exact integer d_p^p (the
// "p-th power distance", squared for l_2), for l_inf with d_inf itself. On a torus axis of
// extent n the coordinate difference is the periodic one, min(|t| mod n, n - |t| mod n).
#pragma once

#include <zdg/arith/error.hpp>
#include <zdg/arith/integer.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace zdg {

struct Metric {
  /// The exponent p >= 1; 0 stands for l_inf.
  int p = 2;

  bool is_inf() const { return p == 0; }
  std::string name() const { return is_inf() ? "linf" : "l" + std::to_string(p); }
  friend bool operator==(const Metric&, const Metric&) = default;

  static Metric l1() { return {1}; }
  static Metric l2() { return {2}; }
  static Metric linf() { return {0}; }
  /// l_p; InvalidArgument for p < 1.
  static Metric lp(long long p) {
    if (p < 1 || p > 1000000) {
      throw InvalidArgument("metric: p = " + std::to_string(p) + " is not an integer >= 1");
    }
    return {static_cast<int>(p)};
  }
};

/// "l1", "l2", "linf", "lP" (P an integer >= 1; "l0" is an error).
inline Metric parse_metric(const std::string& text) {
  if (text == "linf" || text == "Linf" || text == "inf") return Metric::linf();
  if (text.size() >= 2 && (text[0] == 'l' || text[0] == 'L')) {
    std::string digits = text.substr(1);
    bool ok = !digits.empty() && digits.size() <= 8;
    for (char c : digits) ok = ok && c >= '0' && c <= '9';
    if (ok) return Metric::lp(std::stoll(digits));
  }
  throw InvalidArgument("metric: '" + text + "' is not one of l1, l2, linf, lP (P >= 1)");
}

/// The "length" of a coordinate difference t >= 0 in the metric: t^p, or t for l_inf.
inline BigInt metric_power(const Metric& m, std::int64_t t) {
  if (m.is_inf()) return BigInt(t);
  BigInt r = 1;
  for (int i = 0; i < m.p; ++i) r *= t;
  return r;
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
