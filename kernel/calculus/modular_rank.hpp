// The rank of a sparse integer incidence matrix (kernel/calculus/incidence_matrix.hpp) by
// exact Gaussian elimination modulo a prime p < 2^31.
//
// Rank over Q and modulo p: every minor of an integer matrix reduces mod p, so
// rank_p(A) <= rank_Q(A), with equality unless p divides every nonzero maximal minor (finitely
// many p). exact_rank runs two primes (2^31 - 1 and 2^31 - 19) and returns the larger rank.
// For the exterior derivatives of an oriented cell complex of a surface it is exact for every
// p: each row of d0 and each column of d1 holds one +1 and one -1 (the incidence matrix of a
// directed graph, totally unimodular: every minor is 0 or +-1).
//
// Elimination: the matrix is taken in the orientation whose rows are shorter (rank A =
// rank A^T); rows are pivoted in order, each on its column with the fewest remaining
// nonzeros, and the pivot column is eliminated from the other rows. Where every row has at
// most two nonzeros (d0, d1^T: graph incidences), eliminating a row merges one column into
// the other (an edge contraction): rows never grow past two nonzeros and, the smaller column
// being the one merged, the cost is O(nnz log nnz) time and O(nnz) memory. On a general
// matrix the same elimination costs up to O(m n min(m, n)).
//
// Width: residues uint32, products in uint64 (no overflow for p < 2^31). Source: the
// structured Gaussian elimination of sparse integer matrices (Dumas, Villard, "Computing the
// rank of large sparse matrices over finite fields", CASC 2002).
#pragma once

#include <zdg/kernel/calculus/incidence_matrix.hpp>

#include <cstdint>

namespace zdg {

/// rank of A over Z/pZ. InvalidArgument unless p is a prime in [2, 2^31) (checked by trial
/// division, O(sqrt p)).
std::int64_t rank_mod_p(const IncidenceMatrix& a, std::uint32_t p);

struct ExactRank {
  std::int64_t rank = 0;                 ///< max of the two: the rank over Q (see above)
  std::int64_t rank_p1 = 0, rank_p2 = 0; ///< modulo 2^31 - 1 and 2^31 - 19
};

ExactRank exact_rank(const IncidenceMatrix& a);

} // namespace zdg
