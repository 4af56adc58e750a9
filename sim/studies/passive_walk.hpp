#pragma once
/// @file passive_walk.hpp
/// Passive walking of a two-leg chain down a slope (McGeer 1990; Goswami, Thuilot and Espiau
/// 1998; Garcia, Chatterjee, Ruina and Coleman 1998): no joint torque, the swing tip's
/// touchdown located by root finding, the single impact of Mu (2.32-2.36) and relabelling
/// (2.38). The stride map P takes the state at a step's start (after relabelling) to the next
/// step's start; a gait of period k is a fixed point of P^k, found by Newton's method on
/// P^k(x) - x with a central-difference Jacobian, and its multipliers are the eigenvalues of
/// d(P^k)/dx there (one is zero: the start posture has both tips on the ground, a constraint P
/// lands on whatever the perturbation). As in Garcia et al., the swing tip may pass through the
/// ground while the legs cross (scuffing is ignored): the touchdown is the first return of the
/// tip to the ground after it has been ahead of the stance tip and above the ground.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dynamics/model.hpp"

namespace gaitopt::sim {

struct PassiveWalkOptions {
  double step = 1e-3;             ///< RK4 step [s]
  double time_tolerance = 1e-13;  ///< touchdown time [s]: the map's smoothness for differences
  double max_step_time = 50.0;    ///< a step not touched down by then has fallen [s]
  double perturbation = 1e-6;     ///< central-difference step [rad, rad/s]
  double newton_tolerance = 1e-11;
  int newton_iterations = 30;
};

/// `walker` on a slope going down by `gamma` [rad] (dynamics::withSlope: > 0 is uphill there).
dynamics::Model downhill(const dynamics::Model& walker, double gamma);

/// One passive step from the step's start state x = (theta, dtheta).
struct PassiveStep {
  bool ok = false;
  std::string failure;            ///< "fell backwards", "fell forwards", "no touchdown"
  Eigen::VectorXd touchdown;      ///< the state just before the impact (theta, dtheta)
  Eigen::VectorXd next;           ///< the next step's start (theta, dtheta)
  double duration = 0;            ///< [s]
  double interleg_angle = 0;      ///< between the legs at touchdown [rad]
  bool single_impact_ok = false;  ///< the trailing tip leaves the ground (Mu 2.37a)
};

/// The step from x on `model` (its slope applied: dynamics::withSlope).
PassiveStep passiveStep(const dynamics::Model& model, const Eigen::VectorXd& x,
                        const PassiveWalkOptions& options = {});

/// A periodic passive gait: a fixed point of P^period.
struct PassiveGait {
  bool ok = false;
  std::string failure;
  int period = 1;
  Eigen::VectorXd start;                ///< (theta, dtheta) at the first step's start
  double residual = 0;                  ///< |P^period(start) - start|_inf
  std::vector<double> durations;        ///< of its steps [s]
  std::vector<double> interleg_angles;  ///< at its touchdowns [rad]
  Eigen::MatrixXd jacobian;             ///< d(P^period)/dx at start
  Eigen::VectorXcd multipliers;
  double max_multiplier = 0;  ///< largest |multiplier|
  /// The real multiplier most negative, -inf when none is real and below -1e-6 (the zero one is
  /// the constraint's): it crosses -1 where the gait doubles its period.
  double most_negative_multiplier = 0;
};

/// Newton's method on P^period(x) - x from `guess`.
PassiveGait findPassiveGait(const dynamics::Model& model, const Eigen::VectorXd& guess, int period,
                            const PassiveWalkOptions& options = {});

/// Whether a gait of period 2k found by findPassiveGait is a gait of that period, not a gait of
/// period k counted twice: its first k steps differ from its last k by more than `tolerance` in
/// duration [s].
bool hasDistinctHalves(const PassiveGait& gait, double tolerance = 1e-6);

/// The gait of twice the period of `gait` (a fixed point of P^k of `model`), searched by Newton's
/// method from `gait`'s start moved along the eigenvector of its most negative multiplier (the
/// direction a doubled gait leaves by) by 1e-3, 1e-2 and 3e-2, each way; the first one found
/// with distinct halves. Not ok when every search lands on `gait` again or fails, as below the
/// doubling slope, where no such gait exists nearby.
PassiveGait findDoubledGait(const dynamics::Model& model, const PassiveGait& gait,
                            const PassiveWalkOptions& options = {});

}  // namespace gaitopt::sim
