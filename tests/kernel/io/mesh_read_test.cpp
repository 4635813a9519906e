#include <zdg/kernel/io/mesh_read.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/io/mesh_io.hpp>

#include "tests/support/triangle_meshes.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace zdg {
namespace {

const char* kTetraObj = "# a tetrahedron\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 1\n"
                        "f 1 3 2\nf 1/1 2/2 4/3\nf 1//1 4//1 3//1\nf -3 -2 -1\n";

TEST(MeshRead, ObjIndexFormsAndNegativeIndices) {
  const PolygonMesh m = parse_obj_mesh(kTetraObj, "t.obj");
  EXPECT_EQ(m.face_size, 3);
  ASSERT_EQ(m.vertex_count(), 4);
  EXPECT_EQ(m.indices, (std::vector<std::int64_t>{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3}));
}

TEST(MeshRead, OffCountsOnTheKeywordLineAndMixedFacesFanned) {
  const PolygonMesh m = parse_off_mesh(
      "OFF 5 2 0\n# c\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1 255 0 0\n4 0 1 2 3\n3 0 1 4 9 9 9\n",
      "m.off");
  EXPECT_EQ(m.face_size, 3);
  EXPECT_EQ(m.indices, (std::vector<std::int64_t>{0, 1, 2, 0, 2, 3, 0, 1, 4}));
}

// What zdg writes (kernel/io/mesh_io.hpp) reads back: the cube mesh through OBJ and OFF.
TEST(MeshRead, RoundTripOfTheWriters) {
  const PolygonMesh cube = test::cube_mesh(2).mesh;
  const auto dir = std::filesystem::temp_directory_path() / "zdg_mesh_read_test";
  std::filesystem::create_directories(dir);
  for (const std::string ext : {".obj", ".off", ".ply"}) {
    const std::string path = (dir / ("cube" + ext)).string();
    write_mesh(path, cube);
    const PolygonMesh m = read_mesh(path);
    EXPECT_EQ(m.indices, cube.indices) << ext;
    ASSERT_EQ(m.vertex_count(), cube.vertex_count());
    for (std::size_t i = 0; i < m.vertices.size(); ++i) EXPECT_EQ(m.vertices[i], cube.vertices[i]);
  }
  std::filesystem::remove_all(dir);
}

TEST(MeshRead, Errors) {
  EXPECT_THROW(parse_obj_mesh("v 0 0 0\nv 1 0 0\nf 1 2 3\n", "a.obj"), IoError);
  EXPECT_THROW(parse_obj_mesh("v 0 0\n", "a.obj"), IoError);
  EXPECT_THROW(parse_obj_mesh("v 0 nan 0\n", "a.obj"), IoError);
  EXPECT_THROW(parse_obj_mesh("v 0 0 0\nv 1 0 0\nf 1 0 2\n", "a.obj"), IoError);
  EXPECT_THROW(parse_obj_mesh("v 0 0 0\nf 1 1\n", "a.obj"), IoError);
  EXPECT_THROW(parse_off_mesh("OFF\n3 1 0\n0 0 0\n1 0 0\n", "a.off"), IoError);
  EXPECT_THROW(parse_off_mesh("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", "a.off"), IoError);
  EXPECT_THROW(parse_off_mesh("OFF\n3 1000000000 0\n0 0 0\n1 0 0\n0 1 0\n", "a.off"), IoError);
  EXPECT_THROW(parse_off_mesh("PLY\n", "a.off"), IoError);
  EXPECT_THROW(read_mesh("a.stl"), IoError);
  try {
    parse_obj_mesh("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", "a.obj");
    FAIL();
  } catch (const IoError& e) {
    EXPECT_STREQ(e.what(), "a.obj:4: vertex index 9 out of range (3 vertices read)");
  }
}

} // namespace
} // namespace zdg
