#pragma once
/// @file mu_sliding_mode.hpp
/// The sliding-mode controller of Mu (2004) ch. 4 as written, on the controller's model (the
/// hatted matrices) with a known bound on how far the true robot may be from it.
///  SSP, joint coordinates q (2.39), e = q - q_d, memory z = int e (from phaseStartMemory):
///    s = edot + 2 Lambda e + Lambda^2 z                                        (4.1)
///    u = qdd_d - 2 Lambda edot - Lambda^2 e,  v = qdot_d - 2 Lambda e - Lambda^2 z  (4.2)
///    T^ = D^_q u + H^_q v + G^_q   (equivalent control, H as a matrix)          (4.4)
///    T = T^ - (eta + sigma) o tanh(gamma s)                                     (4.5)-(4.6)
///  DSP, reduced coordinates p = (hip x, hip y, torso) (2.21), e = p - p_d, z = int e:
///    s and u as above in p;  T^ realises pdd = u on the hatted model          (4.10)-(4.12)
///    T = T^ - C^- diag(tanh(alpha s)) |C^| (eta_D + sigma)                     (4.14)
///  with C^ the map from joint torques to pdd (2.21 with T_theta = M^T T, 2.43) and
///  C^- = C^T (C C^T)^-1 its right pseudo-inverse.
/// eta (4.5) needs the true matrices, which Mu takes from the simulation; here the controller
/// knows only a bound b, and eta_i is the largest |T^_i - T_i| over the 2^3 corner models of the
/// box where the true masses, inertias, lengths and CoM offsets may be (masses, inertias,
/// geometry; the torques are multilinear in masses and inertias at fixed state, so the corners
/// bound them in practice; not a proof). The box is one of two (BoundSide): within a factor
/// (1 + b) of the model either way, or Mu's premise (sec. 4.2, phi^ = (1 + E) phi with E >= 0:
/// the model overestimates), the truth between phi^ / (1 + b) and phi^. Under Mu's premise one
/// corner is the true robot when b = E, so eta is Mu's exact |Delta| or above it; the symmetric
/// box also reaches phi^ (1 + b), four times the robot's mass in Mu's case 3, and roughly doubles
/// eta. Measured on the polynomial gait, case 3, 0.30 m heel: with Mu's premise it walks 20 of
/// 20 steps; with the symmetric box the ankle torque reached 1359 N m 2 ms into the first step
/// and the stance tip lifted off.
/// Two deviations. For the switch to double support, a "bumpless transfer": the SSP law also
/// low-passes its switching term -(eta + sigma) o tanh(gamma s) (4.5) into T_c,
///    dT_c/dt = (-(eta + sigma) o tanh(gamma s) - T_c) / t_h,   T_c = 0 at the step's start,
/// and the DSP law adds the T_c the SSP ended with, held over the DSP, except at the stance ankle:
/// the DSP starts with the correction the SSP law had found for its model instead of jumping back
/// to T^. In the SSP all five joints are tracked, so that correction includes what the DSP's
/// switching term (on the three p, through C^-) cannot see: torques that only press the tips
/// against each other. Without T_c, on Mu's case 3 (the model twice the robot's mass) T^ pressed
/// the trailing tip with 826 N, 2.8 times the robot's 292 N weight, 1 ms into the DSP, the torques
/// hit their 150 N m limits and the leading tip lifted off at 4 ms
/// (results/mu_cases/walks_by_plant.md). The stance ankle is left out because in the SSP it
/// carries the whole robot's moment about the stance tip, which the DSP shares with the leading
/// tip's force: carried, its -55 N m (t_h = 0.1 s) lifted the polynomial gait's leading tip off
/// (0.30 m heel, model mass +60 %, which walks without T_c). The filter keeps a reaching transient
/// at touchdown out of T_c (the last instant's switching term was -179 N m there). t_h = 0.05 s:
/// the robust optimum's case 3 and the polynomial gait's case 2 walk 20 steps for t_h from 0.03 to
/// 0.3 s, and the polynomial gait with the model's mass +80 % only at 0.05 s. For the contact: Mu's
/// T^ in the DSP (4.12) is the minimum-norm solution C^- (u - B^ pdot) + N^, which leaves the split
/// of the load between the two tips to chance; here T^ gives pdd = u with the leading tip carrying
/// the reference's ground force (the planned load sharing, inside its friction cone),
/// computed_torque.hpp. The switching term is Mu's.
/// With DspFeedForward::kPlan (mu_sliding_mode_plan_dsp) the DSP's T^ is the reference's own
/// torques plus what u - pdd_d costs on the hatted model (dspTrackingTorque), and eta_D bounds
/// only that correction's error over the corners: the optimised plan holds the load split and the
/// tips' internal force the plant needs, which the model's T^ gets wrong by the model's error. On
/// the ensemble optimum (configs/ocp/mu2004_walk_ensemble.yaml) under Mu's case 2, T^ pressed the
/// trailing tip to the edge of its friction cone 1 ms into the DSP and it slid (1 of 20 steps);
/// with the plan's torques cases 2 and 3 walk 20 of 20 (results/mu_cases). The bound assumes the
/// plan fits the plant (Mu's setting: the error is the controller's); on a plant 20 % heavier
/// than the plan's the ankle torque it commands then puts the CoP beyond the foot in step 2 (a
/// fall under the strict CoP rule, results/ensemble_walks, which the law as written walks; with
/// the ankle torque clipped to the foot it walks 20 steps, results/ensemble_walks_clipped).
#include <vector>

#include "dynamics/model.hpp"
#include "dynamics/model_variation.hpp"
#include "sim/controllers/computed_torque.hpp"
#include "sim/controllers/controller.hpp"

namespace gaitopt::sim {

/// Which box of parameters the uncertainty bound b describes (see above).
enum class BoundSide {
  kEitherWay,     ///< phi in [phi^ / (1 + b), phi^ (1 + b)]
  kOverestimated  ///< phi in [phi^ / (1 + b), phi^]: Mu's premise, phi^ = (1 + E) phi
};

/// Mu's controller constants (Table 4.2), the same on every diagonal entry.
struct MuSlidingModeGains {
  double ssp_lambda = 25, ssp_gamma = 1, ssp_sigma = 2;   ///< [1/s], [s/rad], [N m]
  double dsp_lambda = 10, dsp_alpha = 5, dsp_sigma = 10;  ///< [1/s], [s/m], [N m]
  double handover_time = 0.05;  ///< t_h of the SSP's low-passed switching term T_c [s] (not Mu's)
};

/// Table 4.2 for Mu's uncertainty case 1, 2 or 3. @throws std::invalid_argument otherwise.
MuSlidingModeGains muTable42(int mu_case);

class MuSlidingModeController : public Controller {
 public:
  /// `bound`: the relative uncertainty b of each parameter group (>= 0; 0.4 = the true value is
  /// within a factor 1.4 of the model's, on the side(s) `side` says). @throws
  /// std::invalid_argument when the stance ankle is unactuated, a gain is not positive or a bound
  /// is negative.
  MuSlidingModeController(dynamics::Model model, MuSlidingModeGains gains,
                          const dynamics::ParameterErrors& bound,
                          BoundSide side = BoundSide::kEitherWay,
                          DspFeedForward dsp = DspFeedForward::kModel);

  VecD torque(gaits::Phase phase, const VecD& theta, const VecD& dtheta, const gaits::Knot& ref,
              const Eigen::VectorXd& memory) const override;
  /// The same before clipping to the torque limits (Mu's proof assumes no saturation).
  VecD unclippedTorque(gaits::Phase phase, const VecD& theta, const VecD& dtheta,
                       const gaits::Knot& ref, const Eigen::VectorXd& memory) const;
  /// int e (n over q in the SSP, n - 2 over p in the DSP), then the n torques T_c.
  int memorySize(gaits::Phase phase) const override;
  /// The integral of (4.1) starts where the surface passes through the robot, s(t0) = 0:
  /// z(t0) = -(edot + 2 Lambda e) / Lambda^2 at the phase start. Mu starts on the reference
  /// (e = 0, so s = 0, sec. 4.3) and lets the errors a phase inherits decay under u's
  /// K_P = Lambda^2, K_D = 2 Lambda (4.2, 4.10); the switching term (4.6, 4.14) is sized for
  /// the model's uncertainty (4.8-4.9, 4.16-4.17), not for that reaching. From z = 0 it took
  /// the reaching on: at the early touchdown on the impedance ground, s = (-0.25, 0.015, -0.32)
  /// put tanh(alpha s) near 1, and (4.14) through C^- took 897 N off the leading tip's planned
  /// 175 N on the controller's pinned model: the tip left the ground 0.8 ms after touchdown.
  /// T_c: zero in the SSP; in the DSP the SSP's at `previous` (zero without one).
  Eigen::VectorXd phaseStartMemory(gaits::Phase phase, const VecD& theta, const VecD& dtheta,
                                   const gaits::Knot& ref,
                                   const PhaseHandover* previous) const override;
  /// e for the integral of (4.1); T_c's filter in the SSP, held in the DSP.
  Eigen::VectorXd memoryRate(gaits::Phase phase, const VecD& theta, const VecD& dtheta,
                             const gaits::Knot& ref, const Eigen::VectorXd& memory) const override;
  /// torque() and memoryRate() with the SSP's equivalent control and switching term computed
  /// once (they are most of a walk's time).
  ControlOutput control(gaits::Phase phase, const VecD& theta, const VecD& dtheta,
                        const gaits::Knot& ref, const Eigen::VectorXd& memory) const override;

  /// The sliding variable s (4.1) at the same arguments, for tests and logs.
  Eigen::VectorXd slidingVariable(gaits::Phase phase, const VecD& theta, const VecD& dtheta,
                                  const gaits::Knot& ref, const Eigen::VectorXd& memory) const;

 private:
  struct Errors {
    Eigen::VectorXd e, edot;
    Eigen::VectorXd u;        ///< (4.2)/(4.10) reference acceleration
    Eigen::VectorXd planned;  ///< the reference's own acceleration (qdd_d or pdd_d)
    Eigen::VectorXd v;        ///< (4.2), SSP only
    Eigen::VectorXd s;        ///< (4.1)
  };
  Errors errors(gaits::Phase phase, const VecD& theta, const VecD& dtheta, const gaits::Knot& ref,
                const Eigen::VectorXd& memory) const;
  /// The SSP law's two parts at one state: the equivalent control (4.4) and the switching term
  /// (4.5)-(4.6); the torque is their sum, T_c's filter follows the second.
  struct SspLaw {
    VecD own, switching;
  };
  SspLaw sspLaw(const VecD& theta, const VecD& dtheta, const Errors& err) const;
  VecD dspTorque(const VecD& theta, const VecD& dtheta, const gaits::Knot& ref, const Errors& err,
                 const VecD& carried) const;
  /// The SSP's switching term -(eta + sigma) o tanh(gamma s) of (4.5)-(4.6) at that state,
  /// `own` its equivalent control (4.4).
  VecD sspSwitching(const VecD& theta, const VecD& dtheta, const Errors& err,
                    const VecD& own) const;
  /// d(memory)/dt: e, then in the SSP T_c's filter towards `switching` (unused in the DSP).
  Eigen::VectorXd rateOf(gaits::Phase phase, const Errors& err, const VecD& switching,
                         const Eigen::VectorXd& memory) const;
  /// The integral z of (4.1) inside the memory of `phase`.
  int surfaceMemorySize(gaits::Phase phase) const;

  dynamics::Model model_;
  MuSlidingModeGains gains_;
  std::vector<dynamics::Model> corners_;  ///< where the true robot may be
  DspFeedForward dsp_;
};

}  // namespace gaitopt::sim
