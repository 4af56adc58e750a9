#include "gaits/polynomial/dsp_force_distribution.hpp"

#include <vector>

#include <Eigen/Dense>
#include <nlopt.hpp>

#include "dynamics/joint_coordinates.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/ssp_dynamics.hpp"

namespace gaitopt::gaits {
namespace {

/// tau(lambda) = tau_bar - A lambda.
struct TorqueMap {
  Eigen::VectorXd tau_bar;
  Eigen::MatrixXd a;  // n x 2
};

/// One linear constraint row . lambda <= bound (or == bound).
struct LinearRow {
  Eigen::Vector2d row;
  double bound;
};

double objective(unsigned, const double* x, double* grad, void* data) {
  const auto* map = static_cast<const TorqueMap*>(data);
  const Eigen::VectorXd r = map->tau_bar - map->a * Eigen::Vector2d(x[0], x[1]);
  if (grad != nullptr) Eigen::Map<Eigen::Vector2d>{grad} = -2 * map->a.transpose() * r;
  return r.squaredNorm();
}

double linearConstraint(unsigned, const double* x, double* grad, void* data) {
  const auto* c = static_cast<const LinearRow*>(data);
  if (grad != nullptr) Eigen::Map<Eigen::Vector2d>{grad} = c->row;
  return c->row.dot(Eigen::Vector2d(x[0], x[1])) - c->bound;
}

/// Unilateral and friction rows for lambda (force at E) and F_B = total - lambda.
std::vector<LinearRow> contactRows(const Vec2d& total, double mu) {
  return {
      {{0, -1}, 0},                          // F_Ey >= 0
      {{0, 1}, total(1)},                    // F_By >= 0
      {{1, -mu}, 0},                         //  F_Ex <= mu F_Ey
      {{-1, -mu}, 0},                        // -F_Ex <= mu F_Ey
      {{-1, mu}, mu * total(1) - total(0)},  //  F_Bx <= mu F_By
      {{1, mu}, mu * total(1) + total(0)},   // -F_Bx <= mu F_By
  };
}

DspForces forcesFor(const TorqueMap& map, const Vec2d& total, const Vec2d& lambda) {
  return {map.tau_bar - map.a * lambda, total - lambda, lambda, false};
}

}  // namespace

DspForces distributeDspForces(const dynamics::Model& model, const VecD& theta, const VecD& dtheta,
                              const VecD& ddtheta) {
  const int n = model.nLinks();
  const Mat2Xd jac = dynamics::pointJacobian(model.tipWeights(), theta);
  const MatD m_inv_t = dynamics::jointMap(n).transpose().inverse();
  TorqueMap map{m_inv_t * (dynamics::massMatrix(model, theta) * ddtheta +
                           dynamics::nonlinearEffects(model, theta, dtheta)),
                m_inv_t * jac.transpose()};
  // Total ground force F_B + F_E = m (a_com - g_vec), g_vec in the ground frame (model.hpp).
  Vec2d total = model.totalMass() *
                dynamics::pointAcceleration(model.totalComWeights(), theta, dtheta, ddtheta);
  total -= model.totalMass() * model.gravityAcceleration();

  std::vector<LinearRow> rows = contactRows(total, model.friction());
  LinearRow ankle{map.a.row(0).transpose(), map.tau_bar(0)};  // tau0(lambda) = 0
  nlopt::opt opt(nlopt::LD_SLSQP, 2);
  opt.set_min_objective(objective, &map);
  for (auto& row : rows) opt.add_inequality_constraint(linearConstraint, &row, 1e-10);
  if (!model.joints().front().actuated)
    opt.add_equality_constraint(linearConstraint, &ankle, 1e-10);
  opt.set_xtol_abs(1e-10);
  opt.set_ftol_rel(1e-14);
  opt.set_maxeval(200);

  std::vector<double> x{0.5 * total(0), 0.5 * total(1)};  // even split: feasible when any is
  double value = 0;
  try {
    opt.optimize(x, value);
  } catch (const std::exception&) {
    // Infeasible or degenerate: fall back to the least-norm tip force, flagged below.
    const Eigen::Vector2d ls = map.a.colPivHouseholderQr().solve(map.tau_bar);
    x = {ls(0), ls(1)};
  }
  DspForces out = forcesFor(map, total, Vec2d(x[0], x[1]));
  const double tol = 1e-9 * (1 + total.norm());
  out.feasible = true;
  for (const auto& row : rows)
    out.feasible = out.feasible && row.row.dot(out.force_swing) - row.bound <= tol;
  if (!model.joints().front().actuated) out.feasible = out.feasible && std::abs(out.tau(0)) <= tol;
  return out;
}

}  // namespace gaitopt::gaits
