#include <zdg/arith/error.hpp>
#include <zdg/kernel/io/input_file.hpp>
#include <zdg/kernel/io/mesh_read.hpp>
#include <zdg/kernel/io/ply_read.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace zdg {

namespace {

[[noreturn]] void fail(const std::string& source, std::size_t line, const std::string& what) {
  throw IoError(source + ":" + std::to_string(line) + ": " + what);
}

std::string shown(std::string_view f) {
  std::string s(f.substr(0, 40));
  for (char& c : s)
    if (!std::isprint(static_cast<unsigned char>(c))) c = '?';
  return f.size() > 40 ? s + "..." : s;
}

// The whitespace-separated fields of each line, comments ('#') removed; blank lines skipped.
class Lines {
public:
  explicit Lines(std::string_view text) : text_(text) {}
  bool next() {
    while (pos_ < text_.size()) {
      const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
      std::string_view line = text_.substr(pos_, end - pos_);
      pos_ = end + 1;
      ++number_;
      line = line.substr(0, std::min(line.find('#'), line.size()));
      fields_.clear();
      std::size_t i = 0;
      while (i < line.size()) {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        const std::size_t b = i;
        while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        if (i > b) fields_.push_back(line.substr(b, i - b));
      }
      if (!fields_.empty()) return true;
    }
    return false;
  }
  std::size_t number() const { return number_; }
  const std::vector<std::string_view>& fields() const { return fields_; }

private:
  std::string_view text_;
  std::size_t pos_ = 0, number_ = 0;
  std::vector<std::string_view> fields_;
};

double number(std::string_view f, const std::string& source, std::size_t line) {
  const char* first = f.data();
  const char* last = f.data() + f.size();
  if (first != last && *first == '+') ++first;
  double v = 0;
  const auto r = std::from_chars(first, last, v);
  if (r.ec != std::errc() || r.ptr != last)
    fail(source, line, "'" + shown(f) + "' is not a number");
  if (!std::isfinite(v)) fail(source, line, "'" + shown(f) + "' is not finite");
  return v;
}

std::int64_t integer(std::string_view f, const std::string& source, std::size_t line) {
  std::int64_t v = 0;
  const char* first = f.data();
  const char* last = f.data() + f.size();
  if (first != last && *first == '+') ++first;
  const auto r = std::from_chars(first, last, v);
  if (r.ec != std::errc() || r.ptr != last)
    fail(source, line, "'" + shown(f) + "' is not an integer index");
  return v;
}

// Faces of one size kept as they are, of several sizes fanned into triangles.
PolygonMesh assemble(std::vector<Point3<double>> vertices, const std::vector<std::int64_t>& starts,
                     const std::vector<std::int64_t>& indices) {
  PolygonMesh m;
  m.vertices = std::move(vertices);
  const std::size_t nf = starts.empty() ? 0 : starts.size() - 1;
  bool uniform = true;
  for (std::size_t f = 0; f + 1 < nf; ++f)
    uniform = uniform && starts[f + 1] - starts[f] == starts[f + 2] - starts[f + 1];
  if (nf == 0) {
    m.face_size = 3;
  } else if (uniform) {
    m.face_size = static_cast<int>(starts[1] - starts[0]);
    m.indices = indices;
  } else {
    m.face_size = 3;
    for (std::size_t f = 0; f < nf; ++f)
      for (std::int64_t k = starts[f] + 1; k + 1 < starts[f + 1]; ++k)
        m.indices.insert(m.indices.end(), {indices[static_cast<std::size_t>(starts[f])],
                                           indices[static_cast<std::size_t>(k)],
                                           indices[static_cast<std::size_t>(k + 1)]});
  }
  return m;
}

} // namespace

PolygonMesh parse_obj_mesh(std::string_view text, const std::string& source) {
  Lines t(text);
  std::vector<Point3<double>> vertices;
  std::vector<std::int64_t> starts{0}, indices;
  while (t.next()) {
    const auto& f = t.fields();
    if (f[0] == "v") {
      if (f.size() != 4 && f.size() != 5)
        fail(source, t.number(), "a vertex 'v x y z [w]' has 3 or 4 numbers");
      vertices.push_back({number(f[1], source, t.number()), number(f[2], source, t.number()),
                          number(f[3], source, t.number())});
    } else if (f[0] == "f") {
      if (f.size() < 4) fail(source, t.number(), "a face has at least 3 vertices");
      if (f.size() - 1 > 1000000) fail(source, t.number(), "a face of more than 10^6 vertices");
      const auto n = static_cast<std::int64_t>(vertices.size());
      for (std::size_t k = 1; k < f.size(); ++k) {
        const std::string_view token = f[k].substr(0, std::min(f[k].find('/'), f[k].size()));
        std::int64_t i = integer(token, source, t.number());
        if (i == 0 || i > n || i < -n)
          fail(source, t.number(),
               "vertex index " + std::string(token) + " out of range (" + std::to_string(n) +
                   " vertices read)");
        i = i > 0 ? i - 1 : n + i;
        indices.push_back(i);
      }
      starts.push_back(static_cast<std::int64_t>(indices.size()));
    }
  }
  PolygonMesh m = assemble(std::move(vertices), starts, indices);
  m.validate();
  return m;
}

PolygonMesh parse_off_mesh(std::string_view text, const std::string& source) {
  Lines t(text);
  if (!t.next()) throw IoError(source + ": empty file (not an OFF file)");
  if (t.fields()[0] != "OFF")
    fail(source, t.number(),
         "not an OFF file (the first line is '" + shown(t.fields()[0]) + "', not OFF)");
  std::size_t first = 1;
  if (t.fields().size() == 1) {
    if (!t.next()) throw IoError(source + ": the file ends before the counts 'V F E'");
    first = 0;
  }
  const auto& c = t.fields();
  if (c.size() - first != 3 && c.size() - first != 2)
    fail(source, t.number(), "the counts: 'V F E' expected");
  const std::int64_t nv = integer(c[first], source, t.number());
  const std::int64_t nf = integer(c[first + 1], source, t.number());
  if (nv < 0 || nf < 0) fail(source, t.number(), "negative counts");
  std::vector<Point3<double>> vertices;
  for (std::int64_t v = 0; v < nv; ++v) {
    if (!t.next())
      throw IoError(source + ": the file ends after " + std::to_string(v) + " of the " +
                    std::to_string(nv) + " vertices");
    const auto& f = t.fields();
    if (f.size() < 3)
      fail(source, t.number(), "vertex " + std::to_string(v) + ": 'x y z' expected");
    vertices.push_back({number(f[0], source, t.number()), number(f[1], source, t.number()),
                        number(f[2], source, t.number())});
  }
  std::vector<std::int64_t> starts{0}, indices;
  for (std::int64_t q = 0; q < nf; ++q) {
    if (!t.next())
      throw IoError(source + ": the file ends after " + std::to_string(q) + " of the " +
                    std::to_string(nf) + " faces");
    const auto& f = t.fields();
    const std::int64_t k = integer(f[0], source, t.number());
    if (k < 3) fail(source, t.number(), "face " + std::to_string(q) + ": fewer than 3 vertices");
    if (static_cast<std::int64_t>(f.size()) - 1 < k)
      fail(source, t.number(),
           "face " + std::to_string(q) + ": " + std::to_string(f.size() - 1) + " indices for " +
               std::to_string(k) + " vertices");
    for (std::int64_t j = 1; j <= k; ++j) {
      const std::int64_t i = integer(f[static_cast<std::size_t>(j)], source, t.number());
      if (i < 0 || i >= nv)
        fail(source, t.number(),
             "face " + std::to_string(q) + ": vertex index " + std::to_string(i) +
                 " out of range (" + std::to_string(nv) + " vertices)");
      indices.push_back(i);
    }
    starts.push_back(static_cast<std::int64_t>(indices.size()));
  }
  PolygonMesh m = assemble(std::move(vertices), starts, indices);
  m.validate();
  return m;
}

PolygonMesh read_mesh(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  for (char& ch : e) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  if (e == ".ply") return read_ply(path).mesh;
  if (e == ".obj") return parse_obj_mesh(read_input_file(path), path);
  if (e == ".off") return parse_off_mesh(read_input_file(path), path);
  throw IoError(path + ": unknown mesh format '" + e + "' (.ply, .obj or .off)");
}

} // namespace zdg
