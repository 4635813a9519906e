// The estimator registry of the convergence driver. An estimator knows its dimension, its
// parameters (the radius law R = k h^alpha, a mask factor k, ...) and how to run once on a
// shape at one grid step and translation, returning the error statistics over its
// boundary elements (or of its global quantity: then linf = l2 = mean = |error|, n = 1).
//
// Adding an estimator is one file: define a register function that appends Estimator
// entries, and call it from estimators() in convergence/estimator.cpp (2D: estimators_2d.cpp;
// the DSS-based and 3D estimators plug in the same way). The driver loop, the error norms,
// the fit and the outputs never look inside an estimator.
#pragma once

#include <zdg/convergence/shape.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace zdg {

/// Errors over the n boundary elements of one run: max, root mean square, mean of |error|.
struct ErrorStats {
  double linf = 0, l2 = 0, mean = 0;
  std::int64_t n = 0;
};

/// Accumulates absolute errors.
class ErrorAccumulator {
public:
  void add(double error) {
    double a = error < 0 ? -error : error;
    if (!(a <= linf_)) linf_ = a; // a NaN error propagates
    sum_ += a;
    sum2_ += a * a;
    ++n_;
  }
  ErrorStats stats() const;

private:
  double linf_ = 0, sum_ = 0, sum2_ = 0;
  std::int64_t n_ = 0;
};

/// Everything one run needs.
struct RunInput {
  const Shape& shape;
  double h;
  std::vector<double> translation;            // the shape is X + translation
  std::vector<std::pair<double, double>> box; // continuous digitization domain per axis
  double k;                                   // estimator parameter (radius/mask factor)
  double alpha;                               // exponent of the radius law
};

struct Estimator {
  std::string name;
  int dimension; // 2 or 3; 0: any (the run dispatches on the shape)
  std::string description;
  std::string parameters; // documentation of k and alpha for this estimator
  std::string quantity;   // what the error measures ("curvature", "angle (rad)", ...)
  bool uses_k = false, uses_alpha = false;
  double default_k = 0, default_alpha = 0;
  std::function<ErrorStats(const RunInput&)> run;
};

const std::vector<Estimator>& estimators();
/// Throws InvalidArgument listing the known names.
const Estimator& find_estimator(const std::string& name);

namespace detail {
void register_2d_estimators(std::vector<Estimator>& out);
void register_3d_estimators(std::vector<Estimator>& out);
void register_hausdorff_estimators(std::vector<Estimator>& out); // dimension 0: any
} // namespace detail

} // namespace zdg
