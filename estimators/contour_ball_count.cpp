#include <zdg/estimators/contour_ball_count.hpp>

#include <zdg/arith/error.hpp>

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>

namespace zdg {

namespace {

constexpr std::size_t kBlock = 8;
constexpr std::int64_t kLimit = std::int64_t{1} << 40;
constexpr std::int64_t kEmptyLo = std::int64_t{1} << 50;
constexpr std::int64_t kEmptyHi = -(std::int64_t{1} << 50);

int128_t cross(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by) {
  return static_cast<int128_t>(ax) * by - static_cast<int128_t>(ay) * bx;
}

void check_range(std::int64_t v, const char* what) {
  if (v <= -kLimit || v >= kLimit) {
    throw InvalidArgument(std::string("ContourBallCounter: ") + what + " " + std::to_string(v) +
                          " is beyond 2^40 from the first contour");
  }
}

} // namespace

ContourBallCounter::ContourBallCounter(const GaussDigitization2& set,
                                       std::span<const DigitalContour> contours,
                                       double radius_pixels)
    : set_(set), disc_(radius_pixels) {
  if (disc_.r > 1000000) {
    throw InvalidArgument("ContourBallCounter: disc radius " + std::to_string(disc_.r) +
                          " pixels is above 1e6");
  }
  if (!contours.empty()) origin_ = contours.front().start;
  for (const auto& c : contours) {
    Chain ch;
    ch.n = c.size();
    if (ch.n == 0) continue;
    ch.px.resize(ch.n + 1);
    ch.py.resize(ch.n + 1);
    ch.ax.resize(ch.n);
    ch.ay.resize(ch.n);
    ch.bx.resize(ch.n);
    ch.by.resize(ch.n);
    ch.prefix.assign(ch.n + 1, 0);
    Pixel p = c.start;
    for (std::size_t j = 0; j < ch.n; ++j) {
      const int code = c.codes[j];
      ch.px[j] = p.x - origin_.x;
      ch.py[j] = p.y - origin_.y;
      check_range(ch.px[j], "pointel x");
      check_range(ch.py[j], "pointel y");
      Pixel a = DigitalContour::inner_pixel(p, code), b = DigitalContour::outer_pixel(p, code);
      ch.ax[j] = a.x - origin_.x;
      ch.ay[j] = a.y - origin_.y;
      ch.bx[j] = b.x - origin_.x;
      ch.by[j] = b.y - origin_.y;
      Pixel d = freeman_step(code);
      p = Pixel{p.x + d.x, p.y + d.y};
    }
    if (!(p == c.start)) throw InvalidArgument("ContourBallCounter: a contour is not closed");
    ch.px[ch.n] = ch.px[0];
    ch.py[ch.n] = ch.py[0];
    for (std::size_t j = 0; j < ch.n; ++j) {
      ch.prefix[j + 1] = ch.prefix[j] + cross(ch.px[j], ch.py[j], ch.px[j + 1], ch.py[j + 1]);
    }
    const std::size_t blocks = (ch.n + kBlock - 1) / kBlock;
    while (ch.leaves < blocks) ch.leaves *= 2;
    ch.x0.assign(2 * ch.leaves, kEmptyLo);
    ch.x1.assign(2 * ch.leaves, kEmptyHi);
    ch.y0.assign(2 * ch.leaves, kEmptyLo);
    ch.y1.assign(2 * ch.leaves, kEmptyHi);
    for (std::size_t j = 0; j < ch.n; ++j) {
      const std::size_t node = ch.leaves + j / kBlock;
      ch.x0[node] = std::min({ch.x0[node], ch.ax[j], ch.bx[j]});
      ch.x1[node] = std::max({ch.x1[node], ch.ax[j], ch.bx[j]});
      ch.y0[node] = std::min({ch.y0[node], ch.ay[j], ch.by[j]});
      ch.y1[node] = std::max({ch.y1[node], ch.ay[j], ch.by[j]});
    }
    for (std::size_t node = ch.leaves - 1; node >= 1; --node) {
      ch.x0[node] = std::min(ch.x0[2 * node], ch.x0[2 * node + 1]);
      ch.x1[node] = std::max(ch.x1[2 * node], ch.x1[2 * node + 1]);
      ch.y0[node] = std::min(ch.y0[2 * node], ch.y0[2 * node + 1]);
      ch.y1[node] = std::max(ch.y1[2 * node], ch.y1[2 * node + 1]);
    }
    chains_.push_back(std::move(ch));
  }
  // The boundary of D, counter-clockwise from the bottom linel of pixel (0, -r).
  DigitalDiscSet dset(disc_);
  DigitalContour boundary = track_contour(dset, Pixel{0, -disc_.r}, 0);
  first_inner_ = DigitalContour::inner_pixel(boundary.start, boundary.codes.front());
  const std::size_t L = boundary.size();
  bx_.resize(L + 1);
  by_.resize(L + 1);
  bprefix_.assign(L + 1, 0);
  bindex_.reserve(L);
  Pixel p = boundary.start;
  for (std::size_t k = 0; k < L; ++k) {
    bx_[k] = p.x;
    by_[k] = p.y;
    bindex_.emplace(key(p.x, p.y), k);
    Pixel d = freeman_step(boundary.codes[k]);
    p = Pixel{p.x + d.x, p.y + d.y};
  }
  bx_[L] = bx_[0];
  by_[L] = by_[0];
  for (std::size_t k = 0; k < L; ++k) {
    bprefix_[k + 1] = bprefix_[k] + cross(bx_[k], by_[k], bx_[k + 1], by_[k + 1]);
  }
}

std::int64_t ContourBallCounter::key(std::int64_t x, std::int64_t y) const {
  const std::int64_t side = 2 * disc_.r + 4;
  return (y + disc_.r + 1) * side + (x + disc_.r + 1);
}

void ContourBallCounter::add_linels(std::size_t a, std::size_t b) {
  if (!runs_.empty() && runs_.back().end + 1 == a) {
    runs_.back().end = b;
  } else {
    runs_.push_back(Run{a, b});
  }
}

void ContourBallCounter::collect(const Chain& ch, std::size_t node, std::size_t lo, std::size_t hi,
                                 std::int64_t cx, std::int64_t cy) {
  const std::int64_t x0 = ch.x0[node] - cx, x1 = ch.x1[node] - cx;
  const std::int64_t y0 = ch.y0[node] - cy, y1 = ch.y1[node] - cy;
  if (x0 > x1 || disc_.misses_rect(x0, x1, y0, y1)) return;
  const std::size_t first = lo * kBlock;
  if (first >= ch.n) return;
  const std::size_t last = std::min(hi * kBlock, ch.n) - 1;
  if (disc_.contains_rect(x0, x1, y0, y1)) {
    add_linels(first, last);
    return;
  }
  if (hi - lo == 1) {
    for (std::size_t j = first; j <= last; ++j) {
      if (disc_.contains(ch.ax[j] - cx, ch.ay[j] - cy) &&
          disc_.contains(ch.bx[j] - cx, ch.by[j] - cy)) {
        add_linels(j, j);
      }
    }
    return;
  }
  const std::size_t mid = (lo + hi) / 2;
  collect(ch, 2 * node, lo, mid, cx, cy);
  collect(ch, 2 * node + 1, mid, hi, cx, cy);
}

std::int64_t ContourBallCounter::count(const Pixel& c) {
  const std::int64_t cx = c.x - origin_.x, cy = c.y - origin_.y;
  check_range(cx, "centre x");
  check_range(cy, "centre y");
  int128_t twice = 0;
  flips_.clear();
  auto junction = [&](std::int64_t x, std::int64_t y) {
    const std::int64_t rx = x - cx, ry = y - cy;
    auto it = bindex_.end();
    if (std::llabs(rx) <= disc_.r + 1 && std::llabs(ry) <= disc_.r + 1)
      it = bindex_.find(key(rx, ry));
    if (it == bindex_.end()) {
      throw std::logic_error(
          "ContourBallCounter: a run of inner linels ends off the disc boundary");
    }
    flips_.push_back(it->second);
  };
  for (const auto& ch : chains_) {
    runs_.clear();
    collect(ch, 1, 0, ch.leaves, cx, cy);
    if (runs_.empty()) continue;
    if (runs_.size() == 1 && runs_.front().begin == 0 && runs_.front().end == ch.n - 1) {
      twice += ch.prefix[ch.n]; // the whole contour lies in D
      continue;
    }
    if (runs_.size() >= 2 && runs_.front().begin == 0 && runs_.back().end == ch.n - 1) {
      runs_.front().begin = runs_.back().begin; // wraps around the start
      runs_.pop_back();
    }
    for (const auto& run : runs_) {
      const std::size_t b = run.begin, e = run.end + 1;
      int128_t s =
          b < e ? ch.prefix[e] - ch.prefix[b] : (ch.prefix[ch.n] - ch.prefix[b]) + ch.prefix[e];
      // Shoelace terms relative to the centre: cross(p - c, q - c) = cross(p, q) - cross(c, q - p).
      s -= cross(cx, cy, ch.px[e] - ch.px[b], ch.py[e] - ch.py[b]);
      twice += s;
      junction(ch.px[b], ch.py[b]);
      junction(ch.px[e], ch.py[e]);
    }
  }
  std::sort(flips_.begin(), flips_.end());
  bool in = set_.contains(Pixel{c.x + first_inner_.x, c.y + first_inner_.y});
  std::size_t from = 0;
  for (std::size_t k : flips_) {
    if (k == 0) continue; // the toggle between the last and the first boundary linel
    if (in) twice += bprefix_[k] - bprefix_[from];
    from = k;
    in = !in;
  }
  if (in) twice += bprefix_.back() - bprefix_[from];
  if (twice % 2 != 0 || twice < 0 || twice > 2 * static_cast<int128_t>(disc_.size)) {
    throw std::logic_error("ContourBallCounter: inconsistent count (incomplete contours?)");
  }
  return static_cast<std::int64_t>(twice / 2);
}

} // namespace zdg
