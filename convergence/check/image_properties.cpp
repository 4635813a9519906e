// The image family of zdg check: distance transforms, simple points, Betti numbers of small
// binary images, against brute force and definitions written here from the literature.
#include <zdg/convergence/check/property.hpp>
#include <zdg/kernel/images/image.hpp>
#include <zdg/kernel/surfaces/image_surfaces.hpp>
#include <zdg/kernel/surfaces/image_surfels.hpp>
#include <zdg/kernel/topology/adjacency.hpp>
#include <zdg/kernel/topology/betti_numbers.hpp>
#include <zdg/kernel/topology/homotopic_thinning.hpp>
#include <zdg/kernel/topology/simple_points.hpp>
#include <zdg/kernel/transforms/distance_transform.hpp>
#include <zdg/kernel/transforms/voronoi_map.hpp>

#include <array>
#include <cstdlib>
#include <functional>
#include <set>
#include <vector>

namespace zdg::check {

namespace {

// --- small binary images as records ----------------------------------------------------------

Image<std::uint8_t> image_of(const Field& f) {
  std::vector<std::int64_t> ext;
  for (auto e : f.shape) ext.push_back(static_cast<std::int64_t>(e));
  std::vector<std::uint8_t> v;
  for (const auto& x : f.ints) v.push_back(x != 0 ? 1 : 0);
  return Image<std::uint8_t>(Domain(ext), std::move(v));
}

std::vector<std::size_t> shape_of(const Domain& d) {
  std::vector<std::size_t> s;
  for (int k = 0; k < d.dim(); ++k) s.push_back(static_cast<std::size_t>(d.extent(k)));
  return s;
}

// A random 2D (or 3D) 0/1 image with sides in [1, max side], of a random density.
Field random_image(Rng& rng, int dim, std::int64_t max_side) {
  Field f;
  f.name = "image";
  f.kind = FieldKind::array;
  f.numbers = true;
  f.shrink = Shrink::image;
  for (int k = 0; k < dim; ++k) f.shape.push_back(static_cast<std::size_t>(rng.range(1, max_side)));
  const std::uint64_t density = rng.range(1, 9);
  for (std::size_t i = 0; i < shape_size(f.shape); ++i) {
    f.ints.push_back(BigInt(rng.chance(density, 10) ? 1 : 0));
  }
  return f;
}

bool image_shape_ok(const Field& f, std::size_t max_side) {
  if (f.kind != FieldKind::array || (f.shape.size() != 2 && f.shape.size() != 3)) return false;
  for (auto e : f.shape) {
    if (e < 1 || e > max_side) return false;
  }
  for (const auto& x : f.ints) {
    if (x != 0 && x != 1) return false;
  }
  return true;
}

std::vector<std::int64_t> coords(const Domain& d, std::int64_t i) {
  std::vector<std::int64_t> c(static_cast<std::size_t>(d.dim()));
  for (int k = d.dim(); k-- > 0;) {
    c[static_cast<std::size_t>(k)] = i % d.extent(k);
    i /= d.extent(k);
  }
  return c;
}

// --- dt.l2.brute_force ------------------------------------------------------------------------

Record dt_generate(Rng& rng, const Params& params) {
  const int dim = rng.chance(3, 4) ? 2 : 3;
  const auto side = static_cast<std::int64_t>(dim == 2 ? params.max_size
                                                       : std::min<std::size_t>(params.max_size, 6));
  Field f = random_image(rng, dim, side);
  f.ints[rng.below(f.ints.size())] = 0; // at least one background point
  Record r;
  r.fields.push_back(std::move(f));
  return r;
}

bool dt_valid(const Record& c, const Params& params) {
  const Field& f = c.at("image");
  if (!image_shape_ok(f, params.max_size)) return false;
  for (const auto& x : f.ints) {
    if (x == 0) return true;
  }
  return false;
}

Record dt_request(const Record& c) {
  Record r = c;
  return r.text("metric", "l2");
}

// Squared distance to the nearest background point, over every pair: O(N^2).
Record dt_oracle(const Record& c) {
  const Field& f = c.at("image");
  const Image<std::uint8_t> img = image_of(f);
  const Domain& d = img.domain();
  std::vector<std::vector<std::int64_t>> bg;
  for (std::int64_t i = 0; i < img.size(); ++i) {
    if (img[i] == 0) bg.push_back(coords(d, i));
  }
  std::vector<BigInt> out;
  for (std::int64_t i = 0; i < img.size(); ++i) {
    const auto p = coords(d, i);
    std::int64_t best = -1;
    for (const auto& q : bg) {
      std::int64_t s = 0;
      for (std::size_t k = 0; k < p.size(); ++k) s += (p[k] - q[k]) * (p[k] - q[k]);
      if (best < 0 || s < best) best = s;
    }
    out.push_back(BigInt(best));
  }
  Record r;
  r.array("distances", shape_of(d), std::move(out), Shrink::none, true);
  return r;
}

Record dt_compute(const Record& c, IntKind) {
  const Image<std::uint8_t> img = image_of(c.at("image"));
  TransformOptions opt;
  opt.metric = Metric::l2();
  opt.threads = 1;
  const auto dt = distance_transform<std::int64_t>(img, opt);
  std::vector<BigInt> out;
  for (auto v : dt.values()) out.push_back(BigInt(v));
  Record r;
  r.array("distances", shape_of(img.domain()), std::move(out), Shrink::none, true);
  return r;
}

// --- betti.euler --------------------------------------------------------------------------------

const char* const kPairs[4] = {"8,4", "4,8", "26,6", "6,26"};

Record betti_generate(Rng& rng, const Params& params) {
  const int dim = rng.chance(1, 2) ? 2 : 3;
  const auto side = static_cast<std::int64_t>(dim == 2 ? params.max_size
                                                       : std::min<std::size_t>(params.max_size, 5));
  Record r;
  r.fields.push_back(random_image(rng, dim, side));
  r.text("adjacency", kPairs[(dim == 2 ? 0 : 2) + rng.below(2)]);
  return r;
}

bool betti_valid(const Record& c, const Params& params) {
  return image_shape_ok(c.at("image"), params.max_size);
}

// Components of {p in the box : member(p)} under k-adjacency (k = 4, 8 in 2D; 6, 26 in 3D),
// by breadth-first search; with `frame`, the box is first grown by one point on every side
// (outside the image: member) and the component holding the frame is not counted (bounded
// components of the background).
std::int64_t count_components_bfs(const Image<std::uint8_t>& img, int k, bool object, bool frame) {
  const Domain& d = img.domain();
  const int dim = d.dim();
  const std::int64_t pad = frame ? 1 : 0;
  std::vector<std::int64_t> ext;
  for (int a = 0; a < dim; ++a) ext.push_back(d.extent(a) + 2 * pad);
  const Domain big(ext);
  auto member = [&](const std::vector<std::int64_t>& p) {
    bool inside = true;
    std::int64_t i = 0;
    for (int a = 0; a < dim; ++a) {
      const std::int64_t x = p[static_cast<std::size_t>(a)] - pad;
      if (x < 0 || x >= d.extent(a)) inside = false;
      i = i * d.extent(a) + x;
    }
    if (!inside) return !object; // the frame is background
    return (img[i] != 0) == object;
  };
  std::vector<std::vector<std::int64_t>> offsets;
  const int max_l1 = k == 4 || k == 6 ? 1 : dim;
  for (std::int64_t m = 0; m < (dim == 2 ? 9 : 27); ++m) {
    std::vector<std::int64_t> o;
    std::int64_t t = m, l1 = 0;
    for (int a = 0; a < dim; ++a) {
      o.push_back(t % 3 - 1);
      l1 += std::llabs(o.back());
      t /= 3;
    }
    if (l1 >= 1 && l1 <= max_l1) offsets.push_back(o);
  }
  std::vector<std::int64_t> label(static_cast<std::size_t>(big.size()), -1);
  std::int64_t count = 0;
  for (std::int64_t s = 0; s < big.size(); ++s) {
    if (label[static_cast<std::size_t>(s)] >= 0 || !member(coords(big, s))) continue;
    const bool is_frame_component = frame && s == 0;
    std::vector<std::int64_t> stack = {s};
    label[static_cast<std::size_t>(s)] = s;
    while (!stack.empty()) {
      const auto p = coords(big, stack.back());
      stack.pop_back();
      for (const auto& o : offsets) {
        std::vector<std::int64_t> q = p;
        bool in = true;
        std::int64_t j = 0;
        for (int a = 0; a < dim; ++a) {
          q[static_cast<std::size_t>(a)] += o[static_cast<std::size_t>(a)];
          if (q[static_cast<std::size_t>(a)] < 0 ||
              q[static_cast<std::size_t>(a)] >= ext[static_cast<std::size_t>(a)])
            in = false;
          j = j * ext[static_cast<std::size_t>(a)] + q[static_cast<std::size_t>(a)];
        }
        if (!in || label[static_cast<std::size_t>(j)] >= 0 || !member(q)) continue;
        label[static_cast<std::size_t>(j)] = s;
        stack.push_back(j);
      }
    }
    if (!is_frame_component) ++count;
  }
  return count;
}

// chi of the cell complex of the pair (kernel/topology/betti_numbers.hpp), by counting its cells on
// the doubled grid: a cell has doubled coordinates c; for the union of closed unit cubes centred at
// the points (8,4 / 26,6) the cell is in the complex iff some point p with |2 p - c| <= 1 on every
// axis is in X, and its dimension is the number of even coordinates; for the complex on the points
// (4,8 / 6,26) the cell is in iff all its corners are in X, and its dimension is the number of odd
// coordinates. chi = sum of (-1)^dim.
std::int64_t euler_by_cells(const Image<std::uint8_t>& img, bool cubes) {
  const Domain& d = img.domain();
  const int dim = d.dim();
  std::vector<std::int64_t> lo(static_cast<std::size_t>(dim)), ext(static_cast<std::size_t>(dim));
  for (int a = 0; a < dim; ++a) {
    lo[static_cast<std::size_t>(a)] = -1;
    ext[static_cast<std::size_t>(a)] = 2 * d.extent(a) + 1;
  }
  const Domain cells(ext);
  auto in_x = [&](const std::vector<std::int64_t>& p) {
    std::int64_t i = 0;
    for (int a = 0; a < dim; ++a) {
      const std::int64_t x = p[static_cast<std::size_t>(a)];
      if (x < 0 || x >= d.extent(a)) return false;
      i = i * d.extent(a) + x;
    }
    return img[i] != 0;
  };
  std::int64_t chi = 0;
  for (std::int64_t s = 0; s < cells.size(); ++s) {
    auto c = coords(cells, s);
    int odd = 0;
    for (int a = 0; a < dim; ++a) {
      c[static_cast<std::size_t>(a)] += lo[static_cast<std::size_t>(a)];
      odd += (c[static_cast<std::size_t>(a)] & 1) != 0;
    }
    // The points p with |2 p - c| <= 1 on every axis: one per even axis, two per odd axis.
    bool any = false, all = true;
    for (int m = 0; m < (1 << odd); ++m) {
      std::vector<std::int64_t> p(static_cast<std::size_t>(dim));
      int bit = 0;
      for (int a = 0; a < dim; ++a) {
        const std::int64_t x = c[static_cast<std::size_t>(a)];
        if ((x & 1) == 0) {
          p[static_cast<std::size_t>(a)] = x / 2;
        } else {
          p[static_cast<std::size_t>(a)] = ((m >> bit++) & 1) != 0 ? (x + 1) / 2 : (x - 1) / 2;
        }
      }
      const bool in = in_x(p);
      any = any || in;
      all = all && in;
    }
    const int cell_dim = cubes ? dim - odd : odd;
    if (cubes ? any : all) chi += cell_dim % 2 == 0 ? 1 : -1;
  }
  return chi;
}

// The topology of the object by the oracles above: chi by cell counting, b0 by breadth-first
// search, the bounded background components (holes in 2D, cavities b2 in 3D: Alexander
// duality), and b1 = b0 + b2 - chi in 3D. Shared by betti.euler, skeleton.homotopic and
// surface.counts.
struct OracleTopology {
  std::int64_t euler = 0;
  std::vector<BigInt> betti; // b0, b1 (2D); b0, b1, b2 (3D)
};

OracleTopology topology_by_oracle(const Image<std::uint8_t>& img, const AdjacencyPair& pair) {
  const bool cubes = pair.object == 8 || pair.object == 26;
  OracleTopology t;
  t.euler = euler_by_cells(img, cubes);
  const std::int64_t b0 = count_components_bfs(img, pair.object, true, false);
  const std::int64_t bounded = count_components_bfs(img, pair.background, false, true);
  if (img.dim() == 2) {
    t.betti = {BigInt(b0), BigInt(bounded)};
  } else {
    t.betti = {BigInt(b0), BigInt(b0 + bounded - t.euler), BigInt(bounded)};
  }
  return t;
}

Record betti_oracle(const Record& c) {
  const Image<std::uint8_t> img = image_of(c.at("image"));
  const std::string& name = c.at("adjacency").texts.at(0);
  OracleTopology t = topology_by_oracle(img, parse_adjacency_pair(name, img.dim()));
  const std::size_t nb = t.betti.size();
  return Record()
      .text("adjacency", name)
      .integer("euler", BigInt(t.euler))
      .array("betti", {nb}, std::move(t.betti));
}

Record betti_compute(const Record& c, IntKind) {
  const Image<std::uint8_t> img = image_of(c.at("image"));
  const std::string& name = c.at("adjacency").texts.at(0);
  const AdjacencyPair pair = parse_adjacency_pair(name, img.dim());
  const BettiNumbers bn = betti_numbers(img, pair, 1);
  std::vector<BigInt> b;
  for (int k = 0; k < img.dim(); ++k) b.push_back(BigInt(bn.b[static_cast<std::size_t>(k)]));
  const std::size_t nb = b.size();
  return Record()
      .text("adjacency", pair.name())
      .integer("euler", BigInt(bn.euler))
      .array("betti", {nb}, std::move(b));
}

// In 2D, chi = b0 - b1 on any answer (Euler-Poincare); in 3D chi = b0 - b1 + b2.
std::optional<std::string> betti_judge(const Record&, const Record&, const Record& got) {
  if (!got.has("euler") || !got.has("betti")) return std::nullopt;
  const auto& b = got.at("betti").ints;
  if (b.size() < 2) return "betti has fewer than two numbers";
  BigInt alt = b[0] - b[1] + (b.size() > 2 ? b[2] : BigInt(0));
  if (alt != got.int_of("euler")) {
    return "Euler-Poincare fails on the answer: b0 - b1 + b2 = " + alt.str() +
           " but euler = " + got.int_of("euler").str();
  }
  return std::nullopt;
}

bool simple_by_yokoi(int object_adjacency, std::uint32_t config);

// --- voronoi.l2.nearest ---------------------------------------------------------------------

// Squared distances to the nearest background point, and the first such point (by index).
struct Nearest {
  std::vector<std::int64_t> d2, site;
};

Nearest nearest_background(const Image<std::uint8_t>& img) {
  const Domain& d = img.domain();
  std::vector<std::int64_t> bg;
  for (std::int64_t i = 0; i < img.size(); ++i) {
    if (img[i] == 0) bg.push_back(i);
  }
  Nearest n;
  for (std::int64_t i = 0; i < img.size(); ++i) {
    const auto p = coords(d, i);
    std::int64_t best = -1, at = -1;
    for (auto j : bg) {
      const auto q = coords(d, j);
      std::int64_t s = 0;
      for (std::size_t k = 0; k < p.size(); ++k) s += (p[k] - q[k]) * (p[k] - q[k]);
      if (best < 0 || s < best) {
        best = s;
        at = j;
      }
    }
    n.d2.push_back(best);
    n.site.push_back(at);
  }
  return n;
}

std::vector<std::size_t> sites_shape(const Domain& d) {
  auto s = shape_of(d);
  s.push_back(static_cast<std::size_t>(d.dim()));
  return s;
}

Record voronoi_oracle(const Record& c) {
  const Image<std::uint8_t> img = image_of(c.at("image"));
  const Nearest n = nearest_background(img);
  std::vector<BigInt> out;
  for (auto j : n.site) {
    for (auto x : coords(img.domain(), j)) out.push_back(BigInt(x));
  }
  Record r;
  r.array("sites", sites_shape(img.domain()), std::move(out), Shrink::none, true);
  r.at("sites").judged = true; // any nearest background point is right
  return r;
}

Record voronoi_compute(const Record& c, IntKind) {
  const Image<std::uint8_t> img = image_of(c.at("image"));
  TransformOptions opt;
  opt.metric = Metric::l2();
  opt.threads = 1;
  const VoronoiMap v = voronoi_map(img, opt);
  std::vector<BigInt> out;
  for (std::int64_t i = 0; i < img.size(); ++i) {
    for (auto x : v.site_point(i)) out.push_back(BigInt(x));
  }
  Record r;
  r.array("sites", sites_shape(img.domain()), std::move(out), Shrink::none, true);
  return r;
}

// Every point's site is a background point of the image at the smallest squared distance.
std::optional<std::string> voronoi_judge(const Record& c, const Record&, const Record& got) {
  if (!got.has("sites")) return std::nullopt; // reported as a missing field
  const Image<std::uint8_t> img = image_of(c.at("image"));
  const Domain& d = img.domain();
  const Field& f = got.at("sites");
  if (f.shape != sites_shape(d)) return "sites has not the shape (image shape, dimension)";
  const Nearest n = nearest_background(img);
  const auto dim = static_cast<std::size_t>(d.dim());
  for (std::int64_t i = 0; i < img.size(); ++i) {
    const auto p = coords(d, i);
    std::int64_t j = 0, s = 0;
    std::string at = "(";
    for (std::size_t k = 0; k < dim; ++k) {
      const BigInt& x = f.ints[static_cast<std::size_t>(i) * dim + k];
      at += (k > 0 ? ", " : "") + x.str();
      if (x < 0 || x >= d.extent(static_cast<int>(k))) {
        return "the site of point " + std::to_string(i) + " is outside the image";
      }
      const std::int64_t xi = x.convert_to<std::int64_t>();
      j = j * d.extent(static_cast<int>(k)) + xi;
      s += (xi - p[k]) * (xi - p[k]);
    }
    at += ")";
    if (img[j] != 0) {
      return "the site " + at + " of point " + std::to_string(i) + " is an object point";
    }
    if (s != n.d2[static_cast<std::size_t>(i)]) {
      return "the site " + at + " of point " + std::to_string(i) + " is at squared distance " +
             std::to_string(s) + ", the nearest background point at " +
             std::to_string(n.d2[static_cast<std::size_t>(i)]);
    }
  }
  return std::nullopt;
}

// --- skeleton.homotopic -----------------------------------------------------------------------

Record skeleton_generate(Rng& rng, const Params& params) {
  const int dim = rng.chance(2, 3) ? 2 : 3;
  const auto side = static_cast<std::int64_t>(dim == 2 ? params.max_size
                                                       : std::min<std::size_t>(params.max_size, 5));
  Record r;
  r.fields.push_back(random_image(rng, dim, side));
  r.text("adjacency", kPairs[(dim == 2 ? 0 : 2) + rng.below(2)]);
  r.text("skeleton", rng.chance(1, 2) ? "ultimate" : "curve");
  return r;
}

bool skeleton_valid(const Record& c, const Params& params) {
  if (!image_shape_ok(c.at("image"), params.max_size)) return false;
  const auto& s = c.at("skeleton").texts.at(0);
  return s == "ultimate" || s == "curve";
}

std::vector<BigInt> values_of(const Image<std::uint8_t>& img) {
  std::vector<BigInt> v;
  for (auto x : img.values()) v.push_back(BigInt(x != 0 ? 1 : 0));
  return v;
}

// The answer's skeleton is judged against the object (its reference value); its Betti numbers
// as the command reports them must be the object's.
Record skeleton_oracle(const Record& c) {
  const Image<std::uint8_t> img = image_of(c.at("image"));
  const AdjacencyPair pair = parse_adjacency_pair(c.at("adjacency").texts.at(0), img.dim());
  auto b = topology_by_oracle(img, pair).betti;
  const std::size_t nb = b.size();
  Record r;
  r.array("skeleton", shape_of(img.domain()), values_of(img), Shrink::none, true);
  r.at("skeleton").judged = true;
  return r.array("betti", {nb}, std::move(b));
}

Record skeleton_compute(const Record& c, IntKind) {
  const Image<std::uint8_t> img = image_of(c.at("image"));
  ThinningOptions opt;
  opt.pair = parse_adjacency_pair(c.at("adjacency").texts.at(0), img.dim());
  opt.skeleton = parse_skeleton_kind(c.at("skeleton").texts.at(0));
  opt.threads = 1;
  const ThinningResult t = homotopic_thinning(img, opt);
  const BettiNumbers bn = betti_numbers(t.skeleton, opt.pair, 1);
  std::vector<BigInt> b;
  for (int k = 0; k < img.dim(); ++k) b.push_back(BigInt(bn.b[static_cast<std::size_t>(k)]));
  const std::size_t nb = b.size();
  Record r;
  r.array("skeleton", shape_of(img.domain()), values_of(t.skeleton), Shrink::none, true);
  return r.array("betti", {nb}, std::move(b));
}

// The configuration of point i of a 2D or 3D image (bits of kernel/topology/simple_points.hpp;
// outside: background), read here point by point.
std::uint32_t configuration_at(const Image<std::uint8_t>& img, std::int64_t i) {
  const Domain& d = img.domain();
  const int dim = d.dim();
  const auto p = coords(d, i);
  std::uint32_t config = 0;
  for (int m = 0; m < (dim == 2 ? 9 : 27); ++m) {
    int o[3] = {0, 0, 0};
    int t = m;
    for (int a = 0; a < dim; ++a) {
      o[a] = t % 3 - 1;
      t /= 3;
    }
    if (o[0] == 0 && o[1] == 0 && o[2] == 0) continue;
    std::int64_t j = 0;
    bool inside = true;
    for (int a = 0; a < dim; ++a) {
      const std::int64_t x = p[static_cast<std::size_t>(a)] + o[a];
      if (x < 0 || x >= d.extent(a)) inside = false;
      j = j * d.extent(a) + x;
    }
    if (inside && img[j] != 0) config |= std::uint32_t{1} << neighbour_bit(dim, o[0], o[1], o[2]);
  }
  return config;
}

// Homotopic thinning keeps the topology (the Betti numbers of the skeleton, by the oracles, are
// the object's), stays in the object, and leaves no deletable point: every point is not simple
// (2D: Yokoi's number; 3D: the topological numbers), or, for a curve skeleton, an end point
// (exactly one object point among its 3^d - 1 neighbours).
std::optional<std::string> skeleton_judge(const Record& c, const Record& expected,
                                          const Record& got) {
  if (!got.has("skeleton")) return std::nullopt;
  const Field& object = c.at("image");
  const Field& f = got.at("skeleton");
  if (f.shape != object.shape) return "the skeleton has not the image's shape";
  for (std::size_t i = 0; i < f.ints.size(); ++i) {
    if (f.ints[i] != 0 && f.ints[i] != 1) return "the skeleton is not a 0/1 image";
    if (f.ints[i] == 1 && object.ints[i] == 0) {
      return "point " + std::to_string(i) + " of the skeleton is not in the object";
    }
  }
  Field g = f;
  g.name = "image";
  const Image<std::uint8_t> skel = image_of(g);
  const AdjacencyPair pair = parse_adjacency_pair(c.at("adjacency").texts.at(0), skel.dim());
  const auto b = topology_by_oracle(skel, pair).betti;
  if (b != expected.at("betti").ints) {
    std::string t;
    for (const auto& x : b) t += (t.empty() ? "" : " ") + x.str();
    return "the skeleton's Betti numbers (by the oracle) are " + t + ", not the object's";
  }
  const bool curve = c.at("skeleton").texts.at(0) == "curve";
  for (std::int64_t i = 0; i < skel.size(); ++i) {
    if (skel[i] == 0) continue;
    const std::uint32_t config = configuration_at(skel, i);
    if (curve && __builtin_popcount(config) == 1) continue; // an end point
    const bool simple = skel.dim() == 2 ? simple_by_yokoi(pair.object, config)
                                        : is_simple_by_definition(pair, config);
    if (simple) {
      return "point " + std::to_string(i) + " of the skeleton is simple: thinning could go on";
    }
  }
  return std::nullopt;
}

// --- surface.counts ----------------------------------------------------------------------------

// A 3D image: random voxels, or a union of one to three boxes (whose boundaries are mostly free
// of pinches, where the border theorem applies), with at least one object voxel.
Record surface_generate(Rng& rng, const Params& params) {
  const auto side = static_cast<std::int64_t>(params.max_size);
  Field f;
  if (rng.chance(1, 2)) {
    f = random_image(rng, 3, side);
  } else {
    f.name = "image";
    f.kind = FieldKind::array;
    f.numbers = true;
    f.shrink = Shrink::image;
    for (int k = 0; k < 3; ++k) f.shape.push_back(static_cast<std::size_t>(rng.range(1, side)));
    f.ints.assign(shape_size(f.shape), BigInt(0));
    const auto boxes = rng.range(1, 3);
    for (std::int64_t b = 0; b < boxes; ++b) {
      std::int64_t lo[3], hi[3];
      for (int k = 0; k < 3; ++k) {
        const auto e = static_cast<std::int64_t>(f.shape[static_cast<std::size_t>(k)]);
        lo[k] = rng.range(0, e - 1);
        hi[k] = rng.range(lo[k], e - 1);
      }
      for (std::int64_t z = lo[0]; z <= hi[0]; ++z)
        for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
          for (std::int64_t x = lo[2]; x <= hi[2]; ++x)
            f.ints[static_cast<std::size_t>((z * static_cast<std::int64_t>(f.shape[1]) + y) *
                                                static_cast<std::int64_t>(f.shape[2]) +
                                            x)] = 1;
    }
  }
  f.ints[rng.below(f.ints.size())] = 1;
  Record r;
  r.fields.push_back(std::move(f));
  r.text("adjacency", kPairs[2 + rng.below(2)]);
  return r;
}

bool surface_valid(const Record& c, const Params& params) {
  const Field& f = c.at("image");
  if (!image_shape_ok(f, params.max_size) || f.shape.size() != 3) return false;
  for (const auto& x : f.ints) {
    if (x != 0) return true;
  }
  return false;
}

const std::vector<std::string> kComponentColumns = {"euler", "surfaces", "surfels", "voxels"};

struct SurfaceTruth {
  std::int64_t surfels = 0, voxels = 0, pinched = 0, borders = 0, euler = 0;
  std::vector<BigInt> betti;
};

// Everything by brute force on the padded image (outside: background): surfels are the
// (object, background) face-adjacent pairs; a pinched pointel is a 2x2x2 block whose object
// (pair 26,6) or background (6,26) is exactly two opposite voxels; the borders are the
// face-adjacent pairs (k-component of X, kbar-component of the complement).
SurfaceTruth surface_truth(const Image<std::uint8_t>& img, const AdjacencyPair& pair) {
  const Domain& d = img.domain();
  const std::int64_t n0 = d.extent(0) + 2, n1 = d.extent(1) + 2, n2 = d.extent(2) + 2;
  const Domain big({n0, n1, n2});
  std::vector<std::uint8_t> in(static_cast<std::size_t>(big.size()), 0);
  for (std::int64_t i = 0; i < img.size(); ++i) {
    const auto p = coords(d, i);
    if (img[i] != 0) in[static_cast<std::size_t>(((p[0] + 1) * n1 + p[1] + 1) * n2 + p[2] + 1)] = 1;
  }
  // Components of X (k) and of the complement (kbar) on the padded box.
  auto label = [&](bool object, int k) {
    std::vector<std::int64_t> lab(in.size(), -1);
    std::int64_t count = 0;
    for (std::int64_t s = 0; s < big.size(); ++s) {
      if (lab[static_cast<std::size_t>(s)] >= 0 || (in[static_cast<std::size_t>(s)] != 0) != object)
        continue;
      std::vector<std::int64_t> stack = {s};
      lab[static_cast<std::size_t>(s)] = count;
      while (!stack.empty()) {
        const auto p = coords(big, stack.back());
        stack.pop_back();
        for (int m = 0; m < 27; ++m) {
          const std::int64_t o[3] = {m / 9 - 1, m / 3 % 3 - 1, m % 3 - 1};
          const auto l1 = std::llabs(o[0]) + std::llabs(o[1]) + std::llabs(o[2]);
          if (l1 == 0 || (k == 6 && l1 > 1)) continue;
          const std::int64_t q0 = p[0] + o[0], q1 = p[1] + o[1], q2 = p[2] + o[2];
          if (q0 < 0 || q1 < 0 || q2 < 0 || q0 >= n0 || q1 >= n1 || q2 >= n2) continue;
          const auto j = static_cast<std::size_t>((q0 * n1 + q1) * n2 + q2);
          if (lab[j] >= 0 || (in[j] != 0) != object) continue;
          lab[j] = count;
          stack.push_back(static_cast<std::int64_t>(j));
        }
      }
      ++count;
    }
    return lab;
  };
  const auto lx = label(true, pair.object), lb = label(false, pair.background);
  SurfaceTruth t;
  std::set<std::pair<std::int64_t, std::int64_t>> borders;
  for (std::int64_t s = 0; s < big.size(); ++s) {
    if (in[static_cast<std::size_t>(s)] == 0) continue;
    ++t.voxels;
    const auto p = coords(big, s);
    for (int a = 0; a < 3; ++a) {
      for (int sg : {-1, 1}) {
        auto q = p;
        q[static_cast<std::size_t>(a)] += sg;
        const auto j = static_cast<std::size_t>((q[0] * n1 + q[1]) * n2 + q[2]);
        if (in[j] != 0) continue;
        ++t.surfels;
        borders.insert({lx[static_cast<std::size_t>(s)], lb[j]});
      }
    }
  }
  t.borders = static_cast<std::int64_t>(borders.size());
  const bool object_pinches = pair.object == 26;
  for (std::int64_t z = 0; z + 1 < n0; ++z) {
    for (std::int64_t y = 0; y + 1 < n1; ++y) {
      for (std::int64_t x = 0; x + 1 < n2; ++x) {
        std::vector<int> members;
        for (int m = 0; m < 8; ++m) {
          const auto j = static_cast<std::size_t>(((z + (m >> 2)) * n1 + y + ((m >> 1) & 1)) * n2 +
                                                  x + (m & 1));
          if ((in[j] != 0) == object_pinches) members.push_back(m);
        }
        if (members.size() == 2 && (members[0] ^ members[1]) == 7) ++t.pinched;
      }
    }
  }
  const OracleTopology topo = topology_by_oracle(img, pair);
  t.betti = topo.betti;
  t.euler = topo.euler;
  return t;
}

Record surface_oracle(const Record& c) {
  const Image<std::uint8_t> img = image_of(c.at("image"));
  const AdjacencyPair pair = parse_adjacency_pair(c.at("adjacency").texts.at(0), 3);
  const SurfaceTruth t = surface_truth(img, pair);
  const BigInt chi(t.euler);
  Record r;
  r.text("adjacency", pair.name());
  r.integer("surfels", BigInt(t.surfels));
  r.integer("euler", chi);
  r.array("betti", {3}, t.betti);
  r.integer("pinched_pointels", BigInt(t.pinched));
  // Judged: without pinched pointels, one surface per border (Herman's theorem); with them,
  // at least one surface per border (a pinch may split a border's surface or not).
  r.integer("surfaces", BigInt(t.borders));
  r.at("surfaces").judged = true;
  // Judged: the sums of the per-component rows (one reference row of totals).
  r.array("components", {1, 4},
          {BigInt(2) * chi + BigInt(2 * t.pinched), BigInt(t.borders), BigInt(t.surfels),
           BigInt(t.voxels)});
  r.at("components").columns = kComponentColumns;
  r.at("components").judged = true;
  return r;
}

Record surface_compute(const Record& c, IntKind) {
  const Image<std::uint8_t> img = image_of(c.at("image"));
  const AdjacencyPair pair = parse_adjacency_pair(c.at("adjacency").texts.at(0), 3);
  const ImageSurfels sf = image_surfels(img, 1);
  const ImageSurfaces ss = image_surfaces(img, sf, SurfaceConvention::of(pair), 1);
  const BettiNumbers bn = betti_numbers(img, pair, 1);
  std::int64_t euler_sum = 0, voxels = 0;
  for (auto v : img.values()) voxels += v != 0 ? 1 : 0;
  for (const auto& s : ss.surfaces) euler_sum += s.euler;
  const auto nsurf = static_cast<std::int64_t>(ss.surfaces.size());
  Record r;
  r.text("adjacency", pair.name());
  r.integer("surfels", BigInt(static_cast<std::int64_t>(sf.codes.size())));
  r.integer("euler", BigInt(bn.euler));
  r.array("betti", {3}, {BigInt(bn.b[0]), BigInt(bn.b[1]), BigInt(bn.b[2])});
  r.integer("pinched_pointels", BigInt(ss.pinched_pointels));
  r.integer("surfaces", BigInt(nsurf));
  // One row for the whole object: the per-component split is the command's business.
  r.array("components", {1, 4},
          {BigInt(euler_sum), BigInt(nsurf), BigInt(static_cast<std::int64_t>(sf.codes.size())),
           BigInt(voxels)});
  r.at("components").columns = kComponentColumns;
  return r;
}

std::optional<std::string> surface_judge(const Record&, const Record& expected, const Record& got) {
  if (got.has("components")) {
    const Field& rows = got.at("components");
    const Field& ref = expected.at("components");
    BigInt sums[4] = {0, 0, 0, 0};
    for (std::size_t i = 0; i < rows.shape[0]; ++i) {
      for (std::size_t k = 0; k < 4; ++k) sums[k] += rows.ints[i * 4 + k];
    }
    const char* what[4] = {"Euler characteristics (2 chi(X) + 2 pinched pointels)", "surfaces",
                           "surfels", "voxels"};
    for (std::size_t k = 0; k < 4; ++k) {
      if (k == 1) continue; // judged with the surfaces below
      if (sums[k] != ref.ints[k]) {
        return std::string("the components' ") + what[k] + " sum to " + sums[k].str() +
               ", the oracle says " + ref.ints[k].str();
      }
    }
    if (got.has("surfaces") && sums[1] != got.int_of("surfaces")) {
      return "the components' surfaces sum to " + sums[1].str() +
             ", not to surfaces = " + got.int_of("surfaces").str();
    }
  }
  if (got.has("surfaces")) {
    const BigInt& n = got.int_of("surfaces");
    const BigInt& borders = expected.int_of("surfaces");
    const bool pinched = expected.int_of("pinched_pointels") != 0;
    if (pinched ? n < borders : n != borders) {
      return "surfaces = " + n.str() +
             " but the (object, background) component pairs that touch "
             "are " +
             borders.str() + (pinched ? " (at least that many surfaces)" : "");
    }
  }
  return std::nullopt;
}

// --- simple_point.lut ---------------------------------------------------------------------------

// Yokoi, Toriwaki and Fukumura (CGIP 4, 1975): with x_1 .. x_8 the 8 neighbours in cyclic order
// starting at an axis neighbour, N^4 = sum_{k odd} (x_k - x_k x_{k+1} x_{k+2}) and N^8 the same
// on complemented values; the centre (in the object) is simple iff N = 1 for the object's
// adjacency.
bool simple_by_yokoi(int object_adjacency, std::uint32_t config) {
  static const int ring[8][2] = {{1, 0},  {1, 1},   {0, 1},  {-1, 1},
                                 {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
  int x[9];
  for (int k = 0; k < 8; ++k) {
    int v = (config >> neighbour_bit(2, ring[k][0], ring[k][1])) & 1u;
    x[k] = object_adjacency == 8 ? 1 - v : v;
  }
  x[8] = x[0];
  int n = 0;
  for (int k = 0; k < 8; k += 2) n += x[k] - x[k] * x[k + 1] * x[(k + 2) % 8];
  return n == 1;
}

Record simple_generate(Rng& rng, const Params&) {
  return Record()
      .integer("configuration", BigInt(rng.below(256)), Shrink::toward_zero)
      .text("adjacency", rng.chance(1, 2) ? "8,4" : "4,8");
}

bool simple_valid(const Record& c, const Params&) {
  const BigInt& v = c.int_of("configuration");
  return v >= 0 && v < 256;
}

std::optional<std::string> simple_holds(const Record& c, IntKind) {
  const AdjacencyPair pair = parse_adjacency_pair(c.at("adjacency").texts.at(0), 2);
  const auto config = static_cast<std::uint32_t>(c.i64_of("configuration"));
  const bool lut = SimplePointTable::of(pair).simple(config);
  const bool yokoi = simple_by_yokoi(pair.object, config);
  const bool definition = is_simple_by_definition(pair, config);
  if (lut != yokoi || definition != yokoi) {
    return "configuration " + std::to_string(config) + " under (" + pair.name() + "): table says " +
           (lut ? "simple" : "not simple") + ", definition " +
           (definition ? "simple" : "not simple") + ", Yokoi's number " +
           (yokoi ? "simple" : "not simple");
  }
  return std::nullopt;
}

} // namespace

void add_image_properties(std::vector<Property>& out) {
  {
    Property p;
    p.name = "dt.l2.brute_force";
    p.theorem = "the squared Euclidean distance transform of a binary image (separable exact "
                "transform) equals min over the background points of the squared distance";
    p.source = "oracle: every pair of points (brute force); algorithm: Saito and Toriwaki 1994, "
               "Meijster, Roerdink and Hesselink 2000";
    p.operation = "transform dt";
    p.sizes = "image side <= max-size (3D images: <= 6); bits unused";
    p.cost = Cost::moderate;
    p.types = {IntKind::int64};
    p.uses_bits = false;
    p.default_max_size = 12;
    p.max_max_size = 64;
    p.generate = dt_generate;
    p.valid = dt_valid;
    p.request = dt_request;
    p.oracle = dt_oracle;
    p.compute = dt_compute;
    out.push_back(std::move(p));
  }
  {
    Property p;
    p.name = "betti.euler";
    p.theorem = "b0 is the number of k-components, b2 (3D) or b1 (2D) the bounded kbar-"
                "components of the background (Alexander duality), and chi = b0 - b1 + b2 is "
                "the alternating cell count of the complex of the pair (8,4 4,8 26,6 6,26)";
    p.source = "oracle: breadth-first search and cell counting on the doubled grid; Kong and "
               "Rosenfeld, CVGIP 48 (1989); Lee, Poston and Rosenfeld, CVGIP: GMIP 53 (1991)";
    p.operation = "topology betti";
    p.sizes = "image side <= max-size (3D images: <= 5); bits unused";
    p.cost = Cost::moderate;
    p.types = {IntKind::int64};
    p.uses_bits = false;
    p.default_max_size = 8;
    p.max_max_size = 32;
    p.generate = betti_generate;
    p.valid = betti_valid;
    p.oracle = betti_oracle;
    p.compute = betti_compute;
    p.judge = betti_judge;
    out.push_back(std::move(p));
  }
  {
    Property p;
    p.name = "voronoi.l2.nearest";
    p.theorem = "the discrete Voronoi map of the background (separable exact transform) gives "
                "every point a background point at the smallest squared Euclidean distance "
                "(any of them among ties)";
    p.source = "oracle: every pair of points (brute force); algorithm: Maurer, Qi and Raghavan, "
               "PAMI 25 (2003); Breu, Gil, Kirkpatrick and Werman, PAMI 17 (1995)";
    p.operation = "transform voronoi";
    p.sizes = "image side <= max-size (3D images: <= 6); bits unused";
    p.cost = Cost::moderate;
    p.types = {IntKind::int64};
    p.uses_bits = false;
    p.default_max_size = 12;
    p.max_max_size = 64;
    p.generate = dt_generate;
    p.valid = dt_valid;
    p.request = dt_request;
    p.oracle = voronoi_oracle;
    p.compute = voronoi_compute;
    p.judge = voronoi_judge;
    out.push_back(std::move(p));
  }
  {
    Property p;
    p.name = "skeleton.homotopic";
    p.theorem = "homotopic thinning (ultimate or curve skeleton) returns a subset of the object "
                "with the object's Betti numbers in which no point is simple, except the end "
                "points of a curve skeleton";
    p.source = "oracle: Betti numbers by breadth-first search and cell counting, simplicity by "
               "Yokoi's number (2D) and topological numbers (3D); algorithm: Pudney, CVIU 72 "
               "(1998); Bertrand, PRL 15 (1994)";
    p.operation = "topology skeleton";
    p.sizes = "image side <= max-size (3D images: <= 5); bits unused";
    p.cost = Cost::moderate;
    p.types = {IntKind::int64};
    p.uses_bits = false;
    p.default_max_size = 10;
    p.max_max_size = 32;
    p.generate = skeleton_generate;
    p.valid = skeleton_valid;
    p.oracle = skeleton_oracle;
    p.compute = skeleton_compute;
    p.judge = skeleton_judge;
    out.push_back(std::move(p));
  }
  {
    Property p;
    p.name = "surface.counts";
    p.theorem = "the boundary of a 3D object has as many surfels as (object, background) face "
                "pairs; its closed surfaces, one per touching pair (k-component, kbar-component) "
                "when no pointel is pinched (Herman), have Euler characteristics summing to "
                "2 chi(X) + 2 (pinched pointels); b0, b1, b2 and chi are the object's";
    p.source = "oracle: face pairs, components and 2x2x2 blocks by brute force, Betti numbers as "
               "betti.euler; Herman, CVGIP: Graphical Models 54 (1992); Kong and Rosenfeld, "
               "CVGIP 48 (1989); Lachaud and Montanvert, Graphical Models 62 (2000)";
    p.operation = "surface";
    p.sizes = "3D image side <= max-size; pairs 6,26 and 26,6; bits unused";
    p.cost = Cost::moderate;
    p.types = {IntKind::int64};
    p.uses_bits = false;
    p.default_max_size = 4;
    p.max_max_size = 12;
    p.generate = surface_generate;
    p.valid = surface_valid;
    p.oracle = surface_oracle;
    p.compute = surface_compute;
    p.judge = surface_judge;
    out.push_back(std::move(p));
  }
  {
    Property p;
    p.name = "simple_point.lut";
    p.theorem = "the 2D simple-point table and the definition by topological numbers agree with "
                "Yokoi's connectivity number (simple iff N = 1) on every 3x3 configuration";
    p.source = "oracle: Yokoi, Toriwaki and Fukumura, CGIP 4 (1975); Bertrand, PRL 15 (1994)";
    p.sizes = "one 3x3 configuration (0..255); max-size and bits unused";
    p.cost = Cost::cheap;
    p.types = {IntKind::int64};
    p.uses_bits = false;
    p.default_max_size = 1;
    p.generate = simple_generate;
    p.valid = simple_valid;
    p.holds = simple_holds;
    out.push_back(std::move(p));
  }
}

} // namespace zdg::check
