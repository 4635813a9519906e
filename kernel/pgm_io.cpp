#include <zdg/kernel/pgm_io.hpp>

#include <zdg/kernel/output_files.hpp>

#include <algorithm>
#include <fstream>
#include <iterator>

namespace zdg {

namespace {

struct Cursor {
  const std::string& path;
  const std::string& data;
  std::size_t pos = 0;
  int line = 1;

  [[noreturn]] void fail(const std::string& what) const {
    throw IoError(path + ":" + std::to_string(line) + ": " + what);
  }
  void skip_space_and_comments() {
    while (pos < data.size()) {
      char c = data[pos];
      if (c == '#') {
        while (pos < data.size() && data[pos] != '\n') ++pos;
      } else if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
        if (c == '\n') ++line;
        ++pos;
      } else {
        break;
      }
    }
  }
  std::int64_t number(const char* what) {
    skip_space_and_comments();
    if (pos >= data.size()) fail(std::string("truncated file: missing ") + what);
    std::int64_t v = 0;
    std::size_t start = pos;
    while (pos < data.size() && data[pos] >= '0' && data[pos] <= '9') {
      v = v * 10 + (data[pos] - '0');
      if (v > (std::int64_t{1} << 40)) fail(std::string(what) + " too large");
      ++pos;
    }
    if (pos == start) fail(std::string("expected ") + what + ", found '" + data[pos] + "'");
    return v;
  }
};

} // namespace

Image<std::uint16_t> read_pgm(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(path + ": cannot open for reading");
  std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  Cursor c{path, data};
  if (data.empty()) c.fail("empty file (not a PGM image)");
  if (data.size() < 2 || data[0] != 'P' || (data[1] != '2' && data[1] != '5')) {
    c.fail("not a PGM image (magic P2 or P5 expected)");
  }
  bool binary = data[1] == '5';
  c.pos = 2;
  std::int64_t w = c.number("width"), h = c.number("height"), maxval = c.number("maxval");
  if (w < 1 || h < 1) c.fail("empty image " + std::to_string(w) + "x" + std::to_string(h));
  if (maxval < 1 || maxval > 65535)
    c.fail("maxval " + std::to_string(maxval) + " not in [1, 65535]");
  Image<std::uint16_t> img(Domain({h, w}));
  if (binary) {
    if (c.pos >= data.size()) c.fail("truncated file: no pixel data");
    ++c.pos; // the single whitespace after maxval
    std::size_t bpp = maxval < 256 ? 1 : 2;
    std::size_t need = static_cast<std::size_t>(w * h) * bpp;
    if (data.size() - c.pos < need) {
      c.fail("truncated pixel data: " + std::to_string(data.size() - c.pos) + " bytes, " +
             std::to_string(need) + " needed");
    }
    for (std::int64_t i = 0; i < w * h; ++i) {
      std::size_t p = c.pos + static_cast<std::size_t>(i) * bpp;
      std::uint16_t v =
          bpp == 1 ? static_cast<unsigned char>(data[p])
                   : static_cast<std::uint16_t>((static_cast<unsigned char>(data[p]) << 8) |
                                                static_cast<unsigned char>(data[p + 1]));
      if (v > maxval) c.fail("pixel value " + std::to_string(v) + " above maxval");
      img[i] = v;
    }
  } else {
    for (std::int64_t i = 0; i < w * h; ++i) {
      std::int64_t v = c.number("pixel value");
      if (v > maxval)
        c.fail("pixel value " + std::to_string(v) + " above maxval " + std::to_string(maxval));
      img[i] = static_cast<std::uint16_t>(v);
    }
  }
  return img;
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
