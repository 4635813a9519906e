#include <zdg/kernel/surfaces/cubical_cells.hpp>

#include "tests/support/tower.hpp"

#include <gtest/gtest.h>

namespace {

using zdg::KPoint;
using zdg::Surfel;
using zdg::Voxel;

TEST(CubicalCells, DimensionsAndVoxelRoundTrip) {
  EXPECT_EQ(zdg::cell_dimension({1, 3, -5}), 3);
  EXPECT_EQ(zdg::cell_dimension({0, 3, -5}), 2);
  EXPECT_EQ(zdg::cell_dimension({0, -2, 7}), 1);
  EXPECT_EQ(zdg::cell_dimension({0, -2, 4}), 0);
  EXPECT_EQ(zdg::voxel_cell({-3, 0, 2}), (KPoint{-5, 1, 5}));
  EXPECT_EQ(zdg::cell_voxel({-5, 1, 5}), (Voxel{-3, 0, 2}));
}

TEST(CubicalCells, EmbeddingAtStepH) {
  // A voxel z embeds at h z, the pointel 2z at h (z - 1/2), a surfel at its face centre.
  const auto v = zdg::embed_cell(zdg::voxel_cell({2, -1, 0}), 0.5);
  EXPECT_DOUBLE_EQ(v.x, 1.0);
  EXPECT_DOUBLE_EQ(v.y, -0.5);
  EXPECT_DOUBLE_EQ(v.z, 0.0);
  const auto p = zdg::embed_cell({4, 0, -2}, 0.25);
  EXPECT_DOUBLE_EQ(p.x, 0.375);
  EXPECT_DOUBLE_EQ(p.y, -0.125);
  EXPECT_DOUBLE_EQ(p.z, -0.375);
  const Surfel s = zdg::surfel_between({1, 1, 1}, 1, -1);
  const auto c = zdg::surfel_centre(s, 2.0);
  EXPECT_DOUBLE_EQ(c.x, 2.0);
  EXPECT_DOUBLE_EQ(c.y, 1.0);
  EXPECT_DOUBLE_EQ(c.z, 2.0);
}

// The boundary surfel between z and z + sign e_a has inner voxel z, outer voxel z + sign e_a,
// elementary normal sign e_a, dimension 2; its linels have dimension 1 and its pointels 0,
// and the pointels turn counterclockwise around the outward normal.
TEST(CubicalCells, SurfelIncidenceAndOrientation) {
  zdg::test::check_property([] {
    const auto x = *rc::gen::inRange<std::int64_t>(-1000, 1000);
    const auto y = *rc::gen::inRange<std::int64_t>(-1000, 1000);
    const auto z = *rc::gen::inRange<std::int64_t>(-1000, 1000);
    const int a = *rc::gen::inRange(0, 3);
    const int sign = *rc::gen::element(-1, 1);
    const Voxel v{x, y, z};
    const Surfel s = zdg::surfel_between(v, a, sign);
    Voxel o = v;
    zdg::coord(o, a) += sign;
    RC_ASSERT(zdg::cell_dimension(s.k) == 2);
    RC_ASSERT(zdg::orthogonal_axis(s) == a);
    RC_ASSERT(zdg::inner_voxel(s) == v);
    RC_ASSERT(zdg::outer_voxel(s) == o);
    const auto n = zdg::trivial_normal(s);
    RC_ASSERT(n.x + n.y + n.z == sign);
    RC_ASSERT((a == 0 ? n.x : a == 1 ? n.y : n.z) == sign);
    for (const auto& l : zdg::surfel_linels(s)) RC_ASSERT(zdg::cell_dimension(l) == 1);
    const auto p = zdg::surfel_pointels(s);
    for (const auto& q : p) RC_ASSERT(zdg::cell_dimension(q) == 0);
    const auto d = [](const KPoint& u, const KPoint& w) {
      return KPoint{w.x - u.x, w.y - u.y, w.z - u.z};
    };
    const KPoint e1 = d(p[0], p[1]), e2 = d(p[1], p[2]);
    const KPoint cr{e1.y * e2.z - e1.z * e2.y, e1.z * e2.x - e1.x * e2.z,
                    e1.x * e2.y - e1.y * e2.x};
    RC_ASSERT(cr.x * n.x + cr.y * n.y + cr.z * n.z > 0);
  });
}

TEST(CubicalCells, BoxChecks) {
  const zdg::VoxelBox box{{-2, -3, 4}, {2, 3, 4}};
  EXPECT_TRUE(box.contains({-2, 3, 4}));
  EXPECT_FALSE(box.contains({-2, 3, 5}));
  EXPECT_NO_THROW(zdg::check_voxel_box(box));
  EXPECT_THROW(zdg::check_voxel_box({{0, 0, 1}, {0, 0, 0}}), zdg::InvalidArgument);
  EXPECT_THROW(zdg::check_voxel_box({{0, 0, 0}, {0, 0, std::int64_t{1} << 41}}),
               zdg::InvalidArgument);
}

} // namespace
