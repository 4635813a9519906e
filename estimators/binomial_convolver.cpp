#include <zdg/estimators/binomial_convolver.hpp>

#include <zdg/arith/error.hpp>

#include <cmath>
#include <string>

namespace zdg {

long binomial_mask_order(double h, double k, double exponent) {
  if (!(h > 0) || !(k > 0)) throw InvalidArgument("binomial convolver: h and k must be > 0");
  if (!(exponent > 0) || exponent > 2) {
    throw InvalidArgument("binomial convolver: mask exponent " + std::to_string(exponent) +
                          " is not in (0, 2]");
  }
  double n = std::round(k * std::pow(h, -exponent));
  if (n > 1e9) throw InvalidArgument("binomial convolver: mask order too large");
  long m = std::max(2L, static_cast<long>(n));
  return m % 2 == 0 ? m : m + 1;
}

BinomialEstimates binomial_convolver(const DigitalContour& contour, double h, long n) {
  const long N = static_cast<long>(contour.size());
  if (n < 2 || n % 2 != 0) {
    throw InvalidArgument("binomial convolver: mask order " + std::to_string(n) +
                          " must be even and >= 2");
  }
  const long half = n / 2;
  const long reach = std::min(half, static_cast<long>(5.0 * std::sqrt(double(n))) + 2);
  if (2 * reach + 2 >= N) {
    throw InvalidArgument("binomial convolver: mask of order " + std::to_string(n) +
                          " is wider than the contour (" + std::to_string(N) + " linels)");
  }
  // Weights for offsets -reach..reach around the centre j = n/2.
  std::vector<double> w(static_cast<std::size_t>(2 * reach + 1));
  const double lg = std::lgamma(double(n) + 1) - double(n) * std::log(2.0);
  double total = 0;
  for (long o = -reach; o <= reach; ++o) {
    long j = half + o;
    double v = std::exp(lg - std::lgamma(double(j) + 1) - std::lgamma(double(n - j) + 1));
    w[static_cast<std::size_t>(o + reach)] = v;
    total += v;
  }
  for (double& v : w) v /= total;
  // Steps d(i) = p_{i+1} - p_i are the Freeman steps.
  std::vector<double> dx(static_cast<std::size_t>(N)), dy(static_cast<std::size_t>(N));
  for (long i = 0; i < N; ++i) {
    Pixel d = freeman_step(contour.codes[static_cast<std::size_t>(i)]);
    dx[static_cast<std::size_t>(i)] = static_cast<double>(d.x);
    dy[static_cast<std::size_t>(i)] = static_cast<double>(d.y);
  }
  std::vector<double> tx(static_cast<std::size_t>(N)), ty(static_cast<std::size_t>(N));
  for (long k = 0; k < N; ++k) {
    double sx = 0, sy = 0;
    for (long o = -reach; o <= reach; ++o) {
      long i = k + o;
      i = ((i % N) + N) % N;
      double wo = w[static_cast<std::size_t>(o + reach)];
      sx += wo * dx[static_cast<std::size_t>(i)];
      sy += wo * dy[static_cast<std::size_t>(i)];
    }
    tx[static_cast<std::size_t>(k)] = sx;
    ty[static_cast<std::size_t>(k)] = sy;
  }
  BinomialEstimates out;
  out.tangent.resize(static_cast<std::size_t>(N));
  out.curvature.resize(static_cast<std::size_t>(N));
  for (long k = 0; k < N; ++k) {
    auto a = static_cast<std::size_t>(k), b = static_cast<std::size_t>((k + N - 1) % N);
    double d1x = (tx[a] + tx[b]) / 2, d1y = (ty[a] + ty[b]) / 2;
    double d2x = tx[a] - tx[b], d2y = ty[a] - ty[b];
    double s = std::hypot(d1x, d1y);
    out.tangent[a] = {d1x / s, d1y / s};
    out.curvature[a] = (d1x * d2y - d1y * d2x) / (s * s * s * h);
  }
  return out;
}

} // namespace zdg
