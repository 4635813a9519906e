// Test support for thinnings: the theorems every homotopic thinning must satisfy, checked
// inside RapidCheck properties, and the symmetries of the square and the cube.
#pragma once

#include "tests/support/binary_images.hpp"
#include "tests/support/cubical_homology.hpp"
#include <zdg/kernel/topology/simple_points.hpp>
#include <zdg/kernel/topology/skeleton_constraints.hpp>

#include <rapidcheck.h>

#include <array>
#include <cstdint>
#include <vector>

namespace zdg::test {

/// The result is a subset of the object, and the object and the background keep every Betti
/// number (brute-force homology of the cell complexes, tests/support/cubical_homology.hpp).
inline void check_subset_and_homotopy(const Image<std::uint8_t>& object,
                                      const Image<std::uint8_t>& result,
                                      const AdjacencyPair& pair) {
  RC_ASSERT(result.domain() == object.domain());
  for (std::int64_t i = 0; i < object.size(); ++i) {
    RC_ASSERT(result[i] == 0 || object[i] != 0);
  }
  RC_ASSERT(object_homology(object, pair).betti == object_homology(result, pair).betti);
  RC_ASSERT(object_homology(padded_complement(object), pair.complement()).betti ==
            object_homology(padded_complement(result), pair.complement()).betti);
}

/// Replays the deletions on the object: each deleted point is in the object and simple when
/// it is deleted (the definition-level test); the end is the result.
inline void check_deletions_were_simple(const Image<std::uint8_t>& object,
                                        const Image<std::uint8_t>& result,
                                        const AdjacencyPair& pair,
                                        const std::vector<std::int64_t>& deletions) {
  Image<std::uint8_t> cur = object;
  for (auto& v : cur.values()) v = v != 0 ? 1 : 0;
  for (std::int64_t i : deletions) {
    RC_ASSERT(cur[i] != 0);
    RC_ASSERT(is_simple_by_definition(pair, neighbourhood_configuration(cur, i)));
    cur[i] = 0;
  }
  RC_ASSERT(cur == result);
}

/// A symmetry of the square (2D, 8) or the cube (3D, 48): axis permutation and flips, on an
/// image whose extents are all equal.
struct Symmetry {
  std::array<int, 3> perm{0, 1, 2};
  std::array<bool, 3> flip{false, false, false};
};

inline std::vector<Symmetry> symmetries(int dim) {
  std::vector<Symmetry> out;
  std::array<int, 3> p{0, 1, 2};
  do {
    if (dim == 2 && p[2] != 2) continue;
    for (int f = 0; f < (1 << dim); ++f) {
      Symmetry s;
      s.perm = p;
      for (int k = 0; k < dim; ++k) s.flip[static_cast<std::size_t>(k)] = ((f >> k) & 1) != 0;
      out.push_back(s);
    }
  } while (std::next_permutation(p.begin(), p.end()));
  return out;
}

/// Inside a property: a random image on the cube {0..n-1}^dim at a random density.
inline Image<std::uint8_t> random_cubic_image(int dim, std::int64_t n) {
  std::vector<std::int64_t> ext(static_cast<std::size_t>(dim), n);
  Image<std::uint8_t> img{Domain(ext), std::uint8_t{0}};
  const int density = *rc::gen::inRange(30, 90);
  const auto draws = *rc::gen::container<std::vector<int>>(static_cast<std::size_t>(img.size()),
                                                           rc::gen::inRange(0, 100));
  for (std::int64_t i = 0; i < img.size(); ++i)
    img[i] = draws[static_cast<std::size_t>(i)] < density;
  return img;
}

/// The image moved by the symmetry (inverse: the inverse symmetry).
inline Image<std::uint8_t> apply_symmetry(const Image<std::uint8_t>& img, const Symmetry& s,
                                          bool inverse = false) {
  const Domain& d = img.domain();
  const int dim = d.dim();
  const std::int64_t n = d.extent(0);
  Image<std::uint8_t> out(d, std::uint8_t{0});
  std::vector<std::int64_t> q(static_cast<std::size_t>(dim));
  for (std::int64_t i = 0; i < d.size(); ++i) {
    const auto p = d.point(i);
    // forward: q_k = flip_k(p_{perm_k}); inverse: p_{perm_k} = flip_k(q_k).
    for (int k = 0; k < dim; ++k) {
      const auto pk = static_cast<std::size_t>(s.perm[static_cast<std::size_t>(k)]);
      const bool f = s.flip[static_cast<std::size_t>(k)];
      if (!inverse) {
        q[static_cast<std::size_t>(k)] = f ? n - 1 - p[pk] : p[pk];
      } else {
        q[pk] = f ? n - 1 - p[static_cast<std::size_t>(k)] : p[static_cast<std::size_t>(k)];
      }
    }
    out.at(q) = img[i];
  }
  return out;
}

/// Number of k-neighbours of point i in the object.
inline int object_neighbours(const Image<std::uint8_t>& img, std::int64_t i, int k) {
  const std::uint32_t c = neighbourhood_configuration(img, i);
  int n = 0;
  for (const auto& o : neighbour_offsets(img.dim(), k)) {
    n += (c >> neighbour_bit(img.dim(), o[0], o[1], o[2])) & 1u;
  }
  return n;
}

} // namespace zdg::test
