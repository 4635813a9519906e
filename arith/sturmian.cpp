#include <zdg/arith/sturmian.hpp>

#include <zdg/arith/continued_fraction.hpp>
#include <zdg/arith/error.hpp>

#include <map>
#include <span>

namespace zdg {

template <TowerInt I>
std::string QuadraticSurd<I>::str() const {
  // Appended piece by piece (GCC 12 warns falsely on "(" + std::string&&).
  std::string s = "(";
  s.append(to_string(P)).append(" + sqrt(").append(to_string(D)).append("))/");
  return s.append(to_string(Q));
}

template <TowerInt I>
I isqrt(const I& n) {
  if (n < 0) throw InvalidArgument("isqrt of the negative " + to_string(n));
  BigInt r = boost::multiprecision::sqrt(to_bigint(n));
  return int_cast<I>(r);
}

template <TowerInt I>
QuadraticSurd<I> make_surd(const I& a, const I& b, const I& d, const I& c) {
  std::string what = "(";
  what.append(to_string(a)).append(" + ").append(to_string(b)).append(" sqrt(");
  what.append(to_string(d)).append("))/").append(to_string(c));
  if (b == 0) throw InvalidArgument(what + ": b = 0 is a rational, not a quadratic surd");
  if (c == 0) throw InvalidArgument(what + ": zero denominator");
  if (d <= 0) throw InvalidArgument(what + ": d must be positive");
  const I s = isqrt(d);
  if (s * s == d) throw InvalidArgument(what + ": d is a perfect square");
  // (a + b sqrt d)/c = (a' + sqrt(b^2 d))/c' with a' = sign(b) a, c' = sign(b) c.
  I p = b > 0 ? a : I(-a);
  I q = b > 0 ? c : I(-c);
  I D = b * b * d;
  if (floor_mod(I(D - p * p), q) != 0) {
    const I m = abs(q);
    p = p * m;
    D = D * m * m;
    q = q * m;
  }
  return {p, D, q};
}

template <TowerInt I>
I floor_multiple(const QuadraticSurd<I>& x, const I& k) {
  // k x = (kP + sign(k) sqrt(k^2 D)) / Q, and sqrt(k^2 D) lies strictly between s and s + 1
  // (k^2 D is not a square): the numerator lies in (m, m + 1) with m = kP + s (k > 0) or
  // kP - s - 1 (k < 0); no multiple of |Q| lies strictly inside, so the floor is floor(m / Q)
  // for Q > 0 and floor((m + 1) / Q) for Q < 0.
  if (k == 0) return I(0);
  const I s = isqrt(I(k * k * x.D));
  const I m = k > 0 ? I(k * x.P + s) : I(k * x.P - s - 1);
  return x.Q > 0 ? floor_div(m, x.Q) : floor_div(I(m + 1), x.Q);
}

template <TowerInt I>
QuadraticSurd<I> fractional_part(const QuadraticSurd<I>& x) {
  const I f = floor_multiple(x, I(1));
  return {I(x.P - f * x.Q), x.D, x.Q};
}

template <TowerInt I>
PeriodicContinuedFraction<I> periodic_continued_fraction(const QuadraticSurd<I>& x,
                                                         std::size_t max_terms) {
  if (x.Q == 0) throw InvalidArgument("quadratic surd " + x.str() + ": zero denominator");
  if (x.D <= 0) throw InvalidArgument("quadratic surd " + x.str() + ": D must be positive");
  const I s = isqrt(x.D);
  if (s * s == x.D) throw InvalidArgument("quadratic surd " + x.str() + ": D is a square");
  if (floor_mod(I(x.D - x.P * x.P), x.Q) != 0) {
    throw InvalidArgument("quadratic surd " + x.str() + ": Q does not divide D - P^2");
  }
  std::vector<I> terms;
  std::map<std::pair<I, I>, std::size_t> seen; // (P_k, Q_k) -> k
  I P = x.P, Q = x.Q;
  for (;;) {
    auto [it, fresh] = seen.try_emplace({P, Q}, terms.size());
    if (!fresh) {
      const std::size_t start = it->second;
      PeriodicContinuedFraction<I> cf;
      cf.preperiod.assign(terms.begin(), terms.begin() + static_cast<std::ptrdiff_t>(start));
      cf.period.assign(terms.begin() + static_cast<std::ptrdiff_t>(start), terms.end());
      return cf;
    }
    if (terms.size() >= max_terms) {
      throw InvalidArgument("continued fraction of " + x.str() + ": no period within " +
                            std::to_string(max_terms) + " terms");
    }
    I a = Q > 0 ? floor_div(I(P + s), Q) : floor_div(I(P + s + 1), Q);
    P = a * Q - P;
    Q = (x.D - P * P) / Q;
    terms.push_back(std::move(a));
  }
}

Escalated<PeriodicContinuedFraction<BigInt>>
periodic_continued_fraction_exact(const BigInt& a, const BigInt& b, const BigInt& d,
                                  const BigInt& c, std::size_t max_terms) {
  return escalate([&]<class I>(std::type_identity<I>) {
    const auto cf = periodic_continued_fraction(
        make_surd(int_cast<I>(a), int_cast<I>(b), int_cast<I>(d), int_cast<I>(c)), max_terms);
    PeriodicContinuedFraction<BigInt> out;
    for (const auto& t : cf.preperiod) out.preperiod.push_back(to_bigint(t));
    for (const auto& t : cf.period) out.period.push_back(to_bigint(t));
    return out;
  });
}

namespace {
template <TowerInt I>
void require_unit_interval(const QuadraticSurd<I>& alpha) {
  const I f = floor_multiple(alpha, I(1));
  if (f != 0) {
    throw InvalidArgument("characteristic word: the slope " + alpha.str() +
                          " is not in (0, 1) (its floor is " + to_string(f) + ")");
  }
}
} // namespace

template <TowerInt I>
std::string characteristic_word(const QuadraticSurd<I>& alpha, std::size_t n) {
  require_unit_interval(alpha);
  std::string w;
  w.reserve(n);
  I prev = 0; // floor(1 alpha) = 0
  for (std::size_t k = 1; k <= n; ++k) {
    I next = floor_multiple(alpha, int_cast<I>(static_cast<std::int64_t>(k + 1)));
    w.push_back(next - prev == 0 ? '0' : '1');
    prev = std::move(next);
  }
  return w;
}

template <TowerInt I>
std::string standard_word_prefix(const PeriodicContinuedFraction<I>& alpha, std::size_t n) {
  if (alpha.term(0) != 0) {
    throw InvalidArgument("standard words: the slope's continued fraction starts with " +
                          to_string(alpha.term(0)) + ", not 0 (the slope is not in (0, 1))");
  }
  // t_{n} = t_{n-1}^{d_n} t_{n-2}, until the word has n letters (each t_k is a prefix of the
  // next for k >= 1, and the lengths grow at least like the Fibonacci numbers).
  std::string older = "1", old = "0";
  // t_1 = 0^(d_1 - 1) 1.
  const I d1 = alpha.term(1);
  std::string cur;
  for (I i = 1; i < d1 && cur.size() < n; i += 1) cur.push_back('0');
  cur.push_back('1');
  older = old;
  old = cur;
  for (std::size_t k = 2; old.size() < n; ++k) {
    const I dk = alpha.term(k);
    std::string next;
    for (I i = 0; i < dk && next.size() < n; i += 1) next += old;
    if (next.size() < n) next += older;
    older = std::move(old);
    old = std::move(next);
  }
  old.resize(n);
  return old;
}

template <TowerInt I>
std::vector<std::pair<I, I>> surd_convergents(const PeriodicContinuedFraction<I>& cf,
                                              std::size_t count) {
  std::vector<I> terms;
  terms.reserve(count);
  for (std::size_t k = 0; k < count; ++k) terms.push_back(cf.term(k));
  return convergents(std::span<const I>(terms));
}

#define ZDG_INSTANTIATE(I)                                                                         \
  template struct QuadraticSurd<I>;                                                                \
  template QuadraticSurd<I> make_surd(const I&, const I&, const I&, const I&);                     \
  template I isqrt(const I&);                                                                      \
  template I floor_multiple(const QuadraticSurd<I>&, const I&);                                    \
  template QuadraticSurd<I> fractional_part(const QuadraticSurd<I>&);                              \
  template PeriodicContinuedFraction<I> periodic_continued_fraction(const QuadraticSurd<I>&,       \
                                                                    std::size_t);                  \
  template std::string characteristic_word(const QuadraticSurd<I>&, std::size_t);                  \
  template std::string standard_word_prefix(const PeriodicContinuedFraction<I>&, std::size_t);     \
  template std::vector<std::pair<I, I>> surd_convergents(const PeriodicContinuedFraction<I>&,      \
                                                         std::size_t);
ZDG_INSTANTIATE(Int64)
ZDG_INSTANTIATE(Int128)
ZDG_INSTANTIATE(BigInt)
#undef ZDG_INSTANTIATE

} // namespace zdg
