// Gauss digitization as a predicate on Z^2: G_h(X) = { z in Z^2 : h z in X }, restricted to
// a box of Z^2 (points outside the box are outside). The grid is never materialized: at
// h = 1.7e-4 the box [-20,20]^2 holds 5e10 pixels, so every consumer (contour tracking,
// integral invariants) asks the predicate about the few pixels it needs.
//
// The shape decides membership; this header only fixes the interface. An implementation
// answers `contains` exactly for rational shapes (floating-point filter with an exact
// rational fallback, see convergence/shape.hpp) and may override `count` to batch a list
// of queries behind one virtual call (the integral-invariant hot loop).
#pragma once

#include <zdg/kernel/images/box.hpp>

#include <cstdint>
#include <span>

namespace zdg {

class GaussDigitization2 {
public:
  explicit GaussDigitization2(Box2 box) : box_(box) {}
  virtual ~GaussDigitization2() = default;
  GaussDigitization2(const GaussDigitization2&) = delete;
  GaussDigitization2& operator=(const GaussDigitization2&) = delete;

  const Box2& box() const { return box_; }
  /// z in G_h(X) (and in the box).
  bool contains(const Pixel& z) const { return box_.contains(z) && inside(z); }
  /// Number of the given pixels that belong to G_h(X).
  virtual std::int64_t count(std::span<const Pixel> zs) const {
    std::int64_t n = 0;
    for (const auto& z : zs) n += contains(z) ? 1 : 0;
    return n;
  }

protected:
  /// Membership of h z in X, for z inside the box.
  virtual bool inside(const Pixel& z) const = 0;

private:
  Box2 box_;
};

} // namespace zdg
