#include <zdg/arith/floor_sum.hpp>

#include <utility>

namespace zdg {

namespace {
// n (n - 1) / 2 without forming n (n - 1).
template <TowerInt I>
I triangle(const I& n) {
  return n % 2 == 0 ? I((n / 2) * (n - 1)) : I(n * ((n - 1) / 2));
}
} // namespace

template <TowerInt I>
I floor_sum(I n, I m, I a, I b) {
  if (n < 0) throw InvalidArgument("floor_sum: n = " + to_string(n) + " must be >= 0");
  if (m == 0) throw InvalidArgument("floor_sum: m must not be 0");
  if (m < 0) {
    m = -m;
    a = -a;
    b = -b;
  }
  I sum = 0;
  if (a < 0 || a >= m) {
    sum += floor_div(a, m) * triangle(n);
    a = mod(a, m);
  }
  if (b < 0 || b >= m) {
    sum += floor_div(b, m) * n;
    b = mod(b, m);
  }
  while (true) {
    if (a >= m) {
      sum += (a / m) * triangle(n);
      a %= m;
    }
    if (b >= m) {
      sum += (b / m) * n;
      b %= m;
    }
    I y_max = a * n + b;
    if (y_max < m) break;
    n = y_max / m;
    b = y_max % m;
    std::swap(m, a);
  }
  return sum;
}

Escalated<BigInt> floor_sum_exact(const BigInt& n, const BigInt& m, const BigInt& a,
                                  const BigInt& b) {
  return escalate([&]<class I>(std::type_identity<I>) {
    return to_bigint(floor_sum<I>(int_cast<I>(n), int_cast<I>(m), int_cast<I>(a), int_cast<I>(b)));
  });
}

template Int64 floor_sum<Int64>(Int64, Int64, Int64, Int64);
template Int128 floor_sum<Int128>(Int128, Int128, Int128, Int128);
template BigInt floor_sum<BigInt>(BigInt, BigInt, BigInt, BigInt);

} // namespace zdg
