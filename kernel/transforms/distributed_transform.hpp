// The exact distance transform and Voronoi map of a volume split over P ranks (processes of
// an MPI job, or any other team that can exchange bytes): slabs of slices in, blocks of
// columns out, one all-to-all transpose between.
//
// Rank r holds a balanced share of the slices, runs the passes along axes d-1 .. 1 on them, then
// one all-to-all transpose (slab to pencil, in P-1 pairwise rounds) gives it a share of the
// columns, where the pass along axis 0 runs (Meijster, Roerdink and Hesselink 2000). The values
// and the Voronoi sites (ties to the smaller position) equal the in-memory engine's to the bit.
// Communication: N x sizeof(V) x (P-1)/P bytes in all (V the engine's int32 or int64), 16 bytes
// more per point for a Voronoi map; memory per rank about 2 N/P x sizeof(V) plus N/P^2 x
// sizeof(V) and the output. Time: O(N d / P) per rank (l_1, l_2, l_inf; O(N d log n / P)
// otherwise) plus the exchange. Width: the 32- and 64-bit engines only (values up to 2^63),
// InvalidArgument beyond; d >= 2 (design: docs/NOTES.md,
// "kernel/transforms/distributed_transform.hpp").
#pragma once

#include <zdg/kernel/images/image.hpp>
#include <zdg/kernel/transforms/lp_metric.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace zdg {

/// The collective operations the distributed transform needs from a team of ranks. Every rank
/// calls the same operations in the same order (they are collective).
class RankExchange {
public:
  virtual ~RankExchange() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  /// Sends send_bytes bytes to rank `to` while receiving recv_bytes bytes from rank `from`
  /// (the sender's matching call has the same count). to == from == rank(): a copy.
  virtual void sendrecv(int to, const void* send, std::uint64_t send_bytes, int from, void* recv,
                        std::uint64_t recv_bytes) = 0;
  /// The largest of the values given by the ranks, on every rank.
  virtual std::uint64_t max_over_ranks(std::uint64_t value) = 0;
};

/// Part k of n items split over `parts` parts as evenly as possible: [begin, end), the first
/// n mod parts parts one item longer.
struct RankRange {
  std::int64_t begin = 0, end = 0;
  std::int64_t size() const { return end - begin; }
};
RankRange rank_range(std::int64_t n, int parts, int k);

/// What rank r holds of a volume: its slices of the input and its columns of the output.
struct DistributedPart {
  RankRange slices;  // of axis 0: the rank's input is the mask of these slices
  RankRange columns; // of a slice (C order): the rank's output is n_0 rows of these columns
};
DistributedPart distributed_part(const Domain& dom, int rank, int ranks);

/// The distance transform of the volume dom (values of T: std::uint8_t .. std::uint64_t),
/// computed by the team `ex`: this rank gives the mask of its slices (slab_mask:
/// part.slices.size() x slice items of mask_item_bytes bytes, C order, background = all bytes
/// 0) and gets the values of its columns (out: n_0 rows of part.columns.size() values, row z
/// holding the columns [c_r, c_{r+1}) of slice z), and in sites (optional; resized to the same
/// layout) the linear index in dom of a nearest background point: the Voronoi map. Every rank
/// asks for the sites or none does (it is a collective choice, also for ranks without columns). The
/// values and sites equal distance_transform<T>'s and voronoi_map's. Errors, the same on every rank
/// (a rank never waits for one that threw): those of distance_transform, InvalidArgument for a 1-D
/// domain or values past 2^63. stage_done (optional) is called after each of the three stages
/// ("slab passes", "exchange", "axis 0") with the seconds this rank spent in it. Returns the
/// largest value of the whole volume.
template <class T>
T distance_transform_distributed(
    const Domain& dom, const std::uint8_t* slab_mask, int mask_item_bytes,
    const TransformOptions& opt, RankExchange& ex, T* out,
    std::vector<std::int64_t>* sites = nullptr,
    const std::function<void(const char* stage, double seconds)>& stage_done = {});

} // namespace zdg
