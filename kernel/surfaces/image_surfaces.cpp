#include <zdg/kernel/surfaces/image_surfaces.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/arith/integer.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>
#include <zdg/kernel/surfaces/pointel_cycles.hpp>

#include <string>
#include <utility>

namespace zdg {

SurfaceConvention SurfaceConvention::of(int k, int kbar) {
  const bool ok = (k == 6 && (kbar == 26 || kbar == 18)) || (kbar == 6 && (k == 26 || k == 18));
  if (!ok)
    throw InvalidArgument("adjacency pair (" + std::to_string(k) + "," + std::to_string(kbar) +
                          ") for a volume: expected 6,26 or 26,6 or 6,18 or 18,6");
  SurfaceConvention c;
  c.object = k;
  c.background = kbar;
  c.linels = k == 6 ? SurfelAdjacency::exterior : SurfelAdjacency::interior;
  c.object_pinches = k == 26;
  c.background_pinches = kbar == 26;
  return c;
}

SurfaceConvention SurfaceConvention::of(const AdjacencyPair& pair) {
  if (pair.dim != 3)
    throw InvalidArgument("adjacency pair " + pair.name() + " is not a pair of a volume");
  return of(pair.object, pair.background);
}

bool SurfaceConvention::pinched(std::uint8_t configuration) const {
  return (object_pinches && is_opposite_pair(configuration)) ||
         (background_pinches && is_opposite_pair(static_cast<std::uint8_t>(~configuration)));
}

std::int64_t ImageSurfaces::euler_sum() const {
  std::int64_t s = 0;
  for (const auto& f : surfaces) s += f.euler;
  return s;
}

std::int64_t ImageSurfaces::object_euler() const {
  return (euler_sum() - 2 * pinched_pointels) / 2;
}

namespace {

std::uint64_t find_root(std::vector<std::uint64_t>& parent, std::uint64_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

// Links the larger root under the smaller: every parent precedes its child.
void unite(std::vector<std::uint64_t>& parent, std::uint64_t a, std::uint64_t b) {
  a = find_root(parent, a);
  b = find_root(parent, b);
  if (a == b) return;
  if (a < b) std::swap(a, b);
  parent[a] = b;
}

} // namespace

ImageSurfaces image_surfaces(const Image<std::uint8_t>& image, const ImageSurfels& surfels,
                             const SurfaceConvention& convention, unsigned threads) {
  const VoxelGrid& g = surfels.grid;
  const VoxelGrid ig = VoxelGrid::of(image.domain());
  if (ig.nx != g.nx || ig.ny != g.ny || ig.nz != g.nz)
    throw InvalidArgument("image_surfaces: the surfels are not those of this image");
  const std::uint8_t* data = image.values().data();
  const std::int64_t n = surfels.size();
  ImageSurfaces out;
  out.convention = convention;
  std::vector<std::uint64_t> parent(static_cast<std::size_t>(n));
  for (std::int64_t i = 0; i < n; ++i) parent[std::size_t(i)] = std::uint64_t(i);
  std::vector<std::uint8_t> owned(static_cast<std::size_t>(n), 0);

  const std::int64_t chunks = worker_count(threads, n);
  std::vector<std::vector<std::pair<std::uint64_t, std::uint64_t>>> cross(
      static_cast<std::size_t>(chunks));
  std::vector<std::int64_t> pinches(static_cast<std::size_t>(chunks), 0);
  std::vector<std::int64_t> linel_sightings(static_cast<std::size_t>(chunks), 0);
  const PointelStar* stars = pointel_stars(convention.linels);
  parallel_for(chunks, static_cast<unsigned>(chunks), [&](std::int64_t t) {
    const std::int64_t q = n / chunks, r = n % chunks;
    const std::int64_t b = q * t + r * t / chunks, e = q * (t + 1) + r * (t + 1) / chunks;
    auto& my_cross = cross[std::size_t(t)];
    std::int64_t my_pinches = 0, my_linels = 0;
    for_each_surfel(surfels, b, e, [&](std::int64_t i, std::uint64_t code, const std::int64_t* v) {
      int own = 0;
      SurfelCorner k[4];
      std::uint8_t config[4];
      const PointelStar* st[4];
      for (int c = 0; c < 4; ++c) {
        k[c] = surfel_corner(v, code, c);
        config[c] = pointel_configuration(g, data, k[c].q[0], k[c].q[1], k[c].q[2]);
        st[c] = &stars[config[c]];
      }
      for (int c = 0; c < 4; ++c) {
        const int f = k[c].face;
        if (st[c]->owner[std::size_t(f)] == f) {
          ++own;
          if (st[c]->cycle[std::size_t(f)] == 0 && convention.pinched(config[c])) ++my_pinches;
        }
        // The edge from corner c - 1 to corner c: joined at both of its ends.
        const int p = (c + 3) % 4;
        if (st[c]->entering_joined[std::size_t(f)] && st[p]->leaving_joined[std::size_t(k[p].face)])
          ++my_linels;
        const int nf = st[c]->next[std::size_t(f)];
        if (nf < 0) throw Error("image_surfaces: a surfel corner is not a boundary face");
        const LocalSurfel ls = local_face_surfel(g, k[c].q, nf, config[c]);
        const std::int64_t j = surfels.find_in_row(ls.row, ls.code);
        if (j < 0) throw Error("image_surfaces: a neighbour surfel is missing from the list");
        if (j >= b && j < e) {
          unite(parent, std::uint64_t(i), std::uint64_t(j));
        } else if (i < j) {
          my_cross.emplace_back(std::uint64_t(i), std::uint64_t(j));
        }
      }
      owned[std::size_t(i)] = static_cast<std::uint8_t>(own);
    });
    pinches[std::size_t(t)] = my_pinches;
    linel_sightings[std::size_t(t)] = my_linels;
  });
  for (const auto& list : cross)
    for (const auto& [i, j] : list) unite(parent, i, j);
  for (auto p : pinches) out.pinched_pointels += p;
  // Each pinched linel is an edge of its four surfels.
  for (auto p : linel_sightings) out.pinched_linels += p;
  out.pinched_linels /= 4;

  // Labels in place: parents precede children, so one ascending pass relabels.
  std::uint64_t next = 0;
  for (std::int64_t i = 0; i < n; ++i) {
    auto& p = parent[std::size_t(i)];
    if (p == std::uint64_t(i)) {
      out.surfaces.push_back(BoundarySurface{});
      out.surfaces.back().first = i;
      p = next++;
    } else {
      p = parent[std::size_t(p)];
    }
  }
  std::vector<int128_t> volume(out.surfaces.size(), 0);
  for (std::int64_t i = 0; i < n; ++i) {
    const auto s = parent[std::size_t(i)];
    auto& f = out.surfaces[std::size_t(s)];
    ++f.surfels;
    f.vertices += owned[std::size_t(i)];
    const std::uint64_t code = surfels.codes[std::size_t(i)];
    if (code_axis(code) == 0) {
      const std::int64_t x = code_voxel(code) % g.nx;
      volume[std::size_t(s)] += code_positive(code) ? x + 1 : -x;
    }
  }
  for (std::size_t s = 0; s < out.surfaces.size(); ++s) {
    auto& f = out.surfaces[s];
    f.euler = f.vertices - f.surfels;
    f.genus = (2 - f.euler) / 2;
    f.volume = static_cast<std::int64_t>(volume[s]);
  }
  out.surface_of = std::move(parent);
  return out;
}

} // namespace zdg
