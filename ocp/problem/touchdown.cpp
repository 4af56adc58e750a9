#include "ocp/problem/touchdown.hpp"

#include <cmath>

#include "dynamics/energy.hpp"
#include "dynamics/impact/impact.hpp"
#include "dynamics/kinematics.hpp"
#include "ocp/problem/gait_links.hpp"
#include "ocp/transcription/autodiff_constraint.hpp"

namespace gaitopt::ocp {
namespace {

/// y = (P_E[, P_B]): impulses inside their friction cones, pushing up (Mu 2.31 for a double
/// impact, 2.37b for a single one): P_y >= 0, mu P_y - P_x >= 0, mu P_y + P_x >= 0 per tip.
struct ImpulseCones {
  double mu;
  template <class S>
  dynamics::VecX<S> operator()(const dynamics::VecX<S>& y) const {
    const auto tips = static_cast<int>(y.size() / 2);
    dynamics::VecX<S> g(3 * tips);
    for (int tip = 0; tip < tips; ++tip) {
      const S px = y(2 * tip), py = y(2 * tip + 1);
      g.segment(3 * tip, 3) << py, mu * py - px, mu * py + px;
    }
    return g;
  }
};

/// The impact variables from the closed-form maps at the strike state (Mu 2.57-2.62).
Eigen::VectorXd guessImpact(const dynamics::Model& model, const ImpactLayout& l,
                            const Eigen::VectorXd& strike_state) {
  const PointLayout state = PointLayout::biped(model.nLinks(), false, false);
  const VecD theta = state.q.of(strike_state), dtheta = state.v.of(strike_state);
  const auto r = l.doubleImpact() ? dynamics::doubleImpact(model, theta, dtheta)
                                  : dynamics::singleImpact(model, theta, dtheta);
  Eigen::VectorXd v(l.size());
  l.base_velocity.of(v) = r.trailing_velocity;
  l.rates_after.of(v) = r.dtheta_plus;
  l.impulse_leading.of(v) = r.impulse_leading;
  if (l.doubleImpact()) l.impulse_trailing.of(v) = r.impulse_trailing;
  return v;
}

}  // namespace

Touchdown Touchdown::add(Nlp& nlp, const dynamics::Model& model, const OcpConfig& c,
                         const Phase& ssp, double step_length, const std::string& prefix) {
  const int n = model.nLinks();
  const std::vector<int> theta_end = ssp.indices(-1, ssp.point.q);
  Touchdown t;
  t.strike_ = concat(theta_end, ssp.indices(-1, ssp.point.v));
  t.rates_after_ = ssp.indices(-1, ssp.point.v);
  // Every link is nonlinear in the strike angles only (the first n of its variables).
  addLink(nlp, prefix + "touchdown_position", 2, theta_end, n, TipAtTouchdown{&model, step_length});
  if (c.impact == ImpactModel::kImpactless) {
    addLink(nlp, prefix + "touchdown_at_rest", 2, t.strike_, n, StrikeVelocity{&model, false});
    return t;
  }
  const StrikeDesign& strike = c.touchdown;
  if (strike.enabled)  // -v_max <= ydot_e^- <= -v_min: implies the descent below
    addLink(nlp, prefix + "strike_normal_velocity", 1, t.strike_, n, StrikeVelocity{&model, true},
            -strike.normal_max, -strike.normal_min);
  else if (c.swing_descends)
    addLink(nlp, prefix + "strike_downward", 1, t.strike_, n, StrikeVelocity{&model, true}, -kInf,
            0.0);
  if (strike.angle)
    addLink(nlp, prefix + "strike_angle", 2, t.strike_, n,
            StrikeAngle{&model, strike.angle_min, strike.angle_max}, 0.0, kInf);
  ImpactLayout l = ImpactLayout::rigid(n, c.impact == ImpactModel::kDouble);
  Eigen::VectorXd lo = Eigen::VectorXd::Constant(l.size(), -kInf), hi = -lo;
  // The old stance tip leaves the ground.
  if (!l.doubleImpact() && c.trailing_lifts) lo(l.base_velocity[1]) = 0;
  l.offset = nlp.addVariables(prefix + "impact", l.size(), lo, hi,
                              guessImpact(model, l, gather(nlp.initialGuess(), t.strike_)))
                 .offset;
  addLink(nlp, prefix + "impact", l.size(), concat(t.strike_, l.inDecision(l.all()).indices()), n,
          RigidImpact{&model, l});
  if (c.ground_contact && c.impact_friction) {
    const Slice impulses = l.inDecision(l.impulses());
    addLink(nlp, prefix + "impulse_cones", 3 * impulses.size / 2, impulses.indices(), 0,
            ImpulseCones{impulseFrictionBound(model, c)}, 0.0, kInf);
  }
  t.rates_after_ = l.inDecision(l.rates_after).indices();
  t.impact_ = l;
  return t;
}

StrikeReport Touchdown::strike(const dynamics::Model& model, const Eigen::VectorXd& x) const {
  const PointLayout state = PointLayout::biped(model.nLinks(), false, false);
  const Eigen::VectorXd y = gather(x, strike_);
  const VecD theta = state.q.of(y), dtheta = state.v.of(y);
  StrikeReport r;
  r.tip_velocity = dynamics::pointVelocity<double>(model.tipWeights(), theta, dtheta);
  r.normal_velocity = -r.tip_velocity.y();
  r.angle = std::atan2(-r.tip_velocity.y(), -r.tip_velocity.x());  // Xdot_e = -V (cos, sin)
  r.admitted = dynamics::classifyImpact(model, theta, dtheta);
  if (impact_) {
    r.impulse_leading = impact_->inDecision(impact_->impulse_leading).of(x);
    if (impact_->doubleImpact())
      r.impulse_trailing = impact_->inDecision(impact_->impulse_trailing).of(x);
  }
  return r;
}

std::optional<double> Touchdown::energyLoss(const dynamics::Model& model,
                                            const Eigen::VectorXd& x) const {
  if (!impact_) return std::nullopt;
  const PointLayout state = PointLayout::biped(model.nLinks(), false, false);
  const Eigen::VectorXd strike = gather(x, strike_);
  const VecD theta = state.q.of(strike);
  const Vec2d base = impact_->inDecision(impact_->base_velocity).of(x);
  const VecD dtheta_plus = impact_->inDecision(impact_->rates_after).of(x);
  return dynamics::kineticEnergy<double>(model, theta, VecD(state.v.of(strike))) -
         dynamics::kineticEnergy<double>(model, theta, dtheta_plus, base);
}

}  // namespace gaitopt::ocp
