// Number of pixels of a digitized set X in a digital disc, from the boundary of X (Green's
// formula), in O(log n) per query instead of the O(rho) of a symmetric-difference update.
//
// Mathematics. Let D = c + { d : |d|^2 <= rho^2 } (kernel/digitization/digital_disc.hpp) and X a
// set of pixels whose contours (all of them: outer boundaries and holes,
// kernel/curves/digital_contour.hpp) are known. The pixel count of D n X is the area of the union
// of its unit squares, i.e. half the shoelace sum  sum cross(p, q)  over the directed edges p -> q
// of its boundary (D n X on the left). That boundary is made of
//   (a) the contour linels of X whose two pixels both lie in D (oriented as the contour), and
//   (b) the boundary linels of D (counter-clockwise) whose pixel in D belongs to X.
// The (a) linels form maximal runs of consecutive linels along the contours; over a run the
// shoelace sum is a difference of prefix sums. Along the closed boundary of D, membership in X
// of the D-pixels of consecutive boundary linels changes exactly at the pointels where an odd
// number of (a) linels meet, i.e. at the ends of the (a) runs (on a straight part of the
// boundary of D one inner linel meets it; at a concave corner two, A|B and B|C, and the
// membership of A and C differs iff one of them is a contour linel; at a convex corner none).
// So one membership query (the D-pixel of the first boundary linel of D) and the run ends give
// the (b) part as a few differences of prefix sums around the boundary of D.
// The (a) runs are found by descending a tree of bounding boxes over blocks of contour linels
// (a box inside D is a whole run piece, a box missing D is skipped; only the blocks where the
// contour crosses the boundary of D are scanned): O(log n + B) per run end, B = 8.
//
// Precondition: `contours` are ALL the contours of the set met by the discs queried. A missing
// contour of a component met by D gives a wrong count, which cannot be detected from the
// contours alone (the consistency checks, an even shoelace sum and 0 <= count <= |D|, catch
// only some cases and throw std::logic_error). Callers establish completeness, e.g. by a
// topology-preserving digitization of a connected, simply connected shape (one contour).
//
// Cost: construction O(n + rho) (prefix sums, block boxes, the boundary of D and its pointel
// index); a query O(k (log n + B)) for k runs of (a) linels (k = 1 when D meets one arc of the
// boundary) plus one membership query. Not thread-safe (scratch buffers).
// Width: pointels are int64_t; shoelace sums are int128_t (|coordinate| < 2^40 is checked, so
// every sum of < 2^40 terms fits); counts are exact int64_t.
// Sources: Green's formula for digital areas (the shoelace formula on the pixel boundary);
// the use case is the integral-invariant curvature of Coeurjolly, Lachaud, Levallois (CVIU
// 2014), where the count is queried at every linel of the boundary.
#pragma once

#include <zdg/arith/checked.hpp>
#include <zdg/kernel/curves/digital_contour.hpp>
#include <zdg/kernel/digitization/digital_disc.hpp>

#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

namespace zdg {

class ContourBallCounter {
public:
  ContourBallCounter(const GaussDigitization2& set, std::span<const DigitalContour> contours,
                     double radius_pixels);
  /// |D(c) n X|.
  std::int64_t count(const Pixel& c);
  const DigitalDisc& disc() const { return disc_; }

private:
  struct Chain {
    std::size_t n = 0;
    std::vector<std::int64_t> px, py;         // pointels relative to origin_, n + 1 (closed)
    std::vector<int128_t> prefix;             // prefix[j] = sum_{i<j} cross(p_i, p_{i+1})
    std::vector<std::int64_t> ax, ay, bx, by; // the two pixels of each linel
    std::size_t leaves = 1;                   // tree leaves (power of two >= blocks)
    std::vector<std::int64_t> x0, x1, y0, y1; // node boxes of both pixels, heap order
  };
  struct Run {
    std::size_t begin, end; // inclusive linel indices, end < begin when wrapping
  };

  const GaussDigitization2& set_;
  DigitalDisc disc_;
  Pixel origin_{};
  std::vector<Chain> chains_;
  // Boundary of D: pointels relative to the centre, prefix shoelace sums, pointel -> index.
  std::vector<std::int64_t> bx_, by_;
  std::vector<int128_t> bprefix_;
  std::unordered_map<std::int64_t, std::size_t> bindex_;
  Pixel first_inner_{}; // D-pixel of the first boundary linel of D, relative to the centre
  // Scratch.
  std::vector<Run> runs_;
  std::vector<std::size_t> flips_;

  std::int64_t key(std::int64_t x, std::int64_t y) const;
  void collect(const Chain& ch, std::size_t node, std::size_t lo, std::size_t hi, std::int64_t cx,
               std::int64_t cy);
  void add_linels(std::size_t a, std::size_t b);
};

} // namespace zdg
