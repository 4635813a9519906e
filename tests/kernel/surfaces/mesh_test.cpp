#include <zdg/kernel/surfaces/mesh.hpp>

#include <gtest/gtest.h>

namespace {

zdg::PolygonMesh tetrahedron() {
  zdg::PolygonMesh m;
  m.face_size = 3;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  return m;
}

TEST(PolygonMesh, FacesAndValidation) {
  auto m = tetrahedron();
  EXPECT_EQ(m.face_count(), 4);
  EXPECT_EQ(m.face(1)[2], 3);
  EXPECT_NO_THROW(m.validate());
  m.face_scalars.push_back({"k", {1, 2, 3}});
  EXPECT_THROW(m.validate(), zdg::InvalidArgument); // 3 values for 4 faces
  m.face_scalars.clear();
  m.indices[5] = 4;
  EXPECT_THROW(m.validate(), zdg::InvalidArgument); // vertex out of range
  m.indices.pop_back();
  EXPECT_THROW(m.validate(), zdg::InvalidArgument); // not a whole number of faces
}

} // namespace
