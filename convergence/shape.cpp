#include <zdg/convergence/shape.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/arith/rational.hpp>
#include <zdg/convergence/shapes_3d.hpp>

#include <random>

namespace zdg {

Moments2 translate_moments(const Moments2& m, Point2<double> t) {
  const double tx = t.x, ty = t.y;
  return {m[0],
          m[1] + tx * m[0],
          m[2] + ty * m[0],
          m[3] + 2 * tx * m[1] + tx * tx * m[0],
          m[4] + tx * m[2] + ty * m[1] + tx * ty * m[0],
          m[5] + 2 * ty * m[2] + ty * ty * m[0]};
}

namespace {
std::vector<ShapeKind>& mutable_kinds() {
  static std::vector<ShapeKind> kinds = [] {
    std::vector<ShapeKind> k;
    detail::register_2d_shapes(k);
    detail::register_3d_shapes(k);
    return k;
  }();
  return kinds;
}
} // namespace

const std::vector<ShapeKind>& shape_kinds() {
  return mutable_kinds();
}

void register_shape_kind(ShapeKind kind) {
  mutable_kinds().push_back(std::move(kind));
}

std::unique_ptr<Shape> parse_shape(std::string_view spec) {
  auto colon = spec.find(':');
  std::string_view name = spec.substr(0, colon);
  std::string_view args =
      colon == std::string_view::npos ? std::string_view{} : spec.substr(colon + 1);
  bool known = false;
  for (const auto& kind : shape_kinds()) {
    if (kind.name != name) continue;
    known = true;
    if (auto s = kind.make(args, spec)) return s;
  }
  std::string names;
  for (const auto& kind : shape_kinds()) {
    if (names.find(kind.name) == std::string::npos)
      names += (names.empty() ? "" : ", ") + kind.name;
  }
  auto cut = [](std::string_view t) {
    return t.size() <= 60 ? std::string(t) : std::string(t.substr(0, 57)) + "...";
  };
  if (known) throw InvalidArgument("shape '" + cut(spec) + "' is not supported here");
  throw InvalidArgument("unknown shape '" + cut(name) + "' in '" + cut(spec) +
                        "' (known: " + names + ")");
}

std::vector<double> parse_number_list(std::string_view args, std::string_view what) {
  std::vector<double> out;
  if (args.empty()) return out;
  std::size_t start = 0;
  for (;;) {
    auto comma = args.find(',', start);
    std::string_view item =
        args.substr(start, comma == std::string_view::npos ? args.npos : comma - start);
    try {
      out.push_back(parse_rational<BigInt>(item).to_double());
    } catch (const InvalidArgument&) {
      throw InvalidArgument(std::string(what) + ": '" + std::string(item) +
                            "' is not a number (value " + std::to_string(out.size() + 1) + ")");
    }
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return out;
}

std::vector<double> random_translation(std::uint64_t seed, int index, int dimension, double h) {
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ULL + static_cast<std::uint64_t>(index) + 1);
  std::vector<double> t;
  for (int i = 0; i < dimension; ++i) {
    double u = static_cast<double>(rng() >> 11) * 0x1.0p-53; // [0, 1), portable
    t.push_back(h * (2.0 * u - 1.0));
  }
  return t;
}

} // namespace zdg
