#include <zdg/kernel/curves/maximal_segments.hpp>

#include <zdg/arith/escalate.hpp>

#include <sstream>

namespace zdg {

namespace {

using P = Point2<std::int64_t>;

bool adjacent(const P& p, const P& q, Connectivity c) {
  int128_t dx = int128_t(q.x) - p.x, dy = int128_t(q.y) - p.y;
  if (dx < -1 || dx > 1 || dy < -1 || dy > 1 || (dx == 0 && dy == 0)) return false;
  return c == Connectivity::eight || dx == 0 || dy == 0;
}

Connectivity check_curve(std::span<const P> pts, bool closed, std::optional<Connectivity> want) {
  Connectivity c = Connectivity::four;
  const std::size_t n = pts.size();
  for (std::size_t k = 0; k < n; ++k) {
    if (k + 1 == n && (!closed || n == 1)) break;
    std::size_t k1 = k + 1 == n ? 0 : k + 1;
    const P &p = pts[k], &q = pts[k1];
    if (!adjacent(p, q, Connectivity::eight) ||
        (want == Connectivity::four && !adjacent(p, q, Connectivity::four))) {
      std::ostringstream m;
      m << "curve: point " << k1 << " " << q << " is not "
        << (want == Connectivity::four ? "4" : "8") << "-adjacent to point " << k << " " << p;
      if (k1 == 0) m << " (closing the curve)";
      throw InvalidArgument(m.str());
    }
    if (p.x != q.x && p.y != q.y) c = Connectivity::eight;
  }
  return want ? *want : c;
}

template <TowerInt I>
class Walker {
public:
  Walker(std::span<const P> pts, Connectivity c)
      : pts_(pts), n_(static_cast<std::int64_t>(pts.size())), rec_(at(0), c) {}

  Point2<I> at(std::int64_t k) const {
    std::int64_t m = k % n_;
    if (m < 0) m += n_;
    const P& p = pts_[static_cast<std::size_t>(m)];
    return {I(p.x), I(p.y)};
  }
  std::size_t index(std::int64_t k) const {
    std::int64_t m = k % n_;
    return static_cast<std::size_t>(m < 0 ? m + n_ : m);
  }
  MaximalSegment segment(std::int64_t i, std::int64_t j) const {
    MaximalSegment s;
    s.begin = index(i);
    s.end = index(j);
    s.length = static_cast<std::size_t>(j - i + 1);
    s.a = int_cast<Int64>(rec_.a()).value();
    s.b = int_cast<Int64>(rec_.b()).value();
    s.omega = int_cast<Int64>(rec_.omega()).value();
    const auto& o = rec_.origin();
    Int128 mu = int_cast<Int128>(rec_.mu_local()) + Int128(s.a) * int_cast<Int128>(o.x) -
                Int128(s.b) * int_cast<Int128>(o.y);
    s.mu = mu.value();
    return s;
  }

  std::span<const P> pts_;
  std::int64_t n_;
  DssRecognizer<I> rec_;
};

template <TowerInt I>
std::vector<MaximalSegment> cover(std::span<const P> pts, bool closed, Connectivity c) {
  Walker<I> w(pts, c);
  auto& rec = w.rec_;
  const std::int64_t n = w.n_;
  std::vector<MaximalSegment> out;
  std::int64_t i = 0, j = 0; // the recognizer holds p_i .. p_j (unwrapped indices)
  auto full = [&] { return j - i + 1 >= n; };
  auto grow_front = [&] {
    while (!full() && (closed || j + 1 < n) && rec.extend_front(w.at(j + 1))) ++j;
  };
  if (closed) {
    while (!full() && rec.extend_back(w.at(i - 1))) --i;
  }
  grow_front();
  out.push_back(w.segment(i, j));
  const std::int64_t i0 = i;
  while (!full() && (closed || j + 1 < n)) {
    while (!rec.extend_front(w.at(j + 1))) {
      rec.retract_back();
      ++i;
    }
    ++j;
    grow_front();
    if (closed && i >= i0 + n) break; // back to the first segment
    out.push_back(w.segment(i, j));
  }
  return out;
}

template <TowerInt I>
std::vector<MaximalSegment> greedy(std::span<const P> pts, bool closed, Connectivity c) {
  Walker<I> w(pts, c);
  auto& rec = w.rec_;
  const std::int64_t n = w.n_;
  const std::int64_t last = closed ? n : n - 1; // index of the final point (n wraps to 0)
  std::vector<MaximalSegment> out;
  std::int64_t i = 0;
  while (true) {
    rec.reset(w.at(i));
    std::int64_t j = i;
    while (j < last && rec.extend_front(w.at(j + 1))) ++j;
    out.push_back(w.segment(i, j));
    if (j >= last) break;
    i = j;
  }
  return out;
}

} // namespace

template <TowerInt I>
std::vector<MaximalSegment> maximal_segments(std::span<const P> points, bool closed,
                                             std::optional<Connectivity> connectivity) {
  if (points.empty()) return {};
  return cover<I>(points, closed, check_curve(points, closed, connectivity));
}

template <TowerInt I>
std::vector<MaximalSegment> greedy_segmentation(std::span<const P> points, bool closed,
                                                std::optional<Connectivity> connectivity) {
  if (points.empty()) return {};
  return greedy<I>(points, closed, check_curve(points, closed, connectivity));
}

Escalated<std::vector<MaximalSegment>>
maximal_segments_exact(std::span<const P> points, bool closed,
                       std::optional<Connectivity> connectivity) {
  if (points.empty()) return {{}, IntKind::int64};
  const Connectivity c = check_curve(points, closed, connectivity);
  return escalate([&]<class I>(std::type_identity<I>) { return cover<I>(points, closed, c); });
}

Escalated<std::vector<MaximalSegment>>
greedy_segmentation_exact(std::span<const P> points, bool closed,
                          std::optional<Connectivity> connectivity) {
  if (points.empty()) return {{}, IntKind::int64};
  const Connectivity c = check_curve(points, closed, connectivity);
  return escalate([&]<class I>(std::type_identity<I>) { return greedy<I>(points, closed, c); });
}

#define ZDG_INSTANTIATE(I)                                                                         \
  template std::vector<MaximalSegment> maximal_segments<I>(std::span<const P>, bool,               \
                                                           std::optional<Connectivity>);           \
  template std::vector<MaximalSegment> greedy_segmentation<I>(std::span<const P>, bool,            \
                                                              std::optional<Connectivity>);
ZDG_INSTANTIATE(Int64)
ZDG_INSTANTIATE(Int128)
ZDG_INSTANTIATE(BigInt)
#undef ZDG_INSTANTIATE

} // namespace zdg
