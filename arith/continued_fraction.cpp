#include <zdg/arith/continued_fraction.hpp>

namespace zdg {

template <TowerInt I>
std::vector<I> continued_fraction(I p, I q) {
  if (q == 0)
    throw InvalidArgument("continued fraction of " + to_string(p) + "/0: zero denominator");
  if (q < 0) {
    p = -p;
    q = -q;
  }
  std::vector<I> terms;
  // Euclid with floor division: p = a q + r, 0 <= r < q.
  while (q != 0) {
    I a = floor_div(p, q);
    I r = floor_mod(p, q); // not p - a q: that product can leave the type while r fits
    terms.push_back(std::move(a));
    p = std::move(q);
    q = std::move(r);
  }
  return terms;
}

template <TowerInt I>
std::vector<std::pair<I, I>> convergents(std::span<const I> terms) {
  std::vector<std::pair<I, I>> out;
  out.reserve(terms.size());
  I p2 = 0, q2 = 1, p1 = 1, q1 = 0;
  for (std::size_t k = 0; k < terms.size(); ++k) {
    if (k > 0 && terms[k] < 1) {
      throw InvalidArgument("continued fraction term a" + std::to_string(k) + " = " +
                            to_string(terms[k]) + " must be >= 1");
    }
    I p = terms[k] * p1 + p2;
    I q = terms[k] * q1 + q2;
    p2 = std::move(p1);
    q2 = std::move(q1);
    p1 = p;
    q1 = q;
    out.emplace_back(std::move(p), std::move(q));
  }
  return out;
}

template <TowerInt I>
Rational<I> from_continued_fraction(std::span<const I> terms) {
  if (terms.empty()) throw InvalidArgument("empty continued fraction");
  auto c = convergents(terms);
  return Rational<I>(c.back().first, c.back().second);
}

#define ZDG_INSTANTIATE(I)                                                                         \
  template std::vector<I> continued_fraction<I>(I, I);                                             \
  template Rational<I> from_continued_fraction<I>(std::span<const I>);                             \
  template std::vector<std::pair<I, I>> convergents<I>(std::span<const I>);
ZDG_INSTANTIATE(Int64)
ZDG_INSTANTIATE(Int128)
ZDG_INSTANTIATE(BigInt)
#undef ZDG_INSTANTIATE

} // namespace zdg
