#include <zdg/kernel/render/mesh_html.hpp>

#include <zdg/arith/error.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string_view>
#include <vector>

namespace zdg {

namespace {

// The page: @TITLE@ (HTML text) and @DATA@ (JSON) are replaced.
constexpr std::string_view kPage =
#include "mesh_html_page.inc"
    ;

// A JSON string literal; '<' escaped so that the text cannot close the script element.
std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (const unsigned char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += char(c);
    } else if (c < 0x20 || c == '<' || c == '>' || c == '&') {
      static const char* hex = "0123456789abcdef";
      out += "\\u00";
      out += hex[c >> 4];
      out += hex[c & 15];
    } else {
      out += char(c);
    }
  }
  return out + "\"";
}

std::string html_text(const std::string& s) {
  std::string out;
  for (const char c : s) {
    switch (c) {
    case '<':
      out += "&lt;";
      break;
    case '>':
      out += "&gt;";
      break;
    case '&':
      out += "&amp;";
      break;
    case '"':
      out += "&quot;";
      break;
    default:
      out += c;
    }
  }
  return out;
}

// Encodes 3 m bytes (m >= 0) into 4 m characters at out.
char* encode_groups(const unsigned char* p, std::size_t groups, char* out) {
  static const char* a = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  for (std::size_t g = 0; g < groups; ++g, p += 3) {
    const unsigned v = (unsigned(p[0]) << 16) | (unsigned(p[1]) << 8) | p[2];
    *out++ = a[v >> 18];
    *out++ = a[(v >> 12) & 63];
    *out++ = a[(v >> 6) & 63];
    *out++ = a[v & 63];
  }
  return out;
}

// Streams the base64 text of values converted to T (n of them, value(i) gives the i-th), in
// blocks: neither the converted array nor its text is held whole.
template <class T, class Value>
void put_base64(std::ostream& out, std::size_t n, Value value) {
  constexpr std::size_t kBlock = 3 * 16384; // elements: a multiple of 3, so of 3 bytes
  std::vector<T> block;
  block.reserve(kBlock);
  for (std::size_t b = 0; b < n; b += kBlock) {
    const std::size_t m = std::min(kBlock, n - b);
    block.clear();
    for (std::size_t i = 0; i < m; ++i) block.push_back(value(b + i));
    out << base64(block.data(), m * sizeof(T)); // padded only in the last block
  }
}

} // namespace

std::string base64(const void* data, std::size_t n) {
  // The whole groups, then the last one or two bytes padded with zeros and '='.
  const auto* p = static_cast<const unsigned char*>(data);
  std::string out((n + 2) / 3 * 4, '=');
  char* end = encode_groups(p, n / 3, out.data());
  if (const std::size_t rest = n % 3; rest != 0) {
    unsigned char last[3] = {0, 0, 0};
    for (std::size_t k = 0; k < rest; ++k) last[k] = p[n - rest + k];
    char four[4];
    encode_groups(last, 1, four);
    for (std::size_t k = 0; k <= rest; ++k) end[k] = four[k];
  }
  return out;
}

namespace {

void write_page(std::ostream& out, const PolygonMesh& mesh, const MeshHtmlOptions& o) {
  mesh.validate();
  const std::int64_t faces = mesh.face_count();
  constexpr std::int64_t kPickLimit = (std::int64_t{1} << 24) - 2;
  if (faces > o.max_faces || faces > kPickLimit)
    throw InvalidArgument("the page would hold " + std::to_string(faces) + " faces, more than " +
                          std::to_string(std::min(o.max_faces, kPickLimit)) +
                          (o.max_faces < kPickLimit ? " (--max-faces)" : " (the picking limit)") +
                          "; a browser would not open it smoothly");
  if (mesh.vertex_count() > std::int64_t{0xFFFFFFFF})
    throw InvalidArgument("the page holds at most 2^32 - 1 vertices");
  bool found = o.field.empty();
  std::string names;
  for (const auto& f : mesh.face_scalars) {
    found = found || f.first == o.field;
    names += (names.empty() ? "" : ", ") + f.first;
  }
  if (!found)
    throw InvalidArgument("the field '" + o.field + "' is not on the mesh (" +
                          (names.empty() ? std::string("it has none") : names) + ")");
  const auto t = kPage.find("@TITLE@"), d = kPage.find("@DATA@");
  out << kPage.substr(0, t) << html_text(o.title) << kPage.substr(t + 7, d - t - 7);
  out << "{\"title\":" << json_string(o.title) << ",\"face_size\":" << mesh.face_size
      << ",\"faces\":" << faces << ",\"positions\":\"";
  const auto& v = mesh.vertices;
  put_base64<float>(out, 3 * v.size(), [&](std::size_t i) {
    const auto& p = v[i / 3];
    return float(i % 3 == 0 ? p.x : (i % 3 == 1 ? p.y : p.z));
  });
  out << "\",\"indices\":\"";
  put_base64<std::uint32_t>(out, mesh.indices.size(),
                            [&](std::size_t i) { return std::uint32_t(mesh.indices[i]); });
  out << "\",\"fields\":[";
  bool first = true;
  for (const auto& field : mesh.face_scalars) {
    const std::vector<double>& values = field.second; // (a lambda below captures it)
    out << (first ? "" : ",") << "{\"name\":" << json_string(field.first) << ",\"values\":\"";
    put_base64<float>(out, values.size(), [&](std::size_t i) { return float(values[i]); });
    out << "\"}";
    first = false;
  }
  out << "]";
  if (!mesh.face_normals.empty()) {
    out << ",\"normals\":\"";
    const auto& n = mesh.face_normals;
    put_base64<std::int8_t>(out, 3 * n.size(), [&](std::size_t i) {
      const auto& q = n[i / 3];
      const double l = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
      const double c = i % 3 == 0 ? q.x : (i % 3 == 1 ? q.y : q.z);
      return std::int8_t(l > 0 && std::isfinite(l) ? std::lround(127 * c / l) : 0);
    });
    out << "\"";
  }
  if (!o.field.empty()) out << ",\"field\":" << json_string(o.field);
  if (!o.note.empty()) out << ",\"note\":" << json_string(o.note);
  if (o.top_view) out << ",\"view\":\"top\"";
  out << "}" << kPage.substr(d + 6);
}

} // namespace

std::string mesh_html(const PolygonMesh& mesh, const MeshHtmlOptions& o) {
  std::ostringstream out;
  write_page(out, mesh, o);
  return std::move(out).str();
}

void write_mesh_html(const std::string& path, const PolygonMesh& mesh, const MeshHtmlOptions& o) {
  std::ofstream f;
  std::vector<char> buffer(std::size_t{1} << 20);
  f.rdbuf()->pubsetbuf(buffer.data(), std::streamsize(buffer.size()));
  f.open(path, std::ios::binary);
  if (!f) throw IoError(path + ": cannot be written");
  write_page(f, mesh, o);
  f.close();
  if (!f) throw IoError(path + ": write failed");
}

} // namespace zdg
