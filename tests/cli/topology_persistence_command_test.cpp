// zdg topology persistence: the JSON diagrams are the library's (kernel/topology/
// cubical_persistence.hpp), for both filtrations and any dtype the loader reads.
#include "tests/support/binary_images.hpp"
#include "tests/support/cli.hpp"
#include <zdg/kernel/io/npy_io.hpp>
#include <zdg/kernel/io/pgm_io.hpp>
#include <zdg/kernel/topology/betti_numbers.hpp>
#include <zdg/kernel/topology/cubical_persistence.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <random>

namespace zdg {
namespace {

struct Files {
  std::filesystem::path dir = test::scratch_dir("topology_persistence");
  ~Files() { std::filesystem::remove_all(dir); }
  std::string operator()(const std::string& name) const {
    std::string quoted(1, '\'');
    quoted += (dir / name).string();
    quoted += '\'';
    return quoted;
  }
  std::string path(const std::string& name) const { return (dir / name).string(); }
};

// The diagrams of the JSON answer equal the library's, pair for pair (null = +infinity).
void expect_same_diagrams(const nlohmann::json& j, const PersistenceDiagrams& want) {
  ASSERT_EQ(j["diagrams"].size(), want.diagrams.size());
  for (std::size_t k = 0; k < want.diagrams.size(); ++k) {
    const auto& g = j["diagrams"][k];
    ASSERT_EQ(g.size(), want.diagrams[k].size()) << "dimension " << k;
    for (std::size_t i = 0; i < g.size(); ++i) {
      EXPECT_EQ(g[i][0].get<double>(), want.diagrams[k][i].birth);
      if (std::isinf(want.diagrams[k][i].death)) {
        EXPECT_TRUE(g[i][1].is_null());
      } else {
        EXPECT_EQ(g[i][1].get<double>(), want.diagrams[k][i].death);
      }
    }
  }
}

TEST(TopologyPersistenceCommand, ValuesOfAFloatVolumeAsTheLibrary) {
  Files f;
  std::mt19937 rng(5);
  std::normal_distribution<float> normal;
  std::vector<float> v(6 * 7 * 8);
  for (auto& x : v) x = normal(rng);
  write_npy(f.path("noise.npy"), make_npy<float>({6, 7, 8}, v));
  const auto r = test::run_zdg("topology persistence " + f("noise.npy") + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["filtration"], "values");
  Image<double> values{Domain({6, 7, 8})};
  for (std::size_t i = 0; i < v.size(); ++i) values[static_cast<std::int64_t>(i)] = v[i];
  const auto want = cubical_persistence(values);
  expect_same_diagrams(j, want);
  // One essential class, the component born at the minimum.
  EXPECT_TRUE(j["diagrams"][0][0][1].is_null());
}

TEST(TopologyPersistenceCommand, GreyRingInAPgmHasOneLoop) {
  Files f;
  // A ring of grey 50 (a square annulus) on 200, its hole 120: the loop is born at 50 and
  // filled at 120; the background merges nothing (one component from 50).
  Image<std::uint64_t> grey{Domain({9, 9}), std::uint64_t{200}};
  for (std::int64_t y = 2; y <= 6; ++y) {
    for (std::int64_t x = 2; x <= 6; ++x) {
      const bool edge = y == 2 || y == 6 || x == 2 || x == 6;
      grey[y * 9 + x] = edge ? 50 : 120;
    }
  }
  write_pgm(f.path("ring.pgm"), grey);
  const auto r = test::run_zdg("topology persistence " + f("ring.pgm") + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["diagrams"], nlohmann::json::parse("[[[50.0, null]], [[50.0, 120.0]]]"));
  const auto t = test::run_zdg("topology persistence " + f("ring.pgm"));
  ASSERT_EQ(t.status, 0) << t.err;
  EXPECT_NE(t.out.find("dimension 1: 1 pairs, longest [50, 120"), std::string::npos) << t.out;
}

// --filtration dt: the library's signed squared distance; at -1 the sublevel set is the object,
// so the pairs alive there count its Betti numbers (a solid torus: 1, 1, 0).
TEST(TopologyPersistenceCommand, DtFiltrationOfASolidTorus) {
  Files f;
  const auto torus = test::torus_image(8, 3);
  write_npy(f.path("torus.npy"), make_npy<std::uint8_t>(torus.domain().extents(), torus.values()));
  const auto r =
      test::run_zdg("topology persistence " + f("torus.npy") + " --filtration dt --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  expect_same_diagrams(j, cubical_persistence(signed_squared_distance(torus, 1)));
  const BettiNumbers b = betti_numbers(torus, default_adjacency_pair(3), 1);
  for (std::size_t k = 0; k < 3; ++k) {
    std::int64_t alive = 0;
    for (const auto& p : j["diagrams"][k]) {
      alive += p[0].get<double>() <= -1 && (p[1].is_null() || -1 < p[1].get<double>());
    }
    EXPECT_EQ(alive, b.b[k]) << "dimension " << k;
  }
  EXPECT_EQ(b.b[1], 1);
}

} // namespace
} // namespace zdg
