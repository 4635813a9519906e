// The viewer page's contract: RFC 4648 base64 (its test vectors), the geometry and fields it
// embeds decode back to the mesh's float32 values and indices, names cannot close the script,
// and the face budget and unknown fields are refused. The page in a browser:
// tests/python/test_viewer.py.
#include <zdg/arith/error.hpp>
#include <zdg/kernel/render/mesh_html.hpp>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cstring>
#include <string>
#include <vector>

namespace zdg {
namespace {

MeshHtmlOptions options(const std::string& title, const std::string& field, std::int64_t max) {
  MeshHtmlOptions o;
  o.title = title;
  o.field = field;
  o.max_faces = max;
  return o;
}

TEST(MeshHtml, Base64IsRfc4648) {
  const std::pair<const char*, const char*> v[] = {{"", ""},
                                                   {"f", "Zg=="},
                                                   {"fo", "Zm8="},
                                                   {"foo", "Zm9v"},
                                                   {"foob", "Zm9vYg=="},
                                                   {"fooba", "Zm9vYmE="},
                                                   {"foobar", "Zm9vYmFy"}};
  for (const auto& [in, out] : v) EXPECT_EQ(base64(in, std::strlen(in)), out) << in;
}

std::vector<unsigned char> decode(const std::string& s) {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    return c == '+' ? 62 : (c == '/' ? 63 : -1);
  };
  std::vector<unsigned char> out;
  unsigned acc = 0;
  int bits = 0;
  for (char c : s) {
    const int v = value(c);
    if (v < 0) break;
    acc = (acc << 6) | unsigned(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<unsigned char>((acc >> bits) & 255));
    }
  }
  return out;
}

// The base64 text of key "name" in the page's data.
std::string blob(const std::string& page, const std::string& key) {
  const auto k = page.find("\"" + key + "\":\"");
  if (k == std::string::npos) return "";
  const auto b = k + key.size() + 4;
  return page.substr(b, page.find('"', b) - b);
}

RC_GTEST_PROP(MeshHtml, EmbeddedGeometryDecodesToTheMesh, ()) {
  PolygonMesh m;
  m.face_size = *rc::gen::element(3, 4);
  const int nv = *rc::gen::inRange(m.face_size, 40);
  for (int i = 0; i < nv; ++i)
    m.vertices.push_back({*rc::gen::inRange(-1000, 1000) / 8.0,
                          *rc::gen::inRange(-1000, 1000) / 8.0,
                          *rc::gen::inRange(-1000, 1000) / 8.0});
  const int nf = *rc::gen::inRange(1, 50);
  for (int i = 0; i < nf * m.face_size; ++i) m.indices.push_back(*rc::gen::inRange(0, nv));
  std::vector<double> field;
  for (int f = 0; f < nf; ++f) field.push_back(*rc::gen::inRange(-100000, 100000) / 64.0);
  m.face_scalars.emplace_back("ii-mean", field);
  const std::string page = mesh_html(m, options("t", "ii-mean", 1000));
  const auto pos = decode(blob(page, "positions"));
  RC_ASSERT(pos.size() == 12u * std::size_t(nv));
  for (int i = 0; i < nv; ++i) {
    float xyz[3];
    std::memcpy(xyz, pos.data() + 12 * i, 12);
    RC_ASSERT(xyz[0] == float(m.vertices[std::size_t(i)].x));
    RC_ASSERT(xyz[2] == float(m.vertices[std::size_t(i)].z));
  }
  const auto idx = decode(blob(page, "indices"));
  RC_ASSERT(idx.size() == 4 * m.indices.size());
  for (std::size_t i = 0; i < m.indices.size(); ++i) {
    std::uint32_t k = 0;
    std::memcpy(&k, idx.data() + 4 * i, 4);
    RC_ASSERT(std::int64_t(k) == m.indices[i]);
  }
  const auto val = decode(blob(page, "values"));
  RC_ASSERT(val.size() == 4u * std::size_t(nf));
  for (int f = 0; f < nf; ++f) {
    float x = 0;
    std::memcpy(&x, val.data() + 4 * f, 4);
    RC_ASSERT(x == float(field[std::size_t(f)]));
  }
}

TEST(MeshHtml, RefusesWhatABrowserCannotOpenAndUnknownFields) {
  PolygonMesh m;
  m.face_size = 3;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.indices = {0, 1, 2, 0, 2, 1};
  EXPECT_NO_THROW(mesh_html(m, options("t", "", 2)));
  EXPECT_THROW(mesh_html(m, options("t", "", 1)), InvalidArgument);
  EXPECT_THROW(mesh_html(m, options("t", "ii-mean", 10)), InvalidArgument);
  // A name cannot end the data's script element.
  m.face_scalars.emplace_back("</script><b>", std::vector<double>{1, 2});
  const std::string page = mesh_html(m, options("</script>", "", 10));
  EXPECT_EQ(page.find("</script><b>"), std::string::npos);
  EXPECT_NE(page.find("&lt;/script&gt;"), std::string::npos);
}

} // namespace
} // namespace zdg
