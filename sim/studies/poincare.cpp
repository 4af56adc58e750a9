#include "sim/studies/poincare.hpp"

#include <cmath>
#include <stdexcept>

#include <Eigen/Eigenvalues>

namespace gaitopt::sim {
namespace {

/// The state one step later at the section and the step's indicators (duration, advance).
struct Return {
  Eigen::VectorXd x;
  Eigen::Vector2d indicators;
};

/// One period of the closed loop between two crossings of the section, pushed by `impulse`
/// (as a sweep pushes: from mid single support of the step after the section); throws
/// std::runtime_error with the failure.
class SectionMap {
 public:
  SectionMap(const dynamics::Model& plant, const Controller& controller, const Reference& ref,
             const PoincareOptions& o, double clock)
      : plant_(plant), controller_(controller), ref_(ref), o_(o), clock_(clock) {}

  int memory() const { return clock_ > 0 ? controller_.memorySize(gaits::Phase::kSsp) : 0; }

  /// The section state of a walk started at the reference's start.
  Eigen::VectorXd first() const {
    const gaits::Knot& k = ref_.start();
    return clock_ > 0 ? toSection(VecD(k.theta), VecD(k.dtheta)) : stack(k.theta, k.dtheta, {});
  }

  Return operator()(const Eigen::VectorXd& x, double impulse) const {
    const int n = plant_.nLinks();
    const Push push{1, std::nullopt, Vec2d(impulse, 0)};
    const StepResult s =
        clock_ > 0 ? simulateStepFrom(plant_, controller_, ref_,
                                      {clock_, x.head(n), x.segment(n, n), x.tail(memory())},
                                      o_.integrator, o_.rules, push)
                   : simulateStep(plant_, controller_, ref_, x.head(n), x.segment(n, n),
                                  o_.integrator, {}, 0, 0, 0, push, o_.rules);
    if (!s.ok) throw std::runtime_error(s.failure);
    const Eigen::Vector2d e(s.ssp_duration + s.dsp_duration, s.advance);
    if (clock_ == 0) return {stack(s.theta, s.dtheta, {}), e};
    return {toSection(s.theta, s.dtheta, s.stance_velocity), e};
  }

 private:
  Eigen::VectorXd toSection(const VecD& theta, const VecD& dtheta, double slide = 0) const {
    const SspRun run = simulateSingleSupportTo(plant_, controller_, ref_, theta, dtheta, clock_,
                                               o_.integrator, o_.rules, slide);
    if (!run.ok) throw std::runtime_error(run.failure);
    return stack(run.state.theta, run.state.dtheta, run.state.memory);
  }

  static Eigen::VectorXd stack(const VecD& theta, const VecD& dtheta, const Eigen::VectorXd& z) {
    Eigen::VectorXd x(theta.size() + dtheta.size() + z.size());
    x << theta, dtheta, z;
    return x;
  }

  const dynamics::Model& plant_;
  const Controller& controller_;
  const Reference& ref_;
  const PoincareOptions& o_;
  double clock_;
};

double sectionClock(const Reference& ref, const PoincareOptions& o) {
  const double t = std::isnan(o.section_clock) ? ref.touchdownTime() / 2 : o.section_clock;
  if (t != 0 && !(t >= ref.fadeTime() && t < ref.touchdownTime()))
    throw std::invalid_argument("Poincare section clock must be 0 or within [fade, touchdown)");
  return t;
}

/// A, B, C, D by central differences at the fixed point x.
LinearisedGait linearise(const SectionMap& map, const Eigen::VectorXd& x, double h) {
  const Eigen::Index n = x.size();
  LinearisedGait g{Eigen::MatrixXd(n, n), Eigen::MatrixXd(n, 1), Eigen::MatrixXd(2, n),
                   Eigen::MatrixXd(2, 1)};
  for (Eigen::Index i = 0; i <= n; ++i) {  // i == n: the push
    Eigen::VectorXd plus = x, minus = x;
    double d_plus = 0, d_minus = 0;
    if (i < n) {
      plus(i) += h;
      minus(i) -= h;
    } else {
      d_plus = h;
      d_minus = -h;
    }
    const Return p = map(plus, d_plus), m = map(minus, d_minus);
    (i < n ? g.a.col(i) : g.b.col(0)) = (p.x - m.x) / (2 * h);
    (i < n ? g.c.col(i) : g.d.col(0)) = (p.indicators - m.indicators) / (2 * h);
  }
  return g;
}

}  // namespace

PoincareAnalysis analysePoincare(const dynamics::Model& plant, const Controller& controller,
                                 const Reference& ref, const PoincareOptions& o) {
  PoincareAnalysis a;
  a.section_clock = sectionClock(ref, o);
  const SectionMap map(plant, controller, ref, o, a.section_clock);
  try {
    Eigen::VectorXd x = map.first();
    for (int k = 0; k < o.settle_steps; ++k) x = map(x, 0).x;
    a.fixed_point = x;
    a.fixed_point_residual = (map(x, 0).x - x).cwiseAbs().maxCoeff();
    a.linearised = linearise(map, x, o.perturbation);
  } catch (const std::runtime_error& e) {
    a.failure = e.what();
    return a;
  }
  a.jacobian = a.linearised.a;
  a.multipliers = Eigen::EigenSolver<Eigen::MatrixXd>(a.jacobian).eigenvalues();
  a.max_multiplier = a.multipliers.cwiseAbs().maxCoeff();
  a.ok = true;
  if (a.max_multiplier < 1) {
    const GaitSensitivity gsn = gaitSensitivity(a.linearised);
    a.gait_sensitivity_norm = gsn.norm;
    a.gait_sensitivity_per_indicator = gsn.per_indicator;
  }
  return a;
}

}  // namespace gaitopt::sim
