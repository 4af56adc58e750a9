#include "ocp/shape/variant_sets.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "dynamics/joint_coordinates.hpp"

namespace gaitopt::ocp {
namespace {

int actuatedJoints(const dynamics::Model& model) {
  return static_cast<int>(std::count_if(model.joints().begin(), model.joints().end(),
                                        [](const auto& joint) { return joint.actuated; }));
}

}  // namespace

FeedbackLaw::FeedbackLaw(std::string name, const Phase& variant, const Phase& reference,
                         const dynamics::Model& model, const FeedbackGains& gains)
    : ConstraintSet(std::move(name), variant.layout.points() * actuatedJoints(model),
                    variant.name()),
      joints_(actuatedJoints(model)) {
  if (variant.layout.points() != reference.layout.points())
    throw std::invalid_argument("a variant's feedback law needs the reference's mesh");
  const PointLayout& v = variant.point;
  const PointLayout& r = reference.point;
  const MatD map = dynamics::jointMap(model.nLinks());  // q = M theta (Mu 2.41)
  int row = 0;
  for (int p = 0; p < variant.layout.points(); ++p) {
    const int vo = variant.layout.pointOffset(p), ro = reference.layout.pointOffset(p);
    for (int j = 0; j < model.nLinks(); ++j) {
      if (!model.joints()[static_cast<size_t>(j)].actuated) continue;
      entries_.emplace_back(row, vo + v.u[j], 1.0);
      entries_.emplace_back(row, ro + r.u[j], -1.0);
      for (int i = 0; i < model.nLinks(); ++i) {  // - kp M (theta_ref - theta) - kd M (...)
        const double m = map(j, i);
        if (m == 0) continue;
        entries_.emplace_back(row, ro + r.q[i], -gains.kp * m);
        entries_.emplace_back(row, vo + v.q[i], gains.kp * m);
        entries_.emplace_back(row, ro + r.v[i], -gains.kd * m);
        entries_.emplace_back(row, vo + v.v[i], gains.kd * m);
      }
      ++row;
    }
  }
}

void FeedbackLaw::values(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> g) const {
  g.setZero();
  for (const auto& e : entries_) g(e.row()) += e.value() * x(e.col());
}

void FeedbackLaw::jacobian(const Eigen::VectorXd& /*x*/, Triplets& out) const {
  out.insert(out.end(), entries_.begin(), entries_.end());
}

StateDistance::StateDistance(std::string name, std::vector<int> a, std::vector<int> b,
                             double tolerance)
    : ConstraintSet(std::move(name), 1), a_(std::move(a)), b_(std::move(b)), tolerance_(tolerance) {
  if (a_.size() != b_.size()) throw std::invalid_argument("states of different sizes");
}

void StateDistance::values(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> g) const {
  double sum = 0;
  for (size_t i = 0; i < a_.size(); ++i) sum += (x(a_[i]) - x(b_[i])) * (x(a_[i]) - x(b_[i]));
  g(0) = sum;
}

void StateDistance::jacobian(const Eigen::VectorXd& x, Triplets& out) const {
  for (size_t i = 0; i < a_.size(); ++i) {
    const double d = x(a_[i]) - x(b_[i]);
    out.emplace_back(0, a_[i], 2 * d);
    out.emplace_back(0, b_[i], -2 * d);
  }
}

void StateDistance::hessian(const Eigen::VectorXd& /*x*/, const Eigen::VectorXd& lambda,
                            Triplets& out) const {
  const double h = 2 * lambda(0);
  for (size_t i = 0; i < a_.size(); ++i) {
    out.emplace_back(a_[i], a_[i], h);
    out.emplace_back(b_[i], b_[i], h);
    out.emplace_back(std::max(a_[i], b_[i]), std::min(a_[i], b_[i]), -h);
  }
}

VariantSpread::VariantSpread(std::string name, const Phase& variant, const Phase& reference,
                             double weight)
    : CostTerm(std::move(name)), layout_(variant.layout) {
  const Eigen::VectorXd w = variant.layout.quadratureWeights();
  for (int p = 0; p < variant.layout.points(); ++p)
    for (int i = 0; i < variant.point.q.size; ++i)
      pairs_.push_back({variant.layout.pointOffset(p) + variant.point.q[i],
                        reference.layout.pointOffset(p) + reference.point.q[i], weight * w(p)});
}

double VariantSpread::value(const Eigen::VectorXd& x) const {
  double sum = 0;
  for (const Pair& e : pairs_) sum += e.w * (x(e.a) - x(e.b)) * (x(e.a) - x(e.b));
  return duration(x) * sum;
}

void VariantSpread::gradient(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> grad) const {
  const double t = duration(x);
  double unit = 0;  // the value per unit duration: d value / d T
  for (const Pair& e : pairs_) {
    const double d = x(e.a) - x(e.b);
    grad(e.a) += 2 * t * e.w * d;
    grad(e.b) -= 2 * t * e.w * d;
    unit += e.w * d * d;
  }
  if (layout_.freeDuration()) grad(layout_.duration_index) += unit;
}

void VariantSpread::hessian(const Eigen::VectorXd& x, double factor, Triplets& out) const {
  const double t = duration(x);
  for (const Pair& e : pairs_) {
    const double h = 2 * factor * t * e.w;
    out.emplace_back(e.a, e.a, h);
    out.emplace_back(e.b, e.b, h);
    out.emplace_back(std::max(e.a, e.b), std::min(e.a, e.b), -h);
    if (!layout_.freeDuration()) continue;
    const int T = layout_.duration_index;
    const double c = 2 * factor * e.w * (x(e.a) - x(e.b));  // d2 / dT d(theta_k - theta_ref)
    out.emplace_back(std::max(T, e.a), std::min(T, e.a), c);
    out.emplace_back(std::max(T, e.b), std::min(T, e.b), -c);
  }
}

}  // namespace gaitopt::ocp
