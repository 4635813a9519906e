#include <zdg/kernel/curves/digital_contour.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/arith/integer.hpp>

#include <algorithm>
#include <set>
#include <string>
#include <utility>

namespace zdg {

namespace {
std::string str(const Pixel& p) {
  return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")";
}
} // namespace

std::vector<Pixel> DigitalContour::pointels() const {
  std::vector<Pixel> out;
  out.reserve(codes.size());
  Pixel p = start;
  for (auto c : codes) {
    out.push_back(p);
    Pixel d = freeman_step(c);
    p = Pixel{p.x + d.x, p.y + d.y};
  }
  return out;
}

std::int64_t DigitalContour::twice_signed_area() const {
  Int128 s = 0;
  Pixel p = start;
  for (auto c : codes) {
    Pixel d = freeman_step(c);
    Pixel q{p.x + d.x, p.y + d.y};
    s += Int128(p.x) * Int128(q.y) - Int128(q.x) * Int128(p.y);
    p = q;
  }
  return int_cast<Int64>(s).value();
}

// The linel from p to p + d has its midpoint at p + d/2 - (1/2, 1/2) in pixel coordinates;
// its left normal is l = (-d.y, d.x): the inner pixel is the midpoint + l/2.
Pixel DigitalContour::inner_pixel(const Pixel& p, int code) {
  Pixel d = freeman_step(code);
  return Pixel{(2 * p.x + d.x - 1 - d.y) / 2, (2 * p.y + d.y - 1 + d.x) / 2};
}

Pixel DigitalContour::outer_pixel(const Pixel& p, int code) {
  Pixel d = freeman_step(code);
  // (2p + d - (1,1) - l) / 2 with l = (-d.y, d.x); the numerators are even.
  return Pixel{(2 * p.x + d.x - 1 + d.y) / 2, (2 * p.y + d.y - 1 - d.x) / 2};
}

DigitalContour track_contour(const GaussDigitization2& set, const Pixel& start, int code) {
  if (!set.contains(DigitalContour::inner_pixel(start, code)) ||
      set.contains(DigitalContour::outer_pixel(start, code))) {
    throw InvalidArgument("track_contour: the linel from pointel " + str(start) + " with code " +
                          std::to_string(code) + " is not a boundary linel");
  }
  DigitalContour c;
  c.start = start;
  Pixel p = start;
  int dir = code;
  do {
    c.codes.push_back(static_cast<std::uint8_t>(dir));
    Pixel d = freeman_step(dir);
    Pixel in = DigitalContour::inner_pixel(p, dir), out = DigitalContour::outer_pixel(p, dir);
    Pixel ahead_left{in.x + d.x, in.y + d.y}, ahead_right{out.x + d.x, out.y + d.y};
    p = Pixel{p.x + d.x, p.y + d.y};
    if (set.contains(ahead_left)) {
      if (set.contains(ahead_right)) dir = (dir + 3) & 3; // turn right
    } else {
      dir = (dir + 1) & 3; // turn left
    }
  } while (!(p == start && dir == code));
  return c;
}

std::vector<DigitalContour> digital_contours(const GaussDigitization2& set,
                                             const std::vector<std::int64_t>& rows,
                                             const std::vector<std::int64_t>& columns) {
  const Box2& box = set.box();
  std::vector<DigitalContour> out;
  // Linels already on a found contour, as (pointel, code).
  std::set<std::pair<Pixel, int>> seen;
  auto remember = [&](const DigitalContour& c, bool row_scan, std::int64_t line) {
    Pixel p = c.start;
    for (auto code : c.codes) {
      // Vertical linels (codes 1, 3) cross rows; horizontal ones (0, 2) cross columns.
      bool vertical = (code & 1) != 0;
      if (vertical == row_scan) {
        Pixel in = DigitalContour::inner_pixel(p, code);
        if ((row_scan ? in.y : in.x) == line) seen.insert({p, static_cast<int>(code)});
      }
      Pixel d = freeman_step(code);
      p = Pixel{p.x + d.x, p.y + d.y};
    }
  };
  auto scan = [&](bool row_scan, std::int64_t line) {
    std::int64_t lo = row_scan ? box.lo.x : box.lo.y, hi = row_scan ? box.hi.x : box.hi.y;
    if (line < (row_scan ? box.lo.y : box.lo.x) || line > (row_scan ? box.hi.y : box.hi.x)) return;
    auto at = [&](std::int64_t t) { return row_scan ? Pixel{t, line} : Pixel{line, t}; };
    bool prev = false; // outside the box
    for (std::int64_t t = lo; t <= hi + 1; ++t) {
      bool cur = t <= hi && set.contains(at(t));
      if (cur != prev) {
        // Crossing between t - 1 and t. Row scan: vertical linel at pointel x = t; code 3
        // (going down) when entering the set, code 1 when leaving. Column scan: horizontal
        // linel at pointel y = t; code 0 when entering, code 2 when leaving.
        Pixel p;
        int code;
        if (row_scan) {
          code = cur ? 3 : 1;
          p = cur ? Pixel{t, line + 1} : Pixel{t, line};
        } else {
          code = cur ? 0 : 2;
          p = cur ? Pixel{line, t} : Pixel{line + 1, t};
        }
        if (!seen.contains({p, code})) {
          DigitalContour c = track_contour(set, p, code);
          for (std::int64_t r : rows) remember(c, true, r);
          for (std::int64_t col : columns) remember(c, false, col);
          out.push_back(std::move(c));
        }
        prev = cur;
      }
    }
  };
  for (std::int64_t r : rows) scan(true, r);
  for (std::int64_t col : columns) scan(false, col);
  return out;
}

} // namespace zdg
