// zdg surface and zdg contour: topology of known objects through the command line, outputs
// reread by independent readers (numpy for the PLY and the CSV, libpng for the pictures), and
// the contract on bad input (exit 2, one stderr line naming the problem, nothing written, an
// existing output untouched).
#include "tests/support/cli.hpp"
#include "tests/support/png.hpp"
#include "tests/support/python.hpp"
#include <zdg/kernel/io/npy_io.hpp>
#include <zdg/kernel/io/ply_read.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>

namespace zdg {
namespace {

namespace fs = std::filesystem;

struct Files {
  fs::path dir = test::scratch_dir("surface");
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

// A uint8 volume (Z, Y, X) = (n, n, n) of the voxels where f(x, y, z) holds (coordinates
// relative to the centre), saved as .npy.
void save_volume(const std::string& path, std::int64_t n,
                 const std::function<bool(double, double, double)>& f) {
  std::vector<std::int64_t> v(std::size_t(n * n * n));
  const double c = double(n - 1) / 2;
  for (std::int64_t z = 0, i = 0; z < n; ++z)
    for (std::int64_t y = 0; y < n; ++y)
      for (std::int64_t x = 0; x < n; ++x, ++i) v[std::size_t(i)] = f(x - c, y - c, z - c) ? 1 : 0;
  write_npy(path, make_npy(DType::U8, {n, n, n}, v));
}

nlohmann::json run_json(const std::string& args) {
  const auto r = test::run_zdg(args + " --json");
  EXPECT_EQ(r.status, 0) << args << "\n" << r.err;
  return nlohmann::json::parse(r.out);
}

const auto torus = [](double x, double y, double z) {
  const double d = std::sqrt(x * x + y * y) - 6;
  return d * d + z * z <= 6.25;
};
const auto hollow = [](double x, double y, double z) {
  const double r2 = x * x + y * y + z * z;
  return r2 <= 49 && r2 > 9;
};

// --labels all (#38 item 5): a 6 x 6 x 6 volume with a 2 x 2 x 2 cube of label 1 at the origin
// corner and a 2 x 2 x 2 cube of label 7 beside it along x, in a background of 0 (also the
// outside). Cube 1: 24 faces, 4 of them against cube 7; cube 7 likewise: {0,1} 20, {0,7} 20,
// {1,7} 4; each label one component, no tunnel, no cavity.
TEST(SurfaceCommand, LabelsAllGivesTheInterfacesAndEachLabelsTopology) {
  Files f;
  std::vector<std::int64_t> v(216, 0);
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 4; ++x) v[std::size_t((z * 6 + y) * 6 + x)] = x < 2 ? 1 : 7;
  write_npy(f.path("labels.npy"), make_npy(DType::I16, {6, 6, 6}, v));
  const auto j = run_json("surface " + f("labels.npy") + " --labels all");
  EXPECT_EQ(j["background"], "0");
  EXPECT_EQ(j["interfaces"], nlohmann::json::parse(R"([
      {"labels": ["0", "1"], "surfels": "20"},
      {"labels": ["0", "7"], "surfels": "20"},
      {"labels": ["1", "7"], "surfels": "4"}])"));
  ASSERT_EQ(j["labels"].size(), 2u);
  for (const auto& l : j["labels"]) {
    EXPECT_EQ(l["voxels"], "8");
    EXPECT_EQ(l["surfels"], "24");
    EXPECT_EQ(l["betti"], nlohmann::json::parse(R"(["1", "0", "0"])"));
  }
  EXPECT_EQ(j["labels"][1]["label"], "7");
  // Bad uses: one line, exit 2.
  // -o: the interface mesh, one quad per interface surfel.
  const auto m = run_json("surface " + f("labels.npy") + " --labels all -o " + f("m.ply"));
  EXPECT_EQ(m["mesh"]["faces"], "44");
  EXPECT_TRUE(std::filesystem::exists(f.path("m.ply")));
  const std::vector<std::string> bads = {" --labels some", " --labels all --csv " + f("m.csv"),
                                         " --labels all --threshold 3"};
  for (const auto& bad : bads) {
    const auto r = test::run_zdg("surface " + f("labels.npy") + bad);
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("--labels"), std::string::npos) << r.err;
  }
}

TEST(SurfaceCommand, TopologyOfKnownObjects) {
  Files f;
  save_volume(f.path("torus.npy"), 20, torus);
  save_volume(f.path("hollow.npy"), 18, hollow);
  for (const char* adj : {"6,26", "26,6", "6,18", "18,6"}) {
    SCOPED_TRACE(adj);
    auto j = run_json("surface " + f("torus.npy") + " --adjacency " + adj);
    EXPECT_EQ(j["betti"], nlohmann::json({"1", "1", "0"}));
    EXPECT_EQ(j["surfaces"], "1");
    ASSERT_EQ(j["components"].size(), 1u);
    EXPECT_EQ(j["components"][0]["genus"], "1");
    EXPECT_EQ(j["components"][0]["euler"], "0");
    j = run_json("surface " + f("hollow.npy") + " --adjacency " + adj);
    EXPECT_EQ(j["betti"], nlohmann::json({"1", "0", "1"}));
    EXPECT_EQ(j["surfaces"], "2");
    EXPECT_EQ(j["components"][0]["euler"], "4");
    EXPECT_EQ(j["components"][0]["genus"], "0");
    EXPECT_EQ(j["pinched_pointels"], "0");
  }
}

// --harmonic: the dimension of the harmonic 1-forms of each component's closed surfaces,
// from the exact ranks of d0 and d1 (kernel/calculus/harmonic_dimension.hpp), beside the genus
// computed from V - F: 2 genus, summed over the surfaces (torus 2, a slab with two holes 4,
// a hollow ball's two spheres 0); absent without the flag; printed in the text output.
TEST(SurfaceCommand, HarmonicDimensionBesideTheGenus) {
  Files f;
  save_volume(f.path("torus.npy"), 20, torus);
  save_volume(f.path("hollow.npy"), 18, hollow);
  save_volume(f.path("two.npy"), 22, [](double x, double y, double z) {
    const bool slab = std::abs(z) <= 1.5 && std::abs(x) <= 9 && std::abs(y) <= 4.5;
    const bool hole = std::abs(y) <= 1.5 && (std::abs(x - 4.5) <= 1.5 || std::abs(x + 4.5) <= 1.5);
    return slab && !hole;
  });
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"torus.npy", "2"}, {"two.npy", "4"}, {"hollow.npy", "0"}};
  for (const char* adj : {"6,26", "26,6", "6,18", "18,6"}) {
    for (const auto& [name, dim] : cases) {
      SCOPED_TRACE(std::string(adj) + " " + name);
      const auto j = run_json("surface " + f(name) + " --harmonic --adjacency " + adj);
      ASSERT_EQ(j["components"].size(), 1u);
      const auto& c = j["components"][0];
      EXPECT_EQ(c["harmonic_dim"], dim);
      EXPECT_EQ(std::stoll(c["harmonic_dim"].get<std::string>()),
                2 * std::stoll(c["genus"].get<std::string>()));
    }
  }
  const auto plain = run_json("surface " + f("torus.npy"));
  EXPECT_FALSE(plain["components"][0].contains("harmonic_dim"));
  const auto text = test::run_zdg("surface " + f("torus.npy") + " --harmonic --quiet");
  EXPECT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("genus 1, harmonic 1-forms of dimension 2"), std::string::npos)
      << text.out;
}

// Mesh sizes and Euler characteristics: the primal mesh has one quad per surfel and
// V - E + F = the surfaces' sum; marching cubes too (a closed manifold: E = 3F/2).
TEST(SurfaceCommand, MeshesHaveTheSurfacesEuler) {
  Files f;
  save_volume(f.path("hollow.npy"), 18, hollow);
  auto j = run_json("surface " + f("hollow.npy") + " -o " + f("p.ply"));
  EXPECT_EQ(j["mesh"]["faces"], j["surfels"]);
  EXPECT_EQ(j["mesh"]["euler"], "4");
  j = run_json("surface " + f("hollow.npy") + " --mesh marching-cubes -o " + f("m.ply"));
  EXPECT_EQ(j["mesh"]["euler"], "4");
  EXPECT_EQ(j["mesh"]["kind"], "marching-cubes");
  EXPECT_TRUE(fs::exists(f.path("p.ply")));
  EXPECT_TRUE(fs::exists(f.path("m.ply")));
}

// -o OUT.png: a picture of the mesh (kernel/render/render_mesh.hpp), a PNG of the default 1200 x
// 900 pixels (signature and IHDR read back); the JSON still describes the mesh.
TEST(SurfaceCommand, PngOutputIsAPictureOfTheMesh) {
  Files f;
  save_volume(f.path("hollow.npy"), 18, hollow);
  const auto j = run_json("surface " + f("hollow.npy") + " --png " + f("p.png"));
  EXPECT_EQ(j["mesh"]["faces"], j["surfels"]);
  const std::string png = test::read_file(f.path("p.png"));
  ASSERT_GT(png.size(), 24u);
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_EQ(png.substr(12, 4), "IHDR");
  const auto be32 = [&](std::size_t at) {
    std::uint32_t v = 0;
    for (std::size_t i = 0; i < 4; ++i) v = v << 8 | static_cast<unsigned char>(png[at + i]);
    return v;
  };
  EXPECT_EQ(be32(16), 1200u);
  EXPECT_EQ(be32(20), 900u);
}

// The PLY and the CSV read back with numpy: the counts of the JSON, indices in range, the
// per-face ii-mean equal to the CSV's per-surfel column, whose mean is the JSON's.
TEST(SurfaceCommand, OutputsReadBackWithNumpy) {
  if (!test::python_has("numpy")) GTEST_SKIP() << "python3-numpy is not installed";
  Files f;
  save_volume(f.path("ball.npy"), 24,
              [](double x, double y, double z) { return x * x + y * y + z * z <= 81; });
  const auto j = run_json("surface " + f("ball.npy") + " -o " + f("b.ply") + " --csv " +
                          f("b.csv") + " --estimate ii-mean,ii-k1 --radius 4v --threads 2");
  const std::string code = R"(
import sys, numpy as np
data = open(sys.argv[1], 'rb').read()
end = data.index(b'end_header\n') + len(b'end_header\n')
header = data[:end].decode().split('\n')
nv = int([l for l in header if l.startswith('element vertex')][0].split()[2])
nf = int([l for l in header if l.startswith('element face')][0].split()[2])
props = [l.split()[-1] for l in header if l.startswith('property float')]
v = np.frombuffer(data, dtype='<f4', count=3 * nv, offset=end).reshape(nv, 3)
face_fields = props[3:]
dt = np.dtype([('n', 'u1'), ('i', '<i4', (4,))] + [(p, '<f4') for p in face_fields])
faces = np.frombuffer(data, dtype=dt, count=nf, offset=end + 12 * nv)
assert (faces['n'] == 4).all()
assert faces['i'].min() >= 0 and faces['i'].max() < nv
csv = np.genfromtxt(sys.argv[2], delimiter=',', names=True)
assert len(csv) == nf
assert np.allclose(faces['ii_mean'], csv['ii_mean'].astype('<f4'))
print(nv, nf, csv['ii_mean'].mean(), csv['ii_k1'].mean())
)";
  const auto r = test::run_python(code, {f.path("b.ply"), f.path("b.csv")});
  ASSERT_EQ(r.status, 0) << r.err;
  std::istringstream out(r.out);
  std::int64_t nv = 0, nf = 0;
  double mean = 0, k1 = 0;
  out >> nv >> nf >> mean >> k1;
  EXPECT_EQ(std::to_string(nv), j["mesh"]["vertices"].get<std::string>());
  EXPECT_EQ(std::to_string(nf), j["surfels"].get<std::string>());
  EXPECT_NEAR(mean, j["estimates"]["ii-mean"]["mean"].get<double>(), 1e-9);
  EXPECT_NEAR(k1, j["estimates"]["ii-k1"]["mean"].get<double>(), 1e-9);
  // A ball of radius 9 voxels: mean curvature about 1/9 (II at 4 voxels).
  EXPECT_NEAR(mean, 1.0 / 9, 0.03);
}

// --estimate geodesic (the heat method, estimators/heat_geodesics.hpp) on a ball of radius 11
// voxels from the surfel nearest to its north pole: the CSV's distances against the
// great-circle distance R acos(n . n0) between the rays of the surfel centres (mean error
// below 5% of the half circumference pi R), 0 at the source, and the JSON's summary.
TEST(SurfaceCommand, GeodesicDistanceOnABall) {
  Files f;
  const double c = 27.0 / 2; // the centre of the 28^3 volume in voxel coordinates
  save_volume(f.path("ball.npy"), 28,
              [](double x, double y, double z) { return x * x + y * y + z * z <= 121; });
  const auto j = run_json("surface " + f("ball.npy") + " --csv " + f("g.csv") +
                          " --estimate geodesic --source " + std::to_string(c) + "," +
                          std::to_string(c) + "," + std::to_string(c + 11.5) + " --threads 2");
  const auto& g = j["estimates"]["geodesic"];
  const auto source = std::stoll(g["source"].get<std::string>());
  EXPECT_GT(g["max"].get<double>(), 11 * 2.5);
  std::ifstream in(f.path("g.csv"));
  std::string line;
  std::getline(in, line);
  ASSERT_NE(line.find(",geodesic"), std::string::npos) << line;
  std::vector<std::array<double, 4>> rows; // x, y, z, distance (relative to the centre)
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
    rows.push_back({std::stod(cells[2]) - c, std::stod(cells[3]) - c, std::stod(cells[4]) - c,
                    std::stod(cells.back())});
  }
  ASSERT_EQ(std::to_string(rows.size()), j["surfels"].get<std::string>());
  const auto& s0 = rows[std::size_t(source)];
  EXPECT_EQ(s0[3], 0.0);
  EXPECT_GT(s0[2], 10);
  double error = 0;
  for (const auto& r : rows) {
    const double dot = r[0] * s0[0] + r[1] * s0[1] + r[2] * s0[2];
    const double la = std::hypot(r[0], r[1], r[2]), lb = std::hypot(s0[0], s0[1], s0[2]);
    error += std::abs(r[3] - 11 * std::acos(std::clamp(dot / (la * lb), -1.0, 1.0)));
  }
  error /= double(rows.size());
  EXPECT_LT(error, 0.05 * 11 * 3.14159) << error;
}

// The mesh format follows the extension: OBJ and OFF hold the same vertices and faces as the
// JSON counts (read back as text), the OFF's faces the primal quads.
TEST(SurfaceCommand, ObjAndOffByExtension) {
  Files f;
  save_volume(f.path("hollow.npy"), 18, hollow);
  const auto j = run_json("surface " + f("hollow.npy") + " -o " + f("h.obj"));
  const auto k = run_json("surface " + f("hollow.npy") + " -o " + f("h.off"));
  EXPECT_EQ(j["mesh"]["path"], f.path("h.obj"));
  const auto nv = std::stoll(j["mesh"]["vertices"].get<std::string>());
  const auto nf = std::stoll(j["mesh"]["faces"].get<std::string>());
  std::istringstream obj(f.bytes("h.obj"));
  std::int64_t v = 0, faces = 0;
  for (std::string line; std::getline(obj, line);) {
    v += line.rfind("v ", 0) == 0 ? 1 : 0;
    faces += line.rfind("f ", 0) == 0 ? 1 : 0;
  }
  EXPECT_EQ(v, nv);
  EXPECT_EQ(faces, nf);
  std::istringstream off(f.bytes("h.off"));
  std::string magic;
  std::int64_t ov = 0, of = 0, oe = -1;
  off >> magic >> ov >> of >> oe;
  EXPECT_EQ(magic, "OFF");
  EXPECT_EQ(ov, nv);
  EXPECT_EQ(of, nf);
  EXPECT_EQ(k["mesh"]["euler"], "4");
}

// Mean colour difference green - blue over the coloured pixels (|r - b| or |g - b| above 30)
// of the picture's drawing area (left of the colour bar, below the title) whose x is in
// [x0, x1) as fractions of the coloured extent. Viridis' green - blue grows with the value and
// Lambert's factor does not change its sign.
struct ColouredSpan {
  double green_minus_blue = 0;
  std::int64_t pixels = 0;
};

ColouredSpan coloured_span(const RgbImage& img, int right, double x0, double x1) {
  auto coloured = [](Rgb c) {
    return std::abs(int(c.r) - int(c.b)) > 30 || std::abs(int(c.g) - int(c.b)) > 30;
  };
  int lo = img.width, hi = -1;
  for (int y = 40; y < img.height; ++y)
    for (int x = 0; x < right; ++x)
      if (coloured(img.at(x, y))) {
        lo = std::min(lo, x);
        hi = std::max(hi, x);
      }
  ColouredSpan s;
  double sum = 0;
  for (int y = 40; y < img.height; ++y)
    for (int x = 0; x < right; ++x) {
      const double t = double(x - lo) / std::max(1, hi - lo);
      const Rgb c = img.at(x, y);
      if (t >= x0 && t < x1 && coloured(c)) {
        sum += double(c.g) - double(c.b);
        ++s.pixels;
      }
    }
  s.green_minus_blue = s.pixels > 0 ? sum / double(s.pixels) : 0;
  return s;
}

// The picture shows where the curvature is high: a prolate spheroid (semi-axes 11, 5.5, 5.5
// along x, y, z) seen from above (--view 90,90: x to the right), coloured by ii-mean over
// --color-range 0.1:0.3. Its mean curvature is 1/3 at the tips and 0.1 on the waist: the tips
// are yellow-green, the waist blue-purple (viridis, a range of one sign), and the picture has
// the asked size.
TEST(SurfaceCommand, PictureShowsHighCurvatureAtTheTips) {
  Files f;
  save_volume(f.path("spheroid.npy"), 28, [](double x, double y, double z) {
    return x * x / 121 + (y * y + z * z) / 30.25 <= 1;
  });
  const auto j = run_json("surface " + f("spheroid.npy") + " --png " + f("s.png") +
                          " --color ii-mean --radius 3v --view 90,90 --png-size 600x450 --threads 2"
                          " --color-range 0.1:0.3");
  ASSERT_TRUE(j.contains("picture"));
  EXPECT_EQ(j["picture"]["field"], "ii-mean");
  EXPECT_EQ(j["picture"]["color_map"], "viridis");
  EXPECT_EQ(j["picture"]["path"], f.path("s.png"));
  EXPECT_EQ(j["picture"]["range"], nlohmann::json({0.1, 0.3}));
  EXPECT_TRUE(j["estimates"].contains("ii-mean")); // --color computes it
  EXPECT_FALSE(j["mesh"].contains("path"));        // no -o: the mesh is only drawn
  EXPECT_TRUE(j["seconds"].contains("picture"));
  const RgbImage img = test::decode_png(f.path("s.png"));
  ASSERT_EQ(img.width, 600);
  ASSERT_EQ(img.height, 450);
  const int right = 600 - 180; // the colour bar's space
  const auto left_tip = coloured_span(img, right, 0.0, 0.08);
  const auto right_tip = coloured_span(img, right, 0.92, 1.01);
  const auto waist = coloured_span(img, right, 0.4, 0.6);
  ASSERT_GT(left_tip.pixels, 20);
  ASSERT_GT(right_tip.pixels, 20);
  ASSERT_GT(waist.pixels, 200);
  EXPECT_GT(left_tip.green_minus_blue, 0);
  EXPECT_GT(right_tip.green_minus_blue, 0);
  EXPECT_LT(waist.green_minus_blue, 0);
  // Without an estimate the surface is grey and the picture has no colour bar.
  const auto g = run_json("surface " + f("spheroid.npy") + " --png " + f("g.png"));
  EXPECT_FALSE(g["picture"].contains("field"));
  EXPECT_EQ(test::decode_png(f.path("g.png")).width, 1200);
}

TEST(SurfaceCommand, ComponentSelection) {
  Files f;
  save_volume(f.path("two.npy"), 30, [](double x, double y, double z) {
    return (x + 7) * (x + 7) + y * y + z * z <= 36 || (x - 9) * (x - 9) + y * y + z * z <= 9;
  });
  auto j = run_json("surface " + f("two.npy"));
  EXPECT_EQ(j["object_components"], "2");
  EXPECT_EQ(j["components"].size(), 2u);
  EXPECT_EQ(j["betti"][0], "2");
  const auto big = j["components"][0]["voxels"].get<std::string>();
  const auto small = j["components"][1]["voxels"].get<std::string>();
  EXPECT_GT(std::stoll(big), std::stoll(small));
  j = run_json("surface " + f("two.npy") + " --component largest");
  ASSERT_EQ(j["components"].size(), 1u);
  EXPECT_EQ(j["components"][0]["voxels"], big);
  EXPECT_EQ(j["betti"][0], "1");
  j = run_json("surface " + f("two.npy") + " --component 2");
  EXPECT_EQ(j["components"][0]["voxels"], small);
}

// zdg contour --interpolated: marching squares on the grey values at the --threshold level.
// A grey disc f = 100 (1 - |z - c| / 15) (float) thresholded at 0: the interpolated length and
// area are the circle's within 0.5 %, one vertex a linel in the CSV; without --threshold (a
// binary image) the vertices are the linel midpoints.
TEST(ContourCommand, InterpolatedMarchingSquares) {
  Files f;
  const std::int64_t n = 40;
  std::vector<double> v(std::size_t(n * n));
  std::vector<std::int64_t> bin(std::size_t(n * n));
  for (std::int64_t y = 0; y < n; ++y)
    for (std::int64_t x = 0; x < n; ++x) {
      const double r = std::hypot(x - 19.3, y - 20.1);
      v[std::size_t(y * n + x)] = 100 * (1 - r / 15);
      bin[std::size_t(y * n + x)] = r <= 15 ? 1 : 0;
    }
  write_npy(f.path("grey.npy"), make_npy(std::vector<std::int64_t>{n, n}, v));
  write_npy(f.path("bin.npy"), make_npy(DType::U8, {n, n}, bin));
  auto j =
      run_json("contour " + f("grey.npy") + " --threshold 0 --interpolated --csv " + f("g.csv"));
  ASSERT_TRUE(j.contains("interpolated"));
  EXPECT_EQ(j["interpolated"]["level"].get<double>(), 0.0);
  EXPECT_NEAR(j["interpolated"]["length"].get<double>() / (2 * M_PI * 15), 1.0, 5e-3);
  EXPECT_NEAR(j["interpolated"]["area"].get<double>() / (M_PI * 225), 1.0, 5e-3);
  EXPECT_NEAR(j["contours"][0]["interpolated"]["length"].get<double>(),
              j["interpolated"]["length"].get<double>(), 1e-9);
  const auto csv = f.bytes("g.csv");
  EXPECT_NE(csv.find("interpolated_x,interpolated_y"), std::string::npos);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n') - 1,
            std::stoll(j["linels"].get<std::string>()));
  j = run_json("contour " + f("bin.npy") + " --interpolated");
  EXPECT_TRUE(j["interpolated"]["level"].is_null());
  // The polygon of the linel midpoints: shorter than the linel contour, longer than the circle.
  const double l = j["interpolated"]["length"].get<double>();
  EXPECT_LT(l, double(std::stoll(j["linels"].get<std::string>())));
  EXPECT_GT(l, 2 * M_PI * 15 * 0.98);
  j = run_json("contour " + f("bin.npy"));
  EXPECT_FALSE(j.contains("interpolated"));
}

TEST(ContourCommand, TopologyEstimatesAndOutputs) {
  Files f;
  const std::int64_t n = 40;
  std::vector<std::int64_t> v(std::size_t(n * n));
  for (std::int64_t y = 0; y < n; ++y)
    for (std::int64_t x = 0; x < n; ++x) {
      const double r2 = (x - 19.5) * (x - 19.5) + (y - 19.5) * (y - 19.5);
      v[std::size_t(y * n + x)] = r2 <= 225 && r2 > 25 ? 1 : 0;
    }
  write_npy(f.path("ring.npy"), make_npy(DType::U8, {n, n}, v));
  for (const char* adj : {"4,8", "8,4"}) {
    const auto j = run_json("contour " + f("ring.npy") + " --adjacency " + adj +
                            " --estimate ii-curvature,mlp-length,gauss-area,bc-tangent,"
                            "lmst-tangent --radius 3v -o " +
                            f(std::string("r") + adj[0] + ".svg") + " --csv " +
                            f(std::string("r") + adj[0] + ".csv"));
    EXPECT_EQ(j["betti"], nlohmann::json({"1", "1"}));
    ASSERT_EQ(j["contours"].size(), 2u);
    EXPECT_EQ(j["contours"][0]["kind"], "outer");
    EXPECT_EQ(j["contours"][1]["kind"], "hole");
    std::int64_t pixels = 0;
    for (auto b : v) pixels += b;
    EXPECT_EQ(j["estimates"]["gauss-area"]["area"].get<double>(), double(pixels));
    const double len = j["estimates"]["mlp-length"]["total"].get<double>();
    EXPECT_NEAR(len, 2 * M_PI * (15 + 5), 0.05 * 2 * M_PI * 20);
    const auto svg = f.bytes(std::string("r") + adj[0] + ".svg");
    EXPECT_EQ(svg.rfind("<svg", 0), 0u);
    const auto csv = f.bytes(std::string("r") + adj[0] + ".csv");
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n') - 1,
              std::stoll(j["linels"].get<std::string>()));
  }
}

// The 2D picture: the ring's outer contour (curvature 1/28 > 0) is drawn red, its hole's
// (curvature -1/10 < 0) blue (coolwarm, signed values), over the grey object.
TEST(ContourCommand, PictureColoursTheContoursByCurvature) {
  Files f;
  const std::int64_t n = 64;
  std::vector<std::int64_t> v(std::size_t(n * n));
  for (std::int64_t y = 0; y < n; ++y)
    for (std::int64_t x = 0; x < n; ++x) {
      const double r2 = (x - 31.5) * (x - 31.5) + (y - 31.5) * (y - 31.5);
      v[std::size_t(y * n + x)] = r2 <= 28 * 28 && r2 > 10 * 10 ? 1 : 0;
    }
  write_npy(f.path("ring.npy"), make_npy(DType::U8, {n, n}, v));
  const auto j = run_json("contour " + f("ring.npy") + " --png " + f("r.png") +
                          " --color ii-curvature --radius 6v --png-size 500x400");
  EXPECT_EQ(j["picture"]["color_map"], "coolwarm");
  const RgbImage img = test::decode_png(f.path("r.png"));
  ASSERT_EQ(img.width, 500);
  ASSERT_EQ(img.height, 400);
  // Red and blue pixels left of the colour bar: their distances from the ring's centre.
  double cx = 0, cy = 0;
  std::int64_t count = 0;
  std::vector<std::array<int, 3>> pts; // (x, y, +1 red or -1 blue)
  for (int y = 40; y < img.height; ++y)
    for (int x = 0; x < img.width - 180; ++x) {
      const Rgb c = img.at(x, y);
      const int sign = int(c.r) - int(c.b) > 60 ? 1 : (int(c.b) - int(c.r) > 60 ? -1 : 0);
      if (sign == 0) continue;
      pts.push_back({x, y, sign});
      cx += x;
      cy += y;
      ++count;
    }
  ASSERT_GT(count, 100);
  cx /= double(count);
  cy /= double(count);
  double rmax = 0;
  for (const auto& p : pts) rmax = std::max(rmax, std::hypot(p[0] - cx, p[1] - cy));
  std::int64_t outer_red = 0, outer_blue = 0, inner_red = 0, inner_blue = 0;
  for (const auto& p : pts) {
    const double r = std::hypot(p[0] - cx, p[1] - cy) / rmax;
    if (r > 0.7) (p[2] > 0 ? outer_red : outer_blue) += 1;
    if (r < 0.5) (p[2] > 0 ? inner_red : inner_blue) += 1;
  }
  EXPECT_GT(outer_red, 20 * outer_blue) << outer_red << " " << outer_blue;
  EXPECT_GT(inner_blue, 20 * inner_red) << inner_blue << " " << inner_red;
}

TEST(SurfaceCommand, BadInputIsOneLineExitTwoNothingWritten) {
  Files f;
  save_volume(f.path("ball.npy"), 12,
              [](double x, double y, double z) { return x * x + y * y + z * z <= 16; });
  write_npy(f.path("flat.npy"), make_npy(DType::U8, {3, 3}, {0, 1, 0, 1, 1, 1, 0, 1, 0}));
  std::ofstream(f.path("existing.ply"), std::ios::binary) << "keep me";
  std::ofstream(f.path("existing.png"), std::ios::binary) << "keep me too";
  const std::vector<std::string> before = f.listing();
  struct Case {
    std::string args, message;
  };
  const std::string ball = f("ball.npy"), out = " -o " + f("out.ply");
  const Case cases[] = {
      {"surface " + ball + out + " --threshold 2", "selects no voxel"},
      {"surface " + ball + out + " --estimate ii-mean --radius 100v", "larger than the volume"},
      {"surface " + ball + out + " --estimate ii-mean --radius 0", "--radius"},
      {"surface " + ball + " -o " + f("missing/out.ply"), "does not exist"},
      {"surface " + ball + " -o " + f("existing.ply"), "exists (use --force"},
      {"surface " + ball + " --csv " + f("ball.npy") + " --force", "is the input file"},
      {"surface " + ball + out + " --estimate ii-curvature", "unknown estimator"},
      {"surface " + ball + out + " --adjacency 6,6", "6,6"},
      {"surface " + ball + out + " --adjacency 4,8", "4,8"},
      {"surface " + ball + out + " --component 2", "has 1 component"},
      {"surface " + ball + out + " --component none", "--component"},
      {"surface " + ball + out + " --mesh dual", "--mesh"},
      {"surface " + ball + " -o " + f("out.stl"), "unknown mesh format"},
      {"surface " + ball + " --png " + f("out.jpg"), "is a .png file"},
      {"surface " + ball + " --png " + f("missing/out.png"), "does not exist"},
      {"surface " + ball + out + " --png " + f("existing.png"), "exists (use --force"},
      {"surface " + ball + " --png " + f("out.png") + " --color ii-normal", "--color"},
      {"surface " + ball + out + " --color ii-mean", "--color needs --png"},
      {"surface " + ball + out + " --view 0,0", "--view needs --png"},
      {"surface " + ball + " --png " + f("out.png") + " --view 30", "AZIMUTH,ELEVATION"},
      {"surface " + ball + " --png " + f("out.png") + " --view 0,91", "between -90 and 90"},
      {"surface " + ball + " --png " + f("out.png") + " --png-size 100x100", "200x150"},
      {"surface " + ball + " --png " + f("out.png") + " --png-size 800", "WIDTHxHEIGHT"},
      {"surface " + ball + " --png " + f("out.png") + " --color-range 1", "LO:HI"},
      {"surface " + ball + " --png " + f("out.png") + " --color-range 1:0", "below HI"},
      {"surface " + ball + out + " --color-range 0:1", "--color-range needs --png"},
      {"surface " + ball + " --png " + f("out.png") + " --color ii-mean --radius 100v",
       "larger than the volume"},
      {"surface " + ball + out + " --estimate geodesic", "needs --source"},
      {"surface " + ball + out + " --source 0", "only read by --estimate geodesic"},
      {"surface " + ball + out + " --estimate geodesic --source x", "surfel index"},
      {"surface " + ball + out + " --estimate geodesic --source 1,2", "X,Y,Z"},
      {"surface " + ball + out + " --estimate geodesic --source 99999", "surfels (0.."},
      {"surface " + ball + out + " --estimate geodesic --source 100,0,0", "not on the surface"},
      {"surface " + ball + out + " --estimate at-normal --at-lambda -1", "a positive number"},
      {"surface " + ball + out + " --at-alpha 0.2", "only read by --estimate at-normal"},
      {"surface " + ball + out + " --color at-v", "--color needs --png"},
      {"surface " + f("flat.npy") + out, "3D one is needed"},
      {"surface " + f("missing.npy") + out, "missing.npy"},
      {"surface " + ball + out + " --estimate ii-mean --spacing 1,1,2", "isotropic"},
      {"contour " + f("flat.npy") + " -o " + f("out.svg") + " --threshold 5", "selects no voxel"},
      {"contour " + ball + " -o " + f("out.svg"), "2D one is needed"},
      {"contour " + f("flat.npy") + " -o " + f("out.png"), ".svg"},
      {"contour " + f("flat.npy") + " -o " + f("out.svg") + " --estimate ii-mean",
       "unknown estimator"},
      {"contour " + f("flat.npy") + " -o " + f("out.svg") + " --estimate ii-curvature --radius 9v",
       "larger than the image"},
      {"contour " + f("flat.npy") + " -o " + f("missing/out.svg"), "does not exist"},
      {"contour " + f("flat.npy") + " --png " + f("existing.ply"), "is a .png file"},
      {"contour " + f("flat.npy") + " --png " + f("out.png") + " --color ii-mean", "--color"},
      {"contour " + f("flat.npy") + " --color ii-curvature", "--color needs --png"},
      {"contour " + f("flat.npy") + " --png " + f("missing/out.png"), "does not exist"},
      {"contour " + f("flat.npy") + " --png " + f("existing.png"), "exists (use --force"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.args);
    const auto r = test::run_zdg(c.args);
    EXPECT_EQ(r.status, 2) << r.out;
    EXPECT_EQ(r.err.rfind("zdg: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_EQ(f.listing(), before) << "a file was created or removed";
    EXPECT_EQ(f.bytes("existing.ply"), "keep me");
    EXPECT_EQ(f.bytes("existing.png"), "keep me too");
  }
  EXPECT_EQ(test::run_zdg("surface --help").status, 0);
  EXPECT_EQ(test::run_zdg("contour --help").status, 0);
}

// --regularize -o OUT.ply: the primal mesh with the same faces as `zdg surface -o`, every vertex
// moved by at most h/2 per coordinate (here h = 0.5 by --spacing), some of them by a visible
// amount; the JSON reports a lower energy and the displacement in units of h.
TEST(SurfaceCommand, RegularizeMovesVerticesWithinTheirCubes) {
  Files f;
  save_volume(f.path("ball.npy"), 16,
              [](double x, double y, double z) { return x * x + y * y + z * z <= 36; });
  const std::string common = "surface " + f("ball.npy") + " --spacing 0.5,0.5,0.5 --radius 3v";
  run_json(common + " -o " + f("plain.ply"));
  const auto j = run_json(common + " --regularize --gamma 0.1 -o " + f("reg.ply"));
  const auto plain = read_ply(f.path("plain.ply")).mesh;
  const auto reg = read_ply(f.path("reg.ply")).mesh;
  ASSERT_EQ(plain.indices, reg.indices);
  ASSERT_EQ(plain.vertices.size(), reg.vertices.size());
  double moved = 0;
  for (std::size_t i = 0; i < reg.vertices.size(); ++i) {
    const auto d = reg.vertices[i] - plain.vertices[i];
    const double m = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
    EXPECT_LE(m, 0.25 + 1e-5) << i;
    moved = std::max(moved, m);
  }
  EXPECT_GT(moved, 0.02);
  const auto& g = j["regularization"];
  EXPECT_EQ(g["gamma"].get<double>(), 0.1);
  EXPECT_EQ(g["alpha"].get<double>(), 0.001);
  EXPECT_LT(g["energy_after"]["total"].get<double>(), g["energy_before"]["total"].get<double>());
  EXPECT_NEAR(g["max_displacement_h"].get<double>(), moved / 0.5, 1e-4);
  EXPECT_LE(g["max_displacement_h"].get<double>(), 0.5);
  EXPECT_TRUE(g["converged"].get<bool>());
  EXPECT_LE(g["kkt_residual"].get<double>(), 1e-6); // the default tolerance
  EXPECT_EQ(g["solver"].get<std::string>(), "mprgp");
}

} // namespace
} // namespace zdg
