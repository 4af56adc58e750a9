#include "ocp/problem/interior_work.hpp"

#include <algorithm>
#include <utility>
#include <vector>

#include "ocp/transcription/collocation_interpolation.hpp"

namespace gaitopt::ocp {
namespace {

/// dq_j = sum_m c_jm dtheta_m (Mu 2.41): dq_0 = dtheta_0, dq_j = dtheta_{j-1} - dtheta_j.
std::vector<std::pair<int, double>> jointRateTerms(int j) {
  if (j == 0) return {{0, 1.0}};
  return {{j - 1, 1.0}, {j, -1.0}};
}

/// c x: one variable's share of a linear form.
struct Term {
  int index = 0;
  double coefficient = 0;
};

double evaluate(const std::vector<Term>& form, const Eigen::VectorXd& x) {
  double sum = 0;
  for (const Term& t : form) sum += t.coefficient * x(t.index);
  return sum;
}

/// Joint j's torque and rate at local time s of segment k as linear forms of the decision vector,
/// read as the export reads them (collocation_interpolation.hpp): the torque is the quadratic
/// through the segment's three points; the rate is v_k plus h times the integral of the
/// quadratic through its three accelerations, a cubic. `slope` is d(rate)/dT for a free T.
struct SampleForms {
  std::vector<Term> tau, rate, slope;
};

SampleForms sampleForms(const Phase& phase, const Eigen::VectorXd& x, double s, int k, int j) {
  const SegmentBasis value = lagrangeBasis(Scheme::kHermiteSimpson, s);
  const SegmentBasis integral = lagrangeBasisIntegral(Scheme::kHermiteSimpson, s);
  const double fraction = phase.layout.segmentFraction(k);
  const double h = phase.layout.durationAt(x) * fraction;
  SampleForms f;
  for (int i = 0; i < 3; ++i) {
    const int base = phase.layout.pointOffset(2 * k + i);
    const double w = integral[static_cast<size_t>(i)];
    f.tau.push_back({base + phase.point.u[j], value[static_cast<size_t>(i)]});
    for (const auto& [m, c] : jointRateTerms(j)) {
      if (i == 0) f.rate.push_back({base + phase.point.v[m], c});
      f.rate.push_back({base + phase.point.a[m], c * h * w});
      f.slope.push_back({base + phase.point.a[m], c * fraction * w});
    }
  }
  return f;
}

}  // namespace

InteriorWorkSplit::InteriorWorkSplit(std::string name, const Phase& phase,
                                     const InteriorSlacks& slacks)
    : ConstraintSet(std::move(name), slacks.segments * slacks.samples() * slacks.n, phase.name()),
      phase_(phase),
      slacks_(slacks) {}

void InteriorWorkSplit::values(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> g) const {
  const int n = slacks_.n;
  for (int k = 0; k < slacks_.segments; ++k)
    for (int r = 0; r < slacks_.samples(); ++r)
      for (int j = 0; j < n; ++j) {
        const SampleForms f = sampleForms(phase_, x, slacks_.at(r), k, j);
        g((k * slacks_.samples() + r) * n + j) = evaluate(f.tau, x) * evaluate(f.rate, x) -
                                                 x(slacks_.plus(k, r, j)) +
                                                 x(slacks_.minus(k, r, j));
      }
}

void InteriorWorkSplit::jacobian(const Eigen::VectorXd& x, Triplets& out) const {
  const int n = slacks_.n;
  const int duration = phase_.layout.duration_index;
  for (int k = 0; k < slacks_.segments; ++k)
    for (int r = 0; r < slacks_.samples(); ++r)
      for (int j = 0; j < n; ++j) {
        const int row = (k * slacks_.samples() + r) * n + j;
        const SampleForms f = sampleForms(phase_, x, slacks_.at(r), k, j);
        const double tau = evaluate(f.tau, x), rate = evaluate(f.rate, x);
        for (const Term& t : f.tau) out.emplace_back(row, t.index, t.coefficient * rate);
        for (const Term& t : f.rate) out.emplace_back(row, t.index, t.coefficient * tau);
        if (duration >= 0) out.emplace_back(row, duration, tau * evaluate(f.slope, x));
        out.emplace_back(row, slacks_.plus(k, r, j), -1.0);
        out.emplace_back(row, slacks_.minus(k, r, j), 1.0);
      }
}

// Each row is tau * rate, bilinear in (u; v, a); with a free T the rate is bilinear in (T, a)
// too, which adds the (u, T) and (a, T) blocks.
void InteriorWorkSplit::hessian(const Eigen::VectorXd& x, const Eigen::VectorXd& lambda,
                                Triplets& out) const {
  const int n = slacks_.n;
  const int duration = phase_.layout.duration_index;
  const auto add = [&out](int a, int b, double value) {
    out.emplace_back(std::max(a, b), std::min(a, b), value);
  };
  for (int k = 0; k < slacks_.segments; ++k)
    for (int r = 0; r < slacks_.samples(); ++r)
      for (int j = 0; j < n; ++j) {
        const double w = lambda((k * slacks_.samples() + r) * n + j);
        const SampleForms f = sampleForms(phase_, x, slacks_.at(r), k, j);
        for (const Term& a : f.tau)
          for (const Term& b : f.rate) add(a.index, b.index, w * a.coefficient * b.coefficient);
        if (duration < 0) continue;
        const double tau = evaluate(f.tau, x), slope = evaluate(f.slope, x);
        for (const Term& a : f.tau) add(a.index, duration, w * a.coefficient * slope);
        for (const Term& b : f.slope) add(b.index, duration, w * tau * b.coefficient);
      }
}

InteriorWorkCost::InteriorWorkCost(std::string name, const PhaseLayout& layout,
                                   const InteriorSlacks& slacks, double weight)
    : CostTerm(std::move(name)), layout_(layout), slacks_(slacks), weight_(weight) {}

double InteriorWorkCost::coefficient(int k, int r) const {
  return weight_ * layout_.segmentFraction(k) * slacks_.weight(r);
}

/// T sum_k coefficient(k, r) sum (s+ + s-).
double InteriorWorkCost::value(const Eigen::VectorXd& x) const {
  double total = 0;
  for (int k = 0; k < slacks_.segments; ++k)
    for (int r = 0; r < slacks_.samples(); ++r)
      for (int j = 0; j < slacks_.n; ++j)
        total += coefficient(k, r) * (x(slacks_.plus(k, r, j)) + x(slacks_.minus(k, r, j)));
  return layout_.durationAt(x) * total;
}

void InteriorWorkCost::gradient(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> grad) const {
  const double duration = layout_.durationAt(x);
  for (int k = 0; k < slacks_.segments; ++k)
    for (int r = 0; r < slacks_.samples(); ++r)
      for (int j = 0; j < slacks_.n; ++j) {
        grad(slacks_.plus(k, r, j)) += duration * coefficient(k, r);
        grad(slacks_.minus(k, r, j)) += duration * coefficient(k, r);
      }
  if (layout_.freeDuration()) grad(layout_.duration_index) += value(x) / duration;
}

// Linear in the slacks; with a free T, d2/dT ds = coefficient.
void InteriorWorkCost::hessian(const Eigen::VectorXd&, double factor, Triplets& out) const {
  const int t = layout_.duration_index;
  if (t < 0) return;
  for (int k = 0; k < slacks_.segments; ++k)
    for (int r = 0; r < slacks_.samples(); ++r)
      for (int j = 0; j < slacks_.n; ++j)
        for (const int s : {slacks_.plus(k, r, j), slacks_.minus(k, r, j)})
          out.emplace_back(std::max(t, s), std::min(t, s), factor * coefficient(k, r));
}

Eigen::VectorXd pointWeights(const PhaseLayout& layout) {
  const double end = simpsonWeight(0), middle = simpsonWeight(kWorkSubIntervals / 2);
  Eigen::VectorXd w = Eigen::VectorXd::Zero(layout.points());
  for (int k = 0; k < layout.segments; ++k) {
    const double h = layout.segmentFraction(k);
    w(2 * k) += h * end;
    w(2 * k + 1) += h * middle;
    w(2 * k + 2) += h * end;
  }
  return w;
}

InteriorSlacks addInteriorWork(Nlp& nlp, const Phase& phase, double weight) {
  InteriorSlacks s{.offset = 0, .segments = phase.layout.segments, .n = phase.point.n};
  const Eigen::VectorXd& x0 = nlp.initialGuess();
  Eigen::VectorXd start(s.size());
  for (int k = 0; k < s.segments; ++k)
    for (int r = 0; r < s.samples(); ++r)
      for (int j = 0; j < s.n; ++j) {
        const SampleForms f = sampleForms(phase, x0, s.at(r), k, j);
        const double power = evaluate(f.tau, x0) * evaluate(f.rate, x0);
        start(s.plus(k, r, j)) = std::max(power, 0.0);
        start(s.minus(k, r, j)) = std::max(-power, 0.0);
      }
  s.offset =
      nlp.addVariables(phase.name() + "_interior_work", s.size(), Eigen::VectorXd::Zero(s.size()),
                       Eigen::VectorXd::Constant(s.size(), kInf), start, phase.name())
          .offset;
  nlp.addConstraint(
      std::make_unique<InteriorWorkSplit>(phase.name() + "_interior_work_split", phase, s));
  nlp.addCost(std::make_unique<InteriorWorkCost>(phase.name() + "_interior_abs_work", phase.layout,
                                                 s, weight));
  return s;
}

}  // namespace gaitopt::ocp
