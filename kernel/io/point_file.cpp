#include <zdg/kernel/io/point_file.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/io/input_file.hpp>

#include <algorithm>

namespace zdg {

namespace {

bool blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

// A field quoted in an error message: at most 40 characters, control bytes shown as '?'.
std::string shown(std::string_view f) {
  std::string s(f.substr(0, 40));
  for (char& c : s) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  }
  if (f.size() > 40) s += "...";
  return s;
}

[[noreturn]] void fail(const std::string& source, std::size_t line, const std::string& what) {
  throw IoError(source + ":" + std::to_string(line) + ": " + what);
}

std::string dims_text(const std::vector<int>& dims) {
  std::string s;
  for (std::size_t k = 0; k < dims.size(); ++k) {
    s += (k == 0 ? "" : (k + 1 == dims.size() ? " or " : ", ")) + std::to_string(dims[k]);
  }
  return s;
}

} // namespace

std::vector<TextLine> data_lines(std::string_view text) {
  std::vector<TextLine> out;
  std::size_t number = 0, pos = 0;
  while (pos < text.size()) {
    ++number;
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    if (auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    TextLine t{number, line, {}};
    std::size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && blank(line[i])) ++i;
      std::size_t b = i;
      while (i < line.size() && !blank(line[i])) ++i;
      if (i > b) t.fields.push_back(line.substr(b, i - b));
    }
    if (!t.fields.empty()) out.push_back(std::move(t));
  }
  return out;
}

PointList parse_point_file(std::string_view text, const std::string& source,
                           const std::vector<int>& dims) {
  auto lines = data_lines(text);
  if (lines.empty()) throw IoError(source + ": no point (empty file)");
  PointList out;
  const std::size_t dim = lines.front().fields.size();
  if (std::find(dims.begin(), dims.end(), static_cast<int>(dim)) == dims.end()) {
    fail(source, lines.front().number,
         "expected " + dims_text(dims) + " integers a line, got " + std::to_string(dim) +
             " fields");
  }
  out.dim = static_cast<int>(dim);
  out.coords.reserve(lines.size() * dim);
  out.lines.reserve(lines.size());
  for (const auto& l : lines) {
    if (l.fields.size() != dim) {
      fail(source, l.number,
           std::to_string(l.fields.size()) + " fields in a file of " + std::to_string(dim) +
               "D points (mixed dimensions)");
    }
    for (auto f : l.fields) {
      try {
        out.coords.push_back(parse_integer<BigInt>(f));
      } catch (const InvalidArgument&) {
        fail(source, l.number, "'" + shown(f) + "' is not an integer");
      }
    }
    out.lines.push_back(l.number);
  }
  return out;
}

PointList read_point_file(const std::string& path, const std::vector<int>& dims) {
  return parse_point_file(read_input_file(path), path, dims);
}

DigitalPathFile parse_digital_path_file(std::string_view text, const std::string& source) {
  auto lines = data_lines(text);
  if (lines.empty()) throw IoError(source + ": no point (empty file)");
  DigitalPathFile out;
  if (lines.front().fields.size() >= 3) {
    const auto& l = lines.front();
    if (lines.size() > 1) fail(source, lines[1].number, "unexpected text after the Freeman chain");
    try {
      out.chain = parse_freeman_chain(l.text);
    } catch (const Error& e) {
      fail(source, l.number, e.what());
    }
    out.chain_line = l.number;
    return out;
  }
  out.points.reserve(lines.size());
  out.lines.reserve(lines.size());
  for (const auto& l : lines) {
    if (l.fields.size() != 2) {
      fail(source, l.number, "expected a point 'x y', got '" + shown(l.text) + "'");
    }
    try {
      out.points.push_back(
          {parse_integer<BigInt>(l.fields[0]), parse_integer<BigInt>(l.fields[1])});
    } catch (const InvalidArgument&) {
      fail(source, l.number, "expected two integers 'x y', got '" + shown(l.text) + "'");
    }
    out.lines.push_back(l.number);
  }
  return out;
}

DigitalPathFile read_digital_path_file(const std::string& path) {
  return parse_digital_path_file(read_input_file(path), path);
}

} // namespace zdg
