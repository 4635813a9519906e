#include <zdg/kernel/io/pgm_io.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/arith/integer.hpp>
#include <zdg/kernel/io/input_file.hpp>
#include <zdg/kernel/io/output_files.hpp>

#include <algorithm>
#include <cstdint>
#include <string_view>

namespace zdg {

namespace {

struct Cursor {
  const std::string& source;
  std::string_view data;
  std::size_t pos = 0;
  int line = 1;

  [[noreturn]] void fail(const std::string& what) const {
    throw IoError(source + ":" + std::to_string(line) + ": " + what);
  }
  void skip_space_and_comments() {
    while (pos < data.size()) {
      char c = data[pos];
      if (c == '#') {
        while (pos < data.size() && data[pos] != '\n') ++pos;
      } else if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f') {
        if (c == '\n') ++line;
        ++pos;
      } else {
        break;
      }
    }
  }
  // A decimal number of the header or of a P2 raster (parse_integer: "010" is ten).
  std::int64_t number(const char* what) {
    skip_space_and_comments();
    if (pos >= data.size()) fail(std::string("truncated file: missing ") + what);
    const std::size_t start = pos;
    while (pos < data.size() && data[pos] >= '0' && data[pos] <= '9') ++pos;
    if (pos == start) {
      const char c = data[pos];
      const bool printable = c >= 0x20 && c < 0x7f;
      fail(std::string("expected ") + what + ", found " +
           (printable ? std::string("'") + c + "'"
                      : "byte " + std::to_string(static_cast<unsigned char>(c))));
    }
    try {
      return parse_integer<std::int64_t>(data.substr(start, pos - start));
    } catch (const OverflowError&) {
      fail(std::string(what) + " too large");
    }
  }
};

} // namespace

Image<std::uint16_t> parse_pgm(std::string_view data, const std::string& source) {
  Cursor c{source, data};
  if (data.empty()) c.fail("empty file (not a PGM image)");
  if (data.size() < 2 || data[0] != 'P' || (data[1] != '2' && data[1] != '5')) {
    c.fail("not a PGM image (magic P2 or P5 expected)");
  }
  const bool binary = data[1] == '5';
  c.pos = 2;
  const std::int64_t w = c.number("width"), h = c.number("height"), maxval = c.number("maxval");
  if (w < 1 || h < 1) c.fail("empty image " + std::to_string(w) + "x" + std::to_string(h));
  if (maxval < 1 || maxval > 65535)
    c.fail("maxval " + std::to_string(maxval) + " not in [1, 65535]");
  // The raster the header announces must be in the file before anything is allocated: w h
  // pixels of 1 or 2 bytes (P5), or of at least one digit and one separator each (P2, the
  // last separator optional). The products are checked against overflow.
  const std::uint64_t rest = c.pos < data.size() ? data.size() - c.pos : 0;
  const std::uint64_t bpp = binary ? (maxval < 256 ? 1 : 2) : 2;
  std::uint64_t pixels = 0, need = 0;
  const bool overflow = __builtin_mul_overflow(static_cast<std::uint64_t>(w),
                                               static_cast<std::uint64_t>(h), &pixels) ||
                        __builtin_mul_overflow(pixels, bpp, &need);
  const std::uint64_t have = binary ? (rest > 0 ? rest - 1 : 0) : rest + 1;
  if (overflow || need > have) {
    c.fail("truncated pixel data: the header announces " + std::to_string(w) + "x" +
           std::to_string(h) + " pixels, the file holds " + std::to_string(rest) +
           " bytes after it" + (binary ? "" : " (ASCII: at least 2 bytes a pixel)"));
  }
  Image<std::uint16_t> img(Domain({h, w}));
  const auto n = static_cast<std::int64_t>(pixels);
  if (binary) {
    ++c.pos; // the single whitespace after maxval
    for (std::int64_t i = 0; i < n; ++i) {
      std::size_t p = c.pos + static_cast<std::size_t>(i) * bpp;
      std::uint16_t v =
          bpp == 1 ? static_cast<unsigned char>(data[p])
                   : static_cast<std::uint16_t>((static_cast<unsigned char>(data[p]) << 8) |
                                                static_cast<unsigned char>(data[p + 1]));
      if (v > maxval) c.fail("pixel value " + std::to_string(v) + " above maxval");
      img[i] = v;
    }
  } else {
    for (std::int64_t i = 0; i < n; ++i) {
      std::int64_t v = c.number("pixel value");
      if (v > maxval)
        c.fail("pixel value " + std::to_string(v) + " above maxval " + std::to_string(maxval));
      img[i] = static_cast<std::uint16_t>(v);
    }
  }
  return img;
}

Image<std::uint16_t> read_pgm(const std::string& path) {
  return parse_pgm(read_input_file(path), path);
}

void write_pgm(const std::string& path, const Image<std::uint64_t>& image) {
  if (image.dim() != 2) {
    throw InvalidArgument("PGM holds 2D images, not " + std::to_string(image.dim()) + "-D ones");
  }
  std::uint64_t mx = 0;
  for (auto v : image.values()) mx = std::max(mx, v);
  if (mx > 65535) {
    throw InvalidArgument("value " + std::to_string(mx) +
                          " does not fit a PGM (max 65535); use .npy");
  }
  const unsigned maxval = mx < 256 ? 255 : 65535;
  std::string out = "P5\n" + std::to_string(image.domain().extent(1)) + " " +
                    std::to_string(image.domain().extent(0)) + "\n" + std::to_string(maxval) + "\n";
  for (auto v : image.values()) {
    if (maxval == 65535) out.push_back(static_cast<char>(v >> 8));
    out.push_back(static_cast<char>(v & 0xff));
  }
  write_file_atomically(path, out);
}

} // namespace zdg
