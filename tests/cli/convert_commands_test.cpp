// zdg convert: bit-identical round trips between the volume formats, the object mask, and
// the contract on bad input (exit 2, one stderr line naming the file, nothing written, an
// existing output untouched).
#include "tests/support/cli.hpp"
#include <zdg/kernel/io/nifti_io.hpp>
#include <zdg/kernel/io/npy_io.hpp>
#include <zdg/kernel/io/vol_io.hpp>
#include <zdg/kernel/io/volume_io.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

namespace zdg {
namespace {

namespace fs = std::filesystem;

struct Files {
  fs::path dir = test::scratch_dir("convert");
  ~Files() { fs::remove_all(dir); }
  std::string operator()(const std::string& name) const {
    std::string q(1, '\'');
    q.append((dir / name).string());
    q.push_back('\'');
    return q;
  }
  std::string path(const std::string& name) const { return (dir / name).string(); }
  std::string bytes(const std::string& name) const { return test::read_file(dir / name); }
  std::vector<std::string> listing() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename());
    std::sort(names.begin(), names.end());
    return names;
  }
};

// A 3D uint8 ball-like pattern on a lattice box with lower bound 0 (so that .vol's Center
// keys are the ones a conversion through another format gives back).
Image<std::uint8_t> sample(std::int64_t n = 7) {
  Image<std::uint8_t> img(Domain({n, n + 1, n + 2}));
  for (std::int64_t i = 0; i < img.size(); ++i) {
    const auto p = img.domain().point(i);
    const auto r2 = (p[0] - 3) * (p[0] - 3) + (p[1] - 3) * (p[1] - 3) + (p[2] - 4) * (p[2] - 4);
    img[i] = static_cast<std::uint8_t>(r2 <= 9 ? 200 : r2 % 7);
  }
  return img;
}

TEST(ConvertCommand, RoundTripsAreBitIdentical) {
  Files f;
  const auto img = sample();
  write_vol(f.path("a.vol"), img, 3);
  const std::string original = f.bytes("a.vol");
  // vol v3 -> v2 -> v3
  auto r = test::run_zdg("convert " + f("a.vol") + " " + f("b.vol") + " --vol-version 2");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(f.bytes("b.vol"), vol_file_bytes(img, 2));
  r = test::run_zdg("convert " + f("b.vol") + " " + f("c.vol"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(f.bytes("c.vol"), original);
  // vol -> nii -> nii.gz -> npy -> raw -> vol, and back to the same bytes at every step
  const std::vector<std::string> chain = {"d.nii", "e.nii.gz", "f.npy", "g.raw", "h.vol"};
  std::string prev = "a.vol";
  for (const auto& next : chain) {
    const std::string raw =
        prev == "g.raw" ? " --raw-shape 7,8,9 --raw-dtype uint8" : std::string();
    r = test::run_zdg("convert " + f(prev) + " " + f(next) + raw + " --json");
    ASSERT_EQ(r.status, 0) << prev << " -> " << next << ": " << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["output"]["content"], "values");
    EXPECT_EQ(j["input"]["shape"], nlohmann::json::array({"7", "8", "9"}));
    // the reverse conversion reproduces the previous file exactly
    const std::string back = "back_" + prev;
    const std::string raw_back =
        next == "g.raw" ? " --raw-shape 7,8,9 --raw-dtype uint8" : std::string();
    r = test::run_zdg("convert " + f(next) + " " + f(back) + raw_back);
    ASSERT_EQ(r.status, 0) << next << " -> " << back << ": " << r.err;
    EXPECT_EQ(f.bytes(back), f.bytes(prev)) << next << " -> " << prev;
    prev = next;
  }
  EXPECT_EQ(f.bytes("h.vol"), original);
}

TEST(ConvertCommand, SelectionWritesTheMaskAndSpacingIsStored) {
  Files f;
  write_vol(f.path("a.vol"), sample(), 3);
  auto r = test::run_zdg("convert " + f("a.vol") + " " + f("m.nii.gz") +
                         " --threshold 100 --spacing 0.5,0.25,2 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["output"]["content"], "mask");
  EXPECT_EQ(j["input"]["selection"], "value >= 100");
  const auto m = read_nifti(f.path("m.nii.gz"));
  EXPECT_EQ(m.spacing, (std::vector<double>{0.5, 0.25, 2}));
  std::int64_t ones = 0;
  const auto img = sample();
  for (std::int64_t i = 0; i < m.count(); ++i) {
    EXPECT_EQ(m.array.get(i), img[i] >= 100 ? 1 : 0);
    ones += m.array.get(i);
  }
  EXPECT_EQ(j["input"]["voxels"], std::to_string(ones));
  r = test::run_zdg("convert " + f("a.vol") + " " + f("inv.npy") + " --range 1:6 --invert");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto inv = read_npy(f.path("inv.npy"));
  for (std::int64_t i = 0; i < inv.count(); ++i)
    EXPECT_EQ(inv.get(i), img[i] >= 1 && img[i] <= 6 ? 0 : 1);
  EXPECT_EQ(r.out.find("object mask") != std::string::npos, true) << r.out;
  // A 3D array of one slice is the 2D image a PGM holds, and back.
  write_npy(f.path("slice.npy"), make_npy(DType::U8, {1, 2, 3}, {0, 10, 20, 30, 40, 250}));
  r = test::run_zdg("convert " + f("slice.npy") + " " + f("slice.pgm"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(f.bytes("slice.pgm"), std::string("P5\n3 2\n255\n\x00\x0a\x14\x1e\x28\xfa", 17));
  r = test::run_zdg("convert " + f("slice.pgm") + " " + f("flat.npy"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read_npy(f.path("flat.npy")).shape, (std::vector<std::int64_t>{2, 3}));
}

// The contract on bad input: exit status 2, exactly one line on stderr ("zdg: ..." naming the
// file), no file created, an existing output left as it was.
// The cases are split in two tests (bad files, then bad options and outputs) to keep each
// short under the sanitizers.
void check_bad_inputs(bool files_half) {
  Files f;
  write_vol(f.path("a.vol"), sample(), 3);
  const std::string v3 = f.bytes("a.vol");
  const std::size_t payload = v3.find("\n.\n") + 3;
  std::ofstream(f.path("cut.vol"), std::ios::binary) << v3.substr(0, payload + 20);
  std::string corrupt = v3;
  corrupt[payload + 30] = static_cast<char>(corrupt[payload + 30] ^ 0x55);
  std::ofstream(f.path("corrupt.vol"), std::ios::binary) << corrupt;
  write_nifti(f.path("n.nii"), make_scalar_volume(sample()));
  const std::string nii = f.bytes("n.nii");
  std::ofstream(f.path("short.nii"), std::ios::binary) << nii.substr(0, nii.size() - 5);
  write_nifti(f.path("n.nii.gz"), make_scalar_volume(sample()));
  const std::string gz = f.bytes("n.nii.gz");
  std::ofstream(f.path("cut.nii.gz"), std::ios::binary) << gz.substr(0, gz.size() - 40);
  std::string flipped = gz; // the gzip CRC: every byte decompresses, the check must refuse it
  flipped[gz.size() - 8] = static_cast<char>(flipped[gz.size() - 8] ^ 0x55);
  std::ofstream(f.path("corrupt.nii.gz"), std::ios::binary) << flipped;
  std::ofstream(f.path("big.vol"), std::ios::binary)
      << "X: 2147483647\nY: 2147483647\nZ: 2147483647\nVersion: 3\n.\nxxxx";
  std::ofstream(f.path("center.vol"), std::ios::binary)
      << "Center-X: -9223372036854775808\nX: 4\nY: 1\nZ: 1\nVersion: 2\n.\nabcd";
  std::ofstream(f.path("four.raw"), std::ios::binary) << "abcd";
  write_npy(f.path("wide.npy"), make_npy(DType::I16, {1, 2, 2}, {0, 1, 300, 2}));
  write_npy(f.path("flat.npy"), make_npy(DType::U8, {2, 2}, {0, 1, 1, 0}));
  std::ofstream(f.path("existing.vol"), std::ios::binary) << "keep me";
  const std::vector<std::string> before = f.listing();

  struct Case {
    std::string args, message, file;
  };
  const std::string out = f("out.vol");
  const Case cases[] = {
      {"convert " + f("cut.vol") + " " + out, "truncated zlib data", "cut.vol"},
      {"convert " + f("corrupt.vol") + " " + out, "zlib data", "corrupt.vol"},
      {"convert " + f("short.nii") + " " + out, "but the file has", "short.nii"},
      {"convert " + f("cut.nii.gz") + " " + out, "truncated or corrupt NIfTI data", "cut.nii.gz"},
      {"convert " + f("corrupt.nii.gz") + " " + out, "NIfTI", "corrupt.nii.gz"},
      {"convert " + f("big.vol") + " " + out, "more voxels than 2^63 - 1", "big.vol"},
      {"convert " + f("center.vol") + " " + out, "is not in [-2^61, 2^61]", "center.vol"},
      {"convert " + f("four.raw") + " " + out +
           " --raw-shape 3037000500,3037000500,3037000500 "
           "--raw-dtype float64",
       "more than 2^62 bytes", "four.raw"},
      {"convert " + f("four.raw") + " " + out + " --raw-shape 2,3 --raw-dtype uint8",
       "raw file has 4 bytes", "four.raw"},
      {"convert " + f("four.raw") + " " + out + " --raw-shape 2,2", "both --raw-shape and", ""},
      {"convert " + f("a.vol") + " " + out + " --threshold 201", "selects no voxel", "a.vol"},
      {"convert " + f("a.vol") + " " + out + " --label 7.5",
       "selects no voxel (values from 0 to 200)", "a.vol"},
      {"convert " + f("a.vol") + " " + f("missing/out.vol"), "does not exist", "out.vol"},
      {"convert " + f("a.vol") + " " + f("existing.vol"), "exists (use --force", "existing.vol"},
      {"convert " + f("a.vol") + " " + f("a.vol") + " --force", "is the input file", "a.vol"},
      {"convert " + f("a.vol") + " " + f("out.tif"), "unknown volume format", "out.tif"},
      {"convert " + f("missing.vol") + " " + out, "no such file", "missing.vol"},
      {"convert " + f("wide.npy") + " " + out, "value 300 (voxel 2) does not fit", "out.vol"},
      {"convert " + f("flat.npy") + " " + out, ".vol holds 3D volumes", "out.vol"},
      {"convert " + f("a.vol") + " " + f("out.pgm"), "where a 2D one is needed", "a.vol"},
      {"convert " + f("a.vol") + " " + out + " --vol-version 4", "--vol-version", ""},
      {"convert " + f("a.vol") + " " + out + " --threshold nan",
       "--threshold: 'nan' is not a number", ""},
      {"convert " + f("a.vol") + " " + out + " --range 5", "is not LO:HI", ""},
      {"convert " + f("a.vol") + " " + out + " --threshold 1 --label 2", "excludes", ""},
      {"convert " + f("a.vol") + " " + f("out.nii") + " --spacing 1,0,1", "is not positive", ""},
      {"convert " + f("a.vol") + " " + f("out.nii") + " --spacing 1,1", "has 2 entries", ""},
  };
  const std::size_t n = std::size(cases), half = 12;
  for (std::size_t k = files_half ? 0 : half; k < (files_half ? half : n); ++k) {
    const Case& c = cases[k];
    SCOPED_TRACE(c.args);
    const auto r = test::run_zdg(c.args);
    EXPECT_EQ(r.status, 2) << r.out;
    EXPECT_EQ(r.err.rfind("zdg: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    if (!c.file.empty()) {
      EXPECT_NE(r.err.find(c.file), std::string::npos) << r.err;
    }
    EXPECT_EQ(f.listing(), before) << "a file was created or removed";
    EXPECT_EQ(f.bytes("existing.vol"), "keep me");
  }
  if (files_half) return;
  // --force replaces an existing output.
  const auto r = test::run_zdg("convert " + f("a.vol") + " " + f("existing.vol") + " --force");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(f.bytes("existing.vol"), v3);
  EXPECT_EQ(test::run_zdg("convert --help").status, 0);
}

TEST(ConvertCommand, BadFilesAreOneLineExitTwoNothingWritten) {
  check_bad_inputs(true);
}

TEST(ConvertCommand, BadOptionsAndOutputsAreOneLineExitTwoNothingWritten) {
  check_bad_inputs(false);
}

} // namespace
} // namespace zdg
