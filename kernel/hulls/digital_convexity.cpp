#include <zdg/kernel/hulls/digital_convexity.hpp>

#include <zdg/arith/point.hpp>
#include <zdg/kernel/hulls/lattice_hull_2d.hpp>
#include <zdg/kernel/hulls/lattice_hull_3d.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace zdg {

namespace {

template <int D, TowerInt I>
using Pt = std::array<I, D>;

// The hull as half-spaces a . p <= b.
template <int D, TowerInt I>
struct HalfSpaces {
  std::vector<Pt<D, I>> a;
  std::vector<I> b;
  void add(const Pt<D, I>& n, const I& c) {
    a.push_back(n);
    b.push_back(c);
  }
};

template <int D, TowerInt I>
I dot_(const Pt<D, I>& u, const Pt<D, I>& v) {
  I s = u[0] * v[0];
  for (int i = 1; i < D; ++i) s += u[i] * v[i];
  return s;
}

template <int D, TowerInt I>
void sort_unique(std::vector<Pt<D, I>>& v) {
  if (!std::is_sorted(v.begin(), v.end())) std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

// Both signs of n . p = c.
template <int D, TowerInt I>
void add_equality(HalfSpaces<D, I>& h, const Pt<D, I>& n, const I& c) {
  Pt<D, I> m;
  for (int i = 0; i < D; ++i) m[i] = -n[i];
  h.add(n, c);
  h.add(m, -c);
}

template <TowerInt I>
HalfSpaces<2, I> half_spaces(std::span<const Pt<2, I>> pts) {
  std::vector<Point2<I>> q;
  q.reserve(pts.size());
  for (const auto& p : pts) q.push_back({p[0], p[1]});
  const auto v = lattice_hull_2d<I>(std::span<const Point2<I>>(q));
  HalfSpaces<2, I> h;
  if (v.size() == 1) {
    add_equality<2, I>(h, {I(1), I(0)}, v[0].x);
    add_equality<2, I>(h, {I(0), I(1)}, v[0].y);
  } else if (v.size() == 2) {
    const auto d = v[1] - v[0];
    add_equality<2, I>(h, {-d.y, d.x}, -d.y * v[0].x + d.x * v[0].y);
    h.add({d.x, d.y}, dot(d, v[1]));
    h.add({-d.x, -d.y}, -dot(d, v[0]));
  } else {
    // Counterclockwise: the inside is left of each edge a -> b, n = (e.y, -e.x) points out.
    for (std::size_t i = 0; i < v.size(); ++i) {
      const auto& a = v[i];
      const auto e = v[(i + 1) % v.size()] - a;
      h.add({e.y, -e.x}, e.y * a.x - e.x * a.y);
    }
  }
  return h;
}

template <TowerInt I>
Pt<3, I> arr(const Point3<I>& p) {
  return {p.x, p.y, p.z};
}

template <TowerInt I>
HalfSpaces<3, I> half_spaces(std::span<const Pt<3, I>> pts) {
  std::vector<Point3<I>> q;
  q.reserve(pts.size());
  for (const auto& p : pts) q.push_back({p[0], p[1], p[2]});
  const auto hull = lattice_hull_3d<I>(std::span<const Point3<I>>(q));
  HalfSpaces<3, I> h;
  const auto& v = hull.vertices;
  if (hull.dimension == 0) {
    add_equality<3, I>(h, {I(1), I(0), I(0)}, v[0].x);
    add_equality<3, I>(h, {I(0), I(1), I(0)}, v[0].y);
    add_equality<3, I>(h, {I(0), I(0), I(1)}, v[0].z);
  } else if (hull.dimension == 1) {
    // (p - v0) x d = 0 (three equalities, one may be trivial) and v0 . d <= p . d <= v1 . d.
    const auto d = v[1] - v[0];
    for (const auto& e :
         {Point3<I>{I(1), I(0), I(0)}, Point3<I>{I(0), I(1), I(0)}, Point3<I>{I(0), I(0), I(1)}}) {
      const auto n = cross(d, e);
      add_equality<3, I>(h, arr(n), dot(n, v[0]));
    }
    h.add(arr(d), dot(d, v[1]));
    h.add(arr(-d), -dot(d, v[0]));
  } else if (hull.dimension == 2) {
    // The plane n . p = c and, for each edge a -> b of the facet (counterclockwise seen along
    // n), (n x (b - a)) . (p - a) >= 0.
    const auto& n = hull.normals[0];
    const auto& f = hull.facets[0];
    add_equality<3, I>(h, arr(n), dot(n, v[f[0]]));
    for (std::size_t i = 0; i < f.size(); ++i) {
      const auto& a = v[f[i]];
      const auto m = cross(v[f[(i + 1) % f.size()]] - a, n); // = -(n x e)
      h.add(arr(m), dot(m, a));
    }
  } else {
    for (std::size_t i = 0; i < hull.facets.size(); ++i) {
      h.add(arr(hull.normals[i]), dot(hull.normals[i], v[hull.facets[i][0]]));
    }
  }
  return h;
}

// The vertices of Cvxh(pts) (a subset of pts with the same hull).
template <TowerInt I>
std::vector<Pt<2, I>> hull_vertices(std::span<const Pt<2, I>> pts) {
  std::vector<Point2<I>> q;
  q.reserve(pts.size());
  for (const auto& p : pts) q.push_back({p[0], p[1]});
  std::vector<Pt<2, I>> out;
  for (const auto& v : lattice_hull_2d<I>(std::span<const Point2<I>>(q))) out.push_back({v.x, v.y});
  return out;
}

template <TowerInt I>
std::vector<Pt<3, I>> hull_vertices(std::span<const Pt<3, I>> pts) {
  std::vector<Point3<I>> q;
  q.reserve(pts.size());
  for (const auto& p : pts) q.push_back({p[0], p[1], p[2]});
  std::vector<Pt<3, I>> out;
  for (const auto& v : lattice_hull_3d<I>(std::span<const Point3<I>>(q)).vertices)
    out.push_back(arr(v));
  return out;
}

// Cvxh(X + U_mask) = Cvxh(V + U_mask) for V the vertices of Cvxh(X): the half-spaces from the
// few points of V + U_mask.
template <int D, TowerInt I>
HalfSpaces<D, I> dilated_half_spaces(const std::vector<Pt<D, I>>& v, unsigned mask) {
  std::vector<Pt<D, I>> pts;
  for (const auto& p : v) {
    for (unsigned u = 0; u < (1u << D); ++u) {
      if ((u & mask) != u) continue;
      auto q = p;
      for (int i = 0; i < D; ++i) {
        if (u & (1u << i)) q[i] += 1;
      }
      pts.push_back(q);
    }
  }
  sort_unique<D, I>(pts);
  return half_spaces<I>(std::span<const Pt<D, I>>(pts));
}

// The index of a half-space that p violates (the hint first), or -1 when p is in the hull.
template <int D, TowerInt I>
long violated(const HalfSpaces<D, I>& h, const Pt<D, I>& p, std::size_t& hint) {
  const std::size_t m = h.a.size();
  if (hint < m && dot_<D, I>(h.a[hint], p) > h.b[hint]) return static_cast<long>(hint);
  for (std::size_t i = 0; i < m; ++i) {
    if (dot_<D, I>(h.a[i], p) > h.b[i]) {
      hint = i;
      return static_cast<long>(i);
    }
  }
  return -1;
}

// The integers t with (prefix, t) in the hull: [lo, hi], or none.
template <int D, TowerInt I>
std::optional<std::pair<I, I>> column_interval(const HalfSpaces<D, I>& h,
                                               const std::array<I, D - 1>& prefix) {
  std::optional<I> lo, hi;
  for (std::size_t i = 0; i < h.a.size(); ++i) {
    I r = h.b[i];
    for (int j = 0; j + 1 < D; ++j) r -= h.a[i][j] * prefix[j];
    const I& c = h.a[i][D - 1];
    if (c > 0) {
      I t = floor_div(r, c);
      if (!hi || t < *hi) hi = t;
    } else if (c < 0) {
      I t = ceil_div(r, c);
      if (!lo || t > *lo) lo = t;
    } else if (r < 0) {
      return std::nullopt;
    }
  }
  if (!lo || !hi) throw std::logic_error("digital convexity: an unbounded hull column");
  if (*lo > *hi) return std::nullopt;
  return std::make_pair(*lo, *hi);
}

template <int D, TowerInt I>
Pt<D, I> with_last(const std::array<I, D - 1>& prefix, const I& t) {
  Pt<D, I> p;
  for (int j = 0; j + 1 < D; ++j) p[j] = prefix[j];
  p[D - 1] = t;
  return p;
}

template <int D, TowerInt I>
std::array<I, D - 1> prefix_of(const Pt<D, I>& p) {
  std::array<I, D - 1> q;
  for (int j = 0; j + 1 < D; ++j) q[j] = p[j];
  return q;
}

[[noreturn]] void too_many(std::uint64_t limit, const char* what) {
  throw InvalidArgument(std::string("digital convexity: more than ") + std::to_string(limit) + " " +
                        what + " to sweep (raise the limit)");
}

// Calls f(prefix) for each lattice column of the projection of Cvxh(s) along the last axis, in
// lexicographic order. s sorted, non-empty. Each column and each empty row counts against budget.
template <int D, TowerInt I, class F>
void for_each_column(const std::vector<Pt<D, I>>& s, std::uint64_t& budget, std::uint64_t limit,
                     F&& f) {
  auto spend = [&] {
    if (budget == 0) too_many(limit, "lattice columns");
    --budget;
  };
  if constexpr (D == 2) {
    for (I x = s.front()[0]; x <= s.back()[0]; x += 1) {
      spend();
      f(std::array<I, 1>{x});
    }
  } else {
    std::vector<Pt<2, I>> proj;
    proj.reserve(s.size());
    for (const auto& p : s) {
      if (proj.empty() || proj.back()[0] != p[0] || proj.back()[1] != p[1])
        proj.push_back({p[0], p[1]});
    }
    const auto h2 = half_spaces<I>(std::span<const Pt<2, I>>(proj));
    for (I x = proj.front()[0]; x <= proj.back()[0]; x += 1) {
      spend();
      const auto iv = column_interval<2, I>(h2, std::array<I, 1>{x});
      if (!iv) continue;
      for (I y = iv->first; y <= iv->second; y += 1) {
        spend();
        f(std::array<I, 2>{x, y});
      }
    }
  }
}

// A lattice point of Cvxh(s) \ s, s sorted without duplicates.
template <int D, TowerInt I>
std::optional<Pt<D, I>> hull_witness_sorted(const std::vector<Pt<D, I>>& s,
                                            const HalfSpaces<D, I>& h, std::uint64_t max_columns) {
  std::optional<Pt<D, I>> found;
  std::size_t k = 0, hint_lo = 0, hint_hi = 0;
  std::uint64_t budget = max_columns;
  struct Stop {};
  try {
    for_each_column<D, I>(s, budget, max_columns, [&](const std::array<I, D - 1>& q) {
      while (k < s.size() && prefix_of<D, I>(s[k]) < q) ++k; // (never: s is inside)
      std::size_t e = k;
      while (e < s.size() && prefix_of<D, I>(s[e]) == q) ++e;
      if (e == k) {
        if (auto iv = column_interval<D, I>(h, q)) {
          found = with_last<D, I>(q, iv->first);
          throw Stop{};
        }
        return;
      }
      for (std::size_t i = k + 1; i < e; ++i) {
        if (s[i][D - 1] != s[i - 1][D - 1] + 1) {
          found = with_last<D, I>(q, s[i - 1][D - 1] + 1); // between two points of s
          throw Stop{};
        }
      }
      const auto below = with_last<D, I>(q, s[k][D - 1] - 1);
      const auto above = with_last<D, I>(q, s[e - 1][D - 1] + 1);
      k = e;
      if (violated<D, I>(h, below, hint_lo) < 0) {
        found = below;
        throw Stop{};
      }
      if (violated<D, I>(h, above, hint_hi) < 0) {
        found = above;
        throw Stop{};
      }
    });
  } catch (const Stop&) {
  }
  return found;
}

// s + {0, e_axis}, s sorted without duplicates (the result too).
template <int D, TowerInt I>
std::vector<Pt<D, I>> dilate(const std::vector<Pt<D, I>>& s, int axis) {
  std::vector<Pt<D, I>> t(s);
  for (auto& p : t) p[axis] += 1;
  std::vector<Pt<D, I>> out;
  out.reserve(s.size() + s.size() / 4);
  std::set_union(s.begin(), s.end(), t.begin(), t.end(), std::back_inserter(out));
  return out;
}

// The sets X + U_I for every mask I, built by one dilation each from a smaller mask.
template <int D, TowerInt I>
std::vector<std::vector<Pt<D, I>>> dilations(const std::vector<Pt<D, I>>& x) {
  std::vector<std::vector<Pt<D, I>>> out(1u << D);
  out[0] = x;
  for (unsigned mask = 1; mask < (1u << D); ++mask) {
    const int axis = std::countr_zero(mask);
    out[mask] = dilate<D, I>(out[mask & (mask - 1u)], axis);
  }
  return out;
}

// The cell of the rational point num / den (den > 0).
template <int D, TowerInt I>
GridCell<D, I> cell_of(const Pt<D, I>& num, const I& den) {
  GridCell<D, I> c;
  for (int i = 0; i < D; ++i) {
    c.lower[i] = floor_div(num[i], den);
    if (c.lower[i] * den != num[i]) c.open |= 1u << i;
  }
  return c;
}

// Masks by dimension, then value: the lowest-dimensional witness first.
template <int D>
std::vector<unsigned> masks_by_dimension() {
  std::vector<unsigned> m;
  for (unsigned k = 0; k < (1u << D); ++k) m.push_back(k);
  std::stable_sort(m.begin(), m.end(),
                   [](unsigned a, unsigned b) { return std::popcount(a) < std::popcount(b); });
  return m;
}

// Gap on an axis: values g with points of x on both sides and none on x_i = g. The point of
// Cvxh(x) on x_i = g between a (below) and b (above) lies in a cell whose vertices all have
// x_i = g.
template <int D, TowerInt I>
std::optional<GridCell<D, I>> gap_cell(const Pt<D, I>& a, const Pt<D, I>& b, int axis) {
  const I g = a[axis] + 1, den = b[axis] - a[axis], t = g - a[axis];
  Pt<D, I> num;
  for (int j = 0; j < D; ++j) num[j] = a[j] * den + t * (b[j] - a[j]);
  return cell_of<D, I>(num, den);
}

template <int D, TowerInt I>
std::optional<GridCell<D, I>> axis_gap_witness(const std::vector<Pt<D, I>>& x) {
  const std::size_t n = x.size();
  for (int axis = 0; axis < D; ++axis) {
    std::size_t lo = 0, hi = 0; // the points of least and greatest coordinate
    for (std::size_t i = 1; i < n; ++i) {
      if (x[i][axis] < x[lo][axis]) lo = i;
      if (x[i][axis] > x[hi][axis]) hi = i;
    }
    const I span = x[hi][axis] - x[lo][axis];
    if (span < I(static_cast<std::int64_t>(n))) {
      // At most n values: mark them, and at a gap take the nearest points on both sides.
      const I base = x[lo][axis];
      const auto index = [&](const Pt<D, I>& p) {
        return static_cast<std::size_t>(int_cast<Int64>(I(p[axis] - base)).value());
      };
      const std::size_t m = index(x[hi]) + 1;
      std::vector<std::size_t> any(m, n);
      for (std::size_t i = 0; i < n; ++i) any[index(x[i])] = i;
      for (std::size_t k = 1; k < m; ++k) {
        if (any[k] != n) continue;
        std::size_t b = k;
        while (any[b] == n) ++b;
        return gap_cell<D, I>(x[any[k - 1]], x[any[b]], axis);
      }
      continue;
    }
    // More than n values apart: there is a gap; sort to find one.
    std::vector<std::size_t> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](std::size_t u, std::size_t v) { return x[u][axis] < x[v][axis]; });
    for (std::size_t i = 1; i < n; ++i) {
      const auto& a = x[order[i - 1]];
      const auto& b = x[order[i]];
      if (b[axis] > a[axis] + 1) return gap_cell<D, I>(a, b, axis);
    }
  }
  return std::nullopt;
}

// 3D: a lattice point (x, y) of the hull of the projection of x with no point of x above it:
// the cell above it that contains a point of Cvxh(x) (a lift of (x, y) by barycentric
// coordinates in a triangle of projected hull vertices).
template <TowerInt I>
std::optional<GridCell<3, I>> projection_witness(const std::vector<Pt<3, I>>& x) {
  std::vector<Pt<2, I>> proj;
  std::vector<Pt<3, I>> lift; // one preimage of each projected point
  for (const auto& p : x) {
    if (proj.empty() || proj.back()[0] != p[0] || proj.back()[1] != p[1]) {
      proj.push_back({p[0], p[1]});
      lift.push_back(p);
    }
  }
  std::vector<Point2<I>> q;
  for (const auto& p : proj) q.push_back({p[0], p[1]});
  const auto idx = lattice_hull_2d_indices<I>(std::span<const Point2<I>>(q));
  const auto h2 = half_spaces<I>(std::span<const Pt<2, I>>(proj));
  std::size_t k = 0;
  std::optional<Point2<I>> missing;
  for (I xx = proj.front()[0]; xx <= proj.back()[0] && !missing; xx += 1) {
    const auto iv = column_interval<2, I>(h2, std::array<I, 1>{xx});
    if (!iv) continue;
    for (I y = iv->first; y <= iv->second; y += 1) {
      const Pt<2, I> c{xx, y};
      while (k < proj.size() && proj[k] < c) ++k;
      if (k < proj.size() && proj[k] == c) continue;
      missing = Point2<I>{xx, y};
      break;
    }
  }
  if (!missing) return std::nullopt;
  const auto& m = *missing;
  auto v2 = [&](std::size_t i) { return q[idx[i]]; };
  auto v3 = [&](std::size_t i) { return lift[idx[i]]; };
  Pt<3, I> num;
  I den;
  if (idx.size() == 2) {
    // m on the segment v0 v1: t = (m - v0)_k / (v1 - v0)_k on a coordinate where they differ.
    const auto d = v2(1) - v2(0);
    const bool use_x = d.x != 0;
    den = use_x ? d.x : d.y;
    I t = use_x ? m.x - v2(0).x : m.y - v2(0).y;
    if (den < 0) {
      den = -den;
      t = -t;
    }
    for (int j = 0; j < 3; ++j) num[j] = v3(0)[j] * den + t * (v3(1)[j] - v3(0)[j]);
  } else {
    // A triangle (v0, vk, vk+1) of the fan containing m; m - v0 = s (vk - v0) + t (vk1 - v0).
    std::size_t t = 1;
    while (t + 2 < idx.size() &&
           !(orientation(v2(0), v2(t), m) >= 0 && orientation(v2(t), v2(t + 1), m) >= 0 &&
             orientation(v2(t + 1), v2(0), m) >= 0))
      ++t;
    const auto a = v2(t) - v2(0), b = v2(t + 1) - v2(0), w = m - v2(0);
    den = cross(a, b);
    const I s_num = cross(w, b), t_num = cross(a, w);
    for (int j = 0; j < 3; ++j)
      num[j] = v3(0)[j] * den + s_num * (v3(t)[j] - v3(0)[j]) + t_num * (v3(t + 1)[j] - v3(0)[j]);
  }
  return cell_of<3, I>(num, den);
}

} // namespace

template <int D, TowerInt I>
std::optional<std::array<I, D>> hull_convexity_witness(std::span<const std::array<I, D>> x,
                                                       std::uint64_t max_columns) {
  if (x.empty()) throw InvalidArgument("digital convexity: an empty set of points");
  std::vector<Pt<D, I>> s(x.begin(), x.end());
  sort_unique<D, I>(s);
  return hull_witness_sorted<D, I>(s, half_spaces<I>(std::span<const Pt<D, I>>(s)), max_columns);
}

template <int D, TowerInt I>
std::optional<GridCell<D, I>> full_convexity_witness(std::span<const std::array<I, D>> x) {
  if (x.empty()) throw InvalidArgument("digital convexity: an empty set of points");
  std::vector<Pt<D, I>> s(x.begin(), x.end());
  sort_unique<D, I>(s);
  if (auto g = axis_gap_witness<D, I>(s)) return g;
  if constexpr (D == 3) {
    if (auto p = projection_witness<I>(s)) return p;
  }
  // Now every lattice column of each sweep has a point: the sweeps are bounded by the input.
  const auto sets = dilations<D, I>(s);
  const auto hull_v = hull_vertices<I>(std::span<const Pt<D, I>>(s));
  for (unsigned mask : masks_by_dimension<D>()) {
    const auto h = dilated_half_spaces<D, I>(hull_v, mask);
    if (auto w = hull_witness_sorted<D, I>(sets[mask], h, UINT64_MAX)) {
      GridCell<D, I> c{*w, mask};
      for (int i = 0; i < D; ++i) {
        if (mask & (1u << i)) c.lower[i] -= 1;
      }
      return c;
    }
  }
  return std::nullopt;
}

template <int D, TowerInt I>
std::vector<std::array<I, D>> fully_convex_step(std::span<const std::array<I, D>> z,
                                                std::uint64_t max_points) {
  if (z.empty()) throw InvalidArgument("digital convexity: an empty set of points");
  std::vector<Pt<D, I>> s(z.begin(), z.end());
  sort_unique<D, I>(s);
  const auto sets = dilations<D, I>(s);
  // star[mask]: the lowest vertices of the cells of Star(Cvxh(Z)) open along mask, sorted.
  std::vector<std::vector<Pt<D, I>>> star(1u << D);
  std::uint64_t budget = max_points;
  const auto hull_v = hull_vertices<I>(std::span<const Pt<D, I>>(s));
  for (unsigned mask = 0; mask < (1u << D); ++mask) {
    const auto h = dilated_half_spaces<D, I>(hull_v, mask);
    auto& out = star[mask];
    for_each_column<D, I>(sets[mask], budget, max_points, [&](const std::array<I, D - 1>& q) {
      const auto iv = column_interval<D, I>(h, q);
      if (!iv) return;
      for (I t = iv->first; t <= iv->second; t += 1) {
        if (budget == 0) too_many(max_points, "lattice points");
        --budget;
        auto p = with_last<D, I>(q, t);
        for (int i = 0; i < D; ++i) {
          if (mask & (1u << i)) p[i] -= 1;
        }
        out.push_back(p);
      }
    });
    // Columns come in lexicographic order and each column in increasing order: sorted.
  }
  auto in = [](const std::vector<Pt<D, I>>& v, const Pt<D, I>& p) {
    return std::binary_search(v.begin(), v.end(), p);
  };
  std::vector<Pt<D, I>> result;
  for (unsigned mask = 0; mask < (1u << D); ++mask) {
    for (const auto& c : star[mask]) {
      bool minimal = true;
      for (int i = 0; i < D && minimal; ++i) {
        if (!(mask & (1u << i))) continue;
        const auto& faces = star[mask & ~(1u << i)];
        auto up = c;
        up[i] += 1;
        minimal = !in(faces, c) && !in(faces, up);
      }
      if (!minimal) continue;
      for (unsigned u = 0; u < (1u << D); ++u) {
        if ((u & mask) != u) continue;
        auto v = c;
        for (int i = 0; i < D; ++i) {
          if (u & (1u << i)) v[i] += 1;
        }
        result.push_back(v);
      }
    }
  }
  sort_unique<D, I>(result);
  return result;
}

template <int D, TowerInt I>
std::vector<std::array<I, D>> fully_convex_envelope(std::span<const std::array<I, D>> z,
                                                    std::uint64_t max_points,
                                                    std::size_t* iterations) {
  if (z.empty()) throw InvalidArgument("digital convexity: an empty set of points");
  std::vector<Pt<D, I>> cur(z.begin(), z.end());
  sort_unique<D, I>(cur);
  std::size_t n = 0;
  for (;;) {
    auto next = fully_convex_step<D, I>(std::span<const Pt<D, I>>(cur), max_points);
    if (next == cur) break;
    cur = std::move(next);
    ++n;
  }
  if (iterations != nullptr) *iterations = n;
  return cur;
}

template <int D, TowerInt I>
std::vector<std::array<I, D>> digital_segment(const std::array<I, D>& a,
                                              const std::array<I, D>& b) {
  const std::array<Pt<D, I>, 2> z{a, b};
  return fully_convex_envelope<D, I>(std::span<const Pt<D, I>>(z));
}

template <int D, TowerInt I>
std::vector<std::array<I, D>> digital_triangle(const std::array<I, D>& a, const std::array<I, D>& b,
                                               const std::array<I, D>& c) {
  const std::array<Pt<D, I>, 3> z{a, b, c};
  return fully_convex_envelope<D, I>(std::span<const Pt<D, I>>(z));
}

namespace {

template <int D, TowerInt I>
std::vector<Pt<D, I>> points_from(std::span<const BigInt> coords) {
  std::vector<Pt<D, I>> pts(coords.size() / D);
  for (std::size_t k = 0; k < pts.size(); ++k) {
    for (int i = 0; i < D; ++i) pts[k][i] = int_cast<I>(coords[k * D + i]);
  }
  return pts;
}

template <int D, TowerInt I>
ConvexityCheck report_cell(const GridCell<D, I>& c) {
  ConvexityCheck r;
  r.convex = false;
  r.witness_dimension = c.dimension();
  for (int i = 0; i < D; ++i) {
    const BigInt z = int_cast<BigInt>(c.lower[i]);
    r.witness_khalimsky.push_back((c.open & (1u << i)) ? 2 * z + 1 : 2 * z);
  }
  for (unsigned u = 0; u < (1u << D); ++u) {
    if ((u & c.open) != u) continue;
    std::vector<BigInt> v;
    for (int i = 0; i < D; ++i) v.push_back(int_cast<BigInt>(c.lower[i]) + ((u >> i) & 1u));
    r.witness_vertices.push_back(std::move(v));
  }
  return r;
}

template <int D>
Escalated<ConvexityCheck> check_dim(std::span<const BigInt> coords, ConvexityDefinition def,
                                    std::uint64_t max_columns) {
  return escalate([&]<class I>(std::type_identity<I>) {
    const auto pts = points_from<D, I>(coords);
    const std::span<const Pt<D, I>> sp(pts);
    if (def == ConvexityDefinition::hull) {
      const auto w = hull_convexity_witness<D, I>(sp, max_columns);
      return w ? report_cell<D, I>(GridCell<D, I>{*w, 0}) : ConvexityCheck{};
    }
    const auto c = full_convexity_witness<D, I>(sp);
    return c ? report_cell<D, I>(*c) : ConvexityCheck{};
  });
}

template <int D>
Escalated<EnvelopeResult> envelope_dim(std::span<const BigInt> coords, std::uint64_t max_points) {
  return escalate([&]<class I>(std::type_identity<I>) {
    const auto pts = points_from<D, I>(coords);
    EnvelopeResult r;
    const auto env =
        fully_convex_envelope<D, I>(std::span<const Pt<D, I>>(pts), max_points, &r.iterations);
    r.coords.reserve(env.size() * D);
    for (const auto& p : env) {
      for (int i = 0; i < D; ++i) r.coords.push_back(int_cast<BigInt>(p[i]));
    }
    return r;
  });
}

void check_input(int dim, std::span<const BigInt> coords) {
  if (dim != 2 && dim != 3)
    throw InvalidArgument("digital convexity: dimension " + std::to_string(dim) +
                          " (2 or 3 expected)");
  if (coords.empty() || coords.size() % static_cast<std::size_t>(dim) != 0)
    throw InvalidArgument("digital convexity: " + std::to_string(coords.size()) +
                          " coordinates do not make a non-empty set of points");
}

} // namespace

Escalated<ConvexityCheck> digital_convexity_exact(int dim, std::span<const BigInt> coords,
                                                  ConvexityDefinition definition,
                                                  std::uint64_t max_columns) {
  check_input(dim, coords);
  return dim == 2 ? check_dim<2>(coords, definition, max_columns)
                  : check_dim<3>(coords, definition, max_columns);
}

Escalated<EnvelopeResult> fully_convex_envelope_exact(int dim, std::span<const BigInt> coords,
                                                      std::uint64_t max_points) {
  check_input(dim, coords);
  return dim == 2 ? envelope_dim<2>(coords, max_points) : envelope_dim<3>(coords, max_points);
}

#define ZDG_INSTANTIATE(D, I)                                                                      \
  template std::optional<std::array<I, D>> hull_convexity_witness<D, I>(                           \
      std::span<const std::array<I, D>>, std::uint64_t);                                           \
  template std::optional<GridCell<D, I>> full_convexity_witness<D, I>(                             \
      std::span<const std::array<I, D>>);                                                          \
  template std::vector<std::array<I, D>> fully_convex_step<D, I>(                                  \
      std::span<const std::array<I, D>>, std::uint64_t);                                           \
  template std::vector<std::array<I, D>> fully_convex_envelope<D, I>(                              \
      std::span<const std::array<I, D>>, std::uint64_t, std::size_t*);                             \
  template std::vector<std::array<I, D>> digital_segment<D, I>(const std::array<I, D>&,            \
                                                               const std::array<I, D>&);           \
  template std::vector<std::array<I, D>> digital_triangle<D, I>(                                   \
      const std::array<I, D>&, const std::array<I, D>&, const std::array<I, D>&);
ZDG_INSTANTIATE(2, Int64)
ZDG_INSTANTIATE(2, Int128)
ZDG_INSTANTIATE(2, BigInt)
ZDG_INSTANTIATE(3, Int64)
ZDG_INSTANTIATE(3, Int128)
ZDG_INSTANTIATE(3, BigInt)
#undef ZDG_INSTANTIATE

} // namespace zdg
