#include "ocp/transcription/collocation.hpp"

#include <algorithm>
#include <functional>
#include <stdexcept>
#include <utility>

namespace gaitopt::ocp {
namespace {

/// Adds coefficient * (variable) to row `row` for each state component.
void addStateTerms(Triplets& out, int row0, int nx, double coefficient,
                   const std::function<int(int)>& column) {
  for (int i = 0; i < nx; ++i) out.emplace_back(row0 + i, column(i), coefficient);
}

int defectRows(const PhaseLayout& l) {
  return (l.scheme == Scheme::kHermiteSimpson ? 2 : 1) * l.segments * l.nx;
}

}  // namespace

const char* toString(Scheme scheme) {
  return scheme == Scheme::kHermiteSimpson ? "hermite_simpson" : "trapezoidal";
}

Scheme schemeFromString(const std::string& text) {
  if (text == "hermite_simpson") return Scheme::kHermiteSimpson;
  if (text == "trapezoidal") return Scheme::kTrapezoidal;
  throw std::invalid_argument("unknown collocation scheme '" + text +
                              "' (expected trapezoidal or hermite_simpson)");
}

double PhaseLayout::time(int p, double total) const {
  const int k = std::min(p / pointsPerSegment(), segments - 1);
  const double within = static_cast<double>(p - k * pointsPerSegment()) / pointsPerSegment();
  return total * (fraction(k) + within * segmentFraction(k));
}

Eigen::VectorXd PhaseLayout::quadratureWeights() const {
  Eigen::VectorXd w = Eigen::VectorXd::Zero(points());
  for (int k = 0; k < segments; ++k) {
    const double h = segmentFraction(k);
    if (scheme == Scheme::kTrapezoidal) {
      w(k) += h / 2;
      w(k + 1) += h / 2;
    } else {  // Simpson's rule on [t_2k, t_2k+2]
      w(2 * k) += h / 6;
      w(2 * k + 1) += 4 * h / 6;
      w(2 * k + 2) += h / 6;
    }
  }
  return w;
}

void PhaseLayout::validate() const {
  if (segments < 1) throw std::invalid_argument("a phase needs at least one segment");
  if (mesh.empty()) return;
  if (static_cast<int>(mesh.size()) != segments + 1 || mesh.front() != 0.0 || mesh.back() != 1.0)
    throw std::invalid_argument("a phase mesh has segments + 1 fractions from 0 to 1");
  for (int k = 0; k < segments; ++k)
    if (!(segmentFraction(k) > 0))
      throw std::invalid_argument("phase mesh fractions must increase");
}

CollocationDefects::CollocationDefects(std::string name, std::string phase,
                                       const PhaseLayout& layout)
    : ConstraintSet(std::move(name), defectRows(layout), std::move(phase)), layout_(layout) {
  const PhaseLayout& l = layout_;
  l.validate();
  const int nx = l.nx;
  auto states = [&](int row, double c, int p) {
    addStateTerms(states_, row, nx, c, [&](int i) { return l.x(p, i); });
  };
  auto rates = [&](int row, double c, int p) {  // c per unit T
    addStateTerms(scaled_, row, nx, c, [&](int i) { return l.xdot(p, i); });
  };
  for (int k = 0; k < l.segments; ++k) {
    const double h = l.segmentFraction(k);
    if (l.scheme == Scheme::kTrapezoidal) {
      const int row = k * nx;
      states(row, 1.0, k + 1);
      states(row, -1.0, k);
      rates(row, -h / 2, k);
      rates(row, -h / 2, k + 1);
      continue;
    }
    const int a = 2 * k, m = 2 * k + 1, b = 2 * k + 2;
    const int simpson = 2 * k * nx;
    states(simpson, 1.0, b);
    states(simpson, -1.0, a);
    rates(simpson, -h / 6, a);
    rates(simpson, -4 * h / 6, m);
    rates(simpson, -h / 6, b);
    const int hermite = simpson + nx;
    states(hermite, 1.0, m);
    states(hermite, -0.5, a);
    states(hermite, -0.5, b);
    rates(hermite, -h / 8, a);
    rates(hermite, h / 8, b);
  }
}

void CollocationDefects::values(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> g) const {
  const double total = layout_.durationAt(x);
  g.setZero();
  for (const auto& e : states_) g(e.row()) += e.value() * x(e.col());
  for (const auto& e : scaled_) g(e.row()) += total * e.value() * x(e.col());
}

void CollocationDefects::jacobian(const Eigen::VectorXd& x, Triplets& out) const {
  const double total = layout_.durationAt(x);
  out.insert(out.end(), states_.begin(), states_.end());
  for (const auto& e : scaled_) {
    out.emplace_back(e.row(), e.col(), total * e.value());
    if (layout_.freeDuration())
      out.emplace_back(e.row(), layout_.duration_index, e.value() * x(e.col()));
  }
}

void CollocationDefects::hessian(const Eigen::VectorXd&, const Eigen::VectorXd& lambda,
                                 Triplets& out) const {
  if (!layout_.freeDuration()) return;
  const int t = layout_.duration_index;
  for (const auto& e : scaled_)  // d2/dT dxdot of T c xdot
    out.emplace_back(std::max(t, e.col()), std::min(t, e.col()), lambda(e.row()) * e.value());
}

}  // namespace gaitopt::ocp
