#include <zdg/arith/error.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>
#include <zdg/kernel/topology/simple_points.hpp>

#include <array>
#include <memory>
#include <mutex>

namespace zdg {
namespace {

// The 3^D neighbourhood as a bit mask: position p = sum_k (d_k + 1) 3^(D - 1 - k).
template <int D>
struct Cube {
  static constexpr int size = D == 3 ? 27 : 9;
  static constexpr int centre = size / 2;
  static constexpr std::uint32_t full = (std::uint32_t{1} << size) - 1;

  // Positions whose coordinate along axis (0 = slowest) equals v.
  static constexpr std::uint32_t slice(int axis, int v) {
    std::uint32_t m = 0;
    for (int p = 0; p < size; ++p) {
      int q = p, coord = 0;
      for (int k = D - 1; k >= 0; --k) {
        if (k == axis) coord = q % 3;
        q /= 3;
      }
      if (coord == v) m |= std::uint32_t{1} << p;
    }
    return m;
  }
  static constexpr int stride(int axis) { return axis == D - 1 ? 1 : (axis == D - 2 ? 3 : 9); }
  // l1 norm of the offset of position p.
  static constexpr int norm(int p) {
    int n = 0;
    for (int k = 0; k < D; ++k) {
      n += (p % 3) != 1 ? 1 : 0;
      p /= 3;
    }
    return n;
  }
  // Positions of offsets with 1 <= l1 <= m.
  static constexpr std::uint32_t ball(int m) {
    std::uint32_t r = 0;
    for (int p = 0; p < size; ++p) {
      if (norm(p) >= 1 && norm(p) <= m) r |= std::uint32_t{1} << p;
    }
    return r;
  }

  // Constants, evaluated at compile time.
  static constexpr std::array<std::uint32_t, 3> not_high = {slice(0, 2) ^ full, slice(1, 2) ^ full,
                                                            D == 3 ? slice(2, 2) ^ full : 0};
  static constexpr std::array<std::uint32_t, 3> not_low = {slice(0, 0) ^ full, slice(1, 0) ^ full,
                                                           D == 3 ? slice(2, 0) ^ full : 0};
  static constexpr std::array<std::uint32_t, 4> balls = {0, ball(1), ball(2), D == 3 ? ball(3) : 0};

  // S together with its neighbours along one axis (within the cube).
  static std::uint32_t along(std::uint32_t s, int axis) {
    const int t = stride(axis);
    const auto a = static_cast<std::size_t>(axis);
    return s | ((s & not_high[a]) << t) | ((s & not_low[a]) >> t);
  }
  // Dilation of S by the offsets of l1 norm <= M (and l_inf <= 1).
  template <int M>
  static std::uint32_t dilate(std::uint32_t s) {
    if constexpr (M == 1) {
      std::uint32_t r = s;
      for (int a = 0; a < D; ++a) r |= along(s, a);
      return r & full;
    } else if constexpr (M == D) { // all offsets: separable
      std::uint32_t r = s;
      for (int a = 0; a < D; ++a) r = along(r, a);
      return r & full;
    } else { // D = 3, M = 2: union over pairs of axes
      return (along(along(s, 0), 1) | along(along(s, 1), 2) | along(along(s, 0), 2)) & full;
    }
  }

  // The number of M-components of Y (a set of neighbours) that meet `seeds`, stopping at cap:
  // once cap - 1 components are filled, any seed left makes the cap without filling it.
  template <int M>
  static int components(std::uint32_t y, std::uint32_t seeds, int cap) {
    int n = 0;
    seeds &= y;
    while (seeds != 0) {
      if (n + 1 == cap) return cap;
      std::uint32_t comp = seeds & (~seeds + 1);
      for (;;) {
        const std::uint32_t next = dilate<M>(comp) & y;
        if (next == comp) break;
        comp = next;
      }
      ++n;
      seeds &= ~comp;
    }
    return n;
  }

  static std::uint32_t mask_of(std::uint32_t config) {
    const std::uint32_t low = (std::uint32_t{1} << centre) - 1;
    return (config & low) | ((config >> centre) << (centre + 1));
  }

  // T_n(x, Y) = the number of n-components of the geodesic neighbourhood G_n(x, Y), for Y a
  // set of neighbours (the centre not in Y). n = 7 stands for 6+ (3D only).
  static int topological_number(int n, std::uint32_t y, int cap) {
    if (n == 26 || n == 8) return components<D>(y, y, cap); // G = N^1_26 = N*_26 cap Y
    if (n == 18) {                                          // G = N^2_18 in N*_26
      const std::uint32_t n1 = y & balls[2];
      const std::uint32_t g = n1 | (dilate<2>(n1) & y);
      return components<2>(g, g, cap);
    }
    // 4 (2D), 6 and 6+: N^1 = N*_6 cap Y, N^2 in N*_18, N^3 (6+ only) in N*_26.
    const std::uint32_t n1 = y & balls[1];
    std::uint32_t g = n1 | (dilate<1>(n1) & y & balls[2]);
    if (n == 7) g |= dilate<1>(g) & y;
    return components<1>(g, g, cap);
  }

  // The topological number used for an adjacency of the pair: 6 is 6+ when paired with 18.
  static int number_kind(int n, int other) { return (n == 6 && other == 18) ? 7 : n; }

  static TopologicalNumbers numbers(int k, int kbar, std::uint32_t config, int cap) {
    const std::uint32_t x = mask_of(config);
    const std::uint32_t xbar = full & ~x & ~(std::uint32_t{1} << centre);
    TopologicalNumbers t;
    t.object = topological_number(number_kind(k, kbar), x, cap);
    if (cap <= 2 && t.object != 1) return t; // decided: not simple
    t.background = topological_number(number_kind(kbar, k), xbar, cap);
    return t;
  }
};

void check_dim(int dim) {
  if (dim != 2 && dim != 3) {
    throw InvalidArgument("simple points: dimension " + std::to_string(dim) + " (only 2D and 3D)");
  }
}

} // namespace

int neighbour_bit(int dim, int d0, int d1, int d2) {
  check_dim(dim);
  auto ok = [](int v) { return v >= -1 && v <= 1; };
  if (!ok(d0) || !ok(d1) || (dim == 3 && !ok(d2))) {
    throw InvalidArgument("simple points: neighbour offset outside {-1, 0, 1}");
  }
  const int p = dim == 3 ? (d0 + 1) * 9 + (d1 + 1) * 3 + (d2 + 1) : (d0 + 1) * 3 + (d1 + 1);
  const int centre = dim == 3 ? 13 : 4;
  if (p == centre) throw InvalidArgument("simple points: the centre is not a neighbour");
  return p < centre ? p : p - 1;
}

std::uint32_t configuration_count(int dim) {
  check_dim(dim);
  return dim == 3 ? (std::uint32_t{1} << 26) : (std::uint32_t{1} << 8);
}

std::uint32_t neighbourhood_configuration(const Image<std::uint8_t>& image, std::int64_t i) {
  const Domain& dom = image.domain();
  const int dim = dom.dim();
  check_dim(dim);
  if (i < 0 || i >= dom.size()) throw InvalidArgument("simple points: point index outside");
  std::array<std::int64_t, 3> p{0, 0, 0}, n{1, 1, 1};
  {
    std::int64_t q = i;
    for (int k = dim - 1; k >= 0; --k) {
      const auto a = static_cast<std::size_t>(3 - dim + k);
      n[a] = dom.extent(k);
      p[a] = q % n[a];
      q /= n[a];
    }
  }
  std::uint32_t config = 0;
  int bit = 0;
  const int r0 = dim == 3 ? 1 : 0;
  for (int a = -r0; a <= r0; ++a) {
    for (int b = -1; b <= 1; ++b) {
      for (int c = -1; c <= 1; ++c) {
        if (a == 0 && b == 0 && c == 0) continue;
        const std::int64_t q0 = p[0] + a, q1 = p[1] + b, q2 = p[2] + c;
        if (q0 >= 0 && q0 < n[0] && q1 >= 0 && q1 < n[1] && q2 >= 0 && q2 < n[2] &&
            image[(q0 * n[1] + q1) * n[2] + q2] != 0) {
          config |= std::uint32_t{1} << bit;
        }
        ++bit;
      }
    }
  }
  return config;
}

TopologicalNumbers topological_numbers(const AdjacencyPair& pair, std::uint32_t config) {
  make_adjacency_pair(pair.dim, pair.object, pair.background);
  if (config >= configuration_count(pair.dim)) {
    throw InvalidArgument("simple points: configuration " + std::to_string(config) +
                          " has bits beyond the neighbourhood");
  }
  return pair.dim == 3 ? Cube<3>::numbers(pair.object, pair.background, config, 1000)
                       : Cube<2>::numbers(pair.object, pair.background, config, 1000);
}

bool is_simple_by_definition(const AdjacencyPair& pair, std::uint32_t config) {
  if (!is_adjacency_pair(pair.dim, pair.object, pair.background) ||
      config >= configuration_count(pair.dim)) {
    (void)topological_numbers(pair, config); // throws the error
  }
  // Counting stops at 2: enough to tell 1 from the rest.
  const TopologicalNumbers t = pair.dim == 3
                                   ? Cube<3>::numbers(pair.object, pair.background, config, 2)
                                   : Cube<2>::numbers(pair.object, pair.background, config, 2);
  return t.object == 1 && t.background == 1;
}

SimplePointTable::SimplePointTable(const AdjacencyPair& pair, unsigned threads)
    : pair_(make_adjacency_pair(pair.dim, pair.object, pair.background)) {
  const std::uint32_t count = configuration_count(pair.dim);
  bits_.assign((count + 63) / 64, 0);
  const int k = pair.object, kbar = pair.background;
  const bool three_d = pair.dim == 3;
  // One 64-bit word per work item: every word is written by one worker.
  parallel_chunks(static_cast<std::int64_t>(bits_.size()), threads,
                  [&](std::int64_t wb, std::int64_t we) {
                    for (std::int64_t w = wb; w < we; ++w) {
                      std::uint64_t word = 0;
                      for (std::uint32_t j = 0; j < 64; ++j) {
                        const std::uint32_t c = static_cast<std::uint32_t>(w) * 64 + j;
                        if (c >= count) break;
                        const TopologicalNumbers t = three_d ? Cube<3>::numbers(k, kbar, c, 2)
                                                             : Cube<2>::numbers(k, kbar, c, 2);
                        if (t.object == 1 && t.background == 1) word |= std::uint64_t{1} << j;
                      }
                      bits_[static_cast<std::size_t>(w)] = word;
                    }
                  });
}

const SimplePointTable& SimplePointTable::of(const AdjacencyPair& pair) {
  // The six admissible pairs, each built once.
  static const AdjacencyPair pairs[6] = {{2, 8, 4},  {2, 4, 8},  {3, 26, 6},
                                         {3, 6, 26}, {3, 18, 6}, {3, 6, 18}};
  static std::once_flag once[6];
  static std::unique_ptr<SimplePointTable> tables[6];
  for (int i = 0; i < 6; ++i) {
    if (pairs[i] == pair) {
      std::call_once(once[i], [&] { tables[i] = std::make_unique<SimplePointTable>(pair); });
      return *tables[i];
    }
  }
  make_adjacency_pair(pair.dim, pair.object, pair.background); // throws
  throw InvalidArgument("simple points: pair " + pair.name() + " has no table");
}

bool is_simple_point(const Image<std::uint8_t>& image, std::int64_t i, const AdjacencyPair& pair) {
  if (image.dim() != pair.dim) {
    throw InvalidArgument("simple points: pair " + pair.name() + " for a " +
                          std::to_string(image.dim()) + "D image");
  }
  if (i < 0 || i >= image.size() || image[i] == 0) {
    throw InvalidArgument("simple points: the point is not in the object");
  }
  // One query: the definition (a table costs 2^26 evaluations to build in 3D).
  const std::uint32_t config = neighbourhood_configuration(image, i);
  return pair.dim == 2 ? SimplePointTable::of(pair).simple(config)
                       : is_simple_by_definition(pair, config);
}

Image<std::uint8_t> simple_point_mask(const Image<std::uint8_t>& image, const AdjacencyPair& pair,
                                      std::int64_t* count) {
  if (image.dim() != pair.dim)
    throw InvalidArgument("simple points: a " + std::to_string(image.dim()) +
                          "D image under the pair " + pair.name());
  Image<std::uint8_t> simple(image.domain(), std::uint8_t{0});
  std::int64_t n = 0;
  for (std::int64_t i = 0; i < image.size(); ++i) {
    if (image[i] != 0 && is_simple_by_definition(pair, neighbourhood_configuration(image, i))) {
      simple[i] = 1;
      ++n;
    }
  }
  if (count != nullptr) *count = n;
  return simple;
}

} // namespace zdg
