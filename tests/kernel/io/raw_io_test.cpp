#include <zdg/kernel/io/raw_io.hpp>

#include "tests/support/cli.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <fstream>

namespace zdg {
namespace {

const std::vector<DType> kAll = {DType::Bool, DType::U8,  DType::I8,  DType::U16,
                                 DType::I16,  DType::U32, DType::I32, DType::U64,
                                 DType::I64,  DType::F32, DType::F64};

// Round trip: the file is exactly the array's bytes, and reading it with the same shape and
// dtype gives them back (any bytes, NaN patterns included).
RC_GTEST_PROP(RawIo, RoundTripIsBitIdentical, ()) {
  const DType t = *rc::gen::elementOf(kAll);
  const auto shape = *rc::gen::container<std::vector<std::int64_t>>(
      static_cast<std::size_t>(*rc::gen::inRange(2, 4)), rc::gen::inRange(1, 5));
  NpyArray a;
  a.dtype = t;
  a.shape = shape;
  const auto n = static_cast<std::size_t>(a.count()) * dtype_size(t);
  a.bytes = *rc::gen::container<std::vector<unsigned char>>(
      n, t == DType::Bool ? rc::gen::inRange<unsigned char>(0, 2)
                          : rc::gen::arbitrary<unsigned char>());
  const auto dir = test::scratch_dir("raw");
  const std::string path = (dir / "a.raw").string();
  write_raw(path, make_scalar_volume(a));
  const std::string file = test::read_file(path);
  RC_ASSERT(file == std::string(a.bytes.begin(), a.bytes.end()));
  const auto back = read_raw(path, shape, t);
  RC_ASSERT(back.array.bytes == a.bytes);
  RC_ASSERT(back.array.shape == shape);
  RC_ASSERT(back.array.dtype == t);
  RC_ASSERT(read_raw_bytes(file, "mem.raw", shape, t).array.bytes == a.bytes);
  std::filesystem::remove_all(dir);
}

void expect_error(const std::function<void()>& f, const std::string& words) {
  try {
    f();
    ADD_FAILURE() << "no error; expected: " << words;
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(words), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

TEST(RawIo, SizesAreCheckedBeforeReading) {
  const auto dir = test::scratch_dir("raw");
  const std::string path = (dir / "a.raw").string();
  std::ofstream(path, std::ios::binary) << std::string(24, '\x01');
  EXPECT_EQ(read_raw(path, {2, 3, 4}, DType::U8).count(), 24);
  EXPECT_EQ(read_raw(path, {3, 4}, DType::I16).value(0), 257.0);
  expect_error(
      [&] {
        read_raw(path, {2, 3, 5}, DType::U8);
      },
      "raw file has 24 bytes, shape 2,3,5 of uint8 needs 30");
  expect_error([&] { read_raw(path, {2, 3}, DType::U8); }, "needs 6");
  expect_error(
      [&] {
        read_raw(path, {3037000500, 3037000500, 3037000500}, DType::F64);
      },
      "needs more than 2^62 bytes");
  expect_error([&] { read_raw(path, {24}, DType::U8); }, "2 or 3 axes");
  EXPECT_EQ(read_raw(path, {2, 3, 4}, DType::Bool).count(), 24);
  std::ofstream((dir / "two.raw").string(), std::ios::binary) << std::string(4, '\x02');
  expect_error(
      [&] {
        read_raw((dir / "two.raw").string(), {2, 2}, DType::Bool);
      },
      "raw bool value 2");
  expect_error(
      [&] {
        read_raw((dir / "missing.raw").string(), {1, 1}, DType::U8);
      },
      "no such file");
  std::filesystem::remove_all(dir);
}

TEST(RawIo, ParseShape) {
  EXPECT_EQ(parse_raw_shape("64,32,16"), (std::vector<std::int64_t>{64, 32, 16}));
  EXPECT_EQ(parse_raw_shape("010,2"), (std::vector<std::int64_t>{10, 2})); // decimal
  for (const char* bad : {"", "1", "1,2,3,4", "1,,2", "1,-2", "0,3", "a,b", "1,2 ", "+1,2",
                          "99999999999999999999,1"}) {
    EXPECT_THROW(parse_raw_shape(bad), InvalidArgument) << bad;
  }
  EXPECT_EQ(dtype_from_name("float32"), DType::F32);
  EXPECT_THROW(dtype_from_name("float16"), InvalidArgument);
}

} // namespace
} // namespace zdg
