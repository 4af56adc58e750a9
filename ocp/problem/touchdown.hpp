#pragma once
/// @file touchdown.hpp
/// The touchdown at the end of the single support as its own object (as Crocoddyl models an
/// impulse next to its continuous phases): the swing tip lands at (step_length, 0), then
///   impactless: the tip arrives at rest, the rates carry over;
///   rigid impact: the rates jump, the strike optionally designed (normal velocity and strike
///   angle in ranges, OcpConfig::touchdown), with qdot+ and the impulses as variables
///   (ImpactLayout) tied by the impact equations (Mu 2.57-2.62, dynamics/floating_base.hpp), the
///   impulses inside their friction cones and pushing up (2.31 double, 2.37b single) with ground
///   contact on.
/// It owns its variables, rows, guess and energy-loss report.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dynamics/impact/impact.hpp"
#include "dynamics/model.hpp"
#include "ocp/problem/ocp_config.hpp"
#include "ocp/transcription/nlp.hpp"
#include "ocp/transcription/phase.hpp"

namespace gaitopt::ocp {

/// The swing tip's strike in a solution (Mu ch. 5 notation).
struct StrikeReport {
  Vec2d tip_velocity = Vec2d::Zero();  ///< Xdot_e^- relative to B [m/s]
  double normal_velocity = 0;          ///< -ydot_e^- [m/s], > 0 downward
  double angle = 0;  ///< alpha = atan2(-ydot_e^-, -xdot_e^-) [rad]; pi/2 straight down
  /// Which impact the pre-impact state admits by Mu's refined criterion (sec. 5.3).
  dynamics::ImpactType admitted = dynamics::ImpactType::kNeither;
  /// The NLP's impulses on the robot [N s]: at E (P_r or P_S) and at B (P_l, zero for a single
  /// impact); zero when impactless.
  Vec2d impulse_leading = Vec2d::Zero(), impulse_trailing = Vec2d::Zero();
};

class Touchdown {
 public:
  Touchdown() = default;
  /// Adds the touchdown's rows (and impact variables, guessed from the closed-form impact maps
  /// at the strike state of the SSP's guess) to `nlp`, all of phase kLinkPhase: they tie the
  /// SSP's last point to what follows it.
  /// `prefix` starts the names of its sets and block when the problem holds several touchdowns
  /// (other steps, model variants: ocp/shape/gait_shape.hpp).
  /// @throws std::invalid_argument when the friction margin leaves no cone.
  static Touchdown add(Nlp& nlp, const dynamics::Model& model, const OcpConfig& config,
                       const Phase& ssp, double step_length, const std::string& prefix = "");

  /// The impact variables; nullopt when the touchdown is impactless.
  const std::optional<ImpactLayout>& impact() const { return impact_; }
  /// Decision-vector indices of the joint rates right after the touchdown (n).
  const std::vector<int>& ratesAfter() const { return rates_after_; }
  /// The strike state's tip velocity, strike angle and admitted impact type (x: the decision
  /// vector).
  StrikeReport strike(const dynamics::Model& model, const Eigen::VectorXd& x) const;
  /// Kinetic energy lost in the strike [J], from the solution's own impact variables (x: the
  /// decision vector); nullopt when impactless.
  std::optional<double> energyLoss(const dynamics::Model& model, const Eigen::VectorXd& x) const;

 private:
  std::vector<int> strike_;  ///< (theta, dtheta) at the end of the SSP (2 n)
  std::vector<int> rates_after_;
  std::optional<ImpactLayout> impact_;
};

}  // namespace gaitopt::ocp
