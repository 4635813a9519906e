#include <zdg/arith/error.hpp>
#include <zdg/kernel/hulls/lattice_hull_3d.hpp>
#include <zdg/kernel/surfaces/digital_plane_recognition.hpp>

#include <algorithm>
#include <array>
#include <vector>

namespace zdg {

namespace {

template <TowerInt I>
I norm_inf(const Point3<I>& n) {
  return std::max({abs(n.x), abs(n.y), abs(n.z)});
}

template <TowerInt I>
I norm_1(const Point3<I>& n) {
  return abs(n.x) + abs(n.y) + abs(n.z);
}

template <TowerInt I>
Point3<I> primitive(const Point3<I>& n) {
  I g = gcd(gcd(n.x, n.y), n.z);
  return {n.x / g, n.y / g, n.z / g};
}

// The order in which certifying normals are preferred: ||.||_inf, then ||.||_1, then lexicographic.
template <TowerInt I>
bool preferred(const Point3<I>& a, const Point3<I>& b) {
  const I ia = norm_inf(a), ib = norm_inf(b);
  if (ia != ib) return ia < ib;
  const I sa = norm_1(a), sb = norm_1(b);
  if (sa != sb) return sa < sb;
  if (a.x != b.x) return a.x < b.x;
  if (a.y != b.y) return a.y < b.y;
  return a.z < b.z;
}

template <TowerInt I>
NaivePlaneRecognition<I> certify(const Point3<I>& n, std::span<const Point3<I>> pts) {
  NaivePlaneRecognition<I> r;
  r.is_plane = true;
  r.normal = n;
  r.omega = norm_inf(n);
  r.mu = dot(n, pts[0]);
  for (const auto& p : pts) r.mu = std::min(r.mu, dot(n, p));
  return r;
}

} // namespace

template <TowerInt I>
NaivePlaneRecognition<I> recognize_naive_plane(std::span<const Point3<I>> pts) {
  if (pts.empty()) throw InvalidArgument("plane recognition: no point");
  const auto hull = lattice_hull_3d<I>(pts);
  const auto& v = hull.vertices;
  if (hull.dimension == 0) return certify<I>({I(0), I(0), I(1)}, pts);
  if (hull.dimension == 1) {
    // The least primitive normal orthogonal to the line: among u x e_k.
    const Point3<I> u = v[1] - v[0];
    std::vector<Point3<I>> cands;
    for (const auto& e :
         {Point3<I>{I(1), I(0), I(0)}, Point3<I>{I(0), I(1), I(0)}, Point3<I>{I(0), I(0), I(1)}}) {
      Point3<I> c = cross(u, e);
      if (c != Point3<I>{}) {
        c = primitive(c);
        cands.push_back(c);
        cands.push_back(-c);
      }
    }
    auto best = *std::min_element(cands.begin(), cands.end(), preferred<I>);
    return certify(best, pts);
  }
  if (hull.dimension == 2) {
    // The two sides of the flat polygon: normals n and -n.
    auto best = std::min(hull.normals[0], hull.normals[1], preferred<I>);
    return certify(best, pts);
  }
  std::vector<Point3<I>> chords;
  chords.reserve(v.size() * v.size());
  for (const auto& a : v) {
    for (const auto& b : v) chords.push_back(a - b);
  }
  const auto dh = lattice_hull_3d<I>(std::span<const Point3<I>>(chords));
  bool found = false;
  Point3<I> best{};
  for (std::size_t f = 0; f < dh.facets.size(); ++f) {
    const auto& n = dh.normals[f];
    const I h = dot(n, dh.vertices[dh.facets[f][0]]);
    // e_k strictly outside the facet's half-space: n_k > h.
    if (n.x > h || n.y > h || n.z > h) {
      if (!found || preferred(n, best)) best = n;
      found = true;
    }
  }
  if (!found) return {};
  auto r = certify(best, pts);
  for (const auto& p : pts) {
    if (dot(r.normal, p) - r.mu >= r.omega) {
      throw Error("plane recognition: internal error, the certificate does not hold");
    }
  }
  return r;
}

template <TowerInt I>
Escalated<NaivePlaneRecognition<BigInt>>
recognize_naive_plane_exact(std::span<const Point3<I>> pts) {
  return escalate([&]<class J>(std::type_identity<J>) {
    std::vector<Point3<J>> q;
    q.reserve(pts.size());
    for (const auto& p : pts) q.push_back({int_cast<J>(p.x), int_cast<J>(p.y), int_cast<J>(p.z)});
    auto r = recognize_naive_plane<J>(std::span<const Point3<J>>(q));
    NaivePlaneRecognition<BigInt> out;
    out.is_plane = r.is_plane;
    out.normal = {to_bigint(r.normal.x), to_bigint(r.normal.y), to_bigint(r.normal.z)};
    out.mu = to_bigint(r.mu);
    out.omega = to_bigint(r.omega);
    return out;
  });
}

#define ZDG_INSTANTIATE(I)                                                                         \
  template NaivePlaneRecognition<I> recognize_naive_plane<I>(std::span<const Point3<I>>);          \
  template Escalated<NaivePlaneRecognition<BigInt>> recognize_naive_plane_exact<I>(                \
      std::span<const Point3<I>>);
ZDG_INSTANTIATE(Int64)
ZDG_INSTANTIATE(Int128)
ZDG_INSTANTIATE(BigInt)
#undef ZDG_INSTANTIATE

} // namespace zdg
