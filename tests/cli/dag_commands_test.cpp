// zdg dag and zdg render dag: the JSON report equals the library's structures (a volume and a
// mesh streamed by slabs), the ray's hits equal the dense oracle, the picture equals the
// library's rendering.
#include "tests/support/cli.hpp"
#include "tests/support/png.hpp"
#include <zdg/kernel/digitization/voxelize.hpp>
#include <zdg/kernel/images/voxel_dag.hpp>
#include <zdg/kernel/io/ply_read.hpp>
#include <zdg/kernel/io/volume_io.hpp>
#include <zdg/kernel/render/dag_render.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>

namespace zdg {
namespace {

struct Files {
  std::filesystem::path dir = test::scratch_dir("dag");
  ~Files() { std::filesystem::remove_all(dir); }
  std::string operator()(const std::string& name) const {
    std::string q(1, '\'');
    q.append(path(name));
    q.push_back('\'');
    return q;
  }
  std::string path(const std::string& name) const { return (dir / name).string(); }
};

// Two boxes and a diagonal line of voxels in a 13 x 9 x 7 volume (x fastest).
Image<std::uint8_t> scene() {
  Image<std::uint8_t> img(Domain({7, 9, 13}));
  auto& v = img.values();
  for (std::int64_t z = 0; z < 7; ++z)
    for (std::int64_t y = 0; y < 9; ++y)
      for (std::int64_t x = 0; x < 13; ++x) {
        const bool box = (x >= 1 && x < 5 && y >= 2 && y < 6 && z >= 1 && z < 4) ||
                         (x >= 8 && x < 12 && y >= 4 && y < 8 && z >= 3 && z < 6);
        const bool line = x == y && y == z;
        v[static_cast<std::size_t>((z * 9 + y) * 13 + x)] = box || line;
      }
  return img;
}

void write_scene(const std::string& path) {
  write_volume(path, make_scalar_volume(scene()));
}

TEST(DagCommands, ReportEqualsTheLibrary) {
  Files f;
  write_scene(f.path("s.npy"));
  const auto r = test::run_zdg("dag " + f("s.npy") + " --ray -20,3,2,4,0,0 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const Image<std::uint8_t> img = scene();
  const VoxelDag d = build_voxel_dag(img, VoxelDagKind::dag);
  const VoxelDag s = build_voxel_dag(img, VoxelDagKind::ssvdag);
  const VoxelDag t = build_voxel_dag(img, VoxelDagKind::svo);
  EXPECT_EQ(j["extent"], nlohmann::json({13, 9, 7}));
  EXPECT_EQ(j["depth"], 4);
  EXPECT_EQ(j["voxels"], std::to_string(d.stats().voxels));
  EXPECT_EQ(j["dag"]["bytes"], d.stats().bytes);
  EXPECT_EQ(j["dag"]["nodes_per_level"], nlohmann::json(d.stats().nodes_per_level));
  EXPECT_EQ(j["ssvdag"]["bytes"], s.stats().bytes);
  EXPECT_EQ(j["ssvdag"]["leaves"], s.stats().leaves);
  EXPECT_EQ(j["svo"]["bytes"], t.stats().bytes);
  EXPECT_EQ(j["svo"]["nodes"], t.stats().inner_nodes);
  EXPECT_EQ(j["svo"]["leaves"], t.stats().leaves);
  EXPECT_EQ(j["svo"]["pointers"], t.stats().pointers);
  // The line y = 3, z = 2 along +x crosses the first box at x = 1..4, by their x faces.
  nlohmann::json hits = nlohmann::json::array();
  for (std::int64_t x = 1; x < 5; ++x) hits.push_back({{"voxel", {x, 3, 2}}, {"axis", 0}});
  EXPECT_EQ(j["ray"]["hits"], hits);
  EXPECT_EQ(j["ray"]["kind"], "ssvdag");
  // --max-hits and the text report.
  const auto k = test::run_zdg("dag " + f("s.npy") + " --ray -20,3,2,4,0,0 --max-hits 2 --json");
  ASSERT_EQ(k.status, 0) << k.err;
  EXPECT_EQ(nlohmann::json::parse(k.out)["ray"]["hits"].size(), 2u);
  const auto text = test::run_zdg("dag " + f("s.npy"));
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("ssvdag"), std::string::npos);
}

// A mesh voxelized by slabs of 4 layers: the same structure as the dense voxelization's.
TEST(DagCommands, MeshStreamedBySlabsEqualsTheDenseVoxelization) {
  Files f;
  std::ofstream(f.path("tet.ply"))
      << "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
         "property double z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n"
         "0.1 0.1 0.1\n1.1 0.1 0.1\n0.1 1.1 0.1\n0.1 0.1 1.1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  const PolygonMesh mesh = read_ply(f.path("tet.ply")).mesh;
  for (const std::string mode : {"conservative", "solid"}) {
    const auto r =
        test::run_zdg("dag " + f("tet.ply") + " --h 0.05 --slab 4 --mode " + mode + " --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    const VoxelizationGrid g = voxel_grid_for(mesh, 0.05);
    const auto img = voxelize(mesh, g, parse_voxelization_mode(mode), 1);
    const VoxelDag d = build_voxel_dag(img, VoxelDagKind::dag);
    EXPECT_EQ(j["extent"], nlohmann::json({g.extents[0], g.extents[1], g.extents[2]}));
    EXPECT_EQ(j["voxels"], std::to_string(d.stats().voxels));
    EXPECT_EQ(j["dag"]["nodes_per_level"], nlohmann::json(d.stats().nodes_per_level));
    EXPECT_EQ(j["ssvdag"]["bytes"], build_voxel_dag(img, VoxelDagKind::ssvdag).stats().bytes);
    EXPECT_EQ(j["input"]["mode"], mode);
  }
}

TEST(DagCommands, RenderEqualsTheLibrary) {
  Files f;
  write_scene(f.path("s.npy"));
  for (const std::string kind : {"svo", "dag", "ssvdag"}) {
    const std::string out = "p_" + kind + ".png";
    const auto r = test::run_zdg("render dag " + f("s.npy") + " -o " + f(out) +
                                 " --png-size 240x200 --view 30,20 --kind " + kind + " --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    VolumeRenderOptions o;
    o.width = 240;
    o.height = 200;
    o.azimuth = 30;
    o.elevation = 20;
    const DagRendering want = render_dag(build_voxel_dag(scene(), parse_voxel_dag_kind(kind)), o);
    EXPECT_EQ(j["hits"], want.hits);
    EXPECT_GT(want.hits, 1000);
    EXPECT_EQ(j["kind"], kind);
    const RgbImage got = test::decode_png(f.path(out));
    EXPECT_EQ(got.rgb, want.picture.rgb);
  }
}

} // namespace
} // namespace zdg
