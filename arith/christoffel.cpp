#include <zdg/arith/christoffel.hpp>

#include <algorithm>

namespace zdg {

namespace {
template <TowerInt I>
void check_slope(const I& p, const I& q) {
  if (p < 0 || q <= 0 || gcd(p, q) != 1) {
    throw InvalidArgument("Christoffel word: slope " + to_string(p) + "/" + to_string(q) +
                          " must have p >= 0, q > 0 and gcd(p, q) = 1");
  }
}

// Also valid for 1/0, whose word is "1" (a Stern-Brocot root, used by the factorization).
template <TowerInt I>
std::string generate(const I& p, const I& q) {
  I n = p + q;
  if (n > I(static_cast<std::int64_t>(christoffel_max_letters))) {
    throw InvalidArgument("Christoffel word of " + to_string(p) + "/" + to_string(q) + " has " +
                          to_string(n) + " letters, more than the limit " +
                          std::to_string(christoffel_max_letters));
  }
  const auto len = static_cast<std::size_t>(to_double(n));
  std::string w(len, '0');
  // r = k p mod n, maintained incrementally: letter k is 1 exactly when r wraps.
  I r = 0;
  for (std::size_t k = 0; k < len; ++k) {
    r += p;
    if (r >= n) {
      r -= n;
      w[k] = '1';
    }
  }
  return w;
}
} // namespace

template <TowerInt I>
std::string lower_christoffel_word(const I& p, const I& q) {
  check_slope(p, q);
  return generate(p, q);
}

template <TowerInt I>
std::string upper_christoffel_word(const I& p, const I& q) {
  std::string w = lower_christoffel_word(p, q);
  std::reverse(w.begin(), w.end());
  return w;
}

template <TowerInt I>
I christoffel_prefix_ones(const I& p, const I& q, const I& k) {
  check_slope(p, q);
  I n = p + q;
  if (k < 0 || k > n) {
    throw InvalidArgument("Christoffel prefix length " + to_string(k) + " is outside [0, " +
                          to_string(n) + "]");
  }
  return floor_div(I(k * p), n);
}

template <TowerInt I>
int christoffel_letter(const I& p, const I& q, const I& k) {
  I n = p + q;
  if (k < 1 || k > n) {
    throw InvalidArgument("Christoffel letter index " + to_string(k) + " is outside [1, " +
                          to_string(n) + "]");
  }
  I d = christoffel_prefix_ones(p, q, k) - christoffel_prefix_ones(p, q, I(k - 1));
  return d == 0 ? 0 : 1;
}

template <TowerInt I>
StandardFactorization<I> standard_factorization(const I& p, const I& q) {
  check_slope(p, q);
  if (p == 0) {
    throw InvalidArgument("Christoffel word of 0/1 is the single letter 0: it has no standard "
                          "factorization");
  }
  auto parents = stern_brocot_parents(p, q);
  return {generate(parents.left.p, parents.left.q), generate(parents.right.p, parents.right.q),
          parents};
}

std::string conjugate(const std::string& w, std::size_t k) {
  if (w.empty()) return w;
  k %= w.size();
  return w.substr(k) + w.substr(0, k);
}

#define ZDG_INSTANTIATE(I)                                                                         \
  template std::string lower_christoffel_word<I>(const I&, const I&);                              \
  template std::string upper_christoffel_word<I>(const I&, const I&);                              \
  template I christoffel_prefix_ones<I>(const I&, const I&, const I&);                             \
  template int christoffel_letter<I>(const I&, const I&, const I&);                                \
  template StandardFactorization<I> standard_factorization<I>(const I&, const I&);
ZDG_INSTANTIATE(Int64)
ZDG_INSTANTIATE(Int128)
ZDG_INSTANTIATE(BigInt)
#undef ZDG_INSTANTIATE

} // namespace zdg
