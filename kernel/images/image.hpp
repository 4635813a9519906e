// Dense n-D images on a box domain of Z^d.
//
// A Domain is the box prod_k [lower_k, lower_k + extent_k - 1] of Z^d (any d >= 1, lower
// bounds of any sign, extents >= 1). Points are stored in C order (the last axis is
// contiguous): the linear index of p is sum_k (p_k - lower_k) * stride_k with
// stride_{d-1} = 1 and stride_k = stride_{k+1} * extent_{k+1}. The number of points must fit
// int64 (checked at construction, InvalidArgument otherwise).
//
// Image<T> is a Domain plus one value of type T per point (a std::vector<T> in C order).
#pragma once

#include <zdg/arith/error.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace zdg {

class Domain {
public:
  Domain() = default;
  /// The box with these extents; lower bounds default to 0.
  explicit Domain(std::vector<std::int64_t> extents, std::vector<std::int64_t> lower = {})
      : extent_(std::move(extents)), lower_(std::move(lower)) {
    if (extent_.empty()) throw InvalidArgument("domain: dimension 0 (no axis)");
    if (lower_.empty()) lower_.assign(extent_.size(), 0);
    if (lower_.size() != extent_.size()) {
      throw InvalidArgument("domain: " + std::to_string(lower_.size()) + " lower bounds for " +
                            std::to_string(extent_.size()) + " axes");
    }
    stride_.assign(extent_.size(), 1);
    std::int64_t n = 1;
    for (std::size_t k = extent_.size(); k-- > 0;) {
      if (extent_[k] < 1) {
        throw InvalidArgument("domain: extent " + std::to_string(extent_[k]) + " of axis " +
                              std::to_string(k) + " is not positive");
      }
      std::int64_t up = 0;
      if (__builtin_add_overflow(lower_[k], extent_[k] - 1, &up)) {
        throw InvalidArgument("domain: axis " + std::to_string(k) + " leaves int64");
      }
      stride_[k] = n;
      if (__builtin_mul_overflow(n, extent_[k], &n)) {
        throw InvalidArgument("domain: the number of points does not fit int64");
      }
    }
    size_ = n;
  }

  int dim() const { return static_cast<int>(extent_.size()); }
  std::int64_t size() const { return size_; }
  std::int64_t extent(int k) const { return extent_[static_cast<std::size_t>(k)]; }
  std::int64_t lower(int k) const { return lower_[static_cast<std::size_t>(k)]; }
  std::int64_t upper(int k) const { return lower(k) + extent(k) - 1; }
  std::int64_t stride(int k) const { return stride_[static_cast<std::size_t>(k)]; }
  const std::vector<std::int64_t>& extents() const { return extent_; }
  const std::vector<std::int64_t>& lowers() const { return lower_; }

  bool contains(std::span<const std::int64_t> p) const {
    if (p.size() != extent_.size()) return false;
    for (int k = 0; k < dim(); ++k) {
      if (p[static_cast<std::size_t>(k)] < lower(k) || p[static_cast<std::size_t>(k)] > upper(k))
        return false;
    }
    return true;
  }
  /// Linear index of p (InvalidArgument when p is outside).
  std::int64_t index(std::span<const std::int64_t> p) const {
    if (!contains(p)) throw InvalidArgument("domain: point outside the domain");
    std::int64_t i = 0;
    for (int k = 0; k < dim(); ++k) i += (p[static_cast<std::size_t>(k)] - lower(k)) * stride(k);
    return i;
  }
  /// The point of linear index i (0 <= i < size()).
  void point(std::int64_t i, std::span<std::int64_t> out) const {
    for (int k = 0; k < dim(); ++k) {
      out[static_cast<std::size_t>(k)] = lower(k) + i / stride(k);
      i %= stride(k);
    }
  }
  std::vector<std::int64_t> point(std::int64_t i) const {
    std::vector<std::int64_t> p(extent_.size());
    point(i, p);
    return p;
  }

  friend bool operator==(const Domain& a, const Domain& b) {
    return a.extent_ == b.extent_ && a.lower_ == b.lower_;
  }

private:
  std::vector<std::int64_t> extent_, lower_, stride_;
  std::int64_t size_ = 0;
};

template <class T>
class Image {
public:
  Image() = default;
  explicit Image(Domain domain, const T& fill = T{})
      : domain_(std::move(domain)), data_(static_cast<std::size_t>(domain_.size()), fill) {}
  Image(Domain domain, std::vector<T> data) : domain_(std::move(domain)), data_(std::move(data)) {
    if (static_cast<std::int64_t>(data_.size()) != domain_.size()) {
      throw InvalidArgument("image: " + std::to_string(data_.size()) + " values for " +
                            std::to_string(domain_.size()) + " points");
    }
  }

  const Domain& domain() const { return domain_; }
  int dim() const { return domain_.dim(); }
  std::int64_t size() const { return domain_.size(); }
  T& operator[](std::int64_t i) { return data_[static_cast<std::size_t>(i)]; }
  const T& operator[](std::int64_t i) const { return data_[static_cast<std::size_t>(i)]; }
  T& at(std::span<const std::int64_t> p) { return (*this)[domain_.index(p)]; }
  const T& at(std::span<const std::int64_t> p) const { return (*this)[domain_.index(p)]; }
  std::vector<T>& values() { return data_; }
  const std::vector<T>& values() const { return data_; }

  friend bool operator==(const Image& a, const Image& b) {
    return a.domain_ == b.domain_ && a.data_ == b.data_;
  }

private:
  Domain domain_;
  std::vector<T> data_;
};

} // namespace zdg
