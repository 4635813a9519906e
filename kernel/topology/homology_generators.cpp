#include <zdg/arith/error.hpp>
#include <zdg/kernel/topology/homology_generators.hpp>

#include <algorithm>
#include <iterator>
#include <string>

namespace zdg {
namespace {

using Chain = std::vector<std::int64_t>; // sorted positions, each once

// a + b mod 2 (symmetric difference of sorted lists).
void add_into(Chain& a, const Chain& b, Chain& scratch) {
  scratch.clear();
  std::set_symmetric_difference(a.begin(), a.end(), b.begin(), b.end(),
                                std::back_inserter(scratch));
  a.swap(scratch);
}

} // namespace

HomologyGenerators homology_generators(const Image<std::uint8_t>& image) {
  const int d = image.dim();
  if (d != 2 && d != 3) {
    throw InvalidArgument("homology generators: a " + std::to_string(d) +
                          "D image (2D or 3D expected)");
  }
  std::array<std::int64_t, 3> n{1, 1, 1}, m{1, 1, 1};
  for (int k = 0; k < d; ++k) {
    n[static_cast<std::size_t>(k)] = image.domain().extent(k);
    m[static_cast<std::size_t>(k)] = 2 * n[static_cast<std::size_t>(k)] + 1;
  }
  const auto coords = [&](std::int64_t c) {
    std::array<std::int64_t, 3> x{0, 0, 0};
    for (int k = d; k-- > 0;) {
      x[static_cast<std::size_t>(k)] = c % m[static_cast<std::size_t>(k)];
      c /= m[static_cast<std::size_t>(k)];
    }
    return x;
  };
  const auto index = [&](const std::array<std::int64_t, 3>& x) {
    std::int64_t c = 0;
    for (int k = 0; k < d; ++k)
      c = c * m[static_cast<std::size_t>(k)] + x[static_cast<std::size_t>(k)];
    return c;
  };
  const std::int64_t cells = m[0] * m[1] * m[2];
  // A cell is in the complex when one of the voxels whose closure holds it is in the object.
  std::vector<std::uint8_t> in(static_cast<std::size_t>(cells), 0);
  for (std::int64_t v = 0; v < image.size(); ++v) {
    if (image[v] == 0) continue;
    std::array<std::int64_t, 3> p{0, 0, 0};
    std::int64_t rest = v;
    for (int k = d; k-- > 0;) {
      p[static_cast<std::size_t>(k)] = rest % n[static_cast<std::size_t>(k)];
      rest /= n[static_cast<std::size_t>(k)];
    }
    std::array<std::int64_t, 3> o{0, 0, 0};
    const int span = d == 3 ? 27 : 9; // the 3^d cells of the closed voxel, offsets in base 3
    for (int code = 0; code < span; ++code) {
      int c = code;
      for (int k = 0; k < d; ++k) {
        o[static_cast<std::size_t>(k)] = c % 3;
        c /= 3;
      }
      std::array<std::int64_t, 3> x{0, 0, 0};
      for (int k = 0; k < d; ++k)
        x[static_cast<std::size_t>(k)] =
            2 * p[static_cast<std::size_t>(k)] + o[static_cast<std::size_t>(k)];
      in[static_cast<std::size_t>(index(x))] = 1;
    }
  }
  // Positions in the order (dimension, index).
  std::vector<std::vector<std::int64_t>> by_dim(static_cast<std::size_t>(d) + 1);
  for (std::int64_t c = 0; c < cells; ++c) {
    if (in[static_cast<std::size_t>(c)] == 0) continue;
    const auto x = coords(c);
    int odd = 0;
    for (int k = 0; k < d; ++k) odd += x[static_cast<std::size_t>(k)] % 2 != 0;
    by_dim[static_cast<std::size_t>(odd)].push_back(c);
  }
  std::vector<std::int64_t> first(static_cast<std::size_t>(d) + 2, 0);
  for (int k = 0; k <= d; ++k) {
    first[static_cast<std::size_t>(k) + 1] =
        first[static_cast<std::size_t>(k)] +
        static_cast<std::int64_t>(by_dim[static_cast<std::size_t>(k)].size());
  }
  std::vector<std::int64_t> pos(static_cast<std::size_t>(cells), -1);
  std::vector<std::int64_t> cell_at(static_cast<std::size_t>(first.back()));
  for (int k = 0; k <= d; ++k) {
    for (std::size_t i = 0; i < by_dim[static_cast<std::size_t>(k)].size(); ++i) {
      const std::int64_t p = first[static_cast<std::size_t>(k)] + static_cast<std::int64_t>(i);
      pos[static_cast<std::size_t>(by_dim[static_cast<std::size_t>(k)][i])] = p;
      cell_at[static_cast<std::size_t>(p)] = by_dim[static_cast<std::size_t>(k)][i];
    }
  }
  const auto boundary = [&](std::int64_t p) {
    const auto x = coords(cell_at[static_cast<std::size_t>(p)]);
    Chain b;
    for (int k = 0; k < d; ++k) {
      if (x[static_cast<std::size_t>(k)] % 2 == 0) continue;
      for (std::int64_t s = -1; s <= 1; s += 2) {
        auto y = x;
        y[static_cast<std::size_t>(k)] += s;
        b.push_back(pos[static_cast<std::size_t>(index(y))]); // a face of a cell is in
      }
    }
    std::sort(b.begin(), b.end());
    return b;
  };

  HomologyGenerators out;
  out.dim = d;
  out.generators.resize(static_cast<std::size_t>(d));
  // is_low[p]: the cell at p is the pivot of a reduced column of the next dimension (cleared).
  std::vector<std::uint8_t> is_low(cell_at.size(), 0);
  Chain scratch;
  for (int k = d; k >= 1; --k) {
    // Columns of the k-cells: reduced R and V, by the owner of each pivot.
    std::vector<std::int64_t> owner(cell_at.size(), -1);
    std::vector<Chain> r_cols, v_cols;
    for (std::int64_t p = first[static_cast<std::size_t>(k)];
         p < first[static_cast<std::size_t>(k) + 1]; ++p) {
      if (is_low[static_cast<std::size_t>(p)] != 0) continue; // clearing: its column reduces to 0
      Chain r = boundary(p), v{p};
      while (!r.empty() && owner[static_cast<std::size_t>(r.back())] >= 0) {
        const auto i = static_cast<std::size_t>(owner[static_cast<std::size_t>(r.back())]);
        add_into(r, r_cols[i], scratch);
        add_into(v, v_cols[i], scratch);
      }
      if (r.empty()) {
        // A k-cycle that is no pivot of the (k+1)-columns (those are cleared): essential.
        if (k < d) {
          std::vector<std::array<std::int64_t, 3>> g;
          for (auto q : v) g.push_back(coords(cell_at[static_cast<std::size_t>(q)]));
          out.generators[static_cast<std::size_t>(k)].push_back(std::move(g));
        }
        continue;
      }
      owner[static_cast<std::size_t>(r.back())] = static_cast<std::int64_t>(r_cols.size());
      is_low[static_cast<std::size_t>(r.back())] = 1;
      r_cols.push_back(std::move(r));
      v_cols.push_back(std::move(v));
    }
  }
  for (std::int64_t p = first[0]; p < first[1]; ++p) {
    if (is_low[static_cast<std::size_t>(p)] == 0)
      out.generators[0].push_back({coords(cell_at[static_cast<std::size_t>(p)])});
  }
  return out;
}

} // namespace zdg
