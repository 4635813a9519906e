#include <zdg/kernel/io/ply_read.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/io/input_file.hpp>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>

namespace zdg {

namespace {

enum class Type { i8, u8, i16, u16, i32, u32, f32, f64 };

std::optional<Type> type_of(std::string_view s) {
  if (s == "char" || s == "int8") return Type::i8;
  if (s == "uchar" || s == "uint8") return Type::u8;
  if (s == "short" || s == "int16") return Type::i16;
  if (s == "ushort" || s == "uint16") return Type::u16;
  if (s == "int" || s == "int32") return Type::i32;
  if (s == "uint" || s == "uint32") return Type::u32;
  if (s == "float" || s == "float32") return Type::f32;
  if (s == "double" || s == "float64") return Type::f64;
  return std::nullopt;
}

std::size_t size_of(Type t) {
  switch (t) {
  case Type::i8:
  case Type::u8:
    return 1;
  case Type::i16:
  case Type::u16:
    return 2;
  case Type::i32:
  case Type::u32:
  case Type::f32:
    return 4;
  case Type::f64:
    return 8;
  }
  return 0;
}

bool is_integer(Type t) {
  return t != Type::f32 && t != Type::f64;
}

struct Property {
  std::string name;
  Type type = Type::f32;
  bool list = false;
  Type count = Type::u8; // the count's type of a list
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> props;
};

enum class Format { ascii, little, big };

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const std::size_t b = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > b) out.push_back(line.substr(b, i - b));
  }
  return out;
}

// Reads the values of a body, binary or text, record after record.
class Body {
public:
  Body(std::string_view bytes, Format format, const std::string& source)
      : bytes_(bytes), format_(format), source_(source) {}

  std::size_t remaining() const { return bytes_.size() - pos_; }
  Format format() const { return format_; }

  // The next value of type t, as a double (integers are exact: at most 32 bits).
  // `where` () -> std::string names the value in an error (called only then).
  template <class Where>
  double value(Type t, const Where& where) {
    return format_ == Format::ascii ? text_value(t, where) : binary_value(t, where);
  }

  // After the last element: only white space may follow a text body, nothing a binary one.
  void finish() {
    if (format_ == Format::ascii)
      while (pos_ < bytes_.size() && is_space(bytes_[pos_])) ++pos_;
    if (pos_ != bytes_.size())
      throw IoError(source_ + ": " + std::to_string(bytes_.size() - pos_) +
                    " bytes after the last element");
  }

private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

  // The value of type T in the first sizeof(T) bytes (native order).
  template <class T>
  static double as_double(const unsigned char* b) {
    T v;
    std::memcpy(&v, b, sizeof(T));
    return static_cast<double>(v);
  }

  template <class Where>
  double binary_value(Type t, const Where& where) {
    const std::size_t n = size_of(t);
    if (remaining() < n) throw IoError(source_ + ": the file ends inside " + where());
    unsigned char b[8];
    std::memcpy(b, bytes_.data() + pos_, n);
    pos_ += n;
    if ((format_ == Format::big) != (std::endian::native == std::endian::big))
      std::reverse(b, b + n);
    switch (t) {
    case Type::i8:
      return as_double<std::int8_t>(b);
    case Type::u8:
      return as_double<std::uint8_t>(b);
    case Type::i16:
      return as_double<std::int16_t>(b);
    case Type::u16:
      return as_double<std::uint16_t>(b);
    case Type::i32:
      return as_double<std::int32_t>(b);
    case Type::u32:
      return as_double<std::uint32_t>(b);
    case Type::f32:
      return as_double<float>(b);
    case Type::f64:
      return as_double<double>(b);
    }
    return 0;
  }

  template <class Where>
  double text_value(Type t, const Where& where) {
    while (pos_ < bytes_.size() && is_space(bytes_[pos_])) ++pos_;
    const std::size_t b = pos_;
    while (pos_ < bytes_.size() && !is_space(bytes_[pos_])) ++pos_;
    const std::string_view tok = bytes_.substr(b, pos_ - b);
    if (tok.empty()) throw IoError(source_ + ": the file ends inside " + where());
    const char* first = tok.data();
    const char* last = tok.data() + tok.size();
    if (*first == '+') ++first;
    if (is_integer(t)) {
      std::int64_t v = 0;
      const auto r = std::from_chars(first, last, v);
      if (r.ec != std::errc() || r.ptr != last)
        throw IoError(source_ + ": " + where() + ": '" + std::string(tok) + "' is not an integer");
      const auto [lo, hi] = range(t);
      if (v < lo || v > hi)
        throw IoError(source_ + ": " + where() + ": " + std::string(tok) +
                      " is out of the property's type range");
      return double(v);
    }
    double v = 0;
    const auto r = std::from_chars(first, last, v);
    if (r.ec == std::errc::result_out_of_range) {
      const bool negative = *first == '-';
      // from_chars leaves v unchanged here: an overflow is an infinity, an underflow zero.
      bool tiny = false;
      for (const char* p = first; p < last; ++p)
        if (*p == 'e' || *p == 'E') tiny = p + 1 < last && p[1] == '-';
      const double mag = tiny ? 0.0 : std::numeric_limits<double>::infinity();
      return negative ? -mag : mag;
    }
    if (r.ec != std::errc() || r.ptr != last)
      throw IoError(source_ + ": " + where() + ": '" + std::string(tok) + "' is not a number");
    return t == Type::f32 ? double(float(v)) : v;
  }

  static std::pair<std::int64_t, std::int64_t> range(Type t) {
    switch (t) {
    case Type::i8:
      return {-128, 127};
    case Type::u8:
      return {0, 255};
    case Type::i16:
      return {-32768, 32767};
    case Type::u16:
      return {0, 65535};
    case Type::i32:
      return {std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max()};
    default:
      return {0, std::numeric_limits<std::uint32_t>::max()};
    }
  }

  std::string_view bytes_;
  std::size_t pos_ = 0;
  Format format_;
  const std::string& source_;
};

// The least number of bytes one record of e takes in the body (a text value takes a character
// and a separator, but the last one of the file may lack its separator).
std::uint64_t min_record_bytes(const Element& e, Format format) {
  std::uint64_t n = 0;
  for (const auto& p : e.props)
    n += format == Format::ascii ? 2 : size_of(p.list ? p.count : p.type);
  return n;
}

} // namespace

namespace {

// parse_ply, or with faces_optional a file without a face element (a point cloud).
PlyMesh parse_ply_file(std::string_view bytes, const std::string& source, bool faces_optional) {
  // The header: lines up to "end_header", each ended by "\n" (or "\r\n").
  std::size_t pos = 0;
  std::size_t line_no = 0;
  auto next_line = [&]() -> std::optional<std::string_view> {
    if (pos >= bytes.size()) return std::nullopt;
    const std::size_t e = bytes.find('\n', pos);
    if (e == std::string_view::npos) return std::nullopt;
    std::string_view l = bytes.substr(pos, e - pos);
    pos = e + 1;
    ++line_no;
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    return l;
  };
  auto header_error = [&](const std::string& what) {
    return IoError(source + ":" + std::to_string(line_no) + ": " + what);
  };
  const auto magic = next_line();
  if (!magic || *magic != "ply")
    throw IoError(source + ": not a PLY file (its first line is not 'ply')");
  std::optional<Format> format;
  std::string format_name;
  std::vector<Element> elements;
  std::vector<std::string> field_names; // zdg's "comment face fields:"
  bool has_field_comment = false;
  bool ended = false;
  while (auto line = next_line()) {
    const auto w = split(*line);
    if (w.empty()) continue;
    if (w[0] == "comment") {
      if (w.size() >= 3 && w[1] == "face" && w[2] == "fields:") {
        has_field_comment = true;
        field_names.assign(w.begin() + 3, w.end());
      }
      continue;
    }
    if (w[0] == "obj_info") continue;
    if (w[0] == "end_header") {
      ended = true;
      break;
    }
    if (w[0] == "format") {
      if (format) throw header_error("a second format line");
      if (w.size() != 3) throw header_error("format line: 'format TYPE 1.0' expected");
      if (w[2] != "1.0") throw header_error("PLY version '" + std::string(w[2]) + "' (1.0 read)");
      format_name = std::string(w[1]);
      if (w[1] == "ascii")
        format = Format::ascii;
      else if (w[1] == "binary_little_endian")
        format = Format::little;
      else if (w[1] == "binary_big_endian")
        format = Format::big;
      else
        throw header_error("unknown format '" + format_name +
                           "' (ascii, binary_little_endian or binary_big_endian)");
      continue;
    }
    if (w[0] == "element") {
      if (w.size() != 3) throw header_error("element line: 'element NAME COUNT' expected");
      Element e;
      e.name = std::string(w[1]);
      const auto r = std::from_chars(w[2].data(), w[2].data() + w[2].size(), e.count);
      if (r.ec != std::errc() || r.ptr != w[2].data() + w[2].size())
        throw header_error("element " + e.name + ": count '" + std::string(w[2]) +
                           "' is not a non-negative integer");
      for (const auto& o : elements)
        if (o.name == e.name) throw header_error("a second element '" + e.name + "'");
      elements.push_back(std::move(e));
      continue;
    }
    if (w[0] == "property") {
      if (elements.empty()) throw header_error("a property before any element");
      Property p;
      if (w.size() >= 2 && w[1] == "list") {
        if (w.size() != 5)
          throw header_error("list property: 'property list COUNT_TYPE TYPE NAME' expected");
        const auto c = type_of(w[2]), t = type_of(w[3]);
        if (!c || !is_integer(*c))
          throw header_error("list count type '" + std::string(w[2]) + "' (an integer type)");
        if (!t) throw header_error("unknown property type '" + std::string(w[3]) + "'");
        p.list = true;
        p.count = *c;
        p.type = *t;
        p.name = std::string(w[4]);
      } else {
        if (w.size() != 3) throw header_error("property line: 'property TYPE NAME' expected");
        const auto t = type_of(w[1]);
        if (!t) throw header_error("unknown property type '" + std::string(w[1]) + "'");
        p.type = *t;
        p.name = std::string(w[2]);
      }
      for (const auto& o : elements.back().props)
        if (o.name == p.name)
          throw header_error("element " + elements.back().name + ": a second property '" + p.name +
                             "'");
      elements.back().props.push_back(std::move(p));
      continue;
    }
    throw header_error("unknown header line '" + std::string(w[0]) + "'");
  }
  if (!ended) throw IoError(source + ": the header has no end_header line");
  if (!format) throw IoError(source + ": the header has no format line");

  PlyMesh out;
  out.format = format_name;
  const Element* vertex_el = nullptr;
  const Element* face_el = nullptr;
  for (const auto& e : elements) {
    if (e.name == "vertex") vertex_el = &e;
    if (e.name == "face") face_el = &e;
  }
  if (!vertex_el) throw IoError(source + ": no vertex element");
  auto find = [](const Element& e, std::string_view name) -> int {
    for (std::size_t k = 0; k < e.props.size(); ++k)
      if (e.props[k].name == name) return int(k);
    return -1;
  };
  // The vertex element's roles: 0..2 coordinates, 3..5 normal, 6 + j the j-th scalar.
  std::vector<int> vrole(vertex_el->props.size(), -1);
  const char* coord[3] = {"x", "y", "z"};
  const char* normal[3] = {"nx", "ny", "nz"};
  for (int k = 0; k < 3; ++k) {
    const int i = find(*vertex_el, coord[k]);
    if (i < 0 || vertex_el->props[std::size_t(i)].list)
      throw IoError(source + ": the vertex element has no scalar property '" + coord[k] + "'");
    vrole[std::size_t(i)] = k;
  }
  const bool vnormals =
      find(*vertex_el, "nx") >= 0 && find(*vertex_el, "ny") >= 0 && find(*vertex_el, "nz") >= 0;
  for (int k = 0; k < 3 && vnormals; ++k) {
    const auto i = std::size_t(find(*vertex_el, normal[k]));
    if (!vertex_el->props[i].list) vrole[i] = 3 + k;
  }
  for (std::size_t i = 0; i < vrole.size(); ++i) {
    const auto& p = vertex_el->props[i];
    if (vrole[i] >= 0) continue;
    if (p.list) {
      out.other.push_back("vertex." + p.name);
      continue;
    }
    vrole[i] = 6 + int(out.vertex_scalars.size());
    out.vertex_scalars.emplace_back(p.name, std::vector<double>{});
  }
  if (!face_el && !faces_optional)
    throw IoError(source + ": no face element (a point cloud is not a mesh)");
  // The face element's roles: 0 the indices, 1..3 normal, 4 + j the j-th scalar.
  const Element no_faces;
  if (!face_el) face_el = &no_faces; // no records: none is read
  std::vector<int> frole(face_el->props.size(), -1);
  int ind = face_el == &no_faces ? 0 : find(*face_el, "vertex_indices");
  if (ind < 0) ind = find(*face_el, "vertex_index");
  if (face_el != &no_faces) {
    if (ind < 0 || !face_el->props[std::size_t(ind)].list)
      throw IoError(source + ": the face element has no list property 'vertex_indices'");
    if (!is_integer(face_el->props[std::size_t(ind)].type))
      throw IoError(source + ": the face indices are of a floating-point type");
    frole[std::size_t(ind)] = 0;
  }
  bool fnormals = face_el != &no_faces;
  for (int k = 0; k < 3; ++k) {
    const int i = find(*face_el, normal[k]);
    fnormals = fnormals && i >= 0 && !face_el->props[std::size_t(i)].list;
  }
  for (int k = 0; k < 3 && fnormals; ++k) frole[std::size_t(find(*face_el, normal[k]))] = 1 + k;
  std::vector<std::pair<std::string, std::vector<double>>> fscalars;
  for (std::size_t i = 0; i < frole.size(); ++i) {
    const auto& p = face_el->props[i];
    if (frole[i] >= 0) continue;
    if (p.list) {
      out.other.push_back("face." + p.name);
      continue;
    }
    frole[i] = 4 + int(fscalars.size());
    fscalars.emplace_back(p.name, std::vector<double>{});
  }
  if (has_field_comment && field_names.size() == fscalars.size())
    for (std::size_t j = 0; j < fscalars.size(); ++j) fscalars[j].first = field_names[j];
  for (const auto& e : elements)
    if (&e != vertex_el && &e != face_el) out.other.push_back(e.name);

  // The body.
  Body body(bytes.substr(pos), *format, source);
  const auto nv_limit = std::uint64_t(std::numeric_limits<std::int64_t>::max());
  if (vertex_el->count > nv_limit) throw IoError(source + ": too many vertices");
  const auto nv = std::int64_t(vertex_el->count);
  std::vector<Point3<double>> vertices, vnormal;
  std::vector<std::vector<std::int64_t>> mixed; // faces while their sizes may differ
  std::vector<std::int64_t> flat;               // faces of one size
  int face_size = 0;
  bool one_size = true;
  std::vector<Point3<double>> fnormal;
  std::vector<std::vector<double>> fvalues(fscalars.size());
  std::vector<std::int64_t> sizes;
  for (const auto& e : elements) {
    // A count the rest of the file cannot hold is an error before any memory is taken.
    const std::uint64_t least = min_record_bytes(e, *format);
    if (least > 0 && e.count > (body.remaining() + 1) / least)
      throw IoError(source + ": element " + e.name + " claims " + std::to_string(e.count) +
                    " records, more than the file's " + std::to_string(body.remaining()) +
                    " remaining bytes can hold");
    const bool is_vertex = &e == vertex_el, is_face = &e == face_el;
    if (is_vertex) {
      vertices.reserve(e.count);
      if (vnormals) vnormal.reserve(e.count);
      for (auto& s : out.vertex_scalars) s.second.reserve(e.count);
    }
    for (std::uint64_t r = 0; r < e.count; ++r) {
      Point3<double> p{}, n{};
      for (std::size_t i = 0; i < e.props.size(); ++i) {
        const auto& prop = e.props[i];
        const auto where = [&] {
          return e.name + " " + std::to_string(r) + " (" + prop.name + ")";
        };
        if (prop.list) {
          const double c = body.value(prop.count, where);
          if (c < 0) throw IoError(source + ": " + where() + ": negative list length");
          const auto len = std::uint64_t(c);
          if (len > body.remaining())
            throw IoError(source + ": " + where() + ": a list of " + std::to_string(len) +
                          " items, more than the file's remaining bytes");
          if (is_face && frole[i] == 0) {
            if (len < 3)
              throw IoError(source + ": face " + std::to_string(r) + ": " + std::to_string(len) +
                            " vertices (at least 3 needed)");
            std::vector<std::int64_t> f(len);
            for (auto& x : f) {
              const double v = body.value(prop.type, where);
              if (v < 0 || v >= double(nv))
                throw IoError(source + ": face " + std::to_string(r) + ": vertex index " +
                              std::to_string(std::int64_t(v)) + " out of range (" +
                              std::to_string(nv) + " vertices)");
              x = std::int64_t(v);
            }
            if (face_size == 0) face_size = int(std::min<std::uint64_t>(len, 1u << 30));
            if (one_size && std::uint64_t(face_size) != len) {
              one_size = false;
              // The faces so far, as lists.
              const auto fs = std::size_t(face_size);
              for (std::size_t k = 0; k < flat.size(); k += fs)
                mixed.emplace_back(flat.begin() + std::ptrdiff_t(k),
                                   flat.begin() + std::ptrdiff_t(k + fs));
              flat.clear();
              flat.shrink_to_fit();
            }
            if (one_size)
              flat.insert(flat.end(), f.begin(), f.end());
            else
              mixed.push_back(std::move(f));
          } else {
            for (std::uint64_t k = 0; k < len; ++k) (void)body.value(prop.type, where);
          }
          continue;
        }
        const double v = body.value(prop.type, where);
        if (is_vertex) {
          const int role = vrole[i];
          if (role < 3 && !std::isfinite(v))
            throw IoError(source + ": vertex " + std::to_string(r) + ": coordinate " + prop.name +
                          " is not finite");
          if (role == 0) p.x = v;
          if (role == 1) p.y = v;
          if (role == 2) p.z = v;
          if (role == 3) n.x = v;
          if (role == 4) n.y = v;
          if (role == 5) n.z = v;
          if (role >= 6) out.vertex_scalars[std::size_t(role - 6)].second.push_back(v);
        } else if (is_face) {
          const int role = frole[i];
          if (role == 1) n.x = v;
          if (role == 2) n.y = v;
          if (role == 3) n.z = v;
          if (role >= 4) fvalues[std::size_t(role - 4)].push_back(v);
        }
      }
      if (is_vertex) {
        vertices.push_back(p);
        if (vnormals) vnormal.push_back(n);
      }
      if (is_face && fnormals) fnormal.push_back(n);
    }
  }
  body.finish();

  PolygonMesh& m = out.mesh;
  m.vertices = std::move(vertices);
  m.vertex_normals = std::move(vnormal);
  out.file_faces = std::int64_t(face_el->count);
  if (one_size) {
    m.face_size = face_size == 0 ? 3 : face_size;
    m.indices = std::move(flat);
    m.face_normals = std::move(fnormal);
    for (std::size_t j = 0; j < fscalars.size(); ++j)
      m.face_scalars.emplace_back(fscalars[j].first, std::move(fvalues[j]));
  } else {
    // The fan of each face: its scalars and normal repeated on each of its triangles.
    out.triangulated = true;
    m.face_size = 3;
    for (std::size_t j = 0; j < fscalars.size(); ++j)
      m.face_scalars.emplace_back(fscalars[j].first, std::vector<double>{});
    for (std::size_t f = 0; f < mixed.size(); ++f) {
      const auto& q = mixed[f];
      for (std::size_t k = 1; k + 1 < q.size(); ++k) {
        m.indices.insert(m.indices.end(), {q[0], q[k], q[k + 1]});
        if (fnormals) m.face_normals.push_back(fnormal[f]);
        for (std::size_t j = 0; j < fscalars.size(); ++j)
          m.face_scalars[j].second.push_back(fvalues[j][f]);
      }
    }
  }
  m.validate();
  return out;
}

} // namespace

PlyMesh parse_ply(std::string_view bytes, const std::string& source) {
  return parse_ply_file(bytes, source, false);
}

PlyMesh parse_ply_points(std::string_view bytes, const std::string& source) {
  return parse_ply_file(bytes, source, true);
}

PlyMesh read_ply(const std::string& path) {
  return parse_ply(read_input_file(path), path);
}

} // namespace zdg
