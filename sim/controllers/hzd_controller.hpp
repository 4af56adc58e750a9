#pragma once
/// @file hzd_controller.hpp
/// Output-zeroing control of virtual constraints (Westervelt, Grizzle et al. 2003, sec. IV;
/// Isidori's input-output linearisation): with y = q_a - h_d(phi) (hzd_virtual_constraints.hpp)
/// and the pinned-chain dynamics D thetaddot + N = M^T tau (Mu 2.7) on the controller's model,
///   yddot = J thetaddot - h_d''(phi) (c . dtheta)^2,  J = dy/dtheta = H - h_d'(phi) c^T,
///   L_g L_f h = J D^-1 M^T S,  L_f^2 h = -J D^-1 N - h_d''(phi) (c . dtheta)^2,
/// where S injects the n-1 actuated torques (the stance ankle is passive, tau_0 = 0). The
/// feedback-linearising law u = (L_g L_f h)^-1 (-L_f^2 h + v) gives yddot = v, and v comes from
/// a tracking law (tracking_law.hpp) on the error -y: PD v = -Kp y - Kd ydot, or the boundary-
/// layer sliding mode. The torques are clipped to the robot's limits like any controller's.
/// The state alone sets the torques: the step clock's reference knot is ignored.
#include <memory>

#include "sim/controllers/controller.hpp"
#include "sim/controllers/hzd_virtual_constraints.hpp"
#include "sim/controllers/reference.hpp"
#include "sim/controllers/tracking_law.hpp"

namespace gaitopt::sim {

class HzdController : public Controller {
 public:
  HzdController(dynamics::Model nominal, VirtualConstraints constraints,
                std::shared_ptr<const TrackingLaw> law);

  /// @throws std::invalid_argument in double support (HZD walks have an instantaneous one).
  VecD torque(gaits::Phase phase, const VecD& theta, const VecD& dtheta, const gaits::Knot& ref,
              const Eigen::VectorXd& memory) const override;
  /// The actuated torques u before clipping (tau_1 .. tau_n-1).
  VecD unclippedTorque(const VecD& theta, const VecD& dtheta) const;

  const VirtualConstraints& constraints() const { return constraints_; }

 private:
  dynamics::Model model_;
  VirtualConstraints constraints_;
  std::shared_ptr<const TrackingLaw> law_;
};

/// HZD on `ref`'s single support with the fit's default nodes.
/// @throws std::invalid_argument when the reference has a double support or cannot be fitted.
std::unique_ptr<HzdController> makeHzdController(const dynamics::Model& nominal,
                                                 const Reference& ref,
                                                 std::shared_ptr<const TrackingLaw> law);

}  // namespace gaitopt::sim
