#pragma once
/// @file model.hpp
/// Immutable parameters of a planar serial-chain biped (Mu 2004, sec. 2.2-2.3) and the constants
/// every dynamics function needs (p_ij, g_i of eq. 2.8, chain-point weights of eqs. 2.1-2.2).
/// Build it from a robot YAML with loadRobot() (robot_config.hpp); it never changes afterwards.
///
/// Ground slope: every geometric quantity lives in the GROUND frame (x along the slope in the
/// walking direction, y along the slope normal, the ground is y = 0, theta measured from the
/// slope normal, clockwise positive). Only gravity rotates: with slope gamma (> 0 uphill) it is
/// g_vec = (-g sin gamma, -g cos gamma) in that frame. Contact, clearance, friction cones, the
/// ZMP support and the step geometry E = B + (step_length, 0) are unchanged.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "dynamics/conventions.hpp"

namespace gaitopt::dynamics {

/// One rigid link. Units: kg, kg m^2 (about the CoM), m.
struct Link {
  std::string name;
  double mass = 0;        ///< m_i [kg]
  double inertia = 0;     ///< I_i about the link CoM [kg m^2]
  double length = 0;      ///< l_i [m]
  double com = 0;         ///< d_i: CoM distance from the proximal joint along the link [m]
  bool continues = true;  ///< a_i: does the chain continue through the distal end?

  /// a_i of Mu (2.8) as the number the sums multiply by.
  double a() const { return continues ? 1.0 : 0.0; }
};

/// One joint of q-space (q0 = stance ankle, then one per consecutive link pair).
struct Joint {
  std::string name;
  bool actuated = true;
  double torque_limit = 0;    ///< |tau| bound [N m]
  double velocity_limit = 0;  ///< |dq| bound [rad/s]
};

/// Foot geometry about the tip, for ZMP bounds when the ankle is actuated [m].
struct Foot {
  double heel = 0;  ///< extent behind the tip
  double toe = 0;   ///< extent ahead of the tip
};

/// Largest |slope| the gait and OCP configs accept [rad] (about 20 deg; key `slope`).
inline constexpr double kMaxConfigSlope = 0.35;

/// Weights w of a point on the chain: position = sum_j w_j u_j (Mu 2.1-2.2), u_j = (sin, cos).
using ChainPoint = VecD;

class Model {
 public:
  /// `slope` is the ground inclination gamma [rad], > 0 uphill (see the file comment).
  /// @throws std::invalid_argument when the links do not form a two-legged chain or the slope is
  /// not finite with |slope| < pi/2.
  Model(std::string name, std::vector<Link> links, std::vector<Joint> joints, double gravity,
        double friction, Foot foot, double slope = 0.0);

  const std::string& name() const { return name_; }
  int nLinks() const { return static_cast<int>(links_.size()); }
  const std::vector<Link>& links() const { return links_; }
  const Link& link(int i) const { return links_.at(static_cast<size_t>(i)); }
  const std::vector<Joint>& joints() const { return joints_; }
  double gravity() const { return gravity_; }  ///< |g| [m/s^2]; direction: gravityAcceleration()
  double slope() const { return slope_; }      ///< ground inclination gamma [rad], > 0 uphill
  /// Gravity acceleration in the ground frame, g_vec = (-g sin gamma, -g cos gamma) [m/s^2]
  /// (along -y on level ground).
  Eigen::Vector2d gravityAcceleration() const { return gravity_acc_; }
  double friction() const { return friction_; }  ///< Coulomb coefficient mu
  const Foot& foot() const { return foot_; }
  double totalMass() const { return total_mass_; }

  /// Number of links per leg (k); stance leg = links [0, k), swing leg = the last k links.
  int legLinks() const { return leg_links_; }
  /// Index of the terminal branch (torso), if the robot has one.
  std::optional<int> torso() const { return torso_; }

  /// p_ij of Mu (2.8a): D_ij = p_ij cos(theta_i - theta_j), symmetric [kg m^2].
  const MatD& inertiaCoefficients() const { return p_; }
  /// g_i of Mu (2.8c): G_i = -g_i sin(theta_i - slope) [N m] (level ground: -g_i sin(theta_i)).
  const VecD& gravityCoefficients() const { return g_; }
  /// a_i l_i: weights of the swing tip E relative to B (2.1).
  const ChainPoint& tipWeights() const { return tip_; }
  /// Weights of the hip (distal end of the stance leg, eq. 2.13).
  const ChainPoint& hipWeights() const { return hip_; }
  /// Weights of the CoM of link i (2.2).
  const ChainPoint& comWeights(int i) const { return com_.at(static_cast<size_t>(i)); }
  /// Weights of the whole-body CoM: sum_i m_i w_ci / m.
  const ChainPoint& totalComWeights() const { return total_com_; }
  /// Weights of the proximal joint of link i.
  const ChainPoint& jointWeights(int i) const { return joint_.at(static_cast<size_t>(i)); }

 private:
  void checkStructure() const;
  void precompute();

  std::string name_;
  std::vector<Link> links_;
  std::vector<Joint> joints_;
  double gravity_;
  double friction_;
  Foot foot_;
  double slope_;
  Eigen::Vector2d gravity_acc_;
  double total_mass_ = 0;
  int leg_links_ = 0;
  std::optional<int> torso_;
  MatD p_;
  VecD g_;
  ChainPoint tip_, hip_, total_com_;
  std::vector<ChainPoint> com_, joint_;
};

/// For methods written for knees (Mu's five-link robot and RABBIT): @throws
/// std::invalid_argument naming `user` ("the polynomial gait (Mu ch. 3)", ...) unless each leg
/// has two links, thigh and shank.
void requireKneedLegs(const Model& model, std::string_view user);

}  // namespace gaitopt::dynamics
