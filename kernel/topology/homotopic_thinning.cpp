#include <zdg/arith/error.hpp>
#include <zdg/kernel/topology/homotopic_thinning.hpp>
#include <zdg/kernel/transforms/distance_transform.hpp>

#include <algorithm>

namespace zdg {
namespace {

constexpr std::uint8_t kObject = 1, kQueued = 2, kAnchor = 4;

// The rank of the priority of every object point of the padded volume (0 elsewhere), and the
// number of ranks. Equal priorities share a rank.
std::vector<std::uint32_t> priority_ranks(const Image<std::uint8_t>& image,
                                          const ThinningOptions& options,
                                          const detail::PaddedVolume& vol, std::uint32_t& ranks) {
  std::vector<std::uint32_t> rank(vol.flags.size(), 0);
  if (options.priority == nullptr) {
    // Squared Euclidean distance to the background, the outside included: the transform of
    // the padded image (its layer of background is the outside that matters).
    std::vector<std::int64_t> ext;
    const std::int64_t layer = vol.dim() == 3 ? 0 : vol.extent[1] * vol.extent[2];
    if (vol.dim() == 3) ext.push_back(vol.extent[0]);
    ext.push_back(vol.extent[1]);
    ext.push_back(vol.extent[2]);
    Image<std::uint8_t> padded{Domain(ext), std::uint8_t{0}};
    for (std::int64_t q = 0; q < padded.size(); ++q) {
      padded[q] = vol.flags[static_cast<std::size_t>(q + layer)] & kObject;
    }
    TransformOptions t;
    t.threads = options.threads;
    const Image<std::uint32_t> dt = distance_transform<std::uint32_t>(padded, t);
    // Distinct values, ranked.
    std::vector<std::uint32_t> values;
    for (std::int64_t q = 0; q < padded.size(); ++q) {
      if (padded[q] != 0) values.push_back(dt[q]);
    }
    std::sort(values.begin(), values.end());
    values.erase(std::unique(values.begin(), values.end()), values.end());
    ranks = static_cast<std::uint32_t>(values.size());
    for (std::int64_t q = 0; q < padded.size(); ++q) {
      if (padded[q] == 0) continue;
      rank[static_cast<std::size_t>(q + layer)] = static_cast<std::uint32_t>(
          std::lower_bound(values.begin(), values.end(), dt[q]) - values.begin());
    }
    return rank;
  }
  const Image<std::int64_t>& pr = *options.priority;
  if (!(pr.domain() == image.domain())) {
    throw InvalidArgument("thinning: the priority image has another domain than the image");
  }
  std::vector<std::int64_t> values;
  for (std::int64_t i = 0; i < image.size(); ++i) {
    if (image[i] != 0) values.push_back(pr[i]);
  }
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  if (values.size() >= std::size_t{0xFFFFFFFFu}) {
    throw InvalidArgument("thinning: more than 2^32 - 1 distinct priorities");
  }
  ranks = static_cast<std::uint32_t>(values.size());
  for (std::int64_t i = 0; i < image.size(); ++i) {
    if (image[i] == 0) continue;
    rank[static_cast<std::size_t>(vol.padded_index(i))] = static_cast<std::uint32_t>(
        std::lower_bound(values.begin(), values.end(), pr[i]) - values.begin());
  }
  return rank;
}

} // namespace

ThinningResult homotopic_thinning(const Image<std::uint8_t>& image,
                                  const ThinningOptions& options) {
  const AdjacencyPair pair = detail::resolve_pair(image, options);
  detail::PaddedVolume vol(image);
  detail::mark_anchors(image, options, vol);
  std::uint32_t ranks = 0;
  const std::vector<std::uint32_t> rank = priority_ranks(image, options, vol, ranks);

  std::int64_t remaining = 0;
  for (std::uint8_t f : vol.flags) remaining += f & kObject;
  const detail::SimplicityTest simple(pair, remaining >= (std::int64_t{1} << 22));
  const bool conditional =
      options.skeleton == SkeletonKind::curve || options.skeleton == SkeletonKind::surface;
  const int neighbours = vol.dim() == 3 ? 26 : 8;
  const std::uint32_t full = vol.dim() == 3 ? 0x3FFFFFFu : 0xFFu;

  // Buckets of padded indices by priority rank, each consumed in order from head[r].
  std::vector<std::vector<std::int64_t>> bucket(ranks);
  std::vector<std::size_t> head(ranks, 0);
  std::uint32_t current = ranks;
  auto push = [&](std::int64_t p) {
    auto& f = vol.flags[static_cast<std::size_t>(p)];
    f |= kQueued;
    const std::uint32_t r = rank[static_cast<std::size_t>(p)];
    bucket[r].push_back(p);
    current = std::min(current, r);
  };
  for (std::int64_t p = 0; p < vol.size(); ++p) {
    const std::uint8_t f = vol.flags[static_cast<std::size_t>(p)];
    if ((f & kObject) != 0 && (f & kAnchor) == 0 && vol.configuration(p) != full) push(p);
  }

  ThinningResult result;
  result.passes = 1;
  std::int64_t next_report = std::int64_t{1} << 18;
  while (current < ranks) {
    auto& b = bucket[current];
    if (head[current] == b.size()) {
      std::vector<std::int64_t>().swap(b);
      head[current] = 0;
      ++current;
      continue;
    }
    const std::int64_t p = b[head[current]++];
    auto& f = vol.flags[static_cast<std::size_t>(p)];
    f = static_cast<std::uint8_t>(f & ~kQueued);
    if ((f & kObject) == 0 || (f & kAnchor) != 0) continue;
    const std::uint32_t config = vol.configuration(p);
    if (conditional && detail::is_skeleton_point(options.skeleton, pair, config)) {
      f |= kAnchor;
      continue;
    }
    if (!simple(config)) continue;
    f = static_cast<std::uint8_t>(f & ~kObject);
    ++result.deleted;
    --remaining;
    if (options.deletions != nullptr) options.deletions->push_back(vol.image_index(p));
    for (int j = 0; j < neighbours; ++j) {
      const std::int64_t q = p + vol.offset[static_cast<std::size_t>(j)];
      const std::uint8_t g = vol.flags[static_cast<std::size_t>(q)];
      if ((g & kObject) != 0 && (g & (kQueued | kAnchor)) == 0) push(q);
    }
    if (options.progress && result.deleted >= next_report) {
      next_report += std::int64_t{1} << 18;
      options.progress({remaining, result.deleted, 1});
    }
  }
  if (options.progress) options.progress({remaining, result.deleted, 1});
  result.skeleton = vol.object(image.domain());
  return result;
}

} // namespace zdg
