#include <zdg/kernel/topology/skeleton_graph.hpp>

#include "tests/support/binary_images.hpp"
#include "tests/support/tower.hpp"
#include <zdg/kernel/topology/betti_numbers.hpp>
#include <zdg/kernel/topology/critical_kernel_thinning.hpp>
#include <zdg/kernel/topology/homotopic_thinning.hpp>
#include <zdg/kernel/transforms/distance_transform.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace zdg {
namespace {

Image<std::uint8_t> curve_skeleton(const Image<std::uint8_t>& object, bool critical = false) {
  ThinningOptions opt;
  opt.skeleton = SkeletonKind::curve;
  opt.threads = 2;
  return critical ? critical_kernel_thinning(object, opt).skeleton
                  : homotopic_thinning(object, opt).skeleton;
}

std::int64_t b1(const Image<std::uint8_t>& set) {
  return betti_numbers(set, default_adjacency_pair(set.dim()), 1).b[1];
}

// What every graph satisfies: each point of S is in exactly one node or branch; the degrees
// count the branch ends (sum = 2 E); every branch is longer than 0 and at least one step per
// point; the radius profile follows the points.
void check_structure(const Image<std::uint8_t>& s, const SkeletonGraph& g,
                     const Image<std::int64_t>* r2) {
  std::multiset<std::int64_t> seen;
  std::int64_t degrees = 0;
  for (const auto& n : g.nodes) {
    RC_ASSERT(!n.points.empty());
    seen.insert(n.points.begin(), n.points.end());
    degrees += n.degree;
  }
  for (const auto& b : g.branches) {
    seen.insert(b.points.begin(), b.points.end());
    RC_ASSERT(b.length > 0.0);
    RC_ASSERT(b.length >= static_cast<double>(b.points.size()) + 1.0 - 1e-9);
    RC_ASSERT(b.from >= 0 && b.from < static_cast<std::int64_t>(g.nodes.size()));
    RC_ASSERT(b.to >= 0 && b.to < static_cast<std::int64_t>(g.nodes.size()));
    if (r2 != nullptr) {
      RC_ASSERT(b.squared_radii.size() == b.points.size());
      for (std::size_t k = 0; k < b.points.size(); ++k)
        RC_ASSERT(b.squared_radii[k] == (*r2)[b.points[k]]);
    }
  }
  RC_ASSERT(degrees == 2 * static_cast<std::int64_t>(g.branches.size()));
  std::multiset<std::int64_t> all;
  for (std::int64_t i = 0; i < s.size(); ++i) {
    if (s[i] != 0) all.insert(i);
  }
  RC_ASSERT(seen == all);
  RC_ASSERT(g.components == betti_numbers(s, default_adjacency_pair(s.dim()), 1).b[0]);
}

// Random unions of axis-parallel bars (a strut network) in 3D, thinned to curve skeletons: the
// loops of the graph (its cycle rank E - V + C) are b1 of the skeleton, which is b1 of the object
// (thinning keeps the topology).
TEST(SkeletonGraph, LoopsAreB1OfThinnedStrutNetworks) {
  test::check_property([] {
    const std::int64_t n = *rc::gen::inRange<std::int64_t>(6, 16);
    Image<std::uint8_t> obj(Domain({n, n, n}), std::uint8_t{0});
    const int bars = *rc::gen::inRange(1, 9);
    for (int k = 0; k < bars; ++k) {
      const int axis = *rc::gen::inRange(0, 3);
      const std::int64_t w = *rc::gen::inRange<std::int64_t>(1, 4);
      std::int64_t lo[3], hi[3];
      for (int c = 0; c < 3; ++c) {
        if (c == axis) {
          lo[c] = *rc::gen::inRange<std::int64_t>(1, n - 2);
          hi[c] = *rc::gen::inRange<std::int64_t>(lo[c], n - 1);
        } else {
          lo[c] = *rc::gen::inRange<std::int64_t>(1, n - w);
          hi[c] = lo[c] + w - 1;
        }
      }
      for (std::int64_t z = lo[0]; z <= hi[0]; ++z)
        for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
          for (std::int64_t x = lo[2]; x <= hi[2]; ++x) obj[(z * n + y) * n + x] = 1;
    }
    const bool critical = *rc::gen::arbitrary<bool>();
    const auto s = curve_skeleton(obj, critical);
    const auto dt = distance_transform<std::int64_t>(obj, {});
    const auto g = skeleton_graph(s, &dt);
    check_structure(s, g, &dt);
    RC_ASSERT(g.loops == b1(s));
    RC_ASSERT(g.loops == b1(obj));
  });
}

// The same on random 2D images (8-adjacency): loops = b1 of the thinned image.
TEST(SkeletonGraph, LoopsAreB1OfThinnedRandomImages2D) {
  test::check_property([] {
    const auto img = test::random_binary_image(2, 24);
    const auto s = curve_skeleton(img);
    const auto g = skeleton_graph(s);
    check_structure(s, g, nullptr);
    RC_ASSERT(g.loops == b1(s));
  });
}

// A solid torus (ring) thins to a closed curve (with short spurs where the curve thinning kept
// end points; critical kernels keep thicker parts): one loop, b1 of the skeleton.
TEST(SkeletonGraph, RingHasOneLoop) {
  for (bool critical : {false, true}) {
    const auto torus = test::torus_image(10, 3);
    const auto s = curve_skeleton(torus, critical);
    const auto g = skeleton_graph(s);
    EXPECT_EQ(g.loops, 1) << "critical " << critical;
    EXPECT_EQ(g.components, 1);
    EXPECT_EQ(b1(s), 1);
  }
  // The core circle itself (radius 10, one voxel thick, 4-connected steps removed): no node
  // but the loop's own, one branch around it.
  Image<std::uint8_t> ring(Domain({25, 25}), std::uint8_t{0});
  for (std::int64_t y = 0; y < 25; ++y) {
    for (std::int64_t x = 0; x < 25; ++x) {
      const std::int64_t q = (y - 12) * (y - 12) + (x - 12) * (x - 12);
      ring[y * 25 + x] = q >= 90 && q <= 110;
    }
  }
  const auto s = curve_skeleton(ring);
  const auto g = skeleton_graph(s);
  EXPECT_EQ(g.loops, 1);
  EXPECT_EQ(b1(s), 1);
  double length = 0;
  for (const auto& b : g.branches) length += b.length;
  // Between the circle's perimeter and 4/pi of it (8-connected steps).
  EXPECT_GT(length, 2 * 3.14159 * 10 * 0.9);
  EXPECT_LT(length, 2 * 3.14159 * 10 * 4 / 3.14159 * 1.1);
}

// A plus-shaped object (two crossing bars of 3 x 3 section): one junction of degree 4, four
// ends, four branches, no loop.
TEST(SkeletonGraph, PlusHasOneJunctionWithFourBranches) {
  const std::int64_t n = 25;
  Image<std::uint8_t> obj(Domain({7, n, n}), std::uint8_t{0});
  for (std::int64_t z = 2; z <= 4; ++z) {
    for (std::int64_t y = 2; y < n - 2; ++y) {
      for (std::int64_t x = 11; x <= 13; ++x) {
        obj[(z * n + y) * n + x] = 1;
        obj[(z * n + x) * n + y] = 1;
      }
    }
  }
  for (bool critical : {false, true}) {
    const auto s = curve_skeleton(obj, critical);
    const auto dt = distance_transform<std::int64_t>(obj, {});
    const auto g = skeleton_graph(s, &dt);
    std::int64_t junctions = 0, ends = 0;
    for (const auto& node : g.nodes) {
      if (node.kind == SkeletonNodeKind::junction) {
        ++junctions;
        EXPECT_EQ(node.degree, 4);
      }
      ends += node.kind == SkeletonNodeKind::end;
    }
    EXPECT_EQ(junctions, 1) << "critical " << critical;
    EXPECT_EQ(ends, 4);
    EXPECT_EQ(g.branches.size(), 4u);
    EXPECT_EQ(g.loops, 0);
    for (const auto& b : g.branches) {
      EXPECT_GT(b.length, 5.0);
      // Along the bars' core the squared distance to the background is 4 (3 x 3 section) but
      // near the ends and the crossing.
      std::int64_t fours = 0;
      for (auto r : b.squared_radii) fours += r == 4;
      EXPECT_GT(fours, 0);
    }
  }
}

// Worked example on a one-pixel plus built by hand (no thinning): the centre pixel and its four
// neighbours (each of those touches the centre and two others diagonally) form the junction,
// the arms are regular, their tips ends; each branch runs from the junction's point next to
// it to a tip: arms of 4 pixels beyond the centre give 2 regular points and length 3.
TEST(SkeletonGraph, HandBuiltPlus2D) {
  Image<std::uint8_t> s(Domain({11, 11}), std::uint8_t{0});
  for (std::int64_t t = 1; t <= 9; ++t) {
    s[5 * 11 + t] = 1;
    s[t * 11 + 5] = 1;
  }
  const auto g = skeleton_graph(s);
  ASSERT_EQ(g.nodes.size(), 5u);
  ASSERT_EQ(g.branches.size(), 4u);
  EXPECT_EQ(g.nodes[0].kind, SkeletonNodeKind::end); // (1, 5): first in C order
  std::int64_t junction = -1;
  for (std::size_t k = 0; k < g.nodes.size(); ++k) {
    if (g.nodes[k].kind == SkeletonNodeKind::junction) junction = static_cast<std::int64_t>(k);
  }
  ASSERT_GE(junction, 0);
  EXPECT_EQ(
      g.nodes[static_cast<std::size_t>(junction)].points,
      (std::vector<std::int64_t>{4 * 11 + 5, 5 * 11 + 4, 5 * 11 + 5, 5 * 11 + 6, 6 * 11 + 5}));
  EXPECT_EQ(g.nodes[static_cast<std::size_t>(junction)].degree, 4);
  for (const auto& b : g.branches) {
    EXPECT_TRUE(b.from == junction || b.to == junction);
    EXPECT_EQ(b.points.size(), 2u);
    EXPECT_DOUBLE_EQ(b.length, 3.0);
  }
  EXPECT_EQ(g.loops, 0);
}

// Hand-built: a figure eight of two diamonds sharing a point (2D): the shared point has four
// neighbours (a junction of degree 4), two branches from it to itself, two loops.
TEST(SkeletonGraph, FigureEightHasTwoLoops) {
  Image<std::uint8_t> s(Domain({7, 11}), std::uint8_t{0});
  auto set = [&](std::int64_t y, std::int64_t x) { s[y * 11 + x] = 1; };
  // Diamond |y - 3| + |x - 3| = 2, and |y - 3| + |x - 7| = 2; they share (3, 5).
  for (std::int64_t y = 0; y < 7; ++y) {
    for (std::int64_t x = 0; x < 11; ++x) {
      if (std::abs(y - 3) + std::abs(x - 3) == 2 || std::abs(y - 3) + std::abs(x - 7) == 2)
        set(y, x);
    }
  }
  const auto g = skeleton_graph(s);
  EXPECT_EQ(g.loops, 2);
  EXPECT_EQ(g.loops, b1(s));
  EXPECT_EQ(g.components, 1);
}

TEST(SkeletonGraph, RejectsOtherDimensionsAndDomains) {
  EXPECT_THROW(skeleton_graph(Image<std::uint8_t>(Domain({5}), std::uint8_t{1})), InvalidArgument);
  EXPECT_THROW(skeleton_graph(Image<std::uint8_t>(Domain({2, 2, 2, 2}), std::uint8_t{1})),
               InvalidArgument);
  const Image<std::uint8_t> s(Domain({3, 3}), std::uint8_t{1});
  const Image<std::int64_t> r(Domain({3, 4}), std::int64_t{0});
  EXPECT_THROW(skeleton_graph(s, &r), InvalidArgument);
}

} // namespace
} // namespace zdg
