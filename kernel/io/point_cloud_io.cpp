#include <zdg/kernel/io/point_cloud_io.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/io/input_file.hpp>
#include <zdg/kernel/io/npy_io.hpp>
#include <zdg/kernel/io/output_files.hpp>
#include <zdg/kernel/io/ply_read.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>

namespace zdg {

namespace {

// A field as shown in a message: at most 40 characters.
std::string shown(std::string_view f) {
  return std::string(f.substr(0, 40)) + (f.size() > 40 ? "..." : "");
}

[[noreturn]] void fail_line(const std::string& source, std::size_t line, const std::string& what) {
  throw IoError(source + ":" + std::to_string(line) + ": " + what);
}

// The data lines of a text file, one at a time: each non-blank line without its '#' comment,
// split into at most kMax fields (a count past kMax is reported as kMax + 1).
class TextLines {
public:
  static constexpr std::size_t kMax = 6;

  explicit TextLines(std::string_view text) : text_(text) {}

  // The next data line; false at the end of the text.
  bool next() {
    while (pos_ < text_.size()) {
      ++number_;
      std::size_t end = text_.find('\n', pos_);
      if (end == std::string_view::npos) end = text_.size();
      std::string_view line = text_.substr(pos_, end - pos_);
      pos_ = end + 1;
      if (const auto hash = line.find('#'); hash != std::string_view::npos)
        line = line.substr(0, hash);
      count_ = 0;
      std::size_t i = 0;
      while (i < line.size()) {
        while (i < line.size() && blank(line[i])) ++i;
        const std::size_t b = i;
        while (i < line.size() && !blank(line[i])) ++i;
        if (i > b) {
          if (count_ < kMax) fields_[count_] = line.substr(b, i - b);
          if (count_ <= kMax) ++count_;
        }
      }
      if (count_ > 0) return true;
    }
    return false;
  }

  std::size_t number() const { return number_; }
  std::size_t count() const { return count_; } // kMax + 1: more than kMax
  std::string_view field(std::size_t k) const { return fields_[k]; }
  std::string count_text() const {
    return count_ > kMax ? "more than " + std::to_string(kMax) : std::to_string(count_);
  }

private:
  static bool blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

  std::string_view text_;
  std::size_t pos_ = 0, number_ = 0, count_ = 0;
  std::array<std::string_view, kMax> fields_{};
};

// A finite double from a text field (an optional leading '+' accepted).
double finite_number(std::string_view f, const std::string& source, std::size_t line) {
  const char* first = f.data();
  const char* last = f.data() + f.size();
  if (first != last && *first == '+') ++first;
  double v = 0;
  const auto r = std::from_chars(first, last, v);
  if (r.ec == std::errc::result_out_of_range)
    fail_line(source, line, "'" + shown(f) + "' is out of the range of a double");
  if (r.ec != std::errc() || r.ptr != last)
    fail_line(source, line, "'" + shown(f) + "' is not a number");
  if (!std::isfinite(v)) fail_line(source, line, "'" + shown(f) + "' is not finite");
  return v;
}

// Fields k .. k + 2 of the current line as a point.
Point3<double> point_at(const TextLines& t, std::size_t k, const std::string& source) {
  return {finite_number(t.field(k), source, t.number()),
          finite_number(t.field(k + 1), source, t.number()),
          finite_number(t.field(k + 2), source, t.number())};
}

PointCloud parse_xyz(std::string_view text, const std::string& source) {
  PointCloud c;
  TextLines t(text);
  std::size_t columns = 0;
  while (t.next()) {
    if (columns == 0) {
      if (t.count() != 3 && t.count() != 6)
        fail_line(source, t.number(),
                  t.count_text() + " fields: 'x y z' or 'x y z nx ny nz' expected");
      columns = t.count();
    } else if (t.count() != columns) {
      fail_line(source, t.number(),
                t.count_text() + " fields where the first point has " + std::to_string(columns));
    }
    c.points.push_back(point_at(t, 0, source));
    if (columns == 6) c.normals.push_back(point_at(t, 3, source));
  }
  return c;
}

std::uint64_t count_field(std::string_view f, const std::string& source, std::size_t line,
                          const char* what) {
  std::uint64_t v = 0;
  const auto r = std::from_chars(f.data(), f.data() + f.size(), v);
  if (r.ec != std::errc() || r.ptr != f.data() + f.size())
    fail_line(source, line,
              std::string(what) + " '" + shown(f) + "' is not a non-negative integer");
  return v;
}

PointCloud parse_off(std::string_view text, const std::string& source) {
  TextLines t(text);
  if (!t.next()) throw IoError(source + ": empty file (not an OFF file)");
  const std::string_view key = t.field(0);
  if (key != "OFF" && key != "NOFF")
    fail_line(source, t.number(),
              "not an OFF file (the first line is '" + shown(key) + "', not OFF or NOFF)");
  const bool normals = key == "NOFF";
  // The counts: on the keyword's line or on the next data line.
  std::size_t first = 1;
  if (t.count() == 1) {
    if (!t.next()) throw IoError(source + ": the file ends before the counts 'V F E'");
    first = 0;
  }
  if (t.count() - first != 3 && t.count() - first != 2)
    fail_line(source, t.number(), "the counts: 'V F E' expected");
  const std::uint64_t nv = count_field(t.field(first), source, t.number(), "vertex count");
  (void)count_field(t.field(first + 1), source, t.number(), "face count");
  const std::size_t want = normals ? 6 : 3;
  PointCloud c;
  for (std::uint64_t v = 0; v < nv; ++v) {
    if (!t.next())
      throw IoError(source + ": the file ends after " + std::to_string(v) + " of the " +
                    std::to_string(nv) + " vertices");
    if (t.count() != want)
      fail_line(source, t.number(),
                "vertex " + std::to_string(v) + ": " + t.count_text() + " fields (" +
                    std::to_string(want) + " expected in " + std::string(key) + ")");
    c.points.push_back(point_at(t, 0, source));
    if (normals) c.normals.push_back(point_at(t, 3, source));
  }
  return c;
}

PointCloud from_ply(const PlyMesh& ply) {
  PointCloud c;
  c.points = ply.mesh.vertices;
  c.normals = ply.mesh.vertex_normals;
  return c;
}

PointCloud from_npy(const NpyArray& a, const std::string& source) {
  if (a.shape.size() != 2 || (a.shape[1] != 3 && a.shape[1] != 6)) {
    std::string s = "(";
    for (std::size_t k = 0; k < a.shape.size() && k < 8; ++k)
      s += (k ? ", " : "") + std::to_string(a.shape[k]);
    s += a.shape.size() == 1 ? ",)" : ")";
    throw IoError(source + ": an array of shape " + s + " is not a point cloud (N x 3 or N x 6)");
  }
  if (a.dtype == DType::Bool) throw IoError(source + ": a bool array is not a point cloud");
  const std::int64_t n = a.shape[0], w = a.shape[1];
  PointCloud c;
  c.points.reserve(static_cast<std::size_t>(n)); // the data are in memory: n is checked
  if (w == 6) c.normals.reserve(static_cast<std::size_t>(n));
  for (std::int64_t r = 0; r < n; ++r) {
    double v[6] = {};
    for (std::int64_t k = 0; k < w; ++k) {
      v[k] = a.get_double(r * w + k);
      if (!std::isfinite(v[k]))
        throw IoError(source + ": row " + std::to_string(r) + ", column " + std::to_string(k) +
                      ": the value is not finite");
    }
    c.points.push_back({v[0], v[1], v[2]});
    if (w == 6) c.normals.push_back({v[3], v[4], v[5]});
  }
  return c;
}

void put_double(std::string& out, double v) {
  char b[8];
  std::memcpy(b, &v, 8);
  if constexpr (std::endian::native == std::endian::big) std::reverse(b, b + 8);
  out.append(b, 8);
}

void put_text(std::string& out, double v) {
  char b[32];
  const auto r = std::to_chars(b, b + sizeof b, v);
  out.append(b, r.ptr);
}

// Each point's x y z, then its normal's when the cloud has normals: little-endian float64, the
// body of the PLY and npy writers.
void put_rows(std::string& out, const PointCloud& c) {
  for (std::size_t i = 0; i < c.size(); ++i) {
    put_double(out, c.points[i].x);
    put_double(out, c.points[i].y);
    put_double(out, c.points[i].z);
    if (!c.has_normals()) continue;
    put_double(out, c.normals[i].x);
    put_double(out, c.normals[i].y);
    put_double(out, c.normals[i].z);
  }
}

std::string ply_bytes(const PointCloud& c) {
  std::string out =
      "ply\nformat binary_little_endian 1.0\ncomment written by zdg\nelement vertex " +
      std::to_string(c.size()) + "\nproperty double x\nproperty double y\nproperty double z\n";
  if (c.has_normals()) out += "property double nx\nproperty double ny\nproperty double nz\n";
  out += "end_header\n";
  out.reserve(out.size() + c.size() * (c.has_normals() ? 48 : 24));
  put_rows(out, c);
  return out;
}

std::string xyz_bytes(const PointCloud& c) {
  std::string out;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const Point3<double>& p = c.points[i];
    put_text(out, p.x);
    out += ' ';
    put_text(out, p.y);
    out += ' ';
    put_text(out, p.z);
    if (c.has_normals()) {
      const Point3<double>& n = c.normals[i];
      out += ' ';
      put_text(out, n.x);
      out += ' ';
      put_text(out, n.y);
      out += ' ';
      put_text(out, n.z);
    }
    out += '\n';
  }
  return out;
}

std::string npy_bytes(const PointCloud& c) {
  const std::int64_t w = c.has_normals() ? 6 : 3;
  std::string out = npy_header_bytes(DType::F64, {static_cast<std::int64_t>(c.size()), w});
  out.reserve(out.size() + c.size() * static_cast<std::size_t>(w) * 8);
  put_rows(out, c);
  return out;
}

} // namespace

PointCloudFormat point_cloud_format_of(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  for (char& ch : e) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  if (e == ".ply") return PointCloudFormat::ply;
  if (e == ".xyz") return PointCloudFormat::xyz;
  if (e == ".off") return PointCloudFormat::off;
  if (e == ".npy") return PointCloudFormat::npy;
  throw IoError(path + ": unknown point cloud format '" + e + "' (.ply, .xyz, .off or .npy)");
}

PointCloud parse_point_cloud(std::string_view bytes, PointCloudFormat format,
                             const std::string& source) {
  PointCloud c;
  switch (format) {
  case PointCloudFormat::ply:
    c = from_ply(parse_ply_points(bytes, source));
    break;
  case PointCloudFormat::xyz:
    c = parse_xyz(bytes, source);
    break;
  case PointCloudFormat::off:
    c = parse_off(bytes, source);
    break;
  case PointCloudFormat::npy:
    c = from_npy(parse_npy(bytes, source), source);
    break;
  }
  validate_point_cloud(c, source);
  return c;
}

PointCloud read_point_cloud(const std::string& path) {
  const PointCloudFormat format = point_cloud_format_of(path);
  if (format == PointCloudFormat::npy) {
    PointCloud c = from_npy(read_npy(path), path);
    validate_point_cloud(c, path);
    return c;
  }
  return parse_point_cloud(read_input_file(path), format, path);
}

void write_point_cloud(const std::string& path, const PointCloud& cloud,
                       std::optional<PointCloudFormat> format) {
  const PointCloudFormat f = format ? *format : point_cloud_format_of(path);
  if (f == PointCloudFormat::off)
    throw IoError(path + ": point clouds are written as .ply, .xyz or .npy, not .off");
  validate_point_cloud(cloud, path);
  switch (f) {
  case PointCloudFormat::ply:
    write_file_atomically(path, ply_bytes(cloud));
    return;
  case PointCloudFormat::xyz:
    write_file_atomically(path, xyz_bytes(cloud));
    return;
  case PointCloudFormat::npy:
    write_file_atomically(path, npy_bytes(cloud));
    return;
  case PointCloudFormat::off:
    return;
  }
}

} // namespace zdg
