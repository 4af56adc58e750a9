// Exact derivatives of the SSP and DSP dynamics residuals: the analytic Jacobian and Hessian
// against central finite differences (1e-6 relative) and against forward-mode automatic
// differentiation of the templated residual (Eigen AutoDiffScalar, to rounding); on level
// ground and on a slope (the gravity terms of Mu 2.8c with gravity rotated).
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include <fmt/format.h>

#include "dynamics/dsp_dynamics.hpp"
#include "dynamics/model_variation.hpp"
#include "dynamics/residual_derivatives.hpp"
#include "support/fixtures.hpp"

namespace gaitopt::test {
namespace {

using dynamics::DynamicsPoint;
using AD = Eigen::AutoDiffScalar<Eigen::VectorXd>;

Eigen::VectorXd pack(const DynamicsPoint& x, bool dsp) {
  const int n = static_cast<int>(x.theta.size());
  Eigen::VectorXd z(4 * n + (dsp ? 2 : 0));
  z << x.theta, x.dtheta, x.ddtheta, x.tau, (dsp ? Eigen::VectorXd(x.lambda) : Eigen::VectorXd());
  return z;
}

DynamicsPoint unpack(const Eigen::VectorXd& z, int n, bool dsp) {
  DynamicsPoint x{z.segment(0, n), z.segment(n, n), z.segment(2 * n, n), z.segment(3 * n, n)};
  if (dsp) x.lambda = z.tail<2>();
  return x;
}

DynamicsPoint randomPoint(const dynamics::Model& m, std::mt19937& rng) {
  const int n = m.nLinks();
  DynamicsPoint x{randomPosture(rng, m), randomVec(rng, n, -3, 3), randomVec(rng, n, -20, 20),
                  randomVec(rng, n, -50, 50)};
  x.lambda = randomVec(rng, 2, -100, 300);
  return x;
}

Eigen::MatrixXd finiteDifferenceJacobian(const dynamics::Model& m, const DynamicsPoint& x, bool dsp,
                                         double h) {
  const Eigen::VectorXd z = pack(x, dsp);
  const int n = m.nLinks();
  Eigen::MatrixXd jac(dynamics::residualRows(m, dsp), z.size());
  for (int k = 0; k < z.size(); ++k) {
    Eigen::VectorXd zp = z, zm = z;
    zp(k) += h;
    zm(k) -= h;
    jac.col(k) = (dynamics::residual(m, unpack(zp, n, dsp), dsp) -
                  dynamics::residual(m, unpack(zm, n, dsp), dsp)) /
                 (2 * h);
  }
  return jac;
}

Eigen::MatrixXd autodiffJacobian(const dynamics::Model& m, const DynamicsPoint& x, bool dsp) {
  const Eigen::VectorXd z = pack(x, dsp);
  const int n = m.nLinks();
  const int nz = static_cast<int>(z.size());
  auto var = [&](int block, int i) { return AD(z(block * n + i), nz, block * n + i); };
  Vec<AD> th(n), dth(n), ddth(n), tau(n);
  for (int i = 0; i < n; ++i) {
    th(i) = var(0, i);
    dth(i) = var(1, i);
    ddth(i) = var(2, i);
    tau(i) = var(3, i);
  }
  Eigen::MatrixXd jac(dynamics::residualRows(m, dsp), nz);
  if (dsp) {
    const Vec2<AD> lam(AD(z(4 * n), nz, 4 * n), AD(z(4 * n + 1), nz, 4 * n + 1));
    const VecR<AD> r = dynamics::dspResidual(m, th, dth, ddth, tau, lam);
    for (int i = 0; i < r.size(); ++i) jac.row(i) = r(i).derivatives().transpose();
  } else {
    const Vec<AD> r = dynamics::sspResidual(m, th, dth, ddth, tau);
    for (int i = 0; i < r.size(); ++i) jac.row(i) = r(i).derivatives().transpose();
  }
  return jac;
}

struct Case {
  std::string robot;
  bool dsp;
  double slope = 0;  ///< ground inclination [rad]
};

class ResidualDerivativesTest : public ::testing::TestWithParam<Case> {
 protected:
  dynamics::Model model_ = dynamics::withSlope(loadNamed(GetParam().robot), GetParam().slope);
  bool dsp_ = GetParam().dsp;
  std::mt19937 rng_{21};
};

TEST_P(ResidualDerivativesTest, JacobianEqualsCentralDifferencesAndAutoDiff) {
  double worst_fd = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const DynamicsPoint x = randomPoint(model_, rng_);
    const Eigen::MatrixXd jac = dynamics::residualJacobian(model_, x, dsp_);
    const double fd = relErr(finiteDifferenceJacobian(model_, x, dsp_, 1e-6), jac);
    worst_fd = std::max(worst_fd, fd);
    EXPECT_LT(fd, 1e-6);
    EXPECT_LT(relErr(autodiffJacobian(model_, x, dsp_), jac), 1e-13);
  }
  RecordProperty("worst_jacobian_fd_relative_error", fmt::format("{:.2e}", worst_fd));
}

TEST_P(ResidualDerivativesTest, HessianEqualsCentralDifferencesOfTheGradient) {
  double worst = 0;
  const int n = model_.nLinks();
  for (int trial = 0; trial < 20; ++trial) {
    const DynamicsPoint x = randomPoint(model_, rng_);
    const Eigen::VectorXd sigma =
        Eigen::VectorXd(randomVec(rng_, dynamics::residualRows(model_, dsp_), -2, 2));
    const Eigen::MatrixXd hess = dynamics::residualHessian(model_, x, dsp_, sigma);
    EXPECT_EQ((hess - hess.transpose()).norm(), 0.0);
    const Eigen::VectorXd z = pack(x, dsp_);
    auto gradient = [&](const Eigen::VectorXd& zz) -> Eigen::VectorXd {
      return dynamics::residualJacobian(model_, unpack(zz, n, dsp_), dsp_).transpose() * sigma;
    };
    Eigen::MatrixXd fd(z.size(), z.size());
    const double h = 1e-6;
    for (int k = 0; k < z.size(); ++k) {
      Eigen::VectorXd zp = z, zm = z;
      zp(k) += h;
      zm(k) -= h;
      fd.col(k) = (gradient(zp) - gradient(zm)) / (2 * h);
    }
    const double err = relErr(fd, hess);
    worst = std::max(worst, err);
    EXPECT_LT(err, 1e-6);
  }
  RecordProperty("worst_hessian_fd_relative_error", fmt::format("{:.2e}", worst));
}

std::vector<Case> allCases() {
  std::vector<Case> cases;
  for (const auto& r : allRobots()) {
    cases.push_back({r, false});
    cases.push_back({r, true});
  }
  for (const std::string r : {"mu2004_five_link", "compass_gait"}) {
    cases.push_back({r, false, 0.3});
    cases.push_back({r, true, -0.2});
  }
  return cases;
}

INSTANTIATE_TEST_SUITE_P(AllRobots, ResidualDerivativesTest, ::testing::ValuesIn(allCases()),
                         [](const auto& info) {
                           return info.param.robot + (info.param.dsp ? "_dsp" : "_ssp") +
                                  (info.param.slope != 0 ? "_slope" : "");
                         });

}  // namespace
}  // namespace gaitopt::test
