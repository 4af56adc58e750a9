#pragma once
/// @file impedance_contact.hpp
/// A compliant ground for one point contact in the plane: the impedance alternative to the rigid
/// LCP contact in Addi & Rodic (2010) sec. 4. Normal force of Hunt-Crossley type; their pad model
/// (60) is the case exponent = 1 with damping = (3/2) alpha stiffness. Tangential force from a
/// spring-damper to a sticking anchor with a Coulomb limit, their stick/slip law (62) with the
/// normal force in place of the misprinted F_y (docs/derivations.md#impedance-ground).
/// The anchor is state the caller carries between steps: see impedanceContactForce.

namespace gaitopt::sim {

/// Ground parameters (from config; no defaults). Units assume the exponent n.
struct ImpedanceGround {
  double stiffness;             ///< k > 0 [N/m^n]
  double damping;               ///< c >= 0, Hunt-Crossley: c = (3/2) alpha k [N s/m^(n+1)]
  double exponent;              ///< n >= 1 (1 linear, 1.5 Hertz) [-]
  double tangential_stiffness;  ///< k_t > 0 [N/m]
  double tangential_damping;    ///< c_t >= 0 [N s/m]
  double friction;              ///< Coulomb coefficient mu >= 0 [-]
  /// t_p > 0: Addi & Rodic's pad (60) instead of Hunt-Crossley: the stiffness k and damping c
  /// grow as k (1 + 0.1 tan^3(pi delta / (2 t_p))), so the pad cannot be squeezed through its
  /// thickness, and the damping acts only while it is compressed; 0: Hunt-Crossley [m].
  double pad_thickness = 0;
};

/// @throws std::invalid_argument naming the first parameter that is not finite or out of range
/// (stiffness, tangential_stiffness > 0; damping, tangential_damping, friction >= 0; exponent
/// >= 1, since for n < 1 the contact stiffness n k delta^(n-1) is infinite at touch-down).
void validateImpedanceGround(const ImpedanceGround& ground);

/// Hunt-Crossley normal force Fn = max(0, k delta^n + c delta^n delta_dot) [N]: zero out of
/// contact (delta <= 0), and clipped at zero when the ground separates faster than k / c, so it
/// never pulls. The damping vanishes with delta, so the force is continuous at impact and the
/// coefficient of restitution is e ~ 1 - alpha v_impact with alpha = 2c / (3k) for small v.
/// With a pad (pad_thickness > 0) the law of Addi & Rodic (60) on a massless pad:
/// Fn = s k delta^n (1 + (c / k) delta_dot) while compressing, s k delta^n while it restores,
/// s = 1 + 0.1 tan^3(pi delta / (2 t_p)) (their stiffening), delta held just under t_p.
/// @param penetration     delta [m], > 0 in contact
/// @param penetration_rate  d delta / dt [m/s], > 0 while compressing
double huntCrossleyNormalForce(const ImpedanceGround& ground, double penetration,
                               double penetration_rate);

/// Kinematics of the contact point relative to the ground.
struct ContactPointMotion {
  double penetration;          ///< delta [m], > 0 in contact
  double penetration_rate;     ///< d delta / dt [m/s]
  double tangential_position;  ///< x along the ground [m]
  double tangential_velocity;  ///< dx/dt [m/s]
};

struct ImpedanceContactForce {
  double normal;      ///< Fn >= 0 on the point, along the outward ground normal [N]
  double tangential;  ///< Ft on the point along x [N], |Ft| <= mu Fn
  double anchor;      ///< the anchor to carry into the next evaluation [m]
  bool sliding;       ///< the Coulomb limit was active
};

/// Ground force on the point. Stick: Ft = -k_t (x - anchor) - c_t xdot if that is within
/// mu Fn, anchor unchanged. Otherwise slide: Ft = mu Fn in the direction of that trial force
/// and the anchor moves to x + Ft / k_t, so the spring alone carries the friction force and
/// sticking resumes without a jump. While the spring is consistent (|k_t (x - anchor)| <=
/// mu Fn, which this update keeps) the trial force points against xdot, so Ft = -mu Fn
/// sign(xdot) as in Addi & Rodic (62); the trial direction only differs after the normal force
/// drops, where it avoids a spurious reversal. Out of contact Fn = 0, so the anchor follows the
/// point and is ready at touch-down: initialise it to the point's x.
/// In an ODE integrator, evaluate with the anchor of the last accepted step in every stage and
/// keep the returned anchor only from the evaluation at the accepted state.
ImpedanceContactForce impedanceContactForce(const ImpedanceGround& ground,
                                            const ContactPointMotion& motion, double anchor);

}  // namespace gaitopt::sim
