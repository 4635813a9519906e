#include <zdg/kernel/topology/adjacency.hpp>

#include <zdg/arith/error.hpp>

#include <gtest/gtest.h>

#include <cstdlib>

namespace zdg {
namespace {

// Definition: the k-neighbours of the origin are the points of {-1, 0, 1}^d minus the origin
// with l1 norm <= m(k); there are 4, 8 (2D) and 6, 18, 26 (3D) of them.
TEST(Adjacency, NeighbourCountsAndNorms) {
  const int cases[5][3] = {{2, 4, 1}, {2, 8, 2}, {3, 6, 1}, {3, 18, 2}, {3, 26, 3}};
  for (const auto& c : cases) {
    const auto offsets = neighbour_offsets(c[0], c[1]);
    EXPECT_EQ(static_cast<int>(offsets.size()), c[1]);
    EXPECT_EQ(adjacency_max_l1(c[0], c[1]), c[2]);
    for (const auto& o : offsets) {
      const int l1 = std::abs(o[0]) + std::abs(o[1]) + std::abs(o[2]);
      EXPECT_GE(l1, 1);
      EXPECT_LE(l1, c[2]);
      if (c[0] == 2) {
        EXPECT_EQ(o[2], 0);
      }
    }
    // Symmetric: q is a neighbour of p iff p is a neighbour of q.
    for (const auto& o : offsets) {
      bool found = false;
      for (const auto& p : offsets)
        found = found || (p[0] == -o[0] && p[1] == -o[1] && p[2] == -o[2]);
      EXPECT_TRUE(found);
    }
  }
}

TEST(Adjacency, AdmissiblePairsAndTheirComplements) {
  const int pairs2[2][2] = {{8, 4}, {4, 8}};
  const int pairs3[4][2] = {{26, 6}, {6, 26}, {18, 6}, {6, 18}};
  for (const auto& p : pairs2) {
    const auto a = make_adjacency_pair(2, p[0], p[1]);
    EXPECT_TRUE(is_adjacency_pair(2, a.complement().object, a.complement().background));
  }
  for (const auto& p : pairs3) {
    const auto a = make_adjacency_pair(3, p[0], p[1]);
    EXPECT_TRUE(is_adjacency_pair(3, a.complement().object, a.complement().background));
    EXPECT_EQ(parse_adjacency_pair(a.name(), 3), a);
  }
  // Everything else is refused.
  int admissible = 0;
  for (int dim = 1; dim <= 4; ++dim) {
    for (int k = 0; k <= 30; ++k) {
      for (int kb = 0; kb <= 30; ++kb) admissible += is_adjacency_pair(dim, k, kb) ? 1 : 0;
    }
  }
  EXPECT_EQ(admissible, 6);
  EXPECT_THROW(make_adjacency_pair(3, 26, 26), InvalidArgument);
  EXPECT_THROW(make_adjacency_pair(3, 18, 18), InvalidArgument);
  EXPECT_THROW(make_adjacency_pair(3, 26, 18), InvalidArgument);
  EXPECT_THROW(make_adjacency_pair(2, 4, 4), InvalidArgument);
  EXPECT_THROW(make_adjacency_pair(2, 26, 6), InvalidArgument);
  EXPECT_THROW(adjacency_max_l1(3, 8), InvalidArgument);
  EXPECT_THROW(neighbour_offsets(4, 8), InvalidArgument);
}

TEST(Adjacency, Parsing) {
  EXPECT_EQ(parse_adjacency_pair("26,6", 3), (AdjacencyPair{3, 26, 6}));
  EXPECT_EQ(parse_adjacency_pair(" 6 , 18 ", 3), (AdjacencyPair{3, 6, 18}));
  EXPECT_EQ(parse_adjacency_pair("4,8", 2), (AdjacencyPair{2, 4, 8}));
  EXPECT_EQ(default_adjacency_pair(2), (AdjacencyPair{2, 8, 4}));
  EXPECT_EQ(default_adjacency_pair(3), (AdjacencyPair{3, 26, 6}));
  for (const char* bad :
       {"", "26", "26,", ",6", "26;6", "26,6,6", "-26,6", "26,x", "0026,6", "8,4", "26,6 6"}) {
    EXPECT_THROW(parse_adjacency_pair(bad, 3), InvalidArgument) << bad;
  }
  EXPECT_THROW(parse_adjacency_pair("26,6", 2), InvalidArgument);
}

} // namespace
} // namespace zdg
