#pragma once
/// @file rigid_contact_loop.hpp
/// The closed loop of the rigid walk (hybrid_walk.hpp) in one phase and contact mode: controller
/// torques, the stance ankle limited by the foot (contact_rules.hpp), and the free-base
/// accelerations and tip forces of contact_dynamics.hpp. The state is x = (q, qdot, z) with
/// q = (x_b, y_b, theta): B relative to where the step started, and z the controller's memory
/// (controller.hpp), zero at the phase start. The reference starts from where the robot is
/// (`start`, reference.hpp).
#include <optional>

#include <Eigen/Core>

#include "dynamics/model.hpp"
#include "sim/contact/contact_dynamics.hpp"
#include "sim/contact/contact_rules.hpp"
#include "sim/controllers/reference.hpp"
#include "sim/controllers/tracking_controller.hpp"
#include "sim/walk/push.hpp"

namespace gaitopt::sim {

class ContactLoop {
 public:
  struct State {
    VecD theta, dtheta, tau;
    Eigen::VectorXd qdot, qddot;
    Vec2d force_stance = Vec2d::Zero(), force_swing = Vec2d::Zero();  ///< at B, E [N]
    gaits::Knot ref;
    Eigen::VectorXd memory, memory_rate;
    double cop_margin = 0;   ///< of the CoP the controller asked for (StepResult) [m]
    double cop_moment = 1;   ///< dynamics::copMomentMargin of that request [N m]
    bool saturated = false;  ///< the plant's ankle torque was clipped
    /// Of the torques, the push and the friction of a sliding tip: a tip held on rigid ground
    /// does no work, so a step that gains more energy than this does diverged [W].
    double power = 0;
  };

  ContactLoop(const dynamics::Model& plant, const Controller& controller, const Reference& ref,
              gaits::Phase phase, PhaseStart start, const ContactSet& contacts,
              const ContactRules& rules, const std::optional<Push>& push = {}, int step = 0);

  /// The closed loop at (t, x); the last evaluation is kept (events and the observer ask for the
  /// state an RK4 step ended at, where the next step's first stage starts).
  const State& at(double t, const Eigen::VectorXd& x) const;
  Eigen::VectorXd rhs(double t, const Eigen::VectorXd& x) const;

  gaits::Phase phase() const { return phase_; }

 private:
  State evaluate(double t, const Eigen::VectorXd& x) const;
  /// The CoP margins of the stance ankle's torque, clipped when the rules saturate it.
  void limitAnkle(State& s, const Vec2d& pushed) const;
  /// Clips tau0 so the CoP -tau0 / F_By stays in [-heel, toe] (F_By is affine in tau0).
  void saturateAnkle(State& s, const Vec2d& pushed) const;
  bool ankleLimited() const;
  double power(const State& s, const Vec2d& pushed) const;

  const dynamics::Model& plant_;
  const Controller& controller_;
  const Reference& ref_;
  gaits::Phase phase_;
  PhaseStart start_;
  ContactSet contacts_;
  ContactRules rules_;
  std::optional<Push> push_;  ///< acts in single support only
  int step_;                  ///< 0-based, for the push

  // The cache of at(); a loop is local to one phase of one step, never shared by threads.
  mutable bool cached_ = false;
  mutable double cached_t_ = 0;
  mutable Eigen::VectorXd cached_x_;
  mutable State cached_state_;
};

/// Free-base state x = (q, qdot, 0) from the angles and rates with B at (x_b, 0) moving at v_b,
/// and `memory` zeros for the controller.
Eigen::VectorXd contactState(const VecD& theta, const VecD& dtheta, double x_b = 0,
                             const Vec2d& v_b = Vec2d::Zero(), int memory = 0);

/// The controller's memory in x = (q, qdot, memory) of an n_links robot.
Eigen::VectorXd contactMemory(const Eigen::VectorXd& x, int n_links);

}  // namespace gaitopt::sim
