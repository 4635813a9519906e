// Test support for the separable transforms: random small n-D cases (1D to 4D, odd and
// non-cubic extents, negative lower bounds, torus axes, l1 l2 l3 l4 linf) and brute-force
// oracles (every pair of points).
#pragma once

#include <zdg/arith/integer.hpp>
#include <zdg/kernel/images/image.hpp>
#include <zdg/kernel/transforms/lp_metric.hpp>

#include <rapidcheck.h>

#include <cstdint>
#include <cstdlib>
#include <random>
#include <vector>

namespace zdg::test {

/// The engine width a tower type stands for in the typed transform tests.
template <class I>
unsigned engine_bits() {
  if constexpr (std::is_same_v<I, Int64>) {
    return 64;
  } else if constexpr (std::is_same_v<I, Int128>) {
    return 128;
  } else {
    return 256;
  }
}

inline bool sanitized() {
  return std::getenv("ZDG_SANITIZE") != nullptr;
}

struct TransformCase {
  TransformOptions opt;
  Image<std::uint8_t> shape;
};

/// A random case (call inside a RapidCheck property; RapidCheck draws the seed, the case is
/// drawn uniformly from it so that sizes do not depend on RapidCheck's size parameter).
/// finite_p: no linf.
inline TransformCase random_transform_case(bool finite_p = false) {
  std::mt19937 rng(*rc::gen::arbitrary<std::uint32_t>());
  auto pick = [&](int lo, int hi) {
    return lo + static_cast<int>(rng() % static_cast<unsigned>(hi - lo + 1));
  };
  int d = pick(1, 4);
  const int max_extent[] = {0, 40, 16, 8, 5};
  std::vector<std::int64_t> ext, low;
  for (int k = 0; k < d; ++k) {
    ext.push_back(pick(1, max_extent[d]));
    low.push_back(pick(-6, 6));
  }
  TransformCase c;
  c.opt.metric = Metric{finite_p ? pick(1, 4) : pick(0, 4)};
  if (pick(0, 1) == 1) {
    for (int k = 0; k < d; ++k) c.opt.torus.push_back(pick(0, 1) == 1);
  }
  c.opt.threads = static_cast<unsigned>(pick(1, 3));
  Domain dom(ext, low);
  int density = pick(0, 100);
  std::vector<std::uint8_t> v(static_cast<std::size_t>(dom.size()));
  for (auto& x : v) x = pick(0, 99) < density ? 1 : 0;
  v[rng() % v.size()] = 0; // at least one background point
  c.shape = Image<std::uint8_t>(dom, v);
  return c;
}

/// |a_k - b_k| along axis k, periodic on torus axes.
inline std::int64_t axis_difference(const Domain& dom, const TransformOptions& opt, int k,
                                    std::int64_t a, std::int64_t b) {
  std::int64_t t = a > b ? a - b : b - a;
  if (opt.periodic(k)) t = std::min(t, dom.extent(k) - t);
  return t;
}

/// d_p(a, b)^p (d_inf for linf) between points of linear indices i and j, in type I.
/// The points of dom, cached (the oracles ask for them N^2 times).
inline const std::vector<std::vector<std::int64_t>>& cached_points(const Domain& dom) {
  static thread_local Domain cached;
  static thread_local std::vector<std::vector<std::int64_t>> pts;
  if (!(cached == dom) || static_cast<std::int64_t>(pts.size()) != dom.size()) {
    cached = dom;
    pts.clear();
    for (std::int64_t i = 0; i < dom.size(); ++i) pts.push_back(dom.point(i));
  }
  return pts;
}

template <class I>
I metric_length(const Domain& dom, const TransformOptions& opt, std::int64_t i, std::int64_t j) {
  const auto& pts = cached_points(dom);
  const auto& a = pts[static_cast<std::size_t>(i)];
  const auto& b = pts[static_cast<std::size_t>(j)];
  I r = 0;
  for (int k = 0; k < dom.dim(); ++k) {
    std::int64_t t = axis_difference(dom, opt, k, a[static_cast<std::size_t>(k)],
                                     b[static_cast<std::size_t>(k)]);
    if (opt.metric.is_inf()) {
      if (I(t) > r) r = I(t);
    } else {
      I pk = 1;
      for (int e = 0; e < opt.metric.p; ++e) pk *= I(t);
      r += pk;
    }
  }
  return r;
}

/// Brute-force distance transform (values in I).
template <class I>
std::vector<I> brute_distance_transform(const Image<std::uint8_t>& shape,
                                        const TransformOptions& opt) {
  const Domain& dom = shape.domain();
  std::vector<I> out(static_cast<std::size_t>(dom.size()));
  for (std::int64_t i = 0; i < dom.size(); ++i) {
    bool first = true;
    I best = 0;
    for (std::int64_t j = 0; j < dom.size(); ++j) {
      if (shape[j] != 0) continue;
      I v = metric_length<I>(dom, opt, i, j);
      if (first || v < best) best = v;
      first = false;
    }
    out[static_cast<std::size_t>(i)] = best;
  }
  return out;
}

} // namespace zdg::test
