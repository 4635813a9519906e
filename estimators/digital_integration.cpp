#include <zdg/estimators/digital_integration.hpp>

#include <zdg/arith/error.hpp>

#include <cmath>
#include <string>

namespace zdg {

namespace {
void same_size(std::size_t a, std::size_t b, const char* what) {
  if (a != b)
    throw InvalidArgument(std::string("digital integration: ") + what + " (" + std::to_string(a) +
                          " and " + std::to_string(b) + " values)");
}
} // namespace

std::vector<double> surfel_measure(std::span<const Point3<double>> estimated_normals,
                                   std::span<const Point3<double>> elementary_normals) {
  same_size(estimated_normals.size(), elementary_normals.size(),
            "estimated and elementary normals differ in number");
  std::vector<double> mu(estimated_normals.size());
  for (std::size_t i = 0; i < mu.size(); ++i)
    mu[i] = dot(estimated_normals[i], elementary_normals[i]);
  return mu;
}

std::vector<double> surfel_weights(std::span<const double> measure, std::span<const double> areas) {
  same_size(measure.size(), areas.size(), "measures and areas differ in number");
  std::vector<double> w(measure.size());
  for (std::size_t i = 0; i < w.size(); ++i) w[i] = measure[i] * areas[i];
  return w;
}

double digital_integral(std::span<const double> weights, std::span<const double> f) {
  same_size(weights.size(), f.size(), "weights and function values differ in number");
  // Kahan-Babuska (Neumaier) summation.
  double sum = 0, c = 0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const double x = weights[i] * f[i], t = sum + x;
    c += std::abs(sum) >= std::abs(x) ? (sum - t) + x : (x - t) + sum;
    sum = t;
  }
  return sum + c;
}

} // namespace zdg
