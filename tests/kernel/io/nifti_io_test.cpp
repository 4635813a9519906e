// NIfTI through the reference library, checked against nibabel (Debian python3-nibabel) as
// the independent reader and writer.
#include <zdg/kernel/io/nifti_io.hpp>

#include "tests/support/cli.hpp"
#include "tests/support/corrupt_zlib.hpp"
#include "tests/support/nifti_bytes.hpp"
#include "tests/support/peak_memory.hpp"
#include "tests/support/python.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>

#include <zlib.h>

namespace zdg {
namespace {

namespace fs = std::filesystem;

void spit(const fs::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary) << bytes;
}

// A volume of dtype t with values from `seed` (every byte pattern allowed for integers;
// finite values for floats).
ScalarVolume sample_volume(DType t, std::vector<std::int64_t> shape, unsigned seed) {
  NpyArray a;
  a.dtype = t;
  a.shape = std::move(shape);
  a.bytes.resize(static_cast<std::size_t>(a.count()) * dtype_size(t));
  std::uint64_t x = seed * 0x9E3779B97F4A7C15ull + 1;
  for (std::size_t i = 0; i < a.bytes.size(); ++i) {
    x ^= x << 13;
    x ^= x >> 7;
    x ^= x << 17;
    a.bytes[i] = static_cast<unsigned char>(x);
  }
  if (t == DType::F32) {
    for (std::int64_t i = 0; i < a.count(); ++i) {
      const float f = static_cast<float>(i) * 0.25f - 3.0f;
      std::memcpy(a.bytes.data() + 4 * i, &f, 4);
    }
  }
  if (t == DType::F64) {
    for (std::int64_t i = 0; i < a.count(); ++i) {
      const double f = std::sin(static_cast<double>(i) + seed) * 1e3;
      std::memcpy(a.bytes.data() + 8 * i, &f, 8);
    }
  }
  return make_scalar_volume(std::move(a));
}

const DType kNiftiTypes[] = {DType::U8,  DType::I8,  DType::U16, DType::I16, DType::U32,
                             DType::I32, DType::U64, DType::I64, DType::F32, DType::F64};

// Round-trip theorem: read(write(V)) keeps the dtype, the shape, the bytes, and spacing,
// origin and scaling as float32 (NIfTI-1 stores them so); write(read(F)) = F byte for byte,
// compressed or not.
RC_GTEST_PROP(NiftiIo, RoundTripIsBitIdentical, ()) {
  const DType t =
      *rc::gen::elementOf(std::vector<DType>(std::begin(kNiftiTypes), std::end(kNiftiTypes)));
  const int d = *rc::gen::inRange(2, 4);
  const auto shape = *rc::gen::container<std::vector<std::int64_t>>(static_cast<std::size_t>(d),
                                                                    rc::gen::inRange(1, 6));
  ScalarVolume v = sample_volume(t, shape, *rc::gen::inRange(0u, 1000u));
  for (int k = 0; k < d; ++k) {
    v.spacing[static_cast<std::size_t>(k)] = *rc::gen::inRange(1, 400) / 100.0;
    v.origin[static_cast<std::size_t>(k)] = *rc::gen::inRange(-500, 500) / 10.0;
  }
  if (*rc::gen::arbitrary<bool>()) {
    v.slope = *rc::gen::inRange(1, 50) / 8.0;
    v.inter = *rc::gen::inRange(-100, 100) / 4.0;
  }
  const bool gz = *rc::gen::arbitrary<bool>();
  const auto dir = test::scratch_dir("nifti");
  const std::string a = (dir / (gz ? "a.nii.gz" : "a.nii")).string();
  const std::string b = (dir / (gz ? "b.nii.gz" : "b.nii")).string();
  write_nifti(a, v);
  const ScalarVolume back = read_nifti(a);
  RC_ASSERT(back.array.dtype == t);
  RC_ASSERT(back.array.shape == shape);
  RC_ASSERT(back.array.bytes == v.array.bytes);
  RC_ASSERT(back.lower == std::vector<std::int64_t>(static_cast<std::size_t>(d), 0));
  for (int k = 0; k < d; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    RC_ASSERT(back.spacing[kk] == static_cast<double>(static_cast<float>(v.spacing[kk])));
    RC_ASSERT(back.origin[kk] == static_cast<double>(static_cast<float>(v.origin[kk])));
  }
  RC_ASSERT(back.slope == static_cast<double>(static_cast<float>(v.slope)));
  RC_ASSERT(back.inter == static_cast<double>(static_cast<float>(v.inter)));
  write_nifti(b, back);
  RC_ASSERT(test::read_file(a) == test::read_file(b));
  fs::remove_all(dir);
}

TEST(NiftiIo, BoolIsStoredAsUint8AndNamesAreChecked) {
  const auto dir = test::scratch_dir("nifti");
  ScalarVolume v = sample_volume(DType::U8, {2, 3}, 1);
  for (auto& b : v.array.bytes) b &= 1;
  v.array.dtype = DType::Bool;
  write_nifti((dir / "m.nii").string(), v);
  const auto back = read_nifti((dir / "m.nii").string());
  EXPECT_EQ(back.array.dtype, DType::U8);
  EXPECT_EQ(back.array.bytes, v.array.bytes);
  EXPECT_THROW(write_nifti((dir / "m.img").string(), v), IoError);
  EXPECT_THROW(read_nifti((dir / "m.hdr").string()), IoError);
  EXPECT_THROW(read_nifti((dir / "missing.nii").string()), IoError);
  fs::remove_all(dir);
}

// What we write, nibabel reads: dtype, shape (nibabel's (x, y, z) is our (z, y, x)
// reversed), pixdim, scaling, the qform offset and every value.
TEST(NiftiIo, NibabelReadsWhatZdgWrites) {
  if (!test::python_has("nibabel, numpy")) GTEST_SKIP() << "python3-nibabel is not installed";
  const auto dir = test::scratch_dir("nifti");
  // One Python run reads every file (importing nibabel costs about a second).
  const std::string code = R"(
import sys, json, numpy as np, nibabel as nib
out = []
for path in sys.argv[1:]:
    img = nib.load(path)
    raw = np.asarray(img.dataobj.get_unscaled())
    slope, inter = img.dataobj.slope, img.dataobj.inter  # nibabel moves scl_* there on load
    out.append({"dtype": str(img.header.get_data_dtype().newbyteorder('<')),
      "shape": list(raw.shape), "pixdim": [float(x) for x in img.header['pixdim'][1:raw.ndim + 1]],
      "slope": float(slope), "inter": float(inter),
      "offset": [float(x) for x in img.affine[:3, 3]],
      "bytes": np.ascontiguousarray(raw.transpose()).astype(raw.dtype.newbyteorder('<')).tobytes().hex()})
print(json.dumps(out))
)";
  const char* names[] = {"uint8", "int8",   "uint16", "int16",   "uint32",
                         "int32", "uint64", "int64",  "float32", "float64"};
  std::vector<ScalarVolume> written;
  std::vector<std::string> paths, expected_dtype;
  int i = 0;
  for (std::size_t ti = 0; ti < std::size(kNiftiTypes); ++ti) {
    for (bool gz : {false, true}) {
      ScalarVolume v = sample_volume(kNiftiTypes[ti],
                                     i % 2 == 0 ? std::vector<std::int64_t>{3, 4, 5}
                                                : std::vector<std::int64_t>{4, 5},
                                     static_cast<unsigned>(i));
      v.spacing.back() = 0.5;
      v.spacing.front() = 2.25;
      v.origin.back() = -10.5;
      if (i % 3 == 0) {
        v.slope = 2.5;
        v.inter = -1.0;
      }
      paths.push_back((dir / (std::to_string(i) + (gz ? ".nii.gz" : ".nii"))).string());
      write_nifti(paths.back(), v);
      written.push_back(v);
      expected_dtype.push_back(names[ti]);
      ++i;
    }
  }
  const auto r = test::run_python(code, paths);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto all = nlohmann::json::parse(r.out);
  ASSERT_EQ(all.size(), written.size());
  for (std::size_t k = 0; k < written.size(); ++k) {
    SCOPED_TRACE(paths[k]);
    const auto& v = written[k];
    const auto& j = all[k];
    EXPECT_EQ(j["dtype"], expected_dtype[k]);
    std::vector<std::int64_t> shape(v.array.shape.rbegin(), v.array.shape.rend());
    EXPECT_EQ(j["shape"].get<std::vector<std::int64_t>>(), shape);
    std::vector<double> pixdim(v.spacing.rbegin(), v.spacing.rend());
    EXPECT_EQ(j["pixdim"].get<std::vector<double>>(), pixdim);
    EXPECT_EQ(j["offset"][0].get<double>(), -10.5);
    EXPECT_EQ(j["slope"].get<double>(), v.slope);
    EXPECT_EQ(j["inter"].get<double>(), v.inter);
    std::string hex;
    for (unsigned char c : v.array.bytes) {
      const char* digits = "0123456789abcdef";
      hex.push_back(digits[c >> 4]);
      hex.push_back(digits[c & 15]);
    }
    EXPECT_EQ(j["bytes"], hex);
  }
  fs::remove_all(dir);
}

// What nibabel writes, we read: the physical values slope * stored + inter (compared with
// nibabel's get_fdata), pixdim as spacing, a big-endian file, NIfTI-2, 2D images.
TEST(NiftiIo, ZdgReadsWhatNibabelWrites) {
  if (!test::python_has("nibabel, numpy")) GTEST_SKIP() << "python3-nibabel is not installed";
  const auto dir = test::scratch_dir("nifti");
  const std::string code = R"(
import sys, numpy as np, nibabel as nib
d = sys.argv[1]
rng = np.random.default_rng(7)
def save(name, data, cls=nib.Nifti1Image, slope=None, inter=None, dtype=None, zooms=None):
    img = cls(data, np.diag([1.0, 1.0, 1.0, 1.0]))
    if dtype is not None: img.set_data_dtype(dtype)
    if zooms is not None: img.header.set_zooms(zooms)
    if slope is not None: img.header.set_slope_inter(slope, inter)
    nib.save(img, d + '/' + name)
    back = nib.load(d + '/' + name)
    np.ascontiguousarray(back.get_fdata(dtype=np.float64).transpose()).tofile(d + '/' + name + '.f64')
save('i16.nii', rng.integers(-300, 300, size=(5, 4, 3)).astype(np.int16), slope=2.0, inter=-3.0, zooms=(0.5, 0.75, 1.5))
save('f32.nii.gz', rng.normal(size=(6, 5, 4)).astype(np.float32), zooms=(1.0, 2.0, 3.0))
save('u16.nii.gz', rng.integers(0, 60000, size=(3, 3, 3)).astype(np.uint16))
save('big.nii', rng.integers(-3000, 3000, size=(4, 3, 2)).astype('>i2'), dtype='>i2')
save('n2.nii', rng.integers(0, 255, size=(4, 3, 5)).astype(np.uint8), cls=nib.Nifti2Image)
save('flat.nii', rng.integers(0, 2, size=(7, 5)).astype(np.uint8))
save('f64.nii', rng.normal(size=(2, 3, 4)), zooms=(0.1, 0.2, 0.3))
)";
  const auto r = test::run_python(code, {dir.string()});
  ASSERT_EQ(r.status, 0) << r.err;
  for (const std::string name :
       {"i16.nii", "f32.nii.gz", "u16.nii.gz", "big.nii", "n2.nii", "flat.nii", "f64.nii"}) {
    SCOPED_TRACE(name);
    const auto v = read_nifti((dir / name).string());
    const std::string expected = test::read_file(dir / (name + ".f64"));
    ASSERT_EQ(expected.size(), static_cast<std::size_t>(v.count()) * 8);
    for (std::int64_t i = 0; i < v.count(); ++i) {
      double e = 0;
      std::memcpy(&e, expected.data() + 8 * i, 8);
      ASSERT_EQ(v.value(i), e) << "voxel " << i;
    }
    if (name == "i16.nii") {
      EXPECT_EQ(v.array.dtype, DType::I16);
      EXPECT_EQ(v.array.shape, (std::vector<std::int64_t>{3, 4, 5}));
      EXPECT_EQ(v.spacing, (std::vector<double>{1.5, 0.75, 0.5}));
      EXPECT_EQ(v.slope, 2.0);
      EXPECT_EQ(v.inter, -3.0);
    }
    if (name == "big.nii") {
      EXPECT_EQ(v.array.dtype, DType::I16);
    }
    if (name == "flat.nii") {
      EXPECT_EQ(v.array.shape, (std::vector<std::int64_t>{5, 7}));
    }
    if (name == "f64.nii") {
      EXPECT_NEAR(v.spacing[0], 0.3, 1e-7);
      EXPECT_NEAR(v.spacing[2], 0.1, 1e-7);
    }
  }
  fs::remove_all(dir);
}

void expect_io_error(const std::string& path, const std::string& words) {
  try {
    read_nifti(path);
    ADD_FAILURE() << path << " was read; expected: " << words;
  } catch (const IoError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(path, 0), 0u) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    EXPECT_NE(what.find(words), std::string::npos) << what << " (expected '" << words << "')";
  }
}

template <class T>
void patch(std::string& bytes, std::size_t offset, T value) {
  std::memcpy(bytes.data() + offset, &value, sizeof(T));
}

// Bad files: one IoError on one line naming the file; the sizes of the header are checked
// against the file before anything is allocated.
TEST(NiftiIo, BadFilesAreOneLineErrors) {
  const auto dir = test::scratch_dir("nifti");
  const ScalarVolume v = sample_volume(DType::I16, {6, 7, 8}, 3);
  write_nifti((dir / "good.nii").string(), v);
  write_nifti((dir / "good.nii.gz").string(), v);
  const std::string nii = test::read_file(dir / "good.nii");
  const std::string gz = test::read_file(dir / "good.nii.gz");
  ASSERT_EQ(nii.size(), 352u + 6 * 7 * 8 * 2);

  spit(dir / "short.nii", nii.substr(0, nii.size() - 10));
  expect_io_error((dir / "short.nii").string(), "but the file has 1014 bytes");
  spit(dir / "header_only.nii", nii.substr(0, 200));
  expect_io_error((dir / "header_only.nii").string(), "not a NIfTI-1/2 file");
  spit(dir / "cut.nii.gz", gz.substr(0, gz.size() / 2));
  expect_io_error((dir / "cut.nii.gz").string(), "truncated or corrupt NIfTI data");
  std::string garbled = gz;
  for (std::size_t i = 40; i < garbled.size() - 8; i += 7)
    garbled[i] = static_cast<char>(~garbled[i]);
  spit(dir / "garbled.nii.gz", garbled);
  expect_io_error((dir / "garbled.nii.gz").string(), "garbled.nii.gz");
  // Every byte decompresses but the gzip CRC is wrong: refused (the reader reads to the
  // trailer), on a volume large enough that the header read does not reach it.
  const ScalarVolume big = sample_volume(DType::U8, {64, 64, 64}, 7);
  write_nifti((dir / "big.nii.gz").string(), big);
  std::string crc = test::read_file(dir / "big.nii.gz");
  crc[crc.size() - 8] = static_cast<char>(crc[crc.size() - 8] ^ 0x55);
  spit(dir / "crc.nii.gz", crc);
  expect_io_error((dir / "crc.nii.gz").string(), "truncated or corrupt NIfTI data");
  spit(dir / "text.nii", std::string(400, 'x'));
  expect_io_error((dir / "text.nii").string(), "not a NIfTI-1/2 file");
  spit(dir / "empty.nii", "");
  expect_io_error((dir / "empty.nii").string(), "empty file");

  // NIfTI-1 dims (int16 at byte 40): 32767^3 voxels of int16 in a 1 KB file.
  std::string huge = nii;
  patch<std::int16_t>(huge, 42, 32767);
  patch<std::int16_t>(huge, 44, 32767);
  patch<std::int16_t>(huge, 46, 32767);
  spit(dir / "huge.nii", huge);
  expect_io_error((dir / "huge.nii").string(), "bytes from offset 352) but the file has");
  spit(dir / "huge.nii.gz", huge); // not gzip, but named so: the bound on deflate applies
  expect_io_error((dir / "huge.nii.gz").string(), "compressed bytes can hold at most");
  // A 4-D dataset.
  std::string four = nii;
  patch<std::int16_t>(four, 40, 4);
  patch<std::int16_t>(four, 48, 2);
  spit(dir / "four.nii", four);
  expect_io_error((dir / "four.nii").string(), "4-D or larger");
  // Complex data.
  std::string complex = nii;
  patch<std::int16_t>(complex, 70, 32); // DT_COMPLEX64
  patch<std::int16_t>(complex, 72, 64);
  spit(dir / "complex.nii", complex);
  expect_io_error((dir / "complex.nii").string(), "is not supported");
  fs::remove_all(dir);
}

// NIfTI-2 dims are int64: a product past 2^63 is refused before anything else happens.
TEST(NiftiIo, Nifti2DimsWhoseProductOverflows) {
  if (!test::python_has("nibabel, numpy")) GTEST_SKIP() << "python3-nibabel is not installed";
  const auto dir = test::scratch_dir("nifti");
  const auto r = test::run_python(R"(
import sys, numpy as np, nibabel as nib
nib.save(nib.Nifti2Image(np.zeros((2, 2, 2), np.uint8), np.eye(4)), sys.argv[1])
)",
                                  {(dir / "n2.nii").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  std::string n2 = test::read_file(dir / "n2.nii");
  ASSERT_GT(n2.size(), 540u);
  for (int k = 1; k <= 3; ++k)
    patch<std::int64_t>(n2, 16 + 8 * static_cast<std::size_t>(k), std::int64_t{1} << 40);
  spit(dir / "over.nii", n2);
  expect_io_error((dir / "over.nii").string(), "more than 2^62 bytes");
  fs::remove_all(dir);
}

// ---- Issue #41 items 1, 5 and 8: the header is checked by zdg before the library sees it.

void spit_gz(const fs::path& p, const std::string& bytes) {
  gzFile f = gzopen(p.string().c_str(), "wb6");
  ASSERT_NE(f, nullptr);
  if (!bytes.empty()) gzwrite(f, bytes.data(), static_cast<unsigned>(bytes.size()));
  gzclose(f);
}

// The field at `off` of a hand-built NIfTI-2 file (little-endian), replaced.
template <class T>
std::string with(std::string bytes, std::size_t off, T v) {
  patch<T>(bytes, off, v);
  return bytes;
}

// Reads `path` in a child process: "ok", the IoError's text, or (crash) finished = false.
test::ChildMemory read_in_child(const std::string& path) {
  return test::run_in_child_measuring_memory([&] {
    try {
      read_nifti(path);
      return std::string("ok");
    } catch (const IoError& e) {
      return std::string(e.what());
    }
  });
}

void expect_refused_in_child(const std::string& path, const std::string& words) {
  const auto r = read_in_child(path);
  ASSERT_TRUE(r.finished) << path << ": the reader crashed";
  EXPECT_EQ(r.result.rfind(path + ": ", 0), 0u) << r.result;
  EXPECT_EQ(r.result.find('\n'), std::string::npos) << r.result;
  EXPECT_NE(r.result.find(words), std::string::npos) << r.result << " (expected '" << words << "')";
}

TEST(NiftiIo, HandBuiltNifti2ReadsInBothByteOrders) {
  const auto dir = test::scratch_dir("nifti");
  for (const bool big : {false, true}) {
    for (const bool gz : {false, true}) {
      const fs::path p = dir / (std::string(big ? "big" : "little") + (gz ? ".nii.gz" : ".nii"));
      const std::string f = test::nifti2_bytes(5, 4, 3, big);
      gz ? spit_gz(p, f) : spit(p, f);
      const auto v = read_nifti(p.string());
      EXPECT_EQ(v.array.dtype, DType::U8);
      EXPECT_EQ(v.array.shape, (std::vector<std::int64_t>{3, 4, 5}));
      EXPECT_EQ(std::string(v.array.bytes.begin(), v.array.bytes.end()), f.substr(544)) << p;
    }
  }
  fs::remove_all(dir);
}

// Item 5: dim[0] outside 1..7 (2^31 crashed the process inside the library's conversion,
// which loops up to dim[0] over an 8-entry array) and every other field the library or the
// reader trusts: one error naming the file, in a child so that a crash fails the test.
TEST(NiftiIo, Nifti2HeaderFieldsAreCheckedBeforeTheLibrary) {
  const auto dir = test::scratch_dir("nifti");
  const std::string good = test::nifti2_bytes(4, 3, 2);
  struct Case {
    std::string name, bytes, words;
  };
  const std::int64_t big = std::int64_t{1} << 31;
  std::string bad_magic = good;
  bad_magic[8] = '\n'; // "\r\n\032\n" damaged as by a text-mode transfer (CR to LF)
  std::string pair = good;
  pair[5] = 'i';
  const Case cases[] = {
      {"dim0_2p31", with<std::int64_t>(good, 16, big), "NIfTI dim[0] = 2147483648 (1..7)"},
      {"dim0_2p32", with<std::int64_t>(good, 16, (big << 1) + 3),
       "NIfTI dim[0] = 4294967299 (1..7)"},
      {"dim0_neg", with<std::int64_t>(good, 16, -1), "NIfTI dim[0] = -1 (1..7)"},
      {"dim0_min", with<std::int64_t>(good, 16, INT64_MIN), "NIfTI dim[0] = -9223372036854775808"},
      {"dim0_zero", with<std::int64_t>(good, 16, 0), "NIfTI dim[0] = 0 (1..7)"},
      {"dim0_8", with<std::int64_t>(good, 16, 8), "NIfTI dim[0] = 8 (1..7)"},
      {"dim2_zero", with<std::int64_t>(good, 32, 0), "dim[2] = 0 is not positive"},
      {"dim3_neg", with<std::int64_t>(good, 40, -5), "dim[3] = -5 is not positive"},
      {"dim_huge", with<std::int64_t>(good, 24, std::int64_t{1} << 62), "more than 2^62 bytes"},
      {"bitpix", with<std::int16_t>(good, 14, 16), "bitpix 16 disagrees with the datatype uint8"},
      {"datatype", with<std::int16_t>(good, 12, 0), "datatype 0"},
      {"sizeof", with<std::int32_t>(good, 0, 541), "sizeof_hdr 541, 348 or 540"},
      {"magic", bad_magic, "check bytes"},
      {"pair", pair, ".hdr/.img pair"},
      {"short_header", good.substr(0, 500), "truncated NIfTI-2 header (500 of 540 bytes)"},
      {"off_zero", with<std::int64_t>(good, 168, 0), "vox_offset 0 is not in [544, 2^62]"},
      {"off_540", with<std::int64_t>(good, 168, 540), "vox_offset 540 is not in [544"},
      {"off_neg", with<std::int64_t>(good, 168, -544), "vox_offset -544"},
      {"off_huge", with<std::int64_t>(good, 168, INT64_MAX), "vox_offset 9223372036854775807"},
      {"off_past", with<std::int64_t>(good, 168, 560), "from offset 560) but the file has"},
      {"pixdim_nan", with<double>(good, 112, std::nan("")), "pixdim[1] = nan"},
      {"pixdim_inf", with<double>(good, 120, HUGE_VAL), "pixdim[2] = inf"},
      {"inter_nan", with<double>(with<double>(good, 176, 2.0), 184, std::nan("")),
       "scl_inter nan is not finite"},
      {"qoffset_nan", with<double>(with<std::int32_t>(good, 344, 1), 384, std::nan("")),
       "qoffset nan"},
      {"srow_inf", with<double>(with<std::int32_t>(good, 348, 1), 400 + 24, -HUGE_VAL),
       "srow translation -inf"},
  };
  for (const auto& c : cases) {
    for (const bool gz : {false, true}) {
      const fs::path p = dir / (c.name + (gz ? ".nii.gz" : ".nii"));
      gz ? spit_gz(p, c.bytes) : spit(p, c.bytes);
      std::string words = c.words;
      if (gz && c.name == "off_past") words = "truncated or corrupt NIfTI data (8 of 24 bytes)";
      expect_refused_in_child(p.string(), words);
    }
  }
  fs::remove_all(dir);
}

// Item 1: NIfTI-1's float vox_offset of 0, negative, NaN, infinite, 1e30, fractional or
// inside the header was clamped to 348 by the library and the voxels read 4 bytes early
// (exit 0, wrong data). Each is refused; 352 + 16 with 16 bytes of extension space reads.
TEST(NiftiIo, Nifti1VoxOffsetIsChecked) {
  const auto dir = test::scratch_dir("nifti");
  const ScalarVolume v = sample_volume(DType::U8, {2, 3, 4}, 5);
  write_nifti((dir / "good.nii").string(), v);
  const std::string good = test::read_file(dir / "good.nii");
  ASSERT_EQ(good.size(), 352u + 24);
  const float bad[] = {0.0f,  -16.0f, std::nanf(""), HUGE_VALF, -HUGE_VALF,
                       1e30f, 348.0f, 351.0f,        352.5f,    3e9f};
  for (const float off : bad) {
    for (const bool gz : {false, true}) {
      const fs::path p = dir / (gz ? "off.nii.gz" : "off.nii");
      gz ? spit_gz(p, with<float>(good, 108, off)) : spit(p, with<float>(good, 108, off));
      expect_io_error(p.string(), "is not an integer in [352, 2^31)");
    }
  }
  // One float past the file (the data does not fit after it).
  spit(dir / "past.nii", with<float>(good, 108, 368.0f));
  expect_io_error((dir / "past.nii").string(), "from offset 368) but the file has 376 bytes");
  // An extension area of 16 bytes: the voxels start at 368 and read back exactly.
  std::string ext = with<float>(good, 108, 368.0f);
  ext.insert(352, std::string(16, '\x07'));
  for (const bool gz : {false, true}) {
    const fs::path p = dir / (gz ? "ext.nii.gz" : "ext.nii");
    gz ? spit_gz(p, ext) : spit(p, ext);
    EXPECT_EQ(read_nifti(p.string()).array.bytes, v.array.bytes) << p;
  }
  // dim[0] in neither byte order, a .hdr/.img pair's magic, ANALYZE (no magic), bitpix.
  spit(dir / "d0.nii", with<std::int16_t>(good, 40, 1000));
  expect_io_error((dir / "d0.nii").string(), "NIfTI dim[0] = 1000 (1..7)");
  spit(dir / "d0neg.nii", with<std::int16_t>(good, 40, -3));
  expect_io_error((dir / "d0neg.nii").string(), "NIfTI dim[0] = -3 (1..7)");
  std::string pair = good;
  pair[345] = 'i';
  spit(dir / "pair.nii", pair);
  expect_io_error((dir / "pair.nii").string(), ".hdr/.img pair");
  std::string analyze = good;
  std::memset(analyze.data() + 344, 0, 4);
  spit(dir / "analyze.nii", analyze);
  expect_io_error((dir / "analyze.nii").string(), "ANALYZE 7.5");
  spit(dir / "bitpix.nii", with<std::int16_t>(good, 72, 16));
  expect_io_error((dir / "bitpix.nii").string(), "bitpix 16 disagrees");
  fs::remove_all(dir);
}

// Item 8: a 1 MB .nii.gz claiming 1000^3 uint8 voxels (within deflate's 1032:1 bound) whose
// stream turns to garbage after 4 MiB: the error comes with little memory taken (the whole
// claim, 1 GB, was allocated before); a good .nii.gz of several 16 MiB pieces reads exactly.
TEST(NiftiIo, CorruptGzipTakesMemoryOnlyAsBytesArrive) {
  const auto dir = test::scratch_dir("nifti");
  write_nifti((dir / "one.nii").string(), sample_volume(DType::U8, {1, 1, 1}, 1));
  std::string header = test::read_file(dir / "one.nii").substr(0, 352);
  for (int k = 1; k <= 3; ++k)
    patch<std::int16_t>(header, 40 + 2 * static_cast<std::size_t>(k), 1000);
  const std::string file = test::good_then_garbage(header, std::size_t{4} << 20, 1000000, true);
  ASSERT_LT(file.size(), 1100000u);
  spit(dir / "claim.nii.gz", file);
  const auto r = read_in_child((dir / "claim.nii.gz").string());
  ASSERT_TRUE(r.finished);
  const std::string said = "claim.nii.gz: truncated or corrupt NIfTI data (";
  const auto at = r.result.find(said);
  ASSERT_NE(at, std::string::npos) << r.result;
  // The good bytes it counts: the 4 MiB that inflate, less at most the 1 MiB of the failing read.
  const std::int64_t good = std::stoll(r.result.substr(at + said.size()));
  EXPECT_GE(good, std::int64_t{3} << 20) << r.result;
  EXPECT_LE(good, std::int64_t{4} << 20) << r.result;
  EXPECT_NE(r.result.find(" of 1000000000 bytes"), std::string::npos) << r.result;
  EXPECT_LT(r.growth_kib, 96 * 1024) << "KiB taken by a corrupt 1 MB file";

  const ScalarVolume big = sample_volume(DType::U16, {10, 1024, 1024}, 9);
  write_nifti((dir / "big.nii.gz").string(), big);
  EXPECT_EQ(read_nifti((dir / "big.nii.gz").string()).array.bytes, big.array.bytes);
  fs::remove_all(dir);
}

} // namespace
} // namespace zdg
