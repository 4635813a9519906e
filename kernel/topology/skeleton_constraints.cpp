#include <zdg/arith/error.hpp>
#include <zdg/kernel/topology/simple_points.hpp>
#include <zdg/kernel/topology/skeleton_constraints.hpp>
#include <zdg/kernel/transforms/reduced_medial_axis.hpp>

#include <bit>

namespace zdg {

SkeletonKind parse_skeleton_kind(const std::string& text) {
  if (text == "ultimate") return SkeletonKind::ultimate;
  if (text == "curve") return SkeletonKind::curve;
  if (text == "surface") return SkeletonKind::surface;
  if (text == "medial-axis") return SkeletonKind::medial_axis;
  throw InvalidArgument("skeleton '" + text +
                        "' is not one of ultimate, curve, surface, medial-axis");
}

std::string skeleton_kind_name(SkeletonKind kind) {
  switch (kind) {
  case SkeletonKind::ultimate:
    return "ultimate";
  case SkeletonKind::curve:
    return "curve";
  case SkeletonKind::surface:
    return "surface";
  default:
    return "medial-axis";
  }
}

namespace detail {

PaddedVolume::PaddedVolume(const Image<std::uint8_t>& image) {
  const Domain& d = image.domain();
  dim_ = d.dim();
  if (dim_ != 2 && dim_ != 3) {
    throw InvalidArgument("thinning: dimension " + std::to_string(dim_) + " (only 2D and 3D)");
  }
  neighbours_ = dim_ == 3 ? 26 : 8;
  extent = {dim_ == 3 ? d.extent(0) + 2 : 3, d.extent(dim_ - 2) + 2, d.extent(dim_ - 1) + 2};
  std::int64_t total = 0;
  if (__builtin_mul_overflow(extent[0], extent[1], &total) ||
      __builtin_mul_overflow(total, extent[2], &total)) {
    throw InvalidArgument("thinning: the padded image does not fit int64 indices");
  }
  flags.assign(static_cast<std::size_t>(total), 0);
  // Row by row: row r of the image (n2 points) starts at padded_index(r * n2).
  const std::int64_t n2 = extent[2] - 2, rows = d.size() / n2;
  for (std::int64_t r = 0; r < rows; ++r) {
    const std::uint8_t* src = image.values().data() + r * n2;
    std::uint8_t* dst = flags.data() + padded_index(r * n2);
    for (std::int64_t x = 0; x < n2; ++x) dst[x] = src[x] != 0 ? 1 : 0;
  }
  int j = 0;
  const int r0 = dim_ == 3 ? 1 : 0;
  for (int a = -r0; a <= r0; ++a) {
    for (int b = -1; b <= 1; ++b) {
      for (int c = -1; c <= 1; ++c) {
        if (a == 0 && b == 0 && c == 0) continue;
        offset[static_cast<std::size_t>(j++)] = (a * extent[1] + b) * extent[2] + c;
      }
    }
  }
}

std::int64_t PaddedVolume::padded_index(std::int64_t i) const {
  const std::int64_t n1 = extent[1] - 2, n2 = extent[2] - 2;
  const std::int64_t i2 = i % n2, i1 = (i / n2) % n1, i0 = i / (n1 * n2);
  return ((i0 + 1) * extent[1] + (i1 + 1)) * extent[2] + (i2 + 1);
}

std::int64_t PaddedVolume::image_index(std::int64_t p) const {
  const std::int64_t n1 = extent[1] - 2, n2 = extent[2] - 2;
  const std::int64_t p2 = p % extent[2], p1 = (p / extent[2]) % extent[1],
                     p0 = p / (extent[1] * extent[2]);
  return ((p0 - 1) * n1 + (p1 - 1)) * n2 + (p2 - 1);
}

Image<std::uint8_t> PaddedVolume::object(const Domain& domain) const {
  Image<std::uint8_t> out(domain, std::uint8_t{0});
  const std::int64_t n2 = extent[2] - 2, rows = domain.size() / n2;
  for (std::int64_t r = 0; r < rows; ++r) {
    const std::uint8_t* src = flags.data() + padded_index(r * n2);
    std::uint8_t* dst = out.values().data() + r * n2;
    for (std::int64_t x = 0; x < n2; ++x) dst[x] = src[x] & 1u;
  }
  return out;
}

bool is_skeleton_point(SkeletonKind kind, const AdjacencyPair& pair, std::uint32_t config) {
  if (kind == SkeletonKind::curve) {
    // Exactly one object point among all the 3^d - 1 neighbours, whatever the pair (with a
    // count of k-neighbours only, a 6-object would keep every point of a staircase whose
    // lateral neighbours went first: hairs).
    (void)pair;
    return std::popcount(config) == 1;
  }
  if (kind == SkeletonKind::surface) {
    const TopologicalNumbers t = topological_numbers(pair, config);
    return t.object >= 2 || t.background >= 2;
  }
  return false;
}

SimplicityTest::SimplicityTest(const AdjacencyPair& pair, bool use_table) : pair_(pair) {
  if (pair.dim == 2 || use_table) table_ = &SimplePointTable::of(pair);
}

bool SimplicityTest::operator()(std::uint32_t config) const {
  return table_ != nullptr ? table_->simple(config) : is_simple_by_definition(pair_, config);
}

AdjacencyPair resolve_pair(const Image<std::uint8_t>& image, const ThinningOptions& options) {
  if (image.dim() != 2 && image.dim() != 3) {
    throw InvalidArgument("thinning: dimension " + std::to_string(image.dim()) +
                          " (only 2D and 3D)");
  }
  if (options.pair.dim == 0) return default_adjacency_pair(image.dim());
  if (options.pair.dim != image.dim()) {
    throw InvalidArgument("thinning: adjacency pair " + options.pair.name() + " is not for a " +
                          std::to_string(image.dim()) + "D image");
  }
  return make_adjacency_pair(options.pair.dim, options.pair.object, options.pair.background);
}

void mark_anchors(const Image<std::uint8_t>& image, const ThinningOptions& options,
                  PaddedVolume& volume) {
  if (options.anchors != nullptr) {
    if (!(options.anchors->domain() == image.domain())) {
      throw InvalidArgument("thinning: the anchor image has another domain than the image");
    }
    for (std::int64_t i = 0; i < image.size(); ++i) {
      if ((*options.anchors)[i] != 0 && image[i] != 0) {
        volume.flags[static_cast<std::size_t>(volume.padded_index(i))] |= 4u;
      }
    }
  }
  if (options.skeleton == SkeletonKind::medial_axis) {
    // The reduced medial axis of the object with the outside as background: computed on the
    // image padded with one layer of background.
    std::vector<std::int64_t> ext, lower;
    for (int k = 0; k < image.dim(); ++k) {
      ext.push_back(image.domain().extent(k) + 2);
      lower.push_back(image.domain().lower(k) - 1);
    }
    Image<std::uint8_t> padded(Domain(ext, lower), std::uint8_t{0});
    for (std::int64_t i = 0; i < image.size(); ++i) {
      if (image[i] != 0) padded.at(image.domain().point(i)) = 1;
    }
    TransformOptions t;
    t.threads = options.threads;
    for (const MedialBall& b : reduced_medial_axis(padded, t)) {
      const std::int64_t i = image.domain().index(b.centre);
      volume.flags[static_cast<std::size_t>(volume.padded_index(i))] |= 4u;
    }
  }
}

} // namespace detail
} // namespace zdg
