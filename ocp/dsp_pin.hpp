#pragma once
/// @file dsp_pin.hpp
/// The double-support tip E pinned at position level (config constraints.dsp_position_pin,
/// Hermite-Simpson). Mu's DSP dynamics (2.11) hold E with the force lambda; imposing only E's
/// acceleration, J ddtheta + Jdot dtheta = 0 (the second time derivative of 2.9), at every
/// collocation point lets E drift, since the scheme integrates that acceleration only
/// approximately (0.59 mm over the default optimum's DSP). As in Posa, Kuindersma and Tedrake
/// 2016 ("Optimization and stabilization of trajectories for constrained dynamical systems",
/// ICRA, sec. III) the constraint and its rate hold at the knots,
///   phi(theta) = E(theta) - (step_length, 0) = 0 (Mu 2.9)   and   J dtheta = 0,
/// at the end of every segment: four rows per segment. So that the discrete system is not
/// over-determined (with E's acceleration also zero at every point the rows are near-redundant),
/// the acceleration rows of the segment's midpoint and end give way, E's acceleration staying
/// zero at the DSP's first point only: lambda_mid and lambda_end then hold E at the knots. The
/// four rows have full rank: by the Simpson rows theta_end moves with h^2/3 of ddtheta_mid and
/// dtheta_end with 2h/3 of it and h/6 of ddtheta_end, each moved by its lambda through D^-1 J^T.
/// The export (exportPoint: the double integral of the interpolated accelerations) meets every
/// knot, so it holds E there exactly and between knots to the scheme's O(h^4).
/// Posa's own balance, the acceleration rows kept and projection terms J^T gamma added to the
/// defects, was measured on the default problem: the knots are pinned as well, but the points'
/// accelerations then are not those of any pinned motion, and an export made to meet the knots
/// moves them by up to 11 rad/s^2 between the points (the ankle torque by 80 N m, foot B's centre
/// of pressure 1 m off the foot), so it is not used. This form has its own price, measured on
/// the default problem: E's acceleration at the midpoints and segment ends is free, up to
/// 12 m/s^2, so the knots' accelerations are not a pinned tip's and a controller's DSP model
/// (tip acceleration zero) differs from the exported torques by 11 N m there; and the freed
/// forces can be exploited where the cost rewards it (the least-CoT optimum drops by 10 % with a
/// normal force going negative between the points). Hence a switch, off by default.
#include "dynamics/dsp_dynamics.hpp"
#include "dynamics/floating_base.hpp"  // VecX: more entries than links
#include "dynamics/kinematics.hpp"
#include "ocp/nlp.hpp"
#include "ocp/phase.hpp"

namespace gaitopt::ocp {

/// y = (theta (n), dtheta (n)) of a DSP point: E at (step_length, 0) and at rest, Mu (2.9) and
/// its time derivative, 4 rows [m, m/s]. Affine in dtheta.
struct PinnedTip {
  const dynamics::Model* model;
  double step_length;
  template <class S>
  dynamics::VecX<S> operator()(const dynamics::VecX<S>& y) const {
    const int n = model->nLinks();
    const Vec<S> theta = y.head(n), dtheta = y.tail(n);
    dynamics::VecX<S> g(4);
    g.head(2) = dynamics::dspConstraint<S>(*model, theta, step_length);
    g.tail(2) = dynamics::pointVelocity<S>(model->tipWeights(), theta, dtheta);
    return g;
  }
};

/// y = (theta, dtheta, ddtheta) of a DSP point: E's acceleration J ddtheta + Jdot dtheta, 2 rows
/// [m/s^2] (second derivative of Mu 2.9). Affine in ddtheta.
struct TipAcceleration {
  const dynamics::Model* model;
  template <class S>
  dynamics::VecX<S> operator()(const dynamics::VecX<S>& y) const {
    const int n = model->nLinks();
    return dynamics::pointAcceleration<S>(model->tipWeights(), Vec<S>(y.head(n)),
                                          Vec<S>(y.segment(n, n)), Vec<S>(y.tail(n)));
  }
};

/// The pin of a DSP phase whose dynamics rows leave out E's acceleration (BipedDynamics with
/// tip_acceleration_rows false): E's acceleration zero at the first point (its position and
/// velocity are the touchdown's) and a PinnedTip at the end of every segment.
void addDspPin(Nlp& nlp, const dynamics::Model& model, const Phase& phase, double step_length);

}  // namespace gaitopt::ocp
