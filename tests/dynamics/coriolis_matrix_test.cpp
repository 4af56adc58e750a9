// The Coriolis matrix of Mu (2.8b) in the form Mu's sliding-mode proof (4.7) needs: C dtheta is
// (2.8b)'s vector and Ddot - 2C is skew-symmetric, Ddot from central differences of D (2.8a).
#include <random>

#include <gtest/gtest.h>

#include "dynamics/robot_files/robot_config.hpp"
#include "dynamics/ssp_dynamics.hpp"

namespace gaitopt::test {
namespace {

TEST(CoriolisMatrix, DdotMinusTwoCIsSkewSymmetric) {
  const auto model = dynamics::loadRobot(std::string(GAITOPT_SOURCE_DIR) +
                                         "/configs/robots/mu2004_five_link.yaml");
  const int n = model.nLinks();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-2, 2);
  for (int trial = 0; trial < 10; ++trial) {
    VecD theta(n), dtheta(n);
    for (int i = 0; i < n; ++i) {
      theta(i) = u(rng);
      dtheta(i) = 3 * u(rng);
    }
    const double h = 1e-6;
    const MatD ddot = (dynamics::massMatrix<double>(model, VecD(theta + h * dtheta)) -
                       dynamics::massMatrix<double>(model, VecD(theta - h * dtheta))) /
                      (2 * h);
    MatD c(n, n);  // column j: C e_j
    for (int j = 0; j < n; ++j)
      c.col(j) =
          dynamics::coriolisMatrixTimes<double>(model, theta, dtheta, VecD(VecD::Unit(n, j)));
    const MatD skew = ddot - 2 * c;
    EXPECT_LT((skew + skew.transpose()).cwiseAbs().maxCoeff(), 1e-6) << trial;
    // Not trivially zero: the property is about a nonzero matrix.
    EXPECT_GT(skew.cwiseAbs().maxCoeff(), 1e-2) << trial;
  }
}

}  // namespace
}  // namespace gaitopt::test
