#include <zdg/kernel/surfaces/pointel_cycles.hpp>

#include <zdg/kernel/surfaces/image_surfels.hpp>

#include "tests/support/binary_images.hpp"
#include "tests/support/tower.hpp"
#include "tests/support/volumes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace {

using zdg::PointelStar;
using zdg::SurfelAdjacency;

std::set<std::set<int>> cycle_sets(const PointelStar& st) {
  std::set<std::set<int>> out;
  for (int c = 0; c < st.cycles; ++c) {
    std::set<int> s;
    for (int f = 0; f < 12; ++f)
      if (st.cycle[std::size_t(f)] == c) s.insert(f);
    out.insert(s);
  }
  return out;
}

// Every boundary face at the pointel is in exactly one cycle; the faces of the table are the
// faces of the configuration; a cycle's owner is its smallest face and its length its size;
// cycles have at least three faces (a sheet turns around the pointel through >= 3 quads).
TEST(PointelCycles, StarsArePermutationsOfTheBoundaryFaces) {
  for (auto adj : {SurfelAdjacency::interior, SurfelAdjacency::exterior}) {
    for (int c = 0; c < 256; ++c) {
      const auto& st = zdg::pointel_star(std::uint8_t(c), adj);
      int faces = 0;
      for (int f = 0; f < 12; ++f) {
        const bool lo = (c >> zdg::local_face_voxel(f, 0)) & 1,
                   hi = (c >> zdg::local_face_voxel(f, 1)) & 1;
        ASSERT_EQ(((st.faces >> f) & 1) != 0, lo != hi);
        if (lo == hi) {
          EXPECT_EQ(st.next[std::size_t(f)], -1);
          continue;
        }
        ++faces;
        const int g = st.next[std::size_t(f)];
        ASSERT_GE(g, 0);
        EXPECT_NE(g, f);
        EXPECT_EQ(st.cycle[std::size_t(g)], st.cycle[std::size_t(f)]);
        EXPECT_EQ(st.owner[std::size_t(f)], st.owner[std::size_t(g)]);
        EXPECT_LE(st.owner[std::size_t(f)], f);
        EXPECT_GE(st.length[std::size_t(f)], 3);
      }
      int total = 0;
      for (const auto& s : cycle_sets(st)) total += int(s.size());
      EXPECT_EQ(total, faces);
    }
  }
}

// The interior adjacency of X is the exterior adjacency of its complement, with the
// orientation reversed: the same cycles, each run backwards.
TEST(PointelCycles, InteriorOfTheSetIsExteriorOfTheComplement) {
  for (int c = 0; c < 256; ++c) {
    const auto& a = zdg::pointel_star(std::uint8_t(c), SurfelAdjacency::interior);
    const auto& b = zdg::pointel_star(std::uint8_t(~c), SurfelAdjacency::exterior);
    ASSERT_EQ(cycle_sets(a), cycle_sets(b)) << "configuration " << c;
    for (int f = 0; f < 12; ++f) {
      if (a.next[std::size_t(f)] >= 0) {
        EXPECT_EQ(b.next[std::size_t(a.next[std::size_t(f)])], f);
      }
    }
  }
}

TEST(PointelCycles, WorkedConfigurations) {
  auto cycles = [](int c, SurfelAdjacency adj) {
    return zdg::pointel_star(std::uint8_t(c), adj).cycles;
  };
  for (auto adj : {SurfelAdjacency::interior, SurfelAdjacency::exterior}) {
    EXPECT_EQ(cycles(0x00, adj), 0);
    EXPECT_EQ(cycles(0xff, adj), 0);
    EXPECT_EQ(cycles(0x01, adj), 1); // one voxel: its three faces
    EXPECT_EQ(cycles(0x0f, adj), 1); // a half block: one flat sheet of four faces
    EXPECT_EQ(cycles(0x81, adj), 2); // opposite voxels: two sheets meeting at the pointel
    EXPECT_EQ(cycles(0x7e, adj), 2); // opposite holes
  }
  // Two voxels along a linel (local voxels 0 and 3): joined by interior, split by exterior.
  EXPECT_EQ(cycles(0x09, SurfelAdjacency::interior), 1);
  EXPECT_EQ(cycles(0x09, SurfelAdjacency::exterior), 2);
  // Checkerboard (0, 3, 5, 6): four separated voxels, or one sheet around four holes' voxels.
  EXPECT_EQ(cycles(0x69, SurfelAdjacency::exterior), 4);
  EXPECT_EQ(cycles(0x96, SurfelAdjacency::interior), 4);
  EXPECT_TRUE(zdg::is_opposite_pair(0x81));
  EXPECT_TRUE(zdg::is_opposite_pair(0x18));
  EXPECT_FALSE(zdg::is_opposite_pair(0x09));
}

// In an image: the corners of a surfel and the faces there name the surfel back, and the
// surfel met through the table is the bel-adjacency follower of kernel/surfaces/digital_surface.hpp
// through the linel entering that corner.
TEST(PointelCycles, TableFollowersAreTheDigitalSurfaceFollowers) {
  zdg::test::check_property([] {
    const auto v = *zdg::test::small_volume(4);
    const auto adj = *rc::gen::element(SurfelAdjacency::interior, SurfelAdjacency::exterior);
    const auto img = zdg::test::to_image(v, -1, 2, 0);
    const auto s = zdg::image_surfels(img, 1);
    const auto box = s.grid.box();
    auto inside = [&](const zdg::Voxel& z) {
      return box.contains(z) && v.at(int(z.x + 1), int(z.y - 2), int(z.z));
    };
    for (const auto code : s.codes) {
      const auto surfel = s.surfel_of(code);
      const auto pointels = zdg::surfel_pointels(surfel);
      for (int n = 0; n < 4; ++n) {
        // The inner voxel's grid indices by division (the oracle of for_each_surfel's walk).
        const std::int64_t u = zdg::code_voxel(code), nx = s.grid.nx, ny = s.grid.ny;
        const std::int64_t ix[3] = {u % nx, (u / nx) % ny, u / (nx * ny)};
        const auto k = zdg::surfel_corner(ix, code, n);
        const auto config =
            zdg::pointel_configuration(s.grid, img.values().data(), k.q[0], k.q[1], k.q[2]);
        const auto back = zdg::local_face_surfel(s.grid, k.q, k.face, config);
        RC_ASSERT(back.code == code && std::equal(ix, ix + 3, back.c));
        RC_ASSERT(back.row == ix[2] * ny + ix[1]);
        RC_ASSERT(zdg::corner_index(ix, code, k.q) == n);
        // The pointel in Khalimsky coordinates of Z^3.
        const zdg::KPoint p{2 * (k.q[0] + s.grid.lower.x), 2 * (k.q[1] + s.grid.lower.y),
                            2 * (k.q[2] + s.grid.lower.z)};
        RC_ASSERT(pointels[std::size_t(n)] == p);
        const auto prev = pointels[std::size_t((n + 3) % 4)];
        const zdg::KPoint linel{(prev.x + p.x) / 2, (prev.y + p.y) / 2, (prev.z + p.z) / 2};
        const auto ls = zdg::surfel_linels(surfel);
        const auto li = std::size_t(std::find(ls.begin(), ls.end(), linel) - ls.begin());
        RC_ASSERT(li < 4u);
        const auto follower = zdg::surfel_neighbours(inside, box, surfel, adj)[li];
        const auto& st = zdg::pointel_star(config, adj);
        const auto next =
            zdg::local_face_surfel(s.grid, k.q, st.next[std::size_t(k.face)], config).code;
        RC_ASSERT(s.surfel_of(next) == follower);
      }
    }
  });
}

} // namespace
