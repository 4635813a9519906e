#include <zdg/kernel/surfaces/pointel_cycles.hpp>

#include <zdg/arith/error.hpp>

#include <algorithm>

namespace zdg {

namespace {

// The boundary surfel of local face f at the pointel of Khalimsky point 0: the voxels of the
// block are {-1, 0}^3 (Khalimsky -1 and +1 along each axis).
Surfel local_surfel(int f, std::uint8_t config) {
  const int a = f / 4, b = (a + 1) % 3, c = (a + 2) % 3;
  KPoint k{0, 0, 0};
  coord(k, b) = (f & 1) ? 1 : -1;
  coord(k, c) = ((f >> 1) & 1) ? 1 : -1;
  const bool low_inside = ((config >> local_face_voxel(f, 0)) & 1) != 0;
  return {k, low_inside};
}

int face_of_local_surfel(const Surfel& s) {
  const int a = orthogonal_axis(s);
  if (coord(s.k, a) != 0) throw Error("pointel_star: a follower does not touch the pointel");
  return local_face(a, coord(s.k, (a + 1) % 3) > 0 ? 1 : 0, coord(s.k, (a + 2) % 3) > 0 ? 1 : 0);
}

PointelStar build_star(std::uint8_t config, SurfelAdjacency adjacency) {
  PointelStar st;
  st.next.fill(-1);
  st.cycle.fill(-1);
  st.owner.fill(-1);
  st.length.fill(0);
  const VoxelBox box{{-1, -1, -1}, {0, 0, 0}};
  const VoxelPredicate inside = [config](const Voxel& z) {
    const int b = int(z.x + 1) | int(z.y + 1) << 1 | int(z.z + 1) << 2;
    return ((config >> b) & 1) != 0;
  };
  for (int f = 0; f < 12; ++f) {
    const bool lo = ((config >> local_face_voxel(f, 0)) & 1) != 0;
    const bool hi = ((config >> local_face_voxel(f, 1)) & 1) != 0;
    if (lo == hi) continue;
    st.faces = static_cast<std::uint16_t>(st.faces | (1u << f));
    const Surfel s = local_surfel(f, config);
    const auto corners = surfel_pointels(s);
    const auto at = std::find(corners.begin(), corners.end(), KPoint{0, 0, 0}) - corners.begin();
    // The linel entering the pointel: from the previous corner to the pointel.
    const KPoint prev = corners[std::size_t((at + 3) % 4)];
    const KPoint linel{prev.x / 2, prev.y / 2, prev.z / 2};
    int t = 0;
    for (int ax = 0; ax < 3; ++ax)
      if (coord(linel, ax) != coord(s.k, ax)) t = ax;
    const int sign = coord(linel, t) > coord(s.k, t) ? 1 : -1;
    st.next[std::size_t(f)] = static_cast<std::int8_t>(
        face_of_local_surfel(adjacent_surfel(inside, box, s, t, sign, adjacency)));
  }
  for (int f = 0; f < 12; ++f) {
    if (!((st.faces >> f) & 1) || st.cycle[std::size_t(f)] >= 0) continue;
    int n = 0, g = f;
    do {
      st.cycle[std::size_t(g)] = static_cast<std::int8_t>(st.cycles);
      st.owner[std::size_t(g)] = static_cast<std::int8_t>(f);
      g = st.next[std::size_t(g)];
      ++n;
    } while (g != f && n <= 12);
    if (g != f) throw Error("pointel_star: the surfel adjacency is not a permutation");
    for (int h = 0; h < 12; ++h)
      if (st.cycle[std::size_t(h)] == st.cycles) st.length[std::size_t(h)] = std::int8_t(n);
    ++st.cycles;
  }
  // Joined linels: four boundary faces around the linel, all on one cycle.
  for (int f = 0; f < 12; ++f) {
    if (!((st.faces >> f) & 1)) continue;
    const Surfel s = local_surfel(f, config);
    const auto corners = surfel_pointels(s);
    const auto at = std::find(corners.begin(), corners.end(), KPoint{0, 0, 0}) - corners.begin();
    for (int side = 0; side < 2; ++side) {
      const KPoint other = corners[std::size_t((at + (side == 0 ? 3 : 1)) % 4)];
      const KPoint linel{other.x / 2, other.y / 2, other.z / 2};
      int around = 0;
      bool one_cycle = true;
      for (int g = 0; g < 12; ++g) {
        if (!((st.faces >> g) & 1)) continue;
        const auto ls = surfel_linels(local_surfel(g, config));
        if (std::find(ls.begin(), ls.end(), linel) == ls.end()) continue;
        ++around;
        one_cycle = one_cycle && st.cycle[std::size_t(g)] == st.cycle[std::size_t(f)];
      }
      (side == 0 ? st.entering_joined : st.leaving_joined)[std::size_t(f)] =
          around == 4 && one_cycle;
    }
  }
  return st;
}

struct StarTables {
  std::array<PointelStar, 256> interior, exterior;
  StarTables() {
    for (int c = 0; c < 256; ++c) {
      interior[std::size_t(c)] = build_star(std::uint8_t(c), SurfelAdjacency::interior);
      exterior[std::size_t(c)] = build_star(std::uint8_t(c), SurfelAdjacency::exterior);
    }
  }
};

} // namespace

const PointelStar* pointel_stars(SurfelAdjacency adjacency) {
  static const StarTables tables;
  return adjacency == SurfelAdjacency::interior ? tables.interior.data() : tables.exterior.data();
}

const PointelStar& pointel_star(std::uint8_t configuration, SurfelAdjacency adjacency) {
  return pointel_stars(adjacency)[configuration];
}

} // namespace zdg
