// Parallel homotopic thinning by critical kernels (Bertrand, "On critical kernels", C. R.
// Acad. Sci. Paris 345, 2007; Bertrand and Couprie, "Two-dimensional parallel thinning
// algorithms based on critical kernels", JMIV 31, 2008, and "Powerful parallel and symmetric
// 3D thinning schemes based on critical kernels", JMIV 48, 2014): symmetric, independent of
// any scan order, multi-threaded.
//
// Cubical view, pairs (26,6) and (8,4) only: a point is critical iff it is not simple; the
// critical cliques of dimensions 2, 1, 0 are those of Bertrand 2007 (definitions in
// docs/NOTES.md, "kernel/topology/critical_kernel_thinning.hpp"). Theorem (Bertrand 2007):
// if Y is a subset of X meeting every critical clique, X collapses onto Y.
//
// One pass: K_3 = the anchors and the points that are not simple (or meet the skeleton
// condition of kernel/topology/skeleton_constraints.hpp, and then stay anchored); for d = 2, 1, 0
// in turn, every critical d-clique disjoint from K_{d+1} is added whole to K_{d+1}, all at once
// (each d decided on the state of the previous level, hence symmetric); the pass keeps K_0 and
// deletes the rest. Passes repeat until one deletes nothing. The result is invariant under the
// 48 symmetries of the cube (tests rotate the input, thin, rotate back) for the ultimate,
// curve and surface kinds (and any symmetric set of anchors; the reduced medial axis of the
// medial-axis kind breaks ties by scan order, so that kind is not), does not depend on the
// thread count, and is a subset of X with the same Betti numbers (object and background).
//
// Cost: the first pass examines the 6-border (the only points that can be simple), later
// passes only the points whose neighbourhood changed and the candidates kept (any other point
// keeps its verdict), O(1) each (the simplicity test, 26 faces); the number of passes is about
// the largest inscribed radius, or the longest branch for the ultimate kind (open curves
// shrink by their ends, one point per pass). The passes' work is split over the threads;
// the bookkeeping between passes is sequential. Whole cliques are kept where a sequential
// thinning would pick one point, so results can be thicker (a 2x2x2 block stays).
#pragma once

#include <zdg/kernel/topology/skeleton_constraints.hpp>

namespace zdg {

/// Thins the object (nonzero points) of a 2D or 3D image by critical kernels. The priority
/// option is not used. InvalidArgument for another dimension or pair, or anchors of another
/// domain.
ThinningResult critical_kernel_thinning(const Image<std::uint8_t>& image,
                                        const ThinningOptions& options = {});

} // namespace zdg
