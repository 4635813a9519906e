// Points and vectors of Z^2 and Z^3 (or of any coordinate type T: a tower integer, int64_t,
// double): the one lattice point type of zdg, in the lowest layer that needs it.
//
//   a + b, a - b, -a, k * a, a * k      component-wise (a vector space over T)
//   dot(a, b)                           a.x b.x + a.y b.y (+ a.z b.z)
//   cross(a, b)                         2D: the determinant a.x b.y - a.y b.x (a scalar);
//                                       3D: the vector product
//   ==, <=>                             lexicographic order on (x, y[, z])
//
// Width: each operation costs one or two products of coordinates; on the tower types an
// overflow throws OverflowError (arith/integer.hpp), on int64_t it is the caller's to bound.
// Aggregates: Point2<T>{x, y}, Point3<T>{x, y, z}.
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
  friend Point2 operator+(const Point2& a, const Point2& b) { return {a.x + b.x, a.y + b.y}; }
  friend Point2 operator-(const Point2& a, const Point2& b) { return {a.x - b.x, a.y - b.y}; }
  friend Point2 operator-(const Point2& a) { return {-a.x, -a.y}; }
  friend Point2 operator*(const T& k, const Point2& a) { return {k * a.x, k * a.y}; }
  friend Point2 operator*(const Point2& a, const T& k) { return {a.x * k, a.y * k}; }
  Point2& operator+=(const Point2& b) { return *this = *this + b; }
  Point2& operator-=(const Point2& b) { return *this = *this - b; }
  friend T dot(const Point2& a, const Point2& b) { return a.x * b.x + a.y * b.y; }
  /// The determinant det(a, b) = a.x b.y - a.y b.x (> 0 when b is counterclockwise of a).
  friend T cross(const Point2& a, const Point2& b) { return a.x * b.y - a.y * b.x; }
};

template <class T>
struct Point3 {
  T x{}, y{}, z{};
  friend bool operator==(const Point3&, const Point3&) = default;
  friend auto operator<=>(const Point3&, const Point3&) = default;
  friend std::ostream& operator<<(std::ostream& os, const Point3& p) {
    return os << '(' << p.x << ", " << p.y << ", " << p.z << ')';
  }
  friend Point3 operator+(const Point3& a, const Point3& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
  }
  friend Point3 operator-(const Point3& a, const Point3& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
  }
  friend Point3 operator-(const Point3& a) { return {-a.x, -a.y, -a.z}; }
  friend Point3 operator*(const T& k, const Point3& a) { return {k * a.x, k * a.y, k * a.z}; }
  friend Point3 operator*(const Point3& a, const T& k) { return {a.x * k, a.y * k, a.z * k}; }
  Point3& operator+=(const Point3& b) { return *this = *this + b; }
  Point3& operator-=(const Point3& b) { return *this = *this - b; }
  friend T dot(const Point3& a, const Point3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
  friend Point3 cross(const Point3& a, const Point3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
  }
};

} // namespace zdg
