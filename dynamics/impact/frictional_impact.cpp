#include "dynamics/impact/frictional_impact.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include "dynamics/floating_base.hpp"

namespace gaitopt::dynamics {
namespace {

enum class Mode { kStick, kSlidePositive, kSlideNegative };

/// The impulse problem of HGB (82) on the free-base chain: tips in contact (B first when it is
/// one), rows (t, n) = (x, y) per tip.
struct ImpactProblem {
  int n = 0;                   ///< links
  Eigen::MatrixXd d_inv_ct;    ///< D_ext^-1 C^T, (n + 2) x 2k
  Eigen::MatrixXd delassus;    ///< A = C D_ext^-1 C^T, 2k x 2k
  Eigen::VectorXd qdot_minus;  ///< (0, 0, dtheta-): B at rest before the impact
  Eigen::VectorXd v_minus;     ///< C qdot-: tip velocities before the impact
  double mu = 0, restitution = 0;
};

ImpactProblem setUp(const Model& model, const VecD& theta, const VecD& dtheta, bool with_b,
                    double restitution) {
  ImpactProblem p;
  p.n = model.nLinks();
  const int k = with_b ? 2 : 1;
  Eigen::MatrixXd c = Eigen::MatrixXd::Zero(2 * k, p.n + 2);
  if (with_b) c.topLeftCorner(2, 2).setIdentity();  // J_B = [I 0]
  c.bottomRows(2) = floatingJacobian(model.tipWeights(), theta);
  p.d_inv_ct = floatingBaseMassMatrix(model, theta).ldlt().solve(c.transpose());
  p.delassus = c * p.d_inv_ct;
  p.qdot_minus = Eigen::VectorXd::Zero(p.n + 2);
  p.qdot_minus.tail(p.n) = dtheta;
  p.v_minus = c * p.qdot_minus;
  p.mu = model.friction();
  p.restitution = restitution;
  return p;
}

double slipSign(Mode m) {
  return m == Mode::kSlidePositive ? 1.0 : -1.0;
}

/// The impulses of one stick/slide mode per tip: Newton's law in every normal row, and per
/// tangential row either v_t+ = 0 (stick, HGB 79) or P_t = -s mu P_n (slide in direction s,
/// HGB 80-81), with v+ = v- + A P.
Eigen::VectorXd modeImpulses(const ImpactProblem& p, const std::vector<Mode>& modes) {
  const auto rows = static_cast<Eigen::Index>(2 * modes.size());
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(rows, rows);
  Eigen::VectorXd r(rows);
  for (Eigen::Index i = 0; i < rows / 2; ++i) {
    const Eigen::Index t = 2 * i, nr = 2 * i + 1;
    k.row(nr) = p.delassus.row(nr);
    r(nr) = -(1 + p.restitution) * p.v_minus(nr);
    const Mode m = modes[static_cast<size_t>(i)];
    if (m == Mode::kStick) {
      k.row(t) = p.delassus.row(t);
      r(t) = -p.v_minus(t);
    } else {
      k(t, t) = 1;
      k(t, nr) = slipSign(m) * p.mu;
      r(t) = 0;
    }
  }
  return k.fullPivLu().solve(r);
}

/// Does the mode's solution satisfy its own conditions (P_n >= 0; stick inside the cone; slide
/// in the assumed direction)?
bool consistent(const ImpactProblem& p, const std::vector<Mode>& modes,
                const Eigen::VectorXd& impulses) {
  const Eigen::VectorXd v_plus = p.v_minus + p.delassus * impulses;
  const double tol = 1e-12 * (1 + impulses.norm());
  for (size_t i = 0; i < modes.size(); ++i) {
    const auto t = static_cast<Eigen::Index>(2 * i);
    const double p_t = impulses(t), p_n = impulses(t + 1);
    if (p_n < -tol) return false;
    if (modes[i] == Mode::kStick ? std::abs(p_t) > p.mu * p_n + tol
                                 : slipSign(modes[i]) * v_plus(t) <= 0)
      return false;
  }
  return true;
}

/// Every combination of modes for `tips` tips, fewest sliding tips first.
std::vector<std::vector<Mode>> modesToTry(int tips) {
  std::vector<std::vector<Mode>> all{{}};
  for (int i = 0; i < tips; ++i) {
    std::vector<std::vector<Mode>> longer;
    for (const auto& head : all)
      for (Mode m : {Mode::kStick, Mode::kSlidePositive, Mode::kSlideNegative}) {
        longer.push_back(head);
        longer.back().push_back(m);
      }
    all = std::move(longer);
  }
  const auto sliding = [](const std::vector<Mode>& modes) {
    return std::count_if(modes.begin(), modes.end(), [](Mode m) { return m != Mode::kStick; });
  };
  std::stable_sort(all.begin(), all.end(),
                   [&](const auto& a, const auto& b) { return sliding(a) < sliding(b); });
  return all;
}

TipImpact tip(const Eigen::VectorXd& impulses, const Eigen::VectorXd& v_plus, Eigen::Index row,
              Mode mode) {
  return {impulses.segment<2>(row), v_plus.segment<2>(row), mode != Mode::kStick};
}

/// The outcome of one mode: rates, base velocity, each tip's impulse and velocity after.
FrictionalImpact outcome(const ImpactProblem& p, bool with_b, const std::vector<Mode>& modes,
                         const Eigen::VectorXd& impulses) {
  const int tips = with_b ? 2 : 1;
  const Eigen::VectorXd qdot_plus = p.qdot_minus + p.d_inv_ct * impulses;  // HGB (82)
  const Eigen::VectorXd v_plus = p.v_minus + p.delassus * impulses;
  FrictionalImpact out;
  out.dtheta_plus = qdot_plus.tail(p.n);
  out.base_velocity = qdot_plus.head<2>();
  out.leading = tip(impulses, v_plus, 2 * (tips - 1), modes.back());
  out.trailing.velocity = out.base_velocity;  // B is the base
  if (with_b) out.trailing = tip(impulses, v_plus, 0, modes.front());
  out.unilateral_ok =
      with_b ? out.trailing.impulse(1) > 0 : out.base_velocity(1) > 0;  // (2.31a) / (2.37a)
  return out;
}

/// Every mode whose solution satisfies its own conditions, fewest sliding tips first.
std::vector<FrictionalImpact> consistentOutcomes(const ImpactProblem& p, bool with_b) {
  std::vector<FrictionalImpact> found;
  for (const auto& m : modesToTry(with_b ? 2 : 1)) {
    const Eigen::VectorXd trial = modeImpulses(p, m);
    if (!consistent(p, m, trial)) continue;
    found.push_back(outcome(p, with_b, m, trial));
    found.back().consistent = true;
  }
  return found;
}

FrictionalImpact solve(const ImpactProblem& p, bool with_b) {
  const std::vector<FrictionalImpact> found = consistentOutcomes(p, with_b);
  if (!found.empty()) return found.front();
  // None: the all-sticking solution, marked inconsistent.
  const std::vector<Mode> sticking = modesToTry(with_b ? 2 : 1).front();
  return outcome(p, with_b, sticking, modeImpulses(p, sticking));
}

}  // namespace

FrictionalImpact frictionalSingleImpact(const Model& model, const VecD& theta,
                                        const VecD& dtheta_minus, double restitution) {
  return solve(setUp(model, theta, dtheta_minus, false, restitution), false);
}

FrictionalImpact frictionalDoubleImpact(const Model& model, const VecD& theta,
                                        const VecD& dtheta_minus, double restitution) {
  return solve(setUp(model, theta, dtheta_minus, true, restitution), true);
}

ImpactType ComplementarityImpact::type() const {
  if (!staying.empty() && !leaving.empty()) return ImpactType::kEither;
  if (!staying.empty()) return ImpactType::kDouble;
  return leaving.empty() ? ImpactType::kNeither : ImpactType::kSingle;
}

ComplementarityImpact complementarityImpact(const Model& model, const VecD& theta,
                                            const VecD& dtheta_minus, double restitution) {
  ComplementarityImpact out;
  out.staying = consistentOutcomes(setUp(model, theta, dtheta_minus, true, restitution), true);
  // B left free: a solution only where B does not move into the ground (v_Bn+ >= 0).
  for (FrictionalImpact& f :
       consistentOutcomes(setUp(model, theta, dtheta_minus, false, restitution), false))
    if (f.base_velocity(1) >= -1e-12 * (1 + f.base_velocity.norm()))
      out.leaving.push_back(std::move(f));
  return out;
}

}  // namespace gaitopt::dynamics
