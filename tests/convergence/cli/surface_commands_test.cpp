// zdg surface and zdg contour: topology of known objects through the command line, outputs
// reread by independent readers (numpy for the PLY and the CSV), and the contract on bad input
// (exit 2, one stderr line naming the problem, nothing written, an existing output untouched).
#include "tests/support/cli.hpp"
#include "tests/support/python.hpp"
#include <zdg/kernel/npy_io.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>

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

// -o OUT.png: a picture of the mesh (kernel/render_mesh.hpp), a PNG of the default 1200 x 900
// pixels (signature and IHDR read back); the JSON still describes the mesh.
TEST(SurfaceCommand, PngOutputIsAPictureOfTheMesh) {
  Files f;
  save_volume(f.path("hollow.npy"), 18, hollow);
  const auto j = run_json("surface " + f("hollow.npy") + " -o " + f("p.png"));
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

TEST(SurfaceCommand, BadInputIsOneLineExitTwoNothingWritten) {
  Files f;
  save_volume(f.path("ball.npy"), 12,
              [](double x, double y, double z) { return x * x + y * y + z * z <= 16; });
  write_npy(f.path("flat.npy"), make_npy(DType::U8, {3, 3}, {0, 1, 0, 1, 1, 1, 0, 1, 0}));
  std::ofstream(f.path("existing.ply"), std::ios::binary) << "keep me";
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
  }
  EXPECT_EQ(test::run_zdg("surface --help").status, 0);
  EXPECT_EQ(test::run_zdg("contour --help").status, 0);
}

} // namespace
} // namespace zdg
