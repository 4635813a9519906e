#include <zdg/kernel/linalg/intrinsic_delaunay.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/linalg/cotan_laplacian.hpp>

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <string>

namespace zdg {

namespace {

// Heron's formula in Kahan's order (a >= b >= c): exact to rounding even for needles.
double heron(double a, double b, double c) {
  if (a < b) std::swap(a, b);
  if (a < c) std::swap(a, c);
  if (b < c) std::swap(b, c);
  const double p = (a + (b + c)) * (c - (a - b)) * (c + (a - b)) * (a + (b - c));
  return p > 0 ? 0.25 * std::sqrt(p) : 0.0;
}

// The angle opposite o in the triangle of sides o, p, q.
double angle(double o, double p, double q) {
  return std::acos(std::clamp((p * p + q * q - o * o) / (2 * p * q), -1.0, 1.0));
}

constexpr double kDelaunayTolerance = 1e-12;

} // namespace

double IntrinsicTriangulation::area(std::size_t f) const {
  return heron(lengths[f][0], lengths[f][1], lengths[f][2]);
}

double IntrinsicTriangulation::cotangent(std::size_t f, int k) const {
  const auto& l = lengths[f];
  const double o = l[std::size_t(k)], p = l[std::size_t((k + 1) % 3)],
               q = l[std::size_t((k + 2) % 3)];
  return (p * p + q * q - o * o) / (4 * area(f));
}

IntrinsicTriangulation
intrinsic_triangulation(std::span<const Point3<double>> vertices,
                        std::span<const std::array<std::int64_t, 3>> triangles) {
  const auto n = static_cast<std::int64_t>(vertices.size());
  const auto where = [](std::size_t f) {
    return "intrinsic Delaunay: triangle " + std::to_string(f);
  };
  IntrinsicTriangulation t;
  t.triangles.assign(triangles.begin(), triangles.end());
  t.lengths.resize(triangles.size());
  t.twin.assign(3 * triangles.size(), -1);
  // Directed edge (a, b) -> its slot; the reverse edge is the twin.
  std::map<std::pair<std::int64_t, std::int64_t>, std::int64_t> directed;
  std::map<std::pair<std::int64_t, std::int64_t>, int> undirected;
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    const auto& tri = triangles[f];
    check_triangle_indices(tri, n, "intrinsic Delaunay", f);
    for (int k = 0; k < 3; ++k) {
      const auto d = vertices[std::size_t(tri[std::size_t((k + 2) % 3)])] -
                     vertices[std::size_t(tri[std::size_t((k + 1) % 3)])];
      t.lengths[f][std::size_t(k)] = std::sqrt(dot(d, d));
    }
    if (!(t.area(f) > 0)) throw InvalidArgument(where(f) + " is degenerate");
    for (int k = 0; k < 3; ++k) {
      const auto a = tri[std::size_t((k + 1) % 3)], b = tri[std::size_t((k + 2) % 3)];
      if (++undirected[{std::min(a, b), std::max(a, b)}] > 2)
        throw InvalidArgument("intrinsic Delaunay: the edge (" + std::to_string(a) + ", " +
                              std::to_string(b) + ") of triangle " + std::to_string(f) +
                              " has more than two triangles (not a manifold)");
      if (!directed.emplace(std::pair{a, b}, std::int64_t(3 * f + std::size_t(k))).second)
        throw InvalidArgument("intrinsic Delaunay: triangle " + std::to_string(f) +
                              " runs the edge (" + std::to_string(a) + ", " + std::to_string(b) +
                              ") in the same direction as another (not consistently oriented)");
    }
  }
  for (const auto& [e, slot] : directed) {
    const auto r = directed.find({e.second, e.first});
    if (r != directed.end()) t.twin[std::size_t(slot)] = r->second;
  }
  return t;
}

void make_intrinsic_delaunay(IntrinsicTriangulation& t) {
  const std::size_t slots = t.twin.size();
  // Slots to check (an edge may be queued more than once: each pop checks it again).
  std::deque<std::int64_t> queue;
  for (std::size_t s = 0; s < slots; ++s)
    if (t.twin[s] > std::int64_t(s)) queue.push_back(std::int64_t(s)); // once per interior edge
  const std::int64_t max_flips = 1000 * std::int64_t(t.triangles.size()) + 1000;
  while (!queue.empty()) {
    const auto s0 = std::size_t(queue.front());
    queue.pop_front();
    if (t.twin[s0] < 0) continue;
    const auto s1 = std::size_t(t.twin[s0]);
    const std::size_t f = s0 / 3, g = s1 / 3;
    const int k = int(s0 % 3), m = int(s1 % 3);
    if (f == g) continue; // an edge glued to its own triangle: no quadrilateral to flip in
    if (t.cotangent(f, k) + t.cotangent(g, m) >= -kDelaunayTolerance) continue;
    if (++t.flips > max_flips)
      throw Error("intrinsic Delaunay: more than " + std::to_string(max_flips) +
                  " flips (a floating-point cycle)");
    // f = (c, a, b) from corner k, g = (d, b, a) from corner m; the quadrilateral a, d, b, c.
    const auto kf = [&](int i) { return std::size_t((k + i) % 3); };
    const auto kg = [&](int i) { return std::size_t((m + i) % 3); };
    const auto c = t.triangles[f][kf(0)], a = t.triangles[f][kf(1)], b = t.triangles[f][kf(2)];
    const auto d = t.triangles[g][kg(0)];
    const double ab = t.lengths[f][kf(0)], bc = t.lengths[f][kf(1)], ca = t.lengths[f][kf(2)];
    const double ad = t.lengths[g][kg(1)], db = t.lengths[g][kg(2)];
    const double at_a = angle(bc, ab, ca) + angle(db, ab, ad);
    const double cd = std::sqrt(std::max(0.0, ca * ca + ad * ad - 2 * ca * ad * std::cos(at_a)));
    // The outer slots (old numbering) and their twins.
    const std::size_t f1 = 3 * f + kf(1), f2 = 3 * f + kf(2), g1 = 3 * g + kg(1),
                      g2 = 3 * g + kg(2);
    // New: f = (c, a, d): opposite c: ad (was g1), opposite a: dc (new), opposite d: ca (was f2);
    //      g = (d, b, c): opposite d: bc (was f1), opposite b: cd (new), opposite c: db (was g2).
    const std::size_t F0 = 3 * f, F1 = 3 * f + 1, F2 = 3 * f + 2, G0 = 3 * g, G1 = 3 * g + 1,
                      G2 = 3 * g + 2;
    const auto renamed = [&](std::int64_t old) -> std::int64_t {
      if (old < 0) return old;
      const auto o = std::size_t(old);
      return o == g1   ? std::int64_t(F0)
             : o == f2 ? std::int64_t(F2)
             : o == f1 ? std::int64_t(G0)
             : o == g2 ? std::int64_t(G2)
                       : old;
    };
    const std::int64_t tw_ad = renamed(t.twin[g1]), tw_ca = renamed(t.twin[f2]),
                       tw_bc = renamed(t.twin[f1]), tw_db = renamed(t.twin[g2]);
    t.triangles[f] = {c, a, d};
    t.lengths[f] = {ad, cd, ca};
    t.triangles[g] = {d, b, c};
    t.lengths[g] = {bc, cd, db};
    const auto link = [&](std::size_t slot, std::int64_t other) {
      t.twin[slot] = other;
      if (other >= 0) t.twin[std::size_t(other)] = std::int64_t(slot);
    };
    link(F0, tw_ad);
    link(F2, tw_ca);
    link(G0, tw_bc);
    link(G2, tw_db);
    link(F1, std::int64_t(G1));
    // The four outer edges may have stopped being Delaunay.
    for (const std::size_t s : {F0, F2, G0, G2})
      if (t.twin[s] >= 0) queue.push_back(std::int64_t(s));
  }
}

CotanLaplacian intrinsic_cotan_laplacian(const IntrinsicTriangulation& t, std::int64_t n) {
  CotanLaplacian L;
  L.mass.assign(std::size_t(n), 0.0);
  std::vector<SparseTriplet> trip;
  trip.reserve(12 * t.triangles.size());
  for (std::size_t f = 0; f < t.triangles.size(); ++f) {
    const auto& tri = t.triangles[f];
    const double A = t.area(f);
    for (int k = 0; k < 3; ++k) {
      const auto i = tri[std::size_t((k + 1) % 3)], j = tri[std::size_t((k + 2) % 3)];
      L.mass[std::size_t(tri[std::size_t(k)])] += A / 3;
      if (i == j) continue; // a loop edge: w (u_i - u_i) = 0
      const double w = 0.5 * t.cotangent(f, k);
      trip.push_back({i, j, w});
      trip.push_back({j, i, w});
      trip.push_back({i, i, -w});
      trip.push_back({j, j, -w});
    }
  }
  L.stiffness = SparseMatrix::from_triplets(n, n, std::move(trip));
  return L;
}

CotanLaplacian
intrinsic_delaunay_laplacian(std::span<const Point3<double>> vertices,
                             std::span<const std::array<std::int64_t, 3>> triangles) {
  IntrinsicTriangulation t = intrinsic_triangulation(vertices, triangles);
  make_intrinsic_delaunay(t);
  return intrinsic_cotan_laplacian(t, static_cast<std::int64_t>(vertices.size()));
}

} // namespace zdg
