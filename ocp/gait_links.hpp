#pragma once
/// @file gait_links.hpp
/// The constraints that tie the phases of a step together, as templated functors for
/// AutoDiffConstraint: touchdown position, strike direction, the rigid impact (Mu 2.57-2.62 via
/// dynamics/floating_base.hpp) and the relabelling that makes the step periodic (2.38,
/// corrected). Each takes the stacked variables it names, in the order documented.
#include <numbers>

#include "dynamics/floating_base.hpp"
#include "dynamics/kinematics.hpp"

namespace gaitopt::ocp {

/// y = theta_end (n): swing tip at (step_length, 0).
struct TipAtTouchdown {
  const dynamics::Model* model;
  double step_length;
  template <class S>
  dynamics::VecX<S> operator()(const dynamics::VecX<S>& y) const {
    const Vec2<S> tip = dynamics::swingTip<S>(*model, y);
    dynamics::VecX<S> g(2);
    g << tip(0) - step_length, tip(1);
    return g;
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
    const int n = model->nLinks();
    const Vec<S> theta = y.head(n), dtheta = y.tail(n);
    const Vec2<S> v = dynamics::pointVelocity<S>(model->tipWeights(), theta, dtheta);
    if (vertical_only) return dynamics::VecX<S>::Constant(1, v(1));
    return v;
  }
};

/// y = (theta_end (n), dtheta- (n), qdot+ (n+2), P_E (2) [, P_B (2)]): impact residual.
struct RigidImpact {
  const dynamics::Model* model;
  bool both_tips;
  template <class S>
  dynamics::VecX<S> operator()(const dynamics::VecX<S>& y) const {
    const int n = model->nLinks();
    const Vec<S> theta = y.head(n), dtheta = y.segment(n, n);
    const dynamics::VecX<S> qdot_plus = y.segment(2 * n, n + 2);
    const Vec2<S> p_e = y.segment(3 * n + 2, 2);
    const Vec2<S> p_b = both_tips ? Vec2<S>(y.segment(3 * n + 4, 2)) : Vec2<S>::Zero();
    return dynamics::impactResidual<S>(*model, theta, dtheta, qdot_plus, p_e,
                                       both_tips ? &p_b : nullptr);
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
    const int n = model->nLinks();
    dynamics::VecX<S> g(2 * n);
    for (int i = 0; i < n; ++i) {
      const int j = n - 1 - i;
      const bool torso = model->torso() && *model->torso() == i;
      const double turn = torso ? 0.0 : (i < n - model->legLinks() ? -1.0 : 1.0) * std::numbers::pi;
      g(i) = y(2 * n + i) - (y(j) + turn);
      g(n + i) = y(3 * n + i) - y(n + j);
    }
    return g;
  }
};

}  // namespace gaitopt::ocp
