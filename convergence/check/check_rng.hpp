// The random source of the property campaigns (zdg check): SplitMix64 (Steele, Lea and Flood,
// "Fast splittable pseudorandom number generators", OOPSLA 2014), a 64-bit state advanced by
// a Weyl increment and finalized by a bijective mixer. Deterministic on every platform, so
// that a seed or a replay token reproduces a case exactly; case k of a campaign of seed S is
// drawn from case_seed(S, k), independent of the thread that runs it.
//
// Draws: below(n) by the multiply-high reduction (bias below n / 2^64, irrelevant for test
// generation), magnitudes of B bits biased towards the places where exact arithmetic breaks:
// small values, powers of two and their neighbours (2^63 - 1, -2^63, 2^127 ...), values of
// every bit length up to B. O(1) per draw (O(B) for a BigInt).
#pragma once

#include <zdg/arith/integer.hpp>

#include <cstdint>

namespace zdg::check {

class Rng {
public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}

  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  /// Uniform in [0, n) (n > 0).
  std::uint64_t below(std::uint64_t n) {
    return static_cast<std::uint64_t>((static_cast<uint128_t>(next()) * n) >> 64);
  }
  /// Uniform in [lo, hi] (lo <= hi, hi - lo < 2^63).
  std::int64_t range(std::int64_t lo, std::int64_t hi) {
    return lo + static_cast<std::int64_t>(below(static_cast<std::uint64_t>(hi - lo) + 1));
  }
  /// True with probability num / den.
  bool chance(std::uint64_t num, std::uint64_t den) { return below(den) < num; }

  /// Uniform in [0, 2^bits).
  BigInt uniform_bits(int bits) {
    BigInt v = 0;
    int left = bits;
    while (left >= 64) {
      v = (v << 64) | BigInt(next());
      left -= 64;
    }
    if (left > 0) v = (v << left) | BigInt(next() >> (64 - left));
    return v;
  }

  /// An integer of magnitude below 2^bits (bits >= 1), any sign, biased to the edges.
  BigInt edgy(int bits) {
    BigInt v;
    switch (below(5)) {
    case 0:
      v = BigInt(range(-40, 40));
      break;
    case 1: { // a power of two and its neighbours: 2^k - 1, 2^k, 2^k + 1
      const int k = static_cast<int>(below(static_cast<std::uint64_t>(bits)));
      v = (BigInt(1) << k) + BigInt(range(-1, 1));
      if (chance(1, 2)) v = -v;
      break;
    }
    case 2: { // every bit length equally likely
      const int len = 1 + static_cast<int>(below(static_cast<std::uint64_t>(bits)));
      v = uniform_bits(len) | (BigInt(1) << (len - 1));
      if (chance(1, 2)) v = -v;
      break;
    }
    default:
      v = uniform_bits(bits);
      if (chance(1, 2)) v = -v;
      break;
    }
    // Keep |v| < 2^bits (2^k + 1 with k = bits - 1 stays below 2^bits for bits >= 2).
    const BigInt lim = BigInt(1) << bits;
    if (v >= lim || v <= -lim) v = v > 0 ? BigInt(lim - 1) : BigInt(1 - lim);
    return v;
  }

  /// A nonnegative edgy integer below 2^bits.
  BigInt edgy_natural(int bits) {
    BigInt v = edgy(bits);
    return v < 0 ? BigInt(-v) : v;
  }

private:
  std::uint64_t state_;
};

/// The seed of case `index` of a campaign of seed `seed`.
inline std::uint64_t case_seed(std::uint64_t seed, std::uint64_t index) {
  Rng r(seed ^ (index * 0xd1b54a32d192ed03ULL));
  r.next();
  return r.next();
}

} // namespace zdg::check
