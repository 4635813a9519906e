// Measures of a convex lattice polygon given by its vertices (counterclockwise, as
// lattice_hull_2d and the convex-body hulls return them).
//
//   area2     = 2 area = sum_i (x_i y_{i+1} - x_{i+1} y_i)                 (shoelace)
//   boundary  = sum_i gcd(|x_{i+1} - x_i|, |y_{i+1} - y_i|)   lattice points on the boundary
//   interior  = (area2 - boundary + 2) / 2                                  (Pick 1899)
//   lattice width = min over u in Z^2 \ {0} of (max_P <u, p> - min_P <u, p>), with a
//   direction u attaining it.
// Degenerate inputs: one vertex (a point) has boundary 1; two vertices (a segment) have
// area2 0, boundary gcd + 1, interior 0, lattice width 0.
//
// Incremental measures (LatticePolygonMeter): the same three counts from vertices handed over
// one at a time (a streamed hull), O(1) memory, int64 vertices on native 128-bit sums (BigInt
// only past them).
//
// Vertex bound (convex_lattice_polygon_max_vertices): a convex lattice polygon with V >= 2
// vertices has V pairwise distinct nonzero integer edge vectors (a convex polygon turns
// strictly at each vertex: no direction twice), so its perimeter is at least the sum of the V
// smallest norms of nonzero lattice vectors. At most pi (t + sqrt(2)/2)^2 - 1 of them have norm
// <= t (their unit squares are disjoint inside the disc of radius t + sqrt(2)/2), so the k-th
// smallest norm is >= max(1, sqrt((k+1)/pi) - sqrt(2)/2), and summing (integral comparison)
//     perimeter >= L(V) = max(V, 2/(3 sqrt(pi)) ((V+1)^{3/2} - 1) - V sqrt(2)/2).
// The bound is the largest V with L(V) <= perimeter (at least 1: a single point); it grows as
// (3 sqrt(pi) perimeter / 2)^{2/3} = 1.92 perimeter^{2/3} (6.53 r^{2/3} for a disc of radius r,
// less than twice the truth). Jarnik (1926) gives the sharp constant 3 (2 pi)^{-1/3} = 1.63,
// but only asymptotically.
//
// Complexity: O(V log C) for the counts; the lattice width runs the generalized Gauss
// reduction of Kaib and Schnorr (J. Algorithms 21, 1996: "The generalized Gauss reduction
// algorithm") on the width norm w(u) = max <u, p> - min <u, p>, O(V log^2 C) for coordinates
// of size C. Width: products of two coordinates (the shoelace terms): Int64 is safe below
// 2^30; lattice_polygon_measures_exact() escalates to Int128 and BigInt on overflow.
#pragma once

#include <zdg/arith/escalate.hpp>
#include <zdg/arith/integer.hpp>
#include <zdg/arith/point.hpp>

#include <cstdint>
#include <span>

namespace zdg {

template <TowerInt I>
struct LatticePolygonMeasures {
  I area2{0};    // twice the area
  I boundary{0}; // lattice points on the boundary (vertices included)
  I interior{0}; // lattice points in the interior (Pick)
};

/// Twice the signed area (positive for counterclockwise vertices).
template <TowerInt I>
I polygon_area2(std::span<const Point2<I>> v);

/// area2, boundary and interior lattice point counts of a convex lattice polygon with
/// counterclockwise vertices (any number: 0 gives all zeros). Computed on I.
template <TowerInt I>
LatticePolygonMeasures<I> lattice_polygon_measures(std::span<const Point2<I>> v);

/// The same, exact by escalation (Int64 -> Int128 -> BigInt); results as BigInt, with the
/// type that served.
Escalated<LatticePolygonMeasures<BigInt>>
lattice_polygon_measures_exact(std::span<const Point2<BigInt>> v);

/// The measures of a convex lattice polygon whose vertices (counterclockwise) are added one at
/// a time; finish() closes the polygon. Same conventions as lattice_polygon_measures.
class LatticePolygonMeter {
public:
  void add(std::int64_t x, std::int64_t y);
  void add(const BigInt& x, const BigInt& y);
  std::uint64_t count() const { return n_; }
  LatticePolygonMeasures<BigInt> finish() const;

private:
  std::uint64_t n_ = 0;
  bool big_ = false;                             // some vertex is beyond int64: BigInt from then on
  std::int64_t x0_ = 0, y0_ = 0, x_ = 0, y_ = 0; // first and last vertex (int64 mode)
  BigInt bx0_, by0_, bx_, by_;                   // the same in BigInt mode
  int128_t area_ = 0;                            // running sums, flushed into the BigInts before
  int128_t boundary_ = 0;                        // they could overflow
  BigInt big_area_, big_boundary_;
  BigInt first_edge_gcd_; // a two-vertex polygon (a segment) needs it

  void edge_to(std::int64_t x, std::int64_t y);
  void big_edge(const BigInt& ax, const BigInt& ay, const BigInt& bx, const BigInt& by,
                BigInt& area, BigInt& boundary) const;
  void to_big();
};

/// An upper bound on the number of vertices of a convex lattice polygon of the given perimeter
/// (see above); UINT64_MAX past 2^62.
std::uint64_t convex_lattice_polygon_max_vertices(double perimeter);

template <TowerInt I>
struct LatticeWidth {
  I width{0};
  Point2<I> direction{I(0), I(1)}; // a primitive u attaining the width
};

/// Lattice width of the convex hull of v (>= 1 vertex). Computed on I.
template <TowerInt I>
LatticeWidth<I> lattice_width(std::span<const Point2<I>> v);

} // namespace zdg
