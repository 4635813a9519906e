#include <zdg/estimators/ii_3d.hpp>

#include <zdg/arith/integer.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <limits>
#include <numbers>
#include <string>
#include <tuple>
#include <unordered_map>

namespace zdg {

namespace {

constexpr std::int64_t kMaxRadius = 256;
constexpr std::size_t kMaxBlockBytes = std::size_t{1} << 27;  // per chunk
constexpr std::size_t kMaxSharedBytes = std::size_t{1} << 29; // shared by the threads

std::int64_t isqrt(std::int64_t n) {
  auto r = std::int64_t(std::sqrt(double(n)));
  while (r > 0 && r * r > n) --r;
  while ((r + 1) * (r + 1) <= n) ++r;
  return r;
}

void check_radius2(std::int64_t r2) {
  if (r2 < 0 || r2 > kMaxRadius * kMaxRadius)
    throw InvalidArgument("integral invariants: squared digital radius " + std::to_string(r2) +
                          " is outside [0, 256^2]");
}

unsigned threads_or_default(unsigned threads) {
  return worker_count(threads, std::numeric_limits<std::int64_t>::max());
}

/// One row of the ball along an axis a: the offsets t e_a + u e_b + v e_c, |t| <= w, where
/// (a, b, c) is a cyclic permutation of (0, 1, 2).
struct Row {
  int u, v, w;
};

std::vector<Row> ball_rows(std::int64_t r2) {
  const int r = int(isqrt(r2));
  std::vector<Row> rows;
  for (int u = -r; u <= r; ++u)
    for (int v = -r; v <= r; ++v)
      if (std::int64_t(u) * u + std::int64_t(v) * v <= r2)
        rows.push_back({u, v, int(isqrt(r2 - std::int64_t(u) * u - std::int64_t(v) * v))});
  return rows;
}

/// Running moments about the current centre.
struct Accumulator {
  std::int64_t m0 = 0;
  std::int64_t m1[3] = {0, 0, 0};
  std::int64_t m2[6] = {0, 0, 0, 0, 0, 0}; // xx yy zz xy xz yz

  void add(const int* o) {
    ++m0;
    m1[0] += o[0];
    m1[1] += o[1];
    m1[2] += o[2];
    m2[0] += o[0] * o[0];
    m2[1] += o[1] * o[1];
    m2[2] += o[2] * o[2];
    m2[3] += o[0] * o[1];
    m2[4] += o[0] * o[2];
    m2[5] += o[1] * o[2];
  }
  void sub(const int* o) {
    --m0;
    m1[0] -= o[0];
    m1[1] -= o[1];
    m1[2] -= o[2];
    m2[0] -= o[0] * o[0];
    m2[1] -= o[1] * o[1];
    m2[2] -= o[2] * o[2];
    m2[3] -= o[0] * o[1];
    m2[4] -= o[0] * o[2];
    m2[5] -= o[1] * o[2];
  }
  /// The centre moves by e = sign e_a: every relative coordinate q becomes q - e.
  void shift(int a, int sign) {
    // sum (q - e)_i (q - e)_j = M2_ij - M1_i e_j - e_i M1_j + M0 e_i e_j.
    static constexpr int cross[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};
    for (int j = 0; j < 3; ++j)
      if (j != a) m2[cross[a][j]] -= sign * m1[j];
    m2[a] += -2 * sign * m1[a] + m0;
    m1[a] -= sign * m0;
  }
  BallMoments moments() const {
    return {m0, {m1[0], m1[1], m1[2]}, {m2[0], m2[1], m2[2], m2[3], m2[4], m2[5]}};
  }
};

struct Offset {
  std::int64_t lin;
  int o[3];
};

/// The walk: the next voxel is the unvisited one nearest in l1 distance within the
/// l_inf 3-neighbourhood, else the first unvisited one in (z, y, x) order.
std::vector<std::uint32_t>
greedy_walk(const std::vector<Voxel>& voxels,
            const std::unordered_map<Voxel, std::uint32_t, KPointHash>& index) {
  const std::size_t n = voxels.size();
  std::vector<std::uint32_t> order(n);
  for (std::uint32_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    const Voxel &p = voxels[a], &q = voxels[b];
    return std::tie(p.z, p.y, p.x) < std::tie(q.z, q.y, q.x);
  });
  std::vector<Voxel> near;
  for (int dz = -3; dz <= 3; ++dz)
    for (int dy = -3; dy <= 3; ++dy)
      for (int dx = -3; dx <= 3; ++dx)
        if (dx || dy || dz) near.push_back({dx, dy, dz});
  std::stable_sort(near.begin(), near.end(), [](const Voxel& a, const Voxel& b) {
    return std::abs(a.x) + std::abs(a.y) + std::abs(a.z) <
           std::abs(b.x) + std::abs(b.y) + std::abs(b.z);
  });
  std::vector<char> visited(n, 0);
  std::vector<std::uint32_t> walk;
  walk.reserve(n);
  std::size_t next_in_order = 0;
  std::uint32_t cur = order[0];
  while (true) {
    visited[cur] = 1;
    walk.push_back(cur);
    if (walk.size() == n) break;
    std::int64_t best = -1;
    const Voxel c = voxels[cur];
    for (const Voxel& d : near) {
      const auto it = index.find({c.x + d.x, c.y + d.y, c.z + d.z});
      if (it != index.end() && !visited[it->second]) {
        best = it->second;
        break;
      }
    }
    if (best < 0) {
      while (visited[order[next_in_order]]) ++next_in_order;
      best = order[next_in_order];
    }
    cur = std::uint32_t(best);
  }
  return walk;
}

std::int64_t l1(const Voxel& a, const Voxel& b) {
  return std::abs(a.x - b.x) + std::abs(a.y - b.y) + std::abs(a.z - b.z);
}

struct ChunkStats {
  std::size_t full_counts = 0, unit_moves = 0, evaluations = 0;
};

/// The cache of predicate values over a box of voxels: 0 unknown, 1 outside, 2 inside.
/// Accessed through relaxed std::atomic_ref when shared by the threads (two threads may
/// evaluate the same voxel; both store the same value).
struct Cache {
  Voxel lo;
  std::int64_t stride[3] = {1, 0, 0};
  std::size_t size = 0;
};

/// The bounding box of the voxels of walk grown by r + 1.
Cache cache_frame(const std::vector<Voxel>& voxels, std::span<const std::uint32_t> walk,
                  std::int64_t r) {
  Voxel lo = voxels[walk[0]], hi = lo;
  for (const auto i : walk) {
    const Voxel& p = voxels[i];
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  const std::int64_t g = r + 1;
  Cache c;
  c.lo = {lo.x - g, lo.y - g, lo.z - g};
  const double n = double(hi.x - lo.x + 2 * g + 1) * double(hi.y - lo.y + 2 * g + 1) *
                   double(hi.z - lo.z + 2 * g + 1);
  if (n > 1e18) {
    c.size = std::size_t(-1);
    return c;
  }
  c.stride[1] = hi.x - lo.x + 2 * g + 1;
  c.stride[2] = c.stride[1] * (hi.y - lo.y + 2 * g + 1);
  c.size = std::size_t(n);
  return c;
}

/// Moments at the voxels walk[0..), in order, by one full count then unit moves. The
/// predicate cache is `shared` (covering every ball of the walk) or, if null, a block of
/// the chunk's own.
template <bool Second>
ChunkStats run_chunk(const VoxelPredicate& inside, const VoxelBox& box,
                     const std::vector<Voxel>& voxels, std::span<const std::uint32_t> walk,
                     const std::vector<Row>& rows, std::int64_t r, std::int64_t max_jump,
                     const Cache* shared, std::uint8_t* shared_data,
                     std::vector<BallMoments>& out) {
  ChunkStats stats;
  std::vector<std::uint8_t> own;
  Cache frame;
  std::uint8_t* block = shared_data;
  if (shared) {
    frame = *shared;
  } else {
    frame = cache_frame(voxels, walk, r);
    own.assign(frame.size, 0);
    block = own.data();
  }
  const Voxel lo = frame.lo;
  const std::int64_t* stride = frame.stride;
  auto lin_of = [&](const Voxel& p) {
    return (p.x - lo.x) + (p.y - lo.y) * stride[1] + (p.z - lo.z) * stride[2];
  };
  // Entering and leaving offsets, relative to the NEW centre, of the move by sign e_a:
  // the entering voxel of a row is at sign w e_a, the leaving one at -sign (w + 1) e_a.
  std::vector<Offset> enter[6], leave[6];
  for (int a = 0; a < 3; ++a)
    for (int sd = 0; sd < 2; ++sd) {
      const int sign = sd ? 1 : -1, b = (a + 1) % 3, c = (a + 2) % 3;
      auto& en = enter[2 * a + sd];
      auto& le = leave[2 * a + sd];
      en.reserve(rows.size());
      le.reserve(rows.size());
      for (const Row& row : rows) {
        Offset e{}, l{};
        e.o[a] = sign * row.w;
        l.o[a] = -sign * (row.w + 1);
        e.o[b] = l.o[b] = row.u;
        e.o[c] = l.o[c] = row.v;
        e.lin = e.o[0] * stride[0] + e.o[1] * stride[1] + e.o[2] * stride[2];
        l.lin = l.o[0] * stride[0] + l.o[1] * stride[1] + l.o[2] * stride[2];
        en.push_back(e);
        le.push_back(l);
      }
    }
  auto probe = [&](const Voxel& c, std::int64_t centre_lin, std::int64_t off_lin,
                   const int* o) -> bool {
    std::atomic_ref<std::uint8_t> st(block[std::size_t(centre_lin + off_lin)]);
    std::uint8_t v = st.load(std::memory_order_relaxed);
    if (v == 0) {
      ++stats.evaluations;
      const Voxel p{c.x + o[0], c.y + o[1], c.z + o[2]};
      v = box.contains(p) && inside(p) ? 2 : 1;
      st.store(v, std::memory_order_relaxed);
    }
    return v == 2;
  };
  Accumulator acc;
  auto full_count = [&](const Voxel& c) {
    ++stats.full_counts;
    acc = Accumulator{};
    const std::int64_t cl = lin_of(c);
    for (const Row& row : rows)
      for (int t = -row.w; t <= row.w; ++t) {
        const int o[3] = {t, row.u, row.v}; // rows along x: (b, c) = (y, z)
        if (probe(c, cl, o[0] + o[1] * stride[1] + o[2] * stride[2], o)) {
          if constexpr (Second)
            acc.add(o);
          else
            ++acc.m0;
        }
      }
  };
  Voxel cur{};
  for (std::size_t i = 0; i < walk.size(); ++i) {
    const Voxel& target = voxels[walk[i]];
    if (i == 0 || l1(cur, target) > max_jump) {
      full_count(target);
      cur = target;
    }
    while (cur != target) {
      int a = 0;
      while (coord(cur, a) == coord(target, a)) ++a;
      const int sign = coord(target, a) > coord(cur, a) ? 1 : -1;
      coord(cur, a) += sign;
      ++stats.unit_moves;
      if constexpr (Second) acc.shift(a, sign);
      const int d = 2 * a + (sign > 0 ? 1 : 0);
      const std::int64_t cl = lin_of(cur);
      for (const Offset& f : leave[d])
        if (probe(cur, cl, f.lin, f.o)) {
          if constexpr (Second)
            acc.sub(f.o);
          else
            --acc.m0;
        }
      for (const Offset& f : enter[d])
        if (probe(cur, cl, f.lin, f.o)) {
          if constexpr (Second)
            acc.add(f.o);
          else
            ++acc.m0;
        }
    }
    out[walk[i]] = acc.moments();
  }
  return stats;
}

void check_grid(double h, double R) {
  if (!(h > 0) || !std::isfinite(h))
    throw InvalidArgument("integral invariants: grid step h = " + std::to_string(h) +
                          " is not a positive number");
  if (!(R > 0) || !std::isfinite(R))
    throw InvalidArgument("integral invariants: radius R = " + std::to_string(R) +
                          " is not a positive number");
}

} // namespace

std::int64_t ii_digital_radius2(double R, double h) {
  check_grid(h, R);
  const double r = R / h;
  if (!(r <= double(kMaxRadius)))
    throw InvalidArgument("integral invariants: digital radius R/h = " + std::to_string(r) +
                          " exceeds 256");
  return std::int64_t(std::floor(r * r));
}

namespace {

/// The distinct inner and outer voxels of the surfels, and the two indices of each surfel.
struct Centres {
  std::vector<Voxel> voxels;
  std::unordered_map<Voxel, std::uint32_t, KPointHash> index;
  std::vector<std::array<std::uint32_t, 2>> of_surfel;
};

Centres surfel_centres(std::span<const Surfel> surfels) {
  if (surfels.size() >= (std::size_t{1} << 31))
    throw InvalidArgument("integral invariants: " + std::to_string(surfels.size()) +
                          " surfels exceed 2^31");
  const std::int64_t max_coord = kMaxVoxelCoordinate - kMaxRadius - 8;
  Centres c;
  c.index.reserve(2 * surfels.size());
  c.of_surfel.reserve(surfels.size());
  for (const Surfel& s : surfels) {
    if (cell_dimension(s.k) != 2)
      throw InvalidArgument("integral invariants: (" + std::to_string(s.k.x) + ", " +
                            std::to_string(s.k.y) + ", " + std::to_string(s.k.z) +
                            ") is not a surfel");
    std::array<std::uint32_t, 2> ids{};
    const Voxel vs[2] = {inner_voxel(s), outer_voxel(s)};
    for (int j = 0; j < 2; ++j) {
      const Voxel& v = vs[j];
      if (std::abs(v.x) > max_coord || std::abs(v.y) > max_coord || std::abs(v.z) > max_coord)
        throw InvalidArgument("integral invariants: surfel coordinate beyond 2^40");
      auto [it, fresh] = c.index.try_emplace(v, std::uint32_t(c.voxels.size()));
      if (fresh) c.voxels.push_back(v);
      ids[std::size_t(j)] = it->second;
    }
    c.of_surfel.push_back(ids);
  }
  return c;
}

} // namespace

IISurfelMoments ii_surfel_moments(const VoxelPredicate& inside, const VoxelBox& box,
                                  std::span<const Surfel> surfels, std::int64_t r2,
                                  unsigned threads, bool second_order) {
  check_voxel_box(box);
  check_radius2(r2);
  threads = threads_or_default(threads);
  IISurfelMoments result;
  if (surfels.empty()) return result;
  const Centres c = surfel_centres(surfels);
  const ColumnMoments m = ball_moments_by_columns(inside, box, c.voxels, r2, threads, second_order);
  result.moments.reserve(surfels.size());
  for (const auto& ids : c.of_surfel)
    result.moments.push_back({m.moments[ids[0]], m.moments[ids[1]]});
  result.stats.voxels = c.voxels.size();
  result.stats.predicate_evaluations = m.stats.evaluations;
  result.stats.segments = m.stats.segments;
  result.stats.layers = m.stats.layers;
  return result;
}

IISurfelMoments ii_surfel_moments_incremental(const VoxelPredicate& inside, const VoxelBox& box,
                                              std::span<const Surfel> surfels, std::int64_t r2,
                                              unsigned threads, bool second_order) {
  return detail::ii_surfel_moments_incremental(inside, box, surfels, r2, threads, second_order,
                                               kMaxSharedBytes);
}

IISurfelMoments detail::ii_surfel_moments_incremental(
    const VoxelPredicate& inside, const VoxelBox& box, std::span<const Surfel> surfels,
    std::int64_t r2, unsigned threads, bool second_order, std::size_t shared_cache_bytes) {
  check_voxel_box(box);
  check_radius2(r2);
  threads = threads_or_default(threads);
  IISurfelMoments result;
  if (surfels.empty()) return result;
  const Centres centres = surfel_centres(surfels);
  const std::vector<Voxel>& voxels = centres.voxels;
  const std::vector<std::array<std::uint32_t, 2>>& of_surfel = centres.of_surfel;
  const std::vector<std::uint32_t> walk = greedy_walk(voxels, centres.index);
  const std::vector<Row> rows = ball_rows(r2);
  const std::int64_t r = isqrt(r2);
  std::int64_t ball_size = 0;
  for (const Row& row : rows) ball_size += 2 * row.w + 1;
  const std::int64_t max_jump =
      std::max<std::int64_t>(1, ball_size / std::int64_t(2 * rows.size()));

  // Chunks: 8 per thread, halved until their cache block is small enough.
  std::vector<std::pair<std::size_t, std::size_t>> pending, chunks;
  const std::size_t n = walk.size();
  const std::size_t nch = std::min(n, std::size_t(threads) * 8);
  for (std::size_t i = 0; i < nch; ++i) pending.push_back({i * n / nch, (i + 1) * n / nch});
  while (!pending.empty()) {
    const auto [b, e] = pending.back();
    pending.pop_back();
    if (e - b > 1 &&
        cache_frame(voxels, std::span(walk).subspan(b, e - b), r).size > kMaxBlockBytes) {
      pending.push_back({b, (b + e) / 2});
      pending.push_back({(b + e) / 2, e});
    } else {
      chunks.push_back({b, e});
    }
  }
  std::sort(chunks.begin(), chunks.end());

  // One cache shared by all chunks when it is small enough (each voxel evaluated about
  // once), else one per chunk.
  const Cache whole = cache_frame(voxels, walk, r);
  std::vector<std::uint8_t> whole_data;
  if (whole.size <= shared_cache_bytes) whole_data.assign(whole.size, 0);
  const Cache* shared = whole_data.empty() ? nullptr : &whole;

  std::vector<BallMoments> at_voxel(voxels.size());
  std::atomic<std::size_t> full_counts{0}, unit_moves{0}, evaluations{0};
  parallel_for(std::int64_t(chunks.size()), unsigned(threads), [&](std::int64_t c) {
    const auto& chunk = chunks[std::size_t(c)];
    const auto span = std::span(walk).subspan(chunk.first, chunk.second - chunk.first);
    const ChunkStats st = second_order
                              ? run_chunk<true>(inside, box, voxels, span, rows, r, max_jump,
                                                shared, whole_data.data(), at_voxel)
                              : run_chunk<false>(inside, box, voxels, span, rows, r, max_jump,
                                                 shared, whole_data.data(), at_voxel);
    full_counts += st.full_counts;
    unit_moves += st.unit_moves;
    evaluations += st.evaluations;
  });

  result.moments.reserve(surfels.size());
  for (const auto& ids : of_surfel) result.moments.push_back({at_voxel[ids[0]], at_voxel[ids[1]]});
  result.stats.voxels = voxels.size();
  result.stats.predicate_evaluations = evaluations.load();
  result.stats.full_counts = full_counts.load();
  result.stats.unit_moves = unit_moves.load();
  result.stats.chunks = chunks.size();
  result.stats.shared_cache = shared != nullptr;
  return result;
}

double ii_mean_curvature_from_moments(const SurfelBallMoments& m, double h, double R) {
  const double V = h * h * h * 0.5 * double(m.inner.m0 + m.outer.m0);
  return 8.0 / (3.0 * R) - 4.0 * V / (std::numbers::pi * R * R * R * R);
}

IIPrincipalCurvatures ii_principal_curvatures_from_moments(const SurfelBallMoments& m,
                                                           const Surfel& s, double h, double R) {
  // Covariance matrix of each kernel about its own centroid, in voxel units:
  // J = (m0 m2 - m1 m1^T) / m0, the numerator exact in int128; J = 0 for an empty kernel.
  // The estimate uses their average (DGtal's DigitalSurfaceConvolver with lambda = 1/2).
  for (const BallMoments* b : {&m.inner, &m.outer})
    if (b->m0 > 1 && b->m2[0] + b->m2[1] + b->m2[2] == 0)
      throw InvalidArgument("integral invariants: the moments of surfel (" + std::to_string(s.k.x) +
                            ", " + std::to_string(s.k.y) + ", " + std::to_string(s.k.z) +
                            ") lack the second order (computed with second_order = false)");
  if (m.inner.m0 + m.outer.m0 == 0)
    throw InvalidArgument("integral invariants: empty kernels at surfel (" + std::to_string(s.k.x) +
                          ", " + std::to_string(s.k.y) + ", " + std::to_string(s.k.z) +
                          "): not a boundary surfel of the set");
  static constexpr int cross[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};
  Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
  for (const BallMoments* b : {&m.inner, &m.outer}) {
    if (b->m0 == 0) continue;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const int128_t num = int128_t(b->m0) * b->m2[std::size_t(cross[i][j])] -
                             int128_t(b->m1[std::size_t(i)]) * b->m1[std::size_t(j)];
        J(i, j) += 0.5 * double(num) / double(b->m0);
      }
  }
  const Point3<int> nrm = trivial_normal(s);
  const int n[3] = {nrm.x, nrm.y, nrm.z};
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(J);
  const double h5 = h * h * h * h * h;
  const double l1 = h5 * es.eigenvalues()(2), l2 = h5 * es.eigenvalues()(1);
  const double c = 6.0 / (std::numbers::pi * std::pow(R, 6));
  IIPrincipalCurvatures out;
  out.k1 = c * (l2 - 3 * l1) + 8.0 / (5.0 * R);
  out.k2 = c * (l1 - 3 * l2) + 8.0 / (5.0 * R);
  Eigen::Vector3d v1 = es.eigenvectors().col(2), v3 = es.eigenvectors().col(0);
  if (v3.dot(Eigen::Vector3d(n[0], n[1], n[2])) < 0) v3 = -v3;
  const Eigen::Vector3d v2 = v3.cross(v1);
  out.d1 = {v1(0), v1(1), v1(2)};
  out.d2 = {v2(0), v2(1), v2(2)};
  out.normal = {v3(0), v3(1), v3(2)};
  return out;
}

std::vector<double> ii_mean_curvature(const VoxelPredicate& inside, const VoxelBox& box,
                                      std::span<const Surfel> surfels, double h, double R,
                                      unsigned threads) {
  const auto r2 = ii_digital_radius2(R, h);
  const auto m = ii_surfel_moments(inside, box, surfels, r2, threads, false);
  std::vector<double> out;
  out.reserve(surfels.size());
  for (const auto& sm : m.moments) out.push_back(ii_mean_curvature_from_moments(sm, h, R));
  return out;
}

std::vector<IIPrincipalCurvatures> ii_principal_curvatures(const VoxelPredicate& inside,
                                                           const VoxelBox& box,
                                                           std::span<const Surfel> surfels,
                                                           double h, double R, unsigned threads) {
  const auto r2 = ii_digital_radius2(R, h);
  const auto m = ii_surfel_moments(inside, box, surfels, r2, threads, true);
  std::vector<IIPrincipalCurvatures> out;
  out.reserve(surfels.size());
  for (std::size_t i = 0; i < surfels.size(); ++i)
    out.push_back(ii_principal_curvatures_from_moments(m.moments[i], surfels[i], h, R));
  return out;
}

} // namespace zdg
