#include "ocp/problem/dsp_chart.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "ocp/transcription/autodiff_constraint.hpp"

namespace gaitopt::ocp {
namespace {

/// The defect rows of collocation.hpp written on the chart: at level 0 the state c with rate
/// cdot, at level 1 cdot with rate cddot (entries level * nc + j of chartValue).
struct TermWriter {
  int nc;
  std::vector<ChartDefects::Term>& out;

  void add(int row0, int point, int block, double coefficient, bool scaled) const {
    for (int j = 0; j < nc; ++j)
      out.push_back({row0 + j, point, block * nc + j, coefficient, scaled});
  }
  /// x_b - x_a - h/2 (xdot_a + xdot_b) = 0.
  void trapezoid(int row0, int level, int a, int b, double h) const {
    add(row0, b, level, 1.0, false);
    add(row0, a, level, -1.0, false);
    add(row0, a, level + 1, -h / 2, true);
    add(row0, b, level + 1, -h / 2, true);
  }
  /// x_b - x_a - h/6 (xdot_a + 4 xdot_m + xdot_b) = 0.
  void simpson(int row0, int level, int a, int m, int b, double h) const {
    add(row0, b, level, 1.0, false);
    add(row0, a, level, -1.0, false);
    add(row0, a, level + 1, -h / 6, true);
    add(row0, m, level + 1, -4 * h / 6, true);
    add(row0, b, level + 1, -h / 6, true);
  }
  /// x_m - (x_a + x_b)/2 - h/8 (xdot_a - xdot_b) = 0.
  void hermite(int row0, int level, int a, int m, int b, double h) const {
    add(row0, m, level, 1.0, false);
    add(row0, a, level, -0.5, false);
    add(row0, b, level, -0.5, false);
    add(row0, a, level + 1, -h / 8, true);
    add(row0, b, level + 1, h / 8, true);
  }
};

int rowsPerSegment(const PhaseLayout& l, int nc) {
  return 2 * nc * l.pointsPerSegment();
}

}  // namespace

int chartSize(const dynamics::Model& model) {
  dynamics::requireKneedLegs(model,
                             "the double support in reduced coordinates (hip and upper body)");
  return model.nLinks() - 2;
}

namespace {

/// One link's unit vector u = (sin, cos) and its angle's rate and acceleration.
struct LinkMotion {
  double s, c, d, a;
};

LinkMotion linkMotion(const Eigen::VectorXd& y, int n, int j) {
  return {std::sin(y(j)), std::cos(y(j)), y(n + j), y(2 * n + j)};
}

}  // namespace

Eigen::VectorXd chartValue(const dynamics::Model& model, const Eigen::VectorXd& y) {
  const int n = model.nLinks(), nc = chartSize(model);
  Eigen::VectorXd v = Eigen::VectorXd::Zero(3 * nc);
  for (int j = 0; j < n; ++j) {
    const double w = model.hipWeights()(j);
    const auto [s, c, d, a] = linkMotion(y, n, j);
    v(0) += w * s;  // hip x, y (Mu 2.13) and their first two derivatives
    v(1) += w * c;
    v(nc) += w * c * d;
    v(nc + 1) -= w * s * d;
    v(2 * nc) += w * (c * a - s * d * d);
    v(2 * nc + 1) += w * (-s * a - c * d * d);
  }
  for (int i = 0; i < nc - 2; ++i)  // the links between the legs
    for (int level = 0; level < 3; ++level)
      v(level * nc + 2 + i) = y(level * n + model.legLinks() + i);
  return v;
}

Eigen::MatrixXd chartJacobian(const dynamics::Model& model, const Eigen::VectorXd& y) {
  const int n = model.nLinks(), nc = chartSize(model);
  Eigen::MatrixXd jac = Eigen::MatrixXd::Zero(3 * nc, 3 * n);
  for (int j = 0; j < n; ++j) {
    const double w = model.hipWeights()(j);
    const auto [s, c, d, a] = linkMotion(y, n, j);
    const int th = j, dt = n + j, dd = 2 * n + j;
    jac(0, th) = w * c;
    jac(1, th) = -w * s;
    jac(nc, th) = -w * s * d;
    jac(nc, dt) = w * c;
    jac(nc + 1, th) = -w * c * d;
    jac(nc + 1, dt) = -w * s;
    jac(2 * nc, th) = w * (-s * a - c * d * d);
    jac(2 * nc, dt) = -2 * w * s * d;
    jac(2 * nc, dd) = w * c;
    jac(2 * nc + 1, th) = w * (-c * a + s * d * d);
    jac(2 * nc + 1, dt) = -2 * w * c * d;
    jac(2 * nc + 1, dd) = -w * s;
  }
  for (int i = 0; i < nc - 2; ++i)
    for (int level = 0; level < 3; ++level)
      jac(level * nc + 2 + i, level * n + model.legLinks() + i) = 1.0;
  return jac;
}

Eigen::MatrixXd chartHessian(const dynamics::Model& model, const Eigen::VectorXd& y,
                             const Eigen::VectorXd& weights) {
  const int n = model.nLinks(), nc = chartSize(model);
  const double x0 = weights(0), y0 = weights(1), x1 = weights(nc), y1 = weights(nc + 1),
               x2 = weights(2 * nc), y2 = weights(2 * nc + 1);
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  for (int j = 0; j < n; ++j) {
    const double w = model.hipWeights()(j);
    const auto [s, c, d, a] = linkMotion(y, n, j);
    const int th = j, dt = n + j, dd = 2 * n + j;
    h(th, th) = w * (-x0 * s - x1 * c * d + x2 * (-c * a + s * d * d) - y0 * c + y1 * s * d +
                     y2 * (s * a + c * d * d));
    h(dt, th) = h(th, dt) = w * (-x1 * s - 2 * x2 * c * d - y1 * c + 2 * y2 * s * d);
    h(dd, th) = h(th, dd) = w * (-x2 * s - y2 * c);
    h(dt, dt) = w * (-2 * x2 * s - 2 * y2 * c);
  }
  return h;
}

ChartDefects::ChartDefects(std::string name, const dynamics::Model& model, const Phase& phase)
    : ConstraintSet(std::move(name),
                    phase.layout.segments * rowsPerSegment(phase.layout, chartSize(model)),
                    phase.name()),
      phase_(phase),
      model_(&model),
      nc_(chartSize(model)),
      per_segment_(rowsPerSegment(phase.layout, nc_)) {
  const PhaseLayout& l = phase_.layout;
  const TermWriter w{nc_, terms_};
  for (int k = 0; k < l.segments; ++k) {
    const double h = l.segmentFraction(k);  // per unit T: rate terms are scaled by T
    const int row = k * per_segment_;
    for (int level = 0; level < 2; ++level) {
      if (l.scheme == Scheme::kTrapezoidal) {
        w.trapezoid(row + level * nc_, level, k, k + 1, h);
        continue;
      }
      const int a = 2 * k, m = 2 * k + 1, b = 2 * k + 2;
      w.simpson(row + level * nc_, level, a, m, b, h);
      w.hermite(row + 2 * nc_ + level * nc_, level, a, m, b, h);
    }
  }
  std::stable_sort(terms_.begin(), terms_.end(),
                   [](const Term& a, const Term& b) { return a.point < b.point; });
}

template <class Fn>
void ChartDefects::forEachPoint(const Eigen::VectorXd& x, Fn fn) const {
  const Slice m = phase_.point.motion();
  for (auto first = terms_.begin(); first != terms_.end();) {
    const int p = first->point;
    const auto last =
        std::find_if(first, terms_.end(), [p](const Term& t) { return t.point != p; });
    fn(PointTerms{first, last, x.segment(phase_.layout.pointOffset(p) + m.start, m.size),
                  phase_.indices(p, m)});
    first = last;
  }
}

void ChartDefects::values(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> g) const {
  const double duration = phase_.layout.durationAt(x);
  g.setZero();
  forEachPoint(x, [&](const PointTerms& pt) {
    const Eigen::VectorXd chart = chartValue(*model_, pt.motion);
    for (auto t = pt.first; t != pt.last; ++t) g(t->row) += factor(*t, duration) * chart(t->entry);
  });
}

void ChartDefects::jacobian(const Eigen::VectorXd& x, Triplets& out) const {
  const double duration = phase_.layout.durationAt(x);
  const int duration_index = phase_.layout.duration_index;
  forEachPoint(x, [&](const PointTerms& pt) {
    const Eigen::MatrixXd jac = chartJacobian(*model_, pt.motion);
    const Eigen::VectorXd chart = chartValue(*model_, pt.motion);
    for (auto t = pt.first; t != pt.last; ++t) {
      for (size_t c = 0; c < pt.columns.size(); ++c)
        out.emplace_back(t->row, pt.columns[c],
                         factor(*t, duration) * jac(t->entry, static_cast<int>(c)));
      if (t->scaled && duration_index >= 0)
        out.emplace_back(t->row, duration_index, t->coefficient * chart(t->entry));
    }
  });
}

void ChartDefects::hessian(const Eigen::VectorXd& x, const Eigen::VectorXd& lambda,
                           Triplets& out) const {
  const double duration = phase_.layout.durationAt(x);
  const int duration_index = phase_.layout.duration_index;
  const int n = phase_.point.n;
  forEachPoint(x, [&](const PointTerms& pt) {
    const std::vector<int>& col = pt.columns;
    Eigen::VectorXd weights = Eigen::VectorXd::Zero(3 * nc_);
    for (auto t = pt.first; t != pt.last; ++t)
      weights(t->entry) += lambda(t->row) * factor(*t, duration);
    const Eigen::MatrixXd h = chartHessian(*model_, pt.motion, weights);
    // Each link's (theta, theta), (dtheta, theta), (ddtheta, theta) and (dtheta, dtheta).
    for (int j = 0; j < n; ++j)
      for (const auto& [r, c] : {std::pair{j, j}, {n + j, j}, {2 * n + j, j}, {n + j, n + j}})
        out.emplace_back(std::max(col[r], col[c]), std::min(col[r], col[c]), h(r, c));
    if (duration_index < 0) return;
    // d2/dT dy of T * coefficient * chart_entry(y)
    const Eigen::MatrixXd jac = chartJacobian(*model_, pt.motion);
    for (auto t = pt.first; t != pt.last; ++t) {
      if (!t->scaled) continue;
      for (size_t d = 0; d < col.size(); ++d)
        out.emplace_back(std::max(duration_index, col[d]), std::min(duration_index, col[d]),
                         lambda(t->row) * t->coefficient * jac(t->entry, static_cast<int>(d)));
    }
  });
}

void addReducedDsp(Nlp& nlp, const dynamics::Model& model, const Phase& phase, double step_length) {
  nlp.addConstraint(std::make_unique<ChartDefects>(phase.name() + "_chart_defects", model, phase));
  const PointLayout& l = phase.point;
  for (int p = 1; p < phase.layout.points(); ++p)
    addLink(nlp, fmt::format("{}_pin_{}", phase.name(), p), 4,
            concat(phase.indices(p, l.q), phase.indices(p, l.v)), model.nLinks(),
            PinnedTip{&model, step_length});
}

}  // namespace gaitopt::ocp
