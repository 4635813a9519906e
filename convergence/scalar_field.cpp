// Test functions with exact derivatives: a recursive-descent parser to a postfix program,
// evaluated on a stack of second-order jets.
#include <zdg/arith/error.hpp>
#include <zdg/convergence/scalar_field.hpp>

#include <charconv>
#include <cmath>
#include <numbers>
#include <utility>

namespace zdg {

namespace {

enum class Op { constant, x, y, z, add, sub, mul, div, pow, neg, function };
enum class Fn { sin, cos, tan, exp, log, sqrt, sinh, cosh, tanh, atan };

struct FunctionName {
  std::string_view name;
  Fn fn;
};
constexpr FunctionName function_names[] = {
    {"sin", Fn::sin},   {"cos", Fn::cos},   {"tan", Fn::tan},   {"exp", Fn::exp},
    {"log", Fn::log},   {"sqrt", Fn::sqrt}, {"sinh", Fn::sinh}, {"cosh", Fn::cosh},
    {"tanh", Fn::tanh}, {"atan", Fn::atan}};

constexpr std::size_t max_length = 1000;
constexpr int max_depth = 200;

// Hessian entries (xx, yy, zz, xy, xz, yz) as index pairs.
constexpr int hi[6] = {0, 1, 2, 0, 0, 1};
constexpr int hj[6] = {0, 1, 2, 1, 2, 2};

Jet3 constant_jet(double c) {
  Jet3 j;
  j.value = c;
  return j;
}

Jet3 variable_jet(double v, int axis) {
  Jet3 j;
  j.value = v;
  j.gradient[static_cast<std::size_t>(axis)] = 1;
  return j;
}

// f(a) for f with f(t), f'(t), f''(t) = d0, d1, d2 at t = a.value (the chain rule to order 2).
Jet3 chain(const Jet3& a, double d0, double d1, double d2) {
  Jet3 r;
  r.value = d0;
  for (std::size_t i = 0; i < 3; ++i) r.gradient[i] = d1 * a.gradient[i];
  for (std::size_t k = 0; k < 6; ++k) {
    r.hessian[k] =
        d1 * a.hessian[k] + d2 * a.gradient[std::size_t(hi[k])] * a.gradient[std::size_t(hj[k])];
  }
  return r;
}

Jet3 add(const Jet3& a, const Jet3& b, double sign) {
  Jet3 r;
  r.value = a.value + sign * b.value;
  for (std::size_t i = 0; i < 3; ++i) r.gradient[i] = a.gradient[i] + sign * b.gradient[i];
  for (std::size_t k = 0; k < 6; ++k) r.hessian[k] = a.hessian[k] + sign * b.hessian[k];
  return r;
}

Jet3 multiply(const Jet3& a, const Jet3& b) {
  Jet3 r;
  r.value = a.value * b.value;
  for (std::size_t i = 0; i < 3; ++i)
    r.gradient[i] = a.value * b.gradient[i] + b.value * a.gradient[i];
  for (std::size_t k = 0; k < 6; ++k) {
    const auto i = std::size_t(hi[k]), j = std::size_t(hj[k]);
    r.hessian[k] = a.value * b.hessian[k] + b.value * a.hessian[k] + a.gradient[i] * b.gradient[j] +
                   b.gradient[i] * a.gradient[j];
  }
  return r;
}

Jet3 reciprocal(const Jet3& a) {
  const double t = a.value;
  return chain(a, 1 / t, -1 / (t * t), 2 / (t * t * t));
}

bool is_constant(const Jet3& a) {
  for (double g : a.gradient) {
    if (g != 0) return false;
  }
  for (double h : a.hessian) {
    if (h != 0) return false;
  }
  return true;
}

// a^b. A constant exponent c (its jet is constant to second order, so a^b and a^c have the
// same second-order jet): t^c, defined for t < 0 when c is an integer. Otherwise exp(b log a).
Jet3 power(const Jet3& a, const Jet3& b) {
  if (is_constant(b)) {
    const double c = b.value, t = a.value;
    const double d1 = c == 0 ? 0 : c * std::pow(t, c - 1);
    const double d2 = c * (c - 1) == 0 ? 0 : c * (c - 1) * std::pow(t, c - 2);
    return chain(a, std::pow(t, c), d1, d2);
  }
  const double t = a.value;
  const Jet3 log_a = chain(a, std::log(t), 1 / t, -1 / (t * t));
  const Jet3 e = multiply(b, log_a);
  const double v = std::exp(e.value);
  return chain(e, v, v, v);
}

Jet3 apply_function(Fn fn, const Jet3& a) {
  const double t = a.value;
  switch (fn) {
  case Fn::sin:
    return chain(a, std::sin(t), std::cos(t), -std::sin(t));
  case Fn::cos:
    return chain(a, std::cos(t), -std::sin(t), -std::cos(t));
  case Fn::tan: {
    const double v = std::tan(t), d = 1 + v * v;
    return chain(a, v, d, 2 * v * d);
  }
  case Fn::exp: {
    const double v = std::exp(t);
    return chain(a, v, v, v);
  }
  case Fn::log:
    return chain(a, std::log(t), 1 / t, -1 / (t * t));
  case Fn::sqrt: {
    const double s = std::sqrt(t);
    return chain(a, s, 0.5 / s, -0.25 / (s * s * s));
  }
  case Fn::sinh:
    return chain(a, std::sinh(t), std::cosh(t), std::sinh(t));
  case Fn::cosh:
    return chain(a, std::cosh(t), std::sinh(t), std::cosh(t));
  case Fn::tanh: {
    const double v = std::tanh(t), d = 1 - v * v;
    return chain(a, v, d, -2 * v * d);
  }
  case Fn::atan: {
    const double d = 1 / (1 + t * t);
    return chain(a, std::atan(t), d, -2 * t * d * d);
  }
  }
  return a;
}

std::string shown_text(std::string_view text) {
  return "function '" +
         (text.size() <= 60 ? std::string(text) : std::string(text.substr(0, 57)) + "...") + "'";
}

} // namespace

struct ScalarField::Node {
  Op op = Op::constant;
  double value = 0; // constant
  Fn fn = Fn::sin;  // function
};

namespace {

class Parser {
public:
  Parser(std::string_view text, std::vector<ScalarField::Node>& out) : text_(text), out_(out) {}

  void parse() {
    if (text_.size() > max_length) {
      throw InvalidArgument(shown_text(text_) + ": longer than " + std::to_string(max_length) +
                            " characters");
    }
    skip();
    if (pos_ == text_.size()) fail("empty");
    expression(0);
    skip();
    if (pos_ != text_.size()) fail("unexpected '" + std::string(1, text_[pos_]) + "'");
  }

private:
  std::string_view text_;
  std::vector<ScalarField::Node>& out_;
  std::size_t pos_ = 0;

  [[noreturn]] void fail(const std::string& what) const {
    throw InvalidArgument(shown_text(text_) + ": " + what + " at position " +
                          std::to_string(pos_ + 1));
  }

  void skip() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t')) ++pos_;
  }

  bool accept(char c) {
    skip();
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }

  void emit(Op op, double value = 0, Fn fn = Fn::sin) {
    ScalarField::Node n;
    n.op = op;
    n.value = value;
    n.fn = fn;
    out_.push_back(n);
  }

  void check_depth(int depth) const {
    if (depth > max_depth) fail("nested deeper than " + std::to_string(max_depth) + " levels");
  }

  // expression := term (('+' | '-') term)*
  void expression(int depth) {
    check_depth(depth);
    term(depth + 1);
    for (;;) {
      if (accept('+')) {
        term(depth + 1);
        emit(Op::add);
      } else if (accept('-')) {
        term(depth + 1);
        emit(Op::sub);
      } else {
        return;
      }
    }
  }

  // term := unary (('*' | '/') unary)*
  void term(int depth) {
    check_depth(depth);
    unary(depth + 1);
    for (;;) {
      if (accept('*')) {
        unary(depth + 1);
        emit(Op::mul);
      } else if (accept('/')) {
        unary(depth + 1);
        emit(Op::div);
      } else {
        return;
      }
    }
  }

  // unary := ('-' | '+') unary | power
  void unary(int depth) {
    check_depth(depth);
    if (accept('-')) {
      unary(depth + 1);
      emit(Op::neg);
    } else if (accept('+')) {
      unary(depth + 1);
    } else {
      power(depth + 1);
    }
  }

  // power := primary ('^' unary)?   (right associative: the exponent may itself be a power)
  void power(int depth) {
    check_depth(depth);
    primary(depth + 1);
    if (accept('^')) {
      unary(depth + 1);
      emit(Op::pow);
    }
  }

  void primary(int depth) {
    check_depth(depth);
    skip();
    if (pos_ == text_.size()) fail("expression expected");
    const char c = text_[pos_];
    if (c == '(') {
      ++pos_;
      expression(depth + 1);
      if (!accept(')')) fail("')' expected");
      return;
    }
    if ((c >= '0' && c <= '9') || c == '.') {
      number();
      return;
    }
    if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z')) {
      const std::size_t start = pos_;
      while (pos_ < text_.size() && ((text_[pos_] >= 'a' && text_[pos_] <= 'z') ||
                                     (text_[pos_] >= 'A' && text_[pos_] <= 'Z') ||
                                     (text_[pos_] >= '0' && text_[pos_] <= '9')))
        ++pos_;
      const std::string_view word = text_.substr(start, pos_ - start);
      if (word == "x") return emit(Op::x);
      if (word == "y") return emit(Op::y);
      if (word == "z") return emit(Op::z);
      if (word == "pi") return emit(Op::constant, std::numbers::pi);
      for (const auto& f : function_names) {
        if (word == f.name) {
          if (!accept('(')) fail("'(' expected after " + std::string(word));
          expression(depth + 1);
          if (!accept(')')) fail("')' expected");
          emit(Op::function, 0, f.fn);
          return;
        }
      }
      pos_ = start;
      fail("unknown name '" + std::string(word.substr(0, 20)) +
           "' (variables x, y, z; constant pi; functions sin cos tan exp log sqrt sinh cosh "
           "tanh atan)");
    }
    fail("unexpected '" + std::string(1, c) + "'");
  }

  void number() {
    const std::size_t start = pos_;
    while (pos_ < text_.size() &&
           ((text_[pos_] >= '0' && text_[pos_] <= '9') || text_[pos_] == '.'))
      ++pos_;
    if (pos_ < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
      std::size_t p = pos_ + 1;
      if (p < text_.size() && (text_[p] == '+' || text_[p] == '-')) ++p;
      if (p < text_.size() && text_[p] >= '0' && text_[p] <= '9') {
        pos_ = p;
        while (pos_ < text_.size() && text_[pos_] >= '0' && text_[pos_] <= '9') ++pos_;
      }
    }
    double v = 0;
    const char* first = text_.data() + start;
    const char* last = text_.data() + pos_;
    const auto [ptr, ec] = std::from_chars(first, last, v);
    if (ec != std::errc() || ptr != last || !std::isfinite(v)) {
      pos_ = start;
      fail("bad number '" +
           std::string(text_.substr(start, std::min<std::size_t>(last - first, 30))) + "'");
    }
    emit(Op::constant, v);
  }
};

} // namespace

ScalarField::ScalarField(std::string_view text) : text_(text) {
  Parser(text, nodes_).parse();
}

ScalarField::~ScalarField() = default;
ScalarField::ScalarField(const ScalarField&) = default;
ScalarField& ScalarField::operator=(const ScalarField&) = default;
ScalarField::ScalarField(ScalarField&&) noexcept = default;
ScalarField& ScalarField::operator=(ScalarField&&) noexcept = default;

Jet3 ScalarField::jet(Point3<double> p) const {
  std::vector<Jet3> stack;
  stack.reserve(16);
  for (const Node& n : nodes_) {
    switch (n.op) {
    case Op::constant:
      stack.push_back(constant_jet(n.value));
      break;
    case Op::x:
      stack.push_back(variable_jet(p.x, 0));
      break;
    case Op::y:
      stack.push_back(variable_jet(p.y, 1));
      break;
    case Op::z:
      stack.push_back(variable_jet(p.z, 2));
      break;
    case Op::neg:
      stack.back() = chain(stack.back(), -stack.back().value, -1, 0);
      break;
    case Op::function:
      stack.back() = apply_function(n.fn, stack.back());
      break;
    default: {
      const Jet3 b = stack.back();
      stack.pop_back();
      const Jet3 a = stack.back();
      Jet3& r = stack.back();
      if (n.op == Op::add) r = add(a, b, 1);
      if (n.op == Op::sub) r = add(a, b, -1);
      if (n.op == Op::mul) r = multiply(a, b);
      if (n.op == Op::div) r = multiply(a, reciprocal(b));
      if (n.op == Op::pow) r = power(a, b);
    }
    }
  }
  const Jet3 r = stack.back();
  bool finite = std::isfinite(r.value);
  for (double g : r.gradient) finite = finite && std::isfinite(g);
  for (double h : r.hessian) finite = finite && std::isfinite(h);
  if (!finite) {
    throw InvalidArgument(
        shown_text(text_) + " or one of its first two derivatives is not finite at (" +
        std::to_string(p.x) + ", " + std::to_string(p.y) + ", " + std::to_string(p.z) + ")");
  }
  return r;
}

double ScalarField::value(Point3<double> p) const {
  return jet(p).value;
}

double ScalarField::laplace_beltrami(Point3<double> p, Point3<double> n, double k1,
                                     double k2) const {
  const Jet3 j = jet(p);
  const auto& H = j.hessian;
  const double trace = H[0] + H[1] + H[2];
  const double nHn = H[0] * n.x * n.x + H[1] * n.y * n.y + H[2] * n.z * n.z +
                     2 * (H[3] * n.x * n.y + H[4] * n.x * n.z + H[5] * n.y * n.z);
  const double dn = j.gradient[0] * n.x + j.gradient[1] * n.y + j.gradient[2] * n.z;
  return trace - nHn - (k1 + k2) * dn;
}

std::vector<std::string> default_test_functions() {
  return {"x", "x^2-y^2", "exp(z)"};
}

} // namespace zdg
