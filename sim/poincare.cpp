#include "sim/poincare.hpp"

#include <stdexcept>

#include <Eigen/Eigenvalues>

namespace gaitopt::sim {
namespace {

/// P(x), or throws std::runtime_error with the failure.
Eigen::VectorXd returnMap(const dynamics::Model& plant, const Controller& controller,
                          const Reference& ref, const Eigen::VectorXd& x,
                          const PoincareOptions& o) {
  const int n = plant.nLinks();
  const StepResult s = simulateStep(plant, controller, ref, x.head(n), x.tail(n), o.integrator, {},
                                    0, 0, 0, {}, o.rules);
  if (!s.ok) throw std::runtime_error(s.failure);
  Eigen::VectorXd next(2 * n);
  next << s.theta, s.dtheta;
  return next;
}

}  // namespace

PoincareAnalysis analysePoincare(const dynamics::Model& plant, const Controller& controller,
                                 const Reference& ref, const PoincareOptions& o) {
  PoincareAnalysis a;
  const int n = plant.nLinks();
  Eigen::VectorXd x(2 * n);
  x << ref.start().theta, ref.start().dtheta;
  try {
    for (int k = 0; k < o.settle_steps; ++k) x = returnMap(plant, controller, ref, x, o);
    a.fixed_point = x;
    a.fixed_point_residual = (returnMap(plant, controller, ref, x, o) - x).cwiseAbs().maxCoeff();
    a.jacobian.resize(2 * n, 2 * n);
    for (int i = 0; i < 2 * n; ++i) {
      Eigen::VectorXd plus = x, minus = x;
      plus(i) += o.perturbation;
      minus(i) -= o.perturbation;
      a.jacobian.col(i) = (returnMap(plant, controller, ref, plus, o) -
                           returnMap(plant, controller, ref, minus, o)) /
                          (2 * o.perturbation);
    }
  } catch (const std::runtime_error& e) {
    a.failure = e.what();
    return a;
  }
  a.multipliers = Eigen::EigenSolver<Eigen::MatrixXd>(a.jacobian).eigenvalues();
  a.max_multiplier = a.multipliers.cwiseAbs().maxCoeff();
  a.ok = true;
  return a;
}

}  // namespace gaitopt::sim
