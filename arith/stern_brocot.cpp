#include <zdg/arith/stern_brocot.hpp>

#include <zdg/arith/continued_fraction.hpp>

namespace zdg {

namespace {
template <TowerInt I>
std::vector<I> checked_expansion(const I& p, const I& q) {
  if (p <= 0 || q <= 0 || gcd(p, q) != 1) {
    throw InvalidArgument("Stern-Brocot tree: " + to_string(p) + "/" + to_string(q) +
                          " is not a reduced positive fraction");
  }
  return continued_fraction(p, q);
}
} // namespace

template <TowerInt I>
SternBrocotParents<I> stern_brocot_parents(const I& p, const I& q) {
  auto terms = checked_expansion(p, q);
  auto conv = convergents(std::span<const I>(terms));
  std::size_t n = terms.size() - 1;
  Fraction<I> prev =
      n == 0 ? Fraction<I>{1, 0} : Fraction<I>{conv[n - 1].first, conv[n - 1].second};
  Fraction<I> other{p - prev.p, q - prev.q};
  if (n % 2 == 0) return {other, prev};
  return {prev, other};
}

template <TowerInt I>
I stern_brocot_depth(const I& p, const I& q) {
  auto terms = checked_expansion(p, q);
  I d = -1;
  for (const I& a : terms) d += a;
  return d;
}

template <TowerInt I>
std::vector<std::pair<char, I>> stern_brocot_path_runs(const I& p, const I& q) {
  auto terms = checked_expansion(p, q);
  terms.back() -= 1;
  std::vector<std::pair<char, I>> runs;
  for (std::size_t k = 0; k < terms.size(); ++k) {
    if (terms[k] > 0) runs.emplace_back(k % 2 == 0 ? 'R' : 'L', terms[k]);
  }
  return runs;
}

template <TowerInt I>
std::string stern_brocot_path(const I& p, const I& q, std::size_t max_length) {
  I depth = stern_brocot_depth(p, q);
  if (depth > I(static_cast<std::int64_t>(max_length))) {
    throw InvalidArgument("Stern-Brocot path of " + to_string(p) + "/" + to_string(q) + " has " +
                          to_string(depth) + " letters, more than the limit " +
                          std::to_string(max_length));
  }
  std::string s;
  for (const auto& [letter, count] : stern_brocot_path_runs(p, q)) {
    s.append(static_cast<std::size_t>(to_double(count)), letter);
  }
  return s;
}

template <TowerInt I>
Fraction<I> stern_brocot_follow(const std::string& path) {
  // Invariant: current = mediant(left, right).
  Fraction<I> left{0, 1}, right{1, 0}, cur{1, 1};
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (path[i] == 'L') {
      right = cur;
    } else if (path[i] == 'R') {
      left = cur;
    } else {
      throw InvalidArgument("Stern-Brocot path: letter '" + std::string(1, path[i]) +
                            "' at position " + std::to_string(i) + " is neither L nor R");
    }
    cur = mediant(left, right);
  }
  return cur;
}

#define ZDG_INSTANTIATE(I)                                                                         \
  template SternBrocotParents<I> stern_brocot_parents<I>(const I&, const I&);                      \
  template I stern_brocot_depth<I>(const I&, const I&);                                            \
  template std::vector<std::pair<char, I>> stern_brocot_path_runs<I>(const I&, const I&);          \
  template std::string stern_brocot_path<I>(const I&, const I&, std::size_t);                      \
  template Fraction<I> stern_brocot_follow<I>(const std::string&);
ZDG_INSTANTIATE(Int64)
ZDG_INSTANTIATE(Int128)
ZDG_INSTANTIATE(BigInt)
#undef ZDG_INSTANTIATE

} // namespace zdg
