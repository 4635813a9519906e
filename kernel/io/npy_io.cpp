#include <zdg/kernel/io/npy_io.hpp>

#include <zdg/kernel/io/output_files.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/arith/integer.hpp>
#include <zdg/kernel/io/input_file.hpp>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string_view>
#include <unistd.h>
#include <utility>

namespace zdg {

namespace {

struct DTypeInfo {
  DType t;
  const char* descr;
  const char* name;
  std::size_t size;
};

constexpr DTypeInfo kTypes[] = {
    {DType::Bool, "|b1", "bool", 1},   {DType::U8, "|u1", "uint8", 1},
    {DType::U16, "<u2", "uint16", 2},  {DType::U32, "<u4", "uint32", 4},
    {DType::U64, "<u8", "uint64", 8},  {DType::I8, "|i1", "int8", 1},
    {DType::I16, "<i2", "int16", 2},   {DType::I32, "<i4", "int32", 4},
    {DType::I64, "<i8", "int64", 8},   {DType::F32, "<f4", "float32", 4},
    {DType::F64, "<f8", "float64", 8},
};

// The accepted dtypes by name, in kTypes' order ("bool, uint8, ..., float64"): the list every
// message about an unsupported dtype gives, so that it cannot drift from what is read.
std::string accepted_dtype_names() {
  std::string out;
  for (const auto& i : kTypes) out += (out.empty() ? "" : ", ") + std::string(i.name);
  return out;
}

const DTypeInfo& info(DType t) {
  for (const auto& i : kTypes) {
    if (i.t == t) return i;
  }
  return kTypes[0];
}

// The message quotes header text (a dtype, a key) as it was read: control characters (a line
// break inside a quoted dtype) become '?', so that the error stays one line.
[[noreturn]] void fail(const std::string& path, const std::string& what) {
  std::string line = what;
  for (char& c : line)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  throw IoError(path + ": " + line);
}

// The header of an npy file: its dict parsed (a Python literal restricted to what numpy
// writes: string keys; string, True/False and tuple-of-integers values), and where the data
// start.
struct NpyHeader {
  DType dtype = DType::U8;
  std::vector<std::int64_t> shape;
  std::size_t data_offset = 0;  // bytes before the array data
  std::uint64_t data_bytes = 0; // count * itemsize (checked against overflow)
  bool fortran_order = false;   // the data are stored first axis fastest
};

// The fixed prefix: magic, version, header length. Returns the header length and the offset
// of the header text; needs the first 12 bytes (or fewer for a short file: an error then).
std::pair<std::size_t, std::size_t> npy_prefix(const std::string& source, std::string_view data) {
  if (data.empty()) fail(source, "empty file (not an npy array)");
  if (data.size() < 6 || data.compare(0, 6, "\x93NUMPY") != 0) {
    fail(source, "not an npy file (missing \\x93NUMPY magic)");
  }
  if (data.size() < 10) fail(source, "truncated npy header");
  const auto major = static_cast<unsigned char>(data[6]);
  if (major == 1) {
    const std::size_t hlen = static_cast<unsigned char>(data[8]) |
                             (static_cast<std::size_t>(static_cast<unsigned char>(data[9])) << 8);
    return {hlen, 10};
  }
  if (major == 2 || major == 3) {
    if (data.size() < 12) fail(source, "truncated npy header");
    std::size_t hlen = 0;
    for (int k = 3; k >= 0; --k)
      hlen = (hlen << 8) | static_cast<unsigned char>(data[8 + static_cast<std::size_t>(k)]);
    return {hlen, 12};
  }
  fail(source, "unsupported npy format version " + std::to_string(major));
}

// A cursor over the header text.
class HeaderText {
public:
  HeaderText(const std::string& source, std::string_view text) : source_(source), t_(text) {}

  [[noreturn]] void bad(const std::string& what) const {
    fail(source_, "malformed npy header (" + what + ")");
  }
  void skip() {
    while (i_ < t_.size() && (t_[i_] == ' ' || t_[i_] == '\t' || t_[i_] == '\n' || t_[i_] == '\r'))
      ++i_;
  }
  bool at(char c) {
    skip();
    return i_ < t_.size() && t_[i_] == c;
  }
  void expect(char c) {
    if (!at(c)) bad(std::string("expected '") + c + "'");
    ++i_;
  }
  bool done() {
    skip();
    return i_ == t_.size();
  }
  std::string string_literal() {
    skip();
    if (i_ >= t_.size() || (t_[i_] != '\'' && t_[i_] != '"')) bad("expected a quoted string");
    const char q = t_[i_++];
    const std::size_t b = i_;
    while (i_ < t_.size() && t_[i_] != q) {
      if (t_[i_] == '\\') bad("escape in a string");
      ++i_;
    }
    if (i_ >= t_.size()) bad("unterminated string");
    return std::string(t_.substr(b, i_++ - b));
  }
  bool boolean() {
    skip();
    if (t_.substr(i_, 4) == "True") {
      i_ += 4;
      return true;
    }
    if (t_.substr(i_, 5) == "False") {
      i_ += 5;
      return false;
    }
    bad("fortran_order must be True or False");
  }
  // (n0, n1, ...) with an optional trailing comma; "()" is a 0-d array.
  std::vector<std::int64_t> tuple() {
    expect('(');
    std::vector<std::int64_t> out;
    while (!at(')')) {
      skip();
      const std::size_t b = i_;
      while (i_ < t_.size() && t_[i_] >= '0' && t_[i_] <= '9') ++i_;
      if (i_ == b) bad("shape entries must be non-negative integers");
      try {
        out.push_back(parse_integer<std::int64_t>(t_.substr(b, i_ - b)));
      } catch (const Error&) {
        fail(source_, "shape entry " +
                          std::string(t_.substr(b, std::min<std::size_t>(i_ - b, 40))) +
                          " too large");
      }
      if (i_ < t_.size() && t_[i_] == 'L') ++i_; // Python 2 long
      if (at(',')) {
        ++i_;
      } else if (!at(')')) {
        bad("expected ',' or ')' in the shape");
      }
    }
    ++i_;
    return out;
  }

private:
  const std::string& source_;
  std::string_view t_;
  std::size_t i_ = 0;
};

DType dtype_of(const std::string& source, const std::string& d) {
  for (const auto& t : kTypes) {
    const std::string want = t.descr;
    // byte-sized types may be written with '|', '<' or '='; wider ones with '<' or '='.
    bool match = d == want || (d.size() == 3 && (d[0] == '<' || d[0] == '=' || d[0] == '|') &&
                               d.substr(1) == want.substr(1) && (t.size == 1 || d[0] != '|'));
    if (match) return t.t;
  }
  std::string shown = d.substr(0, 40);
  if (!d.empty() && d[0] == '>') {
    fail(source, "big-endian dtype '" + shown + "' is not supported (use little-endian)");
  }
  fail(source, "dtype '" + shown + "' is not supported (accepted: " + accepted_dtype_names() +
                   ", little-endian)");
}

// Parses the dict {'descr': ..., 'fortran_order': ..., 'shape': (...), } (keys in any order,
// each exactly once) and computes the data size without overflow.
NpyHeader parse_header(const std::string& source, std::string_view text, std::size_t offset) {
  HeaderText h(source, text);
  NpyHeader out;
  out.data_offset = offset;
  bool has_descr = false, has_order = false, has_shape = false;
  h.expect('{');
  while (!h.at('}')) {
    const std::string key = h.string_literal();
    h.expect(':');
    bool* seen = nullptr;
    if (key == "descr") {
      out.dtype = dtype_of(source, h.string_literal());
      seen = &has_descr;
    } else if (key == "fortran_order") {
      out.fortran_order = h.boolean();
      seen = &has_order;
    } else if (key == "shape") {
      out.shape = h.tuple();
      seen = &has_shape;
    } else {
      h.bad("unknown key '" + key.substr(0, 40) + "'");
    }
    if (*seen) h.bad("key '" + key + "' given twice");
    *seen = true;
    if (h.at(',')) {
      h.expect(',');
    } else if (!h.at('}')) {
      h.bad("expected ',' or '}'");
    }
  }
  h.expect('}');
  if (!h.done()) h.bad("text after the dict");
  if (!has_descr) fail(source, "npy header has no 'descr' entry");
  if (!has_order) fail(source, "npy header has no 'fortran_order' entry");
  if (!has_shape) fail(source, "npy header has no 'shape' entry");
  std::uint64_t count = 1, extents = 1;
  for (auto e : out.shape) {
    if (__builtin_mul_overflow(count, static_cast<std::uint64_t>(e), &count)) {
      fail(source, "shape too large (more than 2^64 elements)");
    }
    // The extents themselves, zeros skipped: an empty array (4, 0, 88884, ...) still has a
    // domain whose other extents multiply, and that product must fit int64 too.
    if (__builtin_mul_overflow(extents, static_cast<std::uint64_t>(e == 0 ? 1 : e), &extents) ||
        extents > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
      fail(source, "shape too large (its nonzero extents multiply past 2^63)");
    }
  }
  if (__builtin_mul_overflow(count, static_cast<std::uint64_t>(dtype_size(out.dtype)),
                             &out.data_bytes)) {
    fail(source, "shape too large (more than 2^64 bytes)");
  }
  if (count > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
    fail(source, "shape too large (more than 2^63 elements)");
  }
  return out;
}

std::string shape_text(const std::vector<std::int64_t>& shape) {
  std::string s = "(";
  for (std::size_t k = 0; k < shape.size() && k < 8; ++k)
    s += (k ? ", " : "") + std::to_string(shape[k]);
  if (shape.size() > 8) s += ", ...";
  return s + (shape.size() == 1 ? ",)" : ")");
}

// The data must be exactly count * itemsize bytes.
void check_data_size(const std::string& source, const NpyHeader& h, std::uint64_t have) {
  if (have < h.data_bytes) {
    fail(source, "truncated data: " + std::to_string(have) + " bytes for shape " +
                     shape_text(h.shape) + " of " + dtype_name(h.dtype) + " (" +
                     std::to_string(h.data_bytes) + " needed)");
  }
  if (have > h.data_bytes) fail(source, "trailing bytes after the array data");
}

// The bytes of a Fortran-order array (first axis fastest) of this shape, reordered into C order
// (last axis fastest): one pass over the C-order positions with an odometer of the Fortran
// offsets. O(count) moves of `item` bytes.
std::vector<unsigned char> fortran_to_c(const std::vector<unsigned char>& f,
                                        const std::vector<std::int64_t>& shape, std::size_t item) {
  std::vector<unsigned char> c(f.size());
  const std::size_t d = shape.size();
  if (f.empty() || d < 2) return f;
  std::vector<std::uint64_t> fstride(d);
  std::uint64_t s = item;
  for (std::size_t k = 0; k < d; ++k) {
    fstride[k] = s;
    s *= static_cast<std::uint64_t>(shape[k]);
  }
  std::vector<std::int64_t> idx(d, 0);
  std::uint64_t src = 0;
  const std::size_t n = f.size() / item;
  for (std::size_t i = 0; i < n; ++i) {
    std::memcpy(c.data() + i * item, f.data() + src, item);
    for (std::size_t k = d; k-- > 0;) { // advance the C-order index, last axis first
      src += fstride[k];
      if (++idx[k] < shape[k]) break;
      src -= fstride[k] * static_cast<std::uint64_t>(shape[k]);
      idx[k] = 0;
    }
  }
  return c;
}

} // namespace

std::string dtype_name(DType t) {
  return info(t).name;
}
std::size_t dtype_size(DType t) {
  return info(t).size;
}

std::int64_t NpyArray::count() const {
  std::int64_t n = 1;
  for (auto s : shape) {
    if (s == 0) return 0;
  }
  for (auto s : shape) {
    if (__builtin_mul_overflow(n, s, &n)) throw OverflowError("npy shape: element count past 2^63");
  }
  return n;
}

std::int64_t NpyArray::get(std::int64_t i) const {
  const unsigned char* p = bytes.data() + static_cast<std::size_t>(i) * dtype_size(dtype);
  switch (dtype) {
  case DType::Bool:
  case DType::U8:
    return p[0];
  case DType::I8:
    return static_cast<std::int8_t>(p[0]);
  case DType::U16: {
    std::uint16_t v;
    std::memcpy(&v, p, 2);
    return v;
  }
  case DType::I16: {
    std::int16_t v;
    std::memcpy(&v, p, 2);
    return v;
  }
  case DType::U32: {
    std::uint32_t v;
    std::memcpy(&v, p, 4);
    return v;
  }
  case DType::I32: {
    std::int32_t v;
    std::memcpy(&v, p, 4);
    return v;
  }
  case DType::U64: {
    std::uint64_t v;
    std::memcpy(&v, p, 8);
    if (v > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
      throw IoError("uint64 value " + std::to_string(v) + " does not fit int64");
    }
    return static_cast<std::int64_t>(v);
  }
  case DType::I64: {
    std::int64_t v;
    std::memcpy(&v, p, 8);
    return v;
  }
  case DType::F32:
  case DType::F64:
    throw IoError(dtype_name(dtype) + " array where integers are needed");
  }
  return 0;
}

NpyArray parse_npy(std::string_view data, const std::string& source) {
  const auto [hlen, hstart] = npy_prefix(source, data);
  if (data.size() - hstart < hlen) fail(source, "truncated npy header");
  const NpyHeader h = parse_header(source, data.substr(hstart, hlen), hstart + hlen);
  check_data_size(source, h, data.size() - h.data_offset);
  NpyArray a;
  a.dtype = h.dtype;
  a.shape = h.shape;
  a.bytes.assign(data.begin() + static_cast<std::ptrdiff_t>(h.data_offset), data.end());
  if (h.fortran_order) a.bytes = fortran_to_c(a.bytes, a.shape, dtype_size(a.dtype));
  return a;
}

double NpyArray::get_double(std::int64_t i) const {
  const unsigned char* p = bytes.data() + static_cast<std::size_t>(i) * dtype_size(dtype);
  switch (dtype) {
  case DType::F32: {
    float v;
    std::memcpy(&v, p, 4);
    return v;
  }
  case DType::F64: {
    double v;
    std::memcpy(&v, p, 8);
    return v;
  }
  case DType::U64: {
    std::uint64_t v;
    std::memcpy(&v, p, 8);
    return static_cast<double>(v);
  }
  default:
    return static_cast<double>(get(i));
  }
}

bool dtype_is_float(DType t) {
  return t == DType::F32 || t == DType::F64;
}

DType dtype_from_name(const std::string& name) {
  for (const auto& i : kTypes) {
    if (name == i.name) return i.t;
  }
  throw InvalidArgument("dtype '" + name +
                        "' is not supported (accepted: " + accepted_dtype_names() + ")");
}

namespace {
// The header of the file at path, checked against the file's size; `in` is left open.
NpyHeader read_header(const std::string& path, std::ifstream& in, std::uint64_t size) {
  if (!in) fail(path, "cannot open for reading");
  std::string prefix(static_cast<std::size_t>(std::min<std::uint64_t>(size, 12)), '\0');
  in.read(prefix.data(), static_cast<std::streamsize>(prefix.size()));
  const auto [hlen, hstart] = npy_prefix(path, prefix);
  if (size - hstart < hlen) fail(path, "truncated npy header");
  std::string header(hlen, '\0');
  in.seekg(static_cast<std::streamoff>(hstart));
  in.read(header.data(), static_cast<std::streamsize>(hlen));
  if (!in) fail(path, "read error in the npy header");
  const NpyHeader h = parse_header(path, header, hstart + hlen);
  check_data_size(path, h, size - h.data_offset);
  return h;
}
} // namespace

NpyArray read_npy(const std::string& path) {
  // Header first, then the data straight into the array, once its size has been checked
  // against the file's: nothing is allocated on the header's word alone.
  const std::uint64_t size = input_file_size(path);
  std::ifstream in(path, std::ios::binary);
  const NpyHeader h = read_header(path, in, size);
  NpyArray a;
  a.dtype = h.dtype;
  a.shape = h.shape;
  a.bytes.resize(static_cast<std::size_t>(h.data_bytes));
  in.seekg(static_cast<std::streamoff>(h.data_offset));
  in.read(reinterpret_cast<char*>(a.bytes.data()), static_cast<std::streamsize>(a.bytes.size()));
  if (!in && !a.bytes.empty()) fail(path, "read error in the array data");
  if (h.fortran_order) a.bytes = fortran_to_c(a.bytes, a.shape, dtype_size(a.dtype));
  return a;
}

NpyLayout read_npy_layout(const std::string& path) {
  const std::uint64_t size = input_file_size(path);
  std::ifstream in(path, std::ios::binary);
  const NpyHeader h = read_header(path, in, size);
  return {h.dtype, h.shape, h.data_offset, h.data_bytes, h.fortran_order};
}

std::string npy_header_bytes(DType t, const std::vector<std::int64_t>& shape) {
  std::ostringstream h;
  h << "{'descr': '" << info(t).descr << "', 'fortran_order': False, 'shape': (";
  for (std::size_t k = 0; k < shape.size(); ++k)
    h << shape[k] << (shape.size() == 1 ? "," : (k + 1 < shape.size() ? ", " : ""));
  h << "), }";
  std::string header = h.str();
  // Version 1.0 holds a header of up to 65535 bytes (2-byte length), 2.0 up to 4 GiB (4-byte
  // length); the header is ASCII, so 3.0 (UTF-8) is never needed. The whole prefix is padded
  // with spaces to a multiple of 64 bytes and ends with '\n', as numpy writes it.
  const bool v1 = 10 + header.size() + 1 + 63 <= 65535 + 10;
  const std::size_t prefix = v1 ? 10 : 12;
  const std::size_t total = prefix + header.size() + 1;
  header.append((64 - total % 64) % 64, ' ');
  header.push_back('\n');
  if (header.size() > 0xffffffffULL) {
    throw InvalidArgument("npy header of " + std::to_string(header.size()) +
                          " bytes: more than npy's 4 GiB limit");
  }
  std::string out = "\x93NUMPY";
  out.push_back(v1 ? '\x01' : '\x02');
  out.push_back('\x00');
  const std::size_t len = header.size();
  for (std::size_t k = 0; k < (v1 ? 2u : 4u); ++k)
    out.push_back(static_cast<char>((len >> (8 * k)) & 0xff));
  out += header;
  return out;
}

std::string npy_file_bytes(const NpyArray& a) {
  std::string out = npy_header_bytes(a.dtype, a.shape);
  out.append(reinterpret_cast<const char*>(a.bytes.data()), a.bytes.size());
  return out;
}

void write_npy(const std::string& path, const NpyArray& a) {
  write_file_atomically(path, npy_file_bytes(a));
}

NpyArray make_npy(DType t, std::vector<std::int64_t> shape, const std::vector<std::int64_t>& v) {
  NpyArray a;
  a.dtype = t;
  a.shape = std::move(shape);
  const std::size_t sz = dtype_size(t);
  a.bytes.resize(v.size() * sz);
  for (std::size_t i = 0; i < v.size(); ++i) {
    std::int64_t x = v[i];
    bool ok = true;
    switch (t) {
    case DType::Bool:
      ok = x == 0 || x == 1;
      break;
    case DType::U8:
      ok = x >= 0 && x <= 255;
      break;
    case DType::I8:
      ok = x >= -128 && x <= 127;
      break;
    case DType::U16:
      ok = x >= 0 && x <= 65535;
      break;
    case DType::I16:
      ok = x >= -32768 && x <= 32767;
      break;
    case DType::U32:
      ok = x >= 0 && x <= 4294967295LL;
      break;
    case DType::I32:
      ok = x >= INT32_MIN && x <= INT32_MAX;
      break;
    case DType::U64:
      ok = x >= 0;
      break;
    case DType::I64:
      break;
    case DType::F32:
    case DType::F64:
      throw InvalidArgument("make_npy from int64 values builds integer arrays, not " +
                            dtype_name(t));
    }
    if (!ok) throw InvalidArgument("value " + std::to_string(x) + " does not fit " + dtype_name(t));
    std::memcpy(a.bytes.data() + i * sz, &x, sz); // little-endian host
  }
  return a;
}

template <class T>
NpyArray make_npy(std::vector<std::int64_t> shape, const std::vector<T>& v) {
  NpyArray a;
  if constexpr (std::is_same_v<T, std::uint8_t>) a.dtype = DType::U8;
  if constexpr (std::is_same_v<T, std::uint16_t>) a.dtype = DType::U16;
  if constexpr (std::is_same_v<T, std::uint32_t>) a.dtype = DType::U32;
  if constexpr (std::is_same_v<T, std::uint64_t>) a.dtype = DType::U64;
  if constexpr (std::is_same_v<T, std::int64_t>) a.dtype = DType::I64;
  if constexpr (std::is_same_v<T, std::int8_t>) a.dtype = DType::I8;
  if constexpr (std::is_same_v<T, std::int16_t>) a.dtype = DType::I16;
  if constexpr (std::is_same_v<T, std::int32_t>) a.dtype = DType::I32;
  if constexpr (std::is_same_v<T, float>) a.dtype = DType::F32;
  if constexpr (std::is_same_v<T, double>) a.dtype = DType::F64;
  a.shape = std::move(shape);
  a.bytes.resize(v.size() * sizeof(T));
  if (!v.empty()) std::memcpy(a.bytes.data(), v.data(), a.bytes.size());
  return a;
}

template NpyArray make_npy(std::vector<std::int64_t>, const std::vector<std::uint8_t>&);
template NpyArray make_npy(std::vector<std::int64_t>, const std::vector<std::uint16_t>&);
template NpyArray make_npy(std::vector<std::int64_t>, const std::vector<std::uint32_t>&);
template NpyArray make_npy(std::vector<std::int64_t>, const std::vector<std::uint64_t>&);
template NpyArray make_npy(std::vector<std::int64_t>, const std::vector<std::int64_t>&);
template NpyArray make_npy(std::vector<std::int64_t>, const std::vector<std::int8_t>&);
template NpyArray make_npy(std::vector<std::int64_t>, const std::vector<std::int16_t>&);
template NpyArray make_npy(std::vector<std::int64_t>, const std::vector<std::int32_t>&);
template NpyArray make_npy(std::vector<std::int64_t>, const std::vector<float>&);
template NpyArray make_npy(std::vector<std::int64_t>, const std::vector<double>&);

namespace {
Domain npy_domain(const NpyArray& a, const std::vector<std::int64_t>& lower,
                  const std::string& source) {
  const std::string at = source.empty() ? "" : source + ": ";
  if (a.shape.empty()) throw IoError(at + "a 0-dimensional array is not an image");
  for (auto s : a.shape) {
    if (s == 0) throw IoError(at + "empty array (an extent is 0)");
  }
  if (at.empty()) return Domain(a.shape, lower);
  try {
    return Domain(a.shape, lower);
  } catch (const Error& e) {
    throw IoError(at + e.what());
  }
}
} // namespace

Image<std::uint8_t> npy_to_mask(const NpyArray& a, const std::vector<std::int64_t>& lower,
                                const std::string& source) {
  Image<std::uint8_t> img(npy_domain(a, lower, source));
  const std::size_t sz = dtype_size(a.dtype);
  auto& v = img.values();
  if (dtype_is_float(a.dtype)) {
    for (std::size_t i = 0; i < v.size(); ++i)
      v[i] = a.get_double(static_cast<std::int64_t>(i)) != 0.0 ? 1 : 0;
    return img;
  }
  for (std::size_t i = 0; i < v.size(); ++i) {
    bool nz = false;
    for (std::size_t b = 0; b < sz; ++b) nz = nz || a.bytes[i * sz + b] != 0;
    v[i] = nz ? 1 : 0;
  }
  return img;
}

Image<std::int64_t> npy_to_int64(const NpyArray& a, const std::vector<std::int64_t>& lower,
                                 const std::string& source) {
  if (dtype_is_float(a.dtype))
    throw IoError((source.empty() ? "" : source + ": ") + dtype_name(a.dtype) +
                  " array where integers are needed");
  Image<std::int64_t> img(npy_domain(a, lower, source));
  for (std::int64_t i = 0; i < img.size(); ++i) {
    try {
      img[i] = a.get(i);
    } catch (const Error& e) {
      // A uint64 value past 2^63 - 1: say which file and which element.
      throw IoError((source.empty() ? "" : source + ": ") + "element " + std::to_string(i) + ": " +
                    e.what());
    }
  }
  return img;
}

} // namespace zdg
