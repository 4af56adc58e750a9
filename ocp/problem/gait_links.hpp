#pragma once
/// @file gait_links.hpp
/// The constraints that tie the phases of a step together, as templated functors for
/// AutoDiffConstraint: touchdown position, strike direction, the rigid impact (Mu 2.57-2.62 via
/// dynamics/floating_base.hpp) and the relabelling that makes the step periodic (2.38,
/// corrected). Each takes the stacked variables it names, in the order documented.
#include <numbers>

#include "dynamics/dsp_dynamics.hpp"
#include "dynamics/floating_base.hpp"
#include "dynamics/kinematics.hpp"
#include "ocp/transcription/point_layout.hpp"

namespace gaitopt::ocp {

/// y = theta_end (n): swing tip at (step_length, 0).
struct TipAtTouchdown {
  const dynamics::Model* model;
  double step_length;
  template <class S>
  dynamics::VecX<S> operator()(const dynamics::VecX<S>& y) const {
    return dynamics::dspConstraint<S>(*model, y, step_length);  // the DSP's pin, Mu (2.9)
  }
};

/// y = (theta_end, dtheta_end): velocity of the swing tip at strike; `vertical_only` keeps
/// its y component (bounded <= 0 before an impact), else both (= 0 for an impactless
/// touchdown: a tip still sliding would carry its velocity into the DSP).
struct StrikeVelocity {
  const dynamics::Model* model;
  bool vertical_only = true;
  template <class S>
  dynamics::VecX<S> operator()(const dynamics::VecX<S>& y) const {
    const PointLayout strike = PointLayout::biped(model->nLinks(), false, false);
    const Vec2<S> v = dynamics::pointVelocity<S>(model->tipWeights(), Vec<S>(strike.q.of(y)),
                                                 Vec<S>(strike.v.of(y)));
    if (vertical_only) return dynamics::VecX<S>::Constant(1, v(1));
    return v;
  }
};

/// y = (theta_end, dtheta_end): the strike angle alpha of the swing tip's velocity (Mu ch. 5,
/// Xdot_e^- = -V_e (cos alpha, sin alpha), alpha in [0, pi] for a descending tip) kept in
/// [lo, hi] without an inverse trigonometric function: with d = -Xdot_e^- = V_e (cos alpha,
/// sin alpha), g0 = u(lo) x d = V_e sin(alpha - lo) and g1 = d x u(hi) = V_e sin(hi - alpha),
/// both >= 0 exactly when lo <= alpha <= hi (all in [0, pi]). Linear in the rates.
struct StrikeAngle {
  const dynamics::Model* model;
  double lo, hi;  ///< [rad]
  template <class S>
  dynamics::VecX<S> operator()(const dynamics::VecX<S>& y) const {
    using std::cos, std::sin;
    const PointLayout strike = PointLayout::biped(model->nLinks(), false, false);
    const Vec2<S> d = -dynamics::pointVelocity<S>(model->tipWeights(), Vec<S>(strike.q.of(y)),
                                                  Vec<S>(strike.v.of(y)));
    dynamics::VecX<S> g(2);
    g << cos(lo) * d(1) - sin(lo) * d(0), sin(hi) * d(0) - cos(hi) * d(1);
    return g;
  }
};

/// y = (strike state (theta_end, dtheta-), impact variables (ImpactLayout)): impact residual.
struct RigidImpact {
  const dynamics::Model* model;
  ImpactLayout impact;  ///< offset unused: the variables follow the strike state in y
  template <class S>
  dynamics::VecX<S> operator()(const dynamics::VecX<S>& y) const {
    const PointLayout strike = PointLayout::biped(model->nLinks(), false, false);
    const dynamics::VecX<S> vars = y.tail(impact.size());
    const Vec2<S> p_b =
        impact.doubleImpact() ? Vec2<S>(impact.impulse_trailing.of(vars)) : Vec2<S>::Zero();
    return dynamics::impactResidual<S>(*model, strike.q.of(y), strike.v.of(y),
                                       impact.qdotPlus().of(vars), impact.impulse_leading.of(vars),
                                       impact.doubleImpact() ? &p_b : nullptr);
  }
};

/// y = (theta_end (n), dtheta+ (n), theta_start (n), dtheta_start (n)): the start of the step
/// equals the end after relabelling. Leg links turn by pi within the convention's ranges (new
/// stance link = old swing link - pi, new swing link = old stance link + pi), the torso keeps
/// its angle, rates are reversed.
struct Periodicity {
  const dynamics::Model* model;
  template <class S>
  dynamics::VecX<S> operator()(const dynamics::VecX<S>& y) const {
    const PointLayout state = PointLayout::biped(model->nLinks(), false, false);
    const int n = state.n;
    const dynamics::VecX<S> end = y.head(state.stateSize()), start = y.tail(state.stateSize());
    dynamics::VecX<S> g(state.stateSize());
    for (int i = 0; i < n; ++i) {
      const int j = n - 1 - i;
      const bool torso = model->torso() && *model->torso() == i;
      const double turn = torso ? 0.0 : (i < n - model->legLinks() ? -1.0 : 1.0) * std::numbers::pi;
      g(state.q[i]) = start(state.q[i]) - (end(state.q[j]) + turn);
      g(state.v[i]) = start(state.v[i]) - end(state.v[j]);
    }
    return g;
  }
};

}  // namespace gaitopt::ocp
