// Points of Z^2 and Z^3 (or of any coordinate type T: a tower integer, int64_t, double).
// Plain aggregates with lexicographic order; arithmetic helpers live with the algorithms.
#pragma once

#include <compare>
#include <ostream>

namespace zdg {

template <class T>
struct Point2 {
  T x{}, y{};
  friend bool operator==(const Point2&, const Point2&) = default;
  friend auto operator<=>(const Point2&, const Point2&) = default;
  friend std::ostream& operator<<(std::ostream& os, const Point2& p) {
    return os << '(' << p.x << ", " << p.y << ')';
  }
};

template <class T>
struct Point3 {
  T x{}, y{}, z{};
  friend bool operator==(const Point3&, const Point3&) = default;
  friend auto operator<=>(const Point3&, const Point3&) = default;
  friend std::ostream& operator<<(std::ostream& os, const Point3& p) {
    return os << '(' << p.x << ", " << p.y << ", " << p.z << ')';
  }
};

} // namespace zdg
