#include <zdg/kernel/io/npy_io.hpp>

#include "tests/support/cli.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cstring>

#include <fstream>
#include <functional>

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

// np.save of a transposed array writes fortran_order True: the data are first axis fastest. The
// reader returns the same array as np.load, in C order: element (i0, .., i_{d-1}) of the C
// array is the file's item at i0 + s0 (i1 + s1 (i2 + ...)). Oracle: that formula, on random
// shapes of 1 to 4 axes and every item size, through the bytes (parse_npy) and the file
// (read_npy).
TEST(NpyIo, FortranOrderIsReadIntoCOrder) {
  auto dir = test::scratch_dir("npy");
  // np.arange(6, dtype='<i2').reshape(2, 3, order='F'): the file holds 0..5, the array is
  // [[0, 2, 4], [1, 3, 5]].
  std::string data;
  for (char v = 0; v < 6; ++v) data += std::string{v, '\0'};
  write_raw(dir / "f.npy",
            npy_bytes("{'descr': '<i2', 'fortran_order': True, 'shape': (2, 3), }", data));
  EXPECT_EQ(npy_to_int64(read_npy((dir / "f.npy").string())).values(),
            (std::vector<std::int64_t>{0, 2, 4, 1, 3, 5}));
  EXPECT_TRUE(read_npy_layout((dir / "f.npy").string()).fortran_order);
  std::filesystem::remove_all(dir);
}

RC_GTEST_PROP(NpyIo, FortranOrderMatchesTheIndexFormula, ()) {
  static const auto dir = test::scratch_dir("npy_fortran");

  const auto d = *rc::gen::inRange<std::size_t>(1, 5);
  std::vector<std::int64_t> shape;
  for (std::size_t k = 0; k < d; ++k) shape.push_back(*rc::gen::inRange<std::int64_t>(1, 5));
  const DType t = *rc::gen::element(DType::U8, DType::I16, DType::U32, DType::F64);
  const std::size_t item = dtype_size(t);
  std::int64_t n = 1;
  for (auto e : shape) n *= e;
  const auto file = *rc::gen::container<std::string>(static_cast<std::size_t>(n) * item,
                                                     rc::gen::arbitrary<char>());
  std::string dict = "{'descr': '" +
                     std::string(t == DType::U8    ? "|u1"
                                 : t == DType::I16 ? "<i2"
                                 : t == DType::U32 ? "<u4"
                                                   : "<f8") +
                     "', 'fortran_order': True, 'shape': (";
  for (auto e : shape) dict += std::to_string(e) + ", ";
  dict += "), }";
  const std::string bytes = npy_bytes(dict, file);
  write_raw(dir / "p.npy", bytes);
  for (const NpyArray& a : {parse_npy(bytes, "p.npy"), read_npy((dir / "p.npy").string())}) {
    RC_ASSERT(a.shape == shape);
    std::vector<std::int64_t> idx(d, 0);
    for (std::int64_t i = 0; i < n; ++i) {
      std::int64_t f = 0;
      for (std::size_t k = d; k-- > 0;) f = f * shape[k] + idx[k];
      RC_ASSERT(std::memcmp(a.bytes.data() + i * static_cast<std::int64_t>(item),
                            file.data() + f * static_cast<std::int64_t>(item), item) == 0);
      for (std::size_t k = d; k-- > 0;) {
        if (++idx[k] < shape[k]) break;
        idx[k] = 0;
      }
    }
  }
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

// Issue #41 item 14: the unsupported-dtype messages list every dtype that is read, float32
// and float64 included (they were omitted), and each listed name is accepted (by name and as
// an npy descr); the conversions' errors name the file when it is given.
TEST(NpyIo, DtypeMessagesListWhatIsAcceptedAndErrorsNameTheFile) {
  std::string listed;
  try {
    parse_npy(npy_bytes("{'descr': '<c8', 'fortran_order': False, 'shape': (1,), }", "12345678"),
              "c.npy");
    ADD_FAILURE() << "<c8 accepted";
  } catch (const IoError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("c.npy: dtype '<c8' is not supported (accepted: ", 0), 0u) << what;
    const auto open = what.find("(accepted: ") + 11;
    listed = what.substr(open, what.find(", little-endian)") - open);
  }
  std::vector<std::string> names;
  for (std::size_t b = 0, e; b < listed.size(); b = e + 2) {
    e = listed.find(", ", b);
    if (e == std::string::npos) e = listed.size();
    names.push_back(listed.substr(b, e - b));
  }
  EXPECT_EQ(names, (std::vector<std::string>{"bool", "uint8", "uint16", "uint32", "uint64", "int8",
                                             "int16", "int32", "int64", "float32", "float64"}));
  for (const auto& n : names) {
    const DType t = dtype_from_name(n);
    EXPECT_EQ(dtype_name(t), n);
    // An array of that dtype goes through the file format and back.
    NpyArray a;
    a.dtype = t;
    a.shape = {1};
    a.bytes.assign(dtype_size(t), 0);
    EXPECT_EQ(parse_npy(npy_file_bytes(a), "x.npy").dtype, t) << n;
  }
  try {
    dtype_from_name("complex64");
    ADD_FAILURE() << "complex64 accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("(accepted: " + listed + ")"), std::string::npos)
        << e.what();
  }
  NpyArray empty;
  empty.dtype = DType::U8;
  empty.shape = {0, 3};
  for (const auto& f : {std::function<void()>([&] { npy_to_mask(empty, {}, "e.npy"); }),
                        std::function<void()>([&] { npy_to_int64(empty, {}, "e.npy"); })}) {
    try {
      f();
      ADD_FAILURE() << "an empty array was converted";
    } catch (const IoError& e) {
      EXPECT_STREQ(e.what(), "e.npy: empty array (an extent is 0)");
    }
  }
  NpyArray flt;
  flt.dtype = DType::F32;
  flt.shape = {1, 1};
  flt.bytes.assign(4, 0);
  try {
    npy_to_int64(flt, {}, "f.npy");
    ADD_FAILURE() << "float32 converted to integers";
  } catch (const IoError& e) {
    EXPECT_STREQ(e.what(), "f.npy: float32 array where integers are needed");
  }
}

// Issue #18: headers past 65535 bytes wrapped the 2-byte length of version 1.0. Arrays with
// thousands of axes of extent 1 have long headers: they are written as version 2.0 (4-byte
// length), padded to 64 bytes, and read back; short headers stay version 1.0.
TEST(NpyIo, LongHeadersRoundTripAsVersion2) {
  for (std::size_t dims : {1u, 3u, 21000u, 22000u, 40000u}) {
    std::vector<std::int64_t> shape(dims, 1);
    shape[dims / 2] = 2;
    const NpyArray a = make_npy(DType::I16, shape, {-7, 300});
    const std::string bytes = npy_file_bytes(a);
    const bool v2 = bytes[6] == '\x02';
    const std::size_t prefix = v2 ? 12 : 10;
    std::size_t hlen = 0;
    for (std::size_t k = prefix; k-- > 8;) hlen = hlen * 256 + static_cast<unsigned char>(bytes[k]);
    EXPECT_EQ(v2, dims >= 22000) << dims; // about 3 header bytes an axis
    EXPECT_EQ(bytes.size(), prefix + hlen + 4) << dims;
    EXPECT_EQ((prefix + hlen) % 64, 0u);
    EXPECT_EQ(bytes[prefix + hlen - 1], '\n');
    const NpyArray b = parse_npy(bytes, "mem");
    EXPECT_EQ(b.shape, shape);
    EXPECT_EQ(b.dtype, DType::I16);
    EXPECT_EQ(b.bytes, a.bytes);
  }
  // And through a file.
  auto dir = test::scratch_dir("npy");
  std::vector<std::int64_t> shape(30000, 1);
  write_npy((dir / "long.npy").string(), make_npy(DType::U8, shape, {42}));
  auto back = read_npy((dir / "long.npy").string());
  EXPECT_EQ(back.shape, shape);
  EXPECT_EQ(back.get(0), 42);
  std::filesystem::remove_all(dir);
}

// A header may announce any shape: the data size (a product checked against overflow) is
// compared with the bytes present before anything is allocated, so a 100-byte file claiming
// 2^40 elements, or a product past 2^64, is an immediate error.
// Found by the npy fuzzer (kept in tests/fuzz/regressions/npy): an empty array whose other
// extents multiply past 2^63 passed the size check (0 elements) and overflowed count().
TEST(NpyIo, RegressionEmptyArrayWithHugeExtentsIsRefused) {
  try {
    parse_npy(npy_bytes("{'descr': '<u2', 'fortran_order': False, 'shape': (4, 1, 88, 8, 8898, "
                        "88, 8, 888, 8, 88884, 0, 8, 8, 778, 8888, 8), }",
                        ""),
              "mem");
    ADD_FAILURE() << "accepted";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("too large"), std::string::npos) << e.what();
  }
  // A small empty array is fine and counts 0 elements.
  const NpyArray a = parse_npy(
      npy_bytes("{'descr': '<u2', 'fortran_order': False, 'shape': (4, 0, 3), }", ""), "mem");
  EXPECT_EQ(a.count(), 0);
}

// Found by the npy fuzzer (kept in tests/fuzz/regressions/npy): a uint64 value past 2^63 - 1
// was refused by npy_to_int64 with a message that named neither the file nor the element.
TEST(NpyIo, RegressionUint64PastInt64NamesFileAndElement) {
  std::string data(24, '\0');
  const std::uint64_t values[3] = {7, ~std::uint64_t{4}, 9};
  std::memcpy(data.data(), values, 24);
  const NpyArray a =
      parse_npy(npy_bytes("{'descr': '<u8', 'fortran_order': False, 'shape': (3,), }", data), "m");
  try {
    npy_to_int64(a, {}, "u.npy");
    ADD_FAILURE() << "accepted";
  } catch (const IoError& e) {
    EXPECT_EQ(std::string(e.what()),
              "u.npy: element 1: uint64 value 18446744073709551611 does not fit int64");
  }
  // The mask needs no conversion: nonzero bytes are object voxels.
  EXPECT_EQ(npy_to_mask(a, {}, "u.npy").values(), (std::vector<std::uint8_t>{1, 1, 1}));
}

TEST(NpyIo, HeaderSizesAreCheckedBeforeAllocation) {
  auto expect_error = [](const std::string& bytes, const std::string& msg) {
    try {
      parse_npy(bytes, "mem");
      ADD_FAILURE() << "accepted";
    } catch (const IoError& e) {
      EXPECT_NE(std::string(e.what()).find(msg), std::string::npos) << e.what();
    }
  };
  expect_error(npy_bytes("{'descr': '<i8', 'fortran_order': False, 'shape': (1099511627776,), }",
                         "12345678"),
               "truncated data: 8 bytes");
  expect_error(npy_bytes("{'descr': '<i8', 'fortran_order': False, 'shape': (4294967296, "
                         "4294967296, 4294967296), }",
                         ""),
               "shape too large");
  expect_error(npy_bytes("{'descr': '<i8', 'fortran_order': False, 'shape': "
                         "(99999999999999999999,), }",
                         ""),
               "too large");
  // Issue #18: 'shape': } threw std::out_of_range (an abort of the command line).
  expect_error(npy_bytes("{'descr': '<i8', 'fortran_order': False, 'shape': }", ""),
               "malformed npy header");
  expect_error(npy_bytes("{'descr': '<i8', 'fortran_order': False, 'shape': (-1,), }", ""),
               "malformed npy header");
  expect_error(
      npy_bytes("{'descr': '<i8', 'descr': '<i8', 'fortran_order': False, 'shape': (), }", ""),
      "given twice");
  expect_error(
      npy_bytes("{'descr': '<i8', 'fortran_order': False, 'shape': (1,), 'x': 1}", "12345678"),
      "unknown key");
  expect_error(std::string("\x93NUMPY\x02\x00\xff\xff\xff\xff{", 13), "truncated npy header");
  expect_error(std::string("\x93NUMPY\x07\x00\x00\x00", 10), "version 7");
  // Leading zeros in a shape are decimal.
  auto a = parse_npy(npy_bytes("{'descr': '|u1', 'fortran_order': False, 'shape': (010,), }",
                               std::string(10, 'x')),
                     "mem");
  EXPECT_EQ(a.shape, (std::vector<std::int64_t>{10}));
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
