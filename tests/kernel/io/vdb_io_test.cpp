// .vdb volumes (kernel/io/vdb_io.hpp) through read_volume / write_volume: round trips of random
// volumes of every dtype (the values, their dtype, the box, the spacing and origin come back),
// and the errors.
#include <zdg/kernel/io/vdb_io.hpp>

#include "tests/support/cli.hpp"
#include "tests/support/peak_memory.hpp"
#include "tests/support/tower.hpp"
#include <zdg/arith/error.hpp>
#include <zdg/kernel/io/volume_io.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <vector>

// OpenVDB 10's RootNode::readTopology leaks the nodes it has read when a truncated file makes
// it stop (the truncation test below): the library's leak, not zdg's, suppressed for the
// sanitizer runs (LeakSanitizer reads this hook; without a sanitizer it is an unused function).
extern "C" const char* __lsan_default_suppressions();
extern "C" const char* __lsan_default_suppressions() {
  return "leak:readTopology\n";
}

namespace zdg {
namespace {

struct Dir {
  std::filesystem::path dir = test::scratch_dir("vdb");
  ~Dir() { std::filesystem::remove_all(dir); }
  std::string operator()(const std::string& name) const { return (dir / name).string(); }
};

// A random sparse volume: values drawn for the dtype, most voxels zero.
ScalarVolume random_volume(DType t, std::mt19937& rng) {
  const bool two = rng() % 4 == 0;
  std::vector<std::int64_t> shape, lower;
  for (int k = 0; k < (two ? 2 : 3); ++k) {
    shape.push_back(1 + static_cast<std::int64_t>(rng() % 9));
    lower.push_back(static_cast<std::int64_t>(rng() % 21) - 10);
  }
  std::int64_t n = 1;
  for (auto s : shape) n *= s;
  std::vector<std::int64_t> iv(static_cast<std::size_t>(n), 0);
  std::vector<double> fv(static_cast<std::size_t>(n), 0);
  for (std::int64_t i = 0; i < n; ++i) {
    if (rng() % 3 != 0) continue;
    const auto u = static_cast<std::size_t>(i);
    switch (t) {
    case DType::Bool:
      iv[u] = 1;
      break;
    case DType::U8:
      iv[u] = static_cast<std::int64_t>(rng() % 256);
      break;
    case DType::I32:
      iv[u] = static_cast<std::int64_t>(rng()) - (std::int64_t{1} << 31);
      break;
    case DType::I64:
      iv[u] = (static_cast<std::int64_t>(rng()) << 31) ^ static_cast<std::int64_t>(rng());
      break;
    default:
      fv[u] = std::ldexp(static_cast<double>(rng()), -20) - 2000.0;
    }
  }
  ScalarVolume v;
  if (t == DType::F32 || t == DType::F64) {
    NpyArray a;
    a.dtype = t;
    a.shape = shape;
    const std::size_t w = dtype_size(t);
    a.bytes.resize(static_cast<std::size_t>(n) * w);
    for (std::size_t u = 0; u < static_cast<std::size_t>(n); ++u) {
      if (t == DType::F32) {
        const auto f = static_cast<float>(fv[u]);
        std::memcpy(a.bytes.data() + u * w, &f, w);
      } else {
        std::memcpy(a.bytes.data() + u * w, &fv[u], w);
      }
    }
    v = make_scalar_volume(std::move(a));
  } else {
    v = make_scalar_volume(make_npy(t, shape, iv));
  }
  v.lower = lower;
  v.spacing.clear();
  v.origin.clear();
  for (std::size_t k = 0; k < shape.size(); ++k) {
    v.spacing.push_back(0.25 * static_cast<double>(1 + rng() % 8));
    v.origin.push_back(static_cast<double>(static_cast<int>(rng() % 100)) / 8 - 6);
  }
  return v;
}

TEST(VdbIo, RoundTripsKeepValuesBoxSpacingAndOrigin) {
  if (!vdb_supported()) GTEST_SKIP() << "built without OpenVDB";
  Dir d;
  std::mt19937 rng(20261129);
  for (DType t : {DType::Bool, DType::U8, DType::I32, DType::I64, DType::F32, DType::F64}) {
    for (int trial = 0; trial < 20; ++trial) {
      const ScalarVolume v = random_volume(t, rng);
      const std::string path = d("v.vdb");
      write_volume(path, v);
      const ScalarVolume r = read_volume(path);
      SCOPED_TRACE(dtype_name(t) + " " + describe_volume(v));
      // 2D images come back as one slice.
      const bool two = v.dim() == 2;
      ASSERT_EQ(r.dim(), 3);
      std::vector<std::int64_t> shape = v.array.shape, lower = v.lower;
      std::vector<double> spacing = v.spacing, origin = v.origin;
      if (two) {
        shape.insert(shape.begin(), 1);
        lower.insert(lower.begin(), 0);
        spacing.insert(spacing.begin(), 1.0);
        origin.insert(origin.begin(), 0.0);
      }
      EXPECT_EQ(r.array.shape, shape);
      EXPECT_EQ(r.lower, lower);
      for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_NEAR(r.spacing[k], spacing[k], 1e-12);
        EXPECT_NEAR(r.origin[k], origin[k], 1e-9);
      }
      for (std::int64_t i = 0; i < v.count(); ++i) ASSERT_EQ(r.value(i), v.value(i)) << i;
      // The dtype comes back (zdg names it in the grid's metadata).
      EXPECT_EQ(r.array.dtype, v.array.dtype);
      EXPECT_EQ(r.array.bytes, v.array.bytes);
    }
  }
}

TEST(VdbIo, ErrorsNameTheFile) {
  if (!vdb_supported()) GTEST_SKIP() << "built without OpenVDB";
  Dir d;
  std::ofstream(d("junk.vdb")) << "not a vdb file at all";
  try {
    read_volume(d("junk.vdb"));
    FAIL() << "junk read";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("junk.vdb: not a readable OpenVDB file"),
              std::string::npos)
        << e.what();
  }
  // Every truncation of a file is an IoError, never a volume with the rest as background.
  std::mt19937 rng(7);
  ScalarVolume v = random_volume(DType::U8, rng);
  while (v.dim() != 3) v = random_volume(DType::U8, rng);
  write_volume(d("whole.vdb"), v);
  const std::string whole = [&] {
    std::ifstream f(d("whole.vdb"), std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(f), {});
  }();
  for (std::size_t n = 0; n < whole.size(); n += 1 + n / 8) {
    std::ofstream(d("cut.vdb"), std::ios::binary) << whole.substr(0, n);
    EXPECT_THROW(read_volume(d("cut.vdb")), IoError) << n << " of " << whole.size() << " bytes";
  }
  // uint64 values past 2^63 have no OpenVDB grid.
  const ScalarVolume big =
      make_scalar_volume(make_npy(DType::U64, {1, 1, 2}, std::vector<std::int64_t>{0, 0}));
  ScalarVolume b = big;
  const std::uint64_t huge = (std::uint64_t{1} << 63) + 5;
  std::memcpy(b.array.bytes.data() + 8, &huge, 8);
  EXPECT_THROW(write_volume(d("big.vdb"), b), InvalidArgument);
  EXPECT_EQ(volume_format_of("X.VDB"), VolumeFormat::vdb);
}

} // namespace
} // namespace zdg

namespace zdg {
namespace {

// OpenVDB (through zdg's module, libzdg_vdb.so) is loaded by the first .vdb file, not when a
// process starts (its relocations cost every start about 45 ms): in a fresh process (the death
// test's child runs this binary again with this test alone) libopenvdb is not mapped before a
// volume is written and read back, and is after, with the values back.
TEST(VdbIo, OpenVdbIsLoadedAtTheFirstFileOnly) {
  if (!vdb_supported()) GTEST_SKIP() << "built without OpenVDB";
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const Dir dir;
  const std::string path = dir("first.vdb");
  const auto first_use = [&] {
    const bool before = test::library_mapped("libopenvdb");
    std::vector<std::int64_t> values(24, 0);
    values[5] = 7;
    ScalarVolume v;
    v.array = make_npy(DType::U8, {2, 3, 4}, values);
    v.lower = {0, 0, 0};
    v.spacing = {1, 1, 1};
    v.origin = {0, 0, 0};
    write_volume(path, v);
    const ScalarVolume back = read_volume(path);
    const bool after = test::library_mapped("libopenvdb") && test::library_mapped("libzdg_vdb");
    std::exit(!before && after && back.value(5) == 7.0 ? 0 : 1);
  };
  EXPECT_EXIT(first_use(), ::testing::ExitedWithCode(0), "");
}

} // namespace
} // namespace zdg
