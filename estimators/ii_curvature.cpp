#include <zdg/estimators/ii_curvature.hpp>

#include <zdg/arith/error.hpp>

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <string>

namespace zdg {

DigitalBallCounter::DigitalBallCounter(const GaussDigitization2& set, double radius_pixels)
    : set_(set), disc_(radius_pixels) {
  add_.reserve(disc_.w.size());
  rem_.reserve(disc_.w.size());
}

std::int64_t DigitalBallCounter::direct_count(const Pixel& c) const {
  std::vector<Pixel> row;
  std::int64_t n = 0;
  for (std::int64_t dy = -disc_.r; dy <= disc_.r; ++dy) {
    std::int64_t w = disc_.half_width(dy);
    row.clear();
    for (std::int64_t dx = -w; dx <= w; ++dx) row.push_back(Pixel{c.x + dx, c.y + dy});
    n += set_.count(row);
  }
  return n;
}

// Unit move of the centre along Freeman code `code`.
void DigitalBallCounter::step(int code) {
  add_.clear();
  rem_.clear();
  for (std::int64_t k = -disc_.r; k <= disc_.r; ++k) {
    std::int64_t w = disc_.half_width(k);
    switch (code) {
    case 0:
      rem_.push_back({c_.x - w, c_.y + k});
      add_.push_back({c_.x + w + 1, c_.y + k});
      break;
    case 2:
      rem_.push_back({c_.x + w, c_.y + k});
      add_.push_back({c_.x - w - 1, c_.y + k});
      break;
    case 1:
      rem_.push_back({c_.x + k, c_.y - w});
      add_.push_back({c_.x + k, c_.y + w + 1});
      break;
    default:
      rem_.push_back({c_.x + k, c_.y + w});
      add_.push_back({c_.x + k, c_.y - w - 1});
      break;
    }
  }
  count_ += set_.count(add_) - set_.count(rem_);
  Pixel d = freeman_step(code);
  c_ = Pixel{c_.x + d.x, c_.y + d.y};
}

std::int64_t DigitalBallCounter::move_to(const Pixel& c) {
  const std::int64_t dx = c.x - c_.x, dy = c.y - c_.y;
  if (!placed_ || std::llabs(dx) + std::llabs(dy) > disc_.r) {
    c_ = c;
    count_ = direct_count(c);
    placed_ = true;
    return count_;
  }
  for (std::int64_t i = 0; i < std::llabs(dx); ++i) step(dx > 0 ? 0 : 2);
  for (std::int64_t i = 0; i < std::llabs(dy); ++i) step(dy > 0 ? 1 : 3);
  return count_;
}

namespace {

void check_steps(double h, double radius) {
  if (!(h > 0) || !(radius > 0)) {
    throw InvalidArgument("ii_curvature: h and R must be > 0 (h = " + std::to_string(h) +
                          ", R = " + std::to_string(radius) + ")");
  }
}

// kappa = 3 pi / (2R) - 3 A / R^3 at every linel, A = h^2 (count(inner) + count(outer)) / 2.
template <class Count>
std::vector<double> ii_along(const DigitalContour& contour, double h, double radius,
                             Count&& count) {
  std::vector<double> out;
  out.reserve(contour.size());
  const double k0 = 3 * std::numbers::pi / (2 * radius), k1 = 3 / (radius * radius * radius);
  Pixel p = contour.start;
  for (auto code : contour.codes) {
    const std::int64_t both = count(DigitalContour::inner_pixel(p, code), 0) +
                              count(DigitalContour::outer_pixel(p, code), 1);
    out.push_back(k0 - k1 * (h * h * 0.5 * static_cast<double>(both)));
    Pixel d = freeman_step(code);
    p = Pixel{p.x + d.x, p.y + d.y};
  }
  return out;
}

} // namespace

std::vector<double> ii_curvature(const GaussDigitization2& set, const DigitalContour& contour,
                                 double h, double radius) {
  check_steps(h, radius);
  DigitalBallCounter inner(set, radius / h), outer(set, radius / h);
  return ii_along(contour, h, radius, [&](const Pixel& c, int which) {
    return which == 0 ? inner.move_to(c) : outer.move_to(c);
  });
}

std::vector<double> ii_curvature(ContourBallCounter& counter, const DigitalContour& contour,
                                 double h, double radius) {
  check_steps(h, radius);
  const DigitalDisc expected(radius / h);
  if (expected.r != counter.disc().r || expected.w != counter.disc().w) {
    throw InvalidArgument("ii_curvature: the counter's disc is not the ball of radius R/h = " +
                          std::to_string(radius / h) + " pixels");
  }
  return ii_along(contour, h, radius, [&](const Pixel& c, int) { return counter.count(c); });
}

} // namespace zdg
