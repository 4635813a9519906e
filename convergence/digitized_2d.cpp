#include <zdg/convergence/digitized_2d.hpp>

#include <zdg/arith/error.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace zdg::detail {

const Shape2& as_2d(const Shape& s) {
  const auto* p = dynamic_cast<const Shape2*>(&s);
  if (p == nullptr) throw InvalidArgument("shape '" + s.spec() + "' is not a 2D shape");
  return *p;
}

Box2 pixel_box(const std::vector<std::pair<double, double>>& box, double h) {
  if (box.size() != 2) throw InvalidArgument("a 2D run needs a box with 2 axes");
  auto lo = [&](double v) { return static_cast<std::int64_t>(std::floor(v / h)) - 1; };
  auto hi = [&](double v) { return static_cast<std::int64_t>(std::ceil(v / h)) + 1; };
  double span = std::max(box[0].second - box[0].first, box[1].second - box[1].first) / h;
  const double far = std::max({std::abs(box[0].first), std::abs(box[0].second),
                               std::abs(box[1].first), std::abs(box[1].second)}) /
                     h;
  if (!(span < 4e9) || !(far < 1e15)) {
    std::ostringstream msg;
    msg << "grid step h = " << h << " is too small for the box";
    throw InvalidArgument(msg.str());
  }
  return Box2{{lo(box[0].first), lo(box[1].first)}, {hi(box[0].second), hi(box[1].second)}};
}

namespace {

bool certified_complete(const Digitized2& d, double h) {
  const auto reach = d.shape->reach_lower_bound();
  const auto bb = d.shape->bounding_box();
  if (!reach || !(h <= *reach / 2) || !bb || bb->size() != 2) return false;
  const double margin = 2 * h;
  const auto& x = (*bb)[0];
  const auto& y = (*bb)[1];
  const bool inside = static_cast<double>(d.box.lo.x) * h < x.first + d.t.x - margin &&
                      x.second + d.t.x + margin < static_cast<double>(d.box.hi.x) * h &&
                      static_cast<double>(d.box.lo.y) * h < y.first + d.t.y - margin &&
                      y.second + d.t.y + margin < static_cast<double>(d.box.hi.y) * h;
  return inside && d.contours.size() == 1 && d.contours.front().twice_signed_area() > 0;
}

} // namespace

Digitized2 digitize_2d(const RunInput& in) {
  Digitized2 d;
  d.shape = &as_2d(in.shape);
  d.t = {in.translation.at(0), in.translation.at(1)};
  d.box = pixel_box(in.box, in.h);
  d.set = d.shape->digitize(in.h, d.t, d.box);
  // Scan 9 rows and 9 columns spread over the box (and the axes) for contours.
  std::vector<std::int64_t> rows{0}, cols{0};
  for (int i = 1; i <= 9; ++i) {
    rows.push_back(d.box.lo.y + (d.box.hi.y - d.box.lo.y) * i / 10);
    cols.push_back(d.box.lo.x + (d.box.hi.x - d.box.lo.x) * i / 10);
  }
  d.contours = digital_contours(*d.set, rows, cols);
  d.complete = certified_complete(d, in.h);
  d.embed = ContourEmbedding{in.h};
  return d;
}

} // namespace zdg::detail
