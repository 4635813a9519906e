#include <zdg/arith/error.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>
#include <zdg/kernel/topology/adjacency.hpp>
#include <zdg/kernel/topology/connected_components.hpp>

#include <algorithm>
#include <numeric>

namespace zdg {
namespace {

// floor(n k / w) for 0 <= k <= w, without forming n k.
std::int64_t chunk_bound(std::int64_t n, std::int64_t k, std::int64_t w) {
  return n / w * k + n % w * k / w;
}

struct Run {
  std::int64_t begin, end; // [begin, end) along the last axis
};

// The image seen as n0 planes of n1 rows of n2 points (2D: n0 = 1), its runs row by row.
struct RunTable {
  std::int64_t n0 = 1, n1 = 1, n2 = 1;
  bool three_d = true;
  std::vector<std::int64_t> row_begin; // runs of row r: [row_begin[r], row_begin[r + 1])
  std::vector<Run> runs;

  std::int64_t rows() const { return n0 * n1; }
};

RunTable find_runs(const Image<std::uint8_t>& image, Phase phase, unsigned threads) {
  RunTable t;
  const Domain& d = image.domain();
  t.three_d = d.dim() == 3;
  t.n0 = t.three_d ? d.extent(0) : 1;
  t.n1 = d.extent(d.dim() - 2);
  t.n2 = d.extent(d.dim() - 1);
  const std::int64_t rows = t.rows(), n2 = t.n2;
  const std::uint8_t* data = image.values().data();
  const bool want_nonzero = phase == Phase::object;
  // Per chunk of rows: the runs found there, then concatenated in row order.
  const unsigned w = worker_count(threads, rows);
  std::vector<std::vector<Run>> chunk_runs(w);
  std::vector<std::int64_t> counts(static_cast<std::size_t>(rows));
  parallel_for(w, w, [&](std::int64_t k) {
    const std::int64_t rb = chunk_bound(rows, k, w), re = chunk_bound(rows, k + 1, w);
    auto& out = chunk_runs[static_cast<std::size_t>(k)];
    for (std::int64_t r = rb; r < re; ++r) {
      const std::uint8_t* row = data + r * n2;
      const std::size_t before = out.size();
      std::int64_t x = 0;
      while (x < n2) {
        while (x < n2 && (row[x] != 0) != want_nonzero) ++x;
        if (x == n2) break;
        const std::int64_t b = x;
        while (x < n2 && (row[x] != 0) == want_nonzero) ++x;
        out.push_back({b, x});
      }
      counts[static_cast<std::size_t>(r)] = static_cast<std::int64_t>(out.size() - before);
    }
  });
  t.row_begin.assign(static_cast<std::size_t>(rows) + 1, 0);
  std::partial_sum(counts.begin(), counts.end(), t.row_begin.begin() + 1);
  t.runs.reserve(static_cast<std::size_t>(t.row_begin.back()));
  for (auto& c : chunk_runs) {
    t.runs.insert(t.runs.end(), c.begin(), c.end());
    std::vector<Run>().swap(c);
  }
  return t;
}

std::int64_t find_root(std::vector<std::int64_t>& parent, std::int64_t a) {
  while (parent[static_cast<std::size_t>(a)] != a) {
    auto& pa = parent[static_cast<std::size_t>(a)];
    pa = parent[static_cast<std::size_t>(pa)];
    a = pa;
  }
  return a;
}

void unite(std::vector<std::int64_t>& parent, std::int64_t a, std::int64_t b) {
  a = find_root(parent, a);
  b = find_root(parent, b);
  if (a == b) return;
  if (a < b) std::swap(a, b);
  parent[static_cast<std::size_t>(a)] = b; // the smaller index is the root
}

// Unites the runs of row r with those of its preceding neighbour rows r' >= lowest_row.
void unite_row(const RunTable& t, int m, std::int64_t r, std::int64_t lowest_row,
               std::vector<std::int64_t>& parent) {
  const std::int64_t i0 = r / t.n1, i1 = r % t.n1;
  // Preceding row offsets (d0, d1) with l1 norm <= m.
  const int offsets[4][2] = {{0, -1}, {-1, -1}, {-1, 0}, {-1, 1}};
  for (const auto& o : offsets) {
    const int l1 = -o[0] + (o[1] != 0 ? 1 : 0);
    if (l1 > m) continue;
    const std::int64_t j0 = i0 + o[0], j1 = i1 + o[1];
    if (j0 < 0 || j1 < 0 || j1 >= t.n1) continue;
    const std::int64_t q = j0 * t.n1 + j1;
    if (q < lowest_row) continue;
    const std::int64_t slack = l1 < m ? 1 : 0;
    std::int64_t a = t.row_begin[static_cast<std::size_t>(r)];
    const std::int64_t ae = t.row_begin[static_cast<std::size_t>(r) + 1];
    std::int64_t b = t.row_begin[static_cast<std::size_t>(q)];
    const std::int64_t be = t.row_begin[static_cast<std::size_t>(q) + 1];
    while (a < ae && b < be) {
      const Run& ra = t.runs[static_cast<std::size_t>(a)];
      const Run& rb = t.runs[static_cast<std::size_t>(b)];
      if (ra.begin < rb.end + slack && rb.begin < ra.end + slack) unite(parent, a, b);
      // Advance the run that ends first (both when they end together).
      if (ra.end < rb.end) {
        ++a;
      } else if (rb.end < ra.end) {
        ++b;
      } else {
        ++a;
        ++b;
      }
    }
  }
}

struct Forest {
  RunTable table;
  std::vector<std::int64_t> component; // component of every run, 0-based in scan order
  std::int64_t count = 0;
};

Forest label_runs(const Image<std::uint8_t>& image, int k, Phase phase, unsigned threads) {
  const int dim = image.dim();
  if (dim != 2 && dim != 3) {
    throw InvalidArgument("connected components: dimension " + std::to_string(dim) +
                          " (only 2D and 3D images)");
  }
  const int m = adjacency_max_l1(dim, k);
  Forest f;
  f.table = find_runs(image, phase, threads);
  const RunTable& t = f.table;
  const std::int64_t rows = t.rows();
  std::vector<std::int64_t>& parent = f.component;
  parent.resize(t.runs.size());
  std::iota(parent.begin(), parent.end(), std::int64_t{0});
  // Contiguous chunks of rows united in parallel (each touches only its own runs), then the
  // rows whose preceding neighbours lie in an earlier chunk: at most n1 + 1 rows per seam.
  const unsigned w = worker_count(threads, rows);
  auto chunk_begin = [&](std::int64_t c) { return chunk_bound(rows, c, w); };
  parallel_for(w, w, [&](std::int64_t c) {
    const std::int64_t rb = chunk_begin(c), re = chunk_begin(c + 1);
    for (std::int64_t r = rb; r < re; ++r) unite_row(t, m, r, rb, parent);
  });
  for (std::int64_t c = 1; c < static_cast<std::int64_t>(w); ++c) {
    const std::int64_t rb = chunk_begin(c), re = std::min(chunk_begin(c + 1), rb + t.n1 + 1);
    for (std::int64_t r = rb; r < re; ++r) unite_row(t, m, r, 0, parent);
  }
  // Every parent precedes its child: one pass in increasing order flattens the forest, and
  // the roots, numbered in that order, number the components in scan order.
  std::int64_t count = 0;
  for (std::size_t i = 0; i < parent.size(); ++i) {
    if (parent[i] == static_cast<std::int64_t>(i)) {
      parent[i] = -(++count); // a root: its (negated, 1-based) component number
    } else {
      const std::int64_t root_value = parent[static_cast<std::size_t>(parent[i])];
      parent[i] = root_value; // already negated: the parent was visited before
    }
  }
  for (auto& v : parent) v = -v - 1;
  f.count = count;
  return f;
}

bool run_on_border(const RunTable& t, std::int64_t r, const Run& run) {
  const std::int64_t i0 = r / t.n1, i1 = r % t.n1;
  return (t.three_d && (i0 == 0 || i0 == t.n0 - 1)) || i1 == 0 || i1 == t.n1 - 1 ||
         run.begin == 0 || run.end == t.n2;
}

} // namespace

Components connected_components(const Image<std::uint8_t>& image, int k,
                                const ComponentOptions& options) {
  Forest f = label_runs(image, k, options.phase, options.threads);
  const RunTable& t = f.table;
  if (f.count > std::int64_t{0xFFFFFFFF}) {
    throw OverflowError("connected components: " + std::to_string(f.count) +
                        " components do not fit uint32 labels");
  }
  const auto count = static_cast<std::size_t>(f.count);
  std::vector<std::int64_t> sizes(count, 0);
  std::vector<bool> border(count, false);
  for (std::int64_t r = 0; r < t.rows(); ++r) {
    for (std::int64_t i = t.row_begin[static_cast<std::size_t>(r)];
         i < t.row_begin[static_cast<std::size_t>(r) + 1]; ++i) {
      const Run& run = t.runs[static_cast<std::size_t>(i)];
      const auto c = static_cast<std::size_t>(f.component[static_cast<std::size_t>(i)]);
      sizes[c] += run.end - run.begin;
      if (!border[c] && run_on_border(t, r, run)) border[c] = true;
    }
  }
  // rank[c]: the final label - 1 of the component numbered c in scan order.
  std::vector<std::uint32_t> rank(count);
  std::iota(rank.begin(), rank.end(), std::uint32_t{0});
  Components out;
  if (options.order == ComponentOrder::by_size) {
    std::vector<std::uint32_t> by_size(count);
    std::iota(by_size.begin(), by_size.end(), std::uint32_t{0});
    std::stable_sort(by_size.begin(), by_size.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return sizes[a] > sizes[b]; });
    out.sizes.resize(count);
    out.touches_border.resize(count);
    for (std::size_t j = 0; j < count; ++j) {
      rank[by_size[j]] = static_cast<std::uint32_t>(j);
      out.sizes[j] = sizes[by_size[j]];
      out.touches_border[j] = border[by_size[j]];
    }
  } else {
    out.sizes = std::move(sizes);
    out.touches_border = std::move(border);
  }
  out.labels = Image<std::uint32_t>(image.domain(), std::uint32_t{0});
  std::uint32_t* labels = out.labels.values().data();
  parallel_chunks(t.rows(), options.threads, [&](std::int64_t rb, std::int64_t re) {
    for (std::int64_t r = rb; r < re; ++r) {
      for (std::int64_t i = t.row_begin[static_cast<std::size_t>(r)];
           i < t.row_begin[static_cast<std::size_t>(r) + 1]; ++i) {
        const Run& run = t.runs[static_cast<std::size_t>(i)];
        const std::uint32_t label =
            rank[static_cast<std::size_t>(f.component[static_cast<std::size_t>(i)])] + 1;
        std::fill(labels + r * t.n2 + run.begin, labels + r * t.n2 + run.end, label);
      }
    }
  });
  return out;
}

ComponentCount count_components(const Image<std::uint8_t>& image, int k, Phase phase,
                                unsigned threads) {
  Forest f = label_runs(image, k, phase, threads);
  const RunTable& t = f.table;
  std::vector<bool> border(static_cast<std::size_t>(f.count), false);
  for (std::int64_t r = 0; r < t.rows(); ++r) {
    for (std::int64_t i = t.row_begin[static_cast<std::size_t>(r)];
         i < t.row_begin[static_cast<std::size_t>(r) + 1]; ++i) {
      if (run_on_border(t, r, t.runs[static_cast<std::size_t>(i)])) {
        border[static_cast<std::size_t>(f.component[static_cast<std::size_t>(i)])] = true;
      }
    }
  }
  ComponentCount c;
  c.components = f.count;
  c.bounded = f.count - std::count(border.begin(), border.end(), true);
  return c;
}

} // namespace zdg
