#pragma once
/// @file contact_dynamics.hpp
/// The chain on rigid ground with each tip free, sticking or sliding (Hurmuzlu, Genot, Brogliato
/// 2001, sec. 3.3.1): the free-base equations of motion (floating_base_dynamics.hpp)
///   D_ext qddot + b = M_ext^T tau + J_H^T F_push + sum_tips (J_n^T N + J_t^T T),
/// with, at a tip on the ground, the normal acceleration zero (N is its multiplier, HGB 10 with
/// the contact kept), and tangentially either
///   stick:  the tangential acceleration zero, T its multiplier (HGB 35, first line), or
///   slide:  T = -mu N s with s = sgn(v_t) the direction of the slip (HGB 30 and 34).
/// A free tip carries no force. The pinned single and double support of Mu (2.7, 2.11) are the
/// all-sticking cases. The multipliers come from one square linear system (HGB 36-37 with the
/// modes fixed); a sliding tip whose system is singular is a Painlevé case and yields non-finite
/// accelerations, which the walk reports as a divergence.
#include <Eigen/Core>

#include "dynamics/model.hpp"

namespace gaitopt::sim {

/// How one tip touches the ground.
struct TipContact {
  enum class Mode { kFree, kStick, kSlide };
  Mode mode = Mode::kFree;
  double direction = 0;  ///< s = +1 or -1: the way the tip slides (kSlide only)

  bool onGround() const { return mode != Mode::kFree; }
  static TipContact free() { return {}; }
  static TipContact stick() { return {Mode::kStick, 0}; }
  static TipContact slide(double s) { return {Mode::kSlide, s}; }
};

/// Contact at B (the stance tip, base of the chain) and E (the swing tip).
struct ContactSet {
  TipContact b = TipContact::stick();
  TipContact e = TipContact::free();
};

struct ContactAcceleration {
  Eigen::VectorXd qddot;          ///< (xddot_b, yddot_b, thetaddot), n + 2
  Vec2d force_b = Vec2d::Zero();  ///< ground force on the robot at B (x, y) [N]
  Vec2d force_e = Vec2d::Zero();  ///< at E [N]
};

/// Accelerations and tip forces at the free-base state (theta, dtheta) (the base's position and
/// velocity do not enter) under joint torques tau and a force on the hip.
ContactAcceleration contactDynamics(const dynamics::Model& plant, const VecD& theta,
                                    const VecD& dtheta, const VecD& tau, const ContactSet& contacts,
                                    const Vec2d& hip_force = Vec2d::Zero());

}  // namespace gaitopt::sim
