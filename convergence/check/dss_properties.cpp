// The digital straight segment family of zdg check: recognition of paths and subsegments of
// digital straight lines, against a brute-force search of the minimal line.
#include <zdg/arith/dsl_subsegment.hpp>
#include <zdg/arith/dss_recognizer.hpp>
#include <zdg/convergence/check/property.hpp>
#include <zdg/kernel/curves/maximal_segments.hpp>

#include <array>
#include <cstdlib>
#include <numeric>
#include <optional>
#include <set>
#include <span>
#include <vector>

namespace zdg::check {

namespace {

using Local = std::array<std::int64_t, 2>;

struct BruteDss {
  std::int64_t a = 0, b = 1, lo = 0, omega = 1;
};

// The minimal characteristics of a path of distinct points given relative to its first point
// (nullopt when it is not a DSS or repeats a point): the smallest period omega (max(|a|, |b|)
// for 8-connected paths, |a| + |b| for 4-connected ones) of a line a x - b y in [lo, lo +
// omega) with gcd(a, b) = 1 containing every point, oriented by the path ((b, a) . (last -
// first) > 0). O(n omega^2) per period tried, omega <= 2 n + 2.
std::optional<BruteDss> brute_dss(const std::vector<Local>& pts, int conn) {
  std::set<Local> seen(pts.begin(), pts.end());
  if (seen.size() != pts.size()) return std::nullopt;
  if (pts.size() == 1) return BruteDss{0, 1, -pts[0][1], 1}; // every line of period 1
  const std::int64_t dx = pts.back()[0] - pts.front()[0], dy = pts.back()[1] - pts.front()[1];
  const auto max_omega = static_cast<std::int64_t>(2 * pts.size() + 2);
  for (std::int64_t om = 1; om <= max_omega; ++om) {
    for (std::int64_t a = -om; a <= om; ++a) {
      for (std::int64_t b = -om; b <= om; ++b) {
        const std::int64_t w =
            conn == 8 ? std::max(std::llabs(a), std::llabs(b)) : std::llabs(a) + std::llabs(b);
        if (w != om || std::gcd(a, b) != 1 || b * dx + a * dy <= 0) continue;
        std::int64_t lo = 0, hi = 0;
        for (std::size_t k = 0; k < pts.size(); ++k) {
          const std::int64_t r = a * pts[k][0] - b * pts[k][1];
          if (k == 0 || r < lo) lo = r;
          if (k == 0 || r > hi) hi = r;
        }
        if (hi - lo < om) return BruteDss{a, b, lo, om};
      }
    }
  }
  return std::nullopt;
}

std::vector<Point2<BigInt>> path_of(const Record& c) {
  const Field& f = c.at("points");
  std::vector<Point2<BigInt>> pts;
  for (std::size_t k = 0; k < f.shape[0]; ++k) pts.push_back({f.ints[2 * k], f.ints[2 * k + 1]});
  return pts;
}

// Relative coordinates; nullopt when a difference leaves int64 (never for valid paths).
std::vector<Local> local_of(const std::vector<Point2<BigInt>>& pts) {
  std::vector<Local> out;
  for (const auto& p : pts) {
    out.push_back({int_cast<Int64>(BigInt(p.x - pts[0].x)).value(),
                   int_cast<Int64>(BigInt(p.y - pts[0].y)).value()});
  }
  return out;
}

// --- dss.recognize.minimal -----------------------------------------------------------------

// The two steps of an octant (8: an axis step and a diagonal next to it; 4: two orthogonal
// axis steps), chosen at random.
std::pair<Local, Local> random_steps(Rng& rng, int conn) {
  static const Local axes[4] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  const int k = static_cast<int>(rng.below(4));
  const Local e = axes[k], f = axes[(k + (rng.chance(1, 2) ? 1 : 3)) % 4];
  if (conn == 4) return {e, f};
  return {e, Local{e[0] + f[0], e[1] + f[1]}};
}

Record dss_generate(Rng& rng, const Params& params) {
  const int conn = rng.chance(1, 2) ? 4 : 8;
  const auto n = static_cast<std::size_t>(rng.range(1, static_cast<std::int64_t>(params.max_size)));
  auto [s0, s1] = random_steps(rng, conn);
  const std::uint64_t mode = rng.below(10);
  // A digital line pattern: letter i = floor(((i+1) p + c) / (p+q)) - floor((i p + c) / (p+q)).
  const std::int64_t q = rng.range(1, 2 * static_cast<std::int64_t>(params.max_size));
  const std::int64_t p = rng.range(0, q), c = rng.range(0, p + q - 1);
  std::vector<BigInt> flat = {rng.edgy(params.bits), rng.edgy(params.bits)};
  for (std::size_t i = 1; i < n; ++i) {
    Local s;
    if (mode < 6) {
      const auto ii = static_cast<std::int64_t>(i - 1);
      s = ((ii + 1) * p + c) / (p + q) - (ii * p + c) / (p + q) == 1 ? s1 : s0;
    } else if (mode < 9) {
      s = rng.chance(1, 2) ? s1 : s0;
    } else {
      s = random_steps(rng, conn).first;
    }
    flat.push_back(flat[flat.size() - 2] + s[0]);
    flat.push_back(flat[flat.size() - 2] + s[1]);
  }
  return Record()
      .array("points", {n, 2}, std::move(flat), Shrink::path)
      .integer("connectivity", BigInt(conn));
}

bool dss_valid(const Record& c, const Params& params) {
  const Field& f = c.at("points");
  const int conn = static_cast<int>(c.i64_of("connectivity"));
  if (f.shape.size() != 2 || f.shape[0] < 1 || f.shape[0] > params.max_size) return false;
  for (std::size_t k = 1; k < f.shape[0]; ++k) {
    BigInt dx = abs(BigInt(f.ints[2 * k] - f.ints[2 * k - 2]));
    BigInt dy = abs(BigInt(f.ints[2 * k + 1] - f.ints[2 * k - 1]));
    const bool ok = conn == 4 ? dx + dy == 1 : (dx <= 1 && dy <= 1 && dx + dy >= 1);
    if (!ok) return false;
  }
  return true;
}

Record dss_characteristics(const BruteDss& d, const Point2<BigInt>& origin) {
  return Record()
      .integer("a", BigInt(d.a))
      .integer("b", BigInt(d.b))
      .integer("mu", BigInt(d.lo) + BigInt(d.a) * origin.x - BigInt(d.b) * origin.y)
      .integer("omega", BigInt(d.omega));
}

Record dss_oracle(const Record& c) {
  const auto pts = path_of(c);
  const auto local = local_of(pts);
  const int conn = static_cast<int>(c.i64_of("connectivity"));
  Record r;
  if (auto d = brute_dss(local, conn)) {
    r.boolean("is_dss", true).integer("connectivity", BigInt(conn));
    // In absolute coordinates mu = lo + a x0 - b y0 (one point: -y0).
    for (auto& f : dss_characteristics(*d, pts[0]).fields) r.fields.push_back(f);
    return r;
  }
  // Being a DSS is inherited by sub-paths: the longest DSS prefix by a downward scan.
  std::size_t k = local.size() - 1;
  while (k > 1 && !brute_dss(std::vector<Local>(local.begin(),
                                                local.begin() + static_cast<std::ptrdiff_t>(k)),
                             conn)) {
    --k;
  }
  return r.boolean("is_dss", false)
      .integer("connectivity", BigInt(conn))
      .integer("longest_prefix", BigInt(static_cast<std::int64_t>(k)));
}

Record dss_compute(const Record& c, IntKind type) {
  const auto pts = path_of(c);
  const Connectivity conn =
      c.i64_of("connectivity") == 4 ? Connectivity::four : Connectivity::eight;
  auto r = escalate_from(type, [&]<class I>(std::type_identity<I>) {
    std::vector<Point2<I>> q;
    for (const auto& p : pts) q.push_back({int_cast<I>(p.x), int_cast<I>(p.y)});
    return recognize_dss<I>(std::span<const Point2<I>>(q), conn);
  });
  const auto& d = r.value;
  Record out;
  out.boolean("is_dss", d.is_dss).integer("connectivity", BigInt(c.i64_of("connectivity")));
  if (d.is_dss) {
    out.integer("a", d.characteristics.a)
        .integer("b", d.characteristics.b)
        .integer("mu", d.characteristics.mu)
        .integer("omega", d.characteristics.omega);
  } else {
    out.integer("longest_prefix", BigInt(static_cast<std::int64_t>(d.longest_prefix)));
  }
  return out.text("integer_type", std::string(to_string(r.served)));
}

// --- dss.subsegment ------------------------------------------------------------------------

Record subsegment_generate(Rng& rng, const Params& params) {
  BigInt b = rng.chance(1, 3) ? BigInt(rng.range(1, 60)) : rng.edgy_natural(params.bits);
  if (b == 0) b = 1;
  BigInt a = rng.uniform_bits(params.bits + 8) % b;
  if (rng.chance(1, 8)) a = 0;
  if (rng.chance(1, 8)) a = b - 1;
  BigInt x0 = rng.edgy(params.bits);
  BigInt x1 = x0 + rng.range(0, static_cast<std::int64_t>(params.max_size) - 1);
  return Record()
      .integer("a", a, Shrink::toward_zero)
      .integer("b", b, Shrink::toward_zero)
      .integer("mu", rng.edgy(params.bits), Shrink::toward_zero)
      .integer("x0", x0, Shrink::toward_zero)
      .integer("x1", x1, Shrink::toward_zero);
}

bool subsegment_valid(const Record& c, const Params& params) {
  const BigInt &a = c.int_of("a"), &b = c.int_of("b"), &x0 = c.int_of("x0"), &x1 = c.int_of("x1");
  return b >= 1 && a >= 0 && a < b && x0 <= x1 && x1 - x0 < BigInt(params.max_size);
}

Record subsegment_oracle(const Record& c) {
  const BigInt &a = c.int_of("a"), &b = c.int_of("b"), &mu = c.int_of("mu"), &x0 = c.int_of("x0"),
               &x1 = c.int_of("x1");
  // The naive line mu <= a x - b y < mu + b has one point per abscissa: y = floor((a x - mu)/b).
  std::vector<Point2<BigInt>> pts;
  for (BigInt x = x0; x <= x1; ++x) pts.push_back({x, floor_div(BigInt(a * x - mu), b)});
  auto d = brute_dss(local_of(pts), 8);
  if (!d) throw InvalidArgument("subsegment oracle: the window is not a DSS");
  BigInt m = BigInt(d->lo) + BigInt(d->a) * x0 - BigInt(d->b) * pts[0].y;
  return Record().integer("a", BigInt(d->a)).integer("b", BigInt(d->b)).integer("mu", m);
}

Record subsegment_compute(const Record& c, IntKind type) {
  auto r = escalate_from(type, [&]<class I>(std::type_identity<I>) {
    auto s = subsegment_reversed_smart_dss<I>(
        int_cast<I>(c.int_of("a")), int_cast<I>(c.int_of("b")), int_cast<I>(c.int_of("mu")),
        int_cast<I>(c.int_of("x0")), int_cast<I>(c.int_of("x1")));
    return std::array<BigInt, 3>{to_bigint(s.a), to_bigint(s.b), to_bigint(s.mu)};
  });
  return Record()
      .integer("a", r.value[0])
      .integer("b", r.value[1])
      .integer("mu", r.value[2])
      .text("integer_type", std::string(to_string(r.served)));
}

// --- dss.cover.maximal ----------------------------------------------------------------------

const std::vector<std::string> kSegmentColumns = {"begin", "end", "a", "b", "mu"};

// The answer's "segments": rows (begin, end, a, b, mu), written as objects.
Record segments_record(std::vector<BigInt> rows) {
  const std::size_t n = rows.size() / kSegmentColumns.size();
  Record r;
  r.array("segments", {n, kSegmentColumns.size()}, std::move(rows));
  r.at("segments").columns = kSegmentColumns;
  return r;
}

// Open paths of the recognizer's generator, the coordinates kept within 60 bits (the cover
// reads int64 points and the path must not leave them).
Record cover_generate(Rng& rng, const Params& params) {
  Params p = params;
  p.bits = std::min(params.bits, 60);
  return dss_generate(rng, p).boolean("closed", false);
}

bool cover_valid(const Record& c, const Params& params) {
  if (!dss_valid(c, params)) return false;
  const BigInt bound = BigInt(1) << 61;
  for (const auto& x : c.at("points").ints) {
    if (abs(x) > bound) return false;
  }
  return true;
}

// The maximal segments by definition: e(i), the last index of the longest DSS starting at
// point i (brute force, being a DSS is inherited by sub-paths), and [i, e(i)] is maximal iff
// i = 0 or e(i) > e(i - 1) (else [i - 1, e(i - 1)] contains it). O(n^2) brute-force searches.
Record cover_oracle(const Record& c) {
  const auto pts = path_of(c);
  const int conn = static_cast<int>(c.i64_of("connectivity"));
  const std::size_t n = pts.size();
  std::vector<BigInt> rows;
  std::size_t last_end = 0;
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t e = i;
    std::optional<BruteDss> best =
        brute_dss(local_of(std::vector<Point2<BigInt>>{pts[i]}), conn); // one point
    while (e + 1 < n) {
      const std::vector<Point2<BigInt>> sub(pts.begin() + static_cast<std::ptrdiff_t>(i),
                                            pts.begin() + static_cast<std::ptrdiff_t>(e + 2));
      auto d = brute_dss(local_of(sub), conn);
      if (!d) break;
      best = d;
      ++e;
    }
    if (i > 0 && e <= last_end) continue;
    last_end = e;
    const Record ch = dss_characteristics(*best, pts[i]);
    for (const auto& v :
         {BigInt(static_cast<std::int64_t>(i)), BigInt(static_cast<std::int64_t>(e)),
          ch.int_of("a"), ch.int_of("b"), ch.int_of("mu")}) {
      rows.push_back(v);
    }
  }
  return segments_record(std::move(rows));
}

Record cover_compute(const Record& c, IntKind type) {
  const auto pts = path_of(c);
  std::vector<Point2<std::int64_t>> q;
  for (const auto& p : pts)
    q.push_back({int_cast<Int64>(p.x).value(), int_cast<Int64>(p.y).value()});
  const Connectivity conn =
      c.i64_of("connectivity") == 4 ? Connectivity::four : Connectivity::eight;
  auto r = escalate_from(type, [&]<class I>(std::type_identity<I>) {
    return maximal_segments<I>(std::span<const Point2<std::int64_t>>(q), false, conn);
  });
  std::vector<BigInt> rows;
  for (const auto& s : r.value) {
    for (const auto& v :
         {BigInt(static_cast<std::int64_t>(s.begin)), BigInt(static_cast<std::int64_t>(s.end)),
          BigInt(s.a), BigInt(s.b), to_bigint(Int128(s.mu))}) {
      rows.push_back(v);
    }
  }
  return segments_record(std::move(rows)).text("integer_type", std::string(to_string(r.served)));
}

} // namespace

void add_dss_properties(std::vector<Property>& out) {
  {
    Property p;
    p.name = "dss.recognize.minimal";
    p.theorem = "a path is a DSS iff its points lie in one digital straight line (naive for "
                "8-connected paths, standard for 4-connected ones); the recognizer's (a, b, mu, "
                "omega) are the minimal characteristics, oriented by the path; else the longest "
                "DSS prefix";
    p.source = "oracle: search of every line by increasing period (brute force); algorithm: "
               "Debled-Rennesson and Reveilles, IJPRAI 9(4), 1995";
    p.operation = "dss recognize";
    p.sizes = "points <= max-size; the first point's coordinates of up to --bits bits";
    p.cost = Cost::moderate;
    p.default_max_size = 12;
    p.min_max_size = 1;
    p.max_max_size = 40;
    p.generate = dss_generate;
    p.valid = dss_valid;
    p.oracle = dss_oracle;
    p.compute = dss_compute;
    out.push_back(std::move(p));
  }
  {
    Property p;
    p.name = "dss.subsegment";
    p.theorem = "the minimal characteristics of the naive line 0 <= a x - b y - mu < b over "
                "x0 <= x <= x1 (ReversedSmartDSS, O(log b)) are those of the enumerated points";
    p.source = "oracle: the points enumerated and the minimal line searched by brute force; "
               "algorithm: Said and Lachaud, DGCI 2011; Lachaud and Said, DAM 161 (2013)";
    p.operation = "dss subsegment";
    p.sizes = "x1 - x0 < max-size; a, b, mu, x0 of up to --bits bits";
    p.cost = Cost::moderate;
    p.default_max_size = 16;
    p.max_max_size = 40;
    p.generate = subsegment_generate;
    p.valid = subsegment_valid;
    p.oracle = subsegment_oracle;
    p.compute = subsegment_compute;
    out.push_back(std::move(p));
  }
  {
    Property p;
    p.name = "dss.cover.maximal";
    p.theorem = "the tangential cover of an open path is the list of its maximal segments (runs "
                "of consecutive points that are a DSS and extend neither backwards nor forwards), "
                "by increasing first point, each with its minimal characteristics (a, b, mu)";
    p.source = "oracle: the longest DSS from every point by brute-force line search; algorithm: "
               "Feschet and Tougne, DGCI 1999; Lachaud, Vialard and de Vieilleville, IVC 25 "
               "(2007)";
    p.operation = "dss cover";
    p.sizes = "points <= max-size (open paths); the first point's coordinates of up to "
              "min(--bits, 60) bits (the cover reads int64 points)";
    p.cost = Cost::moderate;
    p.default_max_size = 12;
    p.max_max_size = 30;
    p.generate = cover_generate;
    p.valid = cover_valid;
    p.oracle = cover_oracle;
    p.compute = cover_compute;
    out.push_back(std::move(p));
  }
}

} // namespace zdg::check
