// Digital convexity against its definition, cell by cell (Lachaud, JMIV 2022): X is fully convex
// when every cell whose closure meets Cvxh(X) has a vertex in X. The oracle decides "the closed
// cell c meets Cvxh(X)" as "the origin is in Cvxh(X - V(c))" (V(c): the vertices of c): in 2D by
// an angular test written here (the origin is outside iff the points lie in an open half-plane
// through it), in 3D from the facets of lattice_hull_3d (full-dimensional sets). It enumerates
// every cell near X; the library uses the morphological characterisation and column sweeps.
// Also: every subset of a 3x3 box, random subsets of 4x4 and 3x3x3 boxes; the theorems the
// papers state (full convexity implies H-convexity, (3^d - 1)-connectedness and connected axis
// slices; in 2D full convexity is segment convexity, Feschet-Lachaud JMIV 2025); the envelope
// (contains X, fully convex, idempotent, fixed exactly on fully convex sets); segments and
// triangles fully convex by construction; the same answers on every integer type and near 2^62.
#include <zdg/kernel/hulls/digital_convexity.hpp>
#include <zdg/kernel/hulls/lattice_hull_3d.hpp>

#include "tests/support/tower.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <set>
#include <vector>

namespace {

using namespace zdg;

template <int D>
using P = std::array<std::int64_t, D>;

template <int D, class I>
std::vector<std::array<I, D>> to_tower(const std::vector<P<D>>& v) {
  std::vector<std::array<I, D>> out;
  for (const auto& p : v) {
    std::array<I, D> q;
    for (int i = 0; i < D; ++i) q[i] = I(p[i]);
    out.push_back(q);
  }
  return out;
}

template <int D, class I>
P<D> to_int(const std::array<I, D>& p) {
  P<D> q;
  for (int i = 0; i < D; ++i) q[i] = int_cast<Int64>(p[i]).value();
  return q;
}

// --- the oracle ---------------------------------------------------------------------------

// 2D: is the origin in Cvxh(pts)? Outside iff some p has every q strictly left of it or on
// its ray (then the points lie in an open half-plane through the origin).
bool origin_in_hull_2d(const std::vector<P<2>>& pts) {
  for (const auto& p : pts) {
    if (p[0] == 0 && p[1] == 0) return true;
  }
  for (const auto& p : pts) {
    bool all = true;
    for (const auto& q : pts) {
      const std::int64_t c = p[0] * q[1] - p[1] * q[0];
      const std::int64_t d = p[0] * q[0] + p[1] * q[1];
      if (!(c > 0 || (c == 0 && d > 0))) {
        all = false;
        break;
      }
    }
    if (all) return false;
  }
  return true;
}

// 3D, full-dimensional pts: the origin satisfies every facet inequality.
bool origin_in_hull_3d(const std::vector<P<3>>& pts) {
  std::vector<Point3<Int64>> q;
  for (const auto& p : pts) q.push_back({Int64(p[0]), Int64(p[1]), Int64(p[2])});
  const auto h = lattice_hull_3d<Int64>(std::span<const Point3<Int64>>(q));
  EXPECT_EQ(h.dimension, 3);
  for (std::size_t i = 0; i < h.facets.size(); ++i) {
    if (dot(h.normals[i], h.vertices[h.facets[i][0]]) < 0) return false;
  }
  return true;
}

template <int D>
std::vector<P<D>> cell_vertices(const P<D>& lower, unsigned open) {
  std::vector<P<D>> v;
  for (unsigned u = 0; u < (1u << D); ++u) {
    if ((u & open) != u) continue;
    P<D> p = lower;
    for (int i = 0; i < D; ++i) p[i] += (u >> i) & 1u;
    v.push_back(p);
  }
  return v;
}

// Does the closed cell lower + [0,1]^open meet Cvxh(x)?
template <int D>
bool cell_meets_hull(const std::vector<P<D>>& x, const P<D>& lower, unsigned open) {
  std::vector<P<D>> diff;
  for (const auto& p : x) {
    for (const auto& v : cell_vertices<D>(lower, open)) {
      P<D> d;
      for (int i = 0; i < D; ++i) d[i] = p[i] - v[i];
      diff.push_back(d);
    }
  }
  if constexpr (D == 2) {
    return origin_in_hull_2d(diff);
  } else {
    return origin_in_hull_3d(diff);
  }
}

template <int D>
bool has_vertex_in(const std::set<P<D>>& x, const P<D>& lower, unsigned open) {
  for (const auto& v : cell_vertices<D>(lower, open)) {
    if (x.count(v)) return true;
  }
  return false;
}

// Every cell near x (lower corner in [min - 1, max] on each axis), with a callback.
template <int D, class F>
void for_each_cell_near(const std::vector<P<D>>& x, F&& f) {
  P<D> lo = x[0], hi = x[0];
  for (const auto& p : x) {
    for (int i = 0; i < D; ++i) {
      lo[i] = std::min(lo[i], p[i]);
      hi[i] = std::max(hi[i], p[i]);
    }
  }
  P<D> z;
  for (int i = 0; i < D; ++i) z[i] = lo[i] - 1;
  for (;;) {
    for (unsigned open = 0; open < (1u << D); ++open) f(z, open);
    int i = 0;
    while (i < D && ++z[i] > hi[i]) {
      z[i] = lo[i] - 1;
      ++i;
    }
    if (i == D) break;
  }
}

template <int D>
bool oracle_fully_convex(const std::vector<P<D>>& x) {
  const std::set<P<D>> s(x.begin(), x.end());
  bool ok = true;
  for_each_cell_near<D>(x, [&](const P<D>& z, unsigned open) {
    if (ok && cell_meets_hull<D>(x, z, open) && !has_vertex_in<D>(s, z, open)) ok = false;
  });
  return ok;
}

template <int D>
bool oracle_hull_convex(const std::vector<P<D>>& x) {
  const std::set<P<D>> s(x.begin(), x.end());
  bool ok = true;
  for_each_cell_near<D>(x, [&](const P<D>& z, unsigned open) {
    if (ok && open == 0 && !s.count(z) && cell_meets_hull<D>(x, z, 0)) ok = false;
  });
  return ok;
}

// (3^d - 1)-connectedness (8 in 2D, 26 in 3D).
template <int D>
bool connected(const std::vector<P<D>>& x) {
  const std::set<P<D>> s(x.begin(), x.end());
  std::set<P<D>> seen{*s.begin()};
  std::vector<P<D>> stack{*s.begin()};
  while (!stack.empty()) {
    const P<D> p = stack.back();
    stack.pop_back();
    for (const auto& q : s) {
      bool adj = true;
      for (int i = 0; i < D; ++i) adj = adj && q[i] - p[i] >= -1 && q[i] - p[i] <= 1;
      if (adj && seen.insert(q).second) stack.push_back(q);
    }
  }
  return seen.size() == s.size();
}

template <int D, class I>
bool fully_convex(const std::vector<P<D>>& x) {
  const auto t = to_tower<D, I>(x);
  return !full_convexity_witness<D, I>(std::span<const std::array<I, D>>(t));
}
template <int D, class I>
bool hull_convex(const std::vector<P<D>>& x) {
  const auto t = to_tower<D, I>(x);
  return !hull_convexity_witness<D, I>(std::span<const std::array<I, D>>(t));
}

// A library witness (when there is one) is a cell the definition rejects.
template <int D, class I>
bool witness_is_valid(const std::vector<P<D>>& x) {
  const auto t = to_tower<D, I>(x);
  const auto w = full_convexity_witness<D, I>(std::span<const std::array<I, D>>(t));
  if (!w) return true;
  const P<D> z = to_int<D, I>(w->lower);
  const std::set<P<D>> s(x.begin(), x.end());
  return cell_meets_hull<D>(x, z, w->open) && !has_vertex_in<D>(s, z, w->open);
}

template <int D>
std::vector<P<D>> subset_of_box(std::uint64_t bits, int side) {
  std::vector<P<D>> x;
  const int n = D == 2 ? side * side : side * side * side;
  for (int k = 0; k < n; ++k) {
    if (!((bits >> k) & 1u)) continue;
    P<D> p;
    int r = k;
    for (int i = 0; i < D; ++i) {
      p[i] = r % side;
      r /= side;
    }
    x.push_back(p);
  }
  return x;
}

// A subset of the box [0, side)^D: random bits (mostly not convex), or the envelope of one to
// three random points of the box (fully convex; it stays in the box), or that envelope less one
// of its points (near misses).
template <int D>
std::vector<P<D>> gen_subset(int side) {
  const int n = D == 2 ? side * side : side * side * side;
  const int kind = *rc::gen::inRange(0, 3);
  if (kind == 0)
    return subset_of_box<D>(*rc::gen::inRange<std::uint64_t>(1, std::uint64_t(1) << n), side);
  std::vector<std::array<Int64, D>> seeds;
  const int k = *rc::gen::inRange(1, 4);
  for (int j = 0; j < k; ++j) {
    std::array<Int64, D> p;
    for (int i = 0; i < D; ++i) p[i] = Int64(*rc::gen::inRange(0, side));
    seeds.push_back(p);
  }
  const auto env = fully_convex_envelope<D, Int64>(std::span<const std::array<Int64, D>>(seeds));
  std::vector<P<D>> x;
  for (const auto& p : env) x.push_back(to_int<D, Int64>(p));
  if (kind == 2 && x.size() > 1)
    x.erase(x.begin() +
            *rc::gen::inRange<std::ptrdiff_t>(0, static_cast<std::ptrdiff_t>(x.size())));
  return x;
}

// --- worked examples ---------------------------------------------------------------------

TEST(DigitalConvexity, WorkedExamples2d) {
  using I = Int64;
  // Two diagonal neighbours: fully convex (the open square has both as vertices), though not
  // 4-connected: in 2D full convexity is not "H-convex and 4-connected".
  EXPECT_TRUE((fully_convex<2, I>({{0, 0}, {1, 1}})));
  // {(0,0), (2,1)}: H-convex (no lattice point inside the segment) but the segment crosses the
  // vertical edge {1} x (0,1) at (1, 1/2), whose vertices (1,0), (1,1) are not in the set.
  const std::vector<P<2>> knight{{0, 0}, {2, 1}};
  EXPECT_TRUE((hull_convex<2, I>(knight)));
  EXPECT_FALSE((fully_convex<2, I>(knight)));
  const auto t = to_tower<2, I>(knight);
  const auto w = full_convexity_witness<2, I>(std::span<const std::array<I, 2>>(t));
  ASSERT_TRUE(w);
  EXPECT_EQ((to_int<2, I>(w->lower)), (P<2>{1, 0}));
  EXPECT_EQ(w->open, 2u);
  // Its envelope is the 4-connected (standard) digital segment.
  const auto seg = digital_segment<2, I>({I(0), I(0)}, {I(2), I(1)});
  EXPECT_EQ(seg, (to_tower<2, I>({{0, 0}, {1, 0}, {1, 1}, {2, 1}})));
  // A point missing from a square: not H-convex, the witness is that point.
  const std::vector<P<2>> holed{{0, 0}, {1, 0}, {2, 0}, {0, 1}, {2, 1}, {0, 2}, {1, 2}, {2, 2}};
  const auto th = to_tower<2, I>(holed);
  const auto wh = hull_convexity_witness<2, I>(std::span<const std::array<I, 2>>(th));
  ASSERT_TRUE(wh);
  EXPECT_EQ((to_int<2, I>(*wh)), (P<2>{1, 1}));
  const auto wf = full_convexity_witness<2, I>(std::span<const std::array<I, 2>>(th));
  ASSERT_TRUE(wf);
  EXPECT_EQ(wf->dimension(), 0);
}

TEST(DigitalConvexity, WorkedExamples3d) {
  using I = Int64;
  // The unit triangle of the plane x + y + z = 1, the unit cube: fully convex.
  EXPECT_TRUE((fully_convex<3, I>({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}})));
  EXPECT_TRUE((fully_convex<3, I>(subset_of_box<3>(0xffu, 2))));
  // {(0,0,0), (1,1,2)}: H-convex, but its midpoint (1/2, 1/2, 1) lies on the open square
  // (0,1) x (0,1) x {1}, whose vertices are not in the set.
  const std::vector<P<3>> x{{0, 0, 0}, {1, 1, 2}};
  EXPECT_TRUE((hull_convex<3, I>(x)));
  const auto t = to_tower<3, I>(x);
  const auto w = full_convexity_witness<3, I>(std::span<const std::array<I, 3>>(t));
  ASSERT_TRUE(w);
  EXPECT_EQ((to_int<3, I>(w->lower)), (P<3>{0, 0, 1}));
  EXPECT_EQ(w->open, 3u);
  // The digital segment is fully convex and holds both ends.
  const auto seg = digital_segment<3, I>({I(0), I(0), I(0)}, {I(1), I(1), I(2)});
  EXPECT_TRUE(
      (full_convexity_witness<3, I>(std::span<const std::array<I, 3>>(seg)) == std::nullopt));
  EXPECT_TRUE(std::binary_search(seg.begin(), seg.end(), t[0]));
  EXPECT_TRUE(std::binary_search(seg.begin(), seg.end(), t[1]));
}

// --- the definition, exhaustively and at random -------------------------------------------

TEST(DigitalConvexity, EverySubsetOf3x3BoxAgreesWithTheDefinition) {
  for (std::uint64_t bits = 1; bits < 512; ++bits) {
    const auto x = subset_of_box<2>(bits, 3);
    const bool full = oracle_fully_convex<2>(x), hull = oracle_hull_convex<2>(x);
    EXPECT_EQ((fully_convex<2, Int64>(x)), full) << "subset " << bits;
    EXPECT_EQ((hull_convex<2, Int64>(x)), hull) << "subset " << bits;
    EXPECT_TRUE((witness_is_valid<2, Int64>(x))) << "subset " << bits;
  }
}

// All 65536 subsets of the 4x4 box: among them the 40 that fail only at the 1-cells along x
// (X + U_x is the only dilation that is not H-convex, {(1,0), (0,2)} for one) and their
// transposes.
TEST(DigitalConvexity, EverySubsetOf4x4BoxAgreesWithTheDefinition) {
  int fully = 0;
  for (std::uint64_t bits = 1; bits < (1u << 16); ++bits) {
    const auto x = subset_of_box<2>(bits, 4);
    const bool full = fully_convex<2, Int64>(x);
    fully += full;
    EXPECT_EQ(full, oracle_fully_convex<2>(x)) << "subset " << bits;
    EXPECT_EQ((hull_convex<2, Int64>(x)), oracle_hull_convex<2>(x)) << "subset " << bits;
    EXPECT_TRUE((witness_is_valid<2, Int64>(x))) << "subset " << bits;
  }
  EXPECT_GT(fully, 0);
}

template <class I>
class DigitalConvexityTyped : public ::testing::Test {};
TYPED_TEST_SUITE(DigitalConvexityTyped, test::TowerTypes, test::TowerNames);

TYPED_TEST(DigitalConvexityTyped, RandomSubsetsOf4x4BoxAgreeWithTheDefinition) {
  using I = TypeParam;
  test::check_property([] {
    const auto x = gen_subset<2>(4);
    RC_ASSERT((fully_convex<2, I>(x)) == oracle_fully_convex<2>(x));
    RC_ASSERT((hull_convex<2, I>(x)) == oracle_hull_convex<2>(x));
    RC_ASSERT((witness_is_valid<2, I>(x)));
  });
}

TYPED_TEST(DigitalConvexityTyped, RandomSubsetsOf3x3x3BoxAgreeWithTheDefinition) {
  using I = TypeParam;
  test::check_property([] {
    const auto x = gen_subset<3>(3);
    std::vector<Point3<Int64>> q;
    for (const auto& p : x) q.push_back({Int64(p[0]), Int64(p[1]), Int64(p[2])});
    RC_PRE(lattice_hull_3d<Int64>(std::span<const Point3<Int64>>(q)).dimension == 3);
    RC_ASSERT((fully_convex<3, I>(x)) == oracle_fully_convex<3>(x));
    RC_ASSERT((hull_convex<3, I>(x)) == oracle_hull_convex<3>(x));
    RC_ASSERT((witness_is_valid<3, I>(x)));
  });
}

// X x {0} in Z^3 is fully convex iff X is in Z^2: the cells meeting the plane z = 0 in their
// closure are c x {0}, c x (-1,0), c x (0,1), with their vertices in X x {0} iff c has one in X.
TYPED_TEST(DigitalConvexityTyped, APlanarSetIsFullyConvexAsIn2d) {
  using I = TypeParam;
  test::check_property([] {
    const auto x = gen_subset<2>(4);
    const int axis = *rc::gen::inRange(0, 3);
    std::vector<P<3>> y;
    for (const auto& p : x) {
      P<3> q{0, 0, 0};
      q[(axis + 1) % 3] = p[0];
      q[(axis + 2) % 3] = p[1];
      y.push_back(q);
    }
    RC_ASSERT((fully_convex<3, I>(y)) == (fully_convex<2, I>(x)));
    RC_ASSERT((hull_convex<3, I>(y)) == (hull_convex<2, I>(x)));
  });
}

// --- theorems of the papers ----------------------------------------------------------------

// Lachaud 2022: a fully convex set is H-convex (0-convexity), (3^d - 1)-connected, and so are its
// slices by axis-parallel lines (2D) or planes (3D).
template <int D>
bool slices_connected(const std::vector<P<D>>& x) {
  for (int axis = 0; axis < D; ++axis) {
    std::set<std::int64_t> values;
    for (const auto& p : x) values.insert(p[axis]);
    for (auto v : values) {
      std::vector<P<D>> slice;
      for (const auto& p : x) {
        if (p[axis] == v) slice.push_back(p);
      }
      if (!connected<D>(slice)) return false;
    }
  }
  return true;
}

TYPED_TEST(DigitalConvexityTyped, FullyConvexImpliesHConvexConnectedWithConnectedSlices) {
  using I = TypeParam;
  test::check_property([] {
    const bool three = *rc::gen::arbitrary<bool>();
    if (three) {
      const auto x = gen_subset<3>(3);
      if (!fully_convex<3, I>(x)) return;
      RC_ASSERT((hull_convex<3, I>(x)));
      RC_ASSERT(connected<3>(x));
      RC_ASSERT(slices_connected<3>(x));
    } else {
      const auto x = gen_subset<2>(4);
      if (!fully_convex<2, I>(x)) return;
      RC_ASSERT((hull_convex<2, I>(x)));
      RC_ASSERT(connected<2>(x));
      RC_ASSERT(slices_connected<2>(x));
    }
  });
}

// Feschet, Lachaud (JMIV 2025): in dimension 2, X is fully convex iff for every a, b in X every
// cell whose closure meets the segment [a, b] has a vertex in X.
bool segment_convex_2d(const std::vector<P<2>>& x) {
  const std::set<P<2>> s(x.begin(), x.end());
  for (const auto& a : x) {
    for (const auto& b : x) {
      bool ok = true;
      const std::vector<P<2>> ab{a, b};
      for_each_cell_near<2>(ab, [&](const P<2>& z, unsigned open) {
        if (ok && cell_meets_hull<2>(ab, z, open) && !has_vertex_in<2>(s, z, open)) ok = false;
      });
      if (!ok) return false;
    }
  }
  return true;
}

TEST(DigitalConvexity, In2dFullConvexityIsSegmentConvexity) {
  for (std::uint64_t bits = 1; bits < 512; ++bits) {
    const auto x = subset_of_box<2>(bits, 3);
    EXPECT_EQ((fully_convex<2, Int64>(x)), segment_convex_2d(x)) << "subset " << bits;
  }
  test::check_property([] {
    const auto x = gen_subset<2>(4);
    RC_ASSERT((fully_convex<2, Int64>(x)) == segment_convex_2d(x));
  });
}

// --- the envelope ---------------------------------------------------------------------------

template <int D, class I>
void check_envelope(const std::vector<P<D>>& x) {
  const auto t = to_tower<D, I>(x);
  const std::span<const std::array<I, D>> sx(t);
  const auto env = fully_convex_envelope<D, I>(sx);
  const std::span<const std::array<I, D>> se(env);
  for (const auto& p : t) RC_ASSERT(std::binary_search(env.begin(), env.end(), p));
  RC_ASSERT((!full_convexity_witness<D, I>(se)));
  RC_ASSERT((fully_convex_envelope<D, I>(se) == env));
  RC_ASSERT((fully_convex_step<D, I>(se) == env));
  auto sorted = t;
  std::sort(sorted.begin(), sorted.end());
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  const bool fixed = fully_convex_step<D, I>(sx) == sorted;
  RC_ASSERT((fixed == !full_convexity_witness<D, I>(sx)));
  RC_ASSERT(((env == sorted) == !full_convexity_witness<D, I>(sx)));
}

TYPED_TEST(DigitalConvexityTyped, EnvelopeContainsXIsFullyConvexAndIdempotent) {
  using I = TypeParam;
  test::check_property([] {
    if (*rc::gen::arbitrary<bool>()) {
      check_envelope<2, I>(gen_subset<2>(4));
    } else {
      check_envelope<3, I>(gen_subset<3>(3));
    }
  });
}

TYPED_TEST(DigitalConvexityTyped, SegmentsAndTrianglesAreFullyConvexByConstruction) {
  using I = TypeParam;
  test::check_property([] {
    auto coord = [] { return *rc::gen::inRange<std::int64_t>(-6, 7); };
    if (*rc::gen::arbitrary<bool>()) {
      const std::array<I, 2> a{I(coord()), I(coord())}, b{I(coord()), I(coord())},
          c{I(coord()), I(coord())};
      for (const auto& s : {digital_segment<2, I>(a, b), digital_triangle<2, I>(a, b, c)}) {
        RC_ASSERT((!full_convexity_witness<2, I>(std::span<const std::array<I, 2>>(s))));
        RC_ASSERT(std::binary_search(s.begin(), s.end(), a));
        RC_ASSERT(std::binary_search(s.begin(), s.end(), b));
      }
    } else {
      const std::array<I, 3> a{I(coord()), I(coord()), I(coord())},
          b{I(coord()), I(coord()), I(coord())}, c{I(coord()), I(coord()), I(coord())};
      for (const auto& s : {digital_segment<3, I>(a, b), digital_triangle<3, I>(a, b, c)}) {
        RC_ASSERT((!full_convexity_witness<3, I>(std::span<const std::array<I, 3>>(s))));
        RC_ASSERT(std::binary_search(s.begin(), s.end(), a));
        RC_ASSERT(std::binary_search(s.begin(), s.end(), b));
      }
    }
  });
}

// --- exact by escalation -------------------------------------------------------------------

// Translating by a vector near 2^62 changes neither verdict; the witness moves with the set.
TEST(DigitalConvexity, TranslationNear2To62ByEscalation) {
  test::check_property([] {
    const bool three = *rc::gen::arbitrary<bool>();
    const int d = three ? 3 : 2;
    const auto bits = *rc::gen::inRange<std::uint64_t>(1, three ? (std::uint64_t(1) << 27)
                                                                : (std::uint64_t(1) << 16));
    std::vector<BigInt> small, far;
    const BigInt shift = (BigInt(1) << 62) - 3;
    auto push = [&](auto p) {
      for (int i = 0; i < d; ++i) {
        small.push_back(BigInt(p[i]));
        far.push_back(BigInt(p[i]) + shift * (i + 1));
      }
    };
    if (three) {
      for (const auto& p : subset_of_box<3>(bits, 3)) push(p);
    } else {
      for (const auto& p : subset_of_box<2>(bits, 4)) push(p);
    }
    for (auto def : {ConvexityDefinition::full, ConvexityDefinition::hull}) {
      const auto a = digital_convexity_exact(d, small, def);
      const auto b = digital_convexity_exact(d, far, def);
      RC_ASSERT(a.served == IntKind::int64);
      RC_ASSERT(a.value.convex == b.value.convex);
      RC_ASSERT(a.value.witness_dimension == b.value.witness_dimension);
      for (int i = 0; i < static_cast<int>(a.value.witness_khalimsky.size()); ++i)
        RC_ASSERT(b.value.witness_khalimsky[i] - a.value.witness_khalimsky[i] ==
                  2 * shift * (i + 1));
    }
    const auto ea = fully_convex_envelope_exact(d, small), eb = fully_convex_envelope_exact(d, far);
    RC_ASSERT(ea.value.coords.size() == eb.value.coords.size());
    for (std::size_t k = 0; k < ea.value.coords.size(); ++k)
      RC_ASSERT(eb.value.coords[k] - ea.value.coords[k] == shift * (int(k % d) + 1));
  });
}

// The hull test of {(0,0), (10^12, 1)} would sweep 10^12 columns: it stops at the limit; full
// convexity answers at once (the gap at x = 1: the cell {1} x (0,1) holds (1, 10^-12)).
TEST(DigitalConvexity, LongThinSetsStopAtTheLimitOrAnswerAtOnce) {
  const std::vector<BigInt> c{BigInt(0), BigInt(0), BigInt(1000000000000LL), BigInt(1)};
  EXPECT_THROW(digital_convexity_exact(2, c, ConvexityDefinition::hull, 1000), InvalidArgument);
  const auto r = digital_convexity_exact(2, c, ConvexityDefinition::full);
  EXPECT_FALSE(r.value.convex);
  EXPECT_EQ(r.value.witness_khalimsky, (std::vector<BigInt>{BigInt(2), BigInt(1)}));
  EXPECT_THROW(fully_convex_envelope_exact(2, c, 1000), InvalidArgument);
  EXPECT_THROW(digital_convexity_exact(4, c, ConvexityDefinition::full), InvalidArgument);
  EXPECT_THROW(digital_convexity_exact(3, c, ConvexityDefinition::full), InvalidArgument);
}

} // namespace
