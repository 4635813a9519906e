#include <zdg/kernel/surfaces/digital_surface.hpp>

#include <algorithm>
#include <string>
#include <unordered_map>
#include <unordered_set>

namespace zdg {

namespace {

std::string voxel_string(const Voxel& z) {
  return "(" + std::to_string(z.x) + ", " + std::to_string(z.y) + ", " + std::to_string(z.z) + ")";
}

Voxel step(Voxel z, int axis, int sign) {
  coord(z, axis) += sign;
  return z;
}

/// A set of surfels of one box: a flat table with linear probing over 61-bit keys (the
/// Khalimsky coordinates relative to the box, 20 bits each, and the orientation) when the box
/// spans fewer than 2^19 voxels along every axis, else std::unordered_set. Tracking a surface
/// of millions of surfels inserts each one once and probes each of its 4 neighbours: the
/// node-based set spent a third of the tracking time in allocation and pointer chasing.
class SurfelSet {
public:
  explicit SurfelSet(const VoxelBox& box)
      : k0_{2 * box.lo.x - 1, 2 * box.lo.y - 1, 2 * box.lo.z - 1} {
    packed_ = true;
    for (int a = 0; a < 3; ++a)
      packed_ = packed_ && coord(box.hi, a) - coord(box.lo, a) < (std::int64_t{1} << 19) - 2;
    if (packed_) slots_.assign(std::size_t{1} << 12, kEmpty);
  }
  /// True when s was not in the set.
  bool insert(const Surfel& s) {
    if (!packed_) return other_.insert(s).second;
    const std::uint64_t key = pack(s);
    if (key == kEmpty) return other_.insert(s).second; // outside the packed range
    std::size_t i = slot(key);
    while (slots_[i] != kEmpty) {
      if (slots_[i] == key) return false;
      i = (i + 1) & (slots_.size() - 1);
    }
    slots_[i] = key;
    if (++size_ * 2 > slots_.size()) grow();
    return true;
  }
  bool contains(const Surfel& s) const {
    if (!packed_) return other_.count(s) != 0;
    const std::uint64_t key = pack(s);
    if (key == kEmpty) return other_.count(s) != 0;
    for (std::size_t i = slot(key); slots_[i] != kEmpty; i = (i + 1) & (slots_.size() - 1))
      if (slots_[i] == key) return true;
    return false;
  }

private:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
  KPoint k0_;
  bool packed_ = false;
  std::vector<std::uint64_t> slots_;
  std::size_t size_ = 0;
  std::unordered_set<Surfel, SurfelHash> other_;

  std::uint64_t pack(const Surfel& s) const {
    const std::int64_t d[3] = {s.k.x - k0_.x, s.k.y - k0_.y, s.k.z - k0_.z};
    for (const auto v : d)
      if (v < 0 || v >= (std::int64_t{1} << 20)) return kEmpty;
    return (std::uint64_t(d[0]) | std::uint64_t(d[1]) << 20 | std::uint64_t(d[2]) << 40) << 1 |
           std::uint64_t(s.direct);
  }
  std::size_t slot(std::uint64_t key) const {
    return std::size_t((key * 0x9E3779B97F4A7C15ULL) >> 32) & (slots_.size() - 1);
  }
  void grow() {
    std::vector<std::uint64_t> old(slots_.size() * 2, kEmpty);
    old.swap(slots_);
    for (const auto key : old) {
      if (key == kEmpty) continue;
      std::size_t i = slot(key);
      while (slots_[i] != kEmpty) i = (i + 1) & (slots_.size() - 1);
      slots_[i] = key;
    }
  }
};

/// Breadth-first tracking from seed into `order`, with `seen` shared by the calls.
void track_into(const VoxelPredicate& inside, const VoxelBox& box, const Surfel& seed,
                SurfelAdjacency adjacency, SurfelSet& seen, std::vector<Surfel>& order) {
  check_voxel_box(box);
  if (cell_dimension(seed.k) != 2)
    throw InvalidArgument("track_surface: seed " + voxel_string(seed.k) + " is not a surfel");
  auto in = [&](const Voxel& z) { return box.contains(z) && inside(z); };
  if (!in(inner_voxel(seed)) || in(outer_voxel(seed)))
    throw InvalidArgument("track_surface: seed surfel " + voxel_string(seed.k) +
                          " is not a boundary surfel of the set with this orientation");
  std::size_t i = order.size();
  seen.insert(seed);
  order.push_back(seed);
  for (; i < order.size(); ++i) {
    for (const Surfel& n : surfel_neighbours(inside, box, order[i], adjacency))
      if (seen.insert(n)) order.push_back(n);
  }
}

} // namespace

BinaryVolume BinaryVolume::from_predicate(const VoxelPredicate& inside, const VoxelBox& box) {
  check_voxel_box(box);
  BinaryVolume v{box, {}};
  const auto nx = std::size_t(box.hi.x - box.lo.x + 1), ny = std::size_t(box.hi.y - box.lo.y + 1),
             nz = std::size_t(box.hi.z - box.lo.z + 1);
  v.data.resize(nx * ny * nz);
  std::size_t i = 0;
  for (auto z = box.lo.z; z <= box.hi.z; ++z)
    for (auto y = box.lo.y; y <= box.hi.y; ++y)
      for (auto x = box.lo.x; x <= box.hi.x; ++x) v.data[i++] = inside({x, y, z}) ? 1 : 0;
  return v;
}

std::vector<Surfel> boundary_surfels(const VoxelPredicate& inside, const VoxelBox& box) {
  check_voxel_box(box);
  const auto nx = std::size_t(box.hi.x - box.lo.x + 1), ny = std::size_t(box.hi.y - box.lo.y + 1);
  std::vector<std::uint8_t> prev(nx * ny, 0), cur(nx * ny, 0);
  std::vector<Surfel> out;
  for (auto z = box.lo.z; z <= box.hi.z + 1; ++z) {
    if (z <= box.hi.z) {
      std::size_t i = 0;
      for (auto y = box.lo.y; y <= box.hi.y; ++y)
        for (auto x = box.lo.x; x <= box.hi.x; ++x) cur[i++] = inside({x, y, z}) ? 1 : 0;
    } else {
      std::fill(cur.begin(), cur.end(), std::uint8_t{0});
    }
    // z-surfels between slice z - 1 (prev) and slice z (cur).
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i) {
        const auto p = prev[j * nx + i], c = cur[j * nx + i];
        const auto x = box.lo.x + std::int64_t(i), y = box.lo.y + std::int64_t(j);
        if (p && !c) out.push_back(surfel_between({x, y, z - 1}, 2, +1));
        if (!p && c) out.push_back(surfel_between({x, y, z}, 2, -1));
      }
    if (z <= box.hi.z) {
      auto at = [&](std::int64_t i, std::int64_t j) {
        return i >= 0 && j >= 0 && i < std::int64_t(nx) && j < std::int64_t(ny) &&
               cur[std::size_t(j) * nx + std::size_t(i)] != 0;
      };
      for (std::int64_t j = 0; j < std::int64_t(ny); ++j)
        for (std::int64_t i = -1; i < std::int64_t(nx); ++i) {
          const bool a = at(i, j), b = at(i + 1, j);
          const auto y = box.lo.y + j;
          if (a && !b) out.push_back(surfel_between({box.lo.x + i, y, z}, 0, +1));
          if (!a && b) out.push_back(surfel_between({box.lo.x + i + 1, y, z}, 0, -1));
        }
      for (std::int64_t j = -1; j < std::int64_t(ny); ++j)
        for (std::int64_t i = 0; i < std::int64_t(nx); ++i) {
          const bool a = at(i, j), b = at(i, j + 1);
          const auto x = box.lo.x + i;
          if (a && !b) out.push_back(surfel_between({x, box.lo.y + j, z}, 1, +1));
          if (!a && b) out.push_back(surfel_between({x, box.lo.y + j + 1, z}, 1, -1));
        }
    }
    std::swap(prev, cur);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<Surfel> boundary_surfels(const BinaryVolume& volume) {
  return boundary_surfels([&](const Voxel& z) { return volume.at(z); }, volume.box);
}

Surfel find_boundary_surfel(const VoxelPredicate& inside, const VoxelBox& box, const Voxel& start) {
  check_voxel_box(box);
  if (!box.contains(start) || !inside(start))
    throw InvalidArgument("find_boundary_surfel: start voxel " + voxel_string(start) +
                          " is not inside the set");
  Voxel z = start;
  while (z.x < box.hi.x && inside(step(z, 0, 1))) ++z.x;
  return surfel_between(z, 0, +1);
}

Surfel adjacent_surfel(const VoxelPredicate& inside, const VoxelBox& box, const Surfel& s,
                       int tangent_axis, int sign, SurfelAdjacency adjacency) {
  const int a = orthogonal_axis(s);
  const int sigma = s.direct ? 1 : -1;
  const int tau = sign > 0 ? 1 : -1;
  auto in = [&](const Voxel& z) { return box.contains(z) && inside(z); };
  const Voxel I = inner_voxel(s);
  const Voxel I1 = step(I, tangent_axis, tau);
  const Voxel O1 = step(I1, a, sigma);
  const auto concave = [&] { return surfel_between(O1, tangent_axis, -tau); };
  const auto flat = [&] { return surfel_between(I1, a, sigma); };
  const auto convex = [&] { return surfel_between(I, tangent_axis, tau); };
  if (adjacency == SurfelAdjacency::interior) {
    if (in(O1)) return concave();
    return in(I1) ? flat() : convex();
  }
  if (!in(I1)) return convex();
  return in(O1) ? concave() : flat();
}

std::array<Surfel, 4> surfel_neighbours(const VoxelPredicate& inside, const VoxelBox& box,
                                        const Surfel& s, SurfelAdjacency adjacency) {
  const int a = orthogonal_axis(s), b = (a + 1) % 3, c = (a + 2) % 3;
  return {adjacent_surfel(inside, box, s, b, -1, adjacency),
          adjacent_surfel(inside, box, s, b, +1, adjacency),
          adjacent_surfel(inside, box, s, c, -1, adjacency),
          adjacent_surfel(inside, box, s, c, +1, adjacency)};
}

std::vector<Surfel> track_surface(const VoxelPredicate& inside, const VoxelBox& box,
                                  const Surfel& seed, SurfelAdjacency adjacency) {
  check_voxel_box(box);
  SurfelSet seen(box);
  std::vector<Surfel> order;
  track_into(inside, box, seed, adjacency, seen, order);
  return order;
}

std::vector<Surfel> line_boundary_surfels(const VoxelPredicate& inside, const VoxelBox& box,
                                          std::int64_t y, std::int64_t z) {
  check_voxel_box(box);
  std::vector<Surfel> out;
  if (y < box.lo.y || y > box.hi.y || z < box.lo.z || z > box.hi.z) return out;
  bool prev = false;
  for (auto x = box.lo.x; x <= box.hi.x + 1; ++x) {
    const bool cur = x <= box.hi.x && inside({x, y, z});
    if (prev && !cur) out.push_back(surfel_between({x - 1, y, z}, 0, +1));
    if (!prev && cur) out.push_back(surfel_between({x, y, z}, 0, -1));
    prev = cur;
  }
  return out;
}

std::vector<Surfel> track_surfaces(const VoxelPredicate& inside, const VoxelBox& box,
                                   std::span<const Surfel> seeds, SurfelAdjacency adjacency) {
  check_voxel_box(box);
  std::vector<Surfel> out;
  SurfelSet seen(box); // one set for all the surfaces: each surfel hashed once
  for (const Surfel& seed : seeds) {
    if (seen.contains(seed)) continue;
    track_into(inside, box, seed, adjacency, seen, out);
  }
  return out;
}

QuadSurface primal_surface(std::span<const Surfel> surfels) {
  QuadSurface q;
  std::unordered_map<KPoint, std::uint32_t, KPointHash> index;
  index.reserve(surfels.size() + 8);
  q.quads.reserve(surfels.size());
  std::unordered_set<std::uint64_t> edges;
  edges.reserve(2 * surfels.size() + 8);
  for (const Surfel& s : surfels) {
    std::array<std::uint32_t, 4> quad{};
    const auto p = surfel_pointels(s);
    for (std::size_t i = 0; i < 4; ++i) {
      auto [it, fresh] = index.try_emplace(p[i], std::uint32_t(q.vertices.size()));
      if (fresh) q.vertices.push_back(p[i]);
      quad[i] = it->second;
    }
    for (std::size_t i = 0; i < 4; ++i) {
      const auto u = quad[i], v = quad[(i + 1) % 4];
      edges.insert((std::uint64_t(std::min(u, v)) << 32) | std::max(u, v));
    }
    q.quads.push_back(quad);
  }
  q.edge_count = edges.size();
  return q;
}

std::int64_t euler_characteristic(const QuadSurface& surface) {
  return std::int64_t(surface.vertices.size()) - std::int64_t(surface.edge_count) +
         std::int64_t(surface.quads.size());
}

} // namespace zdg
