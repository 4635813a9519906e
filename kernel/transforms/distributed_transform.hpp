// The exact distance transform and Voronoi map of a volume split over P ranks (processes of
// an MPI job, or any other team that can exchange bytes): slabs of slices in, blocks of
// columns out, one all-to-all transpose between.
//
// The separable transform (kernel/transforms/separable_engine.hpp) makes one pass per axis; all but
// the pass along axis 0 (the slowest) work on lines inside one slice of axis 0. Rank r holds the
// slices [z_r, z_{r+1}) of the mask (a balanced split of n_0: the first n_0 mod P ranks have
// one slice more; ranks past n_0 have none) and runs the mask pass and the passes along axes
// d-1 .. 1 on them, locally. The columns of a slice (its n_1 ... n_{d-1} points in C order)
// are split the same way, [c_r, c_{r+1}); rank r sends to rank q the part [c_q, c_{q+1}) of
// each of its slices and receives from every rank its slices of the columns [c_r, c_{r+1}):
// an n_0 x w_r array whose axis 0 is the volume's (the data from rank s lands in rows
// [z_s, z_{s+1}), already in place). The pass along axis 0 then runs locally on these whole
// columns. This is the slab-to-pencil transpose of distributed FFTs, applied to the separable
// lower envelopes of Meijster, Roerdink and Hesselink (2000); the out-of-core transform
// (kernel/transforms/out_of_core_transform.hpp) does the same with a file as the transpose. Each
// line sees the operations of the in-memory engine in the same order: the values, and the
// sites of the Voronoi map (ties to the smaller position on the line), are the same to the
// bit (tests/kernel/transforms/distributed_transform_test.cpp, for every metric, torus axes, lower
// bounds, mask item widths and P from 1 to 5 with empty slabs).
//
// Communication: each rank sends (P-1)/P of its slab's values (N/P x sizeof(V) bytes, V the
// engine's int32 or int64) and receives as much: N x sizeof(V) x (P-1)/P bytes in all, in P-1
// rounds of pairwise exchanges (round k: send to r+k, receive from r-k, mod P), 2 x sizeof(int64)
// more per point for a Voronoi map. Memory per rank: the slab's values and the block's (2 x
// N/P x sizeof(V)), one round's send buffer (N/P^2 x sizeof(V)), the output block.
// Time: the in-memory engine's O(N d / P) per rank (l_1, l_2, l_inf; O(N d log n / P) for other
// l_p), plus the exchange. Width: as the out-of-core transform, the 32- and 64-bit engines only
// (values up to 2^63: every l_1, l_2, l_inf volume below 2^20 per side, l_p for small p),
// InvalidArgument beyond; d >= 2.
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
