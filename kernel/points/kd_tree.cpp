#include <zdg/kernel/points/kd_tree.hpp>

#include <nanoflann.hpp>

#include <algorithm>
#include <limits>

namespace zdg {
namespace {

struct Points {
  std::vector<Point3<double>> p;
  std::size_t kdtree_get_point_count() const { return p.size(); }
  double kdtree_get_pt(std::size_t i, std::size_t d) const {
    return d == 0 ? p[i].x : (d == 1 ? p[i].y : p[i].z);
  }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};

using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Points>,
                                                 Points, 3, std::size_t>;

double distance2(const Point3<double>& q, const Point3<double>& p) {
  const double dx = q.x - p.x, dy = q.y - p.y, dz = q.z - p.z;
  return dx * dx + dy * dy + dz * dz;
}

bool before(const Neighbour& a, const Neighbour& b) {
  return a.distance2 < b.distance2 || (a.distance2 == b.distance2 && a.index < b.index);
}

// The tree prunes with `candidate < worstDist()` at leaves and `bound <= worstDist()` for
// subtrees, with bounds accumulated in floating point: the sets below report a worst distance
// a few ulps above the true one so that ties and rounding never hide a point, and decide
// membership themselves with the exact order of zdg::before.
double slack(double d) {
  return d == std::numeric_limits<double>::infinity()
             ? d
             : d * (1 + 8 * std::numeric_limits<double>::epsilon()) +
                   std::numeric_limits<double>::denorm_min();
}

// The k first by (distance, index); distances recomputed with distance2 so that the order
// does not depend on how the tree accumulates them.
class NearestSet {
public:
  NearestSet(const Points& pts, const Point3<double>& q, std::size_t k, std::vector<Neighbour>& out)
      : pts_(pts), q_(q), k_(k), out_(out) {
    out_.clear();
    out_.reserve(k);
  }
  bool full() const { return out_.size() == k_; }
  std::size_t size() const { return out_.size(); }
  double worstDist() const {
    return full() ? slack(out_.back().distance2) : std::numeric_limits<double>::infinity();
  }
  bool addPoint(double, std::size_t index) {
    const Neighbour n{index, distance2(q_, pts_.p[index])};
    if (full() && !before(n, out_.back())) return true;
    auto at = std::upper_bound(out_.begin(), out_.end(), n, before);
    if (full()) out_.pop_back();
    out_.insert(at, n);
    return true;
  }

private:
  const Points& pts_;
  Point3<double> q_;
  std::size_t k_;
  std::vector<Neighbour>& out_;
};

class WithinSet {
public:
  WithinSet(const Points& pts, const Point3<double>& q, double r2, std::vector<Neighbour>& out)
      : pts_(pts), q_(q), r2_(r2), out_(out) {
    out_.clear();
  }
  bool full() const { return true; }
  std::size_t size() const { return out_.size(); }
  double worstDist() const { return slack(r2_); }
  bool addPoint(double, std::size_t index) {
    const double d = distance2(q_, pts_.p[index]);
    if (d <= r2_) out_.push_back({index, d});
    return true;
  }

private:
  const Points& pts_;
  Point3<double> q_;
  double r2_;
  std::vector<Neighbour>& out_;
};

} // namespace

struct KdTree::Impl {
  Points points;
  Tree tree;
  explicit Impl(std::span<const Point3<double>> p)
      : points{std::vector<Point3<double>>(p.begin(), p.end())},
        tree(3, points, nanoflann::KDTreeSingleIndexAdaptorParams(16)) {}
};

KdTree::KdTree(std::span<const Point3<double>> points) : impl_(std::make_unique<Impl>(points)) {}
KdTree::~KdTree() = default;
KdTree::KdTree(KdTree&&) noexcept = default;
KdTree& KdTree::operator=(KdTree&&) noexcept = default;

std::size_t KdTree::size() const {
  return impl_->points.p.size();
}
const Point3<double>& KdTree::point(std::size_t i) const {
  return impl_->points.p[i];
}

void KdTree::nearest(const Point3<double>& q, std::size_t k, std::vector<Neighbour>& out) const {
  k = std::min(k, size());
  NearestSet set(impl_->points, q, k, out);
  if (k == 0) return;
  const double v[3] = {q.x, q.y, q.z};
  impl_->tree.findNeighbors(set, v, nanoflann::SearchParams());
}

void KdTree::within(const Point3<double>& q, double r, std::vector<Neighbour>& out) const {
  WithinSet set(impl_->points, q, r < 0 ? -1.0 : r * r, out);
  if (r < 0 || size() == 0) return;
  const double v[3] = {q.x, q.y, q.z};
  impl_->tree.findNeighbors(set, v, nanoflann::SearchParams());
  std::sort(out.begin(), out.end(), before);
}

} // namespace zdg
