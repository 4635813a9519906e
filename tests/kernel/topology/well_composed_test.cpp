#include <zdg/kernel/topology/well_composed.hpp>

#include "tests/support/tower.hpp"
#include <zdg/arith/error.hpp>
#include <zdg/kernel/topology/connected_components.hpp>

#include <gtest/gtest.h>

#include <vector>

namespace zdg {
namespace {

Image<std::uint8_t> random_image(int dim, int max_extent) {
  std::vector<std::int64_t> ext;
  for (int k = 0; k < dim; ++k) ext.push_back(*rc::gen::inRange<std::int64_t>(1, max_extent + 1));
  Image<std::uint8_t> img{Domain(ext)};
  const int density = *rc::gen::inRange(0, 101);
  for (auto& v : img.values()) v = *rc::gen::inRange(0, 100) < density ? 1 : 0;
  return img;
}

// The definition, block by block through at(): C1 in every axis plane, C2 in every cube.
bool well_composed_by_definition(const Image<std::uint8_t>& img) {
  const Domain& d = img.domain();
  const int dim = d.dim();
  std::vector<std::int64_t> p(static_cast<std::size_t>(dim));
  auto get = [&](std::vector<std::int64_t> q) { return d.contains(q) && img.at(q) != 0; };
  for (std::int64_t i = 0; i < d.size(); ++i) {
    d.point(i, p);
    for (int a = 0; a < dim; ++a) {
      for (int b = a + 1; b < dim; ++b) {
        auto q = [&](int da, int db) {
          auto r = p;
          r[static_cast<std::size_t>(a)] += da;
          r[static_cast<std::size_t>(b)] += db;
          return get(r);
        };
        if (q(0, 0) == q(1, 1) && q(1, 0) == q(0, 1) && q(0, 0) != q(1, 0)) return false;
      }
    }
    if (dim == 3) {
      int count = 0;
      bool bits[8];
      for (int c = 0; c < 8; ++c) {
        auto r = p;
        for (int k = 0; k < 3; ++k) r[static_cast<std::size_t>(k)] += (c >> (2 - k)) & 1;
        bits[c] = get(r);
        count += bits[c];
      }
      for (int c = 0; c < 4; ++c) {
        if (count == 2 && bits[c] && bits[7 - c]) return false;
        if (count == 6 && !bits[c] && !bits[7 - c]) return false;
      }
    }
  }
  return true;
}

TEST(WellComposed, EqualsTheDefinition) {
  test::check_property([] {
    const int dim = *rc::gen::inRange(2, 4);
    const Image<std::uint8_t> img = random_image(dim, dim == 2 ? 9 : 5);
    const WellComposedness w = well_composedness(img);
    RC_ASSERT(w.well_composed == well_composed_by_definition(img));
    if (!w.well_composed) RC_ASSERT(w.corner.size() == static_cast<std::size_t>(dim));
  });
}

// Latecki, Eckhardt, Rosenfeld (CVIU 1995): in a well-composed 2D set the 4- and 8-components of
// the set, and of its complement, are the same; in 3D the 6- and 26-components.
TEST(WellComposed, ConnectivitiesAgreeOnWellComposedSets) {
  test::check_property([] {
    const int dim = *rc::gen::inRange(2, 4);
    const Image<std::uint8_t> img = random_image(dim, dim == 2 ? 9 : 5);
    RC_PRE(well_composedness(img).well_composed);
    const int lo = dim == 2 ? 4 : 6, hi = dim == 2 ? 8 : 26;
    for (Phase ph : {Phase::object, Phase::background}) {
      RC_ASSERT(count_components(img, lo, ph).components ==
                count_components(img, hi, ph).components);
    }
  });
}

TEST(WellComposed, WorkedExamples) {
  // The two diagonal pixels of a 2 x 2 block: C1.
  Image<std::uint8_t> diag(Domain({2, 2}), std::vector<std::uint8_t>{1, 0, 0, 1});
  const WellComposedness w = well_composedness(diag);
  EXPECT_FALSE(w.well_composed);
  EXPECT_EQ(w.corner, (std::vector<std::int64_t>{0, 0}));
  EXPECT_EQ(w.configuration, "C1 axes (0, 1)");
  // Two antipodal voxels of a 2 x 2 x 2 cube: C2 (no face holds a diagonal pair alone... each
  // face has one voxel or none).
  Image<std::uint8_t> anti(Domain({2, 2, 2}), std::vector<std::uint8_t>{1, 0, 0, 0, 0, 0, 0, 1});
  EXPECT_EQ(well_composedness(anti).configuration, "C2");
  // Its complement too.
  Image<std::uint8_t> co(Domain({2, 2, 2}), std::vector<std::uint8_t>{0, 1, 1, 1, 1, 1, 1, 0});
  EXPECT_EQ(well_composedness(co).configuration, "C2");
  // A full box is well-composed; a 1-D image is refused.
  EXPECT_TRUE(well_composedness(Image<std::uint8_t>(Domain({3, 4, 5}), 1)).well_composed);
  EXPECT_THROW(well_composedness(Image<std::uint8_t>(Domain({3}), 1)), InvalidArgument);
}

} // namespace
} // namespace zdg
