#include "dynamics/dsp_dynamics.hpp"

#include <stdexcept>

namespace gaitopt::dynamics {
namespace {

using MatK = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxLinks + 2, kMaxLinks + 2>;

}  // namespace

DspSolution dspForwardDynamics(const Model& model, const VecD& theta, const VecD& dtheta,
                               const VecD& tau) {
  const int n = model.nLinks();
  const Mat2Xd jac = pointJacobian(model.tipWeights(), theta);
  MatK kkt = MatK::Zero(n + 2, n + 2);
  kkt.topLeftCorner(n, n) = massMatrix(model, theta);
  kkt.topRightCorner(n, 2) = -jac.transpose();
  kkt.bottomLeftCorner(2, n) = jac;
  VecR<double> rhs(n + 2);
  rhs.head(n) = generalizedTorque(tau) - nonlinearEffects(model, theta, dtheta);
  rhs.tail(2) = -pointBias(model.tipWeights(), theta, dtheta);
  const VecR<double> sol = kkt.partialPivLu().solve(rhs);
  return {sol.head(n), sol.tail<2>()};
}

ReducedCoordinates reducedCoordinates(const Model& model, const VecD& theta, const VecD& dtheta) {
  const int n = model.nLinks();
  const bool knees = model.legLinks() >= 2;
  const int m = (knees ? 2 : 0) + (model.torso() ? 1 : 0);
  if (n == 2)
    throw std::invalid_argument("a two-link chain pinned at both tips is rigid: no DSP motion");
  if (m != n - 2)
    throw std::invalid_argument("the DSP of this chain has no independent coordinates");
  ReducedCoordinates out{VecD::Zero(m), MatD::Zero(m, n), VecD::Zero(m)};
  int row = 0;
  if (knees) {
    out.p.head<2>() = pointPosition(model.hipWeights(), theta);
    out.r.topRows(2) = pointJacobian(model.hipWeights(), theta);
    out.rdot_dth.head<2>() = pointBias(model.hipWeights(), theta, dtheta);
    row = 2;
  }
  if (const auto t = model.torso()) {
    out.p(row) = theta(*t);
    out.r(row, *t) = 1;
  }
  return out;
}

ReducedDsp reducedDspModel(const Model& model, const VecD& theta, const VecD& dtheta) {
  const int n = model.nLinks();
  const ReducedCoordinates rc = reducedCoordinates(model, theta, dtheta);
  const int m = n - 2;
  const Mat2Xd jac = pointJacobian(model.tipWeights(), theta);
  MatD a(n, n), adot(n, n);  // [R; J] and [Rdot; Jdot] of (2.16-2.17)
  a << rc.r, jac;
  MatD rdot = MatD::Zero(m, n);
  if (model.legLinks() >= 2) rdot.topRows(2) = pointJacobianDot(model.hipWeights(), theta, dtheta);
  adot << rdot, pointJacobianDot(model.tipWeights(), theta, dtheta);

  const auto d_ldlt = massMatrix(model, theta).ldlt();
  const MatD sa = adot * a.inverse();                      // S_a (2.19)
  const MatD sb = a * d_ldlt.solve(MatD::Identity(n, n));  // S_b = [R; J] D^-1
  const MatD sc = sb * jac.transpose();                    // S_c = [R; J] D^-1 J^T
  const Eigen::Matrix2d sc2_inv = sc.bottomRows(2).inverse();
  const MatD sc1 = sc.topRows(m);

  ReducedDsp out;
  out.b = sa.topLeftCorner(m, m) - sc1 * sc2_inv * sa.bottomLeftCorner(2, m);  // (2.21)
  out.c = sb.topRows(m) - sc1 * sc2_inv * sb.bottomRows(2);                    // (2.21)
  out.lam_p = -sc2_inv * sa.bottomLeftCorner(2, m);                            // (2.20b)
  out.lam_t = -sc2_inv * sb.bottomRows(2);                                     // (2.20b)
  out.n_vec = nonlinearEffects(model, theta, dtheta);
  out.pdot = rc.r * dtheta;
  return out;
}

}  // namespace gaitopt::dynamics
