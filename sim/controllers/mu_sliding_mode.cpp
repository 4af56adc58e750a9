#include "sim/controllers/mu_sliding_mode.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "dynamics/dsp_dynamics.hpp"
#include "dynamics/joint_coordinates.hpp"
#include "dynamics/ssp_dynamics.hpp"
#include "sim/controllers/computed_torque.hpp"

namespace gaitopt::sim {
namespace {

using dynamics::toAbsolute;
using dynamics::toJoint;

void requirePositive(double value, const std::string& name) {
  if (!(value > 0)) throw std::invalid_argument("sliding-mode " + name + " must be positive");
}

/// The corner models of the box phi in [phi^ / (1 + b), phi^ (1 + b)] (kEitherWay) or
/// [phi^ / (1 + b), phi^] (kOverestimated, Mu's premise) for three groups: masses,
/// inertias, and the geometry (lengths with CoM offsets, scaled together so the two legs stay
/// mirror images, as relabelling (2.38) needs, with the larger of the two bounds). A group with
/// b = 0 stays at the model's value.
std::vector<dynamics::Model> cornerModels(const dynamics::Model& model,
                                          const dynamics::ParameterErrors& b, BoundSide side) {
  const double bounds[3] = {b.mass, b.inertia, std::max(b.length, b.com)};
  if (!(b.mass >= 0 && b.inertia >= 0 && b.length >= 0 && b.com >= 0))
    throw std::invalid_argument("sliding-mode uncertainty bounds must be >= 0");
  std::vector<dynamics::Model> corners;
  for (int mask = 0; mask < 8; ++mask) {
    double e[3];
    bool skip = false;
    for (int g = 0; g < 3; ++g) {
      const bool high = (mask >> g) & 1;
      skip = skip || (bounds[g] == 0 && high);  // one corner for a group without uncertainty
      const double top = side == BoundSide::kEitherWay ? bounds[g] : 0.0;
      e[g] = high ? top : 1 / (1 + bounds[g]) - 1;
    }
    if (!skip) corners.push_back(dynamics::perturbedModel(model, {e[0], e[1], e[2], e[2]}));
  }
  return corners;
}

/// SSP equivalent control (4.4) on model m: T = D_q u + H_q v + G_q, evaluated in absolute
/// angles as M^-T (D M^-1 u + C M^-1 v + G) (2.43-2.44).
VecD sspEquivalent(const dynamics::Model& m, const VecD& theta, const VecD& dtheta, const VecD& u,
                   const VecD& v) {
  const VecD generalized =
      dynamics::massMatrix(m, theta) * toAbsolute<double>(u) +
      dynamics::coriolisMatrixTimes<double>(m, theta, dtheta, toAbsolute<double>(v)) +
      dynamics::gravityVector<double>(m, theta);
  return dynamics::jointTorque<double>(generalized);
}

/// eta of (4.5) / eta_D of (4.13): per joint, the largest departure of a corner model's
/// equivalent control from the controller's own.
template <class Equivalent>
VecD uncertaintyBound(const std::vector<dynamics::Model>& corners, const VecD& own,
                      const Equivalent& equivalent) {
  VecD eta = VecD::Zero(own.size());
  for (const auto& corner : corners) eta = eta.cwiseMax((equivalent(corner) - own).cwiseAbs());
  return eta;
}

}  // namespace

MuSlidingModeGains muTable42(int mu_case) {
  switch (mu_case) {
    case 1:
      return {25, 1, 2, 10, 5, 10};
    case 2:
      return {100, 2.5, 2, 10, 10, 35};
    case 3:
      return {80, 2.5, 2, 30, 5, 10};
    default:
      throw std::invalid_argument("Mu's Table 4.2 has cases 1, 2 and 3, not " +
                                  std::to_string(mu_case));
  }
}

MuSlidingModeController::MuSlidingModeController(dynamics::Model model, MuSlidingModeGains gains,
                                                 const dynamics::ParameterErrors& bound,
                                                 BoundSide side, DspFeedForward dsp)
    : model_(std::move(model)),
      gains_(gains),
      corners_(cornerModels(model_, bound, side)),
      dsp_(dsp) {
  if (!model_.joints().front().actuated)
    throw std::invalid_argument(
        "sliding-mode control of every joint needs an actuated stance ankle");
  requirePositive(gains.ssp_lambda, "SSP Lambda");
  requirePositive(gains.ssp_gamma, "SSP gamma");
  requirePositive(gains.ssp_sigma, "SSP sigma");
  requirePositive(gains.dsp_lambda, "DSP Lambda");
  requirePositive(gains.dsp_alpha, "DSP alpha");
  requirePositive(gains.dsp_sigma, "DSP sigma");
  requirePositive(gains.handover_time, "handover time");
}

int MuSlidingModeController::surfaceMemorySize(gaits::Phase phase) const {
  return phase == gaits::Phase::kSsp ? model_.nLinks() : model_.nLinks() - 2;
}

int MuSlidingModeController::memorySize(gaits::Phase phase) const {
  return surfaceMemorySize(phase) + model_.nLinks();
}

MuSlidingModeController::Errors MuSlidingModeController::errors(
    gaits::Phase phase, const VecD& theta, const VecD& dtheta, const gaits::Knot& ref,
    const Eigen::VectorXd& memory) const {
  Errors r;
  Eigen::VectorXd dd_ref, d_ref;
  double lambda = 0;
  if (phase == gaits::Phase::kSsp) {
    lambda = gains_.ssp_lambda;
    r.e = toJoint<double>(VecD(theta - ref.theta));
    r.edot = toJoint<double>(VecD(dtheta - ref.dtheta));
    dd_ref = toJoint<double>(VecD(ref.ddtheta));
    d_ref = toJoint<double>(VecD(ref.dtheta));
  } else {
    lambda = gains_.dsp_lambda;
    const auto now = dynamics::reducedCoordinates(model_, theta, dtheta);
    const auto want = dynamics::reducedCoordinates(model_, ref.theta, ref.dtheta);
    d_ref = want.r * ref.dtheta;
    r.e = now.p - want.p;
    r.edot = now.r * dtheta - d_ref;
    dd_ref = want.r * ref.ddtheta + want.rdot_dth;
  }
  const double l2 = lambda * lambda;
  const Eigen::VectorXd z = memory.head(surfaceMemorySize(phase));
  r.s = r.edot + 2 * lambda * r.e + l2 * z;
  r.planned = dd_ref;
  r.u = dd_ref - 2 * lambda * r.edot - l2 * r.e;
  r.v = d_ref - 2 * lambda * r.e - l2 * z;
  return r;
}

MuSlidingModeController::SspLaw MuSlidingModeController::sspLaw(const VecD& theta,
                                                                const VecD& dtheta,
                                                                const Errors& err) const {
  const VecD own = sspEquivalent(model_, theta, dtheta, err.u, err.v);
  return {own, sspSwitching(theta, dtheta, err, own)};
}

VecD MuSlidingModeController::sspSwitching(const VecD& theta, const VecD& dtheta, const Errors& err,
                                           const VecD& own) const {
  const VecD eta = uncertaintyBound(corners_, own, [&](const dynamics::Model& m) {
    return sspEquivalent(m, theta, dtheta, err.u, err.v);
  });
  const Eigen::VectorXd switching = (gains_.ssp_gamma * err.s).array().tanh();
  return -((eta.array() + gains_.ssp_sigma) * switching.array()).matrix();
}

VecD MuSlidingModeController::dspTorque(const VecD& theta, const VecD& dtheta,
                                        const gaits::Knot& ref, const Errors& err,
                                        const VecD& carried) const {
  const auto equivalent = [&](const dynamics::Model& m) -> VecD {
    return dspTrackingTorque(m, theta, dtheta, err.u, err.planned, ref, dsp_);
  };
  const VecD own = equivalent(model_);
  const VecD eta = uncertaintyBound(corners_, own, equivalent);
  // C^ on joint torques: pdd = B pdot + C_theta (M^T T - N) (2.21, 2.43).
  const int n = model_.nLinks();
  const Eigen::MatrixXd c =
      dynamics::reducedDspModel(model_, theta, dtheta).c * dynamics::jointMap(n).transpose();
  const Eigen::MatrixXd c_pinv =
      c.transpose() * (c * c.transpose()).ldlt().solve(Eigen::MatrixXd::Identity(n - 2, n - 2));
  const Eigen::VectorXd per_output =
      (gains_.dsp_alpha * err.s).array().tanh() *
      (c.cwiseAbs() * (eta.array() + gains_.dsp_sigma).matrix()).array();
  return own + carried - c_pinv * per_output;
}

VecD MuSlidingModeController::unclippedTorque(gaits::Phase phase, const VecD& theta,
                                              const VecD& dtheta, const gaits::Knot& ref,
                                              const Eigen::VectorXd& memory) const {
  const Errors err = errors(phase, theta, dtheta, ref, memory);
  if (phase == gaits::Phase::kDsp)
    return dspTorque(theta, dtheta, ref, err, memory.tail(model_.nLinks()));
  const SspLaw law = sspLaw(theta, dtheta, err);
  return law.own + law.switching;
}

VecD MuSlidingModeController::torque(gaits::Phase phase, const VecD& theta, const VecD& dtheta,
                                     const gaits::Knot& ref, const Eigen::VectorXd& memory) const {
  return clipTorque(model_, unclippedTorque(phase, theta, dtheta, ref, memory));
}

Eigen::VectorXd MuSlidingModeController::phaseStartMemory(gaits::Phase phase, const VecD& theta,
                                                          const VecD& dtheta,
                                                          const gaits::Knot& ref,
                                                          const PhaseHandover* previous) const {
  Eigen::VectorXd memory = Eigen::VectorXd::Zero(memorySize(phase));
  // (4.1) at z = 0 is edot + 2 Lambda e; the z that cancels it.
  const double lambda = phase == gaits::Phase::kSsp ? gains_.ssp_lambda : gains_.dsp_lambda;
  memory.head(surfaceMemorySize(phase)) =
      -errors(phase, theta, dtheta, ref, memory).s / (lambda * lambda);
  if (phase == gaits::Phase::kDsp && previous != nullptr && previous->phase == gaits::Phase::kSsp) {
    memory.tail(model_.nLinks()) = previous->memory.tail(model_.nLinks());
    memory(surfaceMemorySize(phase)) = 0;  // not the stance ankle's (mu_sliding_mode.hpp)
  }
  return memory;
}

Eigen::VectorXd MuSlidingModeController::rateOf(gaits::Phase phase, const Errors& err,
                                                const VecD& switching,
                                                const Eigen::VectorXd& memory) const {
  Eigen::VectorXd rate = Eigen::VectorXd::Zero(memorySize(phase));
  rate.head(surfaceMemorySize(phase)) = err.e;
  if (phase == gaits::Phase::kSsp)
    rate.tail(model_.nLinks()) = (switching - memory.tail(model_.nLinks())) / gains_.handover_time;
  return rate;
}

Eigen::VectorXd MuSlidingModeController::memoryRate(gaits::Phase phase, const VecD& theta,
                                                    const VecD& dtheta, const gaits::Knot& ref,
                                                    const Eigen::VectorXd& memory) const {
  const Errors err = errors(phase, theta, dtheta, ref, memory);
  if (phase == gaits::Phase::kDsp) return rateOf(phase, err, VecD(), memory);
  return rateOf(phase, err, sspLaw(theta, dtheta, err).switching, memory);
}

ControlOutput MuSlidingModeController::control(gaits::Phase phase, const VecD& theta,
                                               const VecD& dtheta, const gaits::Knot& ref,
                                               const Eigen::VectorXd& memory) const {
  const Errors err = errors(phase, theta, dtheta, ref, memory);
  if (phase == gaits::Phase::kDsp)
    return {clipTorque(model_, dspTorque(theta, dtheta, ref, err, memory.tail(model_.nLinks()))),
            rateOf(phase, err, VecD(), memory)};
  const SspLaw law = sspLaw(theta, dtheta, err);
  return {clipTorque(model_, law.own + law.switching), rateOf(phase, err, law.switching, memory)};
}

Eigen::VectorXd MuSlidingModeController::slidingVariable(gaits::Phase phase, const VecD& theta,
                                                         const VecD& dtheta, const gaits::Knot& ref,
                                                         const Eigen::VectorXd& memory) const {
  return errors(phase, theta, dtheta, ref, memory).s;
}

}  // namespace gaitopt::sim
