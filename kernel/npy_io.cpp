#include <zdg/kernel/npy_io.hpp>

#include <zdg/kernel/output_files.hpp>

#include <zdg/arith/error.hpp>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <unistd.h>

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

const DTypeInfo& info(DType t) {
  for (const auto& i : kTypes) {
    if (i.t == t) return i;
  }
  return kTypes[0];
}

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw IoError(path + ": " + what);
}

// The value of key 'key' in the header dict, as raw text up to the next top-level comma.
std::string dict_value(const std::string& path, const std::string& header, const std::string& key) {
  auto k = header.find("'" + key + "'");
  if (k == std::string::npos) fail(path, "npy header has no '" + key + "' entry");
  auto colon = header.find(':', k);
  if (colon == std::string::npos) fail(path, "malformed npy header");
  std::size_t i = colon + 1;
  while (i < header.size() && header[i] == ' ') ++i;
  if (i < header.size() && header[i] == '(') {
    auto close = header.find(')', i);
    if (close == std::string::npos) fail(path, "malformed shape in npy header");
    return header.substr(i, close - i + 1);
  }
  auto end = header.find_first_of(",}", i);
  if (end == std::string::npos) fail(path, "malformed npy header");
  return header.substr(i, end - i);
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
  for (auto s : shape) n *= s;
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
                        "' (bool, uint8/16/32/64, int8/16/32/64, float32, float64)");
}

NpyArray read_npy(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot open for reading");
  std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (data.empty()) fail(path, "empty file (not an npy array)");
  if (data.size() < 10 || data.compare(0, 6, "\x93NUMPY") != 0) {
    fail(path, "not an npy file (missing \\x93NUMPY magic)");
  }
  auto major = static_cast<unsigned char>(data[6]);
  std::size_t hlen = 0, hstart = 0;
  if (major == 1) {
    hlen = static_cast<unsigned char>(data[8]) |
           (static_cast<std::size_t>(static_cast<unsigned char>(data[9])) << 8);
    hstart = 10;
  } else if (major == 2 || major == 3) {
    if (data.size() < 12) fail(path, "truncated npy header");
    for (int k = 3; k >= 0; --k)
      hlen = (hlen << 8) | static_cast<unsigned char>(data[8 + static_cast<std::size_t>(k)]);
    hstart = 12;
  } else {
    fail(path, "unsupported npy format version " + std::to_string(major));
  }
  if (data.size() < hstart + hlen) fail(path, "truncated npy header");
  std::string header = data.substr(hstart, hlen);
  NpyArray a;
  std::string descr = dict_value(path, header, "descr");
  std::string d = descr;
  if (d.size() >= 2 && (d.front() == '\'' || d.front() == '"')) d = d.substr(1, d.size() - 2);
  bool found = false;
  for (const auto& t : kTypes) {
    std::string want = t.descr;
    // byte-sized types may be written with '|', '<' or '='; wider ones with '<' or '='.
    bool match = d == want || (d.size() == 3 && (d[0] == '<' || d[0] == '=' || d[0] == '|') &&
                               d.substr(1) == want.substr(1) && (t.size == 1 || d[0] != '|'));
    if (match) {
      a.dtype = t.t;
      found = true;
      break;
    }
  }
  if (!found) {
    if (!d.empty() && d[0] == '>') {
      fail(path, "big-endian dtype '" + d + "' is not supported (use little-endian)");
    }
    fail(path, "dtype '" + d +
                   "' is not supported (bool, uint8/16/32/64, int8/16/32/64, float32/64 only)");
  }
  std::string fo = dict_value(path, header, "fortran_order");
  if (fo.find("True") != std::string::npos) {
    fail(path, "Fortran-order arrays are not supported (save with np.ascontiguousarray)");
  }
  if (fo.find("False") == std::string::npos) fail(path, "malformed fortran_order in npy header");
  std::string shape = dict_value(path, header, "shape");
  std::string num;
  for (char c : shape.substr(1)) {
    if (c >= '0' && c <= '9') {
      num.push_back(c);
    } else if (c == ',' || c == ')') {
      if (!num.empty()) {
        if (num.size() > 18) fail(path, "shape entry " + num + " too large");
        a.shape.push_back(std::stoll(num));
      }
      num.clear();
    } else if (c != ' ' && c != 'L') {
      fail(path, "malformed shape " + shape + " in npy header");
    }
  }
  std::int64_t count = 1;
  for (auto s : a.shape) {
    if (s != 0 && count > std::numeric_limits<std::int64_t>::max() / s / 8) {
      fail(path, "shape " + shape + " too large");
    }
    count *= s;
  }
  std::size_t need = static_cast<std::size_t>(count) * dtype_size(a.dtype);
  std::size_t have = data.size() - hstart - hlen;
  if (have < need) {
    fail(path, "truncated data: " + std::to_string(have) + " bytes for shape " + shape + " of " +
                   dtype_name(a.dtype) + " (" + std::to_string(need) + " needed)");
  }
  if (have > need) fail(path, "trailing bytes after the array data");
  a.bytes.assign(data.begin() + static_cast<std::ptrdiff_t>(hstart + hlen), data.end());
  return a;
}

void write_npy(const std::string& path, const NpyArray& a) {
  std::ostringstream h;
  h << "{'descr': '" << info(a.dtype).descr << "', 'fortran_order': False, 'shape': (";
  for (std::size_t k = 0; k < a.shape.size(); ++k)
    h << a.shape[k] << (a.shape.size() == 1 ? "," : (k + 1 < a.shape.size() ? ", " : ""));
  h << "), }";
  std::string header = h.str();
  std::size_t total = 10 + header.size() + 1;
  header.append((64 - total % 64) % 64, ' ');
  header.push_back('\n');
  std::string out = "\x93NUMPY";
  out.push_back('\x01');
  out.push_back('\x00');
  out.push_back(static_cast<char>(header.size() & 0xff));
  out.push_back(static_cast<char>(header.size() >> 8));
  out += header;
  out.append(reinterpret_cast<const char*>(a.bytes.data()), a.bytes.size());
  write_file_atomically(path, out);
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
Domain npy_domain(const NpyArray& a, const std::vector<std::int64_t>& lower) {
  if (a.shape.empty()) throw IoError("a 0-dimensional array is not an image");
  for (auto s : a.shape) {
    if (s == 0) throw IoError("empty array (an extent is 0)");
  }
  return Domain(a.shape, lower);
}
} // namespace

Image<std::uint8_t> npy_to_mask(const NpyArray& a, const std::vector<std::int64_t>& lower) {
  Image<std::uint8_t> img(npy_domain(a, lower));
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

Image<std::int64_t> npy_to_int64(const NpyArray& a, const std::vector<std::int64_t>& lower) {
  Image<std::int64_t> img(npy_domain(a, lower));
  for (std::int64_t i = 0; i < img.size(); ++i) img[i] = a.get(i);
  return img;
}

} // namespace zdg
