#include <zdg/arith/error.hpp>
#include <zdg/kernel/topology/cubical_persistence.hpp>
#include <zdg/kernel/transforms/distance_transform.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <string>
#include <unordered_map>
#include <utility>

namespace zdg {
namespace {

constexpr std::uint32_t kNone = 0xffffffffu;
// How many voxels ahead the passes ask the cache for the neighbourhood they will read.
constexpr std::uint32_t kAhead = 12;

// The monotone map of a double to uint64 (x < y iff key(x) < key(y); -0 and +0 one key).
std::uint64_t order_key(double x) {
  if (x == 0) x = 0.0;
  const auto b = std::bit_cast<std::uint64_t>(x);
  return (b >> 63) != 0 ? ~b : (b | (std::uint64_t{1} << 63));
}

// The cubical complex of an n0 x n1 x n2 voxel box in Khalimsky coordinates (2 n_k + 1 per
// axis: a coordinate is odd on a cell's open extent, even on its boundary), and the ranks of
// its voxels in the order (value, index).
class Complex {
public:
  Complex(const Image<double>& values, std::array<std::int64_t, 3> n) : n_(n) {
    voxels_ = values.size(); // n0 n1 n2, checked by the Domain
    // Below 2^32 voxels, the cell and vertex counts (at most 27 and 8 times more) fit int64.
    if (voxels_ >= std::int64_t{kNone}) {
      throw InvalidArgument("cubical persistence: " + std::to_string(voxels_) +
                            " voxels are too many (at most 2^32 - 2)");
    }
    for (std::size_t k = 0; k < 3; ++k) m_[k] = 2 * n_[k] + 1;
    cells_ = m_[0] * m_[1] * m_[2];
    vertices_ = (n_[0] + 1) * (n_[1] + 1) * (n_[2] + 1);
    std::uint64_t product = 0;
    if (3 * vertices_ >= std::int64_t{kNone} ||
        __builtin_mul_overflow(static_cast<std::uint64_t>(cells_),
                               static_cast<std::uint64_t>(voxels_), &product)) {
      throw InvalidArgument("cubical persistence: " + std::to_string(voxels_) +
                            " voxels are too many (3 vertices and cells times voxels must fit "
                            "32 and 64 bits)");
    }
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(static_cast<std::size_t>(voxels_));
    for (std::int64_t i = 0; i < voxels_; ++i) {
      const double x = values[i];
      if (!std::isfinite(x)) {
        throw InvalidArgument("cubical persistence: value " + std::to_string(x) + " at voxel " +
                              std::to_string(i) + " is not finite");
      }
      keyed[static_cast<std::size_t>(i)] = {order_key(x), static_cast<std::uint32_t>(i)};
    }
    std::sort(keyed.begin(), keyed.end());
    order_.resize(keyed.size());
    rank_.resize(keyed.size());
    sorted_.resize(keyed.size());
    for (std::size_t r = 0; r < keyed.size(); ++r) {
      order_[r] = keyed[r].second;
      sorted_[r] = values[keyed[r].second];
      rank_[keyed[r].second] = static_cast<std::uint32_t>(r);
    }
  }

  std::int64_t voxels() const { return voxels_; }
  std::int64_t cells() const { return cells_; }
  std::int64_t vertices() const { return vertices_; }
  std::uint32_t voxel_of_rank(std::uint32_t r) const { return order_[r]; }
  std::uint32_t rank_of(std::uint32_t v) const { return rank_[v]; }
  double value_of_rank(std::uint32_t r) const { return sorted_[r]; }
  /// Asks the cache for the ranks of the 3x3x3 voxels around voxel v and, when `parents` is
  /// given, the entries of the 2x2 rows of its corner vertices in an array `per_vertex` wide
  /// per vertex (the passes visit the voxels in value order: random places of the volume).
  void prefetch_around(std::uint32_t v, const std::uint32_t* parents = nullptr,
                       int per_vertex = 1) const {
    const auto x = voxel_coords(v);
    for (std::int64_t a = -1; a <= 1; ++a) {
      for (std::int64_t b = -1; b <= 1; ++b) {
        const std::int64_t i = x[0] + a, j = x[1] + b;
        if (i < 0 || j < 0 || i >= n_[0] || j >= n_[1]) continue;
        __builtin_prefetch(&rank_[static_cast<std::size_t>((i * n_[1] + j) * n_[2] + x[2])]);
      }
    }
    if (parents == nullptr) return;
    for (std::int64_t a = 0; a <= 1; ++a) {
      for (std::int64_t b = 0; b <= 1; ++b) {
        const std::int64_t id = ((x[0] + a) * (n_[1] + 1) + x[1] + b) * (n_[2] + 1) + x[2];
        __builtin_prefetch(&parents[static_cast<std::size_t>(id * per_vertex)]);
      }
    }
  }
  std::int64_t extent(int k) const { return n_[static_cast<std::size_t>(k)]; }

  std::array<std::int64_t, 3> voxel_coords(std::uint32_t v) const {
    const std::int64_t i = v / (n_[1] * n_[2]), j = (v / n_[2]) % n_[1], k = v % n_[2];
    return {i, j, k};
  }
  std::int64_t cell_index(const std::array<std::int64_t, 3>& x) const {
    return (x[0] * m_[1] + x[1]) * m_[2] + x[2];
  }
  std::array<std::int64_t, 3> cell_coords(std::int64_t c) const {
    return {c / (m_[1] * m_[2]), (c / m_[2]) % m_[1], c % m_[2]};
  }
  /// The vertex of even Khalimsky coordinates x, numbered in the (n+1)^3 grid.
  std::uint32_t vertex_id(const std::array<std::int64_t, 3>& x) const {
    return static_cast<std::uint32_t>(((x[0] / 2) * (n_[1] + 1) + x[1] / 2) * (n_[2] + 1) +
                                      x[2] / 2);
  }
  /// The edge of Khalimsky coordinates x (one odd coordinate): 3 * its lower vertex + axis.
  std::uint32_t edge_id(const std::array<std::int64_t, 3>& x) const {
    for (int a = 0; a < 3; ++a) {
      if (x[static_cast<std::size_t>(a)] % 2 != 0) {
        auto y = x;
        y[static_cast<std::size_t>(a)] -= 1;
        return 3 * vertex_id(y) + static_cast<std::uint32_t>(a);
      }
    }
    throw Error("cubical persistence: edge_id of a vertex");
  }
  /// The rank of the voxel with which the cell x enters: the least rank of its top cofaces.
  std::uint32_t entry_rank(const std::array<std::int64_t, 3>& x) const {
    std::array<std::int64_t, 2> lo[3];
    std::array<int, 3> count{};
    for (std::size_t a = 0; a < 3; ++a) {
      const std::int64_t c = x[a];
      if (c % 2 != 0) {
        lo[a][0] = (c - 1) / 2;
        count[a] = 1;
      } else {
        int q = 0;
        if (c / 2 - 1 >= 0) lo[a][static_cast<std::size_t>(q++)] = c / 2 - 1;
        if (c / 2 < n_[a]) lo[a][static_cast<std::size_t>(q++)] = c / 2;
        count[a] = q;
      }
    }
    std::uint32_t best = kNone;
    for (int p = 0; p < count[0]; ++p) {
      for (int q = 0; q < count[1]; ++q) {
        const std::int64_t base =
            (lo[0][static_cast<std::size_t>(p)] * n_[1] + lo[1][static_cast<std::size_t>(q)]) *
            n_[2];
        for (int s = 0; s < count[2]; ++s) {
          best = std::min(
              best, rank_[static_cast<std::size_t>(base + lo[2][static_cast<std::size_t>(s)])]);
        }
      }
    }
    return best;
  }

private:
  std::array<std::int64_t, 3> n_{}, m_{};
  std::int64_t voxels_ = 0, cells_ = 0, vertices_ = 0;
  std::vector<std::uint32_t> order_, rank_;
  std::vector<double> sorted_; ///< the values in rank order
};

class BitSet {
public:
  explicit BitSet(std::int64_t n) : w_(static_cast<std::size_t>((n + 63) / 64), 0) {}
  void set(std::int64_t i) { w_[static_cast<std::size_t>(i >> 6)] |= std::uint64_t{1} << (i & 63); }
  bool test(std::int64_t i) const {
    return ((w_[static_cast<std::size_t>(i >> 6)] >> (i & 63)) & 1u) != 0;
  }

private:
  std::vector<std::uint64_t> w_;
};

std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

// The offsets of the faces of a voxel in Khalimsky coordinates, in increasing cell index
// order, with their dimension (the number of zero offsets).
struct FaceOffset {
  std::array<std::int64_t, 3> d;
  int dim;
};
const std::vector<FaceOffset>& face_offsets() {
  static const std::vector<FaceOffset> offsets = [] {
    std::vector<FaceOffset> v;
    for (std::int64_t a = -1; a <= 1; ++a) {
      for (std::int64_t b = -1; b <= 1; ++b) {
        for (std::int64_t c = -1; c <= 1; ++c) {
          v.push_back({{a, b, c}, (a == 0) + (b == 0) + (c == 0)});
        }
      }
    }
    return v;
  }();
  return offsets;
}

void add_pair(std::vector<PersistencePair>& out, double birth, double death) {
  if (birth < death) out.push_back({birth, death});
}

// Dimension 0: union-find on the vertices, the edges in filtration order. Marks the edges that
// merge two components (negative: their rows leave the dimension-1 matrix).
void vertex_components(const Complex& cx, BitSet& paired, std::vector<PersistencePair>& out) {
  std::vector<std::uint32_t> parent(static_cast<std::size_t>(cx.vertices()), kNone);
  std::vector<std::uint32_t> birth(parent.size()); // a vertex's entry rank
  const auto n = static_cast<std::uint32_t>(cx.voxels());
  for (std::uint32_t r = 0; r < n; ++r) {
    if (r + kAhead < n) cx.prefetch_around(cx.voxel_of_rank(r + kAhead), parent.data());
    const auto v = cx.voxel_coords(cx.voxel_of_rank(r));
    const std::array<std::int64_t, 3> centre{2 * v[0] + 1, 2 * v[1] + 1, 2 * v[2] + 1};
    for (const auto& f : face_offsets()) {
      if (f.dim != 0) continue;
      const std::uint32_t id =
          cx.vertex_id({centre[0] + f.d[0], centre[1] + f.d[1], centre[2] + f.d[2]});
      if (parent[id] == kNone) { // born with this voxel
        parent[id] = id;
        birth[id] = r;
      }
    }
    const double death = cx.value_of_rank(r);
    for (const auto& f : face_offsets()) {
      if (f.dim != 1) continue;
      const std::array<std::int64_t, 3> e{centre[0] + f.d[0], centre[1] + f.d[1],
                                          centre[2] + f.d[2]};
      if (cx.entry_rank(e) != r) continue; // entered with an earlier voxel
      std::array<std::int64_t, 3> a = e, b = e;
      for (std::size_t k = 0; k < 3; ++k) {
        if (f.d[k] == 0) {
          a[k] -= 1;
          b[k] += 1;
        }
      }
      std::uint32_t ra = find_root(parent, cx.vertex_id(a));
      std::uint32_t rb = find_root(parent, cx.vertex_id(b));
      if (ra == rb) continue; // a 1-cycle is born
      // The root of a component is its oldest vertex; the younger one dies.
      const auto key = [&](std::uint32_t root) { return std::pair{birth[root], root}; };
      const auto ka = key(ra), kb = key(rb);
      if (ka < kb) std::swap(ra, rb); // ra: the younger
      add_pair(out, cx.value_of_rank(std::max(ka, kb).first), death);
      parent[ra] = rb;
      paired.set(cx.cell_index(e));
    }
  }
  if (cx.voxels() > 0)
    out.push_back({cx.value_of_rank(0), std::numeric_limits<double>::infinity()});
}

// The top dimension by duality: union-find on the voxels and the outside (node N), the 2-cells
// in reverse filtration order. Marks the 2-cells that merge (positive: their columns are
// cleared from the dimension-1 matrix). `planar`: the slab of a 2D image, the faces across
// axis 0 left out: the union-find on the pixels over the edges of the 2D complex, whose pairs
// are the 2D image's 1-dimensional ones.
void voids(const Complex& cx, BitSet& paired, std::vector<PersistencePair>& out, bool planar) {
  const auto n = static_cast<std::uint32_t>(cx.voxels());
  std::vector<std::uint32_t> parent(static_cast<std::size_t>(n) + 1, kNone);
  parent[n] = n;
  const auto key = [&](std::uint32_t node) { return node == n ? n : cx.rank_of(node); };
  const auto& offsets = face_offsets();
  for (std::uint32_t r = n; r-- > 0;) {
    if (r >= kAhead) cx.prefetch_around(cx.voxel_of_rank(r - kAhead));
    const std::uint32_t vi = cx.voxel_of_rank(r);
    parent[vi] = vi;
    const auto v = cx.voxel_coords(vi);
    const std::array<std::int64_t, 3> centre{2 * v[0] + 1, 2 * v[1] + 1, 2 * v[2] + 1};
    const double birth = cx.value_of_rank(r);
    for (auto it = offsets.rbegin(); it != offsets.rend(); ++it) {
      if (it->dim != 2 || (planar && it->d[0] != 0)) continue;
      std::array<std::int64_t, 3> w = v;
      std::uint32_t other = n;
      bool inside = true;
      for (std::size_t k = 0; k < 3; ++k) {
        w[k] += it->d[k];
        inside = inside && w[k] >= 0 && w[k] < cx.extent(static_cast<int>(k));
      }
      if (inside) {
        other = static_cast<std::uint32_t>((w[0] * cx.extent(1) + w[1]) * cx.extent(2) + w[2]);
        if (cx.rank_of(other) < r) continue; // the face entered with that voxel
      }
      std::uint32_t ra = find_root(parent, vi), rb = find_root(parent, other);
      if (ra == rb) continue;                   // negative: kills a 1-cycle
      if (key(ra) > key(rb)) std::swap(ra, rb); // ra: the younger (lower rank)
      add_pair(out, birth, cx.value_of_rank(key(ra)));
      parent[ra] = rb;
      paired.set(cx.cell_index({centre[0] + it->d[0], centre[1] + it->d[1], centre[2] + it->d[2]}));
    }
  }
}

// Dimension 1: the columns of the 2-cells that duality left unpaired, in filtration order,
// rows the edges that dimension 0 left unpaired; reduced with a max-heap (entries cancel in
// pairs). A key is entry rank * cells + cell index: the filtration order of the edges.
class MiddleReduction {
public:
  MiddleReduction(const Complex& cx, const BitSet& paired) : cx_(cx), paired_(paired) {
    owner_.assign(static_cast<std::size_t>(3 * cx.vertices()), kNone);
  }

  void run(std::vector<PersistencePair>& out) {
    const auto n = static_cast<std::uint32_t>(cx_.voxels());
    for (std::uint32_t r = 0; r < n; ++r) {
      if (r + kAhead < n) cx_.prefetch_around(cx_.voxel_of_rank(r + kAhead), owner_.data(), 3);
      const std::uint32_t vi = cx_.voxel_of_rank(r);
      const auto v = cx_.voxel_coords(vi);
      const std::array<std::int64_t, 3> centre{2 * v[0] + 1, 2 * v[1] + 1, 2 * v[2] + 1};
      for (const auto& f : face_offsets()) {
        if (f.dim != 2) continue;
        std::array<std::int64_t, 3> w = v;
        bool inside = true;
        for (std::size_t k = 0; k < 3; ++k) {
          w[k] += f.d[k];
          inside = inside && w[k] >= 0 && w[k] < cx_.extent(static_cast<int>(k));
        }
        if (inside) {
          const auto other =
              static_cast<std::uint32_t>((w[0] * cx_.extent(1) + w[1]) * cx_.extent(2) + w[2]);
          if (cx_.rank_of(other) < r) continue;
        }
        const std::int64_t cell =
            cx_.cell_index({centre[0] + f.d[0], centre[1] + f.d[1], centre[2] + f.d[2]});
        if (paired_.test(cell)) continue; // cleared
        reduce(cell, r, out);
      }
    }
  }

private:
  // The boundary of the 2-cell, without the rows of paired edges.
  void boundary(std::int64_t cell, std::vector<std::uint64_t>& into) const {
    const auto x = cx_.cell_coords(cell);
    const auto cells = static_cast<std::uint64_t>(cx_.cells());
    for (std::size_t a = 0; a < 3; ++a) {
      if (x[a] % 2 == 0) continue;
      for (std::int64_t s = -1; s <= 1; s += 2) {
        auto e = x;
        e[a] += s;
        const std::int64_t ei = cx_.cell_index(e);
        if (paired_.test(ei)) continue;
        into.push_back(std::uint64_t{cx_.entry_rank(e)} * cells + static_cast<std::uint64_t>(ei));
      }
    }
  }

  // Pops the largest entry that does not cancel; false when the column is zero.
  bool pop_pivot(std::uint64_t& pivot) {
    while (!heap_.empty()) {
      std::pop_heap(heap_.begin(), heap_.end());
      pivot = heap_.back();
      heap_.pop_back();
      if (!heap_.empty() && heap_.front() == pivot) {
        std::pop_heap(heap_.begin(), heap_.end());
        heap_.pop_back();
        continue;
      }
      return true;
    }
    return false;
  }

  void push(std::uint64_t k) {
    heap_.push_back(k);
    std::push_heap(heap_.begin(), heap_.end());
  }

  void reduce(std::int64_t cell, std::uint32_t r, std::vector<PersistencePair>& out) {
    const auto cells = static_cast<std::uint64_t>(cx_.cells());
    heap_.clear();
    boundary(cell, heap_);
    std::make_heap(heap_.begin(), heap_.end());
    bool modified = false;
    std::uint64_t pivot = 0;
    std::vector<std::uint64_t> other;
    for (;;) {
      if (!pop_pivot(pivot)) {
        throw Error("cubical persistence: a 2-cell left unpaired by duality has a zero "
                    "reduced boundary (internal error)");
      }
      const std::uint32_t edge =
          cx_.edge_id(cx_.cell_coords(static_cast<std::int64_t>(pivot % cells)));
      const std::uint32_t k = owner_[edge];
      if (k == kNone) {
        const auto col = static_cast<std::uint32_t>(columns_.size());
        columns_.push_back(cell);
        owner_[edge] = col;
        add_pair(out, cx_.value_of_rank(static_cast<std::uint32_t>(pivot / cells)),
                 cx_.value_of_rank(r));
        if (modified) {
          std::vector<std::uint64_t> reduced{pivot};
          std::uint64_t e = 0;
          while (pop_pivot(e)) reduced.push_back(e);
          stored_.emplace(col, std::move(reduced));
        }
        return;
      }
      // Add column k (its pivot is this one: push it back, the two cancel).
      push(pivot);
      modified = true;
      const auto it = stored_.find(k);
      if (it != stored_.end()) {
        for (auto e : it->second) push(e);
      } else {
        other.clear();
        boundary(columns_[k], other);
        for (auto e : other) push(e);
      }
    }
  }

  const Complex& cx_;
  const BitSet& paired_;
  std::vector<std::uint32_t> owner_;  ///< per edge id: the column whose pivot it is
  std::vector<std::int64_t> columns_; ///< the 2-cell of each column with a pivot
  std::unordered_map<std::uint32_t, std::vector<std::uint64_t>> stored_; ///< reduced columns
  std::vector<std::uint64_t> heap_;
};

} // namespace

PersistenceDiagrams cubical_persistence(const Image<double>& values) {
  const int d = values.dim();
  if (d != 2 && d != 3) {
    throw InvalidArgument("cubical persistence: a " + std::to_string(d) +
                          "D image (2D or 3D expected)");
  }
  const Domain& dom = values.domain();
  const std::array<std::int64_t, 3> n =
      d == 3 ? std::array{dom.extent(0), dom.extent(1), dom.extent(2)}
             : std::array{std::int64_t{1}, dom.extent(0), dom.extent(1)};
  const Complex cx(values, n);
  BitSet paired(cx.cells());
  std::vector<std::vector<PersistencePair>> dgm(3);
  vertex_components(cx, paired, dgm[0]);
  if (d == 2) {
    voids(cx, paired, dgm[1], true);
  } else {
    voids(cx, paired, dgm[2], false);
    MiddleReduction(cx, paired).run(dgm[1]);
  }
  dgm.resize(static_cast<std::size_t>(d));
  for (auto& g : dgm) {
    std::sort(g.begin(), g.end(), [](const PersistencePair& a, const PersistencePair& b) {
      return a.birth != b.birth ? a.birth < b.birth : a.death < b.death;
    });
  }
  return {std::move(dgm)};
}

Image<double> signed_squared_distance(const Image<std::uint8_t>& mask, unsigned threads) {
  std::int64_t object = 0;
  for (auto x : mask.values()) object += x != 0;
  if (object == 0 || object == mask.size()) {
    throw InvalidArgument(std::string("signed distance: the image has no ") +
                          (object == 0 ? "object" : "background") + " point");
  }
  TransformOptions opt;
  opt.threads = threads;
  const auto inside = distance_transform<std::int64_t>(mask, opt);
  Image<std::uint8_t> complement(mask.domain());
  for (std::int64_t i = 0; i < mask.size(); ++i) complement[i] = mask[i] == 0;
  const auto outside = distance_transform<std::int64_t>(complement, opt);
  Image<double> out(mask.domain());
  constexpr std::int64_t exact = std::int64_t{1} << 53;
  for (std::int64_t i = 0; i < mask.size(); ++i) {
    const std::int64_t s = mask[i] != 0 ? -inside[i] : outside[i];
    if (s > exact || s < -exact) {
      throw InvalidArgument("signed distance: squared distance " + std::to_string(s) +
                            " past 2^53 (not exact in double)");
    }
    out[i] = static_cast<double>(s);
  }
  return out;
}

} // namespace zdg
