#pragma once
/// @file touchdown.hpp
/// The touchdown at the end of the single support as its own object (as Crocoddyl models an
/// impulse next to its continuous phases): the swing tip lands at (step_length, 0), then
///   impactless: the tip arrives at rest, the rates carry over;
///   rigid impact: the rates jump, with qdot+ and the impulses as variables (ImpactLayout) tied
///   by the impact equations (Mu 2.57-2.62, dynamics/floating_base.hpp), the impulses inside
///   their friction cones for a double impact.
/// It owns its variables, rows, guess and energy-loss report.
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "dynamics/model.hpp"
#include "ocp/nlp.hpp"
#include "ocp/ocp_config.hpp"
#include "ocp/phase.hpp"

namespace gaitopt::ocp {

class Touchdown {
 public:
  Touchdown() = default;
  /// Adds the touchdown's rows (and impact variables, guessed from the closed-form impact maps
  /// at the strike state of the SSP's guess) to `nlp`, all of phase kLinkPhase: they tie the
  /// SSP's last point to what follows it.
  /// @throws std::invalid_argument when the friction margin leaves no cone.
  static Touchdown add(Nlp& nlp, const dynamics::Model& model, const OcpConfig& config,
                       const Phase& ssp, double step_length);

  /// The impact variables; nullopt when the touchdown is impactless.
  const std::optional<ImpactLayout>& impact() const { return impact_; }
  /// Decision-vector indices of the joint rates right after the touchdown (n).
  const std::vector<int>& ratesAfter() const { return rates_after_; }
  /// Kinetic energy lost in the strike [J], from the solution's own impact variables (x: the
  /// decision vector); nullopt when impactless.
  std::optional<double> energyLoss(const dynamics::Model& model, const Eigen::VectorXd& x) const;

 private:
  std::vector<int> strike_;  ///< (theta, dtheta) at the end of the SSP (2 n)
  std::vector<int> rates_after_;
  std::optional<ImpactLayout> impact_;
};

}  // namespace gaitopt::ocp
