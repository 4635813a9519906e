// Output-sensitive convex hull of the lattice points of a convex body K in R^2:
//
//   conv(K cap Z^2), its vertices counterclockwise from the lowest-then-leftmost one,
//
// without enumerating K cap Z^2. K is a closed disc with rational centre and radius, an
// axis-aligned closed ellipse ((x-cx)/a)^2 + ((y-cy)/b)^2 <= 1 with rational data, or a
// bounded intersection of rational half-planes a x + b y <= c (the integer hull of a
// polygon). K enters only through an exact oracle: line_range(q, v), the integers k with
// q + k v in K (an interval: K is convex), decided by integer inequalities after clearing
// denominators (a quadratic k^2-inequality solved with an integer square root and checked
// exactly, or one linear inequality per half-plane).
//
// Algorithm (the edge-by-edge walk of Harvey 1999, "Computing the convex hull of the lattice
// points in a disc"; Balza-Gomez, Moreau, Michelucci 1999 "Convex hull of grid points below a
// line or a convex curve"; Har-Peled 1998): from a vertex P reached along the primitive
// direction d, let w with det(d, w) = 1. The next edge direction is the lattice direction e
// closest to d (counterclockwise) with P + e in K. The integers a with P + w + a d in K give
// a unimodular bracket (outside w + (amax+1) d, inside w + amax d); a Stern-Brocot descent
// then alternates runs of mediants towards the outer side and towards the inner side, each
// run solved in one line_range call (so the descent costs O(log r) calls, its run lengths
// being partial quotients). Correctness of the runs: if P + d_in is in K and a mediant
// P + d_in + d_out is not, no direction between d_out and that mediant has a point in K
// (convexity of K - P with 0 and d_in in it); an empty level-1 line means every lattice
// point of K lies on the line of the last edge (P - d in K makes the slice of K at level 1
// contain floor(a/b) whenever a d + b w is in K - P). The edge is then followed to its end
// by one more line_range call. Time O(V log r) oracle calls for V vertices (V =
// Theta(r^{2/3}) for a disc of radius r: Balog-Barany 1991), plus finding the first vertex:
// lattice lines <u, x> = t are scanned from the lowest t until one meets K (rows or columns,
// along the shorter axis, for a disc or ellipse: one or two lines; for a polygon u is its
// lattice-width direction, so a thin polygon needs few lines; past 2^26 empty lines in a row the
// walk stops with InvalidArgument). The output is rotated to start at the lowest-then-leftmost
// vertex. Half-plane regions are first classified exactly (empty, unbounded, bounded) and bounded
// in O(m^3) rational arithmetic for m half-planes.
//
// Streaming (disc_hull_stream, ellipse_hull_stream): the vertices are handed to a sink as the
// walk finds them, in the output order, so that a huge hull is written without being held:
// a disc is always scanned by rows, so the first vertex found (the leftmost point of the
// lowest row) is the lowest-then-leftmost one and the walk order is the output order (memory
// O(1)); an ellipse scanned by columns is buffered and rotated (memory O(V)). A run that
// overflows its integer type has handed over a prefix of the (type-independent) sequence; the
// wider run skips that prefix, so every vertex reaches the sink exactly once.
//
// Vertex bounds (disc_hull_max_vertices, ellipse_hull_max_vertices): the hull is a convex
// lattice polygon inside the body, so its perimeter is at most the body's (2 pi r for a disc,
// pi sqrt(2 (a^2 + b^2)) for an ellipse) and convex_lattice_polygon_max_vertices
// (kernel/hulls/lattice_polygon.hpp) bounds its vertex count: about 6.54 r^{2/3} for a disc,
// against the observed 3.45 r^{2/3} (Balog-Barany 1991: Theta(r^{2/3})). The *_exact and
// *_stream entry points refuse (InvalidArgument, before any work) a body whose bound exceeds
// their max_vertices, kHullMaxVertices (10^8) by default: every front end (command line,
// `zdg serve`, Python) shares that default.
//
// Width: the quadratic oracles square D x - Cx (D the common denominator of the data), so
// Int64 needs about D r < 2^31 (a disc of integer radius 10^9 at an integer centre still
// runs on Int64: the walk's lines are nearly tangent, which keeps the products small); the
// *_exact entry points escalate Int64 -> Int128 -> BigInt on OverflowError.
#pragma once

#include <zdg/arith/escalate.hpp>
#include <zdg/arith/integer.hpp>
#include <zdg/arith/point.hpp>
#include <zdg/arith/rational.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace zdg {

/// The integers k of a line q + k v inside a body: [first, second] (nonempty when present).
template <TowerInt I>
using LineRange = std::optional<std::pair<I, I>>;

/// The body alpha (D x - Cx)^2 + beta (D y - Cy)^2 <= gamma (all integers, alpha, beta > 0),
/// with an integer box [xlo, xhi] x [ylo, yhi] containing its lattice points.
template <TowerInt I>
struct QuadraticBody {
  I D, Cx, Cy, alpha, beta, gamma;
  I xlo, xhi, ylo, yhi;
  // The walk finds its first vertex on the lattice lines <u, x> = t, t = tlo, tlo + 1, ...
  Point2<I> u{I(0), I(1)};
  I tlo{0}, thi{-1};
  bool contains(const Point2<I>& p) const;
  LineRange<I> line_range(const Point2<I>& q, const Point2<I>& v) const;
  /// For q in K: the largest k >= 0 with q + k v in K.
  I last_inside(const Point2<I>& q, const Point2<I>& v) const;
  /// For q not in K: the least k >= 1 with q + k v in K, if any.
  std::optional<I> first_inside(const Point2<I>& q, const Point2<I>& v) const;
};

/// Closed disc of centre (cx, cy) and radius r >= 0 (InvalidArgument for r < 0).
template <TowerInt I>
QuadraticBody<I> disc_body(const Rational<I>& cx, const Rational<I>& cy, const Rational<I>& r);

/// Closed axis-aligned ellipse ((x-cx)/a)^2 + ((y-cy)/b)^2 <= 1, a, b > 0 (InvalidArgument
/// otherwise).
template <TowerInt I>
QuadraticBody<I> ellipse_body(const Rational<I>& cx, const Rational<I>& cy, const Rational<I>& a,
                              const Rational<I>& b);

/// a x + b y <= c.
template <TowerInt I>
struct HalfPlane {
  Rational<I> a, b, c;
};

enum class RegionKind { bounded, unbounded, empty };
const char* to_string(RegionKind k);

/// A bounded intersection of half-planes, scaled to integer rows a x + b y <= c.
template <TowerInt I>
struct PolygonBody {
  std::vector<std::array<I, 3>> rows;
  I xlo, xhi, ylo, yhi;
  // Scan lines <u, x> = t along a flat direction u of the polygon (its lattice-width
  // direction, from the generalized Gauss reduction): few lines for a thin polygon.
  Point2<I> u{I(0), I(1)};
  I tlo{0}, thi{-1};
  bool contains(const Point2<I>& p) const;
  LineRange<I> line_range(const Point2<I>& q, const Point2<I>& v) const;
  I last_inside(const Point2<I>& q, const Point2<I>& v) const { return line_range(q, v)->second; }
  std::optional<I> first_inside(const Point2<I>& q, const Point2<I>& v) const {
    auto r = line_range(q, v);
    if (!r || r->second < 1) return std::nullopt;
    return r->first;
  }
};

/// Classifies the region of hs (empty, unbounded or bounded) and, when bounded, returns the
/// body. No half-plane at all is the whole plane (unbounded).
template <TowerInt I>
std::pair<RegionKind, PolygonBody<I>> polygon_body(std::span<const HalfPlane<I>> hs);

/// The hull walk on any body with line_range/contains and the box fields; computed on I.
template <TowerInt I, class Body>
std::vector<Point2<I>> convex_body_hull(const Body& body);

/// The same walk handing each vertex to emit as soon as it is found, in walk order
/// (counterclockwise, from the first point of the first scan line meeting the lattice: the
/// lowest-then-leftmost vertex when body.u = (0, 1)); returns the number of vertices.
template <TowerInt I, class Body>
std::size_t convex_body_hull_walk(const Body& body,
                                  const std::function<void(const Point2<I>&)>& emit);

/// One-off entry points (computed on I: may throw OverflowError).
template <TowerInt I>
std::vector<Point2<I>> disc_hull(const Rational<I>& cx, const Rational<I>& cy,
                                 const Rational<I>& r);
template <TowerInt I>
std::vector<Point2<I>> ellipse_hull(const Rational<I>& cx, const Rational<I>& cy,
                                    const Rational<I>& a, const Rational<I>& b);

template <TowerInt I>
struct HalfPlaneHull {
  RegionKind region = RegionKind::empty;
  std::vector<Point2<I>> vertices; // empty unless region == bounded
};
template <TowerInt I>
HalfPlaneHull<I> halfplane_hull(std::span<const HalfPlane<I>> hs);

/// The default vertex bound of the disc and ellipse entry points (see above).
inline constexpr std::uint64_t kHullMaxVertices = 100'000'000;

/// The region and the hull vertices, as BigInt (the result of the *_exact entry points).
struct BodyHull {
  RegionKind region = RegionKind::bounded;
  std::vector<Point2<BigInt>> vertices;
};
/// Exact by escalation (Int64 -> Int128 -> BigInt): data as BigInt rationals, result vertices
/// as BigInt, with the type that served. InvalidArgument before any work when the proven vertex
/// bound exceeds max_vertices.
Escalated<BodyHull> disc_hull_exact(const Rational<BigInt>& cx, const Rational<BigInt>& cy,
                                    const Rational<BigInt>& r,
                                    std::uint64_t max_vertices = kHullMaxVertices);
Escalated<BodyHull> ellipse_hull_exact(const Rational<BigInt>& cx, const Rational<BigInt>& cy,
                                       const Rational<BigInt>& a, const Rational<BigInt>& b,
                                       std::uint64_t max_vertices = kHullMaxVertices);
Escalated<BodyHull> halfplane_hull_exact(std::span<const HalfPlane<BigInt>> hs);

/// Receives the vertices of a hull one at a time, counterclockwise from the lowest-then-leftmost
/// one. vertex() may throw (an output error ends the walk) but never OverflowError, which the
/// escalation would take for the walk's own.
class HullVertexSink {
public:
  virtual ~HullVertexSink() = default;
  /// A vertex whose coordinates fit int64.
  virtual void vertex(std::int64_t x, std::int64_t y) = 0;
  /// A vertex with a coordinate beyond int64.
  virtual void vertex(const BigInt& x, const BigInt& y) = 0;
};

struct StreamedHull {
  std::size_t vertices = 0;
  IntKind served = IntKind::int64;
};

/// The vertices of disc_hull_exact / ellipse_hull_exact, handed to the sink as they are found
/// (same order, same validation, same vertex bound).
StreamedHull disc_hull_stream(const Rational<BigInt>& cx, const Rational<BigInt>& cy,
                              const Rational<BigInt>& r, HullVertexSink& sink,
                              std::uint64_t max_vertices = kHullMaxVertices);
StreamedHull ellipse_hull_stream(const Rational<BigInt>& cx, const Rational<BigInt>& cy,
                                 const Rational<BigInt>& a, const Rational<BigInt>& b,
                                 HullVertexSink& sink,
                                 std::uint64_t max_vertices = kHullMaxVertices);

/// Upper bounds on the number of vertices of the hull of the lattice points of a disc of
/// radius r, of an ellipse of semi-axes a and b (UINT64_MAX when beyond; see above).
std::uint64_t disc_hull_max_vertices(const Rational<BigInt>& r);
std::uint64_t ellipse_hull_max_vertices(const Rational<BigInt>& a, const Rational<BigInt>& b);

/// InvalidArgument (naming both numbers) when the bound exceeds max_vertices: the check of the
/// entry points above, for a front end that must refuse before it opens its outputs.
void check_disc_hull_vertices(const Rational<BigInt>& r, std::uint64_t max_vertices);
void check_ellipse_hull_vertices(const Rational<BigInt>& a, const Rational<BigInt>& b,
                                 std::uint64_t max_vertices);

/// floor(sqrt(n)) for n >= 0.
template <TowerInt I>
I floor_sqrt(const I& n);

} // namespace zdg
