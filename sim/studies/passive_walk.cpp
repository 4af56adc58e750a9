#include "sim/studies/passive_walk.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include "dynamics/impact/impact.hpp"
#include "dynamics/impact/relabel.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/model_variation.hpp"
#include "dynamics/ssp_dynamics.hpp"
#include "sim/walk/event_integrator.hpp"

namespace gaitopt::sim {
namespace {

/// The hip below a fifth of its height at the start has fallen.
constexpr double kFallenHipFraction = 0.2;

struct Split {
  VecD theta, dtheta;
};

Split split(const dynamics::Model& model, const Eigen::VectorXd& x) {
  const int n = model.nLinks();
  return {x.head(n), x.tail(n)};
}

Rhs passiveRhs(const dynamics::Model& model) {
  return [&model](double, const Eigen::VectorXd& x) {
    const auto [theta, dtheta] = split(model, x);
    Eigen::VectorXd dx(x.size());
    dx << dtheta, dynamics::sspForwardDynamics(model, theta, dtheta, VecD::Zero(model.nLinks()));
    return dx;
  };
}

/// Events of the swing phase before the touchdown can happen: the swing tip ahead of the stance
/// tip, above the ground and at the top of its arc (its height's rate <= 0); the hip fallen.
Events armingEvents(const dynamics::Model& model, double fallen) {
  return [&model, fallen](double, const Eigen::VectorXd& x) {
    const auto [theta, dtheta] = split(model, x);
    const Vec2d tip = dynamics::swingTip<double>(model, theta);
    const double rising = (dynamics::pointJacobian<double>(model.tipWeights(), theta) * dtheta).y();
    Eigen::VectorXd g(2);
    g << (tip.x() > 0 && tip.y() > 0 ? rising : 1.0),
        dynamics::hip<double>(model, theta).y() - fallen;
    return g;
  };
}

/// The touchdown (swing tip height reaching zero) and the hip fallen.
Events touchdownEvents(const dynamics::Model& model, double fallen) {
  return [&model, fallen](double, const Eigen::VectorXd& x) {
    const VecD theta = x.head(model.nLinks());
    Eigen::VectorXd g(2);
    g << dynamics::swingTip<double>(model, theta).y(),
        dynamics::hip<double>(model, theta).y() - fallen;
    return g;
  };
}

/// The angle between the legs (hip to stance tip, hip to swing tip) [rad].
double interlegAngle(const dynamics::Model& model, const VecD& theta) {
  const Vec2d hip = dynamics::hip<double>(model, theta);
  const Vec2d a = -hip, b = dynamics::swingTip<double>(model, theta) - hip;
  return std::abs(std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b)));
}

std::string fallOf(const dynamics::Model& model, const Eigen::VectorXd& x) {
  return dynamics::hip<double>(model, VecD(x.head(model.nLinks()))).x() < 0 ? "fell backwards"
                                                                            : "fell forwards";
}

/// P^k(x) as one vector, or why a step failed; the steps' durations and touchdown angles.
struct Steps {
  bool ok = true;
  std::string failure;
  Eigen::VectorXd end;
  std::vector<double> durations, angles;
};

Steps steps(const dynamics::Model& model, const Eigen::VectorXd& x, int k,
            const PassiveWalkOptions& o) {
  Steps s{true, "", x, {}, {}};
  for (int i = 0; i < k && s.ok; ++i) {
    const PassiveStep step = passiveStep(model, s.end, o);
    s.ok = step.ok;
    s.failure = step.failure;
    s.end = step.next;
    s.durations.push_back(step.duration);
    s.angles.push_back(step.interleg_angle);
  }
  return s;
}

double mostNegativeReal(const Eigen::VectorXcd& lambda) {
  double most = -std::numeric_limits<double>::infinity();
  bool found = false;
  for (const auto& l : lambda)
    // The constraint's zero multiplier is no period doubling, whatever the sign of its rounding.
    if (std::abs(l.imag()) < 1e-9 && l.real() < -1e-6 && (!found || l.real() < most)) {
      most = l.real();
      found = true;
    }
  return found ? most : -std::numeric_limits<double>::infinity();
}

}  // namespace

dynamics::Model downhill(const dynamics::Model& walker, double gamma) {
  return dynamics::withSlope(walker, -gamma);
}

PassiveStep passiveStep(const dynamics::Model& model, const Eigen::VectorXd& x,
                        const PassiveWalkOptions& o) {
  const auto [theta0, dtheta0] = split(model, x);
  const double fallen = kFallenHipFraction * dynamics::hip<double>(model, theta0).y();
  const EventIntegratorOptions io{o.step, o.time_tolerance};
  const Rhs f = passiveRhs(model);
  PassiveStep out;
  const EventIntegration armed =
      integrateToEvent(f, armingEvents(model, fallen), 0.0, x, o.max_step_time, io);
  const EventIntegration down = armed.event == 0
                                    ? integrateToEvent(f, touchdownEvents(model, fallen), armed.t,
                                                       armed.x, o.max_step_time, io)
                                    : armed;
  out.touchdown = out.next = down.x;
  out.duration = down.t;
  if (down.event != 0 || armed.event != 0) {
    out.failure = down.event == 1 ? fallOf(model, down.x) : "no touchdown";
    return out;
  }
  const auto [theta, dtheta] = split(model, down.x);
  const dynamics::ImpactResult impact = dynamics::singleImpact(model, theta, dtheta);
  out.interleg_angle = interlegAngle(model, theta);
  out.single_impact_ok = impact.unilateral_ok;
  out.next << dynamics::relabelAngles<double>(model, theta),
      dynamics::relabelRates<double>(impact.dtheta_plus);
  out.ok = true;
  return out;
}

PassiveGait findPassiveGait(const dynamics::Model& model, const Eigen::VectorXd& guess, int period,
                            const PassiveWalkOptions& o) {
  PassiveGait g;
  g.period = period;
  g.start = guess;
  const auto m = guess.size();
  for (int it = 0; it <= o.newton_iterations; ++it) {
    const Steps s = steps(model, g.start, period, o);
    if (!s.ok) {
      g.failure = s.failure;
      return g;
    }
    const Eigen::VectorXd residual = s.end - g.start;
    g.residual = residual.cwiseAbs().maxCoeff();
    g.durations = s.durations;
    g.interleg_angles = s.angles;
    g.jacobian.resize(m, m);
    for (Eigen::Index j = 0; j < m; ++j) {
      Eigen::VectorXd up = g.start, down = g.start;
      up(j) += o.perturbation;
      down(j) -= o.perturbation;
      const Steps a = steps(model, up, period, o), b = steps(model, down, period, o);
      if (!a.ok || !b.ok) {
        g.failure = "a perturbed start " + (a.ok ? b.failure : a.failure);
        return g;
      }
      g.jacobian.col(j) = (a.end - b.end) / (2 * o.perturbation);
    }
    if (g.residual < o.newton_tolerance) {
      g.multipliers = g.jacobian.eigenvalues();
      g.max_multiplier = g.multipliers.cwiseAbs().maxCoeff();
      g.most_negative_multiplier = mostNegativeReal(g.multipliers);
      g.ok = true;
      return g;
    }
    const Eigen::MatrixXd newton = g.jacobian - Eigen::MatrixXd::Identity(m, m);
    g.start -= newton.partialPivLu().solve(residual);
  }
  g.failure = "Newton's method did not converge";
  return g;
}

bool hasDistinctHalves(const PassiveGait& gait, double tolerance) {
  const auto half = gait.durations.size() / 2;
  if (gait.period % 2 != 0 || half == 0) return false;
  for (std::size_t i = 0; i < half; ++i)
    if (std::abs(gait.durations[i] - gait.durations[i + half]) > tolerance) return true;
  return false;
}

PassiveGait findDoubledGait(const dynamics::Model& model, const PassiveGait& gait,
                            const PassiveWalkOptions& o) {
  Eigen::EigenSolver<Eigen::MatrixXd> eig(gait.jacobian);
  Eigen::Index most = 0;
  for (Eigen::Index i = 0; i < eig.eigenvalues().size(); ++i)
    if (eig.eigenvalues()(i).real() < eig.eigenvalues()(most).real()) most = i;
  const Eigen::VectorXd direction = eig.eigenvectors().col(most).real().normalized();
  PassiveGait doubled;
  for (double size : {1e-3, -1e-3, 1e-2, -1e-2, 3e-2, -3e-2}) {
    doubled = findPassiveGait(model, gait.start + size * direction, 2 * gait.period, o);
    if (doubled.ok && hasDistinctHalves(doubled)) return doubled;
  }
  doubled.ok = false;
  if (doubled.failure.empty()) doubled.failure = "every search found the gait of half the period";
  return doubled;
}

}  // namespace gaitopt::sim
