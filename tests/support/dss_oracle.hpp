// Brute-force oracle for digital straight segments, for tests: searches every (a, b) with
// gcd(a, b) = 1 by increasing period omega and checks feasibility exactly (the points fit a
// line of period omega iff max - min of a x - b y over them is < omega). The first period that
// fits gives the minimal characteristics; the test also checks that they are unique once
// oriented along the path ((b, a) . (last - first) > 0) and that mu is tight (both leaning
// points present). Exponential in nothing but slow (O(n omega^2) per period): short paths only.
#pragma once

#include <zdg/arith/dss_recognizer.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>
#include <optional>
#include <set>
#include <utility>
#include <vector>

namespace zdg::test {

struct OracleDss {
  BigInt a, b, mu, omega;
  int candidates = 0; // oriented lines of the minimal period that contain the points
  bool tight = false; // max - min of the remainders == omega - 1
};

/// Minimal characteristics of the path (as a set of distinct points, in order), or nullopt when
/// it is not a DSS (repeated points included).
inline std::optional<OracleDss> oracle_dss(const std::vector<Point2<BigInt>>& pts, Connectivity c) {
  std::set<std::pair<BigInt, BigInt>> seen;
  for (const auto& p : pts) {
    if (!seen.insert({p.x, p.y}).second) return std::nullopt;
  }
  const auto& f = pts.front();
  if (pts.size() == 1) return OracleDss{BigInt(0), BigInt(1), BigInt(-f.y), BigInt(1), 1, true};
  const auto& l = pts.back();
  BigInt dx = l.x - f.x, dy = l.y - f.y;
  const long max_omega = 2 * static_cast<long>(pts.size()) + 2;
  for (long om = 1; om <= max_omega; ++om) {
    std::optional<OracleDss> found;
    int count = 0;
    for (long a = -om; a <= om; ++a) {
      for (long b = -om; b <= om; ++b) {
        long w = c == Connectivity::eight ? std::max(std::labs(a), std::labs(b))
                                          : std::labs(a) + std::labs(b);
        if (w != om || std::gcd(a, b) != 1) continue;
        if (BigInt(b) * dx + BigInt(a) * dy <= 0) continue;
        BigInt lo, hi;
        bool first = true;
        for (const auto& p : pts) {
          BigInt r = BigInt(a) * p.x - BigInt(b) * p.y;
          if (first || r < lo) lo = r;
          if (first || r > hi) hi = r;
          first = false;
        }
        if (hi - lo < om) {
          ++count;
          if (!found) found = OracleDss{BigInt(a), BigInt(b), lo, BigInt(om), 0, hi - lo == om - 1};
        }
      }
    }
    if (found) {
      found->candidates = count;
      return found;
    }
  }
  return std::nullopt;
}

/// The four (eight) steps of the connectivity, counter-clockwise from (1, 0).
inline std::vector<std::pair<int, int>> all_steps(Connectivity c) {
  if (c == Connectivity::four) return {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  return {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
}

} // namespace zdg::test
