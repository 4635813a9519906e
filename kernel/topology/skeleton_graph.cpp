#include <zdg/arith/error.hpp>
#include <zdg/kernel/topology/betti_numbers.hpp>
#include <zdg/kernel/topology/skeleton_graph.hpp>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

namespace zdg {

namespace {

struct UnionFind {
  std::vector<std::int64_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  std::int64_t find(std::int64_t x) {
    while (parent[static_cast<std::size_t>(x)] != x) {
      auto& p = parent[static_cast<std::size_t>(x)];
      p = parent[static_cast<std::size_t>(p)];
      x = p;
    }
    return x;
  }
  void unite(std::int64_t a, std::int64_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
  }
};

} // namespace

std::string skeleton_node_kind_name(SkeletonNodeKind kind) {
  switch (kind) {
  case SkeletonNodeKind::junction:
    return "junction";
  case SkeletonNodeKind::end:
    return "end";
  case SkeletonNodeKind::joint:
    return "joint";
  case SkeletonNodeKind::isolated:
    return "isolated";
  case SkeletonNodeKind::loop:
    return "loop";
  }
  return "?";
}

SkeletonGraph skeleton_graph(const Image<std::uint8_t>& skeleton,
                             const Image<std::int64_t>* squared_radius) {
  const Domain& dom = skeleton.domain();
  const int d = dom.dim();
  if (d != 2 && d != 3) {
    throw InvalidArgument("skeleton graph: a " + std::to_string(d) +
                          "-D image (the graph is built in 2D and 3D)");
  }
  if (squared_radius != nullptr && !(squared_radius->domain() == dom)) {
    throw InvalidArgument("skeleton graph: the squared-radius image has another domain");
  }
  // The points of S (increasing linear index) and their coordinates (from 0).
  std::vector<std::int64_t> pts;
  for (std::int64_t i = 0; i < dom.size(); ++i) {
    if (skeleton[i] != 0) pts.push_back(i);
  }
  const auto n = static_cast<std::int64_t>(pts.size());
  auto id_of = [&](std::int64_t index) -> std::int64_t {
    const auto it = std::lower_bound(pts.begin(), pts.end(), index);
    return it != pts.end() && *it == index ? it - pts.begin() : -1;
  };
  std::vector<std::array<std::int64_t, 3>> co(pts.size());
  for (std::size_t j = 0; j < pts.size(); ++j) {
    std::int64_t r = pts[j];
    co[j] = {0, 0, 0};
    for (int k = d; k-- > 0;) {
      co[j][static_cast<std::size_t>(k + 3 - d)] = r % dom.extent(k);
      r /= dom.extent(k);
    }
  }
  // Neighbours in S (8- or 26-adjacency).
  std::vector<std::vector<std::int64_t>> nb(pts.size());
  for (std::int64_t j = 0; j < n; ++j) {
    const auto& c = co[static_cast<std::size_t>(j)];
    for (int a = (d == 3 ? -1 : 0); a <= (d == 3 ? 1 : 0); ++a) {
      for (int b = -1; b <= 1; ++b) {
        for (int e = -1; e <= 1; ++e) {
          if (a == 0 && b == 0 && e == 0) continue;
          const std::array<std::int64_t, 3> q{c[0] + a, c[1] + b, c[2] + e};
          std::int64_t index = 0;
          bool inside = true;
          for (int k = 0; k < d; ++k) {
            const std::int64_t t = q[static_cast<std::size_t>(k + 3 - d)];
            inside = inside && t >= 0 && t < dom.extent(k);
            index += t * dom.stride(k);
          }
          if (!inside || skeleton[index] == 0) continue;
          nb[static_cast<std::size_t>(j)].push_back(id_of(index));
        }
      }
    }
  }
  auto adjacent = [&](std::int64_t u, std::int64_t v) {
    for (std::size_t k = 0; k < 3; ++k) {
      const std::int64_t t =
          co[static_cast<std::size_t>(u)][k] - co[static_cast<std::size_t>(v)][k];
      if (t < -1 || t > 1) return false;
    }
    return true;
  };
  auto step = [&](std::int64_t u, std::int64_t v) {
    std::int64_t s = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      const std::int64_t t =
          co[static_cast<std::size_t>(u)][k] - co[static_cast<std::size_t>(v)][k];
      s += t * t;
    }
    return std::sqrt(static_cast<double>(s));
  };
  std::vector<char> regular(pts.size(), 0);
  for (std::int64_t j = 0; j < n; ++j) {
    const auto& v = nb[static_cast<std::size_t>(j)];
    regular[static_cast<std::size_t>(j)] = v.size() == 2 && !adjacent(v[0], v[1]);
  }
  // Nodes: components of the node points.
  SkeletonGraph g;
  std::vector<std::int64_t> node_of(pts.size(), -1);
  for (std::int64_t j = 0; j < n; ++j) {
    if (regular[static_cast<std::size_t>(j)] || node_of[static_cast<std::size_t>(j)] >= 0) continue;
    const auto id = static_cast<std::int64_t>(g.nodes.size());
    g.nodes.emplace_back();
    std::vector<std::int64_t> stack{j};
    node_of[static_cast<std::size_t>(j)] = id;
    while (!stack.empty()) {
      const std::int64_t u = stack.back();
      stack.pop_back();
      g.nodes.back().points.push_back(pts[static_cast<std::size_t>(u)]);
      for (auto v : nb[static_cast<std::size_t>(u)]) {
        if (regular[static_cast<std::size_t>(v)] || node_of[static_cast<std::size_t>(v)] >= 0)
          continue;
        node_of[static_cast<std::size_t>(v)] = id;
        stack.push_back(v);
      }
    }
    std::sort(g.nodes.back().points.begin(), g.nodes.back().points.end());
  }
  // Branches: components of the regular points (paths or cycles).
  std::vector<char> seen(pts.size(), 0);
  for (std::int64_t j = 0; j < n; ++j) {
    if (!regular[static_cast<std::size_t>(j)] || seen[static_cast<std::size_t>(j)]) continue;
    // Walk from j to one end (the previous point stays behind), then back across to the other.
    auto walk = [&](std::int64_t start, std::int64_t first) {
      std::vector<std::int64_t> path;
      std::int64_t prev = start, cur = first;
      while (cur != start && regular[static_cast<std::size_t>(cur)]) {
        path.push_back(cur);
        const auto& v = nb[static_cast<std::size_t>(cur)];
        const std::int64_t next = v[0] == prev ? v[1] : v[0];
        prev = cur;
        cur = next;
      }
      return std::make_pair(path, cur); // cur: a node point, or start (a cycle)
    };
    const auto& v = nb[static_cast<std::size_t>(j)];
    auto [left, left_end] = walk(j, v[0]);
    SkeletonBranch br;
    std::vector<std::int64_t> seq;
    std::int64_t a = -1, b = -1; // the node points at the ends
    if (left_end == j) {
      // A cycle: its smallest point becomes a node of kind loop.
      std::vector<std::int64_t> cyc{j};
      cyc.insert(cyc.end(), left.begin(), left.end());
      const auto lo = std::min_element(cyc.begin(), cyc.end()) - cyc.begin();
      std::rotate(cyc.begin(), cyc.begin() + lo, cyc.end());
      for (auto u : cyc) seen[static_cast<std::size_t>(u)] = 1;
      const auto id = static_cast<std::int64_t>(g.nodes.size());
      g.nodes.emplace_back();
      g.nodes.back().kind = SkeletonNodeKind::loop;
      g.nodes.back().points = {pts[static_cast<std::size_t>(cyc[0])]};
      node_of[static_cast<std::size_t>(cyc[0])] = id;
      a = b = cyc[0];
      seq.assign(cyc.begin() + 1, cyc.end());
    } else {
      auto [right, right_end] = walk(j, v[1]);
      seq.assign(left.rbegin(), left.rend());
      seq.push_back(j);
      seq.insert(seq.end(), right.begin(), right.end());
      a = left_end;
      b = right_end;
      for (auto u : seq) seen[static_cast<std::size_t>(u)] = 1;
    }
    br.from = node_of[static_cast<std::size_t>(a)];
    br.to = node_of[static_cast<std::size_t>(b)];
    std::int64_t prev = a;
    for (auto u : seq) {
      br.length += step(prev, u);
      prev = u;
      br.points.push_back(pts[static_cast<std::size_t>(u)]);
      if (squared_radius != nullptr)
        br.squared_radii.push_back((*squared_radius)[pts[static_cast<std::size_t>(u)]]);
    }
    br.length += step(prev, b);
    g.branches.push_back(std::move(br));
  }
  // Degrees, kinds, components, loops.
  UnionFind uf(g.nodes.size());
  for (const auto& br : g.branches) {
    ++g.nodes[static_cast<std::size_t>(br.from)].degree;
    ++g.nodes[static_cast<std::size_t>(br.to)].degree;
    uf.unite(br.from, br.to);
  }
  for (std::size_t k = 0; k < g.nodes.size(); ++k) {
    auto& node = g.nodes[k];
    if (uf.find(static_cast<std::int64_t>(k)) == static_cast<std::int64_t>(k)) ++g.components;
    if (node.kind == SkeletonNodeKind::loop) continue;
    node.kind = node.degree == 0   ? SkeletonNodeKind::isolated
                : node.degree == 1 ? SkeletonNodeKind::end
                : node.degree == 2 ? SkeletonNodeKind::joint
                                   : SkeletonNodeKind::junction;
  }
  // The cycles inside nodes (a cycle of the clique complex has at least 4 points): b1 of each
  // node's points, on a copy of their bounding box with a margin of background.
  std::int64_t inside = 0;
  for (auto& node : g.nodes) {
    if (node.points.size() < 4) continue;
    std::array<std::int64_t, 3> lo{}, hi{};
    lo.fill(INT64_MAX);
    hi.fill(INT64_MIN);
    for (auto i : node.points) {
      const auto& c = co[static_cast<std::size_t>(id_of(i))];
      for (std::size_t k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], c[k]);
        hi[k] = std::max(hi[k], c[k]);
      }
    }
    std::vector<std::int64_t> ext;
    for (int k = 3 - d; k < 3; ++k)
      ext.push_back(hi[static_cast<std::size_t>(k)] - lo[static_cast<std::size_t>(k)] + 3);
    Image<std::uint8_t> box{Domain(ext), std::uint8_t{0}};
    for (auto i : node.points) {
      const auto& c = co[static_cast<std::size_t>(id_of(i))];
      std::int64_t j = 0;
      for (int k = 3 - d; k < 3; ++k) {
        const auto uk = static_cast<std::size_t>(k);
        j = j * ext[static_cast<std::size_t>(k - 3 + d)] + (c[uk] - lo[uk] + 1);
      }
      box[j] = 1;
    }
    node.loops = betti_numbers(box, default_adjacency_pair(d), 1).b[1];
    inside += node.loops;
  }
  g.loops = static_cast<std::int64_t>(g.branches.size()) -
            static_cast<std::int64_t>(g.nodes.size()) + g.components + inside;
  return g;
}

} // namespace zdg
