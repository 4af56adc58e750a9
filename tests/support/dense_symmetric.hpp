#pragma once
/// Dense references for the KKT solver tests: a dense symmetric matrix as the solver's lower
/// triangle, and what dense linear algebra says of it.
#include <Eigen/Dense>
#include <vector>

#include "ocp/solve/kkt/symmetric_pattern.hpp"

namespace gaitopt::test {

/// The lower triangle by columns, every diagonal entry stored (zero or not).
struct Lower {
  ocp::kkt::SymmetricPattern pattern;
  std::vector<double> values;
};

inline Lower lowerOf(const Eigen::MatrixXd& m) {
  std::vector<int> outer{0}, inner;
  std::vector<double> values;
  for (int c = 0; c < m.cols(); ++c) {
    for (int r = c; r < m.rows(); ++r) {
      if (r != c && m(r, c) == 0.0) continue;
      inner.push_back(r);
      values.push_back(m(r, c));
    }
    outer.push_back(static_cast<int>(inner.size()));
  }
  return {ocp::kkt::SymmetricPattern::fromLowerCsc(static_cast<int>(m.cols()), outer, inner),
          values};
}

inline int negativeEigenvalues(const Eigen::MatrixXd& m) {
  const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(m).eigenvalues();
  return static_cast<int>((ev.array() < 0).count());
}

/// Normwise backward error of x as a solution of m x = b: the smallest relative change of m and
/// b that makes it exact (Rigal and Gaches).
inline double backwardError(const Eigen::MatrixXd& m, const Eigen::VectorXd& x,
                            const Eigen::VectorXd& b) {
  return (b - m * x).norm() / (m.norm() * x.norm() + b.norm());
}

}  // namespace gaitopt::test
