#include "ocp/problem/quarter_work.hpp"

#include <algorithm>
#include <array>
#include <utility>

namespace gaitopt::ocp {
namespace {

/// Lagrange basis of the points (0, 1/2, 1) at s = 1/4 and s = 3/4.
constexpr std::array<std::array<double, 3>, 2> kBasis{
    {{0.375, 0.75, -0.125}, {-0.125, 0.75, 0.375}}};
/// The quarter points' weight in h/12 (1, 4, 2, 4, 1).
constexpr double kQuarterWeight = 4.0 / 12.0;

/// dq_j = sum_m c_jm dtheta_m (Mu 2.41): dq_0 = dtheta_0, dq_j = dtheta_{j-1} - dtheta_j.
std::vector<std::pair<int, double>> jointRateTerms(int j) {
  if (j == 0) return {{0, 1.0}};
  return {{j - 1, 1.0}, {j, -1.0}};
}

/// Torque and joint rate of joint j at quarter r of segment k, and where they come from.
struct QuarterValues {
  double tau = 0, dq = 0;
};

QuarterValues quarterValues(const Phase& phase, const Eigen::VectorXd& x, int k, int r, int j) {
  QuarterValues out;
  for (int i = 0; i < 3; ++i) {
    const int base = phase.layout.pointOffset(2 * k + i);
    const double weight = kBasis[static_cast<size_t>(r)][static_cast<size_t>(i)];
    out.tau += weight * x(base + phase.point.u[j]);
    for (const auto& [m, c] : jointRateTerms(j)) out.dq += weight * c * x(base + phase.point.v[m]);
  }
  return out;
}

}  // namespace

QuarterWorkSplit::QuarterWorkSplit(std::string name, const Phase& phase,
                                   const QuarterSlacks& slacks)
    : ConstraintSet(std::move(name), slacks.segments * 2 * slacks.n, phase.name()),
      phase_(phase),
      slacks_(slacks) {}

void QuarterWorkSplit::values(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> g) const {
  const int n = slacks_.n;
  for (int k = 0; k < slacks_.segments; ++k)
    for (int r = 0; r < 2; ++r)
      for (int j = 0; j < n; ++j) {
        const QuarterValues q = quarterValues(phase_, x, k, r, j);
        g((k * 2 + r) * n + j) =
            q.tau * q.dq - x(slacks_.plus(k, r, j)) + x(slacks_.minus(k, r, j));
      }
}

void QuarterWorkSplit::jacobian(const Eigen::VectorXd& x, Triplets& out) const {
  const int n = slacks_.n;
  for (int k = 0; k < slacks_.segments; ++k)
    for (int r = 0; r < 2; ++r)
      for (int j = 0; j < n; ++j) {
        const int row = (k * 2 + r) * n + j;
        const QuarterValues q = quarterValues(phase_, x, k, r, j);
        for (int i = 0; i < 3; ++i) {
          const int base = phase_.layout.pointOffset(2 * k + i);
          const double weight = kBasis[static_cast<size_t>(r)][static_cast<size_t>(i)];
          out.emplace_back(row, base + phase_.point.u[j], weight * q.dq);
          for (const auto& [m, c] : jointRateTerms(j))
            out.emplace_back(row, base + phase_.point.v[m], weight * c * q.tau);
        }
        out.emplace_back(row, slacks_.plus(k, r, j), -1.0);
        out.emplace_back(row, slacks_.minus(k, r, j), 1.0);
      }
}

// Each row is bilinear: d2/du_{a,j} dv_{b,m} = L_a L_b c_jm.
void QuarterWorkSplit::hessian(const Eigen::VectorXd&, const Eigen::VectorXd& lambda,
                               Triplets& out) const {
  const int n = slacks_.n;
  for (int k = 0; k < slacks_.segments; ++k)
    for (int r = 0; r < 2; ++r)
      for (int j = 0; j < n; ++j) {
        const double w = lambda((k * 2 + r) * n + j);
        const auto& basis = kBasis[static_cast<size_t>(r)];
        for (int a = 0; a < 3; ++a) {
          const int u = phase_.layout.pointOffset(2 * k + a) + phase_.point.u[j];
          for (int b = 0; b < 3; ++b)
            for (const auto& [m, c] : jointRateTerms(j)) {
              const int v = phase_.layout.pointOffset(2 * k + b) + phase_.point.v[m];
              out.emplace_back(
                  std::max(u, v), std::min(u, v),
                  w * basis[static_cast<size_t>(a)] * basis[static_cast<size_t>(b)] * c);
            }
        }
      }
}

QuarterWorkCost::QuarterWorkCost(std::string name, const PhaseLayout& layout,
                                 const QuarterSlacks& slacks, double weight)
    : CostTerm(std::move(name)), layout_(layout), slacks_(slacks), weight_(weight) {}

double QuarterWorkCost::coefficient(int k) const {
  return weight_ * layout_.segmentFraction(k) * kQuarterWeight;
}

/// T sum_k coefficient(k) sum (s+ + s-).
double QuarterWorkCost::value(const Eigen::VectorXd& x) const {
  double total = 0;
  for (int k = 0; k < slacks_.segments; ++k)
    for (int r = 0; r < 2; ++r)
      for (int j = 0; j < slacks_.n; ++j)
        total += coefficient(k) * (x(slacks_.plus(k, r, j)) + x(slacks_.minus(k, r, j)));
  return layout_.durationAt(x) * total;
}

void QuarterWorkCost::gradient(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> grad) const {
  const double duration = layout_.durationAt(x);
  for (int k = 0; k < slacks_.segments; ++k)
    for (int r = 0; r < 2; ++r)
      for (int j = 0; j < slacks_.n; ++j) {
        grad(slacks_.plus(k, r, j)) += duration * coefficient(k);
        grad(slacks_.minus(k, r, j)) += duration * coefficient(k);
      }
  if (layout_.freeDuration()) grad(layout_.duration_index) += value(x) / duration;
}

// Linear in the slacks; with a free T, d2/dT ds = coefficient.
void QuarterWorkCost::hessian(const Eigen::VectorXd&, double factor, Triplets& out) const {
  const int t = layout_.duration_index;
  if (t < 0) return;
  for (int k = 0; k < slacks_.segments; ++k)
    for (int r = 0; r < 2; ++r)
      for (int j = 0; j < slacks_.n; ++j)
        for (const int s : {slacks_.plus(k, r, j), slacks_.minus(k, r, j)})
          out.emplace_back(std::max(t, s), std::min(t, s), factor * coefficient(k));
}

Eigen::VectorXd fivePointWeights(const PhaseLayout& layout) {
  Eigen::VectorXd w = Eigen::VectorXd::Zero(layout.points());
  for (int k = 0; k < layout.segments; ++k) {
    const double h = layout.segmentFraction(k);
    w(2 * k) += h / 12;
    w(2 * k + 1) += 2 * h / 12;
    w(2 * k + 2) += h / 12;
  }
  return w;
}

QuarterSlacks addQuarterWork(Nlp& nlp, const Phase& phase, double weight) {
  QuarterSlacks s{.offset = 0, .segments = phase.layout.segments, .n = phase.point.n};
  const Eigen::VectorXd& x0 = nlp.initialGuess();
  Eigen::VectorXd start(s.size());
  for (int k = 0; k < s.segments; ++k)
    for (int r = 0; r < 2; ++r)
      for (int j = 0; j < s.n; ++j) {
        const QuarterValues q = quarterValues(phase, x0, k, r, j);
        start(s.plus(k, r, j)) = std::max(q.tau * q.dq, 0.0);
        start(s.minus(k, r, j)) = std::max(-q.tau * q.dq, 0.0);
      }
  s.offset =
      nlp.addVariables(phase.name() + "_quarter_work", s.size(), Eigen::VectorXd::Zero(s.size()),
                       Eigen::VectorXd::Constant(s.size(), kInf), start, phase.name())
          .offset;
  nlp.addConstraint(
      std::make_unique<QuarterWorkSplit>(phase.name() + "_quarter_work_split", phase, s));
  nlp.addCost(std::make_unique<QuarterWorkCost>(phase.name() + "_quarter_abs_work", phase.layout, s,
                                                weight));
  return s;
}

}  // namespace gaitopt::ocp
