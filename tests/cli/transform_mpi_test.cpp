// zdg transform dt|voronoi --mpi under mpiexec with 1 to 4 ranks (issue #15): the outputs are
// the single-process command's, byte for byte, on volumes whose slabs are uneven or empty;
// errors are one line of zdg, exit 2, no output. The distributed algorithm itself is checked
// on random volumes by tests/kernel/transforms/distributed_transform_test.cpp (ranks as threads);
// these tests check the MPI binding: the exchange through MPI and the MPI-IO offsets of the slabs
// and column blocks.
#include "tests/support/cli.hpp"
#include <zdg/kernel/io/npy_io.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <random>
#include <stdexcept>
#include <system_error>

namespace zdg {
namespace {

struct Files {
  std::filesystem::path dir = test::scratch_dir("mpi");
  ~Files() { std::filesystem::remove_all(dir); }
  std::string operator()(const std::string& name) const {
    std::string q(1, '\''); // (not "'" + ... + "'": a false -Wstringop-overflow of GCC 12)
    q.append((dir / name).string());
    q.push_back('\'');
    return q;
  }
  std::string path(const std::string& name) const { return (dir / name).string(); }
};

using test::mpi_built;
using test::zdg_lines;

// A random mask (items of the dtype's width) with background density `percent`.
template <class X>
void write_mask(const std::string& path, const std::vector<std::int64_t>& shape, int percent,
                std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::int64_t n = 1;
  for (auto e : shape) n *= e;
  std::vector<X> v(static_cast<std::size_t>(n));
  for (auto& x : v) x = static_cast<X>(static_cast<int>(rng() % 100) < percent ? 0 : 1 + rng() % 3);
  v[rng() % v.size()] = 0;
  write_npy(path, make_npy<X>(shape, v));
}

// Theorem (as for the kernel's threads): the distributed command's output is the single-process
// command's, byte for byte (header and values), for every P, including slabs of unequal sizes,
// ranks without a slice (P > n_0) or without a column, torus axes, lower bounds, l_1, l_2, l_3,
// l_inf, and the Voronoi map's coordinates.
TEST(MpiTransform, OutputsEqualTheSingleProcessCommand) {
  if (!mpi_built()) GTEST_SKIP() << "zdg was built without MPI";
  Files f;
  struct Case {
    std::vector<std::int64_t> shape;
    bool wide; // uint16 items instead of uint8
    std::string options;
  };
  const std::vector<Case> cases = {
      {{7, 5, 3}, false, "--metric l2"},
      {{3, 11, 6}, true, "--metric l1 --torus 0,2"},
      {{13, 17, 11}, false, "--metric l3 --torus all --lower -4,2,7"},
      {{10, 2}, true, "--metric linf"},
      {{6, 4, 3, 5}, false, "--metric l2 --torus 1"},
  };
  std::uint32_t seed = 2014;
  for (const auto& c : cases) {
    if (c.wide) {
      write_mask<std::uint16_t>(f.path("in.npy"), c.shape, 8, seed++);
    } else {
      write_mask<std::uint8_t>(f.path("in.npy"), c.shape, 8, seed++);
    }
    for (const std::string cmd : {"dt", "voronoi"}) {
      auto ref = test::run_zdg("transform " + cmd + " " + f("in.npy") + " -o " + f("ref.npy") +
                               " --force " + c.options);
      ASSERT_EQ(ref.status, 0) << ref.err;
      const std::string expect = test::read_file(f.path("ref.npy"));
      for (int P = 1; P <= 4; ++P) {
        auto r = test::run_mpi(P, "transform " + cmd + " " + f("in.npy") + " -o " + f("out.npy") +
                                      " --force --mpi --json " + c.options);
        ASSERT_EQ(r.status, 0) << cmd << " " << c.options << " P = " << P << ": " << r.err;
        EXPECT_EQ(test::read_file(f.path("out.npy")), expect)
            << cmd << " " << c.options << ", P = " << P;
        // One JSON report, from rank 0.
        const auto j = nlohmann::json::parse(r.out);
        EXPECT_EQ(j["ranks"], P);
        EXPECT_EQ(j["mpi"], true);
        for (const char* s : {"read", "slab passes", "exchange", "axis 0", "write"})
          EXPECT_TRUE(j["stages"].contains(s)) << s;
      }
    }
  }
}

// Errors: one line of zdg (whatever mpiexec adds), exit 2, no output file, an existing output
// kept: the input missing, no background on any rank, a 1-D image, a float input, an output
// that exists without --force; and --mpi without a launcher.
TEST(MpiTransform, ErrorsAreOneLineAndNoOutput) {
  Files f;
  write_npy(f.path("in.npy"), make_npy<std::uint8_t>({4, 3}, std::vector<std::uint8_t>(12, 0)));
  auto single = test::run_zdg("transform dt " + f("in.npy") + " -o " + f("out.npy") + " --mpi");
  EXPECT_EQ(single.status, 2);
  EXPECT_EQ(zdg_lines(single.err), 1) << single.err;
  EXPECT_NE(single.err.find(mpi_built() ? "MPI launcher" : "without MPI"), std::string::npos)
      << single.err;
  EXPECT_FALSE(std::filesystem::exists(f.path("out.npy")));
  if (!mpi_built()) return;

  write_npy(f.path("ones.npy"), make_npy<std::uint8_t>({5, 4}, std::vector<std::uint8_t>(20, 1)));
  write_npy(f.path("line.npy"), make_npy<std::uint8_t>({6}, std::vector<std::uint8_t>(6, 0)));
  write_npy(f.path("float.npy"), make_npy<double>({3, 3}, std::vector<double>(9, 0.0)));
  struct Case {
    std::string args, message;
  };
  const std::vector<Case> cases = {
      {"transform dt " + f("missing.npy") + " -o " + f("out.npy") + " --mpi", "no such file"},
      {"transform dt " + f("ones.npy") + " -o " + f("out.npy") + " --mpi", "no background point"},
      {"transform voronoi " + f("line.npy") + " -o " + f("out.npy") + " --mpi", "1-D image"},
      {"transform dt " + f("float.npy") + " -o " + f("out.npy") + " --mpi", "float64"},
      {"transform dt " + f("in.npy") + " -o " + f("out.npy") + " --mpi --out-of-core",
       "--out-of-core"},
  };
  for (const auto& c : cases) {
    auto r = test::run_mpi(3, c.args);
    EXPECT_EQ(r.status, 2) << c.args << ": " << r.err;
    EXPECT_EQ(zdg_lines(r.err), 1) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(f.path("out.npy"))) << c.args;
    // Nor a staged output: rank 0 stages it before the ranks agree on a failure, and must
    // remove it before any rank exits (mpiexec then kills the others).
    for (const auto& e : std::filesystem::directory_iterator(f.dir))
      EXPECT_NE(e.path().filename().string()[0], '.') << c.args << ": " << e.path();
  }
  // An existing output is refused without --force and left as it was.
  write_npy(f.path("out.npy"), make_npy<std::uint8_t>({1}, std::vector<std::uint8_t>{7}));
  const std::string before = test::read_file(f.path("out.npy"));
  auto r = test::run_mpi(2, "transform dt " + f("in.npy") + " -o " + f("out.npy") + " --mpi");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--force"), std::string::npos) << r.err;
  EXPECT_EQ(test::read_file(f.path("out.npy")), before);
  for (const auto& e : std::filesystem::directory_iterator(f.dir)) // no staged file left
    EXPECT_NE(e.path().filename().string()[0], '.') << e.path();
}

} // namespace
} // namespace zdg
