#include <zdg/kernel/topology/homotopic_thinning.hpp>

#include "tests/support/binary_images.hpp"
#include "tests/support/check_registry.hpp"
#include "tests/support/thinning_checks.hpp"
#include "tests/support/tower.hpp"
#include <zdg/arith/error.hpp>
#include <zdg/kernel/topology/betti_numbers.hpp>
#include <zdg/kernel/transforms/reduced_medial_axis.hpp>

#include <gtest/gtest.h>

#include <bit>

namespace zdg {
namespace {

const AdjacencyPair kPairs[6] = {{3, 26, 6}, {3, 6, 26}, {3, 18, 6},
                                 {3, 6, 18}, {2, 8, 4},  {2, 4, 8}};
const SkeletonKind kKinds[4] = {SkeletonKind::ultimate, SkeletonKind::curve, SkeletonKind::surface,
                                SkeletonKind::medial_axis};

std::int64_t count(const Image<std::uint8_t>& img) {
  std::int64_t n = 0;
  for (auto v : img.values()) n += v != 0;
  return n;
}

// Theorems of homotopic thinning, on random small images, every pair and skeleton kind, with
// or without anchors and a random priority: the result is a subset of the object, anchors are
// kept, every deleted point was simple when deleted (replayed with the definition-level test),
// so object and background keep their Betti numbers (brute-force homology), and no deletable
// point remains (ultimate: no simple point outside the anchors).
TEST(HomotopicThinning, SubsetHomotopyEquivalentAndEveryDeletionSimple) {
  test::check_property([] {
    const auto pair = kPairs[*rc::gen::inRange(0, 6)];
    const auto kind = kKinds[*rc::gen::inRange(0, 4)];
    const auto img = test::random_binary_image(pair.dim, pair.dim == 3 ? 6 : 10);
    ThinningOptions opt;
    opt.pair = pair;
    opt.skeleton = kind;
    opt.threads = *rc::gen::inRange(1u, 4u);
    std::vector<std::int64_t> log;
    opt.deletions = &log;
    Image<std::uint8_t> anchors(img.domain(), std::uint8_t{0});
    if (*rc::gen::arbitrary<bool>()) {
      for (std::int64_t i = 0; i < img.size(); ++i) anchors[i] = *rc::gen::inRange(0, 10) == 0;
      opt.anchors = &anchors;
    }
    Image<std::int64_t> priority(img.domain(), std::int64_t{0});
    if (*rc::gen::arbitrary<bool>()) {
      for (std::int64_t i = 0; i < img.size(); ++i) priority[i] = *rc::gen::inRange(-3, 4);
      opt.priority = &priority;
    }
    const auto r = homotopic_thinning(img, opt);
    RC_ASSERT(r.deleted == static_cast<std::int64_t>(log.size()));
    test::check_subset_and_homotopy(img, r.skeleton, pair);
    test::check_deletions_were_simple(img, r.skeleton, pair, log);
    for (std::int64_t i = 0; i < img.size(); ++i) {
      if (opt.anchors != nullptr && anchors[i] != 0 && img[i] != 0) RC_ASSERT(r.skeleton[i] != 0);
    }
    if (kind == SkeletonKind::ultimate) {
      for (std::int64_t i = 0; i < img.size(); ++i) {
        if (r.skeleton[i] == 0 || (opt.anchors != nullptr && anchors[i] != 0)) continue;
        RC_ASSERT(!is_simple_by_definition(pair, neighbourhood_configuration(r.skeleton, i)));
      }
    }
    if (kind == SkeletonKind::curve) {
      for (std::int64_t i = 0; i < img.size(); ++i) {
        if (r.skeleton[i] == 0 || (opt.anchors != nullptr && anchors[i] != 0)) continue;
        const auto c = neighbourhood_configuration(r.skeleton, i);
        RC_ASSERT(!is_simple_by_definition(pair, c) || std::popcount(c) == 1);
      }
    }
    // Idempotent: thinning the result again deletes nothing (isthmus persistence makes the
    // surface kind a fixed point only given the isthmuses it anchored on the way).
    if (kind == SkeletonKind::ultimate || kind == SkeletonKind::curve) {
      const auto again = homotopic_thinning(r.skeleton, opt);
      RC_ASSERT(again.skeleton == r.skeleton);
    }
  });
}

// The medial-axis skeleton contains the reduced medial axis, so its medial balls rebuild the
// object.
TEST(HomotopicThinning, MedialAxisSkeletonKeepsTheMedialAxis) {
  test::check_property([] {
    const int dim = *rc::gen::inRange(2, 4);
    const auto img = test::random_binary_image(dim, dim == 3 ? 7 : 12);
    ThinningOptions opt;
    opt.skeleton = SkeletonKind::medial_axis;
    const auto r = homotopic_thinning(img, opt);
    // The axis of the image padded with background (the outside is background).
    std::vector<std::int64_t> ext, lower;
    for (int k = 0; k < dim; ++k) {
      ext.push_back(img.domain().extent(k) + 2);
      lower.push_back(-1);
    }
    Image<std::uint8_t> padded(Domain(ext, lower), std::uint8_t{0});
    for (std::int64_t i = 0; i < img.size(); ++i) padded.at(img.domain().point(i)) = img[i] != 0;
    for (const auto& b : reduced_medial_axis(padded)) {
      RC_ASSERT(r.skeleton.at(b.centre) != 0);
    }
  });
}

TEST(HomotopicThinning, BallThinsToOnePoint) {
  const auto ball = test::ball_image(9, 80);
  for (const auto& pair : kPairs) {
    if (pair.dim != 3) continue;
    ThinningOptions opt;
    opt.pair = pair;
    const auto r = homotopic_thinning(ball, opt);
    EXPECT_EQ(count(r.skeleton), 1) << pair.name();
    // The curve skeleton of a ball: a point, or a segment of two end points.
    opt.skeleton = SkeletonKind::curve;
    EXPECT_LE(count(homotopic_thinning(ball, opt).skeleton), 2) << pair.name();
  }
  const auto disc = test::annulus_image(12, -1, 120);
  for (const auto& pair : {AdjacencyPair{2, 8, 4}, AdjacencyPair{2, 4, 8}}) {
    ThinningOptions opt;
    opt.pair = pair;
    EXPECT_EQ(count(homotopic_thinning(disc, opt).skeleton), 1) << pair.name();
  }
}

// Malandain, Bertrand and Ayache's classification ("Topological segmentation of discrete
// surfaces", IJCV 10, 1993): a point of a closed curve has T = 2, T-bar = 1; a point of a closed
// surface has T = 1, T-bar = 2. Returns the number of points of the set that are not of the
// class (t, tbar).
std::int64_t points_not_of_class(const Image<std::uint8_t>& set, const AdjacencyPair& pair, int t,
                                 int tbar) {
  std::int64_t wrong = 0;
  for (std::int64_t i = 0; i < set.size(); ++i) {
    if (set[i] == 0) continue;
    const auto n = topological_numbers(pair, neighbourhood_configuration(set, i));
    wrong += (n.object != t || n.background != tbar) ? 1 : 0;
  }
  return wrong;
}

// A solid torus thins to a closed curve (Betti (1, 1, 0), every point a curve point), a hollow
// sphere to a closed surface (Betti (1, 0, 1), every point a surface point). The curve kind
// may keep short spurs (end points appear on the digital boundary) but no surface point; the
// surface kind keeps the closed surface and the few isthmuses it anchored on the way.
TEST(HomotopicThinning, TorusToClosedCurveAndSphereToClosedSurface) {
  const auto torus = test::torus_image(10, 3);
  const auto sphere = test::hollow_sphere_image(10, 30, 99);
  for (const auto& pair : kPairs) {
    if (pair.dim != 3) continue;
    ThinningOptions opt;
    opt.pair = pair;
    const auto c = homotopic_thinning(torus, opt).skeleton;
    EXPECT_EQ(betti_numbers(c, pair).b, (std::array<std::int64_t, 3>{1, 1, 0})) << pair.name();
    EXPECT_EQ(points_not_of_class(c, pair, 2, 1), 0) << pair.name() << " of " << count(c);
    const auto s = homotopic_thinning(sphere, opt).skeleton;
    EXPECT_EQ(betti_numbers(s, pair).b, (std::array<std::int64_t, 3>{1, 0, 1})) << pair.name();
    EXPECT_EQ(points_not_of_class(s, pair, 1, 2), 0) << pair.name() << " of " << count(s);

    opt.skeleton = SkeletonKind::curve;
    const auto cc = homotopic_thinning(torus, opt).skeleton;
    EXPECT_EQ(betti_numbers(cc, pair).b, (std::array<std::int64_t, 3>{1, 1, 0})) << pair.name();
    for (std::int64_t i = 0; i < cc.size(); ++i) {
      if (cc[i] == 0) continue;
      EXPECT_EQ(topological_numbers(pair, neighbourhood_configuration(cc, i)).background, 1);
    }
    EXPECT_LT(count(cc), 2 * count(c));
    opt.skeleton = SkeletonKind::surface;
    const auto ss = homotopic_thinning(sphere, opt).skeleton;
    EXPECT_EQ(betti_numbers(ss, pair).b, (std::array<std::int64_t, 3>{1, 0, 1})) << pair.name();
    EXPECT_LE(count(ss), count(s) + count(s) / 50) << pair.name();
  }
  const auto ring = test::annulus_image(12, 30, 120);
  for (const auto& pair : {AdjacencyPair{2, 8, 4}, AdjacencyPair{2, 4, 8}}) {
    ThinningOptions opt;
    opt.pair = pair;
    const auto c = homotopic_thinning(ring, opt).skeleton;
    EXPECT_EQ(betti_numbers(c, pair).b, (std::array<std::int64_t, 3>{1, 1, 0})) << pair.name();
    EXPECT_EQ(points_not_of_class(c, pair, 2, 2), 0) << pair.name() << " of " << count(c);
  }
}

// The curve skeleton of a box keeps its extremities: a 3 x 3 x 15 bar thins to a segment
// along its axis, end to end.
TEST(HomotopicThinning, CurveSkeletonOfABarIsItsAxis) {
  Image<std::uint8_t> bar(Domain({3, 3, 15}), std::uint8_t{1});
  ThinningOptions opt;
  opt.skeleton = SkeletonKind::curve;
  const auto r = homotopic_thinning(bar, opt).skeleton;
  EXPECT_GE(count(r), 13);
  EXPECT_EQ(betti_numbers(r, {3, 26, 6}).b, (std::array<std::int64_t, 3>{1, 0, 0}));
  opt.skeleton = SkeletonKind::ultimate;
  EXPECT_EQ(count(homotopic_thinning(bar, opt).skeleton), 1);
}

TEST(HomotopicThinning, ThreadCountDoesNotChangeTheResult) {
  const auto torus = test::torus_image(10, 3);
  ThinningOptions opt;
  opt.skeleton = SkeletonKind::curve;
  opt.threads = 1;
  const auto a = homotopic_thinning(torus, opt).skeleton;
  opt.threads = 3;
  EXPECT_EQ(homotopic_thinning(torus, opt).skeleton, a);
}

TEST(HomotopicThinning, RefusesBadInput) {
  Image<std::uint8_t> img(Domain({4, 4, 4}), std::uint8_t{1});
  ThinningOptions opt;
  opt.pair = {2, 8, 4};
  EXPECT_THROW(homotopic_thinning(img, opt), InvalidArgument);
  opt.pair = {3, 26, 26};
  EXPECT_THROW(homotopic_thinning(img, opt), InvalidArgument);
  opt.pair = {};
  Image<std::int64_t> priority(Domain({4, 4, 5}), std::int64_t{0});
  opt.priority = &priority;
  EXPECT_THROW(homotopic_thinning(img, opt), InvalidArgument);
  opt.priority = nullptr;
  Image<std::uint8_t> anchors(Domain({4, 4}), std::uint8_t{0});
  opt.anchors = &anchors;
  EXPECT_THROW(homotopic_thinning(img, opt), InvalidArgument);
  EXPECT_THROW(homotopic_thinning(Image<std::uint8_t>(Domain({4}), std::uint8_t{1})),
               InvalidArgument);
  EXPECT_THROW(parse_skeleton_kind("bones"), InvalidArgument);
  EXPECT_EQ(parse_skeleton_kind("medial-axis"), SkeletonKind::medial_axis);
}

} // namespace
// The registered property skeleton.homotopic (zdg check): Betti numbers kept (by the
// breadth-first and cell-counting oracles), no simple point left but curve end points.
TEST(HomotopicThinning, RegisteredHomotopyPropertyHolds) {
  test::expect_registered_property("skeleton.homotopic", IntKind::int64, 300);
}

} // namespace zdg
