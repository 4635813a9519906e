// The dimension of the harmonic 1-forms of the cell complex of a closed digital surface
// (kernel/surfaces/surfel_complex.hpp), computed from its exterior derivatives
// (kernel/calculus/exterior_derivative.hpp) by exact ranks (kernel/calculus/modular_rank.hpp):
//     dim H^1 = dim ker d1 - dim im d0 = #linels - rank d0 - rank d1.
// By the discrete Hodge theorem the harmonic 1-forms (d1 h = 0, d0^T star1 h = 0, for any
// positive diagonal stars) are isomorphic to the first cohomology H^1 (Desbrun, Hirani, Leok,
// Marsden 2005, 6; Desbrun, Kanso, Tong 2008, 4.3), whose dimension on a closed orientable
// surface of genus g is 2g; on a complex with several closed surfaces it is the sum. This is
// a count taken from the operators, independent of the Euler characteristic
// V - E + F (kernel/surfaces/image_surfaces.hpp), which it must agree with: for one
// connected closed surface rank d0 = V - 1 and rank d1 = F - 1, so dim = E - V - F + 2.
// The count is that of the complex given: at a pinched linel (kernel/surfaces/
// pointel_cycles.hpp) surfel_complex pairs the four sides in face order, not by the surfel
// adjacency, and can glue the two passages crosswise (a surface then splits into two face
// components and the dimension differs from 2 genus: found by the random property of the
// test, which asserts 2 genus only without pinched linels); elsewhere it is 2 genus.
//
// O(nnz log nnz) per rank (graph incidences: modular_rank.hpp), twice (two primes); O(F)
// memory. Counts int64. Errors: InvalidArgument when a surface label is out of range or when
// the labels do not split the complex (a linel or pointel shared by two labelled surfaces).
#pragma once

#include <zdg/kernel/calculus/modular_rank.hpp>
#include <zdg/kernel/surfaces/surfel_complex.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace zdg {

struct HarmonicDimension {
  std::int64_t pointels = 0, linels = 0, surfels = 0;
  ExactRank d0, d1;
  std::int64_t dimension = 0; ///< linels - d0.rank - d1.rank
};

HarmonicDimension harmonic_dimension(const SurfelComplex& c);

/// Per surface, where surface_of[s] in [0, surfaces) labels each surfel (the closed surfaces
/// of kernel/surfaces/image_surfaces.hpp): the dimension of each surface's sub-complex.
std::vector<HarmonicDimension> harmonic_dimensions(const SurfelComplex& c,
                                                   std::span<const std::uint64_t> surface_of,
                                                   std::int64_t surfaces);

} // namespace zdg
