// Digital convexity of a finite lattice set X in Z^d (d = 2, 3): full convexity, H-convexity,
// the fully convex envelope.
//
// Cells. C^d is the cubical complex of the lattice: a cell is c = z + (0,1)^I, the product of the
// open unit intervals (z_i, z_i + 1) for the axes i in I and the points {z_i} for the others; z is
// its lowest vertex, |I| its dimension, its closure is z + [0,1]^I and its vertices z + U_I with
// U_I = {0,1}^I. Khalimsky coordinates: 2 z_i on a closed axis, 2 z_i + 1 on an open one.
//
// Definitions (Lachaud, "An alternative definition for digital convexity", JMIV 64, 2022):
//   Star(Y) = { c in C^d : closure(c) meets Y } for Y in R^d (for a lattice set: the cells with
//   a vertex in Y);
//   X is H-convex (the classical digital convexity, "hull" here) when Cvxh(X) cap Z^d = X;
//   X is digitally k-convex when Star_k(Cvxh(X)) = Star_k(X) (k-cells), and fully convex when it
//   is k-convex for every 0 <= k <= d. As X is in Cvxh(X), full convexity reads: every cell
//   whose closure meets Cvxh(X) has a vertex in X. 0-convexity is H-convexity, so a fully
//   convex set is H-convex.
// Test (the morphological characterisation of the paper, proved here as the code uses it): the
//   cell z + (0,1)^I meets Cvxh(X) in its closure iff z + e_I is in Cvxh(X) + [0,1]^I =
//   Cvxh(X + U_I) (e_I = sum of e_i, i in I), and it has a vertex in X iff z + e_I is in
//   X + U_I. So X is fully convex iff X + U_I is H-convex for every I in {1..d}, and a lattice
//   point w of Cvxh(X + U_I) outside X + U_I is the witness cell (w - e_I) + (0,1)^I.
// Envelope (Lachaud, same line of work; DGtal's DigitalConvexity::envelope): FC(Z) =
//   Extr(Skel(Star(Cvxh(Z)))): the vertices of the cells of Star(Cvxh(Z)) none of whose proper
//   faces is in it (the cells that Cvxh(Z) meets in their relative interior only);
//   FC*(Z) = FC(FC(...FC(Z))) until a fixed point. Z is in FC(Z); FC*(Z) is fully convex.
//   A digital segment [a, b] = FC*({a, b}) and triangle FC*({a, b, c}) are fully convex by
//   construction.
//
// Algorithm. The vertices V of Cvxh(X) once (lattice_hull_2d, lattice_hull_3d: any dimension,
//   degenerate ones included); Cvxh(X + U_I) = Cvxh(V + U_I) as integer half-spaces a . p <= b;
//   X + U_I by merging sorted lists; the lattice columns of its projection along the last axis
//   (3D: the lattice points of the 2D hull of the projected points); in each column the points
//   of the set must be an interval [lo, hi] with lo - 1 and hi + 1 outside the hull (the
//   half-space that excluded the previous column's point tried first; in a column without
//   points the exact integer interval of the hull must be empty). Before that, full convexity
//   checks what bounds the sweep: the projection of X on each axis is an interval (a gap g gives
//   the witness cell of the point of Cvxh(X) on x_i = g), and in 3D every lattice point of the
//   hull of the projection on (x, y) has a point of X above it (else the witness is the cell
//   above it containing a point of Cvxh(X)). Then the columns are O(n) and the cost is
//   O(2^d n + n log n + hull) for n points. The H-convexity test alone sweeps the columns of its
//   projection and stops past `max_columns` (InvalidArgument): {(0, 0), (10^12, 1)} is H-convex
//   with 10^12 columns. The envelope enumerates the lattice points of each Cvxh(Z + U_I)
//   (O(points + columns) each) and stops past `max_points` (InvalidArgument).
// Width: half-spaces a . p <= b with a from cross products of coordinate differences:
//   about 3 b + 6 bits for b-bit coordinates in 3D (2 b + 3 in 2D); f<D, I> throws OverflowError
//   past I, the _exact functions escalate Int64 -> Int128 -> BigInt (arith/escalate.hpp).
#pragma once

#include <zdg/arith/escalate.hpp>
#include <zdg/arith/integer.hpp>

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace zdg {

/// The cell lower + (0,1)^open of C^d (open: a bit mask of axes, bit 0 = x).
template <int D, TowerInt I>
struct GridCell {
  std::array<I, D> lower{};
  unsigned open = 0;
  int dimension() const { return std::popcount(open); }
  friend bool operator==(const GridCell&, const GridCell&) = default;
};

/// Default limits of the sweeps that the input does not bound (see the header comment).
inline constexpr std::uint64_t kConvexityMaxColumns = 100'000'000;
inline constexpr std::uint64_t kEnvelopeMaxPoints = 100'000'000;

/// A lattice point of Cvxh(X) not in X, or none when X is H-convex (X non-empty; duplicates
/// allowed). Throws OverflowError past I, InvalidArgument past max_columns columns.
template <int D, TowerInt I>
std::optional<std::array<I, D>>
hull_convexity_witness(std::span<const std::array<I, D>> x,
                       std::uint64_t max_columns = kConvexityMaxColumns);

/// A cell whose closure meets Cvxh(X) and has no vertex in X (the lowest dimension first), or
/// none when X is fully convex (X non-empty; duplicates allowed). Throws OverflowError past I.
template <int D, TowerInt I>
std::optional<GridCell<D, I>> full_convexity_witness(std::span<const std::array<I, D>> x);

/// FC(Z), sorted and without duplicates (Z non-empty). InvalidArgument past max_points.
template <int D, TowerInt I>
std::vector<std::array<I, D>> fully_convex_step(std::span<const std::array<I, D>> z,
                                                std::uint64_t max_points = kEnvelopeMaxPoints);

/// FC*(Z), sorted and without duplicates; `iterations` (optional) receives the number of FC
/// steps that changed the set.
template <int D, TowerInt I>
std::vector<std::array<I, D>> fully_convex_envelope(std::span<const std::array<I, D>> z,
                                                    std::uint64_t max_points = kEnvelopeMaxPoints,
                                                    std::size_t* iterations = nullptr);

/// The fully convex digital segment FC*({a, b}) and triangle FC*({a, b, c}).
template <int D, TowerInt I>
std::vector<std::array<I, D>> digital_segment(const std::array<I, D>& a, const std::array<I, D>& b);
template <int D, TowerInt I>
std::vector<std::array<I, D>> digital_triangle(const std::array<I, D>& a, const std::array<I, D>& b,
                                               const std::array<I, D>& c);

// --- points of any size (row-major coordinates, dim 2 or 3), exact by escalation -------------

enum class ConvexityDefinition { full, hull };

struct ConvexityCheck {
  bool convex = true;
  int witness_dimension = -1;            // the witness cell's dimension (0: a lattice point)
  std::vector<BigInt> witness_khalimsky; // its Khalimsky coordinates (empty when convex)
  std::vector<std::vector<BigInt>> witness_vertices; // its 2^dimension vertices
};

/// The check of `definition` on the points coords[k dim .. k dim + dim) (at least one).
Escalated<ConvexityCheck> digital_convexity_exact(int dim, std::span<const BigInt> coords,
                                                  ConvexityDefinition definition,
                                                  std::uint64_t max_columns = kConvexityMaxColumns);

struct EnvelopeResult {
  std::vector<BigInt> coords; // FC*(Z), row-major, sorted, without duplicates
  std::size_t iterations = 0;
};
Escalated<EnvelopeResult>
fully_convex_envelope_exact(int dim, std::span<const BigInt> coords,
                            std::uint64_t max_points = kEnvelopeMaxPoints);

} // namespace zdg
