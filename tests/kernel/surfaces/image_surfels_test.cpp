#include <zdg/kernel/surfaces/image_surfels.hpp>

#include <zdg/kernel/surfaces/digital_surface.hpp>

#include "tests/support/binary_images.hpp"
#include "tests/support/tower.hpp"
#include "tests/support/volumes.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace {

using zdg::test::SmallVolume;

// Oracle: the (inside, outside) 6-neighbour pairs counted on the volume itself.
std::int64_t inside_outside_pairs(const SmallVolume& v) {
  std::int64_t n = 0;
  for (int z = 0; z < v.nz; ++z)
    for (int y = 0; y < v.ny; ++y)
      for (int x = 0; x < v.nx; ++x) {
        if (!v.at(x, y, z)) continue;
        n += !v.at(x - 1, y, z) + !v.at(x + 1, y, z) + !v.at(x, y - 1, z) + !v.at(x, y + 1, z) +
             !v.at(x, y, z - 1) + !v.at(x, y, z + 1);
      }
  return n;
}

TEST(ImageSurfels, CountIsTheNumberOfInsideOutsidePairs) {
  zdg::test::check_property([] {
    const SmallVolume v = *zdg::test::small_volume(6);
    const auto s = zdg::image_surfels(zdg::test::to_image(v), 1);
    RC_ASSERT(s.size() == inside_outside_pairs(v));
    RC_ASSERT(std::is_sorted(s.codes.begin(), s.codes.end()));
    RC_ASSERT(std::adjacent_find(s.codes.begin(), s.codes.end()) == s.codes.end());
    for (std::int64_t i = 0; i < s.size(); ++i) {
      const auto c = s.codes[std::size_t(i)];
      const auto z = s.grid.voxel(zdg::code_voxel(c));
      int o[3] = {0, 0, 0};
      o[zdg::code_axis(c)] = zdg::code_positive(c) ? 1 : -1;
      RC_ASSERT(v.at(int(z.x), int(z.y), int(z.z)));
      RC_ASSERT(!v.at(int(z.x) + o[0], int(z.y) + o[1], int(z.z) + o[2]));
      RC_ASSERT(s.find(c) == i);
    }
  });
}

TEST(ImageSurfels, SameSurfelsAsTheSliceScanOfDigitalSurface) {
  zdg::test::check_property([] {
    const SmallVolume v = *zdg::test::small_volume(5);
    const auto lx = *rc::gen::inRange(-3, 4), ly = *rc::gen::inRange(-3, 4),
               lz = *rc::gen::inRange(-3, 4);
    const auto img = zdg::test::to_image(v, lx, ly, lz);
    const auto s = zdg::image_surfels(img, 2);
    auto mine = s.surfels(2);
    std::sort(mine.begin(), mine.end());
    const zdg::VoxelBox box = s.grid.box();
    const auto theirs = zdg::boundary_surfels(
        [&](const zdg::Voxel& z) { return v.at(int(z.x - lx), int(z.y - ly), int(z.z - lz)); },
        box);
    RC_ASSERT(mine == theirs);
  });
}

// for_each_surfel walks the row index instead of dividing: the indices it hands out are
// those of the division, on any sub-range (a worker's chunk starts mid-row); find_in_row is
// find when the row is the code's, for the codes of surfels and for codes of none.
TEST(ImageSurfels, RowWalkAndRowSearchAgreeWithTheDivisions) {
  zdg::test::check_property([] {
    const SmallVolume v = *zdg::test::small_volume(6);
    const auto s = zdg::image_surfels(zdg::test::to_image(v, 3, -2, 1), 1);
    const auto n = s.size();
    const auto b = *rc::gen::inRange<std::int64_t>(0, n + 1);
    const auto e = *rc::gen::inRange<std::int64_t>(b, n + 1);
    std::int64_t next = b;
    zdg::for_each_surfel(s, b, e, [&](std::int64_t i, std::uint64_t code, const std::int64_t* c) {
      RC_ASSERT(i == next++);
      RC_ASSERT(code == s.codes[std::size_t(i)]);
      const std::int64_t u = zdg::code_voxel(code);
      RC_ASSERT(c[0] == u % s.grid.nx);
      RC_ASSERT(c[1] == (u / s.grid.nx) % s.grid.ny);
      RC_ASSERT(c[2] == u / (s.grid.nx * s.grid.ny));
    });
    RC_ASSERT(next == e);
    for (std::int64_t u = 0; u < s.grid.size(); ++u)
      for (int d = 0; d < 6; ++d) {
        const auto code = zdg::surfel_code(u, d / 2, (d & 1) != 0);
        RC_ASSERT(s.find_in_row(u / s.grid.nx, code) == s.find(code));
      }
  });
}

TEST(ImageSurfels, ThreadsDoNotChangeTheResult) {
  const auto img = zdg::test::ball_image(9, 60);
  const auto a = zdg::image_surfels(img, 1), b = zdg::image_surfels(img, 3);
  EXPECT_EQ(a.codes, b.codes);
  EXPECT_EQ(a.row_start, b.row_start);
}

TEST(ImageSurfels, WorkedExamples) {
  // One voxel: 6 surfels; a full 4 x 3 x 2 box: 2 (12 + 8 + 6) = 52; an empty one: none.
  SmallVolume one{1, 1, 1, {1}};
  EXPECT_EQ(zdg::image_surfels(zdg::test::to_image(one)).size(), 6);
  SmallVolume full{4, 3, 2, std::vector<std::uint8_t>(24, 1)};
  EXPECT_EQ(zdg::image_surfels(zdg::test::to_image(full)).size(), 52);
  SmallVolume empty{4, 3, 2, std::vector<std::uint8_t>(24, 0)};
  const auto e = zdg::image_surfels(zdg::test::to_image(empty));
  EXPECT_EQ(e.size(), 0);
  EXPECT_EQ(e.find(zdg::surfel_code(0, 0, true)), -1);
}

TEST(ImageSurfels, RefusesNon3DImages) {
  zdg::Image<std::uint8_t> flat(zdg::Domain({3, 3}));
  EXPECT_THROW(zdg::image_surfels(flat), zdg::InvalidArgument);
}

} // namespace

namespace {

// Theorem (the interfaces partition the boundaries): in a labelled image, for every label L
// other than the outside's, the interfaces holding L add up to the boundary surfels of
// {label == L}; every interface joins two different labels; and the interfaces add up to the
// axis-neighbour pairs (outside included) whose labels differ. Oracle for the first:
// image_surfels of the label's mask; for the last: the pairs counted on the padded volume.
TEST(LabelInterfaces, PartitionTheBoundariesOfEveryLabel) {
  zdg::test::check_property([] {
    const auto nx = *rc::gen::inRange(1, 6), ny = *rc::gen::inRange(1, 6),
               nz = *rc::gen::inRange(1, 6);
    const auto labels = *rc::gen::container<std::vector<std::int64_t>>(
        static_cast<std::size_t>(nx * ny * nz), rc::gen::inRange<std::int64_t>(0, 4));
    const auto outside = *rc::gen::inRange<std::int64_t>(0, 4);
    const zdg::Domain dom({nz, ny, nx}, {*rc::gen::inRange(-3, 3), 0, 0});
    const zdg::Image<std::int64_t> img(dom, labels);
    const auto interfaces = zdg::label_interfaces(img, outside);
    std::int64_t total = 0;
    for (const auto& f : interfaces) {
      RC_ASSERT(f.a < f.b);
      RC_ASSERT(f.surfels > 0);
      total += f.surfels;
    }
    RC_ASSERT(
        std::is_sorted(interfaces.begin(), interfaces.end(), [](const auto& x, const auto& y) {
          return std::pair{x.a, x.b} < std::pair{y.a, y.b};
        }));
    for (std::int64_t L = 0; L < 4; ++L) {
      if (L == outside) continue;
      zdg::Image<std::uint8_t> mask(dom);
      for (std::int64_t i = 0; i < dom.size(); ++i) mask[i] = img[i] == L ? 1 : 0;
      std::int64_t sum = 0;
      for (const auto& f : interfaces) {
        if (f.a == L || f.b == L) sum += f.surfels;
      }
      RC_ASSERT(sum == zdg::image_surfels(mask, 1).size());
    }
    // Padded: every axis-neighbour pair of the (n + 2)^3 box with different labels.
    auto at = [&](int x, int y, int z) {
      if (x < 0 || y < 0 || z < 0 || x >= nx || y >= ny || z >= nz) return outside;
      return labels[static_cast<std::size_t>((z * ny + y) * nx + x)];
    };
    std::int64_t pairs = 0;
    for (int z = -1; z <= nz; ++z)
      for (int y = -1; y <= ny; ++y)
        for (int x = -1; x <= nx; ++x) {
          pairs += (x < nx && at(x, y, z) != at(x + 1, y, z)) +
                   (y < ny && at(x, y, z) != at(x, y + 1, z)) +
                   (z < nz && at(x, y, z) != at(x, y, z + 1));
        }
    RC_ASSERT(total == pairs);
  });
}

TEST(LabelInterfaces, WorkedExample) {
  // 1 x 1 x 3: labels 1 2 2, outside 0: {0,1} 5 faces, {0,2} 9, {1,2} 1.
  const zdg::Image<std::int64_t> img(zdg::Domain({1, 1, 3}), std::vector<std::int64_t>{1, 2, 2});
  EXPECT_EQ(zdg::label_interfaces(img),
            (std::vector<zdg::LabelInterface>{{0, 1, 5}, {0, 2, 9}, {1, 2, 1}}));
  // 2D: a 1 x 2 row of labels 3 and 0 inside an outside of 0: {0, 3} 4 edges.
  const zdg::Image<std::int64_t> row(zdg::Domain({1, 2}), std::vector<std::int64_t>{3, 0});
  EXPECT_EQ(zdg::label_interfaces(row), (std::vector<zdg::LabelInterface>{{0, 3, 4}}));
}

} // namespace
