#include "sim/controllers/computed_torque.hpp"

#include <algorithm>

#include <Eigen/Dense>

#include "dynamics/dsp_dynamics.hpp"
#include "dynamics/ground.hpp"
#include "dynamics/joint_coordinates.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/ssp_dynamics.hpp"

namespace gaitopt::sim {

namespace {

/// E's ground force: the reference's plus its vertical share of the difference in total load.
Vec2d leadingForce(const Vec2d& total, const Vec2d& force_b_ref, const Vec2d& force_e_ref) {
  const Vec2d planned = force_b_ref + force_e_ref;
  const double share = planned(1) > 0 ? std::clamp(force_e_ref(1) / planned(1), 0.0, 1.0) : 0.5;
  return force_e_ref + share * (total - planned);
}

}  // namespace

VecD dspComputedTorque(const dynamics::Model& model, const VecD& theta, const VecD& dtheta,
                       const VecD& pddot, const Vec2d& force_b_ref, const Vec2d& force_e_ref) {
  const int n = model.nLinks();
  const auto now = dynamics::reducedCoordinates(model, theta, dtheta);
  const auto& tip = model.tipWeights();
  const auto jac = dynamics::pointJacobian<double>(tip, theta);
  // n equations, n unknowns: the (n-2) reduced accelerations and the tip staying pinned.
  Eigen::MatrixXd a(n, n);
  Eigen::VectorXd b(n);
  a << now.r, jac;
  b << pddot - now.rdot_dth, -dynamics::pointBias<double>(tip, theta, dtheta);
  const VecD thdd = a.partialPivLu().solve(b);
  const Vec2d total = dynamics::stanceForce<double>(model, theta, dtheta, thdd, Vec2d::Zero());
  const Vec2d force_e = leadingForce(total, force_b_ref, force_e_ref);
  const VecD generalized = dynamics::massMatrix(model, theta) * thdd +
                           dynamics::nonlinearEffects(model, theta, dtheta) -
                           jac.transpose() * force_e;
  return dynamics::jointTorque<double>(generalized);
}

VecD dspTrackingTorque(const dynamics::Model& model, const VecD& theta, const VecD& dtheta,
                       const VecD& pddot, const VecD& planned, const gaits::Knot& ref,
                       DspFeedForward dsp) {
  const auto at = [&](const VecD& a) {
    return dspComputedTorque(model, theta, dtheta, a, ref.force_stance, ref.force_swing);
  };
  const VecD wanted = at(pddot);
  if (dsp == DspFeedForward::kModel) return wanted;
  return VecD(ref.tau) + wanted - at(planned);
}

VecD clipTorque(const dynamics::Model& model, VecD tau) {
  for (int j = 0; j < model.nLinks(); ++j) {
    const auto& joint = model.joints()[static_cast<size_t>(j)];
    const double limit = joint.actuated ? joint.torque_limit : 0.0;
    tau(j) = std::clamp(tau(j), -limit, limit);
  }
  return tau;
}

}  // namespace gaitopt::sim
