#include <zdg/arith/error.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>
#include <zdg/kernel/transforms/distance_transform.hpp>
#include <zdg/kernel/transforms/local_thickness.hpp>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <queue>
#include <string>
#include <type_traits>
#include <vector>

namespace zdg {

namespace {

__extension__ typedef unsigned __int128 U128;
__extension__ typedef __int128 I128;

// The largest dimension: the selection looks at 3^d - 1 neighbours.
constexpr int kMaxDim = 6;
// Slices of axis 0 painted by one task.
constexpr std::int64_t kGroup = 8;

void check_options(const Image<std::uint8_t>& shape, const TransformOptions& opt) {
  if (!(opt.metric == Metric::l2())) {
    throw InvalidArgument("local thickness: the metric is l2 (Euclidean balls), not " +
                          opt.metric.name());
  }
  const Domain& dom = shape.domain();
  if (dom.dim() > kMaxDim) {
    throw InvalidArgument("local thickness: a " + std::to_string(dom.dim()) +
                          "-D image (dimensions 1 to " + std::to_string(kMaxDim) + ")");
  }
  for (int k = 0; k < dom.dim(); ++k) {
    if (opt.periodic(k)) {
      throw InvalidArgument("local thickness: axis " + std::to_string(k) +
                            " is periodic (inscribed balls are taken in the box, no torus)");
    }
  }
  if (dom.extent(dom.dim() - 1) >= INT32_MAX) {
    throw InvalidArgument("local thickness: a line (last axis) of " +
                          std::to_string(dom.extent(dom.dim() - 1)) + " points (at most 2^31 - 2)");
  }
}

// floor(sqrt(n)), exact for every uint64.
std::uint64_t isqrt(std::uint64_t n) {
  auto r = static_cast<std::uint64_t>(std::sqrt(static_cast<double>(n)));
  while (r > 0 && static_cast<U128>(r) * r > n) --r;
  while (static_cast<U128>(r + 1) * (r + 1) <= n) ++r;
  return r;
}

// A vector e tested for containment: B(c) in B(c + e) iff DT(c + e) > M(DT(c), e), with
// M(w, e) = max { |p - e|^2 : |p|^2 < w } (exact, from `table` when there is one) or its upper
// bound (sqrt(w - 1) + |e|)^2 (tested as in the header).
struct Neighbour {
  std::vector<int> step;
  std::int64_t offset = 0;
  std::uint64_t k = 0; // |e|^2
  const std::vector<std::uint64_t>* table = nullptr;
};

// The tables M(w, e) for w = 0 .. maxw, one per sorted pattern of |e_i| (M depends only on
// it: the lattice shells are invariant under the signed permutations of the axes). For p in a
// shell |p|^2 = s, max |p - e|^2 = s + |e|^2 + 2 max p.e, and max p.e pairs the sorted |p_i|
// with the sorted |e_i| (rearrangement inequality), so enumerating the points
// p_1 >= ... >= p_d >= 0 with |p|^2 < maxw suffices.
class ContainmentTables {
public:
  ContainmentTables(int d, std::uint64_t maxw, const std::vector<std::vector<int>>& patterns)
      : d_(d) {
    for (const auto& pat : patterns) {
      std::uint64_t e2 = 0;
      for (int x : pat) e2 += static_cast<std::uint64_t>(x * x);
      std::vector<std::int64_t> best(maxw + 1, -1);
      std::vector<std::uint64_t> p(static_cast<std::size_t>(d), 0);
      enumerate(0, 0, maxw, pat, p, best);
      std::vector<std::uint64_t> t(maxw + 1, 0);
      std::int64_t run = -1;
      for (std::uint64_t w = 1; w <= maxw; ++w) {
        run = std::max(run, best[w - 1]);
        t[w] = static_cast<std::uint64_t>(run) + e2;
      }
      tables_.push_back({pat, std::move(t)});
    }
  }
  const std::vector<std::uint64_t>* find(std::vector<int> pat) const {
    for (auto& x : pat) x = std::abs(x);
    std::sort(pat.rbegin(), pat.rend());
    for (const auto& [q, t] : tables_) {
      if (q == pat) return &t;
    }
    return nullptr;
  }

private:
  void enumerate(int k, std::uint64_t s, std::uint64_t maxw, const std::vector<int>& pat,
                 std::vector<std::uint64_t>& p, std::vector<std::int64_t>& best) {
    if (k == d_) {
      std::uint64_t dot = 0;
      for (int j = 0; j < d_; ++j)
        dot += p[static_cast<std::size_t>(j)] *
               static_cast<std::uint64_t>(pat[static_cast<std::size_t>(j)]);
      auto& b = best[s];
      b = std::max(b, static_cast<std::int64_t>(s + 2 * dot));
      return;
    }
    const std::uint64_t top = k == 0 ? ~std::uint64_t{0} : p[static_cast<std::size_t>(k - 1)];
    for (std::uint64_t x = 0; x <= top && s + x * x < maxw; ++x) {
      p[static_cast<std::size_t>(k)] = x;
      enumerate(k + 1, s + x * x, maxw, pat, p, best);
    }
  }
  int d_;
  std::vector<std::pair<std::vector<int>, std::vector<std::uint64_t>>> tables_;
};

// Exact tables are built when the fundamental points are few: d <= 3 and DT values < 2^16.
constexpr std::uint64_t kTableMaxValue = std::uint64_t{1} << 16;

template <class T>
struct Centre {
  std::int64_t index = 0;
  T value = 0;
  // 3-D: the neighbour c + e of largest DT(c + e) > DT(c), whose ball's lines this one need not
  // paint (guide_value 0 when there is none).
  T guide_value = 0;
  std::array<std::int8_t, 3> guide{};
};

// The painting order: larger values first, then smaller linear indices.
template <class T>
bool first(const Centre<T>& a, const Centre<T>& b) {
  return a.value > b.value || (a.value == b.value && a.index < b.index);
}

// The layout seen by the painting: at least 2 axes (a 1-D image is one slice of one line).
struct Layout {
  std::vector<std::int64_t> ext; // D >= 2 extents
  std::int64_t slices = 1, slice_size = 1, nx = 1, rows = 1;
  std::vector<std::int64_t> row_stride; // per axis 1 .. D-2: rows per unit step
};

Layout layout_of(const Domain& dom) {
  Layout L;
  L.ext = dom.extents();
  if (L.ext.size() == 1) L.ext.insert(L.ext.begin(), 1);
  const auto D = L.ext.size();
  L.slices = L.ext[0];
  L.nx = L.ext[D - 1];
  L.rows = 1;
  L.row_stride.assign(D, 0);
  for (std::size_t k = D - 1; k-- > 1;) {
    L.row_stride[k] = L.rows;
    L.rows *= L.ext[k];
  }
  L.slice_size = L.rows * L.nx;
  return L;
}

// The kept centres of each slice of axis 0, sorted in painting order (see the header: a centre
// is dropped when the ball of a point c + e, e in {-1, 0, 1}^d, with a value as large contains
// its ball; vectors of {-2 .. 2}^3 dropped only 3% more on foams, for 2.3 times the time).
template <class T>
std::vector<std::vector<Centre<T>>> kept_centres(const Domain& dom, const Layout& L,
                                                 const std::vector<T>& v, unsigned threads) {
  const int d = dom.dim();
  T maxw = 0;
  for (auto x : v) maxw = std::max(maxw, x);
  const bool exact = d <= 3 && static_cast<std::uint64_t>(maxw) < kTableMaxValue;
  const int reach = 1;
  std::vector<std::vector<int>> patterns;
  std::vector<Neighbour> nbrs;
  {
    std::vector<int> e(static_cast<std::size_t>(d), -reach);
    for (;;) {
      Neighbour n;
      n.step = e;
      int far = 0;
      for (int k = 0; k < d; ++k) {
        const int x = e[static_cast<std::size_t>(k)];
        n.offset += x * dom.stride(k);
        n.k += static_cast<std::uint64_t>(x * x);
        far = std::max(far, std::abs(x));
      }
      if (n.k > 0) {
        std::vector<int> pat = e;
        for (auto& x : pat) x = std::abs(x);
        std::sort(pat.rbegin(), pat.rend());
        if (std::find(patterns.begin(), patterns.end(), pat) == patterns.end())
          patterns.push_back(pat);
        nbrs.push_back(std::move(n));
      }
      int k = d - 1;
      while (k >= 0 && e[static_cast<std::size_t>(k)] == reach)
        e[static_cast<std::size_t>(k--)] = -reach;
      if (k < 0) break;
      ++e[static_cast<std::size_t>(k)];
    }
  }
  std::unique_ptr<ContainmentTables> tables;
  if (exact) {
    tables = std::make_unique<ContainmentTables>(d, static_cast<std::uint64_t>(maxw), patterns);
    for (auto& n : nbrs) n.table = tables->find(n.step);
  }
  std::vector<std::vector<Centre<T>>> out(static_cast<std::size_t>(L.slices));
  parallel_for(L.slices, threads, [&](std::int64_t s) {
    auto& mine = out[static_cast<std::size_t>(s)];
    const std::int64_t begin = s * L.slice_size, end = begin + L.slice_size;
    std::vector<std::int64_t> p = dom.point(begin);
    for (int k = 0; k < d; ++k) p[static_cast<std::size_t>(k)] -= dom.lower(k);
    std::size_t last = 0;
    for (std::int64_t i = begin; i < end; ++i) {
      const T w = v[static_cast<std::size_t>(i)];
      if (w != 0) {
        bool interior = true;
        for (int k = 0; k < d && interior; ++k) {
          interior = p[static_cast<std::size_t>(k)] >= reach &&
                     p[static_cast<std::size_t>(k)] < dom.extent(k) - reach;
        }
        const std::uint64_t m = static_cast<std::uint64_t>(w) - 1;
        // Whether e contains the ball: the neighbour that dropped the previous point is tried
        // first (neighbouring points tend to be dropped towards the same side).
        auto contains = [&](const Neighbour& n) {
          const auto w2 = static_cast<std::uint64_t>(v[static_cast<std::size_t>(i + n.offset)]);
          if (w2 < static_cast<std::uint64_t>(w)) return false;
          if (n.table != nullptr) return w2 > (*n.table)[static_cast<std::size_t>(w)];
          if (w2 <= m + n.k) return false;
          const U128 a = w2 - m - n.k;
          return a * a > static_cast<U128>(4) * m * n.k;
        };
        auto inside = [&](const Neighbour& n) {
          for (int k = 0; k < d; ++k) {
            const std::int64_t q =
                p[static_cast<std::size_t>(k)] + n.step[static_cast<std::size_t>(k)];
            if (q < 0 || q >= dom.extent(k)) return false;
          }
          return true;
        };
        bool dropped = false;
        if (interior) {
          dropped = contains(nbrs[last]);
          for (std::size_t j = 0; j < nbrs.size() && !dropped; ++j) {
            if (contains(nbrs[j])) {
              dropped = true;
              last = j;
            }
          }
        } else {
          for (std::size_t j = 0; j < nbrs.size() && !dropped; ++j) {
            dropped = inside(nbrs[j]) && contains(nbrs[j]);
          }
        }
        if (!dropped) {
          Centre<T> ce{i, w, 0, {}};
          if (d == 3) {
            for (const auto& n : nbrs) {
              if (!interior && !inside(n)) continue;
              const T w2 = v[static_cast<std::size_t>(i + n.offset)];
              if (w2 > w && w2 > ce.guide_value) {
                ce.guide_value = w2;
                for (std::size_t k = 0; k < 3; ++k)
                  ce.guide[k] = static_cast<std::int8_t>(n.step[k]);
              }
            }
          }
          mine.push_back(ce);
        }
      }
      for (int k = d - 1; k >= 0; --k) { // next point in C order
        if (++p[static_cast<std::size_t>(k)] < dom.extent(k)) break;
        p[static_cast<std::size_t>(k)] = 0;
      }
    }
    std::sort(mine.begin(), mine.end(), first<T>);
  });
  return out;
}

// Union-find of the unpainted points of the lines of a group of slices: next[x] = x while x is
// unpainted, the line's end (nx) is a sentinel.
struct Painter {
  std::int32_t* next = nullptr;
  std::int64_t nx = 0;

  std::int32_t find(std::int32_t* line, std::int32_t x) const {
    while (line[x] != x) {
      line[x] = line[line[x]];
      x = line[x];
    }
    return x;
  }
};

template <class T>
void paint(const Layout& L, const std::vector<std::vector<Centre<T>>>& centres, T maxw,
           unsigned threads, T* out) {
  if (maxw == 0) return;
  const auto R = static_cast<std::int64_t>(isqrt(static_cast<std::uint64_t>(maxw) - 1));
  const std::int64_t groups = (L.slices + kGroup - 1) / kGroup;
  const std::size_t D = L.ext.size();
  const std::int64_t line = L.nx + 1;
  parallel_for(groups, threads, [&](std::int64_t g) {
    const std::int64_t g0 = g * kGroup, g1 = std::min(L.slices, g0 + kGroup);
    // The centres whose ball meets a slice of the group, in decreasing value.
    // (Each slice's list is sorted already: a merge of the slices' lists.)
    std::vector<Centre<T>> mine;
    using Head = std::pair<std::int64_t, std::size_t>; // (slice, position in its list)
    auto later = [&](const Head& a, const Head& b) {
      return first(centres[static_cast<std::size_t>(b.first)][b.second],
                   centres[static_cast<std::size_t>(a.first)][a.second]);
    };
    std::priority_queue<Head, std::vector<Head>, decltype(later)> heads(later);
    for (std::int64_t s = std::max<std::int64_t>(0, g0 - R); s < std::min(L.slices, g1 + R); ++s) {
      if (!centres[static_cast<std::size_t>(s)].empty()) heads.push({s, 0});
    }
    while (!heads.empty()) {
      auto [s, k] = heads.top();
      heads.pop();
      const auto& list = centres[static_cast<std::size_t>(s)];
      // The balls of slice s that reach the group are a prefix of its list (value > gap^2).
      const std::int64_t gap = s < g0 ? g0 - s : (s >= g1 ? s - (g1 - 1) : 0);
      if (static_cast<std::uint64_t>(gap * gap) >= static_cast<std::uint64_t>(list[k].value))
        continue;
      mine.push_back(list[k]);
      if (k + 1 < list.size()) heads.push({s, k + 1});
    }
    std::vector<std::array<std::int64_t, kMaxDim>> coords(mine.size());
    for (std::size_t j = 0; j < mine.size(); ++j) {
      std::int64_t i = mine[j].index;
      for (std::size_t k = D; k-- > 0;) {
        coords[j][k] = i % L.ext[k];
        i /= L.ext[k];
      }
    }
    // One slice at a time: the union-find of its lines (one slice stays in cache).
    std::vector<std::int32_t> next(static_cast<std::size_t>(L.rows * line));
    Painter pt{next.data(), L.nx};
    const std::array<std::int64_t, kMaxDim>* c = nullptr;
    I128 gb = -1;                     // the guide's budget in the current slice
    std::array<std::int64_t, 3> ge{}; // the guide's offset
    // Paints line `row` of slice z over [c_x - h, c_x + h] (clipped) with w.
    auto paint_line = [&](std::int64_t z, std::int64_t row, std::int64_t h, T w) {
      const std::int64_t x0 = std::max<std::int64_t>(0, (*c)[D - 1] - h);
      const std::int64_t x1 = std::min(L.nx - 1, (*c)[D - 1] + h);
      std::int32_t* ln = pt.next + row * line;
      T* o = out + z * L.slice_size + row * L.nx;
      auto x = pt.find(ln, static_cast<std::int32_t>(x0));
      while (x <= x1) {
        o[x] = w;
        ln[x] = x + 1;
        x = pt.find(ln, x + 1);
      }
    };
    // The lines of the ball from axis k (1 <= k <= D-2) on, with budget b = w - 1 - (squared
    // distances along the axes before k); on axis D-2 the half-width along the last axis
    // shrinks as the offset grows (no square root per line).
    auto rows_of = [&](auto&& self, std::size_t k, std::uint64_t b, std::int64_t row,
                       std::int64_t z, T w) -> void {
      if (k == D - 1) {
        paint_line(z, row, static_cast<std::int64_t>(isqrt(b)), w);
        return;
      }
      const auto h = static_cast<std::int64_t>(isqrt(b));
      if (k == D - 2) {
        // A line whose interval lies in the guide's ball is left to the others: each of its
        // points y has R2(y) >= DT(guide) > w, and the kept ball of value R2(y) containing y
        // does not leave y (its own guide would have a value > R2(y) and contain y).
        auto guided = [&](std::int64_t t, std::int64_t hh) {
          if (gb < 0) return false;
          const std::int64_t dy = t - ge[1];
          const I128 rest = gb - static_cast<I128>(dy) * dy;
          const I128 need = hh + (ge[2] < 0 ? -ge[2] : ge[2]);
          return rest >= need * need;
        };
        auto hx = static_cast<std::uint64_t>(h);
        for (std::int64_t t = 0; t <= h; ++t) {
          const std::uint64_t rest = b - static_cast<std::uint64_t>(t * t);
          while (hx * hx > rest) --hx;
          const auto hh = static_cast<std::int64_t>(hx);
          if ((*c)[k] + t < L.ext[k] && !guided(t, hh))
            paint_line(z, row + ((*c)[k] + t) * L.row_stride[k], hh, w);
          if (t > 0 && (*c)[k] - t >= 0 && !guided(-t, hh))
            paint_line(z, row + ((*c)[k] - t) * L.row_stride[k], hh, w);
        }
        return;
      }
      const std::int64_t t0 = std::max<std::int64_t>(0, (*c)[k] - h);
      const std::int64_t t1 = std::min(L.ext[k] - 1, (*c)[k] + h);
      for (std::int64_t t = t0; t <= t1; ++t) {
        const auto dt = static_cast<std::uint64_t>(t > (*c)[k] ? t - (*c)[k] : (*c)[k] - t);
        self(self, k + 1, b - dt * dt, row + t * L.row_stride[k], z, w);
      }
    };
    for (std::int64_t z = g0; z < g1; ++z) {
      for (std::size_t j = 0; j < next.size(); ++j) {
        next[j] = static_cast<std::int32_t>(static_cast<std::int64_t>(j) % line);
      }
      for (std::size_t j = 0; j < mine.size(); ++j) {
        c = &coords[j];
        const auto m = static_cast<std::uint64_t>(mine[j].value) - 1;
        const auto dz = static_cast<std::uint64_t>(z > (*c)[0] ? z - (*c)[0] : (*c)[0] - z);
        if (dz * dz > m) continue;
        // The guide's budget in this slice (3-D only; < 0: its ball misses the slice).
        gb = -1;
        if (D == 3 && mine[j].guide_value != 0) {
          for (std::size_t k = 0; k < 3; ++k) ge[k] = mine[j].guide[k];
          const std::int64_t gz = z - (*c)[0] - ge[0];
          gb = static_cast<I128>(mine[j].guide_value) - 1 - static_cast<I128>(gz) * gz;
        }
        rows_of(rows_of, 1, m - dz * dz, 0, z, mine[j].value);
      }
    }
  });
}

template <class T>
void thickness_in_place(const Domain& dom, std::vector<T>& v, unsigned threads) {
  const Layout L = layout_of(dom);
  const auto centres = kept_centres(dom, L, v, threads);
  T maxw = 0;
  for (const auto& s : centres) {
    for (const auto& c : s) maxw = std::max(maxw, c.value);
  }
  paint(L, centres, maxw, threads, v.data());
}

// R2 on the narrowest unsigned type that holds the DT bound, handed to `emit`.
template <class Emit>
void squared_radius(const Image<std::uint8_t>& shape, const TransformOptions& opt, Emit&& emit) {
  check_options(shape, opt);
  TransformOptions o = opt;
  o.torus.clear();
  const BigInt bound = distance_transform_max_value(shape.domain(), o);
  if (bound <= BigInt(std::numeric_limits<std::uint32_t>::max())) {
    auto dt = distance_transform<std::uint32_t>(shape, o);
    thickness_in_place(shape.domain(), dt.values(), opt.threads);
    emit(dt.values());
  } else if (bound <= BigInt(std::numeric_limits<std::int64_t>::max())) {
    auto dt = distance_transform<std::uint64_t>(shape, o);
    thickness_in_place(shape.domain(), dt.values(), opt.threads);
    emit(dt.values());
  } else {
    throw OverflowError("local thickness: squared distances up to " + bound.str() +
                        " on this domain do not fit int64");
  }
}

} // namespace

Image<std::int64_t> local_thickness_squared_radius(const Image<std::uint8_t>& shape,
                                                   const TransformOptions& opt) {
  Image<std::int64_t> out(shape.domain());
  squared_radius(shape, opt, [&](const auto& v) {
    for (std::size_t i = 0; i < v.size(); ++i) out.values()[i] = static_cast<std::int64_t>(v[i]);
  });
  return out;
}

Image<float> local_thickness(const Image<std::uint8_t>& shape, const TransformOptions& opt) {
  Image<float> out(shape.domain());
  squared_radius(shape, opt, [&](const auto& v) {
    auto& o = out.values();
    parallel_chunks(static_cast<std::int64_t>(v.size()), opt.threads,
                    [&](std::int64_t b, std::int64_t e) {
                      for (auto i = b; i < e; ++i) {
                        const auto s = static_cast<double>(v[static_cast<std::size_t>(i)]);
                        o[static_cast<std::size_t>(i)] = static_cast<float>(2.0 * std::sqrt(s));
                      }
                    });
  });
  return out;
}

} // namespace zdg
