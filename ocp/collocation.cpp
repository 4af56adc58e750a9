#include "ocp/collocation.hpp"

#include <functional>
#include <stdexcept>

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

double PhaseLayout::time(int p) const {
  const int per_segment = scheme == Scheme::kHermiteSimpson ? 2 : 1;
  return segmentLength() * p / per_segment;
}

Eigen::VectorXd PhaseLayout::quadratureWeights() const {
  const double h = segmentLength();
  Eigen::VectorXd w = Eigen::VectorXd::Zero(points());
  for (int k = 0; k < segments; ++k) {
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

CollocationDefects::CollocationDefects(const PhaseLayout& layout, const std::string& name)
    : ConstraintSet(name, defectRows(layout)), layout_(layout) {
  const PhaseLayout& l = layout_;
  const double h = l.segmentLength();
  const int nx = l.nx;
  for (int k = 0; k < l.segments; ++k) {
    if (l.scheme == Scheme::kTrapezoidal) {
      const int row = k * nx;
      addStateTerms(entries_, row, nx, 1.0, [&](int i) { return l.x(k + 1, i); });
      addStateTerms(entries_, row, nx, -1.0, [&](int i) { return l.x(k, i); });
      addStateTerms(entries_, row, nx, -h / 2, [&](int i) { return l.xdot(k, i); });
      addStateTerms(entries_, row, nx, -h / 2, [&](int i) { return l.xdot(k + 1, i); });
      continue;
    }
    const int a = 2 * k, m = 2 * k + 1, b = 2 * k + 2;
    const int simpson = 2 * k * nx;
    addStateTerms(entries_, simpson, nx, 1.0, [&](int i) { return l.x(b, i); });
    addStateTerms(entries_, simpson, nx, -1.0, [&](int i) { return l.x(a, i); });
    addStateTerms(entries_, simpson, nx, -h / 6, [&](int i) { return l.xdot(a, i); });
    addStateTerms(entries_, simpson, nx, -4 * h / 6, [&](int i) { return l.xdot(m, i); });
    addStateTerms(entries_, simpson, nx, -h / 6, [&](int i) { return l.xdot(b, i); });
    const int hermite = simpson + nx;
    addStateTerms(entries_, hermite, nx, 1.0, [&](int i) { return l.x(m, i); });
    addStateTerms(entries_, hermite, nx, -0.5, [&](int i) { return l.x(a, i); });
    addStateTerms(entries_, hermite, nx, -0.5, [&](int i) { return l.x(b, i); });
    addStateTerms(entries_, hermite, nx, -h / 8, [&](int i) { return l.xdot(a, i); });
    addStateTerms(entries_, hermite, nx, h / 8, [&](int i) { return l.xdot(b, i); });
  }
}

void CollocationDefects::values(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> g) const {
  g.setZero();
  for (const auto& e : entries_) g(e.row()) += e.value() * x(e.col());
}

void CollocationDefects::jacobian(const Eigen::VectorXd&, Triplets& out) const {
  out.insert(out.end(), entries_.begin(), entries_.end());
}

}  // namespace gaitopt::ocp
