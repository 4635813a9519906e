#include <zdg/arith/dss_recognizer.hpp>

#include <string>

namespace zdg {

template class DssRecognizer<Int64>;
template class DssRecognizer<Int128>;
template class DssRecognizer<BigInt>;

namespace {

template <class T>
BigInt big(const T& v) {
  if constexpr (std::same_as<T, BigInt>) {
    return v;
  } else {
    return BigInt(v);
  }
}

template <class T>
Connectivity connectivity_of(std::span<const Point2<T>> path) {
  Connectivity c = Connectivity::four;
  for (std::size_t k = 1; k < path.size(); ++k) {
    BigInt dx = big(path[k].x) - big(path[k - 1].x), dy = big(path[k].y) - big(path[k - 1].y);
    BigInt ax = abs(dx), ay = abs(dy);
    if (ax > 1 || ay > 1 || (ax == 0 && ay == 0)) {
      throw InvalidArgument("path: point " + std::to_string(k) + " (" + big(path[k].x).str() +
                            ", " + big(path[k].y).str() + ") is not 8-adjacent to point " +
                            std::to_string(k - 1) + " (" + big(path[k - 1].x).str() + ", " +
                            big(path[k - 1].y).str() + ")");
    }
    if (ax == 1 && ay == 1) c = Connectivity::eight;
  }
  return c;
}

template <TowerInt I, class T>
Point2<I> cast(const Point2<T>& p) {
  return {int_cast<I>(p.x), int_cast<I>(p.y)};
}

template <TowerInt I, class T>
DssRecognition run(std::span<const Point2<T>> path, Connectivity c) {
  DssRecognizer<I> rec(cast<I>(path[0]), c);
  std::size_t k = 1;
  const std::size_t n = path.size();
  for (; k < n; ++k) {
    if (!rec.extend_front(cast<I>(path[k]))) break;
  }
  DssRecognition out;
  out.is_dss = k == n;
  out.longest_prefix = k;
  out.connectivity = c;
  out.characteristics = rec.characteristics();
  return out;
}

template <class T>
Escalated<DssRecognition> recognize(std::span<const Point2<T>> path, Connectivity c) {
  if (path.empty()) throw InvalidArgument("DSS recognition: the path has no point");
  return escalate([&]<class I>(std::type_identity<I>) { return run<I>(path, c); });
}

} // namespace

Connectivity path_connectivity(std::span<const Point2<std::int64_t>> path) {
  // Fast path without BigInt: differences of int64 fit in __int128.
  Connectivity c = Connectivity::four;
  for (std::size_t k = 1; k < path.size(); ++k) {
    int128_t dx = int128_t(path[k].x) - path[k - 1].x, dy = int128_t(path[k].y) - path[k - 1].y;
    if (dx < -1 || dx > 1 || dy < -1 || dy > 1 || (dx == 0 && dy == 0)) {
      return connectivity_of(path); // throws with the message
    }
    if (dx != 0 && dy != 0) c = Connectivity::eight;
  }
  return c;
}

Connectivity path_connectivity(std::span<const Point2<BigInt>> path) {
  return connectivity_of(path);
}

template <TowerInt I>
DssRecognition recognize_dss(std::span<const Point2<I>> path, Connectivity c) {
  if (path.empty()) throw InvalidArgument("DSS recognition: the path has no point");
  return run<I>(path, c);
}

template DssRecognition recognize_dss<Int64>(std::span<const Point2<Int64>>, Connectivity);
template DssRecognition recognize_dss<Int128>(std::span<const Point2<Int128>>, Connectivity);
template DssRecognition recognize_dss<BigInt>(std::span<const Point2<BigInt>>, Connectivity);

Escalated<DssRecognition> recognize_dss_exact(std::span<const Point2<std::int64_t>> path,
                                              Connectivity c) {
  return recognize(path, c);
}

Escalated<DssRecognition> recognize_dss_exact(std::span<const Point2<BigInt>> path,
                                              Connectivity c) {
  return recognize(path, c);
}

} // namespace zdg
