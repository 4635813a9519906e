#include <zdg/kernel/linalg/principal_angles.hpp>

#include <zdg/arith/error.hpp>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <string>

namespace zdg {

namespace {

// A W-orthonormal basis of span(vectors), as the columns of sqrt(W) [vectors] made orthonormal.
Eigen::MatrixXd orthonormal_basis(std::span<const std::vector<double>> vectors,
                                  const Eigen::VectorXd& root_w, const char* name) {
  const auto n = root_w.size();
  if (vectors.empty()) {
    throw InvalidArgument(std::string("principal angles: subspace ") + name + " has no vector");
  }
  Eigen::MatrixXd m(n, Eigen::Index(vectors.size()));
  for (std::size_t j = 0; j < vectors.size(); ++j) {
    if (Eigen::Index(vectors[j].size()) != n) {
      throw InvalidArgument(std::string("principal angles: vector ") + std::to_string(j) + " of " +
                            name + " has " + std::to_string(vectors[j].size()) +
                            " entries, the weights " + std::to_string(n));
    }
    for (Eigen::Index i = 0; i < n; ++i)
      m(i, Eigen::Index(j)) = root_w(i) * vectors[j][std::size_t(i)];
  }
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(m);
  qr.setThreshold(1e-10);
  if (qr.rank() != m.cols()) {
    throw InvalidArgument(std::string("principal angles: the vectors of ") + name +
                          " are linearly dependent (rank " + std::to_string(qr.rank()) + " of " +
                          std::to_string(m.cols()) + ")");
  }
  return qr.householderQ() * Eigen::MatrixXd::Identity(n, m.cols());
}

} // namespace

std::vector<double> principal_angles(std::span<const std::vector<double>> a,
                                     std::span<const std::vector<double>> b,
                                     std::span<const double> weights) {
  Eigen::VectorXd root_w(Eigen::Index(weights.size()));
  for (std::size_t i = 0; i < weights.size(); ++i) {
    if (!(weights[i] > 0) || !std::isfinite(weights[i])) {
      throw InvalidArgument("principal angles: weight " + std::to_string(i) + " = " +
                            std::to_string(weights[i]) + " is not positive");
    }
    root_w(Eigen::Index(i)) = std::sqrt(weights[i]);
  }
  Eigen::MatrixXd qa = orthonormal_basis(a, root_w, "A");
  Eigen::MatrixXd qb = orthonormal_basis(b, root_w, "B");
  if (qb.cols() > qa.cols()) std::swap(qa, qb); // angles are symmetric; q <= p below
  const Eigen::MatrixXd c = qa.transpose() * qb;
  const Eigen::VectorXd cosines = Eigen::JacobiSVD<Eigen::MatrixXd>(c).singularValues();
  const Eigen::VectorXd sines =
      Eigen::JacobiSVD<Eigen::MatrixXd>(qb - qa * c).singularValues(); // decreasing
  const auto m = cosines.size();
  std::vector<double> out;
  for (Eigen::Index i = 0; i < m; ++i) {
    // The i-th smallest angle: the i-th largest cosine and the i-th smallest sine.
    const double cs = std::min(1.0, cosines(i));
    const double sn = std::min(1.0, sines(m - 1 - i));
    out.push_back(std::atan2(sn, cs));
  }
  std::sort(out.begin(), out.end());
  return out;
}

} // namespace zdg
