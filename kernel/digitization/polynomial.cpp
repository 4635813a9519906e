#include <zdg/kernel/digitization/polynomial.hpp>

#include <zdg/arith/error.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <sstream>

namespace zdg {

namespace {

constexpr std::array<char, 3> kVariableNames{'x', 'y', 'z'};

// The text as quoted in messages: at most 60 characters.
std::string quoted(std::string_view text) {
  if (text.size() <= 60) return "'" + std::string(text) + "'";
  return "'" + std::string(text.substr(0, 57)) + "...' (" + std::to_string(text.size()) +
         " characters)";
}

class Parser {
public:
  Parser(std::string_view text, int nvars) : text_(text), nvars_(nvars) {}

  Polynomial parse() {
    skip();
    if (pos_ >= text_.size()) fail("empty polynomial");
    Polynomial p = expression();
    skip();
    if (pos_ < text_.size()) fail_here("unexpected");
    for (const auto& m : p.terms()) {
      if (!std::isfinite(m.coefficient_double)) {
        fail("coefficient " + m.coefficient.str().substr(0, 30) +
             "... of the expansion beyond the range of double");
      }
    }
    return p;
  }

private:
  std::string_view text_;
  int nvars_;
  std::size_t pos_ = 0;
  int depth_ = 0; // nesting of parentheses and unary signs
  int outer_ = 0; // degree of the factors that will multiply the factor being parsed
  long work_ = 0; // products and sums of terms performed so far

  [[noreturn]] void fail(const std::string& what) const {
    throw InvalidArgument("poly: " + what + " in " + quoted(text_));
  }
  [[noreturn]] void fail_here(const std::string& what) const {
    std::string found = pos_ < text_.size() ? "'" + std::string(1, text_[pos_]) + "'" : "end";
    throw InvalidArgument("poly: " + what + " " + found + " at position " +
                          std::to_string(pos_ + 1) + " of " + quoted(text_));
  }
  void skip() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  bool peek(char c) {
    skip();
    return pos_ < text_.size() && text_[pos_] == c;
  }
  void enter() {
    if (++depth_ > kPolynomialMaxNesting) {
      fail_here("nesting deeper than " + std::to_string(kPolynomialMaxNesting) + " levels at");
    }
  }
  void charge(std::size_t cost) {
    work_ += static_cast<long>(std::min<std::size_t>(cost, std::size_t{1} << 40));
    if (work_ > kPolynomialMaxWork) {
      fail("expansion too large (more than " + std::to_string(kPolynomialMaxWork) +
           " products and sums of terms)");
    }
  }
  void check_degree(int degree) const {
    if (degree > kPolynomialMaxDegree) {
      fail("total degree " + std::to_string(degree) + " larger than " +
           std::to_string(kPolynomialMaxDegree));
    }
  }
  Polynomial sum(const Polynomial& a, const Polynomial& b, int sign) {
    charge(a.terms().size() + b.terms().size());
    return sign > 0 ? a + b : a - b;
  }
  Polynomial product(const Polynomial& a, const Polynomial& b) {
    check_degree(outer_ + a.degree() + b.degree());
    charge(a.terms().size() * b.terms().size());
    return a * b;
  }

  Polynomial expression() {
    Polynomial acc;
    bool first = true;
    for (;;) {
      skip();
      int sign = 1;
      if (peek('+') || peek('-')) {
        sign = text_[pos_] == '-' ? -1 : 1;
        ++pos_;
      } else if (!first) {
        return acc;
      }
      Polynomial t = term();
      acc = first && sign > 0 ? std::move(t) : sum(acc, t, sign);
      first = false;
      skip();
      if (!(peek('+') || peek('-'))) return acc;
    }
  }

  bool starts_factor() {
    skip();
    if (pos_ >= text_.size()) return false;
    char c = text_[pos_];
    return std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '(' || c == 'x' ||
           c == 'y' || c == 'z';
  }

  // The next factor of a product whose factors so far are acc: parsed knowing that it will be
  // multiplied by acc (and by the factors outside), so that a degree beyond the cap is refused
  // before it is expanded.
  Polynomial next_factor(const Polynomial& acc) {
    const int saved = outer_;
    outer_ += acc.degree();
    Polynomial f = power();
    outer_ = saved;
    return f;
  }

  Polynomial term() {
    Polynomial acc = power();
    for (;;) {
      if (peek('*')) {
        ++pos_;
        acc = product(acc, next_factor(acc));
      } else if (peek('/')) {
        fail_here("division by a non-number");
      } else if (starts_factor()) {
        acc = product(acc, next_factor(acc)); // implicit multiplication: 3x, 2(x+y), x y
      } else {
        return acc;
      }
    }
  }

  Polynomial power() {
    Polynomial base = factor();
    if (peek('^')) {
      ++pos_;
      skip();
      std::size_t start = pos_;
      while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_;
      if (pos_ == start) fail_here("expected a non-negative integer exponent, found");
      std::string digits(text_.substr(start, pos_ - start));
      if (digits.size() > 3 || std::stoi(digits) > kPolynomialMaxDegree) {
        pos_ = start;
        fail_here("exponent larger than " + std::to_string(kPolynomialMaxDegree) +
                  " starting with");
      }
      const int k = std::stoi(digits);
      check_degree(outer_ + base.degree() * k);
      Polynomial r = Polynomial::constant(BigRational(1), nvars_);
      for (int i = 0; i < k; ++i) r = product(r, base);
      return r;
    }
    return base;
  }

  Polynomial factor() {
    skip();
    if (pos_ >= text_.size()) fail_here("expected a number, a variable or '(', found");
    char c = text_[pos_];
    if (c == '(') {
      enter();
      ++pos_;
      Polynomial p = expression();
      if (!peek(')')) fail_here("expected ')', found");
      ++pos_;
      --depth_;
      return p;
    }
    if (c == '-' || c == '+') {
      enter();
      ++pos_;
      Polynomial p = power();
      --depth_;
      if (c == '+') return p;
      charge(p.terms().size());
      return Polynomial::constant(BigRational(0), nvars_) - p;
    }
    for (int v = 0; v < 3; ++v) {
      if (c == kVariableNames[static_cast<std::size_t>(v)]) {
        if (v >= nvars_) {
          fail_here("variable not allowed in " + std::to_string(nvars_) + "D:");
        }
        ++pos_;
        // "x2" (x^2? x_2?) and the tail of "0x10": a digit right after a variable is refused.
        if (pos_ < text_.size() &&
            (std::isdigit(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '.')) {
          --pos_;
          fail_here("a digit right after the variable (write x*2 or x^2; numbers are decimal, "
                    "no 0x, 0o, 0b)");
        }
        return Polynomial::variable(v, nvars_);
      }
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return number();
    fail_here("expected a number, a variable or '(', found");
  }

  // digits[.digits][/digits]
  Polynomial number() {
    std::size_t start = pos_;
    while (pos_ < text_.size() &&
           (std::isdigit(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '.')) {
      ++pos_;
    }
    std::string num(text_.substr(start, pos_ - start));
    if (std::count(num.begin(), num.end(), '.') > 1 || num == ".") {
      pos_ = start;
      fail_here("malformed number starting with");
    }
    BigRational value;
    try {
      value = parse_rational<BigInt>(num);
    } catch (const InvalidArgument&) {
      pos_ = start;
      fail_here("malformed number starting with");
    }
    if (pos_ < text_.size() && text_[pos_] == '/') {
      std::size_t slash = pos_;
      ++pos_;
      std::size_t dstart = pos_;
      while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_;
      if (pos_ == dstart) {
        pos_ = slash;
        fail_here("a denominator must be a positive integer after");
      }
      BigInt den = parse_integer<BigInt>(text_.substr(dstart, pos_ - dstart));
      if (den == 0) {
        pos_ = slash;
        fail_here("zero denominator after");
      }
      value = value / BigRational(den);
    }
    if (pos_ < text_.size() && std::isalpha(static_cast<unsigned char>(text_[pos_])) &&
        std::find(kVariableNames.begin(), kVariableNames.end(), text_[pos_]) ==
            kVariableNames.end()) {
      // 1e5, 0b1, 0o7, 0X1F, 2a: not a decimal number, and not a product with a variable.
      fail_here("a number followed by a letter (numbers are decimal: no exponent, no 0x, 0o, "
                "0b):");
    }
    if (!std::isfinite(value.to_double())) {
      pos_ = start;
      fail_here("number beyond the range of double starting with");
    }
    return Polynomial::constant(value, nvars_);
  }
};

double pow_int(double b, int e) {
  double r = 1.0;
  for (int i = 0; i < e; ++i) r *= b;
  return r;
}

} // namespace

BigRational exact_rational(double v) {
  if (!std::isfinite(v)) throw InvalidArgument("not a finite number");
  if (v == 0.0) return BigRational(0);
  int exp = 0;
  double m = std::frexp(v, &exp); // v = m 2^exp, 0.5 <= |m| < 1
  auto mant = static_cast<std::int64_t>(std::ldexp(m, 53));
  exp -= 53;
  BigInt num(mant), den(1);
  if (exp >= 0) {
    num <<= exp;
  } else {
    den <<= -exp;
  }
  return BigRational(num, den);
}

Polynomial Polynomial::parse(std::string_view text, int nvars) {
  if (nvars != 2 && nvars != 3) throw InvalidArgument("poly: dimension must be 2 or 3");
  return Parser(text, nvars).parse();
}

Polynomial Polynomial::constant(const BigRational& c, int nvars) {
  Polynomial p;
  p.nvars_ = nvars;
  if (c != BigRational(0)) p.terms_.push_back(Monomial{{0, 0, 0}, c, c.to_double()});
  p.normalize();
  return p;
}

Polynomial Polynomial::variable(int index, int nvars) {
  Polynomial p;
  p.nvars_ = nvars;
  Monomial m{{0, 0, 0}, BigRational(1), 1.0};
  m.exponent[static_cast<std::size_t>(index)] = 1;
  p.terms_.push_back(m);
  p.normalize();
  return p;
}

// Sorts the terms by exponent and merges equal exponents in place (moves, no copies of the
// coefficients): O(n log n) for n terms.
void Polynomial::normalize() {
  std::sort(terms_.begin(), terms_.end(),
            [](const Monomial& a, const Monomial& b) { return a.exponent < b.exponent; });
  std::size_t out = 0;
  for (std::size_t i = 0; i < terms_.size();) {
    std::size_t j = i + 1;
    for (; j < terms_.size() && terms_[j].exponent == terms_[i].exponent; ++j) {
      terms_[i].coefficient += terms_[j].coefficient;
    }
    if (!(terms_[i].coefficient == BigRational(0))) {
      if (out != i) terms_[out] = std::move(terms_[i]);
      ++out;
    }
    i = j;
  }
  terms_.resize(out);
  degree_ = 0;
  for (auto& m : terms_) {
    m.coefficient_double = m.coefficient.to_double();
    degree_ = std::max(degree_, m.degree());
  }
}

Polynomial operator+(const Polynomial& a, const Polynomial& b) {
  Polynomial r;
  r.nvars_ = std::max(a.nvars_, b.nvars_);
  r.terms_ = a.terms_;
  r.terms_.insert(r.terms_.end(), b.terms_.begin(), b.terms_.end());
  r.normalize();
  return r;
}

Polynomial operator-(const Polynomial& a, const Polynomial& b) {
  Polynomial nb = b;
  for (auto& m : nb.terms_) m.coefficient = -m.coefficient;
  return a + nb;
}

Polynomial operator*(const Polynomial& a, const Polynomial& b) {
  Polynomial r;
  r.nvars_ = std::max(a.nvars_, b.nvars_);
  r.terms_.reserve(a.terms_.size() * b.terms_.size());
  for (const auto& ma : a.terms_) {
    for (const auto& mb : b.terms_) {
      Monomial& m = r.terms_.emplace_back();
      for (std::size_t i = 0; i < 3; ++i) m.exponent[i] = ma.exponent[i] + mb.exponent[i];
      m.coefficient = ma.coefficient * mb.coefficient;
    }
  }
  r.normalize();
  return r;
}

Polynomial Polynomial::pow(int k) const {
  Polynomial r = constant(BigRational(1), nvars_);
  for (int i = 0; i < k; ++i) r = r * *this;
  return r;
}

std::string Polynomial::str() const {
  if (terms_.empty()) return "0";
  std::ostringstream s;
  bool first = true;
  for (const auto& m : terms_) {
    BigRational c = m.coefficient;
    bool neg = c < BigRational(0);
    if (neg) c = -c;
    s << (neg ? (first ? "-" : " - ") : (first ? "" : " + "));
    bool unit = c == BigRational(1) && m.degree() > 0;
    if (!unit) s << c.str();
    bool need_star = !unit;
    for (std::size_t i = 0; i < 3; ++i) {
      if (m.exponent[i] == 0) continue;
      s << (need_star ? "*" : "") << kVariableNames[i];
      if (m.exponent[i] > 1) s << '^' << m.exponent[i];
      need_star = true;
    }
    first = false;
  }
  return s.str();
}

double Polynomial::value(const double* p) const {
  double v = 0.0;
  for (const auto& m : terms_) {
    double t = m.coefficient_double;
    for (int i = 0; i < nvars_; ++i) t *= pow_int(p[i], m.exponent[static_cast<std::size_t>(i)]);
    v += t;
  }
  return v;
}

void Polynomial::gradient(const double* p, double* g) const {
  for (int i = 0; i < nvars_; ++i) g[i] = 0.0;
  for (const auto& m : terms_) {
    for (int d = 0; d < nvars_; ++d) {
      int ed = m.exponent[static_cast<std::size_t>(d)];
      if (ed == 0) continue;
      double t = m.coefficient_double * ed;
      for (int i = 0; i < nvars_; ++i) {
        int e = m.exponent[static_cast<std::size_t>(i)] - (i == d ? 1 : 0);
        t *= pow_int(p[i], e);
      }
      g[d] += t;
    }
  }
}

void Polynomial::hessian(const double* p, double* hess) const {
  for (int i = 0; i < nvars_ * nvars_; ++i) hess[i] = 0.0;
  for (const auto& m : terms_) {
    for (int a = 0; a < nvars_; ++a) {
      for (int b = 0; b < nvars_; ++b) {
        std::array<int, 3> e = m.exponent;
        double t = m.coefficient_double;
        t *= e[static_cast<std::size_t>(a)];
        e[static_cast<std::size_t>(a)] -= 1;
        if (t == 0.0) continue;
        t *= e[static_cast<std::size_t>(b)];
        e[static_cast<std::size_t>(b)] -= 1;
        if (t == 0.0) continue;
        for (int i = 0; i < nvars_; ++i) t *= pow_int(p[i], e[static_cast<std::size_t>(i)]);
        hess[a * nvars_ + b] += t;
      }
    }
  }
}

BigRational Polynomial::value_exact(const BigRational* p) const {
  BigRational v(0);
  for (const auto& m : terms_) {
    BigRational t = m.coefficient;
    for (int i = 0; i < nvars_; ++i) {
      for (int k = 0; k < m.exponent[static_cast<std::size_t>(i)]; ++k) t *= p[i];
    }
    v += t;
  }
  return v;
}

int Polynomial::sign_exact(const BigRational* p) const {
  BigRational v = value_exact(p);
  return v < BigRational(0) ? -1 : (v > BigRational(0) ? 1 : 0);
}

} // namespace zdg
