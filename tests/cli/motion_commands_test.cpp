// zdg motion check|apply: the lattice certificate and its witness, the motion of a volume equal
// to the kernel's, the topology before and after, the output contract.
#include "tests/support/cli.hpp"
#include <zdg/kernel/images/rigid_motion.hpp>
#include <zdg/kernel/io/npy_io.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace zdg {
namespace {

struct Files {
  std::filesystem::path dir = test::scratch_dir("motion");
  ~Files() { std::filesystem::remove_all(dir); }
  std::string operator()(const std::string& name) const {
    std::string q(1, '\'');
    q.append((dir / name).string());
    q.push_back('\'');
    return q;
  }
  std::string path(const std::string& name) const { return (dir / name).string(); }
};

std::vector<BigInt> big(const nlohmann::json& a) {
  std::vector<BigInt> v;
  for (const auto& x : a) v.push_back(parse_integer<BigInt>(x.get<std::string>()));
  return v;
}

TEST(MotionCommands, LatticeCertificate) {
  auto r = test::run_zdg("motion check --rotation 3,4,5 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["bijective"].get<bool>());
  EXPECT_EQ(j["method"], "period");
  EXPECT_EQ(j["period"], "5");
  EXPECT_TRUE(j["witness"].is_null());
  // (20, 21, 29) is no twin triple: two points with one image and a point with none.
  r = test::run_zdg("motion check --rotation 20,21,29 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j["bijective"].get<bool>());
  const RigidMotion m = rotation_2d(20, 21, 29);
  const auto p1 = big(j["witness"]["points"][0]), p2 = big(j["witness"]["points"][1]);
  EXPECT_NE(p1, p2);
  EXPECT_EQ(digitized_image(m, p1), big(j["witness"]["image"]));
  EXPECT_EQ(digitized_image(m, p2), big(j["witness"]["image"]));
  EXPECT_EQ(j["witness"]["hole"].size(), 2u);
  // Text mode names the pair.
  r = test::run_zdg("motion check --rotation 20,21,29");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("not a bijection"), std::string::npos) << r.out;
}

// A 9 x 9 square ring (b1 = 1) turned by (5, 12, 13) about its centre.
std::vector<std::uint8_t> ring() {
  std::vector<std::uint8_t> v(81, 0);
  for (int y = 2; y <= 6; ++y) {
    for (int x = 2; x <= 6; ++x)
      v[static_cast<std::size_t>(y * 9 + x)] = (y == 2 || y == 6 || x == 2 || x == 6) ? 1 : 0;
  }
  return v;
}

TEST(MotionCommands, ApplyEqualsTheKernelAndReportsTopology) {
  Files f;
  write_npy(f.path("ring.npy"), make_npy<std::uint8_t>({9, 9}, ring()));
  const Image<std::uint8_t> img(Domain({9, 9}), ring());
  using Q = Rational<BigInt>;
  const RigidMotion m = motion_about(rotation_2d(5, 12, 13), {Q(4), Q(4)}, {Q(0), Q(0)});
  const MotionOnImage want = apply_motion(img, m, false);
  auto r = test::run_zdg("motion apply " + f("ring.npy") + " --rotation 5,12,13 -o " +
                         f("out.npy") + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["points"], "16");
  EXPECT_EQ(j["images"], std::to_string(want.images));
  EXPECT_EQ(j["center"], nlohmann::json::parse(R"(["4", "4"])"));
  const auto got = npy_to_int64(read_npy(f.path("out.npy"))).values();
  ASSERT_EQ(got.size(), want.image.values().size());
  EXPECT_TRUE(std::equal(got.begin(), got.end(), want.image.values().begin()));
  // The output exists: refused without --force, replaced with it.
  r = test::run_zdg("motion apply " + f("ring.npy") + " --rotation 5,12,13 -o " + f("out.npy"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("exists"), std::string::npos) << r.err;
  r = test::run_zdg("motion apply " + f("ring.npy") + " --rotation 5,12,13 -o " + f("out.npy") +
                    " --force");
  EXPECT_EQ(r.status, 0) << r.err;
  // check: the same counts, the ring's topology on both sides, the lattice block.
  r = test::run_zdg("motion check " + f("ring.npy") + " --rotation 5,12,13 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["images"], std::to_string(want.images));
  EXPECT_EQ(j["bijective"].get<bool>(), want.images == 16);
  EXPECT_EQ(j["topology"]["input"]["betti"], nlohmann::json::parse(R"(["1", "1"])"));
  EXPECT_TRUE(j["topology"]["input"]["well_composed"].get<bool>());
  EXPECT_EQ(j["topology_preserved"].get<bool>(),
            j["topology"]["input"]["betti"] == j["topology"]["image"]["betti"]);
  // (5, 12, 13) is a twin triple (12 = 13 - 1): a bijection of Z^2, so of the ring.
  EXPECT_TRUE(j["lattice"]["bijective"].get<bool>());
  EXPECT_TRUE(j["bijective"].get<bool>());
}

TEST(MotionCommands, QuaternionQuarterTurnOfACube) {
  Files f;
  std::vector<std::uint8_t> v(6 * 6 * 6, 0);
  for (int z = 1; z < 5; ++z)
    for (int y = 1; y < 5; ++y)
      for (int x = 1; x < 4; ++x) v[static_cast<std::size_t>((z * 6 + y) * 6 + x)] = 1;
  write_npy(f.path("box.npy"), make_npy<std::uint8_t>({6, 6, 6}, v));
  auto r = test::run_zdg("motion check " + f("box.npy") + " --quaternion 1,1,0,0 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["points"], "48");
  EXPECT_EQ(j["images"], "48");
  EXPECT_TRUE(j["bijective"].get<bool>());
  EXPECT_TRUE(j["topology_preserved"].get<bool>());
  EXPECT_EQ(j["denominator"], "1");
  EXPECT_FALSE(j.contains("lattice"));
}

} // namespace
} // namespace zdg
