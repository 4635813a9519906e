// Fuzz target: shape specs as `--shape` and TOML read them (convergence/shape.hpp,
// parse_shape: ball, ellipse, flower, accflower, polygon, poly: in 2D and 3D, the named 3D
// surfaces). Expected outcomes: a shape whose canonical text reads back to a shape of the same
// dimension, or zdg::InvalidArgument. The shape's cheap queries (box, class, membership of a
// point) must not fail.
#include <zdg/arith/error.hpp>
#include <zdg/convergence/shape.hpp>
#include <zdg/convergence/shapes_3d.hpp>

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    auto shape = zdg::parse_shape(text);
    if (shape->dimension() != 2 && shape->dimension() != 3) __builtin_trap();
    if (zdg::parse_shape(shape->spec())->dimension() != shape->dimension()) __builtin_trap();
    (void)shape->bounding_box();
    (void)shape->shape_class();
    if (const auto* s2 = dynamic_cast<const zdg::Shape2*>(shape.get())) {
      (void)s2->contains({0.5, -0.25});
    } else if (const auto* s3 = dynamic_cast<const zdg::Shape3*>(shape.get())) {
      (void)s3->contains({0.5, -0.25, 0.125});
    }
  } catch (const zdg::InvalidArgument&) {
  }
  return 0;
}
