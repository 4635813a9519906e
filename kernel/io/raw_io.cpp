#include <zdg/kernel/io/raw_io.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/io/output_files.hpp>

#include <charconv>
#include <filesystem>
#include <fstream>

namespace zdg {

namespace {

std::string shape_text(const std::vector<std::int64_t>& shape) {
  std::string s;
  for (std::size_t k = 0; k < shape.size(); ++k) {
    if (k > 0) s += ',';
    s += std::to_string(shape[k]);
  }
  return s;
}

// The byte count of the array, with overflow checks.
std::uint64_t raw_bytes_needed(const std::string& name, const std::vector<std::int64_t>& shape,
                               DType dtype) {
  if (shape.size() != 2 && shape.size() != 3)
    throw InvalidArgument(name + ": raw shape " + shape_text(shape) + " (2 or 3 axes needed)");
  std::uint64_t n = dtype_size(dtype);
  for (auto s : shape) {
    if (s < 1)
      throw InvalidArgument(name + ": raw shape " + shape_text(shape) + " has an extent < 1");
    if (__builtin_mul_overflow(n, static_cast<std::uint64_t>(s), &n) ||
        n > (std::uint64_t{1} << 62))
      throw InvalidArgument(name + ": raw shape " + shape_text(shape) + " of " + dtype_name(dtype) +
                            " needs more than 2^62 bytes");
  }
  return n;
}

} // namespace

std::vector<std::int64_t> parse_raw_shape(const std::string& text) {
  std::vector<std::int64_t> shape;
  std::size_t pos = 0;
  while (true) {
    const auto comma = text.find(',', pos);
    const std::string part =
        text.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
    std::int64_t v = 0;
    const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), v);
    if (part.empty() || ec != std::errc() || end != part.data() + part.size() || v < 1)
      throw InvalidArgument("--raw-shape '" + text + "': '" + part +
                            "' is not a positive decimal integer (Z,Y,X or Y,X)");
    shape.push_back(v);
    if (comma == std::string::npos) break;
    pos = comma + 1;
  }
  if (shape.size() != 2 && shape.size() != 3)
    throw InvalidArgument("--raw-shape '" + text + "': 2 or 3 extents (Z,Y,X or Y,X)");
  return shape;
}

namespace {

ScalarVolume finish(const std::string& name, NpyArray a) {
  if (a.dtype == DType::Bool) {
    for (auto b : a.bytes) {
      if (b > 1) throw IoError(name + ": raw bool value " + std::to_string(b) + " (0 or 1)");
    }
  }
  return make_scalar_volume(std::move(a));
}

[[noreturn]] void wrong_size(const std::string& name, std::uint64_t size,
                             const std::vector<std::int64_t>& shape, DType dtype,
                             std::uint64_t need) {
  throw IoError(name + ": raw file has " + std::to_string(size) + " bytes, shape " +
                shape_text(shape) + " of " + dtype_name(dtype) + " needs " + std::to_string(need));
}

} // namespace

ScalarVolume read_raw_bytes(std::string_view bytes, const std::string& name,
                            const std::vector<std::int64_t>& shape, DType dtype) {
  const std::uint64_t need = raw_bytes_needed(name, shape, dtype);
  if (bytes.size() != need) wrong_size(name, bytes.size(), shape, dtype, need);
  NpyArray a;
  a.dtype = dtype;
  a.shape = shape;
  a.bytes.assign(bytes.begin(), bytes.end());
  return finish(name, std::move(a));
}

ScalarVolume read_raw(const std::string& path, const std::vector<std::int64_t>& shape,
                      DType dtype) {
  const std::uint64_t need = raw_bytes_needed(path, shape, dtype);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw IoError(path + ": no such file");
  const auto size = static_cast<std::uint64_t>(std::filesystem::file_size(path, ec));
  if (ec) throw IoError(path + ": cannot read the file size");
  if (size != need) wrong_size(path, size, shape, dtype, need);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(path + ": cannot open for reading");
  NpyArray a;
  a.dtype = dtype;
  a.shape = shape;
  a.bytes.resize(static_cast<std::size_t>(need));
  in.read(reinterpret_cast<char*>(a.bytes.data()), static_cast<std::streamsize>(need));
  if (static_cast<std::uint64_t>(in.gcount()) != need) throw IoError(path + ": read error");
  return finish(path, std::move(a));
}

void write_raw(const std::string& path, const ScalarVolume& volume) {
  volume.validate();
  write_file_atomically(path,
                        std::string_view(reinterpret_cast<const char*>(volume.array.bytes.data()),
                                         volume.array.bytes.size()));
}

} // namespace zdg
