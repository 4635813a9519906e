// Exact digital rays: the voxels a rational line crosses, in its order.
//
// A digital ray is the line (O + t D) / den, t real (integers O, D, den > 0, D not zero), in voxel
// coordinates: voxel x is the unit cube centred on x (x, y, z order). Its voxels in a box of
// `extent` (the voxels 0 <= x_a < extent_a) are those the line crosses over a positive length,
// in the order of t; a line in a face plane belongs to the half-open cube [x - 1/2, x + 1/2)
// of the fixed axis. A step crosses one, two or three faces at once (the line through an edge
// or a corner visits no voxel of zero length). Amanatides & Woo 1987, "A fast voxel traversal
// algorithm for ray tracing", Eurographics: every comparison exact in 128-bit integers.
//
// Bounds (checked, InvalidArgument otherwise): |O_a|, |D_a| and den at most 2^42, extents in
// [1, 2^20]; parameters t are then fractions n / d with |n| < 2^65 and 0 < d <= 2^44, whose
// cross products fit 128 bits. Cost: O(1) per visited voxel, no allocation (for_each).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace zdg {

struct DigitalRay {
  std::array<std::int64_t, 3> origin{};    ///< numerators, voxel coordinates (x, y, z)
  std::array<std::int64_t, 3> direction{}; ///< not all zero
  std::int64_t denominator = 1;
};

/// A parameter t = n / d of a digital ray (d > 0), compared exactly.
struct RayTime {
  __extension__ __int128 n = 0, d = 1;
};
inline bool operator<(const RayTime& a, const RayTime& b) {
  return a.n * b.d < b.n * a.d;
}
inline bool same_time(const RayTime& a, const RayTime& b) {
  return a.n * b.d == b.n * a.d;
}

/// The open parameter interval (in, out) over which the line lies in the box's interior along
/// each moving axis and in the half-open slab [-1/2, extent - 1/2) along each fixed one;
/// `hit` false when it is empty. `in_axis`: the moving axis whose face the line enters by (the
/// last of the entry times; the lowest axis among equal ones).
struct RayChord {
  bool hit = false;
  RayTime in, out;
  int in_axis = 0;
};

/// InvalidArgument when the ray or the extent breaks the bounds above.
void check_digital_ray(const DigitalRay& ray, const std::array<std::int64_t, 3>& extent);

/// The chord of the box (ray and extent checked by the caller).
RayChord digital_ray_chord(const DigitalRay& ray, const std::array<std::int64_t, 3>& extent);

/// The parameter at which the line crosses the plane x_axis = (2 k - 1) / 2 (the face between
/// voxels k - 1 and k); the axis must move.
inline RayTime ray_plane_time(const DigitalRay& ray, int axis, std::int64_t k) {
  __extension__ typedef __int128 i128;
  const i128 plane = (2 * static_cast<i128>(k) - 1) * ray.denominator;
  const i128 n = plane - 2 * static_cast<i128>(ray.origin[std::size_t(axis)]);
  const i128 d = 2 * static_cast<i128>(ray.direction[std::size_t(axis)]);
  return d < 0 ? RayTime{-n, -d} : RayTime{n, d};
}

/// Calls visit(voxel) for the voxels above, in order (ray and extent checked by the caller).
template <class Visit>
void for_each_ray_voxel(const DigitalRay& r, const std::array<std::int64_t, 3>& extent,
                        Visit&& visit);

/// The voxels (x, y, z) of a box of `extent` (x, y, z) that the ray crosses over a positive
/// length, in the order of the ray; empty when it misses the box. Checks the bounds.
std::vector<std::array<std::int64_t, 3>>
digital_ray_voxels(const DigitalRay& ray, const std::array<std::int64_t, 3>& extent);

// ---- implementation ----

namespace ray_detail {
__extension__ typedef __int128 i128;
inline i128 floor_div(i128 a, i128 b) { // b > 0
  i128 q = a / b;
  if (a % b != 0 && a < 0) --q;
  return q;
}
[[noreturn]] void entry_outside();
} // namespace ray_detail

template <class Visit>
void for_each_ray_voxel(const DigitalRay& r, const std::array<std::int64_t, 3>& extent,
                        Visit&& visit) {
  using ray_detail::i128;
  const RayChord ch = digital_ray_chord(r, extent);
  if (!ch.hit) return;
  const i128 den = r.denominator;
  std::array<std::int64_t, 3> v{};
  std::array<RayTime, 3> next{};
  for (std::size_t a = 0; a < 3; ++a) {
    const i128 D = r.direction[a];
    // P_a(t_in) + 1/2 = X / Y.
    const i128 X = 2 * (static_cast<i128>(r.origin[a]) * ch.in.d + ch.in.n * D) + den * ch.in.d;
    const i128 Y = 2 * den * ch.in.d;
    const i128 c = D >= 0 ? ray_detail::floor_div(X, Y)
                          : -ray_detail::floor_div(-X, Y) - 1; // D < 0: ceil(X / Y) - 1
    if (c < 0 || c >= extent[a]) ray_detail::entry_outside();
    v[a] = static_cast<std::int64_t>(c);
    if (D != 0) next[a] = ray_plane_time(r, int(a), v[a] + (D > 0 ? 1 : 0));
  }
  for (;;) {
    visit(v);
    std::size_t best = 3;
    for (std::size_t a = 0; a < 3; ++a)
      if (r.direction[a] != 0 && (best == 3 || next[a] < next[best])) best = a;
    const RayTime t = next[best];
    if (!(t < ch.out)) return;
    for (std::size_t a = 0; a < 3; ++a) {
      if (r.direction[a] == 0 || !same_time(next[a], t)) continue;
      const int s = r.direction[a] > 0 ? 1 : -1;
      v[a] += s;
      next[a] = ray_plane_time(r, int(a), v[a] + (s > 0 ? 1 : 0));
    }
  }
}

} // namespace zdg
