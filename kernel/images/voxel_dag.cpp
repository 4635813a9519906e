#include <zdg/arith/error.hpp>
#include <zdg/kernel/images/voxel_dag.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

namespace zdg {

namespace {

constexpr std::uint32_t kEmpty = 0xFFFFFFFFu;
constexpr std::uint32_t kMaxIndex = (std::uint32_t{1} << 29) - 1;
constexpr std::int64_t kMaxSide = std::int64_t{1} << 20;

std::uint64_t mix(std::uint64_t x) { // splitmix64's finaliser
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ull;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

// The leaf reflected along the axes of m (bit a: coordinate a -> 3 - coordinate a); bit
// x + 4 y + 16 z.
std::uint64_t reflect_leaf(std::uint64_t v, unsigned m) {
  if (m & 1) { // reverse each group of 4 bits
    v = ((v & 0x5555555555555555ull) << 1) | ((v >> 1) & 0x5555555555555555ull);
    v = ((v & 0x3333333333333333ull) << 2) | ((v >> 2) & 0x3333333333333333ull);
  }
  if (m & 2) { // reverse the 4 groups of 4 bits in each 16
    v = ((v & 0x0F0F0F0F0F0F0F0Full) << 4) | ((v >> 4) & 0x0F0F0F0F0F0F0F0Full);
    v = ((v & 0x00FF00FF00FF00FFull) << 8) | ((v >> 8) & 0x00FF00FF00FF00FFull);
  }
  if (m & 4) { // reverse the 4 groups of 16 bits
    v = ((v & 0x0000FFFF0000FFFFull) << 16) | ((v >> 16) & 0x0000FFFF0000FFFFull);
    v = (v << 32) | (v >> 32);
  }
  return v;
}

// The voxels of the level-1 sub-cube s (x + 2 y + 4 z) of a leaf.
constexpr std::array<std::uint64_t, 8> sub_cube_masks() {
  std::array<std::uint64_t, 8> m{};
  for (unsigned s = 0; s < 8; ++s)
    for (unsigned v = 0; v < 8; ++v) {
      const unsigned x = 2 * (s & 1) + (v & 1), y = 2 * ((s >> 1) & 1) + ((v >> 1) & 1),
                     z = 2 * ((s >> 2) & 1) + ((v >> 2) & 1);
      m[s] |= std::uint64_t{1} << (x + 4 * y + 16 * z);
    }
  return m;
}
constexpr std::array<std::uint64_t, 8> kSubCube = sub_cube_masks();

unsigned stored_bit(unsigned x, unsigned y, unsigned z, unsigned m) {
  if (m & 1) x = 3 - x;
  if (m & 2) y = 3 - y;
  if (m & 4) z = 3 - z;
  return x + 4 * y + 16 * z;
}

// The index of the reference of stored slot s in a node whose header is h.
inline std::uint32_t child_offset(std::uint32_t h, unsigned s) {
  return 1 + static_cast<std::uint32_t>(std::popcount(h & 0xFFu & ((1u << s) - 1)));
}

} // namespace

std::string voxel_dag_kind_name(VoxelDagKind kind) {
  switch (kind) {
  case VoxelDagKind::svo:
    return "svo";
  case VoxelDagKind::dag:
    return "dag";
  case VoxelDagKind::ssvdag:
    return "ssvdag";
  }
  return "dag";
}

VoxelDagKind parse_voxel_dag_kind(const std::string& text) {
  for (auto k : {VoxelDagKind::svo, VoxelDagKind::dag, VoxelDagKind::ssvdag})
    if (voxel_dag_kind_name(k) == text) return k;
  throw InvalidArgument("voxel DAG kind '" + text + "': expected svo, dag or ssvdag");
}

double VoxelDagStats::bits_per_voxel() const {
  return voxels == 0 ? 0.0 : 8.0 * static_cast<double>(bytes) / static_cast<double>(voxels);
}

// ---- building ----------------------------------------------------------------------------------

struct VoxelDagBuilder::State {
  VoxelDag dag;
  std::int64_t nx = 1, ny = 1, nz = 1, side = 4, bw = 1;
  std::int64_t z = 0, layers = 0;
  std::vector<std::uint64_t> layer; // the current 4-deep layer of leaves, bw x bw
  bool layer_empty = true;
  struct Pending {
    bool present = false, empty = true;
    std::vector<std::uint32_t> refs;
  };
  std::vector<Pending> pending; // per level
  std::vector<std::uint32_t> leaf_table, node_table;
  std::size_t leaf_count = 0, node_count = 0;

  bool merge() const { return dag.kind_ != VoxelDagKind::svo; }
  bool symmetric() const { return dag.kind_ == VoxelDagKind::ssvdag; }

  void count_level(int level) { ++dag.per_level_[static_cast<std::size_t>(dag.depth_ - level)]; }

  static void check_index(std::size_t i) {
    if (i > kMaxIndex)
      throw InvalidArgument("voxel DAG: more than 2^29 stored references (the 32-bit "
                            "encoding's limit)");
  }

  std::uint32_t store_leaf(std::uint64_t mask) {
    check_index(dag.leaves_.size());
    dag.leaves_.push_back(mask);
    count_level(2);
    return static_cast<std::uint32_t>(dag.leaves_.size() - 1);
  }

  std::uint32_t intern_leaf(std::uint64_t mask) {
    ++dag.svo_leaves_;
    unsigned m = 0;
    if (symmetric())
      for (unsigned r = 1; r < 8; ++r) {
        const std::uint64_t c = reflect_leaf(mask, r);
        if (c < reflect_leaf(mask, m)) m = r;
      }
    const std::uint64_t key = reflect_leaf(mask, m);
    if (!merge()) return store_leaf(key) << 3;
    if (2 * (leaf_count + 1) > leaf_table.size()) grow_leaves();
    const std::size_t cap = leaf_table.size() - 1;
    for (std::size_t h = mix(key) & cap;; h = (h + 1) & cap) {
      const std::uint32_t e = leaf_table[h];
      if (e == 0) {
        const std::uint32_t i = store_leaf(key);
        leaf_table[h] = i + 1;
        ++leaf_count;
        return i << 3 | m;
      }
      if (dag.leaves_[e - 1] == key) return (e - 1) << 3 | m;
    }
  }

  void grow_leaves() {
    std::vector<std::uint32_t> t(std::max<std::size_t>(1024, 2 * leaf_table.size()), 0);
    const std::size_t cap = t.size() - 1;
    for (std::uint32_t e : leaf_table)
      if (e != 0) {
        std::size_t h = mix(dag.leaves_[e - 1]) & cap;
        while (t[h] != 0) h = (h + 1) & cap;
        t[h] = e;
      }
    leaf_table.swap(t);
  }

  std::uint64_t node_hash(const std::uint32_t* w) const {
    std::uint64_t h = w[0];
    const int n = std::popcount(w[0] & 0xFFu);
    for (int i = 1; i <= n; ++i) h = mix(h * 0x9E3779B97F4A7C15ull + w[i]);
    return mix(h);
  }

  void grow_nodes() {
    std::vector<std::uint32_t> t(std::max<std::size_t>(1024, 2 * node_table.size()), 0);
    const std::size_t cap = t.size() - 1;
    for (std::uint32_t e : node_table)
      if (e != 0) {
        std::size_t h = node_hash(dag.words_.data() + (e - 1)) & cap;
        while (t[h] != 0) h = (h + 1) & cap;
        t[h] = e;
      }
    node_table.swap(t);
  }

  // The node of level `level` whose children (slots 0..7) are c; not all empty.
  // The reflections that leave a stored subtree unchanged (bit r: reflection r): a reference's
  // bits matter modulo them, and are normalized to the least of their coset so that equal
  // subtrees get equal references (the key below is then a canonical form of the class).
  unsigned stabilizer(std::uint32_t ref, int level) const {
    if (level == 2) {
      const std::uint64_t v = dag.leaves_[ref >> 3];
      unsigned st = 0;
      for (unsigned r = 0; r < 8; ++r)
        if (reflect_leaf(v, r) == v) st |= 1u << r;
      return st;
    }
    return (dag.words_[ref >> 3] >> 16) & 0xFFu;
  }
  static std::uint32_t normalized(std::uint32_t ref, unsigned stab) {
    if (ref == kEmpty) return ref;
    unsigned best = 7;
    for (unsigned r = 0; r < 8; ++r)
      if ((stab >> r) & 1) best = std::min(best, (ref & 7u) ^ r);
    return (ref & ~7u) | best;
  }

  std::uint32_t intern_node(const std::array<std::uint32_t, 8>& c, int level) {
    ++dag.svo_inner_;
    std::array<std::uint32_t, 8> key = c;
    unsigned m = 0, stab = 1;
    if (symmetric()) {
      std::array<unsigned, 8> st{};
      for (unsigned s = 0; s < 8; ++s) {
        st[s] = c[s] == kEmpty ? 1u : stabilizer(c[s], level - 1);
        key[s] = normalized(c[s], st[s]);
      }
      std::array<std::array<std::uint32_t, 8>, 8> k{};
      for (unsigned r = 0; r < 8; ++r) {
        for (unsigned s = 0; s < 8; ++s) {
          const std::uint32_t e = c[s ^ r];
          k[r][s] = e == kEmpty ? kEmpty : normalized(e ^ r, st[s ^ r]);
        }
        if (k[r] < k[m]) m = r;
      }
      key = k[m];
      stab = 0;
      for (unsigned r = 0; r < 8; ++r)
        if (k[r] == key) stab |= 1u << (r ^ m);
    }
    std::array<std::uint32_t, 9> w{};
    int n = 0;
    for (unsigned s = 0; s < 8; ++s)
      if (key[s] != kEmpty) {
        w[0] |= 1u << s;
        w[static_cast<std::size_t>(++n)] = key[s];
      }
    w[0] |= static_cast<std::uint32_t>(level) << 8 | stab << 16;
    auto store = [&] {
      check_index(dag.words_.size() + static_cast<std::size_t>(n));
      const auto at = static_cast<std::uint32_t>(dag.words_.size());
      dag.words_.insert(dag.words_.end(), w.begin(), w.begin() + n + 1);
      count_level(level);
      return at;
    };
    if (!merge()) return store() << 3;
    if (2 * (node_count + 1) > node_table.size()) grow_nodes();
    const std::size_t cap = node_table.size() - 1;
    for (std::size_t h = node_hash(w.data()) & cap;; h = (h + 1) & cap) {
      const std::uint32_t e = node_table[h];
      if (e == 0) {
        const std::uint32_t at = store();
        node_table[h] = at + 1;
        ++node_count;
        return at << 3 | m;
      }
      if (std::equal(w.begin(), w.begin() + n + 1, dag.words_.begin() + (e - 1)))
        return (e - 1) << 3 | m;
    }
  }

  // Two z-consecutive layers of level `level` (lower, upper) -> one of level + 1.
  void push(int level, Pending in) {
    if (level == dag.depth_) {
      dag.root_ = in.empty ? kEmpty : in.refs[0];
      return;
    }
    Pending& p = pending[static_cast<std::size_t>(level)];
    if (!p.present) {
      p = std::move(in);
      p.present = true;
      return;
    }
    Pending up;
    up.present = true;
    if (!(p.empty && in.empty)) {
      const std::int64_t n = side >> level, h = n / 2;
      up.refs.assign(static_cast<std::size_t>(h * h), kEmpty);
      const std::uint32_t* zs[2] = {p.empty ? nullptr : p.refs.data(),
                                    in.empty ? nullptr : in.refs.data()};
      for (std::int64_t Y = 0; Y < h; ++Y)
        for (std::int64_t X = 0; X < h; ++X) {
          std::array<std::uint32_t, 8> c{};
          bool any = false;
          for (unsigned s = 0; s < 8; ++s) {
            const std::uint32_t* l = zs[s >> 2];
            const std::int64_t y = 2 * Y + ((s >> 1) & 1), x = 2 * X + (s & 1);
            c[s] = l ? l[y * n + x] : kEmpty;
            any = any || c[s] != kEmpty;
          }
          if (any) {
            up.refs[static_cast<std::size_t>(Y * h + X)] = intern_node(c, level + 1);
            up.empty = false;
          }
        }
      if (up.empty) up.refs.clear();
    }
    p = Pending{};
    push(level + 1, std::move(up));
  }

  void emit_layer() {
    Pending l;
    if (!layer_empty) {
      l.refs.assign(layer.size(), kEmpty);
      for (std::size_t i = 0; i < layer.size(); ++i)
        if (layer[i] != 0) {
          l.refs[i] = intern_leaf(layer[i]);
          l.empty = false;
          layer[i] = 0;
        }
    }
    layer_empty = true;
    ++layers;
    push(2, std::move(l));
  }
};

VoxelDagBuilder::VoxelDagBuilder(const std::array<std::int64_t, 3>& extent, VoxelDagKind kind)
    : s_(std::make_unique<State>()) {
  for (std::int64_t e : extent)
    if (e < 1 || e > kMaxSide)
      throw InvalidArgument("voxel DAG: extent " + std::to_string(e) +
                            " outside [1, 2^20] (the digital rays' bound)");
  State& s = *s_;
  s.nx = extent[0];
  s.ny = extent[1];
  s.nz = extent[2];
  s.dag.extent_ = extent;
  s.dag.kind_ = kind;
  s.dag.depth_ = 2;
  while ((std::int64_t{1} << s.dag.depth_) < std::max({s.nx, s.ny, s.nz})) ++s.dag.depth_;
  s.side = std::int64_t{1} << s.dag.depth_;
  s.bw = s.side / 4;
  s.layer.assign(static_cast<std::size_t>(s.bw * s.bw), 0);
  s.pending.resize(static_cast<std::size_t>(s.dag.depth_) + 1);
  s.dag.per_level_.assign(static_cast<std::size_t>(s.dag.depth_ - 1), 0);
}

VoxelDagBuilder::~VoxelDagBuilder() = default;

void VoxelDagBuilder::add_slices(const std::uint8_t* data, std::int64_t slices) {
  State& s = *s_;
  if (slices < 0 || slices > s.nz - s.z)
    throw InvalidArgument("voxel DAG: " + std::to_string(slices) + " slices after " +
                          std::to_string(s.z) + " pass the extent " + std::to_string(s.nz));
  for (std::int64_t k = 0; k < slices; ++k, ++s.z) {
    const std::uint8_t* slice = data + k * s.nx * s.ny;
    const unsigned zb = 16 * static_cast<unsigned>(s.z & 3);
    for (std::int64_t y = 0; y < s.ny; ++y) {
      const std::uint8_t* row = slice + y * s.nx;
      std::uint64_t* bricks = s.layer.data() + (y >> 2) * s.bw;
      const unsigned yb = 4 * static_cast<unsigned>(y & 3) + zb;
      std::int64_t x = 0;
      for (; x < s.nx; x += 8) {
        const std::int64_t n = std::min<std::int64_t>(8, s.nx - x);
        if (n == 8) {
          std::uint64_t w;
          std::memcpy(&w, row + x, 8);
          if (w == 0) continue;
        }
        for (std::int64_t i = x; i < x + n; ++i)
          if (row[i] != 0) {
            bricks[i >> 2] |= std::uint64_t{1} << (static_cast<unsigned>(i & 3) + yb);
            ++s.dag.voxels_;
            s.layer_empty = false;
          }
      }
    }
    if ((s.z & 3) == 3) s.emit_layer();
  }
}

VoxelDag VoxelDagBuilder::finish() {
  State& s = *s_;
  if ((s.z & 3) != 0) s.emit_layer();
  while (s.layers < s.bw) s.emit_layer();
  VoxelDag out = std::move(s.dag);
  s_ = std::make_unique<State>();
  return out;
}

VoxelDag build_voxel_dag(const Image<std::uint8_t>& volume, VoxelDagKind kind) {
  const Domain& d = volume.domain();
  if (d.dim() != 3)
    throw InvalidArgument("voxel DAG: a 3D volume is needed (got dimension " +
                          std::to_string(d.dim()) + ")");
  VoxelDagBuilder b({d.extent(2), d.extent(1), d.extent(0)}, kind);
  b.add_slices(volume.values().data(), d.extent(0));
  return b.finish();
}

// ---- queries -----------------------------------------------------------------------------------

bool VoxelDag::contains(const std::array<std::int64_t, 3>& v) const {
  for (std::size_t a = 0; a < 3; ++a)
    if (v[a] < 0 || v[a] >= extent_[a]) return false;
  std::uint32_t ref = root_;
  unsigned m = 0;
  for (int level = depth_; level >= 3; --level) {
    if (ref == kEmpty) return false;
    m ^= ref & 7;
    const std::uint32_t* node = words_.data() + (ref >> 3);
    unsigned s = 0;
    for (unsigned a = 0; a < 3; ++a) s |= static_cast<unsigned>((v[a] >> (level - 1)) & 1) << a;
    s ^= m;
    if (!((node[0] >> s) & 1)) return false;
    ref = node[child_offset(node[0], s)];
  }
  if (ref == kEmpty) return false;
  m ^= ref & 7;
  const unsigned bit = stored_bit(static_cast<unsigned>(v[0] & 3), static_cast<unsigned>(v[1] & 3),
                                  static_cast<unsigned>(v[2] & 3), m);
  return (leaves_[ref >> 3] >> bit) & 1;
}

namespace {

__extension__ typedef __int128 i128;

// A parameter n / d (d > 0) with its double approximation v: comparisons are decided on v when
// the gap exceeds v's error bound (|v - n/d| <= 2^-51.9 |n/d|: n rounded once, d < 2^53 exact,
// one division), and exactly on the 128-bit cross products otherwise.
struct Time {
  i128 n, d;
  double v;
};
Time make_time(i128 n, i128 d) {
  if (d < 0) {
    n = -n;
    d = -d;
  }
  return {n, d, static_cast<double>(n) / static_cast<double>(d)};
}
inline bool lt(const Time& a, const Time& b) {
  const double gap = b.v - a.v, tol = (std::abs(a.v) + std::abs(b.v)) * 0x1p-50;
  if (gap > tol) return true;
  if (gap < -tol) return false;
  return a.n * b.d < b.n * a.d;
}
inline bool eq(const Time& a, const Time& b) {
  const double gap = b.v - a.v, tol = (std::abs(a.v) + std::abs(b.v)) * 0x1p-50;
  if (gap > tol || gap < -tol) return false;
  return a.n * b.d == b.n * a.d;
}

// A piece of a node's chord in one child: its ends are the node's entry, exit or mid-plane
// parameters (pointers into the caller's frame: no copies on the way down).
struct Piece {
  const Time* start;
  const Time* end;
  unsigned slot;
  int axis;
};

// The ray's walk through the stored nodes (see the header).
struct RayWalk {
  const std::vector<std::uint32_t>& words;
  const std::vector<std::uint64_t>& leaves;
  const DigitalRay& r;
  std::vector<DagRayHit>* out;     // all hits, up to max; or
  std::optional<DagRayHit>* first; // the first only
  std::size_t max;
  std::size_t found = 0;
  std::array<i128, 3> o2{}, d2{}; // 2 O, 2 D

  bool full() const { return found >= max; }
  void emit(const std::array<std::int64_t, 3>& v, int axis) {
    ++found;
    if (first)
      *first = DagRayHit{v, axis};
    else
      out->push_back({v, axis});
  }

  // The pieces of (tin, tout) in the children of size h of the cube at c, in order; tm receives
  // the mid-plane parameters the pieces point to.
  int split(const std::array<std::int64_t, 3>& c, std::int64_t h, const Time& tin, int ain,
            const Time& tout, Time* tm, Piece* pieces) const {
    int cut[3];
    int n = 0;
    unsigned slot = 0;
    int axis = ain;
    for (int a = 0; a < 3; ++a) {
      const auto ua = static_cast<std::size_t>(a);
      const i128 plane = (2 * static_cast<i128>(c[ua] + h) - 1) * r.denominator;
      if (d2[ua] == 0) {
        if (o2[ua] >= plane) slot |= 1u << a;
        continue;
      }
      tm[a] = make_time(plane - o2[ua], d2[ua]);
      const bool after_in = lt(tin, tm[a]);
      // The child's side at the entry: above the mid-plane when it was crossed before (D > 0)
      // or will be crossed after (D < 0) the entry.
      if (after_in == (d2[ua] < 0)) slot |= 1u << a;
      if (!after_in) {
        if (a < axis && eq(tm[a], tin)) axis = a; // crossed at the entry: the lowest axis
        continue;
      }
      if (!lt(tm[a], tout)) continue;
      int i = n++;
      while (i > 0 && lt(tm[a], tm[cut[i - 1]])) {
        cut[i] = cut[i - 1];
        --i;
      }
      cut[i] = a;
    }
    int count = 0;
    const Time* start = &tin;
    for (int k = 0; k <= n; ++k) {
      const Time* end = k < n ? &tm[cut[k]] : &tout;
      // A piece of zero length (two cuts at one parameter: an edge or a corner) is skipped; the
      // next piece keeps the lower axis.
      if (k == 0 || !eq(*start, *end)) {
        pieces[count++] = {start, end, slot, axis};
        start = end;
        if (k < n) axis = cut[k];
      }
      if (k < n) slot ^= 1u << cut[k];
    }
    return count;
  }

  static std::array<std::int64_t, 3> child(const std::array<std::int64_t, 3>& c, unsigned s,
                                           std::int64_t h) {
    return {c[0] + (s & 1 ? h : 0), c[1] + (s & 2 ? h : 0), c[2] + (s & 4 ? h : 0)};
  }

  void leaf(std::uint64_t mask, unsigned m, const std::array<std::int64_t, 3>& c, const Time& tin,
            int ain, const Time& tout) {
    Time t2[3];
    Piece p2[4];
    const int n2 = split(c, 2, tin, ain, tout, t2, p2);
    for (int i = 0; i < n2 && !full(); ++i) {
      if ((mask & kSubCube[p2[i].slot ^ m]) == 0) continue;
      const auto c1 = child(c, p2[i].slot, 2);
      Time t1[3];
      Piece p1[4];
      const int n1 = split(c1, 1, *p2[i].start, p2[i].axis, *p2[i].end, t1, p1);
      for (int j = 0; j < n1 && !full(); ++j) {
        const auto v = child(c1, p1[j].slot, 1);
        const unsigned bit =
            stored_bit(static_cast<unsigned>(v[0] & 3), static_cast<unsigned>(v[1] & 3),
                       static_cast<unsigned>(v[2] & 3), m);
        if ((mask >> bit) & 1) emit(v, p1[j].axis);
      }
    }
  }

  void node(std::uint32_t ref, int level, unsigned m, const std::array<std::int64_t, 3>& c,
            const Time& tin, int ain, const Time& tout) {
    m ^= ref & 7;
    if (level == 2) {
      leaf(leaves[ref >> 3], m, c, tin, ain, tout);
      return;
    }
    const std::uint32_t* w = words.data() + (ref >> 3);
    const std::int64_t h = std::int64_t{1} << (level - 1);
    Time t[3];
    Piece p[4];
    const int n = split(c, h, tin, ain, tout, t, p);
    for (int i = 0; i < n && !full(); ++i) {
      const unsigned s = p[i].slot ^ m;
      if (!((w[0] >> s) & 1)) continue;
      node(w[child_offset(w[0], s)], level - 1, m, child(c, p[i].slot, h), *p[i].start, p[i].axis,
           *p[i].end);
    }
  }

  void run(std::uint32_t root, int depth, std::int64_t side) {
    const std::array<std::int64_t, 3> box{side, side, side};
    check_digital_ray(r, box);
    if (root == kEmpty || max == 0) return;
    const RayChord ch = digital_ray_chord(r, box);
    if (!ch.hit) return;
    for (std::size_t a = 0; a < 3; ++a) {
      o2[a] = 2 * static_cast<i128>(r.origin[a]);
      d2[a] = 2 * static_cast<i128>(r.direction[a]);
    }
    const Time tin = make_time(ch.in.n, ch.in.d), tout = make_time(ch.out.n, ch.out.d);
    node(root, depth, 0, {0, 0, 0}, tin, ch.in_axis, tout);
  }
};

} // namespace

std::vector<DagRayHit> VoxelDag::ray_hits(const DigitalRay& ray, std::size_t max_hits) const {
  std::vector<DagRayHit> out;
  RayWalk walk{words_, leaves_, ray, &out, nullptr, max_hits};
  walk.run(root_, depth_, side());
  return out;
}

std::optional<DagRayHit> VoxelDag::first_hit(const DigitalRay& ray) const {
  std::optional<DagRayHit> first;
  RayWalk walk{words_, leaves_, ray, nullptr, &first, 1};
  walk.run(root_, depth_, side());
  return first;
}

VoxelDagStats VoxelDag::stats() const {
  VoxelDagStats s;
  s.kind = kind_;
  s.depth = depth_;
  s.voxels = voxels_;
  s.leaves = static_cast<std::int64_t>(leaves_.size());
  s.nodes_per_level = per_level_;
  for (std::size_t i = 0; i + 1 < per_level_.size(); ++i) s.inner_nodes += per_level_[i];
  s.pointers = static_cast<std::int64_t>(words_.size()) - s.inner_nodes;
  s.bytes = 4 * (s.inner_nodes + s.pointers) + 8 * s.leaves;
  s.svo_inner_nodes = svo_inner_;
  s.svo_leaves = svo_leaves_;
  s.svo_pointers = std::max<std::int64_t>(0, svo_inner_ + svo_leaves_ - 1); // all but the root
  s.svo_bytes = 4 * (svo_inner_ + s.svo_pointers) + 8 * svo_leaves_;
  return s;
}

Image<std::uint8_t> VoxelDag::to_image() const {
  Image<std::uint8_t> img(Domain({extent_[2], extent_[1], extent_[0]}));
  auto& v = img.values();
  auto set = [&](const std::array<std::int64_t, 3>& p) {
    if (p[0] < extent_[0] && p[1] < extent_[1] && p[2] < extent_[2])
      v[static_cast<std::size_t>((p[2] * extent_[1] + p[1]) * extent_[0] + p[0])] = 1;
  };
  auto walk = [&](auto&& self, std::uint32_t ref, int level, unsigned m,
                  const std::array<std::int64_t, 3>& c) -> void {
    m ^= ref & 7;
    if (level == 2) {
      const std::uint64_t mask = leaves_[ref >> 3];
      for (unsigned z = 0; z < 4; ++z)
        for (unsigned y = 0; y < 4; ++y)
          for (unsigned x = 0; x < 4; ++x)
            if ((mask >> stored_bit(x, y, z, m)) & 1) set({c[0] + x, c[1] + y, c[2] + z});
      return;
    }
    const std::uint32_t* w = words_.data() + (ref >> 3);
    const std::int64_t h = std::int64_t{1} << (level - 1);
    for (unsigned s = 0; s < 8; ++s) {
      const unsigned st = s ^ m;
      if (!((w[0] >> st) & 1)) continue;
      self(self, w[child_offset(w[0], st)], level - 1, m,
           {c[0] + (s & 1 ? h : 0), c[1] + (s & 2 ? h : 0), c[2] + (s & 4 ? h : 0)});
    }
  };
  if (root_ != kEmpty) walk(walk, root_, depth_, 0, {0, 0, 0});
  return img;
}

} // namespace zdg
