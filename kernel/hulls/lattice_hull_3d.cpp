#include <zdg/kernel/hulls/lattice_hull_3d.hpp>

#include <zdg/kernel/hulls/lattice_hull_2d.hpp>

#include <algorithm>
#include <array>
#include <numeric>
#include <optional>
#include <unordered_map>

namespace zdg {

namespace {

template <TowerInt I>
bool is_zero(const Point3<I>& a) {
  return a.x == 0 && a.y == 0 && a.z == 0;
}
template <TowerInt I>
bool lex_less(const Point3<I>& a, const Point3<I>& b) {
  if (a.x != b.x) return a.x < b.x;
  if (a.y != b.y) return a.y < b.y;
  return a.z < b.z;
}
template <TowerInt I>
Point3<I> primitive(const Point3<I>& n) {
  I g = gcd(gcd(n.x, n.y), n.z);
  return {n.x / g, n.y / g, n.z / g};
}

// Keeps the points extreme in each of their three axis-parallel lines (deduplicated).
template <TowerInt I>
std::vector<Point3<I>> line_extremes(std::span<const Point3<I>> pts) {
  std::vector<Point3<I>> p(pts.begin(), pts.end());
  std::sort(p.begin(), p.end(), lex_less<I>);
  p.erase(std::unique(p.begin(), p.end()), p.end());
  for (int axis = 0; axis < 3; ++axis) {
    // Order with `axis` last: lines along `axis` are consecutive runs.
    auto key = [axis](const Point3<I>& a) -> std::array<const I*, 3> {
      if (axis == 0) return {&a.y, &a.z, &a.x};
      if (axis == 1) return {&a.x, &a.z, &a.y};
      return {&a.x, &a.y, &a.z};
    };
    std::sort(p.begin(), p.end(), [&](const Point3<I>& a, const Point3<I>& b) {
      auto ka = key(a), kb = key(b);
      for (int i = 0; i < 3; ++i) {
        if (*ka[i] != *kb[i]) return *ka[i] < *kb[i];
      }
      return false;
    });
    std::vector<Point3<I>> keep;
    keep.reserve(p.size());
    for (std::size_t i = 0; i < p.size();) {
      std::size_t j = i + 1;
      auto ki = key(p[i]);
      while (j < p.size()) {
        auto kj = key(p[j]);
        if (*kj[0] != *ki[0] || *kj[1] != *ki[1]) break;
        ++j;
      }
      keep.push_back(p[i]);
      if (j - 1 > i) keep.push_back(p[j - 1]);
      i = j;
    }
    p.swap(keep);
  }
  std::sort(p.begin(), p.end(), lex_less<I>);
  return p;
}

template <TowerInt I>
struct Face {
  std::array<int, 3> v;
  std::array<int, 3> nb; // neighbour across edge (v[i], v[i+1])
  Point3<I> n;
  I off;
  std::vector<int> outside;
  bool alive = true;
};

template <TowerInt I>
class Builder {
public:
  explicit Builder(std::vector<Point3<I>> p) : p_(std::move(p)) {}

  LatticeHull3d<I> run() {
    LatticeHull3d<I> out;
    const int n = static_cast<int>(p_.size());
    if (n == 0) return out;
    // Affinely independent seeds.
    int i1 = -1, i2 = -1, i3 = -1;
    for (int i = 1; i < n && i1 < 0; ++i) i1 = i; // points are distinct
    if (i1 < 0) return finish_point(out);
    Point3<I> nrm;
    for (int i = 1; i < n && i2 < 0; ++i) {
      auto c = cross((p_[i1] - p_[0]), (p_[i] - p_[0]));
      if (!is_zero(c)) {
        i2 = i;
        nrm = c;
      }
    }
    if (i2 < 0) return finish_segment(out);
    for (int i = 1; i < n && i3 < 0; ++i) {
      if (dot(nrm, (p_[i] - p_[0])) != 0) i3 = i;
    }
    if (i3 < 0) return finish_planar(out, nrm);
    build({0, i1, i2, i3});
    return finish_solid(out);
  }

private:
  std::vector<Point3<I>> p_;
  std::vector<Face<I>> f_;
  std::vector<int> mark_; // visibility epoch per face
  int epoch_ = 0;

  int add_face(int a, int b, int c) {
    Face<I> f;
    f.v = {a, b, c};
    f.nb = {-1, -1, -1};
    f.n = cross((p_[b] - p_[a]), (p_[c] - p_[a]));
    f.off = dot(f.n, p_[a]);
    f_.push_back(std::move(f));
    mark_.push_back(0);
    return static_cast<int>(f_.size()) - 1;
  }
  bool above(const Face<I>& f, int q) const { return dot(f.n, p_[q]) > f.off; }

  void build(std::array<int, 4> s) {
    // Orient the tetrahedron so that the fourth point is below the first face.
    auto [a, b, c, d] = s;
    if (dot(cross((p_[b] - p_[a]), (p_[c] - p_[a])), (p_[d] - p_[a])) > 0) std::swap(b, c);
    int f0 = add_face(a, b, c), f1 = add_face(a, d, b), f2 = add_face(b, d, c),
        f3 = add_face(c, d, a);
    link_all({f0, f1, f2, f3});
    std::vector<int> stack;
    for (int f : {f0, f1, f2, f3}) stack.push_back(f);
    const int n = static_cast<int>(p_.size());
    for (int q = 0; q < n; ++q) {
      if (q == a || q == b || q == c || q == d) continue;
      for (int f : {f0, f1, f2, f3}) {
        if (above(f_[f], q)) {
          f_[f].outside.push_back(q);
          break;
        }
      }
    }
    std::vector<int> visible, horizon_face, horizon_edge, fresh;
    while (!stack.empty()) {
      int fi = stack.back();
      stack.pop_back();
      if (!f_[fi].alive || f_[fi].outside.empty()) continue;
      // The furthest point of the conflict list (largest n . q).
      int apex = f_[fi].outside[0];
      I best = dot(f_[fi].n, p_[apex]);
      for (int q : f_[fi].outside) {
        I sq = dot(f_[fi].n, p_[q]);
        if (sq > best) {
          best = sq;
          apex = q;
        }
      }
      // Visible region by depth-first search; horizon edges in order.
      ++epoch_;
      visible.clear();
      horizon_face.clear();
      horizon_edge.clear();
      collect(fi, apex, visible, horizon_face, horizon_edge);
      // New faces on the horizon.
      fresh.clear();
      std::unordered_map<int, int> starts; // horizon edge start vertex -> new face
      for (std::size_t h = 0; h < horizon_face.size(); ++h) {
        const Face<I>& g = f_[horizon_face[h]];
        int e = horizon_edge[h];
        // The edge as seen from the visible side: (g.v[e+1], g.v[e]).
        int u = g.v[(e + 1) % 3], w = g.v[e];
        int nf = add_face(u, w, apex);
        f_[nf].nb[0] = horizon_face[h];
        f_[horizon_face[h]].nb[e] = nf;
        fresh.push_back(nf);
        starts[u] = nf;
      }
      for (int nf : fresh) {
        int w = f_[nf].v[1];
        int next = starts.at(w); // the new face starting at w shares edge (w, apex)
        f_[nf].nb[1] = next;
        f_[next].nb[2] = nf;
      }
      // Reassign the conflict points of the dead faces.
      for (int vf : visible) {
        for (int q : f_[vf].outside) {
          if (q == apex) continue;
          for (int nf : fresh) {
            if (above(f_[nf], q)) {
              f_[nf].outside.push_back(q);
              break;
            }
          }
        }
        f_[vf].outside.clear();
        f_[vf].outside.shrink_to_fit();
        f_[vf].alive = false;
      }
      for (int nf : fresh) {
        if (!f_[nf].outside.empty()) stack.push_back(nf);
      }
    }
  }

  // Faces visible from apex (strictly above), by depth-first search from a visible face, and
  // the horizon: (non-visible face, index of its edge shared with a visible face).
  void collect(int start, int apex, std::vector<int>& visible, std::vector<int>& hface,
               std::vector<int>& hedge) {
    const int vis = 2 * epoch_, hid = 2 * epoch_ + 1;
    std::vector<int> st{start};
    mark_[start] = vis;
    visible.push_back(start);
    while (!st.empty()) {
      int f = st.back();
      st.pop_back();
      for (int e = 0; e < 3; ++e) {
        int g = f_[f].nb[e];
        if (mark_[g] != vis && mark_[g] != hid) {
          if (above(f_[g], apex)) {
            mark_[g] = vis;
            visible.push_back(g);
            st.push_back(g);
          } else {
            mark_[g] = hid;
          }
        }
        if (mark_[g] == hid) {
          int back = 0;
          while (f_[g].nb[back] != f) ++back;
          hface.push_back(g);
          hedge.push_back(back);
        }
      }
    }
  }

  void link_all(std::array<int, 4> fs) {
    for (int a : fs) {
      for (int i = 0; i < 3; ++i) {
        int u = f_[a].v[i], w = f_[a].v[(i + 1) % 3];
        for (int b : fs) {
          if (b == a) continue;
          for (int j = 0; j < 3; ++j) {
            if (f_[b].v[j] == w && f_[b].v[(j + 1) % 3] == u) f_[a].nb[i] = b;
          }
        }
      }
    }
  }

  LatticeHull3d<I> finish_point(LatticeHull3d<I>& out) {
    out.dimension = 0;
    out.vertices = {p_[0]};
    return out;
  }
  LatticeHull3d<I> finish_segment(LatticeHull3d<I>& out) {
    out.dimension = 1;
    out.vertices = {p_.front(), p_.back()}; // sorted: the extremes of a line
    return out;
  }
  LatticeHull3d<I> finish_planar(LatticeHull3d<I>& out, const Point3<I>& nrm) {
    out.dimension = 2;
    // Project along the largest normal component (injective on the plane).
    int drop = 2;
    if (abs(nrm.x) >= abs(nrm.y) && abs(nrm.x) >= abs(nrm.z)) {
      drop = 0;
    } else if (abs(nrm.y) >= abs(nrm.z)) {
      drop = 1;
    }
    std::vector<Point2<I>> q;
    q.reserve(p_.size());
    for (const auto& p : p_) {
      if (drop == 0) q.push_back({p.y, p.z});
      if (drop == 1) q.push_back({p.z, p.x});
      if (drop == 2) q.push_back({p.x, p.y});
    }
    auto idx = lattice_hull_2d_indices<I>(std::span<const Point2<I>>(q));
    // (y,z), (z,x), (x,y) are right-handed projections: ccw there is ccw seen from the side
    // where the dropped coordinate grows, i.e. with normal sign(component) * e_drop.
    const I& comp = drop == 0 ? nrm.x : (drop == 1 ? nrm.y : nrm.z);
    Point3<I> up = comp > 0 ? nrm : Point3<I>{I(-nrm.x), I(-nrm.y), I(-nrm.z)};
    std::vector<Point3<I>> poly;
    for (auto i : idx) poly.push_back(p_[i]);
    std::vector<Point3<I>> verts = poly;
    std::sort(verts.begin(), verts.end(), lex_less<I>);
    auto index_of = [&](const Point3<I>& v) {
      return static_cast<std::size_t>(std::lower_bound(verts.begin(), verts.end(), v, lex_less<I>) -
                                      verts.begin());
    };
    std::vector<std::size_t> f;
    for (const auto& v : poly) f.push_back(index_of(v));
    out.vertices = verts;
    out.facets.push_back(f);
    out.normals.push_back(primitive(up));
    std::reverse(f.begin(), f.end());
    out.facets.push_back(f);
    out.normals.push_back(primitive(Point3<I>{I(-up.x), I(-up.y), I(-up.z)}));
    return out;
  }

  LatticeHull3d<I> finish_solid(LatticeHull3d<I>& out) {
    out.dimension = 3;
    const int nf = static_cast<int>(f_.size());
    // Union-find of coplanar neighbours. Two facets of a 3D convex polytope sharing an edge are
    // coplanar iff the third vertex of one lies on the plane of the other (then their outward
    // normals agree): n . p == off, 3b + 5 bits like every other predicate here (comparing the
    // normals by a cross product would need 4b + 7 bits).
    std::vector<int> parent(nf);
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](int x) {
      while (parent[x] != x) x = parent[x] = parent[parent[x]];
      return x;
    };
    for (int a = 0; a < nf; ++a) {
      if (!f_[a].alive) continue;
      for (int b : f_[a].nb) {
        const auto& fb = f_[b];
        if (b > a && std::all_of(fb.v.begin(), fb.v.end(),
                                 [&](int v) { return dot(f_[a].n, p_[v]) == f_[a].off; })) {
          parent[find(a)] = find(b);
        }
      }
    }
    // Boundary cycles of each group.
    std::unordered_map<int, std::vector<std::pair<int, int>>> edges; // root -> boundary edges
    for (int a = 0; a < nf; ++a) {
      if (!f_[a].alive) continue;
      int r = find(a);
      auto& list = edges[r];
      for (int i = 0; i < 3; ++i) {
        if (find(f_[a].nb[i]) != r) list.push_back({f_[a].v[i], f_[a].v[(i + 1) % 3]});
      }
    }
    std::vector<std::vector<int>> polys;
    std::vector<Point3<I>> norms;
    std::vector<int> roots;
    for (auto& [r, list] : edges) roots.push_back(r);
    std::sort(roots.begin(), roots.end());
    for (int r : roots) {
      auto& list = edges[r];
      std::unordered_map<int, int> next;
      for (auto [u, w] : list) next[u] = w;
      std::vector<int> cyc;
      int start = list.front().first, u = start;
      do {
        cyc.push_back(u);
        u = next.at(u);
      } while (u != start);
      // Drop the points inside an edge of the polygon.
      std::vector<int> poly;
      const std::size_t k = cyc.size();
      for (std::size_t i = 0; i < k; ++i) {
        const auto& a = p_[cyc[(i + k - 1) % k]];
        const auto& b = p_[cyc[i]];
        const auto& c = p_[cyc[(i + 1) % k]];
        if (!is_zero(cross((b - a), (c - b)))) poly.push_back(cyc[i]);
      }
      polys.push_back(poly);
      norms.push_back(primitive(f_[r].n));
    }
    // Renumber the vertices in lexicographic order.
    std::vector<int> used;
    for (const auto& poly : polys) used.insert(used.end(), poly.begin(), poly.end());
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end()); // p_ is sorted: so is this
    for (int i : used) out.vertices.push_back(p_[i]);
    const Point3<I>& o = out.vertices.front();
    I vol = 0;
    for (std::size_t fi = 0; fi < polys.size(); ++fi) {
      std::vector<std::size_t> f;
      for (int i : polys[fi]) {
        f.push_back(
            static_cast<std::size_t>(std::lower_bound(used.begin(), used.end(), i) - used.begin()));
      }
      const auto& poly = polys[fi];
      for (std::size_t j = 1; j + 1 < poly.size(); ++j) {
        vol += dot((p_[poly[0]] - o), cross((p_[poly[j]] - o), (p_[poly[j + 1]] - o)));
      }
      out.facets.push_back(std::move(f));
      out.normals.push_back(norms[fi]);
    }
    out.volume6 = vol;
    return out;
  }
};

} // namespace

template <TowerInt I>
LatticeHull3d<I> lattice_hull_3d(std::span<const Point3<I>> pts) {
  return Builder<I>(line_extremes(pts)).run();
}

namespace {
template <TowerInt To, TowerInt From>
LatticeHull3d<To> convert_hull(const LatticeHull3d<From>& h) {
  LatticeHull3d<To> o;
  o.dimension = h.dimension;
  for (const auto& v : h.vertices)
    o.vertices.push_back({int_cast<To>(v.x), int_cast<To>(v.y), int_cast<To>(v.z)});
  o.facets = h.facets;
  for (const auto& v : h.normals)
    o.normals.push_back({int_cast<To>(v.x), int_cast<To>(v.y), int_cast<To>(v.z)});
  o.volume6 = int_cast<To>(h.volume6);
  return o;
}
} // namespace

template <TowerInt I>
Escalated<LatticeHull3d<BigInt>> lattice_hull_3d_exact(std::span<const Point3<I>> pts) {
  return escalate([&]<class J>(std::type_identity<J>) {
    if constexpr (std::same_as<I, J>) {
      return convert_hull<BigInt>(lattice_hull_3d<J>(pts));
    } else {
      // OverflowError when a point does not fit J: the next type is tried.
      std::vector<Point3<J>> q;
      q.reserve(pts.size());
      for (const auto& p : pts) q.push_back({int_cast<J>(p.x), int_cast<J>(p.y), int_cast<J>(p.z)});
      return convert_hull<BigInt>(lattice_hull_3d<J>(std::span<const Point3<J>>(q)));
    }
  });
}

template <TowerInt I>
I lattice_points_in_hull_3d(const LatticeHull3d<I>& h) {
  if (h.dimension < 0) return I(0);
  if (h.dimension == 0) return I(1);
  if (h.dimension == 1) {
    auto d = (h.vertices[1] - h.vertices[0]);
    return gcd(gcd(d.x, d.y), d.z) + 1;
  }
  I lo_x = h.vertices[0].x, hi_x = lo_x, lo_y = h.vertices[0].y, hi_y = lo_y;
  for (const auto& v : h.vertices) {
    lo_x = std::min(lo_x, v.x);
    hi_x = std::max(hi_x, v.x);
    lo_y = std::min(lo_y, v.y);
    hi_y = std::max(hi_y, v.y);
  }
  I count = 0;
  if (h.dimension == 2) {
    // The plane n . p = c; count the points of the plane inside the polygon, column by column
    // along a coordinate axis not parallel to the plane... scanning every coordinate pair.
    const Point3<I>& n = h.normals[0];
    const auto& f = h.facets[0];
    I c = dot(n, h.vertices[f[0]]);
    I lo_z = h.vertices[0].z, hi_z = lo_z;
    for (const auto& v : h.vertices) {
      lo_z = std::min(lo_z, v.z);
      hi_z = std::max(hi_z, v.z);
    }
    // Inside the polygon (ccw seen along n): (b - a) x (p - a) . n >= 0 for every edge.
    auto inside = [&](const Point3<I>& p) {
      for (std::size_t i = 0; i < f.size(); ++i) {
        const auto& a = h.vertices[f[i]];
        const auto& b = h.vertices[f[(i + 1) % f.size()]];
        if (dot(cross((b - a), (p - a)), n) < 0) return false;
      }
      return true;
    };
    for (I x = lo_x; x <= hi_x; ++x) {
      for (I y = lo_y; y <= hi_y; ++y) {
        if (n.z != 0) {
          I r = c - n.x * x - n.y * y;
          if (mod(r, n.z) != 0) continue;
          if (inside(Point3<I>{x, y, I(r / n.z)})) count += 1;
        } else {
          for (I z = lo_z; z <= hi_z; ++z) {
            if (dot(n, Point3<I>{x, y, z}) == c && inside(Point3<I>{x, y, z})) count += 1;
          }
        }
      }
    }
    return count;
  }
  std::vector<I> offs;
  for (std::size_t i = 0; i < h.facets.size(); ++i)
    offs.push_back(dot(h.normals[i], h.vertices[h.facets[i][0]]));
  for (I x = lo_x; x <= hi_x; ++x) {
    for (I y = lo_y; y <= hi_y; ++y) {
      std::optional<I> zlo, zhi;
      bool ok = true;
      for (std::size_t i = 0; i < h.facets.size() && ok; ++i) {
        const auto& n = h.normals[i];
        I r = offs[i] - n.x * x - n.y * y; // n.z z <= r
        if (n.z > 0) {
          I t = floor_div(r, n.z);
          if (!zhi || t < *zhi) zhi = t;
        } else if (n.z < 0) {
          I t = ceil_div(r, n.z);
          if (!zlo || t > *zlo) zlo = t;
        } else if (r < 0) {
          ok = false;
        }
      }
      if (ok && zlo && zhi && *zlo <= *zhi) count += *zhi - *zlo + 1;
    }
  }
  return count;
}

#define ZDG_INSTANTIATE(I)                                                                         \
  template LatticeHull3d<I> lattice_hull_3d<I>(std::span<const Point3<I>>);                        \
  template Escalated<LatticeHull3d<BigInt>> lattice_hull_3d_exact<I>(std::span<const Point3<I>>);  \
  template I lattice_points_in_hull_3d<I>(const LatticeHull3d<I>&);
ZDG_INSTANTIATE(Int64)
ZDG_INSTANTIATE(Int128)
ZDG_INSTANTIATE(BigInt)
#undef ZDG_INSTANTIATE

} // namespace zdg
