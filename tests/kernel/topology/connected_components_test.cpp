#include <zdg/kernel/topology/connected_components.hpp>

#include "tests/support/binary_images.hpp"
#include "tests/support/tower.hpp"
#include <zdg/arith/error.hpp>
#include <zdg/kernel/topology/adjacency.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <deque>

namespace zdg {
namespace {

// Oracle: breadth-first search from every unvisited point in C order, straight from the
// definition of k-adjacency (neighbour_offsets); components numbered in scan order.
struct BfsComponents {
  std::vector<std::int64_t> label; // 0 outside the set, 1.. in scan order
  std::vector<std::int64_t> sizes;
  std::vector<bool> border;
};

BfsComponents bfs_components(const Image<std::uint8_t>& img, int k, Phase phase) {
  const Domain& dom = img.domain();
  const int d = dom.dim();
  const auto offsets = neighbour_offsets(d, k);
  BfsComponents out;
  out.label.assign(static_cast<std::size_t>(dom.size()), 0);
  auto in_set = [&](std::int64_t i) { return (img[i] != 0) == (phase == Phase::object); };
  for (std::int64_t s = 0; s < dom.size(); ++s) {
    if (!in_set(s) || out.label[static_cast<std::size_t>(s)] != 0) continue;
    const auto c = static_cast<std::int64_t>(out.sizes.size()) + 1;
    out.sizes.push_back(0);
    out.border.push_back(false);
    std::deque<std::int64_t> queue{s};
    out.label[static_cast<std::size_t>(s)] = c;
    while (!queue.empty()) {
      const std::int64_t i = queue.front();
      queue.pop_front();
      ++out.sizes.back();
      const auto p = dom.point(i);
      for (int a = 0; a < d; ++a) {
        if (p[static_cast<std::size_t>(a)] == dom.lower(a) ||
            p[static_cast<std::size_t>(a)] == dom.upper(a)) {
          out.border.back() = true;
        }
      }
      for (const auto& o : offsets) {
        auto q = p;
        for (int a = 0; a < d; ++a)
          q[static_cast<std::size_t>(a)] += o[static_cast<std::size_t>(a)];
        if (!dom.contains(q)) continue;
        const std::int64_t j = dom.index(q);
        if (in_set(j) && out.label[static_cast<std::size_t>(j)] == 0) {
          out.label[static_cast<std::size_t>(j)] = c;
          queue.push_back(j);
        }
      }
    }
  }
  return out;
}

const int kAdjacencies[5][2] = {{2, 4}, {2, 8}, {3, 6}, {3, 18}, {3, 26}};

// The run-based union-find labels exactly the k-components of the definition (BFS oracle), in
// scan order, with their sizes and border flags, for every adjacency, phase and thread count.
TEST(ConnectedComponents, ScanOrderLabelsEqualBreadthFirstSearch) {
  test::check_property([] {
    const auto& adj = kAdjacencies[*rc::gen::inRange(0, 5)];
    const int dim = adj[0], k = adj[1];
    const auto img = test::random_binary_image(dim, dim == 2 ? 12 : 7);
    const Phase phase = *rc::gen::element(Phase::object, Phase::background);
    const unsigned threads = *rc::gen::inRange(1u, 5u);
    const auto oracle = bfs_components(img, k, phase);
    const auto got = connected_components(img, k, {phase, ComponentOrder::by_scan, threads});
    RC_ASSERT(got.labels.domain() == img.domain());
    for (std::int64_t i = 0; i < img.size(); ++i) {
      RC_ASSERT(static_cast<std::int64_t>(got.labels[i]) ==
                oracle.label[static_cast<std::size_t>(i)]);
    }
    RC_ASSERT(got.sizes == oracle.sizes);
    RC_ASSERT(got.touches_border == oracle.border);
    const auto count = count_components(img, k, phase, threads);
    RC_ASSERT(count.components == got.count());
    RC_ASSERT(count.bounded == static_cast<std::int64_t>(
                                   std::count(oracle.border.begin(), oracle.border.end(), false)));
  });
}

// Ranking by size: the same partition, labels 1..C by non-increasing size, ties in scan order.
TEST(ConnectedComponents, SizeOrderIsAStablePermutationOfScanOrder) {
  test::check_property([] {
    const auto& adj = kAdjacencies[*rc::gen::inRange(0, 5)];
    const auto img = test::random_binary_image(adj[0], adj[0] == 2 ? 12 : 7);
    const auto scan =
        connected_components(img, adj[1], {Phase::object, ComponentOrder::by_scan, 1});
    const auto size =
        connected_components(img, adj[1], {Phase::object, ComponentOrder::by_size, 2});
    RC_ASSERT(scan.count() == size.count());
    // A bijection between the labelings, and the first point of each component decides ties.
    std::vector<std::int64_t> to_size(static_cast<std::size_t>(scan.count()) + 1, -1);
    for (std::int64_t i = 0; i < img.size(); ++i) {
      const auto a = scan.labels[i], b = size.labels[i];
      RC_ASSERT((a == 0) == (b == 0));
      if (a == 0) continue;
      if (to_size[a] < 0) to_size[a] = b;
      RC_ASSERT(to_size[a] == static_cast<std::int64_t>(b));
    }
    for (std::int64_t c = 1; c < size.count(); ++c) {
      RC_ASSERT(size.sizes[static_cast<std::size_t>(c - 1)] >=
                size.sizes[static_cast<std::size_t>(c)]);
    }
    for (std::int64_t a = 1; a <= scan.count(); ++a) {
      const auto b = to_size[static_cast<std::size_t>(a)];
      RC_ASSERT(size.sizes[static_cast<std::size_t>(b - 1)] ==
                scan.sizes[static_cast<std::size_t>(a - 1)]);
      for (std::int64_t a2 = a + 1; a2 <= scan.count(); ++a2) {
        const auto b2 = to_size[static_cast<std::size_t>(a2)];
        if (scan.sizes[static_cast<std::size_t>(a - 1)] ==
            scan.sizes[static_cast<std::size_t>(a2 - 1)]) {
          RC_ASSERT(b < b2);
        }
      }
    }
  });
}

TEST(ConnectedComponents, WorkedExamples2D) {
  // Two diagonal pixels: one 8-component, two 4-components; the background around a
  // 4-connected ring of 8 pixels has one hole under 4-adjacency.
  Image<std::uint8_t> diag(Domain({2, 2}), std::vector<std::uint8_t>{1, 0, 0, 1});
  EXPECT_EQ(count_components(diag, 8).components, 1);
  EXPECT_EQ(count_components(diag, 4).components, 2);
  Image<std::uint8_t> ring(Domain({5, 5}), std::uint8_t{0});
  for (std::int64_t i = 0; i < 25; ++i) {
    const auto y = i / 5, x = i % 5;
    ring[i] = (y >= 1 && y <= 3 && x >= 1 && x <= 3 && !(x == 2 && y == 2)) ? 1 : 0;
  }
  EXPECT_EQ(count_components(ring, 4, Phase::background).components, 2);
  EXPECT_EQ(count_components(ring, 4, Phase::background).bounded, 1);
  const auto c = connected_components(ring, 4, {Phase::background});
  EXPECT_EQ(c.sizes, (std::vector<std::int64_t>{16, 1}));
  EXPECT_EQ(c.touches_border, (std::vector<bool>{true, false}));
  EXPECT_EQ(c.labels[12], 2u);
}

TEST(ConnectedComponents, WorkedExamples3D) {
  // Corner-sharing voxels: 26-adjacent only; edge-sharing: 18; face-sharing: 6.
  Image<std::uint8_t> corner(Domain({2, 2, 2}), std::uint8_t{0});
  corner[0] = corner[7] = 1;
  EXPECT_EQ(count_components(corner, 26).components, 1);
  EXPECT_EQ(count_components(corner, 18).components, 2);
  Image<std::uint8_t> edge(Domain({2, 2, 2}), std::uint8_t{0});
  edge[0] = edge[3] = 1;
  EXPECT_EQ(count_components(edge, 18).components, 1);
  EXPECT_EQ(count_components(edge, 6).components, 2);
  // A hollow cube: the cavity is one bounded background component.
  Image<std::uint8_t> hollow(Domain({3, 3, 3}), std::uint8_t{1});
  hollow[13] = 0;
  EXPECT_EQ(count_components(hollow, 6, Phase::background).bounded, 1);
  EXPECT_EQ(count_components(hollow, 26, Phase::background).bounded, 1);
  const auto none = count_components(Image<std::uint8_t>(Domain({3, 4, 5}), std::uint8_t{0}), 26);
  EXPECT_EQ(none.components, 0);
}

TEST(ConnectedComponents, ThreadCountDoesNotChangeTheResultOnALargerImage) {
  // A ball of 6-separated shells, 40^3, labelled with 1, 2, 3 and 7 threads.
  const auto img = test::image_from({40, 41, 42}, [](const std::vector<std::int64_t>& c) {
    const auto s = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
    return (s / 97) % 3 != 0 || (c[0] + c[1]) % 13 == 0;
  });
  const auto ref = connected_components(img, 6, {Phase::object, ComponentOrder::by_size, 1});
  for (unsigned t : {2u, 3u, 7u}) {
    const auto got = connected_components(img, 6, {Phase::object, ComponentOrder::by_size, t});
    EXPECT_EQ(got.labels, ref.labels);
    EXPECT_EQ(got.sizes, ref.sizes);
  }
  EXPECT_GT(ref.count(), 1);
}

TEST(ConnectedComponents, RefusesOtherDimensionsAndAdjacencies) {
  Image<std::uint8_t> line(Domain({5}), std::uint8_t{1});
  EXPECT_THROW(connected_components(line, 2), InvalidArgument);
  Image<std::uint8_t> flat(Domain({3, 3}), std::uint8_t{1});
  EXPECT_THROW(connected_components(flat, 6), InvalidArgument);
  Image<std::uint8_t> cube(Domain({3, 3, 3}), std::uint8_t{1});
  EXPECT_THROW(count_components(cube, 8), InvalidArgument);
}

} // namespace
} // namespace zdg
