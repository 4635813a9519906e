#include <zdg/kernel/npy_io.hpp>

#include "tests/support/cli.hpp"

#include <gtest/gtest.h>

#include <fstream>

namespace zdg {
namespace {

void write_raw(const std::filesystem::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary) << bytes;
}

// An npy v1.0 file with this header dict and data.
std::string npy_bytes(const std::string& dict, const std::string& data) {
  std::string h = dict;
  std::size_t total = 10 + h.size() + 1;
  h.append((64 - total % 64) % 64, ' ');
  h.push_back('\n');
  std::string out = "\x93NUMPY";
  out.push_back('\x01');
  out.push_back('\x00');
  out.push_back(static_cast<char>(h.size() & 0xff));
  out.push_back(static_cast<char>(h.size() >> 8));
  return out + h + data;
}

TEST(NpyIo, RoundTripEveryDtype) {
  auto dir = test::scratch_dir("npy");
  std::vector<std::int64_t> v{0, 1, 1, 0, 1, 1};
  for (DType t : {DType::Bool, DType::U8, DType::U16, DType::U32, DType::U64, DType::I8, DType::I16,
                  DType::I32, DType::I64}) {
    auto path = (dir / (dtype_name(t) + ".npy")).string();
    write_npy(path, make_npy(t, {2, 3}, v));
    auto a = read_npy(path);
    EXPECT_EQ(a.dtype, t);
    EXPECT_EQ(a.shape, (std::vector<std::int64_t>{2, 3}));
    auto img = npy_to_int64(a, {-1, 5});
    EXPECT_EQ(img.values(), v);
    EXPECT_EQ(img.domain().lower(0), -1);
    EXPECT_EQ(npy_to_mask(a).values(), (std::vector<std::uint8_t>{0, 1, 1, 0, 1, 1}));
  }
  std::vector<std::int64_t> big{-5, std::numeric_limits<std::int64_t>::max(), 7};
  auto path = (dir / "big.npy").string();
  write_npy(path, make_npy<std::int64_t>({3}, big));
  EXPECT_EQ(npy_to_int64(read_npy(path)).values(), big);
  EXPECT_THROW(make_npy(DType::U8, {1}, {256}), InvalidArgument);
  std::filesystem::remove_all(dir);
}

TEST(NpyIo, ReadsWhatNumpyWrites) {
  // Bytes of np.save(f, np.array([[1, 2, 3]], dtype=np.uint16)) with numpy's header.
  auto dir = test::scratch_dir("npy");
  std::string data("\x01\x00\x02\x00\x03\x00", 6);
  write_raw(dir / "a.npy",
            npy_bytes("{'descr': '<u2', 'fortran_order': False, 'shape': (1, 3), }", data));
  auto a = read_npy((dir / "a.npy").string());
  EXPECT_EQ(a.dtype, DType::U16);
  EXPECT_EQ(npy_to_int64(a).values(), (std::vector<std::int64_t>{1, 2, 3}));
  std::filesystem::remove_all(dir);
}

TEST(NpyIo, MalformedFilesAreClearErrors) {
  auto dir = test::scratch_dir("npy");
  auto expect_error = [&](const std::string& name, const std::string& bytes,
                          const std::string& msg) {
    write_raw(dir / name, bytes);
    try {
      read_npy((dir / name).string());
      ADD_FAILURE() << name << " was accepted";
    } catch (const IoError& e) {
      EXPECT_NE(std::string(e.what()).find(msg), std::string::npos) << e.what();
    }
  };
  expect_error("empty.npy", "", "empty file");
  expect_error("magic.npy", "hello world, not numpy", "magic");
  expect_error("fortran.npy",
               npy_bytes("{'descr': '|u1', 'fortran_order': True, 'shape': (2, 2), }", "abcd"),
               "Fortran");
  expect_error("float.npy",
               npy_bytes("{'descr': '<c8', 'fortran_order': False, 'shape': (1,), }", "12345678"),
               "'<c8' is not supported");
  expect_error("bigendian.npy",
               npy_bytes("{'descr': '>i4', 'fortran_order': False, 'shape': (1,), }", "1234"),
               "big-endian");
  expect_error("truncated.npy",
               npy_bytes("{'descr': '<i4', 'fortran_order': False, 'shape': (2, 3), }", "12345678"),
               "truncated data");
  expect_error("header.npy", std::string("\x93NUMPY\x01\x00\x40\x00{'descr'", 17),
               "truncated npy header");
  expect_error("noshape.npy", npy_bytes("{'descr': '<i4', 'fortran_order': False, }", ""),
               "'shape'");
  EXPECT_THROW(read_npy((dir / "missing.npy").string()), IoError);
  write_raw(dir / "zero.npy",
            npy_bytes("{'descr': '|u1', 'fortran_order': False, 'shape': (0, 3), }", ""));
  EXPECT_THROW(npy_to_mask(read_npy((dir / "zero.npy").string())), IoError);
  std::filesystem::remove_all(dir);
}

} // namespace
} // namespace zdg

namespace zdg {
namespace {

// float32 / float64 arrays: written and read bit for bit, read as numpy writes them.
TEST(NpyIo, FloatDtypes) {
  auto dir = test::scratch_dir("npy");
  const std::vector<float> f{-0.0f, 1.5f, std::numeric_limits<float>::infinity(), 3.25e-30f};
  const std::vector<double> d{0.1, -2.0, 1e300, 5e-324};
  write_npy((dir / "f.npy").string(), make_npy<float>({2, 2}, f));
  write_npy((dir / "d.npy").string(), make_npy<double>({4, 1}, d));
  auto a = read_npy((dir / "f.npy").string());
  EXPECT_EQ(a.dtype, DType::F32);
  for (std::int64_t i = 0; i < 4; ++i)
    EXPECT_EQ(a.get_double(i), static_cast<double>(f[static_cast<std::size_t>(i)]));
  EXPECT_EQ(npy_to_mask(a).values(), (std::vector<std::uint8_t>{0, 1, 1, 1}));
  EXPECT_THROW(npy_to_int64(a), IoError);
  auto b = read_npy((dir / "d.npy").string());
  EXPECT_EQ(b.dtype, DType::F64);
  for (std::int64_t i = 0; i < 4; ++i) EXPECT_EQ(b.get_double(i), d[static_cast<std::size_t>(i)]);
  write_raw(dir / "numpy.npy",
            npy_bytes("{'descr': '<f4', 'fortran_order': False, 'shape': (1, 2), }",
                      std::string("\x00\x00\xc0\x3f\x00\x00\x20\xc1", 8)));
  auto c = read_npy((dir / "numpy.npy").string());
  EXPECT_EQ(c.get_double(0), 1.5);
  EXPECT_EQ(c.get_double(1), -10.0);
  EXPECT_EQ(dtype_name(DType::F64), "float64");
  EXPECT_TRUE(dtype_is_float(DType::F32));
  EXPECT_FALSE(dtype_is_float(DType::I64));
  EXPECT_THROW(make_npy(DType::F32, {1}, {1}), InvalidArgument);
  std::filesystem::remove_all(dir);
}

} // namespace
} // namespace zdg
