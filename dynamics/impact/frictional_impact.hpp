#pragma once
/// @file frictional_impact.hpp
/// Rigid impact of the swing tip E with Coulomb friction and Newton restitution (Hurmuzlu,
/// Genot, Brogliato 2001, sec. 3.3.2 and appendix B, eqs. 76-82). Labels are the
/// pre-impact ones (impact.hpp): B the trailing tip, E the colliding one; impulses are exerted by
/// the ground on the robot; the configuration does not change.
///
/// The chain with a free base, q = (x_b, y_b, theta) (Mu 2.47-2.62, floating_base.hpp), takes
/// the impulses P_i = (P_t, P_n) at the tips in contact: D_ext (qdot+ - qdot-) = sum_i J_i^T P_i
/// (HGB 82). At each tip, in the normal direction Newton's law v_n+ = -e_n v_n- (e_n = 0: the
/// plastic impact of HGB 76-78 with its normal velocity ended at zero), and in the tangential
/// direction Coulomb's law at impulse level (HGB 79-81):
///   |P_t| <  mu P_n  =>  v_t+ = 0                      (the tip sticks)
///   P_t = -mu P_n sgn(v_t+), v_t+ != 0                 (the tip slides: the impulse lies on the
///                                                       cone and opposes the slip it leaves)
/// The stick/slide mode of each tip is found by enumeration (HGB sec. 3.3.2, the extension of
/// the enumeration methods to stick/slip): all tips sticking first, then one sliding tip, then
/// two; the first mode whose solution satisfies its own conditions is the outcome. When every
/// tip sticks and e_n = 0 the result is Mu's rigid map (2.23-2.37, impact.hpp).
///
/// With e_n = 0 the kinetic energy cannot grow: dT = P . v+ - 1/2 P^T A P with A = C D^-1 C^T,
/// and P_n v_n+ = 0, P_t v_t+ <= 0 (Coulomb's maximum dissipation). With e_n > 0, Newton's law
/// with friction can create energy (the Kane-Levinson example); keep e_n small.
#include <vector>

#include "dynamics/impact/impact.hpp"
#include "dynamics/model.hpp"

namespace gaitopt::dynamics {

/// What happened at one tip during the impact.
struct TipImpact {
  Vec2d impulse = Vec2d::Zero();   ///< (P_t, P_n) on the robot [N s]
  Vec2d velocity = Vec2d::Zero();  ///< the tip's velocity after the impact [m/s]
  bool slides = false;             ///< the impulse is on the cone boundary, v_t+ != 0
};

struct FrictionalImpact {
  VecD dtheta_plus;                     ///< post-impact absolute rates [rad/s]
  Vec2d base_velocity = Vec2d::Zero();  ///< velocity of B after the impact [m/s]
  TipImpact trailing;                   ///< B (no impulse for a single impact)
  TipImpact leading;                    ///< E
  /// Double: P_By > 0 (Mu 2.31a); single: ydot_b+ > 0 (2.37a).
  bool unilateral_ok = false;
  /// A stick/slide mode satisfies Coulomb's law at every tip with P_n >= 0. False when none does
  /// (e.g. the sticking impulse pulls a tip, P_n < 0): then the all-sticking solution is returned.
  bool consistent = false;
};

/// Single impact (B free, at rest before, as Mu 2.32-2.37): E takes the impulse.
/// @param restitution e_n in [0, 1].
FrictionalImpact frictionalSingleImpact(const Model& model, const VecD& theta,
                                        const VecD& dtheta_minus, double restitution);

/// Double impact (B on the ground at rest before, as Mu 2.23-2.31): both tips take impulses.
/// @param restitution e_n in [0, 1] (B, at rest before, keeps v_n+ = 0 either way).
FrictionalImpact frictionalDoubleImpact(const Model& model, const VecD& theta,
                                        const VecD& dtheta_minus, double restitution);

/// The impact as one complementarity problem over both tips (HGB sec. 4: at B, Signorini's law
/// at impulse level, v_Bn+ >= 0, P_Bn >= 0, P_Bn v_Bn+ = 0, with Newton's law at E, and Coulomb's
/// law at every tip in contact), instead of Mu's two models each checked after the fact. Its
/// solutions are the consistent modes of B (leaves the ground, sticks, slides either way) times E
/// (sticks, slides either way): Mu's single impact is the family where B leaves, his double the
/// family where it stays. Where Mu's sticking conditions call both consistent ("either") or
/// neither, this law says which families hold once the tips may slide.
struct ComplementarityImpact {
  std::vector<FrictionalImpact> staying;  ///< solutions with B on the ground (double)
  std::vector<FrictionalImpact> leaving;  ///< solutions with B lifting off (single)
  /// kDouble or kSingle when every solution is of that family, kEither when both families have
  /// one (the law does not decide: the problem has several solutions), kNeither when none.
  ImpactType type() const;
};

/// All solutions at the pre-impact state. @param restitution e_n in [0, 1].
ComplementarityImpact complementarityImpact(const Model& model, const VecD& theta,
                                            const VecD& dtheta_minus, double restitution);

}  // namespace gaitopt::dynamics
