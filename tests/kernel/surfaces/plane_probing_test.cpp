// Plane probing on standard planes, on every tower type:
// - exactness (JMIV 2017, Thm. 2 and 4): from the origin and the frame (e_x, e_y, e_z), the
//   H- and R-algorithms return the normal N of the standard plane 0 <= N.x < ||N||_1 exactly,
//   for random primitive N of every octant, the R-algorithm with a reduced basis;
// - invariants at the end: det(m_0, m_1, m_2) = 1 (the frame is unimodular), the base
//   triangle q - m_k is in the plane and the apex q is not;
// - step bound: each step lowers sum_k N.m_k (which starts at ||N||_1 and stays >= 3, every
//   N.m_k being a positive integer) by at least 1, so steps <= ||N||_1 - 3;
// - worked examples: normals of DGtal's plane-probing test suite (H: exact normal and a
//   non-reduced basis; R: exact normal and a reduced basis), two of them large;
// - bad input: a zero component, a non-primitive normal, too many steps.
// General form (probe_plane, any predicate, start and frame):
// - on the standard plane of a positive N from the origin and the unit frame it is
//   probe_standard_plane (every field equal), on every tower type;
// - from the reflected unit frame of N's octant it returns N exactly (JMIV 2017), keeps the
//   determinant and the invariant (base in, apex out);
// - on a digital half-space N . x < c, from an apex q on its first outside layer (N . q = c)
//   and the frame of N's octant, it returns N exactly (the run is a standard-plane run), for
//   random primitive N up to 10^6 (200 on Int64) and q up to 10^6; from a higher valid apex it
//   need not (a worked counterexample);
// - a start that is not a valid tetrahedron is refused.
#include <zdg/kernel/surfaces/plane_probing.hpp>

#include "tests/support/check_registry.hpp"
#include "tests/support/tower.hpp"

#include <array>
#include <chrono>
#include <numeric>

namespace {

using namespace zdg;

template <TowerInt I>
I det3(const Point3<I>& a, const Point3<I>& b, const Point3<I>& c) {
  return dot(a, cross(b, c));
}

template <TowerInt I>
void check_probe(const Point3<I>& n, ProbingAlgorithm alg) {
  auto r = probe_standard_plane<I>(n, alg);
  RC_ASSERT(r.normal == n);
  const I omega = abs(n.x) + abs(n.y) + abs(n.z);
  RC_ASSERT(I(static_cast<std::int64_t>(r.steps)) <= omega - I(3));
  if (alg == ProbingAlgorithm::r) RC_ASSERT(r.reduced_basis);
  auto in_plane = [&](const Point3<I>& x) {
    I h = dot(n, x);
    return I(0) <= h && h < omega;
  };
  for (const auto& m : r.frame) RC_ASSERT(in_plane(r.apex - m));
  RC_ASSERT(!in_plane(r.apex));
  // Unimodular up to the reflection of the octant.
  I d = det3(r.frame[0], r.frame[1], r.frame[2]);
  RC_ASSERT(abs(d) == I(1));
}

template <class I>
class PlaneProbingTest : public ::testing::Test {};
TYPED_TEST_SUITE(PlaneProbingTest, test::TowerTypes, test::TowerNames);

// Components up to a bound that the type surely serves (see the header's width note).
template <TowerInt I>
std::int64_t component_bound() {
  if constexpr (std::same_as<I, Int64>) {
    return 200;
  } else {
    return 1'000'000;
  }
}

// A random primitive normal of a random octant, its components on one scale (10, 1000 or
// bound) so that both skewed and balanced normals come.
template <TowerInt I>
Point3<I> random_primitive_normal(std::int64_t bound) {
  const std::int64_t scale = *rc::gen::element<std::int64_t>(10, 1000, bound);
  auto component = [&] {
    std::int64_t v = *rc::gen::inRange<std::int64_t>(1, scale + 1);
    return *rc::gen::arbitrary<bool>() ? -v : v;
  };
  std::int64_t a = component(), b = component(), c = component();
  std::int64_t g = std::gcd(std::gcd(a, b), c);
  return Point3<I>{I(a / g), I(b / g), I(c / g)};
}

TYPED_TEST(PlaneProbingTest, BothAlgorithmsReturnTheExactNormalOfEveryOctant) {
  using I = TypeParam;
  test::check_property([] {
    // One scale for the three components: R's step count grows with the skew of the
    // normal (about 10^6 steps for (1, 1, 10^6)), which is H's regime, not R's.
    const Point3<I> n = random_primitive_normal<I>(component_bound<I>());
    check_probe(n, ProbingAlgorithm::r);
    // H can take up to ||N||_1 steps: keep it to moderate normals.
    if (abs(n.x) + abs(n.y) + abs(n.z) <= I(3000)) {
      check_probe(n, ProbingAlgorithm::h);
    }
  });
}

TYPED_TEST(PlaneProbingTest, WorkedExamplesFromDGtalsTestSuite) {
  using I = TypeParam;
  const std::int64_t normals[][3] = {{1, 117, 148}, {1, 120, 25}, {1, 126, 77}, {1, 137, 29},
                                     {1, 157, 199}, {1, 199, 34}, {2, 6, 15}};
  for (const auto& v : normals) {
    const Point3<I> n{I(v[0]), I(v[1]), I(v[2])};
    auto h = probe_standard_plane<I>(n, ProbingAlgorithm::h);
    auto r = probe_standard_plane<I>(n, ProbingAlgorithm::r);
    EXPECT_EQ(h.normal, n);
    EXPECT_EQ(r.normal, n);
    EXPECT_TRUE(r.reduced_basis) << n;
    if (v[0] == 1) {
      EXPECT_FALSE(h.reduced_basis) << n; // DGtal's list: H ends non-reduced
    }
    EXPECT_LE(r.steps, h.steps) << n;
  }
}

TEST(PlaneProbing, LargeNormalsByEscalation) {
  // DGtal's two large examples, then normals past 2^64.
  for (const auto& v : {Point3<BigInt>{1, 59438, 82499}, Point3<BigInt>{2071, 8513, 6444}}) {
    auto h = probe_standard_plane_exact(v, ProbingAlgorithm::h);
    auto r = probe_standard_plane_exact(v, ProbingAlgorithm::r);
    EXPECT_EQ(h.value.normal, v);
    EXPECT_EQ(r.value.normal, v);
    EXPECT_FALSE(h.value.reduced_basis);
    EXPECT_TRUE(r.value.reduced_basis);
  }
  // A random primitive normal of 140-bit components (Python's random, seed 5).
  const Point3<BigInt> n{BigInt("1108421672374323185299812375476538325761094"),
                         BigInt("-908805694116326258062026452994543254052831"),
                         BigInt("649204429366996542705981200261544889122209")};
  ASSERT_EQ(gcd(gcd(n.x, n.y), n.z), BigInt(1));
  auto r = probe_standard_plane_exact(n, ProbingAlgorithm::r);
  EXPECT_EQ(r.served, IntKind::bigint);
  EXPECT_EQ(r.value.normal, n);
  EXPECT_TRUE(r.value.reduced_basis);
  EXPECT_EQ(
      probe_standard_plane_exact(Point3<Int64>{Int64(2), Int64(3), Int64(5)}, ProbingAlgorithm::h)
          .served,
      IntKind::int64);
}

TYPED_TEST(PlaneProbingTest, BadInputIsRefused) {
  using I = TypeParam;
  EXPECT_THROW(probe_standard_plane<I>({I(0), I(1), I(2)}, ProbingAlgorithm::r), InvalidArgument);
  EXPECT_THROW(probe_standard_plane<I>({I(2), I(4), I(6)}, ProbingAlgorithm::h), InvalidArgument);
  EXPECT_THROW(probe_standard_plane<I>({I(1), I(50), I(101)}, ProbingAlgorithm::h, 3),
               InvalidArgument);
}

// Issue #41: the step budget (default kPlaneProbingMaxSteps) is met within about a second,
// and the H-algorithm past its proven bound ||N||_1 - 3 is refused before any work.
TEST(PlaneProbing, StepBudgetAndProvenBound) {
  const Point3<BigInt> n{BigInt(1000000007), BigInt(1000000009), BigInt(3)};
  try {
    probe_standard_plane_exact(n, ProbingAlgorithm::h);
    FAIL() << "no refusal";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("||N||_1 - 3 = 2000000016 steps on this normal, more "
                                         "than max_steps 1000000"),
              std::string::npos)
        << e.what();
  }
  const auto t0 = std::chrono::steady_clock::now();
  try {
    probe_standard_plane_exact(n, ProbingAlgorithm::r);
    FAIL() << "no refusal";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("not ended after 1000000 steps (the proven bound for "
                                         "this normal is ||N||_1 - 3 = 2000000016 steps)"),
              std::string::npos)
        << e.what();
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_LT(seconds, 10.0); // about 1 s in a release build (80 s with the old default)
  // Under the bound both run: the budget is never what ends a run that the bound allows.
  const Point3<BigInt> small{BigInt(2), BigInt(6), BigInt(15)};
  EXPECT_EQ(probe_standard_plane_exact(small, ProbingAlgorithm::h, 20).value.normal, small);
  EXPECT_THROW(probe_standard_plane_exact(small, ProbingAlgorithm::h, 19), InvalidArgument);
}

template <TowerInt I>
std::array<Point3<I>, 3> octant_frame(const Point3<I>& n) {
  auto sg = [](const I& v) { return v < I(0) ? I(-1) : I(1); };
  return {Point3<I>{sg(n.x), I(0), I(0)}, Point3<I>{I(0), sg(n.y), I(0)},
          Point3<I>{I(0), I(0), sg(n.z)}};
}

TYPED_TEST(PlaneProbingTest, GeneralProbingOnTheStandardPlaneIsProbeStandardPlane) {
  using I = TypeParam;
  test::check_property([] {
    Point3<I> n = random_primitive_normal<I>(component_bound<I>());
    n = {abs(n.x), abs(n.y), abs(n.z)};
    const I omega = n.x + n.y + n.z;
    auto in_plane = [&](const Point3<I>& x) {
      I h = dot(n, x);
      return I(0) <= h && h < omega;
    };
    const std::array<Point3<I>, 3> unit = {Point3<I>{I(1), I(0), I(0)}, Point3<I>{I(0), I(1), I(0)},
                                           Point3<I>{I(0), I(0), I(1)}};
    for (auto alg : {ProbingAlgorithm::r, ProbingAlgorithm::h}) {
      if (alg == ProbingAlgorithm::h && omega > I(3000)) continue;
      const auto g = probe_plane<I>(in_plane, Point3<I>{I(0), I(0), I(0)}, unit, alg);
      const auto o = probe_standard_plane<I>(n, alg);
      RC_ASSERT(g.normal == o.normal);
      RC_ASSERT(g.frame == o.frame);
      RC_ASSERT(g.apex == o.apex);
      RC_ASSERT(g.steps == o.steps);
      RC_ASSERT(g.predicate_calls == o.predicate_calls);
      RC_ASSERT(g.reduced_basis == o.reduced_basis);
    }
  });
}

TYPED_TEST(PlaneProbingTest, ReflectedFramesReturnTheExactNormal) {
  using I = TypeParam;
  test::check_property([] {
    const Point3<I> n = random_primitive_normal<I>(component_bound<I>());
    const I omega = abs(n.x) + abs(n.y) + abs(n.z);
    auto in_plane = [&](const Point3<I>& x) {
      I h = dot(n, x);
      return I(0) <= h && h < omega;
    };
    const auto m = octant_frame(n);
    for (auto alg : {ProbingAlgorithm::r, ProbingAlgorithm::h}) {
      if (alg == ProbingAlgorithm::h && omega > I(3000)) continue;
      const auto r = probe_plane<I>(in_plane, Point3<I>{I(0), I(0), I(0)}, m, alg);
      RC_ASSERT(r.normal == n);
      RC_ASSERT(det3(r.frame[0], r.frame[1], r.frame[2]) == det3(m[0], m[1], m[2]));
      for (const auto& f : r.frame) RC_ASSERT(in_plane(r.apex - f));
      RC_ASSERT(!in_plane(r.apex));
      if (alg == ProbingAlgorithm::r) RC_ASSERT(r.reduced_basis);
    }
  });
}

TYPED_TEST(PlaneProbingTest, HalfSpacesFromTheFirstOutsideLayerReturnTheExactNormal) {
  using I = TypeParam;
  test::check_property([] {
    const Point3<I> n = random_primitive_normal<I>(component_bound<I>());
    const std::int64_t far = 1'000'000;
    const Point3<I> q{I(*rc::gen::inRange<std::int64_t>(-far, far)),
                      I(*rc::gen::inRange<std::int64_t>(-far, far)),
                      I(*rc::gen::inRange<std::int64_t>(-far, far))};
    const I c = dot(n, q);
    auto below = [&](const Point3<I>& x) { return dot(n, x) < c; };
    const I omega = abs(n.x) + abs(n.y) + abs(n.z);
    auto shell = [&](const Point3<I>& x) {
      const I v = dot(n, x);
      return c - omega <= v && v < c;
    };
    const auto m = octant_frame(n);
    const Point3<I> o = q - m[0] - m[1] - m[2];
    const auto r = probe_plane<I>(below, o, m, ProbingAlgorithm::r);
    RC_ASSERT(r.normal == n);
    RC_ASSERT(r.reduced_basis);
    const auto s = probe_plane<I>(shell, o, m, ProbingAlgorithm::r);
    RC_ASSERT(s.normal == n);
    RC_ASSERT(s.steps == r.steps);
    if (omega <= I(3000)) {
      RC_ASSERT(probe_plane<I>(below, o, m, ProbingAlgorithm::h).normal == n);
    }
  });
}

TYPED_TEST(PlaneProbingTest, AHigherApexNeedNotGiveTheNormal) {
  using I = TypeParam;
  const Point3<I> n{I(14), I(14), I(15)};
  const Point3<I> q{I(0), I(0), I(0)};
  auto below = [&](const Point3<I>& x) { return dot(n, x) < I(-1); }; // N . q = c + 1
  const auto m = octant_frame(n);
  const auto r = probe_plane<I>(below, q - m[0] - m[1] - m[2], m, ProbingAlgorithm::r);
  EXPECT_EQ(r.normal, (Point3<I>{I(1), I(1), I(1)}));
}

TYPED_TEST(PlaneProbingTest, InvalidStartsAreRefused) {
  using I = TypeParam;
  const Point3<I> n{I(2), I(3), I(5)};
  auto below = [&](const Point3<I>& x) { return dot(n, x) < I(0); };
  const Point3<I> z{I(0), I(0), I(0)};
  const std::array<Point3<I>, 3> unit = {Point3<I>{I(1), I(0), I(0)}, Point3<I>{I(0), I(1), I(0)},
                                         Point3<I>{I(0), I(0), I(1)}};
  const Point3<I> o = z - unit[0] - unit[1] - unit[2]; // apex 0: N . 0 = 0, outside
  EXPECT_EQ(probe_plane<I>(below, o, unit, ProbingAlgorithm::h).normal, n);
  // Not unimodular.
  auto twice = unit;
  twice[0] = Point3<I>{I(2), I(0), I(0)};
  EXPECT_THROW(probe_plane<I>(below, o, twice, ProbingAlgorithm::h), InvalidArgument);
  // Apex inside, base vertex outside.
  EXPECT_THROW(probe_plane<I>(below, o - unit[0], unit, ProbingAlgorithm::h), InvalidArgument);
  EXPECT_THROW(probe_plane<I>(below, o + unit[0], unit, ProbingAlgorithm::r), InvalidArgument);
}

// The registered property plane.probe.normal (zdg check): the exact normal within ||N||_1 - 3
// steps, both algorithms, every octant, starting on each integer type.
TYPED_TEST(PlaneProbingTest, RegisteredNormalPropertyHolds) {
  zdg::test::expect_registered_property("plane.probe.normal", zdg::int_kind<TypeParam>(), 200);
}

} // namespace
