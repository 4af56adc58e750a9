#include "sim/controllers/hzd_controller.hpp"

#include <stdexcept>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include "dynamics/joint_coordinates.hpp"
#include "dynamics/ssp_dynamics.hpp"
#include "sim/controllers/computed_torque.hpp"

namespace gaitopt::sim {

HzdController::HzdController(dynamics::Model nominal, VirtualConstraints constraints,
                             std::shared_ptr<const TrackingLaw> law)
    : model_(std::move(nominal)), constraints_(std::move(constraints)), law_(std::move(law)) {}

VecD HzdController::unclippedTorque(const VecD& theta, const VecD& dtheta) const {
  const int n = model_.nLinks();
  const VecD& c = constraints_.phaseWeights();
  const double dphi = c.dot(dtheta);
  const auto h = constraints_.at(c.dot(theta));
  // J = H - h_d' c^T with H the rows 1..n-1 of the joint map (q_a = H theta).
  const Eigen::MatrixXd jac = dynamics::jointMap(n).bottomRows(n - 1) - h.dh * c.transpose();
  const auto d = dynamics::massMatrix<double>(model_, theta).ldlt();
  Eigen::MatrixXd injected(n, n - 1);  // D^-1 M^T S: thetaddot per unit actuated torque
  for (int j = 1; j < n; ++j)
    injected.col(j - 1) = d.solve(dynamics::generalizedTorque<double>(VecD::Unit(n, j)));
  const Eigen::MatrixXd lglf = jac * injected;
  const VecD lf2 = -jac * d.solve(dynamics::nonlinearEffects<double>(model_, theta, dtheta)) -
                   h.ddh * dphi * dphi;
  const VecD y = constraints_.output(theta), dy = constraints_.outputRate(theta, dtheta);
  const VecD v = law_->correction(-y, -dy);
  return lglf.partialPivLu().solve(v - lf2);
}

VecD HzdController::torque(gaits::Phase phase, const VecD& theta, const VecD& dtheta,
                           const gaits::Knot& /*ref*/, const Eigen::VectorXd& /*memory*/) const {
  if (phase != gaits::Phase::kSsp) throw std::invalid_argument("HZD control has no double support");
  const int n = model_.nLinks();
  VecD tau = VecD::Zero(n);
  tau.tail(n - 1) = unclippedTorque(theta, dtheta);
  return clipTorque(model_, tau);  // the passive stance ankle stays at 0
}

std::unique_ptr<HzdController> makeHzdController(const dynamics::Model& nominal,
                                                 const Reference& ref,
                                                 std::shared_ptr<const TrackingLaw> law) {
  if (ref.hasDsp())
    throw std::invalid_argument(
        "HZD control needs a gait with an instantaneous double support (this one has a DSP)");
  return std::make_unique<HzdController>(nominal, VirtualConstraints(nominal, ref), std::move(law));
}

}  // namespace gaitopt::sim
