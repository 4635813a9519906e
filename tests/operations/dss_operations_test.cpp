// The DSS operations: the path rules (adjacency, connectivity, the repeated closing point),
// agreement with the kernel's cover, and the three front ends giving one JSON form.
#include <zdg/arith/error.hpp>
#include <zdg/operations/dss_operations.hpp>

#include "tests/support/cli.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <rapidcheck/gtest.h>

#include <fstream>

namespace zdg {
namespace {

std::vector<Point2<BigInt>> big(const std::vector<Point2<std::int64_t>>& pts) {
  std::vector<Point2<BigInt>> out;
  for (const auto& p : pts) out.push_back({BigInt(p.x), BigInt(p.y)});
  return out;
}

// A random 8-connected path (distinct consecutive points).
std::vector<Point2<std::int64_t>> random_path() {
  const auto steps = *rc::gen::container<std::vector<int>>(rc::gen::inRange(0, 8));
  static const int dx[] = {1, 1, 0, -1, -1, -1, 0, 1}, dy[] = {0, 1, 1, 1, 0, -1, -1, -1};
  std::vector<Point2<std::int64_t>> pts{{0, 0}};
  for (int s : steps) pts.push_back({pts.back().x + dx[s], pts.back().y + dy[s]});
  return pts;
}

// Oracle: the kernel's tangential cover of the same int64 path.
RC_GTEST_PROP(DssOperations, CoverIsTheKernelsCover, ()) {
  const auto pts = random_path();
  const auto r = dss_cover_operation({{big(pts), 0, {}}, false, false});
  RC_ASSERT(r.segments == maximal_segments_exact(pts, false, r.connectivity).value);
  const auto g = dss_cover_operation({{big(pts), 0, {}}, false, true});
  RC_ASSERT(g.segments == greedy_segmentation_exact(pts, false, r.connectivity).value);
}

TEST(DssOperations, PathRules) {
  // A closed square given with its first point repeated: the copy is dropped.
  const std::vector<Point2<std::int64_t>> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
  const auto r = dss_cover_operation({{big(square), 0, {}}, true, false});
  EXPECT_EQ(r.points, 4u);
  EXPECT_EQ(r.connectivity, Connectivity::four);
  // Not adjacent: the message names the point through `where`.
  DssPathOptions o{big({{0, 0}, {2, 0}}), 0,
                   [](std::size_t k) { return "f:" + std::to_string(k + 10); }};
  try {
    dss_recognize_operation(o);
    ADD_FAILURE() << "a gap was accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("f:11: point (2, 0)"), std::string::npos) << e.what();
  }
  EXPECT_THROW(dss_recognize_operation({big({{0, 0}, {1, 1}}), 4, {}}), InvalidArgument);
  EXPECT_THROW(dss_recognize_operation({{}, 0, {}}), InvalidArgument);
  EXPECT_THROW(dss_recognize_operation({big({{0, 0}}), 5, {}}), InvalidArgument);
  const std::vector<Point2<BigInt>> far{{BigInt(1) << 70, BigInt(0)},
                                        {(BigInt(1) << 70) + 1, BigInt(0)}};
  EXPECT_THROW(dss_cover_operation({{far, 0, {}}, false, false}), InvalidArgument);
  EXPECT_TRUE(dss_recognize_operation({far, 0, {}}).recognition.is_dss);
}

TEST(DssOperations, FrontEndsPrintTheOperationsJson) {
  const auto dir = test::scratch_dir("dss_ops");
  const std::vector<Point2<std::int64_t>> path{{0, 0}, {1, 0}, {2, 1}, {3, 1}, {4, 2},
                                               {5, 2}, {6, 2}, {7, 3}, {8, 5}};
  std::ofstream f(dir / "p.txt");
  std::string points = "[";
  for (const auto& p : path) {
    f << p.x << ' ' << p.y << '\n';
    points +=
        (points.size() > 1 ? ", [" : "[") + std::to_string(p.x) + ", " + std::to_string(p.y) + "]";
  }
  f.close();
  points += "]";
  // (8, 5) is not adjacent to (7, 3): refused by every front end.
  EXPECT_THROW(dss_recognize_operation({big(path), 0, {}}), InvalidArgument);
  auto r = test::run_zdg("dss recognize " + (dir / "p.txt").string() + " --json");
  EXPECT_EQ(r.status, 2) << r.out; // the last step is not adjacent
  std::vector<Point2<std::int64_t>> ok(path.begin(), path.end() - 1);
  std::ofstream g(dir / "q.txt");
  std::string qpoints = "[";
  for (const auto& p : ok) {
    g << p.x << ' ' << p.y << '\n';
    qpoints +=
        (qpoints.size() > 1 ? ", [" : "[") + std::to_string(p.x) + ", " + std::to_string(p.y) + "]";
  }
  g.close();
  qpoints += "]";
  const auto rq = to_json(dss_recognize_operation({big(ok), 0, {}}));
  r = test::run_zdg("dss recognize " + (dir / "q.txt").string() + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out), rq);
  r = test::run_zdg("serve 'dss recognize'", "{\"points\": " + qpoints + "}\n");
  EXPECT_EQ(nlohmann::json::parse(r.out), rq);
  const auto cover = to_json(dss_cover_operation({{big(ok), 0, {}}, false, false}));
  r = test::run_zdg("dss cover " + (dir / "q.txt").string() + " --json");
  EXPECT_EQ(nlohmann::json::parse(r.out), cover);
  r = test::run_zdg("serve 'dss cover'", "{\"points\": " + qpoints + "}\n");
  EXPECT_EQ(nlohmann::json::parse(r.out), cover);
  r = test::run_zdg("serve 'dss recognize'", "{\"points\": " + points + "}\n");
  EXPECT_NE(nlohmann::json::parse(r.out).value("error", ""), "") << r.out;
  std::filesystem::remove_all(dir);
}

} // namespace
} // namespace zdg
