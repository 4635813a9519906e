#include <zdg/kernel/transforms/distributed_transform.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/transforms/distance_transform.hpp>
#include <zdg/kernel/transforms/separable_engine.hpp>

#include <algorithm>
#include <chrono>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

namespace zdg {

namespace {

double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

bool has_background(const std::uint8_t* mask, std::int64_t n, int item) {
  const auto uitem = static_cast<std::int64_t>(item);
  for (std::int64_t i = 0; i < n; ++i) {
    const std::uint8_t* p = mask + i * uitem;
    if (std::all_of(p, p + uitem, [](std::uint8_t b) { return b == 0; })) return true;
  }
  return false;
}

// The transpose: this rank's slab (rows of `slice` items, its slices) to its block of columns
// (n_0 rows of w items): the rank's own part copied, then P - 1 rounds of pairwise exchanges
// (round k: send to r + k, receive from r - k, mod P).
template <class X>
void transpose_slabs(const Domain& dom, RankExchange& ex, const std::vector<X>& slab,
                     std::vector<X>& block) {
  const int P = ex.size(), r = ex.rank();
  const std::int64_t n0 = dom.extent(0), slice = dom.stride(0);
  const RankRange mine = rank_range(n0, P, r), cols = rank_range(slice, P, r);
  const std::int64_t w = cols.size();
  // The rank's own part: straight from the slab into the block.
  for (std::int64_t z = 0; z < mine.size(); ++z) {
    const X* row = slab.data() + z * slice + cols.begin;
    std::copy(row, row + w, block.data() + (mine.begin + z) * w);
  }
  std::vector<X> send;
  for (int k = 1; k < P; ++k) {
    const int to = (r + k) % P, from = (r - k + P) % P;
    const RankRange to_cols = rank_range(slice, P, to), from_slices = rank_range(n0, P, from);
    const std::int64_t tw = to_cols.size();
    send.resize(static_cast<std::size_t>(mine.size() * tw));
    for (std::int64_t z = 0; z < mine.size(); ++z) {
      const X* row = slab.data() + z * slice + to_cols.begin;
      std::copy(row, row + tw, send.data() + z * tw);
    }
    ex.sendrecv(to, send.data(), send.size() * sizeof(X), from,
                block.data() + from_slices.begin * w,
                static_cast<std::uint64_t>(from_slices.size() * w) * sizeof(X));
  }
}

} // namespace

RankRange rank_range(std::int64_t n, int parts, int k) {
  if (parts < 1 || k < 0 || k >= parts || n < 0) {
    throw InvalidArgument("rank_range: part " + std::to_string(k) + " of " + std::to_string(parts) +
                          " parts of " + std::to_string(n) + " items");
  }
  const std::int64_t q = n / parts, rem = n % parts;
  const std::int64_t begin = k * q + std::min<std::int64_t>(k, rem);
  return {begin, begin + q + (k < rem ? 1 : 0)};
}

DistributedPart distributed_part(const Domain& dom, int rank, int ranks) {
  if (dom.dim() < 2) {
    throw InvalidArgument("distributed transform: a 1-D image has one axis only (its slabs would "
                          "be the whole line): use the in-memory transform");
  }
  return {rank_range(dom.extent(0), ranks, rank), rank_range(dom.stride(0), ranks, rank)};
}

template <class T>
T distance_transform_distributed(const Domain& dom, const std::uint8_t* slab_mask, int item,
                                 const TransformOptions& opt, RankExchange& ex, T* out,
                                 std::vector<std::int64_t>* sites,
                                 const std::function<void(const char*, double)>& stage_done) {
  detail::require_mask_item_bytes(item, "distributed transform");
  const DistributedPart part = distributed_part(dom, ex.rank(), ex.size());
  const auto bounds = detail::envelope_bounds(dom, opt, BigInt(0));
  detail::require_output_fits(bounds, opt, BigInt(std::numeric_limits<T>::max()),
                              "distance transform");
  if (bounds.width != detail::ValueWidth::I32 && bounds.width != detail::ValueWidth::I64) {
    throw InvalidArgument("distributed transform: the intermediate values of " + opt.metric.name() +
                          " on this domain need more than 64 bits (bound " + bounds.need.str() +
                          "); use the in-memory transform");
  }
  const std::int64_t n0 = dom.extent(0), slice = dom.stride(0);
  const std::int64_t z0 = part.slices.begin, w = part.columns.size();
  // The background, looked for by every rank in its slices: the same answer (and error) on all.
  const bool local = has_background(slab_mask, part.slices.size() * slice, item);
  if (ex.max_over_ranks(local ? 1 : 0) == 0) detail::throw_no_background(opt);

  auto done = [&](const char* stage, std::chrono::steady_clock::time_point t0) {
    if (stage_done) stage_done(stage, since(t0));
  };
  T largest = 0;
  detail::with_value_type(bounds.width, [&]<class V>(std::type_identity<V>) {
    if constexpr (std::is_same_v<V, std::int32_t> || std::is_same_v<V, std::int64_t>) {
      const V inf = detail::envelope_infinity<V>(bounds);
      // (1) The mask pass and the passes along axes d-1 .. 1, on the rank's slices.
      auto t0 = std::chrono::steady_clock::now();
      std::vector<V> slab(static_cast<std::size_t>(part.slices.size() * slice));
      std::vector<std::int64_t> slab_sites;
      if (part.slices.size() > 0) {
        std::vector<std::int64_t> ext = dom.extents();
        ext[0] = part.slices.size();
        detail::EnvelopePart slices;
        slices.axis0 = false;
        detail::separable_envelope_part<V>(Domain(ext), opt, slab_mask, slab.data(), inf,
                                           sites != nullptr ? &slab_sites : nullptr, item, slices);
        // The sites are linear indices in the slab: in the volume, z0 slices further.
        for (auto& s : slab_sites) {
          if (s >= 0) s += z0 * slice;
        }
      }
      done("slab passes", t0);

      // (2) The transpose: every rank's slices of this rank's columns.
      t0 = std::chrono::steady_clock::now();
      std::vector<V> block(static_cast<std::size_t>(n0 * w));
      transpose_slabs(dom, ex, slab, block);
      std::vector<V>().swap(slab);
      std::vector<std::int64_t> block_sites;
      if (sites != nullptr) {
        block_sites.resize(static_cast<std::size_t>(n0 * w));
        transpose_slabs(dom, ex, slab_sites, block_sites);
        std::vector<std::int64_t>().swap(slab_sites);
      }
      done("exchange", t0);

      // (3) The pass along axis 0 on whole columns.
      t0 = std::chrono::steady_clock::now();
      if (w > 0) {
        TransformOptions column_opt = opt;
        column_opt.torus = {opt.periodic(0), false};
        detail::EnvelopePart columns;
        columns.slices = false;
        detail::separable_envelope_part<V>(Domain({n0, w}), column_opt, nullptr, block.data(), inf,
                                           sites != nullptr ? &block_sites : nullptr, item,
                                           columns);
      }
      for (std::size_t i = 0; i < block.size(); ++i) {
        out[i] = static_cast<T>(block[i]);
        largest = std::max(largest, out[i]);
      }
      if (sites != nullptr) *sites = std::move(block_sites);
      done("axis 0", t0);
    } else {
      throw InvalidArgument("distributed transform: 64-bit engines only"); // excluded above
    }
  });
  return static_cast<T>(ex.max_over_ranks(largest));
}

#define ZDG_DIST_INSTANTIATE(T)                                                                    \
  template T distance_transform_distributed(                                                       \
      const Domain&, const std::uint8_t*, int, const TransformOptions&, RankExchange&, T*,         \
      std::vector<std::int64_t>*, const std::function<void(const char*, double)>&);
ZDG_DIST_INSTANTIATE(std::uint8_t)
ZDG_DIST_INSTANTIATE(std::uint16_t)
ZDG_DIST_INSTANTIATE(std::uint32_t)
ZDG_DIST_INSTANTIATE(std::uint64_t)
#undef ZDG_DIST_INSTANTIATE

} // namespace zdg
