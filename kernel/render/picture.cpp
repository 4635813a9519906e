#include <zdg/kernel/render/picture.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/io/output_files.hpp>

#include <png.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace zdg {

namespace {

// The glyphs, row by row from the top ('#' = ink). Characters not listed are drawn as '?'.
struct Glyph {
  char c;
  const char* rows[7];
};
constexpr Glyph kGlyphs[] = {
    {'0', {".###.", "#...#", "#..##", "#.#.#", "##..#", "#...#", ".###."}},
    {'1', {"..#..", ".##..", "..#..", "..#..", "..#..", "..#..", ".###."}},
    {'2', {".###.", "#...#", "....#", "...#.", "..#..", ".#...", "#####"}},
    {'3', {"#####", "...#.", "..#..", "...#.", "....#", "#...#", ".###."}},
    {'4', {"...#.", "..##.", ".#.#.", "#..#.", "#####", "...#.", "...#."}},
    {'5', {"#####", "#....", "####.", "....#", "....#", "#...#", ".###."}},
    {'6', {"..##.", ".#...", "#....", "####.", "#...#", "#...#", ".###."}},
    {'7', {"#####", "....#", "...#.", "..#..", ".#...", ".#...", ".#..."}},
    {'8', {".###.", "#...#", "#...#", ".###.", "#...#", "#...#", ".###."}},
    {'9', {".###.", "#...#", "#...#", ".####", "....#", "...#.", ".##.."}},
    {'-', {".....", ".....", ".....", "#####", ".....", ".....", "....."}},
    {'+', {".....", "..#..", "..#..", "#####", "..#..", "..#..", "....."}},
    {'.', {".....", ".....", ".....", ".....", ".....", ".##..", ".##.."}},
    {',', {".....", ".....", ".....", ".....", ".##..", "..#..", ".#..."}},
    {':', {".....", ".##..", ".##..", ".....", ".##..", ".##..", "....."}},
    {';', {".....", ".##..", ".##..", ".....", ".##..", "..#..", ".#..."}},
    {'(', {"...#.", "..#..", ".#...", ".#...", ".#...", "..#..", "...#."}},
    {')', {".#...", "..#..", "...#.", "...#.", "...#.", "..#..", ".#..."}},
    {'[', {".###.", ".#...", ".#...", ".#...", ".#...", ".#...", ".###."}},
    {']', {".###.", "...#.", "...#.", "...#.", "...#.", "...#.", ".###."}},
    {'/', {".....", "....#", "...#.", "..#..", ".#...", "#....", "....."}},
    {'=', {".....", ".....", "#####", ".....", "#####", ".....", "....."}},
    {'_', {".....", ".....", ".....", ".....", ".....", ".....", "#####"}},
    {'%', {"##...", "##..#", "...#.", "..#..", ".#...", "#..##", "...##"}},
    {'<', {"...#.", "..#..", ".#...", "#....", ".#...", "..#..", "...#."}},
    {'>', {".#...", "..#..", "...#.", "....#", "...#.", "..#..", ".#..."}},
    {'*', {".....", "..#..", "#.#.#", ".###.", "#.#.#", "..#..", "....."}},
    {'\'', {"..#..", "..#..", ".#...", ".....", ".....", ".....", "....."}},
    {'!', {"..#..", "..#..", "..#..", "..#..", "..#..", ".....", "..#.."}},
    {'?', {".###.", "#...#", "....#", "...#.", "..#..", ".....", "..#.."}},
    {'^', {"..#..", ".#.#.", "#...#", ".....", ".....", ".....", "....."}},
    {'#', {".#.#.", ".#.#.", "#####", ".#.#.", "#####", ".#.#.", ".#.#."}},
    {'a', {".....", ".....", ".###.", "....#", ".####", "#...#", ".####"}},
    {'b', {"#....", "#....", "#.##.", "##..#", "#...#", "#...#", "####."}},
    {'c', {".....", ".....", ".###.", "#....", "#....", "#...#", ".###."}},
    {'d', {"....#", "....#", ".##.#", "#..##", "#...#", "#...#", ".####"}},
    {'e', {".....", ".....", ".###.", "#...#", "#####", "#....", ".###."}},
    {'f', {"..##.", ".#..#", ".#...", "###..", ".#...", ".#...", ".#..."}},
    {'g', {".....", ".####", "#...#", "#...#", ".####", "....#", ".###."}},
    {'h', {"#....", "#....", "#.##.", "##..#", "#...#", "#...#", "#...#"}},
    {'i', {"..#..", ".....", ".##..", "..#..", "..#..", "..#..", ".###."}},
    {'j', {"...#.", ".....", "..##.", "...#.", "...#.", "#..#.", ".##.."}},
    {'k', {"#....", "#....", "#..#.", "#.#..", "##...", "#.#..", "#..#."}},
    {'l', {".##..", "..#..", "..#..", "..#..", "..#..", "..#..", ".###."}},
    {'m', {".....", ".....", "##.#.", "#.#.#", "#.#.#", "#...#", "#...#"}},
    {'n', {".....", ".....", "#.##.", "##..#", "#...#", "#...#", "#...#"}},
    {'o', {".....", ".....", ".###.", "#...#", "#...#", "#...#", ".###."}},
    {'p', {".....", ".....", "####.", "#...#", "####.", "#....", "#...."}},
    {'q', {".....", ".....", ".##.#", "#..##", ".####", "....#", "....#"}},
    {'r', {".....", ".....", "#.##.", "##..#", "#....", "#....", "#...."}},
    {'s', {".....", ".....", ".###.", "#....", ".###.", "....#", "####."}},
    {'t', {".#...", ".#...", "###..", ".#...", ".#...", ".#..#", "..##."}},
    {'u', {".....", ".....", "#...#", "#...#", "#...#", "#..##", ".##.#"}},
    {'v', {".....", ".....", "#...#", "#...#", "#...#", ".#.#.", "..#.."}},
    {'w', {".....", ".....", "#...#", "#...#", "#.#.#", "#.#.#", ".#.#."}},
    {'x', {".....", ".....", "#...#", ".#.#.", "..#..", ".#.#.", "#...#"}},
    {'y', {".....", ".....", "#...#", "#...#", ".####", "....#", ".###."}},
    {'z', {".....", ".....", "#####", "...#.", "..#..", ".#...", "#####"}},
    {'A', {".###.", "#...#", "#...#", "#####", "#...#", "#...#", "#...#"}},
    {'B', {"####.", "#...#", "#...#", "####.", "#...#", "#...#", "####."}},
    {'C', {".###.", "#...#", "#....", "#....", "#....", "#...#", ".###."}},
    {'D', {"###..", "#..#.", "#...#", "#...#", "#...#", "#..#.", "###.."}},
    {'E', {"#####", "#....", "#....", "####.", "#....", "#....", "#####"}},
    {'F', {"#####", "#....", "#....", "####.", "#....", "#....", "#...."}},
    {'G', {".###.", "#...#", "#....", "#.###", "#...#", "#...#", ".####"}},
    {'H', {"#...#", "#...#", "#...#", "#####", "#...#", "#...#", "#...#"}},
    {'I', {".###.", "..#..", "..#..", "..#..", "..#..", "..#..", ".###."}},
    {'J', {"..###", "...#.", "...#.", "...#.", "...#.", "#..#.", ".##.."}},
    {'K', {"#...#", "#..#.", "#.#..", "##...", "#.#..", "#..#.", "#...#"}},
    {'L', {"#....", "#....", "#....", "#....", "#....", "#....", "#####"}},
    {'M', {"#...#", "##.##", "#.#.#", "#.#.#", "#...#", "#...#", "#...#"}},
    {'N', {"#...#", "#...#", "##..#", "#.#.#", "#..##", "#...#", "#...#"}},
    {'O', {".###.", "#...#", "#...#", "#...#", "#...#", "#...#", ".###."}},
    {'P', {"####.", "#...#", "#...#", "####.", "#....", "#....", "#...."}},
    {'Q', {".###.", "#...#", "#...#", "#...#", "#.#.#", "#..#.", ".##.#"}},
    {'R', {"####.", "#...#", "#...#", "####.", "#.#..", "#..#.", "#...#"}},
    {'S', {".####", "#....", "#....", ".###.", "....#", "....#", "####."}},
    {'T', {"#####", "..#..", "..#..", "..#..", "..#..", "..#..", "..#.."}},
    {'U', {"#...#", "#...#", "#...#", "#...#", "#...#", "#...#", ".###."}},
    {'V', {"#...#", "#...#", "#...#", "#...#", "#...#", ".#.#.", "..#.."}},
    {'W', {"#...#", "#...#", "#...#", "#.#.#", "#.#.#", "#.#.#", ".#.#."}},
    {'X', {"#...#", "#...#", ".#.#.", "..#..", ".#.#.", "#...#", "#...#"}},
    {'Y', {"#...#", "#...#", ".#.#.", "..#..", "..#..", "..#..", "..#.."}},
    {'Z', {"#####", "....#", "...#.", "..#..", ".#...", "#....", "#####"}},
};

const Glyph* glyph_of(char c) {
  static const Glyph* table[128] = {};
  static const bool ready = [] {
    for (const auto& g : kGlyphs) table[static_cast<unsigned char>(g.c)] = &g;
    return true;
  }();
  (void)ready;
  const auto u = static_cast<unsigned char>(c);
  if (c == ' ') return nullptr;
  if (u < 128 && table[u] != nullptr) return table[u];
  return table[static_cast<unsigned char>('?')];
}

// matplotlib's viridis and coolwarm at 17 evenly spaced points.
constexpr Rgb kViridis[17] = {
    {68, 1, 84},    {72, 24, 106},  {71, 45, 123},  {66, 64, 134},  {59, 82, 139},  {51, 99, 141},
    {44, 114, 142}, {38, 130, 142}, {33, 145, 140}, {31, 160, 136}, {40, 174, 128}, {63, 188, 115},
    {94, 201, 98},  {132, 212, 75}, {173, 220, 48}, {216, 226, 25}, {253, 231, 37}};
constexpr Rgb kCoolwarm[17] = {{59, 76, 192},   {78, 104, 216},  {98, 130, 234},  {119, 154, 247},
                               {141, 176, 254}, {163, 194, 254}, {185, 208, 249}, {204, 217, 237},
                               {221, 220, 220}, {236, 211, 197}, {245, 196, 172}, {247, 176, 147},
                               {244, 152, 122}, {235, 125, 98},  {221, 95, 75},   {202, 59, 55},
                               {180, 4, 38}};

// Where libpng's output and messages go: the file, and the first error (libpng's default
// handlers print "libpng error: ..." on stderr, a second line beside zdg's own).
struct PngSink {
  std::FILE* file = nullptr;
  int write_errno = 0; // the errno of a failed write or flush; 0 if none
  char error[200] = {};
};

[[noreturn]] void png_on_error(png_structp png, png_const_charp message) {
  auto* sink = static_cast<PngSink*>(png_get_error_ptr(png));
  std::snprintf(sink->error, sizeof sink->error, "%s", message != nullptr ? message : "error");
  png_longjmp(png, 1);
}

// Warnings are about chunks zdg does not write; they do not make the file wrong.
void png_on_warning(png_structp, png_const_charp) {}

void png_write_to_file(png_structp png, png_bytep data, std::size_t n) {
  auto* sink = static_cast<PngSink*>(png_get_io_ptr(png));
  if (n != 0 && std::fwrite(data, 1, n, sink->file) != n) {
    sink->write_errno = errno != 0 ? errno : EIO;
    png_error(png, "write error");
  }
}

void png_flush_file(png_structp png) {
  auto* sink = static_cast<PngSink*>(png_get_io_ptr(png));
  if (std::fflush(sink->file) != 0) {
    sink->write_errno = errno != 0 ? errno : EIO;
    png_error(png, "write error");
  }
}

// libpng reports errors by longjmp: this function holds nothing with a destructor and
// modifies nothing after setjmp. False when libpng failed.
bool png_write_rows(png_structp png, png_infop info, PngSink* sink, png_bytep* rows, int w, int h) {
  if (setjmp(png_jmpbuf(png)) != 0) return false;
  png_set_write_fn(png, sink, png_write_to_file, png_flush_file);
  png_set_compression_level(png, 6);
  png_set_IHDR(png, info, static_cast<png_uint_32>(w), static_cast<png_uint_32>(h), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  png_write_image(png, rows);
  png_write_end(png, nullptr);
  return true;
}

} // namespace

RgbImage::RgbImage(int w, int h, Rgb fill) : width(w), height(h) {
  if (w < 1 || h < 1 || w > 32768 || h > 32768)
    throw InvalidArgument("picture size " + std::to_string(w) + "x" + std::to_string(h) +
                          " (1..32768 pixels per side)");
  rgb.resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3);
  for (std::size_t i = 0; i < rgb.size(); i += 3) {
    rgb[i] = fill.r;
    rgb[i + 1] = fill.g;
    rgb[i + 2] = fill.b;
  }
}

Rgb RgbImage::at(int x, int y) const {
  const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                         static_cast<std::size_t>(x)) *
                        3;
  return {rgb[i], rgb[i + 1], rgb[i + 2]};
}

void RgbImage::set(int x, int y, Rgb c) {
  if (x < 0 || y < 0 || x >= width || y >= height) return;
  const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                         static_cast<std::size_t>(x)) *
                        3;
  rgb[i] = c.r;
  rgb[i + 1] = c.g;
  rgb[i + 2] = c.b;
}

void RgbImage::fill_rect(int x0, int y0, int x1, int y1, Rgb c) {
  for (int y = std::max(0, y0); y < std::min(height, y1); ++y)
    for (int x = std::max(0, x0); x < std::min(width, x1); ++x) set(x, y, c);
}

void check_picture_size(int width, int height, const std::string& what) {
  if (width < 200 || height < 150 || width > 8192 || height > 8192)
    throw InvalidArgument(what + ": picture size " + std::to_string(width) + "x" +
                          std::to_string(height) + " (200x150 .. 8192x8192)");
}

void write_png(const std::string& path, const RgbImage& image) {
  if (image.width < 1 || image.height < 1 ||
      image.rgb.size() != static_cast<std::size_t>(image.width) * image.height * 3)
    throw InvalidArgument(path + ": malformed picture");
  OutputSet out(Existing::replace);
  const auto staging = out.add(path);
  PngSink sink;
  sink.file = std::fopen(staging.c_str(), "wb");
  if (sink.file == nullptr) throw IoError(path + ": cannot write (" + std::strerror(errno) + ")");
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, &sink, png_on_error, png_on_warning);
  png_infop info = png == nullptr ? nullptr : png_create_info_struct(png);
  if (png == nullptr || info == nullptr) {
    png_destroy_write_struct(&png, nullptr);
    std::fclose(sink.file);
    throw IoError(path + ": libpng: cannot start");
  }
  std::vector<png_bytep> rows(static_cast<std::size_t>(image.height));
  for (int y = 0; y < image.height; ++y)
    rows[static_cast<std::size_t>(y)] =
        const_cast<png_bytep>(image.rgb.data()) + static_cast<std::size_t>(y) * image.width * 3;
  const bool failed = !png_write_rows(png, info, &sink, rows.data(), image.width, image.height);
  png_destroy_write_struct(&png, &info);
  int err = sink.write_errno;
  if ((std::fflush(sink.file) != 0 || std::ferror(sink.file) != 0) && err == 0)
    err = errno != 0 ? errno : EIO;
  if (std::fclose(sink.file) != 0 && err == 0) err = errno != 0 ? errno : EIO;
  if (failed || err != 0) {
    // One message: the system's reason for a failed write, else libpng's own.
    const std::string why = err != 0 ? std::strerror(err) : std::string("libpng: ") + sink.error;
    throw IoError(path + ": PNG write failed (" + why + ")");
  }
  out.commit();
}

Rgb map_color(ColorMap map, double t) {
  if (std::isnan(t)) return {150, 150, 150};
  t = std::clamp(t, 0.0, 1.0);
  const Rgb* c = map == ColorMap::viridis ? kViridis : kCoolwarm;
  const double s = t * 16.0;
  const int k = std::min(15, static_cast<int>(s));
  const double u = s - k;
  auto mix = [u](std::uint8_t a, std::uint8_t b) {
    return static_cast<std::uint8_t>(std::lround(a + (b - a) * u));
  };
  return {mix(c[k].r, c[k + 1].r), mix(c[k].g, c[k + 1].g), mix(c[k].b, c[k + 1].b)};
}

Rgb ColorScale::operator()(double v) const {
  return map_color(map, hi > lo ? (v - lo) / (hi - lo) : 0.5);
}

ColorScale choose_color_scale(std::span<const double> values, std::optional<double> lo,
                              std::optional<double> hi, double clip_percent,
                              std::optional<ColorMap> map) {
  if (clip_percent < 0 || clip_percent >= 50 || std::isnan(clip_percent))
    throw InvalidArgument("colour range clipping " + std::to_string(clip_percent) +
                          "% (0 <= clip < 50)");
  std::vector<double> finite;
  const std::size_t stride = values.size() > 1000000 ? values.size() / 1000000 + 1 : 1;
  finite.reserve(values.size() / stride + 1);
  for (std::size_t i = 0; i < values.size(); i += stride) {
    if (std::isfinite(values[i])) finite.push_back(values[i]);
  }
  double a = 0.0, b = 1.0;
  if (!finite.empty()) {
    const auto pick = [&](double q) {
      auto k = static_cast<std::size_t>(std::floor(q * static_cast<double>(finite.size() - 1)));
      std::nth_element(finite.begin(), finite.begin() + static_cast<std::ptrdiff_t>(k),
                       finite.end());
      return finite[k];
    };
    a = pick(clip_percent / 100.0);
    b = pick(1.0 - clip_percent / 100.0);
  }
  ColorScale s;
  s.lo = lo ? *lo : a;
  s.hi = hi ? *hi : b;
  if (!std::isfinite(s.lo) || !std::isfinite(s.hi) || s.lo > s.hi)
    throw InvalidArgument("colour range [" + short_number(s.lo) + ", " + short_number(s.hi) +
                          "] is not an interval");
  const bool signed_range = s.lo < 0 && s.hi > 0;
  s.map = map ? *map : (signed_range ? ColorMap::coolwarm : ColorMap::viridis);
  if (!map && signed_range && !lo && !hi) {
    const double m = std::max(-s.lo, s.hi);
    s.lo = -m;
    s.hi = m;
  }
  if (s.lo == s.hi) {
    s.lo -= 0.5;
    s.hi += 0.5;
  }
  return s;
}

std::string color_map_name(ColorMap map) {
  return map == ColorMap::viridis ? "viridis" : "coolwarm";
}

int text_width(std::string_view text, int scale) {
  return text.empty() ? 0 : (6 * static_cast<int>(text.size()) - 1) * scale;
}

void draw_text(RgbImage& image, int x, int y, std::string_view text, Rgb color, int scale) {
  for (std::size_t k = 0; k < text.size(); ++k) {
    const Glyph* g = glyph_of(text[k]);
    if (g == nullptr) continue;
    const int gx = x + static_cast<int>(k) * 6 * scale;
    for (int row = 0; row < 7; ++row)
      for (int col = 0; col < 5; ++col)
        if (g->rows[row][col] == '#')
          image.fill_rect(gx + col * scale, y + row * scale, gx + (col + 1) * scale,
                          y + (row + 1) * scale, color);
  }
}

std::string short_number(double value, int digits) {
  if (std::isnan(value)) return "nan";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, value);
  return buf;
}

void draw_color_bar(RgbImage& image, int x, int y, int w, int h, ColorMap map, double lo, double hi,
                    const std::string& label, int scale) {
  const Rgb ink{20, 20, 20};
  for (int row = 0; row < h; ++row) {
    const double t = h == 1 ? 0.5 : 1.0 - static_cast<double>(row) / (h - 1);
    image.fill_rect(x, y + row, x + w, y + row + 1, map_color(map, t));
  }
  // frame and ticks
  image.fill_rect(x - 1, y - 1, x + w + 1, y, ink);
  image.fill_rect(x - 1, y + h, x + w + 1, y + h + 1, ink);
  image.fill_rect(x - 1, y - 1, x, y + h + 1, ink);
  image.fill_rect(x + w, y - 1, x + w + 1, y + h + 1, ink);
  const int tx = x + w + 4 * scale;
  const double values[3] = {hi, 0.5 * (lo + hi), lo};
  const int rows[3] = {y, y + h / 2, y + h - 1};
  for (int k = 0; k < 3; ++k)
    draw_text(image, tx, rows[k] - 7 * scale / 2, short_number(values[k]), ink, scale);
  draw_text(image, x, y - 12 * scale, label, ink, scale);
}

} // namespace zdg
