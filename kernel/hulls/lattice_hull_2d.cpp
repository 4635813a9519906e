#include <zdg/kernel/hulls/lattice_hull_2d.hpp>

#include <algorithm>
#include <array>
#include <numeric>

namespace zdg {

namespace {
// Lexicographic orders (BigInt has no <=>, so Point2's defaulted one is not used).
template <TowerInt I>
bool xy_less(const Point2<I>& a, const Point2<I>& b) {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}
template <TowerInt I>
bool yx_less(const Point2<I>& a, const Point2<I>& b) {
  return a.y < b.y || (a.y == b.y && a.x < b.x);
}
} // namespace

// Akl-Toussaint throw-away: the extreme points in the 8 directions (+-x, +-y, +-(x+y),
// +-(x-y)) span a convex polygon of hull points; points strictly inside it are no vertices.
template <TowerInt I>
std::vector<std::size_t> akl_toussaint_survivors(std::span<const Point2<I>> pts) {
  const std::size_t n = pts.size();
  std::array<std::size_t, 8>
      e{}; // ccw: min y, max x-y, max x, max x+y, max y, min x-y, min x, min x+y
  std::array<I, 8> best;
  auto key = [&](int k, const Point2<I>& p) -> I {
    switch (k) {
    case 0:
      return -p.y;
    case 1:
      return p.x - p.y;
    case 2:
      return p.x;
    case 3:
      return p.x + p.y;
    case 4:
      return p.y;
    case 5:
      return p.y - p.x;
    case 6:
      return -p.x;
    default:
      return -p.x - p.y;
    }
  };
  for (int k = 0; k < 8; ++k) best[k] = key(k, pts[0]);
  for (std::size_t i = 1; i < n; ++i) {
    for (int k = 0; k < 8; ++k) {
      I v = key(k, pts[i]);
      if (v > best[k]) {
        best[k] = v;
        e[k] = i;
      }
    }
  }
  std::vector<std::size_t> poly;
  for (int k = 0; k < 8; ++k) {
    if (poly.empty() || pts[poly.back()] != pts[e[k]]) poly.push_back(e[k]);
  }
  while (poly.size() > 1 && pts[poly.back()] == pts[poly.front()]) poly.pop_back();
  std::vector<std::size_t> keep;
  if (poly.size() < 3) {
    keep.resize(n);
    std::iota(keep.begin(), keep.end(), std::size_t{0});
    return keep;
  }
  for (std::size_t i = 0; i < n; ++i) {
    bool inside = true;
    for (std::size_t k = 0; k < poly.size() && inside; ++k) {
      inside = orientation(pts[poly[k]], pts[poly[(k + 1) % poly.size()]], pts[i]) > 0;
    }
    if (!inside) keep.push_back(i);
  }
  return keep;
}

template <TowerInt I>
std::vector<std::size_t> lattice_hull_2d_indices(std::span<const Point2<I>> pts) {
  std::vector<std::size_t> idx;
  if (pts.size() > 64) {
    idx = akl_toussaint_survivors(pts);
  } else {
    idx.resize(pts.size());
    std::iota(idx.begin(), idx.end(), std::size_t{0});
  }
  std::stable_sort(idx.begin(), idx.end(),
                   [&](std::size_t a, std::size_t b) { return xy_less(pts[a], pts[b]); });
  idx.erase(std::unique(idx.begin(), idx.end(),
                        [&](std::size_t a, std::size_t b) { return pts[a] == pts[b]; }),
            idx.end());
  const std::size_t n = idx.size();
  if (n <= 2) {
    if (n == 2 && yx_less(pts[idx[1]], pts[idx[0]])) std::swap(idx[0], idx[1]);
    return idx;
  }
  // Lower chain left to right, then upper chain right to left; strict left turns only.
  std::vector<std::size_t> h(2 * n);
  std::size_t k = 0;
  for (std::size_t i = 0; i < n; ++i) {
    while (k >= 2 && orientation(pts[h[k - 2]], pts[h[k - 1]], pts[idx[i]]) <= 0) --k;
    h[k++] = idx[i];
  }
  for (std::size_t i = n - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && orientation(pts[h[k - 2]], pts[h[k - 1]], pts[idx[i]]) <= 0) --k;
    h[k++] = idx[i];
  }
  h.resize(k - 1);     // the last point repeats the first
  if (h.size() == 2) { // all collinear: the two endpoints, lowest-then-leftmost first
    if (yx_less(pts[h[1]], pts[h[0]])) std::swap(h[0], h[1]);
    return h;
  }
  auto lowest = std::min_element(
      h.begin(), h.end(), [&](std::size_t a, std::size_t b) { return yx_less(pts[a], pts[b]); });
  std::rotate(h.begin(), lowest, h.end());
  return h;
}

namespace {
template <TowerInt To, TowerInt From>
std::vector<Point2<To>> convert_points(std::span<const Point2<From>> pts) {
  std::vector<Point2<To>> out;
  out.reserve(pts.size());
  for (const auto& p : pts) out.push_back({int_cast<To>(p.x), int_cast<To>(p.y)});
  return out;
}
} // namespace

template <TowerInt I>
std::vector<Point2<I>> lattice_hull_2d(std::span<const Point2<I>> pts) {
  std::vector<Point2<I>> out;
  for (auto i : lattice_hull_2d_indices<I>(pts)) out.push_back(pts[i]);
  return out;
}

template <TowerInt I>
Escalated<std::vector<Point2<I>>> lattice_hull_2d_exact(std::span<const Point2<I>> pts) {
  auto idx = escalate([&]<class J>(std::type_identity<J>) {
    if constexpr (std::same_as<I, J>) {
      return lattice_hull_2d_indices<I>(pts);
    } else {
      auto conv = convert_points<J, I>(pts); // OverflowError when a point does not fit J
      return lattice_hull_2d_indices<J>(std::span<const Point2<J>>(conv));
    }
  });
  std::vector<Point2<I>> out;
  out.reserve(idx.value.size());
  for (auto i : idx.value) out.push_back(pts[i]);
  return {std::move(out), idx.served};
}

#define ZDG_INSTANTIATE(I)                                                                         \
  template std::vector<std::size_t> lattice_hull_2d_indices<I>(std::span<const Point2<I>>);        \
  template std::vector<Point2<I>> lattice_hull_2d<I>(std::span<const Point2<I>>);                  \
  template Escalated<std::vector<Point2<I>>> lattice_hull_2d_exact<I>(std::span<const Point2<I>>);
ZDG_INSTANTIATE(Int64)
ZDG_INSTANTIATE(Int128)
ZDG_INSTANTIATE(BigInt)
#undef ZDG_INSTANTIATE

} // namespace zdg
