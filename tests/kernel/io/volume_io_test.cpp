#include <zdg/kernel/io/volume_io.hpp>

#include <zdg/kernel/io/nifti_io.hpp>
#include <zdg/kernel/io/vol_io.hpp>

#include "tests/support/cli.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cstring>
#include <limits>

namespace zdg {
namespace {

namespace fs = std::filesystem;

TEST(VolumeIo, FormatByName) {
  EXPECT_EQ(volume_format_of("a/b.vol"), VolumeFormat::vol);
  EXPECT_EQ(volume_format_of("B.NII"), VolumeFormat::nifti);
  EXPECT_EQ(volume_format_of("c.nii.gz"), VolumeFormat::nifti_gz);
  EXPECT_EQ(volume_format_of("x.npy"), VolumeFormat::npy);
  EXPECT_EQ(volume_format_of("x.pgm"), VolumeFormat::pgm);
  EXPECT_EQ(volume_format_of("x.raw"), VolumeFormat::raw);
  EXPECT_THROW(volume_format_of("x.tif"), IoError);
  EXPECT_THROW(volume_format_of("x.gz"), IoError);
  EXPECT_EQ(volume_format_name(VolumeFormat::nifti_gz), "nifti.gz");
}

// Round trip through every format that holds the dtype: read(write(V)) has V's dtype, shape
// and bytes, and writing what was read gives the same file again.
RC_GTEST_PROP(VolumeIo, EveryFormatRoundTripsBitIdentical, ()) {
  const bool flat = *rc::gen::arbitrary<bool>();
  const auto shape =
      *rc::gen::container<std::vector<std::int64_t>>(flat ? 2 : 3, rc::gen::inRange(1, 5));
  const DType t = *rc::gen::elementOf(
      std::vector<DType>{DType::U8, DType::I8, DType::U16, DType::I16, DType::U32, DType::I32,
                         DType::U64, DType::I64, DType::F32, DType::F64});
  NpyArray a;
  a.dtype = t;
  a.shape = shape;
  a.bytes = *rc::gen::container<std::vector<unsigned char>>(
      static_cast<std::size_t>(a.count()) * dtype_size(t), rc::gen::arbitrary<unsigned char>());
  const ScalarVolume v = make_scalar_volume(a);
  std::vector<std::string> names = {"a.npy", "a.nii", "a.nii.gz", "a.raw"};
  if (t == DType::U8 && !flat) names.push_back("a.vol");
  bool wide = false; // PGM is 16-bit when a value exceeds 255, else 8-bit
  for (std::int64_t i = 0; t == DType::U16 && i < a.count(); ++i) wide = wide || a.get(i) > 255;
  if ((t == DType::U8 || wide) && flat) names.push_back("a.pgm");
  const auto dir = test::scratch_dir("volume");
  for (const auto& name : names) {
    const std::string p = (dir / name).string(), q = (dir / ("b" + name.substr(1))).string();
    write_volume(p, v);
    RawLayout raw;
    if (name == "a.raw") {
      raw.shape = shape;
      raw.dtype = t;
    }
    const auto back = read_volume(p, raw);
    RC_ASSERT(back.array.shape == shape);
    RC_ASSERT(back.array.bytes == a.bytes);
    RC_ASSERT(back.array.dtype == t);
    write_volume(q, back);
    RC_ASSERT(test::read_file(p) == test::read_file(q));
  }
  fs::remove_all(dir);
}

TEST(VolumeIo, VolBothVersionsAndStagingNames) {
  const auto dir = test::scratch_dir("volume");
  Image<std::uint8_t> img(Domain({2, 2, 3}, {4, -2, 0}));
  for (std::int64_t i = 0; i < img.size(); ++i) img[i] = static_cast<std::uint8_t>(i * 20);
  const ScalarVolume v = make_scalar_volume(img);
  for (int version : {2, 3}) {
    VolumeWriteOptions o;
    o.vol_version = version;
    write_volume((dir / "a.vol").string(), v, o);
    EXPECT_EQ(test::read_file(dir / "a.vol"), vol_file_bytes(img, version));
    EXPECT_EQ(read_volume((dir / "a.vol").string()).lower, img.domain().lowers());
  }
  // An explicit format writes to a name without the extension (an OutputSet staging file).
  VolumeWriteOptions o;
  o.format = VolumeFormat::nifti_gz;
  write_volume((dir / ".staging-1").string(), v, o);
  fs::rename(dir / ".staging-1", dir / "c.nii.gz");
  EXPECT_EQ(read_volume((dir / "c.nii.gz").string()).array.bytes, v.array.bytes);
  fs::remove_all(dir);
}

// Regression (shrunk by EveryFormatRoundTripsBitIdentical: float32 2x3x2, last value -inf):
// libnifti's nifti_image_load replaces NaN and infinities by 0, so the NIfTI reader reads the
// payload itself. Every non-finite float32/float64 value reads back bit-identical.
TEST(VolumeIo, NonFiniteFloatsSurviveNifti) {
  const auto dir = test::scratch_dir("volume");
  for (const DType t : {DType::F32, DType::F64}) {
    NpyArray a;
    a.dtype = t;
    a.shape = {2, 3, 2};
    a.bytes.assign(static_cast<std::size_t>(a.count()) * dtype_size(t), 0);
    const double special[4] = {-std::numeric_limits<double>::infinity(),
                               std::numeric_limits<double>::infinity(),
                               std::numeric_limits<double>::quiet_NaN(), -0.0};
    for (int k = 0; k < 4; ++k) {
      unsigned char* at = a.bytes.data() + static_cast<std::size_t>(8 + k) * dtype_size(t);
      if (t == DType::F32) {
        const auto f = static_cast<float>(special[k]);
        std::memcpy(at, &f, sizeof f);
      } else {
        std::memcpy(at, &special[k], sizeof special[k]);
      }
    }
    const ScalarVolume v = make_scalar_volume(a);
    for (const char* name : {"a.nii", "a.nii.gz"}) {
      write_volume((dir / (std::string(t == DType::F32 ? "f" : "d") + name)).string(), v);
      EXPECT_EQ(read_volume((dir / (std::string(t == DType::F32 ? "f" : "d") + name)).string())
                    .array.bytes,
                a.bytes)
          << name;
    }
  }
  fs::remove_all(dir);
}

TEST(VolumeIo, ValuesThatDoNotFitAreErrors) {
  const auto dir = test::scratch_dir("volume");
  NpyArray a = make_npy(DType::I16, {1, 2, 2}, {0, 1, 300, 2});
  ScalarVolume v = make_scalar_volume(a);
  try {
    write_volume((dir / "a.vol").string(), v);
    ADD_FAILURE();
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("value 300 (voxel 2) does not fit a .vol voxel"),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(dir / "a.vol"));
  EXPECT_THROW(write_volume((dir / "a.pgm").string(), v), InvalidArgument); // 3D
  // Scaled values: written as their physical values (float64 in .npy, integers in .vol).
  v.array = make_npy(DType::I16, {1, 2, 2}, {0, 1, 2, 3});
  v.slope = 2.0;
  v.inter = 1.0;
  write_volume((dir / "a.npy").string(), v);
  const auto f = read_volume((dir / "a.npy").string());
  EXPECT_EQ(f.array.dtype, DType::F64);
  EXPECT_EQ(f.value(3), 7.0);
  write_volume((dir / "a.vol").string(), v);
  EXPECT_EQ(read_volume((dir / "a.vol").string()).value(3), 7.0);
  v.inter = 0.5;
  EXPECT_THROW(write_volume((dir / "b.vol").string(), v), InvalidArgument); // 0.5 not integral
  // The raw layout: both or neither.
  RawLayout half;
  half.dtype = DType::U8;
  EXPECT_THROW(read_volume((dir / "a.npy").string(), half), InvalidArgument);
  EXPECT_THROW(read_volume((dir / "x.raw").string()), InvalidArgument);
  EXPECT_THROW(read_volume((dir / "missing.npy").string()), IoError);
  NpyArray one = make_npy(DType::U8, {4}, {1, 2, 3, 4});
  write_npy((dir / "one.npy").string(), one);
  EXPECT_THROW(read_volume((dir / "one.npy").string()), IoError); // 1-D
  fs::remove_all(dir);
}

} // namespace
} // namespace zdg
