// The operations of zdg surface / zdg contour on a user's object: their counts against the
// kernel's oracles and closed forms, the estimator registry, the progress reports, and the
// CSV / JSON forms. The front ends' agreement is in tests/cli/ and tests/python/.
#include <zdg/arith/error.hpp>
#include <zdg/kernel/topology/connected_components.hpp>
#include <zdg/operations/surface_operations.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>

namespace zdg {
namespace {

ObjectImage object(Image<std::uint8_t> mask) {
  ObjectImage im;
  const int d = mask.dim();
  im.spacing.assign(std::size_t(d), 1.0);
  im.origin.assign(std::size_t(d), 0.0);
  im.mask = std::move(mask);
  im.name = "test";
  return im;
}

// A ball of radius r (voxel centres), with a tunnel of side t along z when t > 0 (a torus).
Image<std::uint8_t> ball(int n, double r, int t = 0) {
  Image<std::uint8_t> m(Domain({n, n, n}));
  const double c = (n - 1) / 2.0;
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const double d2 = (x - c) * (x - c) + (y - c) * (y - c) + (z - c) * (z - c);
        const bool tunnel = t > 0 && std::abs(x - c) < t / 2.0 && std::abs(y - c) < t / 2.0;
        m[(std::int64_t(z) * n + y) * n + x] = d2 <= r * r && !tunnel ? 1 : 0;
      }
  return m;
}

Image<std::uint8_t> random_mask(std::vector<std::int64_t> ext) {
  Image<std::uint8_t> m{Domain(ext)};
  const auto bits =
      *rc::gen::container<std::vector<bool>>(std::size_t(m.size()), rc::gen::arbitrary<bool>());
  for (std::int64_t i = 0; i < m.size(); ++i) m[i] = bits[std::size_t(i)] ? 1 : 0;
  return m;
}

// Oracle: the kernel's components (by size) and the surfels' bookkeeping. Every voxel of the
// object is in one component; the components' surfels add up to the boundary's; the
// selected K-th component has the K-th largest size.
RC_GTEST_PROP(SurfaceOperation, ComponentsAddUpToTheObject, ()) {
  const auto mask = random_mask({4, 5, 6});
  const auto pair = *rc::gen::element(AdjacencyPair{3, 6, 26}, AdjacencyPair{3, 26, 6},
                                      AdjacencyPair{3, 6, 18}, AdjacencyPair{3, 18, 6});
  SurfaceOptions o;
  o.adjacency = pair;
  o.threads = 1;
  const auto r = surface_operation(object(mask), o);
  ComponentOptions copt;
  copt.order = ComponentOrder::by_size;
  const Components c = connected_components(mask, pair.object, copt);
  RC_ASSERT(r.object_components == c.count());
  std::int64_t voxels = 0, surfels = 0, surfaces = 0;
  for (const auto& k : r.components) {
    voxels += k.voxels;
    surfels += k.surfels;
    surfaces += k.surfaces;
  }
  RC_ASSERT(voxels == std::count(mask.values().begin(), mask.values().end(), 1));
  RC_ASSERT(surfels == r.surfels);
  RC_ASSERT(surfaces == r.surfaces);
  RC_ASSERT(r.betti == betti_numbers(mask, pair, 1));
  if (c.count() > 0) {
    o.component = *rc::gen::inRange<std::int64_t>(1, c.count() + 1);
    const auto s = surface_operation(object(mask), o);
    RC_ASSERT(s.components.size() == 1u);
    RC_ASSERT(s.components[0].voxels == c.sizes[std::size_t(o.component - 1)]);
    o.component = c.count() + 1;
    RC_ASSERT_THROWS_AS(surface_operation(object(mask), o), InvalidArgument);
  }
}

// Green's theorem on the contours: the signed areas of the contours (outer positive, holes
// negative) add up to the object's pixel count; b0 and b1 count the outer and hole contours.
RC_GTEST_PROP(ContourOperation, SignedAreasAddUpToThePixels, ()) {
  const auto mask =
      random_mask({*rc::gen::inRange<std::int64_t>(1, 9), *rc::gen::inRange<std::int64_t>(1, 9)});
  ContourOptions o;
  o.adjacency = *rc::gen::element(AdjacencyPair{2, 4, 8}, AdjacencyPair{2, 8, 4});
  o.threads = 1;
  const auto r = contour_operation(object(mask), o);
  std::int64_t area2 = 0, outer = 0, holes = 0;
  for (const auto& k : r.contours.contours) {
    const auto a = k.twice_signed_area();
    area2 += a;
    (a > 0 ? outer : holes) += 1;
  }
  RC_ASSERT(area2 == 2 * std::count(mask.values().begin(), mask.values().end(), 1));
  RC_ASSERT(outer == r.betti.b[0]);
  RC_ASSERT(holes == r.betti.b[1]);
}

// Closed forms: the boundary of a ball is a sphere (chi 2, genus 0; the solid ball has Betti
// numbers 1 0 0), a ball with a tunnel a torus (genus 1, b1 = 1); the integral-invariant mean
// curvature of a ball of radius 20 is close to 1/20 (kernel radius 8 voxels: within 20%).
TEST(SurfaceOperation, SphereAndTorus) {
  SurfaceOptions o;
  auto r = surface_operation(object(ball(32, 12)), o);
  EXPECT_EQ(r.betti.b, (std::array<std::int64_t, 3>{1, 0, 0}));
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_EQ(r.components[0].euler, 2);
  EXPECT_EQ(r.components[0].genus, 0);
  r = surface_operation(object(ball(32, 12, 6)), o);
  EXPECT_EQ(r.betti.b, (std::array<std::int64_t, 3>{1, 1, 0}));
  EXPECT_EQ(r.components[0].euler, 0);
  EXPECT_EQ(r.components[0].genus, 1);
  o.estimates = {"ii-mean"};
  o.radius = {8, true, ""};
  r = surface_operation(object(ball(48, 20)), o);
  double sum = 0;
  for (double m : r.estimates.mean) sum += m;
  EXPECT_NEAR(sum / double(r.estimates.mean.size()), 1.0 / 20, 0.01);
}

// Every estimator of the registry runs, appears in the JSON and adds its CSV columns; an
// unknown name is refused with the registry's list.
TEST(SurfaceOperation, EveryRegisteredEstimatorRuns) {
  const auto dir = std::filesystem::temp_directory_path() / "zdg_surface_operations_test";
  std::filesystem::create_directories(dir);
  for (const auto& e : surface_estimators()) {
    SurfaceOptions o;
    o.estimates = {e.name};
    o.radius = {3, true, ""};
    o.keep_surfels = true;
    o.mesh = SurfaceMesh::primal;
    if (e.name == "geodesic") o.source = GeodesicSource{0, {}};
    const auto r = surface_operation(object(ball(16, 5)), o);
    const auto j = to_json(r);
    EXPECT_TRUE(j["estimates"].contains(e.name)) << e.name;
    const auto csv = (dir / "s.csv").string();
    write_surface_csv(csv, r);
    std::ifstream f(csv);
    std::string header;
    std::getline(f, header);
    EXPECT_GT(std::count(header.begin(), header.end(), ','), 8) << e.name << ": " << header;
    EXPECT_EQ(r.mesh->face_count(), r.surfels);
    // The ii-normal and ii-directions are vectors: not mesh scalars; every other is.
    const bool scalar = e.name != "ii-normal" && e.name != "ii-directions";
    EXPECT_EQ(!r.mesh->face_scalars.empty(), scalar) << e.name;
  }
  std::filesystem::remove_all(dir);
  SurfaceOptions o;
  o.estimates = {"ii-bogus"};
  try {
    surface_operation(object(ball(8, 3)), o);
    FAIL() << "ii-bogus accepted";
  } catch (const InvalidArgument& err) {
    EXPECT_NE(std::string(err.what()).find(estimator_names(surface_estimators())),
              std::string::npos)
        << err.what();
  }
}

// The progress callback sees each step start then end, and the result records its seconds.
TEST(SurfaceOperation, ProgressReportsEveryStep) {
  std::vector<ProgressEvent> events;
  SurfaceOptions o;
  o.mesh = SurfaceMesh::marching_cubes;
  o.progress = [&](const ProgressEvent& e) { events.push_back(e); };
  const auto r = surface_operation(object(ball(12, 4)), o);
  ASSERT_EQ(events.size() % 2, 0u);
  for (std::size_t i = 0; i < events.size(); i += 2) {
    EXPECT_FALSE(events[i].done);
    EXPECT_TRUE(events[i + 1].done);
    EXPECT_EQ(events[i].what, events[i + 1].what);
    EXPECT_GE(events[i + 1].seconds, 0);
  }
  EXPECT_EQ(events.size(), 2 * r.seconds.size());
  for (const char* k : {"components", "betti", "surfels", "surfaces", "mesh"})
    EXPECT_EQ(r.seconds.count(k), 1u) << k;
}

// Estimates need square voxels unless a step is given; the radius is bounded by the image.
TEST(SurfaceOperation, EstimatesCheckTheirInput) {
  SurfaceOptions o;
  o.estimates = {"ii-mean"};
  auto im = object(ball(12, 4));
  im.spacing = {1, 1, 2};
  EXPECT_THROW(surface_operation(im, o), InvalidArgument);
  o.step = 1.0;
  EXPECT_NO_THROW(surface_operation(im, o));
  o.radius = {50, true, "50v"};
  EXPECT_THROW(surface_operation(object(ball(12, 4)), o), InvalidArgument);
  SurfaceOptions g;
  g.estimates = {"geodesic"};
  EXPECT_THROW(check_surface_options(g), InvalidArgument); // no source
  g.estimates.clear();
  g.source = GeodesicSource{0, {}};
  EXPECT_THROW(check_surface_options(g), InvalidArgument); // a source without geodesic
}

} // namespace
} // namespace zdg
