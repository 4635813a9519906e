// Mesh writers, checked by independent readers: numpy parsing the binary PLY (a Python
// snippet builds the record layout from the header it reads), and small text parsers here for
// OBJ and OFF.
#include <zdg/kernel/io/mesh_io.hpp>

#include "tests/support/cli.hpp"
#include "tests/support/python.hpp"
#include "tests/support/voxel_mesh.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>

namespace zdg {
namespace {

namespace fs = std::filesystem;

// A digitized ball of radius 2.5 (its primal quads) with two fields and face normals.
PolygonMesh sample_mesh() {
  PolygonMesh m =
      test::voxel_primal_mesh([](std::int64_t x, std::int64_t y,
                                 std::int64_t z) { return 4 * (x * x + y * y + z * z) <= 25; },
                              -4, 4);
  std::vector<double> k;
  for (std::int64_t f = 0; f < m.face_count(); ++f) k.push_back(0.1 * static_cast<double>(f) - 3);
  m.face_scalars.emplace_back("ii-mean", k);
  for (std::int64_t f = 0; f < m.face_count(); ++f) {
    const auto idx = m.face(f);
    const auto& a = m.vertices[static_cast<std::size_t>(idx[0])];
    const auto& b = m.vertices[static_cast<std::size_t>(idx[1])];
    const auto& c = m.vertices[static_cast<std::size_t>(idx[2])];
    m.face_normals.push_back(cross(b - a, c - b));
  }
  return m;
}

const char* kPlyReader = R"(
import sys, json, numpy as np
data = open(sys.argv[1], 'rb').read()
end = data.index(b'end_header\n') + len(b'end_header\n')
header = data[:end].decode('ascii').split('\n')
assert header[0] == 'ply' and header[1] == 'format binary_little_endian 1.0'
types = {'float': '<f4', 'double': '<f8', 'int': '<i4', 'uint': '<u4', 'uchar': 'u1'}
elements = []
for line in header:
    w = line.split()
    if w[:1] == ['element']: elements.append((w[1], int(w[2]), []))
    if w[:1] == ['property'] and w[1] == 'list': elements[-1][2].append(('list', w[2], w[3], w[4]))
    if w[:1] == ['property'] and w[1] != 'list': elements[-1][2].append((w[2], types[w[1]]))
out, pos = {}, end
for name, count, props in elements:
    fields = []
    for p in props:
        if p[0] == 'list':
            # uniform faces: read the count of the first record to size the list
            k = data[pos]
            fields += [(p[3] + '_n', types[p[1]]), (p[3], types[p[2]], (k,))]
        else:
            fields.append(p)
    dt = np.dtype(fields)
    arr = np.frombuffer(data, dtype=dt, count=count, offset=pos)
    pos += dt.itemsize * count
    out[name] = {f[0]: arr[f[0]].tolist() for f in fields}
assert pos == len(data), (pos, len(data))
print(json.dumps(out))
)";

TEST(MeshIo, PlyReadBackByNumpy) {
  if (!test::python_has("numpy")) GTEST_SKIP() << "python3-numpy is not installed";
  const auto dir = test::scratch_dir("mesh");
  const PolygonMesh m = sample_mesh();
  write_ply((dir / "a.ply").string(), m);
  const auto r = test::run_python(kPlyReader, {(dir / "a.ply").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& v = j["vertex"];
  ASSERT_EQ(v["x"].size(), m.vertices.size());
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    EXPECT_EQ(v["x"][i].get<double>(), static_cast<float>(m.vertices[i].x));
    EXPECT_EQ(v["y"][i].get<double>(), static_cast<float>(m.vertices[i].y));
    EXPECT_EQ(v["z"][i].get<double>(), static_cast<float>(m.vertices[i].z));
  }
  const auto& f = j["face"];
  ASSERT_EQ(f["vertex_indices"].size(), static_cast<std::size_t>(m.face_count()));
  const auto& k = m.face_scalars[1].second;
  for (std::int64_t i = 0; i < m.face_count(); ++i) {
    const auto ui = static_cast<std::size_t>(i);
    EXPECT_EQ(f["vertex_indices_n"][ui], 4);
    for (std::size_t c = 0; c < 4; ++c) EXPECT_EQ(f["vertex_indices"][ui][c], m.face(i)[c]);
    EXPECT_EQ(f["z"][ui].get<double>(), static_cast<float>(m.face_scalars[0].second[ui]));
    EXPECT_EQ(f["ii_mean"][ui].get<double>(), static_cast<float>(k[ui]));
    EXPECT_EQ(f["nx"][ui].get<double>(), static_cast<float>(m.face_normals[ui].x));
    EXPECT_EQ(f["nz"][ui].get<double>(), static_cast<float>(m.face_normals[ui].z));
  }
  const std::string text = test::read_file(dir / "a.ply");
  EXPECT_NE(text.find("comment face fields: z ii-mean\n"), std::string::npos);
  fs::remove_all(dir);
}

// OBJ and OFF reread by a parser written here: the same vertices (as float32) and faces.
TEST(MeshIo, ObjAndOffReadBack) {
  const auto dir = test::scratch_dir("mesh");
  PolygonMesh m = sample_mesh();
  m.vertex_normals.assign(m.vertices.size(), Point3<double>{0, 0, 1});
  for (unsigned threads : {1u, 3u}) {
    write_mesh((dir / "a.obj").string(), m, std::nullopt, threads);
    write_mesh((dir / "a.off").string(), m, std::nullopt, threads);
    std::istringstream obj(test::read_file(dir / "a.obj"));
    std::vector<Point3<double>> verts;
    std::vector<std::int64_t> idx;
    std::int64_t normals = 0;
    for (std::string line; std::getline(obj, line);) {
      std::istringstream ls(line);
      std::string tag;
      ls >> tag;
      if (tag == "v") {
        Point3<double> p;
        ls >> p.x >> p.y >> p.z;
        verts.push_back(p);
      } else if (tag == "vn") {
        ++normals;
      } else if (tag == "f") {
        for (std::string w; ls >> w;) {
          EXPECT_EQ(w.substr(w.find("//") + 2), w.substr(0, w.find("//")));
          idx.push_back(std::stoll(w) - 1);
        }
      }
    }
    ASSERT_EQ(verts.size(), m.vertices.size());
    for (std::size_t i = 0; i < verts.size(); ++i)
      EXPECT_EQ(static_cast<float>(verts[i].x), static_cast<float>(m.vertices[i].x));
    EXPECT_EQ(idx, m.indices);
    EXPECT_EQ(normals, m.vertex_count());

    std::istringstream off(test::read_file(dir / "a.off"));
    std::string magic;
    std::int64_t nv = 0, nf = 0, ne = -1;
    off >> magic >> nv >> nf >> ne;
    EXPECT_EQ(magic, "OFF");
    EXPECT_EQ(nv, m.vertex_count());
    EXPECT_EQ(nf, m.face_count());
    EXPECT_EQ(ne, 0);
    for (std::int64_t i = 0; i < nv; ++i) {
      float x = 0, y = 0, z = 0;
      off >> x >> y >> z;
      EXPECT_EQ(y, static_cast<float>(m.vertices[static_cast<std::size_t>(i)].y));
    }
    std::vector<std::int64_t> oidx;
    for (std::int64_t f = 0; f < nf; ++f) {
      int k = 0;
      off >> k;
      EXPECT_EQ(k, 4);
      for (int c = 0; c < k; ++c) {
        std::int64_t i = 0;
        off >> i;
        oidx.push_back(i);
      }
    }
    EXPECT_EQ(oidx, m.indices);
    EXPECT_TRUE(off.good());
    std::string rest;
    off >> rest;
    EXPECT_TRUE(rest.empty());
  }
  fs::remove_all(dir);
}

TEST(MeshIo, ErrorsLeaveNothing) {
  const auto dir = test::scratch_dir("mesh");
  PolygonMesh bad = sample_mesh();
  bad.indices[5] = bad.vertex_count();
  EXPECT_THROW(write_ply((dir / "a.ply").string(), bad), InvalidArgument);
  EXPECT_THROW(write_obj((dir / "a.obj").string(), bad), InvalidArgument);
  EXPECT_THROW(write_off((dir / "a.off").string(), bad), InvalidArgument);
  const PolygonMesh m = sample_mesh();
  EXPECT_THROW(write_ply((dir / "missing" / "a.ply").string(), m), IoError);
  EXPECT_THROW(write_mesh((dir / "a.stl").string(), m), IoError);
  EXPECT_TRUE(fs::is_empty(dir));
  EXPECT_EQ(ply_property_name("ii-mean"), "ii_mean");
  EXPECT_EQ(ply_property_name("k 1/2"), "k_1_2");
  // Explicit format: a staging name without the extension.
  write_mesh((dir / ".staging").string(), m, MeshFormat::ply);
  EXPECT_EQ(test::read_file(dir / ".staging").rfind("ply\nformat binary_little_endian 1.0\n", 0),
            0u);
  // A triangle mesh with no field and no normals.
  PolygonMesh t;
  t.face_size = 3;
  t.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  t.indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  write_ply((dir / "t.ply").string(), t);
  EXPECT_EQ(fs::file_size(dir / "t.ply"),
            test::read_file(dir / "t.ply").find("end_header\n") + 11 + 4 * 12 + 4 * 13);
  fs::remove_all(dir);
}

} // namespace
} // namespace zdg
