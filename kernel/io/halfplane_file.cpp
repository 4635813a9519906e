#include <zdg/kernel/io/halfplane_file.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/io/input_file.hpp>
#include <zdg/kernel/io/point_file.hpp>

namespace zdg {

std::vector<HalfPlane<BigInt>> parse_halfplane_file(std::string_view text,
                                                    const std::string& source) {
  auto lines = data_lines(text);
  if (lines.empty()) throw IoError(source + ": no half-plane (empty file)");
  std::vector<HalfPlane<BigInt>> out;
  out.reserve(lines.size());
  for (const auto& l : lines) {
    const std::string where = source + ":" + std::to_string(l.number) + ": ";
    if (l.fields.size() != 3) {
      throw IoError(where + "expected 'a b c' (a x + b y <= c), got " +
                    std::to_string(l.fields.size()) + " fields");
    }
    Rational<BigInt> v[3];
    for (int k = 0; k < 3; ++k) {
      try {
        v[k] = parse_rational<BigInt>(l.fields[static_cast<std::size_t>(k)]);
      } catch (const InvalidArgument& e) {
        throw IoError(where + e.what() + " (rationals: 7, -3/4, 1000.5)");
      }
    }
    out.push_back({v[0], v[1], v[2]});
  }
  return out;
}

std::vector<HalfPlane<BigInt>> read_halfplane_file(const std::string& path) {
  return parse_halfplane_file(read_input_file(path), path);
}

} // namespace zdg
