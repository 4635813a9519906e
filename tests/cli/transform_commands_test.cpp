// zdg transform: JSON summaries, outputs checked against the kernel, error exits.
#include "tests/support/cli.hpp"
#include <zdg/kernel/io/npy_io.hpp>
#include <zdg/kernel/transforms/chamfer_transform.hpp>
#include <zdg/kernel/transforms/distance_transform.hpp>
#include <zdg/kernel/transforms/local_thickness.hpp>
#include <zdg/kernel/transforms/reverse_distance_transform.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>
#include <tuple>

namespace zdg {
namespace {

struct Files {
  std::filesystem::path dir = test::scratch_dir("transform");
  ~Files() { std::filesystem::remove_all(dir); }
  std::string operator()(const std::string& name) const {
    std::string q(1, '\'');
    q.append((dir / name).string());
    q.push_back('\'');
    return q;
  }
  std::string path(const std::string& name) const { return (dir / name).string(); }
};

// A 4 x 5 shape with one background point and a hole pattern.
Image<std::uint8_t> small_shape() {
  return Image<std::uint8_t>(
      Domain({4, 5}),
      std::vector<std::uint8_t>{1, 1, 1, 1, 1, 1, 0, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0, 1});
}

TEST(TransformCommands, DtWritesTheDistanceTransform) {
  Files f;
  auto shape = small_shape();
  write_npy(f.path("in.npy"), make_npy<std::uint8_t>({4, 5}, shape.values()));
  for (const std::string metric : {"l1", "l2", "l3", "linf"}) {
    auto r = test::run_zdg("transform dt " + f("in.npy") + " -o " + f("out.npy") +
                           " --force --metric " + metric + " --torus 1 --threads 2 --json");
    ASSERT_EQ(r.status, 0) << r.err;
    auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["metric"], metric);
    EXPECT_EQ(j["shape"], nlohmann::json::array({4, 5}));
    EXPECT_EQ(j["torus"], nlohmann::json::array({1}));
    EXPECT_EQ(j["dtype"], "uint8");
    TransformOptions opt;
    opt.metric = parse_metric(metric);
    opt.torus = {false, true};
    auto dt = distance_transform<std::int64_t>(shape, opt);
    EXPECT_EQ(npy_to_int64(read_npy(f.path("out.npy"))).values(), dt.values());
    std::int64_t mx = *std::max_element(dt.values().begin(), dt.values().end());
    EXPECT_EQ(j["max_value"], std::to_string(mx));
  }
}

// The JSON reports the workers the transform used (one threads rule, worker_count): one below
// 2^15 points whatever --threads asks, the request above it.
TEST(TransformCommands, ThreadsReportedAreThoseUsed) {
  Files f;
  write_npy(f.path("small.npy"), make_npy<std::uint8_t>({4, 5}, small_shape().values()));
  std::vector<std::uint8_t> big(256 * 256, 1);
  big[0] = 0;
  write_npy(f.path("big.npy"), make_npy<std::uint8_t>({256, 256}, big));
  for (const auto& [input, threads, used] :
       {std::tuple{"small.npy", "2", 1}, std::tuple{"big.npy", "2", 2},
        std::tuple{"big.npy", "1", 1}}) {
    auto r = test::run_zdg("transform dt " + f(input) + " -o " + f("out.npy") +
                           " --force --threads " + threads + " --json");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out)["threads"], used) << input << " --threads " << threads;
  }
}

TEST(TransformCommands, OutputDtypeIsTheNarrowestForTheBound) {
  Files f;
  Image<std::uint8_t> img(Domain({300}), std::uint8_t{1});
  img[0] = 0;
  write_npy(f.path("in.npy"), make_npy<std::uint8_t>({300}, img.values()));
  auto r = test::run_zdg("transform dt " + f("in.npy") + " -o " + f("out.npy") + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["dtype"], "uint32"); // 299^2 > 65535
  EXPECT_EQ(read_npy(f.path("out.npy")).dtype, DType::U32);
  EXPECT_EQ(npy_to_int64(read_npy(f.path("out.npy"))).values()[299], 299 * 299);
  r = test::run_zdg("transform dt " + f("in.npy") + " -o " + f("out.npy") +
                    " --force --metric l1 --json");
  EXPECT_EQ(nlohmann::json::parse(r.out)["dtype"], "uint16");
}

// The mapped path reads an integer .npy of any width in place (nonzero = foreground, negative
// values included), as the general path reads it through npy_to_mask; float inputs take the
// general path (-0.0 is background). Same transform for each.
TEST(TransformCommands, DtReadsEveryDtypeOfTheInput) {
  Files f;
  const std::vector<std::int64_t> values{3, -1, 0, 7, 1, 1, 256, -32768, 1, 1, 0, 1};
  Image<std::uint8_t> mask(Domain({3, 4}));
  for (std::size_t i = 0; i < values.size(); ++i) mask.values()[i] = values[i] != 0 ? 1 : 0;
  const auto expect = distance_transform<std::int64_t>(mask, {});
  for (DType t : {DType::I16, DType::I32, DType::I64}) {
    write_npy(f.path("in.npy"), make_npy(t, {3, 4}, values));
    auto r = test::run_zdg("transform dt " + f("in.npy") + " -o " + f("out.npy") + " --force");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(npy_to_int64(read_npy(f.path("out.npy"))).values(), expect.values()) << dtype_name(t);
  }
  std::vector<double> fv(values.begin(), values.end());
  fv[2] = -0.0;
  write_npy(f.path("in.npy"), make_npy<double>({3, 4}, fv));
  auto r = test::run_zdg("transform dt " + f("in.npy") + " -o " + f("out.npy") + " --force");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(npy_to_int64(read_npy(f.path("out.npy"))).values(), expect.values());
}

// An output larger than the disk allows (here a file-size limit: the same EFBIG/ENOSPC from the
// space reservation) is refused before the transform runs: one line, exit 2, no file left.
TEST(TransformCommands, AnOutputThatDoesNotFitIsOneLineAndNoFile) {
  Files f;
  Image<std::uint8_t> img(Domain({128, 128, 128}), std::uint8_t{1});
  img[0] = 0;
  write_npy(f.path("in.npy"), make_npy<std::uint8_t>({128, 128, 128}, img.values()));
  const std::string err = f.path("err");
  // A 1 MiB limit on the files written (2048 blocks of 512 bytes): the 4 MiB uint16 output does
  // not fit (the 2 MiB input is only read).
  const std::string cmd = "ulimit -f 2048; '" + std::string(test::cli_path()) + "' transform dt " +
                          f("in.npy") + " -o " + f("out.npy") + " 2>'" + err + "'";
  const int raw = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(raw));
  EXPECT_EQ(WEXITSTATUS(raw), 2);
  const std::string text = test::read_file(err);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;
  EXPECT_NE(text.find("does not fit on the disk"), std::string::npos) << text;
  EXPECT_FALSE(std::filesystem::exists(f.path("out.npy")));
  for (const auto& e : std::filesystem::directory_iterator(f.dir)) {
    EXPECT_EQ(e.path().filename().string().find(".zdg-tmp"), std::string::npos) << e.path();
  }
}

TEST(TransformCommands, VoronoiPowerRdtRma) {
  Files f;
  auto shape = small_shape();
  write_npy(f.path("in.npy"), make_npy<std::uint8_t>({4, 5}, shape.values()));
  auto r =
      test::run_zdg("transform voronoi " + f("in.npy") + " -o " + f("vor.npy") + " --lower -2,3");
  ASSERT_EQ(r.status, 0) << r.err;
  auto vor = read_npy(f.path("vor.npy"));
  EXPECT_EQ(vor.shape, (std::vector<std::int64_t>{4, 5, 2}));
  // point (0, 0) of the array is (-2, 3); its nearest background is array (1, 1) = (-1, 4)
  EXPECT_EQ(vor.get(0), -1);
  EXPECT_EQ(vor.get(1), 4);

  r = test::run_zdg("transform rma " + f("in.npy") + " -o " + f("rma.npy") + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  auto rma = read_npy(f.path("rma.npy"));
  ASSERT_EQ(rma.shape.size(), 2u);
  EXPECT_EQ(rma.shape[1], 3);
  EXPECT_EQ(nlohmann::json::parse(r.out)["balls"], rma.shape[0]);
  // the medial balls, as an image of values, rebuild the shape through `zdg transform rdt`
  std::vector<std::int64_t> v(20, 0);
  for (std::int64_t b = 0; b < rma.shape[0]; ++b)
    v[static_cast<std::size_t>(rma.get(3 * b) * 5 + rma.get(3 * b + 1))] = rma.get(3 * b + 2);
  write_npy(f.path("balls.npy"), make_npy<std::int64_t>({4, 5}, v));
  r = test::run_zdg("transform rdt " + f("balls.npy") + " -o " + f("rdt.npy"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(npy_to_mask(read_npy(f.path("rdt.npy"))).values(), shape.values());

  r = test::run_zdg("transform power " + f("balls.npy") + " -o " + f("pow.npy") + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read_npy(f.path("pow.npy")).shape, (std::vector<std::int64_t>{4, 5, 2}));
}

TEST(TransformCommands, PgmAndVolFormats) {
  Files f;
  std::ofstream(f.path("in.pgm")) << "P2\n3 2\n1\n1 1 1\n1 0 1\n";
  auto r = test::run_zdg("transform dt " + f("in.pgm") + " -o " + f("out.pgm"));
  ASSERT_EQ(r.status, 0) << r.err;
  r = test::run_zdg("transform dt " + f("out.pgm") + " -o " + f("out2.npy") + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  std::ofstream(f.path("in.vol"), std::ios::binary) << "X: 3\nY: 1\nZ: 1\nVersion: 2\n.\n"
                                                    << std::string("\x01\x00\x01", 3);
  r = test::run_zdg("transform dt " + f("in.vol") + " -o " + f("out.vol") + " --metric l1");
  ASSERT_EQ(r.status, 0) << r.err;
}

TEST(TransformCommands, ErrorsExitTwoAndLeaveNoOutput) {
  Files f;
  write_npy(f.path("full.npy"), make_npy<std::uint8_t>({3, 3}, std::vector<std::uint8_t>(9, 1)));
  write_npy(f.path("in.npy"), make_npy<std::uint8_t>({4, 5}, small_shape().values()));
  std::ofstream(f.path("empty.npy")) << "";
  struct Case {
    std::string args, message;
  };
  const Case cases[] = {
      {"transform dt " + f("full.npy") + " -o " + f("out.npy"), "no background"},
      {"transform dt " + f("empty.npy") + " -o " + f("out.npy"), "empty file"},
      {"transform dt " + f("in.npy") + " -o " + f("out.npy") + " --metric l0", "p = 0"},
      {"transform dt " + f("in.npy") + " -o " + f("out.npy") + " --torus 2", "axis 2"},
      {"transform dt " + f("in.npy") + " -o " + f("out.npy") + " --lower 1,2,3", "--lower"},
      {"transform dt " + f("in.npy") + " -o " + f("in.npy"), "refusing to overwrite"},
      {"transform dt " + f("missing.npy") + " -o " + f("out.npy"), "missing.npy"},
      {"transform power " + f("in.npy") + " -o " + f("out.npy") + " --metric linf", "linf"},
      {"transform voronoi " + f("in.npy") + " -o " + f("out.pgm"), ".npy"},
  };
  for (const auto& c : cases) {
    auto r = test::run_zdg(c.args);
    EXPECT_EQ(r.status, 2) << c.args;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << " -> " << r.err;
    EXPECT_EQ(r.err.rfind("zdg: ", 0), 0u) << r.err;
    EXPECT_FALSE(std::filesystem::exists(f.path("out.npy"))) << c.args;
  }
  // the input was not touched
  EXPECT_EQ(npy_to_mask(read_npy(f.path("in.npy"))).values(), small_shape().values());
  auto r = test::run_zdg("transform dt --help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("--metric"), std::string::npos);
}

// zdg transform chamfer: the values of the kernel's transform, the mask's error bound in the
// JSON (Borgefors' <5,7,11>: rho_max^2 = 26), the default mask by dimension, and one-line errors.
TEST(TransformCommands, ChamferWritesTheChamferTransform) {
  Files f;
  auto shape = small_shape();
  write_npy(f.path("in.npy"), make_npy<std::uint8_t>({4, 5}, shape.values()));
  auto r = test::run_zdg("transform chamfer " + f("in.npy") + " -o " + f("out.npy") +
                         " --mask 5,7,11 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["command"], "chamfer");
  EXPECT_EQ(j["metric"], "chamfer <5,7,11>");
  EXPECT_EQ(j["mask"], nlohmann::json::array({5, 7, 11}));
  EXPECT_EQ(j["error_bound"]["rho_max_squared"], "26");
  EXPECT_EQ(j["error_bound"]["rho_min_squared"], "121/5");
  EXPECT_EQ(j["dtype"], "uint8");
  const auto expect = chamfer_transform<std::uint64_t>(shape, ChamferMask(2, {5, 7, 11}));
  const auto got = npy_to_int64(read_npy(f.path("out.npy"))).values();
  ASSERT_EQ(got.size(), expect.values().size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(static_cast<std::uint64_t>(got[i]), expect.values()[i]);
  }
  EXPECT_EQ(j["max_value"],
            std::to_string(*std::max_element(expect.values().begin(), expect.values().end())));

  // 3D, default <3,4,5>: one background voxel at a corner of a 3 x 3 x 3 cube; the far corner
  // is 2 vertex moves away.
  std::vector<std::uint8_t> cube(27, 1);
  cube[0] = 0;
  write_npy(f.path("cube.npy"), make_npy<std::uint8_t>({3, 3, 3}, cube));
  r = test::run_zdg("transform chamfer " + f("cube.npy") + " -o " + f("cube_out.npy") + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["metric"], "chamfer <3,4,5>");
  EXPECT_EQ(j["max_value"], "10");

  // Errors: one line, exit 2, no output.
  for (const std::string bad : {" --mask 3,0", " --mask 3,4,5,6", " --mask x", " --mask 3,,4"}) {
    r = test::run_zdg("transform chamfer " + f("in.npy") + " -o " + f("bad.npy") + bad);
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(f.path("bad.npy")));
  }
  write_npy(f.path("line.npy"), make_npy<std::uint8_t>({4}, {1, 0, 1, 1}));
  r = test::run_zdg("transform chamfer " + f("line.npy") + " -o " + f("bad.npy"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("1-D image"), std::string::npos) << r.err;
  r = test::run_zdg("transform chamfer " + f("in.npy") + " -o " + f("out.npy"));
  EXPECT_EQ(r.status, 2) << "an existing output without --force";
}

// zdg serve transform chamfer answers the command's values (the 3 x 3 image with its centre as
// background: axis 3, diagonal 4 with <3,4>).
TEST(TransformCommands, ChamferIsServed) {
  Files f;
  {
    std::ofstream(f.path("request")) << "{\"image\": [[1,1,1],[1,0,1],[1,1,1]], \"mask\": [3, 4]}\n"
                                     << "{\"image\": [[1,0]], \"mask\": [3, 0]}\n";
  }
  const std::string cmd = "'" + std::string(test::cli_path()) + "' serve transform chamfer <" +
                          f("request") + " >" + f("out") + " 2>" + f("err");
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << test::read_file(f.path("err"));
  std::istringstream lines(test::read_file(f.path("out")));
  std::string line;
  ASSERT_TRUE(std::getline(lines, line));
  auto j = nlohmann::json::parse(line);
  EXPECT_EQ(j["distances"], nlohmann::json::parse("[[4,3,4],[3,0,3],[4,3,4]]")) << line;
  EXPECT_EQ(j["metric"], "chamfer <3,4>");
  ASSERT_TRUE(std::getline(lines, line));
  EXPECT_NE(line.find("\"error\""), std::string::npos) << line;
}

// zdg transform thickness: float32 diameters, the kernel's local_thickness; the JSON summary; the
// selection options; an existing output refused without --force.
TEST(TransformCommands, ThicknessWritesTheLocalThickness) {
  Files f;
  // A 9 x 12 image: a 7 x 7 square joined to a bar 3 wide, background around.
  Image<std::uint8_t> shape(Domain({9, 12}), std::uint8_t{0});
  for (std::int64_t y = 1; y <= 7; ++y) {
    for (std::int64_t x = 1; x <= 7; ++x) shape[y * 12 + x] = 1;
  }
  for (std::int64_t y = 3; y <= 5; ++y) {
    for (std::int64_t x = 8; x <= 10; ++x) shape[y * 12 + x] = 1;
  }
  std::vector<std::uint8_t> grey(shape.values());
  for (auto& v : grey) v = v != 0 ? 200 : 10;
  write_npy(f.path("in.npy"), make_npy<std::uint8_t>({9, 12}, grey));
  auto r = test::run_zdg("transform thickness " + f("in.npy") + " --threshold 100 -o " +
                         f("t.npy") + " --threads 2 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["command"], "thickness");
  EXPECT_EQ(j["dtype"], "float32");
  EXPECT_EQ(j["max_value"], "8");
  EXPECT_EQ(j["voxels"], "58");
  const auto a = read_npy(f.path("t.npy"));
  EXPECT_EQ(a.dtype, DType::F32);
  EXPECT_EQ(a.shape, (std::vector<std::int64_t>{9, 12}));
  const auto expected = local_thickness(shape, {});
  std::vector<float> got(expected.values().size());
  for (std::size_t i = 0; i < got.size(); ++i)
    got[i] = static_cast<float>(a.get_double(static_cast<std::int64_t>(i)));
  EXPECT_EQ(got, expected.values());
  EXPECT_EQ(got[4 * 12 + 4], 8.0f);  // the square's centre: DT 16
  EXPECT_EQ(got[4 * 12 + 10], 4.0f); // the bar's end: squared radius 4
  EXPECT_EQ(got[0], 0.0f);
  // Without --force the output stays as it is.
  r = test::run_zdg("transform thickness " + f("in.npy") + " -o " + f("t.npy"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("exists (use --force"), std::string::npos) << r.err;
  r = test::run_zdg("transform thickness " + f("in.npy") + " --threshold 100 -o " + f("t.npy") +
                    " --force");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("zdg transform thickness"), std::string::npos) << r.out;
}

} // namespace
} // namespace zdg
