#include <zdg/arith/error.hpp>
#include <zdg/estimators/probing_normal.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <thread>
#include <utility>

namespace zdg {

namespace {

constexpr int kMaxWalk = 256;

struct Start {
  Voxel origin;
  std::array<Voxel, 3> frame; // u_x, u_y, u_z
  int moves = 0;
};

Voxel unit(int axis, int sign) {
  Voxel v{0, 0, 0};
  coord(v, axis) = sign;
  return v;
}

// The walk of the header in the octant (u_a, u_b, u_c); nullopt when it does not end.
template <class In>
std::optional<Start> walk(const In& in, const Voxel& outer, const std::array<Voxel, 3>& u_abc,
                          const std::array<int, 3>& axes) {
  Voxel q = outer;
  for (int moves = 0; moves <= kMaxWalk; ++moves) {
    int k = 0;
    while (k < 3 && in(q - u_abc[std::size_t(k)])) ++k;
    if (k == 3) {
      Start st;
      for (int i = 0; i < 3; ++i)
        st.frame[std::size_t(axes[std::size_t(i)])] = u_abc[std::size_t(i)];
      st.origin = q - u_abc[0] - u_abc[1] - u_abc[2];
      st.moves = moves;
      return st;
    }
    q = q - u_abc[std::size_t(k)];
  }
  return std::nullopt;
}

template <TowerInt I>
Voxel to_voxel(const Point3<I>& p) {
  return {int_cast<Int64>(p.x).value(), int_cast<Int64>(p.y).value(), int_cast<Int64>(p.z).value()};
}

template <TowerInt I, class In>
PlaneProbingResult<I> probe(const In& in, const Start& st, ProbingAlgorithm alg,
                            std::uint64_t max_steps) {
  auto cast = [](const Voxel& v) { return Point3<I>{I(v.x), I(v.y), I(v.z)}; };
  auto pred = [&](const Point3<I>& x) { return in(to_voxel(x)); };
  return probe_plane<I>(pred, cast(st.origin),
                        {cast(st.frame[0]), cast(st.frame[1]), cast(st.frame[2])}, alg, max_steps);
}

} // namespace

SurfelProbe probing_surfel_normal(const VoxelPredicate& inside, const VoxelBox& box,
                                  const Surfel& s, ProbingAlgorithm algorithm,
                                  std::uint64_t max_steps) {
  auto in = [&](const Voxel& z) { return box.contains(z) && inside(z); };
  // The inner 26-boundary of X: the probed set (see the header).
  auto shell = [&](const Voxel& z) {
    if (!in(z)) return false;
    for (std::int64_t dz = -1; dz <= 1; ++dz) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        for (std::int64_t dx = -1; dx <= 1; ++dx) {
          if ((dx != 0 || dy != 0 || dz != 0) && !in(Voxel{z.x + dx, z.y + dy, z.z + dz}))
            return true;
        }
      }
    }
    return false;
  };
  const int a = orthogonal_axis(s), b = (a + 1) % 3, c = (a + 2) % 3;
  const int sigma = s.direct ? 1 : -1;
  const Voxel outer = outer_voxel(s);
  std::optional<Start> best;
  // A local normal m (minus the solid's moment about the inner voxel in the 5 x 5 x 5 block:
  // the normal points away from where X extends), computed only when the octants fail; zero
  // until then, so that octant ties keep the fixed order.
  std::int64_t m[3] = {0, 0, 0};
  // The walks in the four frames (u_a, shear u_a + s_b e_b, shear u_a + s_c e_c) around axis
  // ax (shear 0: the octants, 1: the sheared frames); the shortest walk wins, on a tie the
  // frame whose signs agree more with m's tangent components, then the order of kSigns.
  constexpr std::pair<int, int> kSigns[] = {{1, 1}, {1, -1}, {-1, 1}, {-1, -1}};
  auto frames = [&](int ax, int sg, int shear) {
    const int bx = (ax + 1) % 3, cx = (ax + 2) % 3;
    const Voxel ua = unit(ax, sg), sh{shear * ua.x, shear * ua.y, shear * ua.z};
    int best_agree = -1;
    for (const auto& [sb, sc] : kSigns) {
      auto st = walk(in, outer, {ua, sh + unit(bx, sb), sh + unit(cx, sc)}, {ax, bx, cx});
      if (!st) continue;
      const int agree = int(m[bx] * sb > 0) + int(m[cx] * sc > 0);
      if (!best || st->moves < best->moves || (st->moves == best->moves && agree > best_agree)) {
        best = st;
        best_agree = agree;
      }
    }
  };
  frames(a, sigma, 0);
  // No octant: the sheared frames, unimodular like the octants, whose dot products with N are
  // positive for both signs of a tangent component smaller than |N_a| (the case of the
  // octants' failures: a tangent component near zero). Where none starts either (the
  // surfel's axis nearly orthogonal to the normal: a riser of the staircase), the sheared
  // frames around the other axes a' with m_a' != 0, oriented by the sign of m_a', the larger
  // |m_a'| first.
  bool sheared = false;
  if (!best) {
    const Voxel inner = outer - unit(a, sigma);
    for (std::int64_t dz = -2; dz <= 2; ++dz)
      for (std::int64_t dy = -2; dy <= 2; ++dy)
        for (std::int64_t dx = -2; dx <= 2; ++dx) {
          if (!in(inner + Voxel{dx, dy, dz})) continue;
          m[0] -= dx, m[1] -= dy, m[2] -= dz;
        }
    frames(a, sigma, 1);
    int others[2] = {b, c};
    if (std::abs(m[c]) > std::abs(m[b])) std::swap(others[0], others[1]);
    for (const int ax : others) {
      if (best) break;
      if (m[ax] != 0) frames(ax, m[ax] > 0 ? 1 : -1, 1);
    }
    sheared = best.has_value();
  }
  SurfelProbe out;
  const auto t = trivial_normal(s);
  out.normal = {double(t.x), double(t.y), double(t.z)};
  if (!best) return out;
  try {
    Point3<double> n;
    std::uint64_t steps = 0, calls = 0;
    try {
      const auto r = probe<Int64>(shell, *best, algorithm, max_steps);
      out.exact = to_voxel(r.normal);
      n = {double(out.exact.x), double(out.exact.y), double(out.exact.z)};
      steps = r.steps;
      calls = r.predicate_calls;
    } catch (const OverflowError&) {
      const auto r = probe<Int128>(shell, *best, algorithm, max_steps);
      out.exact = to_voxel(r.normal);
      n = {double(out.exact.x), double(out.exact.y), double(out.exact.z)};
      steps = r.steps;
      calls = r.predicate_calls;
    }
    const double len = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    out.normal = {n.x / len, n.y / len, n.z / len};
    out.probed = true;
    out.sheared = sheared;
    out.steps = steps;
    out.predicate_calls = calls;
  } catch (const InvalidArgument&) {
    out.exact = {0, 0, 0}; // max_steps reached: the trivial normal
  } catch (const OverflowError&) {
    out.exact = {0, 0, 0}; // the normal does not fit int64: the trivial normal
  }
  return out;
}

std::vector<SurfelProbe> probing_normals(const VoxelPredicate& inside, const VoxelBox& box,
                                         std::span<const Surfel> surfels,
                                         ProbingAlgorithm algorithm, unsigned threads) {
  const unsigned workers = worker_count(threads, std::int64_t(surfels.size()));
  std::vector<SurfelProbe> out(surfels.size());
  parallel_for(std::int64_t(surfels.size()), workers, [&](std::int64_t i) {
    out[std::size_t(i)] = probing_surfel_normal(inside, box, surfels[std::size_t(i)], algorithm);
  });
  return out;
}

} // namespace zdg
