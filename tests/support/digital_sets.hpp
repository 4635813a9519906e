// Test support: digitized discs and balls given by exact integer predicates.
#pragma once

#include <zdg/kernel/digitization/gauss_digitization.hpp>
#include <zdg/kernel/surfaces/cubical_cells.hpp>
#include <zdg/kernel/surfaces/digital_surface.hpp>

#include <cstdint>

namespace zdg::test {

/// The digital disc x^2 + y^2 <= r2 in the box [-3000, 3000]^2.
class DiscDigitization final : public GaussDigitization2 {
public:
  explicit DiscDigitization(std::int64_t r2)
      : GaussDigitization2(Box2{{-3000, -3000}, {3000, 3000}}), r2_(r2) {}

protected:
  bool inside(const Pixel& z) const override { return z.x * z.x + z.y * z.y <= r2_; }

private:
  std::int64_t r2_;
};

/// The digital ball |z - c|^2 <= r2.
inline VoxelPredicate ball_predicate(Voxel c, std::int64_t r2) {
  return [=](const Voxel& z) {
    const auto dx = z.x - c.x, dy = z.y - c.y, dz = z.z - c.z;
    return dx * dx + dy * dy + dz * dz <= r2;
  };
}

} // namespace zdg::test
