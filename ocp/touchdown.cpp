#include "ocp/touchdown.hpp"

#include "dynamics/energy.hpp"
#include "dynamics/impact.hpp"
#include "ocp/autodiff_constraint.hpp"
#include "ocp/gait_links.hpp"

namespace gaitopt::ocp {
namespace {

/// y = (P_E, P_B): impulses inside their friction cones, pushing up.
struct ImpulseCones {
  double mu;
  template <class S>
  dynamics::VecX<S> operator()(const dynamics::VecX<S>& y) const {
    dynamics::VecX<S> g(6);
    for (int tip = 0; tip < 2; ++tip) {
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

Eigen::VectorXd gather(const Eigen::VectorXd& x, const std::vector<int>& idx) {
  Eigen::VectorXd y(static_cast<Eigen::Index>(idx.size()));
  for (size_t i = 0; i < idx.size(); ++i) y(static_cast<Eigen::Index>(i)) = x(idx[i]);
  return y;
}

}  // namespace

Touchdown Touchdown::add(Nlp& nlp, const dynamics::Model& model, const OcpConfig& c,
                         const Phase& ssp, double step_length) {
  const int n = model.nLinks();
  const std::vector<int> theta_end = ssp.indices(-1, ssp.point.q);
  Touchdown t;
  t.strike_ = concat(theta_end, ssp.indices(-1, ssp.point.v));
  t.rates_after_ = ssp.indices(-1, ssp.point.v);
  // Every link is nonlinear in the strike angles only (the first n of its variables).
  addLink(nlp, "touchdown_position", 2, theta_end, n, TipAtTouchdown{&model, step_length});
  if (c.impact == ImpactModel::kImpactless) {
    addLink(nlp, "touchdown_at_rest", 2, t.strike_, n, StrikeVelocity{&model, false});
    return t;
  }
  if (c.swing_descends)
    addLink(nlp, "strike_downward", 1, t.strike_, n, StrikeVelocity{&model, true}, -kInf, 0.0);
  ImpactLayout l = ImpactLayout::rigid(n, c.impact == ImpactModel::kDouble);
  Eigen::VectorXd lo = Eigen::VectorXd::Constant(l.size(), -kInf), hi = -lo;
  // The old stance tip leaves the ground.
  if (!l.doubleImpact() && c.trailing_lifts) lo(l.base_velocity[1]) = 0;
  l.offset = nlp.addVariables("impact", l.size(), lo, hi,
                              guessImpact(model, l, gather(nlp.initialGuess(), t.strike_)))
                 .offset;
  addLink(nlp, "impact", l.size(), concat(t.strike_, l.inDecision(l.all()).indices()), n,
          RigidImpact{&model, l});
  if (l.doubleImpact() && c.ground_contact)
    addLink(nlp, "impulse_cones", 6, l.inDecision(l.impulses()).indices(), 0,
            ImpulseCones{frictionBound(model, c)}, 0.0, kInf);
  t.rates_after_ = l.inDecision(l.rates_after).indices();
  t.impact_ = l;
  return t;
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
