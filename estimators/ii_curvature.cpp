#include "estimators/ii_curvature.hpp"

#include "arith/error.hpp"

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <string>

namespace zdg {

DigitalBallCounter::DigitalBallCounter(const GaussDigitization2& set, double radius_pixels)
    : set_(set) {
  if (!(radius_pixels >= 0) || radius_pixels > 1e8) {
    throw InvalidArgument("digital ball radius " + std::to_string(radius_pixels) +
                          " pixels is out of range [0, 1e8]");
  }
  const double r2 = radius_pixels * radius_pixels;
  rr_ = static_cast<std::int64_t>(std::floor(radius_pixels));
  while (static_cast<double>((rr_ + 1) * (rr_ + 1)) <= r2) ++rr_;
  while (rr_ > 0 && static_cast<double>(rr_ * rr_) > r2) --rr_;
  w_.resize(static_cast<std::size_t>(2 * rr_ + 1));
  for (std::int64_t dy = -rr_; dy <= rr_; ++dy) {
    auto w = static_cast<std::int64_t>(std::floor(std::sqrt(std::max(0.0, r2 - double(dy * dy)))));
    while (static_cast<double>((w + 1) * (w + 1) + dy * dy) <= r2) ++w;
    while (w > 0 && static_cast<double>(w * w + dy * dy) > r2) --w;
    w_[static_cast<std::size_t>(dy + rr_)] = w;
  }
  add_.reserve(w_.size());
  rem_.reserve(w_.size());
}

std::int64_t DigitalBallCounter::ball_size() const {
  std::int64_t n = 0;
  for (auto w : w_) n += 2 * w + 1;
  return n;
}

std::int64_t DigitalBallCounter::direct_count(const Pixel& c) const {
  std::vector<Pixel> row;
  std::int64_t n = 0;
  for (std::int64_t dy = -rr_; dy <= rr_; ++dy) {
    std::int64_t w = w_[static_cast<std::size_t>(dy + rr_)];
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
  for (std::int64_t k = -rr_; k <= rr_; ++k) {
    std::int64_t w = w_[static_cast<std::size_t>(k + rr_)];
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
  if (!placed_ || std::llabs(dx) + std::llabs(dy) > rr_) {
    c_ = c;
    count_ = direct_count(c);
    placed_ = true;
    return count_;
  }
  for (std::int64_t i = 0; i < std::llabs(dx); ++i) step(dx > 0 ? 0 : 2);
  for (std::int64_t i = 0; i < std::llabs(dy); ++i) step(dy > 0 ? 1 : 3);
  return count_;
}

std::vector<double> ii_curvature(const GaussDigitization2& set, const DigitalContour& contour,
                                 double h, double radius) {
  if (!(h > 0) || !(radius > 0)) {
    throw InvalidArgument("ii_curvature: h and R must be > 0 (h = " + std::to_string(h) +
                          ", R = " + std::to_string(radius) + ")");
  }
  DigitalBallCounter inner(set, radius / h), outer(set, radius / h);
  std::vector<double> out;
  out.reserve(contour.size());
  const double k0 = 3 * std::numbers::pi / (2 * radius), k1 = 3 / (radius * radius * radius);
  Pixel p = contour.start;
  for (auto code : contour.codes) {
    std::int64_t a = inner.move_to(DigitalContour::inner_pixel(p, code));
    std::int64_t b = outer.move_to(DigitalContour::outer_pixel(p, code));
    double area = h * h * 0.5 * static_cast<double>(a + b);
    out.push_back(k0 - k1 * area);
    Pixel d = freeman_step(code);
    p = Pixel{p.x + d.x, p.y + d.y};
  }
  return out;
}

} // namespace zdg
