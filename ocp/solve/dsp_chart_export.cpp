#include "ocp/solve/dsp_chart_export.hpp"

#include <Eigen/LU>

#include "ocp/problem/dsp_chart.hpp"
#include "ocp/transcription/collocation_interpolation.hpp"

namespace gaitopt::ocp {
namespace {

/// Newton stops when E and the chart are met to this [m, rad].
constexpr double kTolerance = 1e-13;
constexpr int kMaxIterations = 30;
/// Below this reciprocal condition number of the rows the chart is near its singularity (a leg
/// stretched straight, where the hip's distance to its tip has a maximum), and the rates and
/// accelerations solved from it amplify the solver's tolerance by its inverse: the point keeps
/// its collocated values. The shipped optima stay above 5e-3.
constexpr double kMinConditioning = 1e-6;

/// Rows: E's position (2), the hip's (2), the upper-body angles; as chartValue and PinnedTip.
MatD constraintJacobian(const dynamics::Model& model, const VecD& theta, int nc) {
  const int n = model.nLinks();
  MatD a = MatD::Zero(n, n);
  a.topRows(2) = dynamics::pointJacobian<double>(model.tipWeights(), theta);
  a.middleRows(2, 2) = dynamics::pointJacobian<double>(model.hipWeights(), theta);
  for (int i = 0; i < nc - 2; ++i) a(4 + i, model.legLinks() + i) = 1.0;
  return a;
}

Eigen::VectorXd constraintValue(const dynamics::Model& model, double step_length, const VecD& theta,
                                const Eigen::VectorXd& c) {
  const int nc = static_cast<int>(c.size());
  Eigen::VectorXd f(model.nLinks());
  f.head(2) = dynamics::swingTip<double>(model, theta) - Vec2d(step_length, 0.0);
  f.segment(2, 2) = dynamics::pointPosition<double>(model.hipWeights(), theta) - c.head(2);
  for (int i = 0; i < nc - 2; ++i) f(4 + i) = theta(model.legLinks() + i) - c(2 + i);
  return f;
}

}  // namespace

ChartTrack chartTrack(const dynamics::Model& model, const Phase& phase, const Eigen::VectorXd& x) {
  const int nc = chartSize(model);
  const PhaseLayout& l = phase.layout;
  ChartTrack track;
  track.layout = PhaseLayout{.scheme = l.scheme,
                             .segments = l.segments,
                             .duration = l.durationAt(x),
                             .nx = 2 * nc,
                             .nu = 0,
                             .nz = 0,
                             .nq = nc,
                             .mesh = l.mesh};
  track.values.resize(track.layout.variables());
  const Slice motion = phase.point.motion();
  for (int p = 0; p < l.points(); ++p)
    track.values.segment(track.layout.pointOffset(p), 3 * nc) =
        chartValue(model, motion.of(l.point(x, p)));
  return track;
}

void placeOnChart(const dynamics::Model& model, double step_length, const ChartTrack& track,
                  double t, const PointLayout& layout, Eigen::VectorXd& point) {
  VecD theta = layout.q.of(point), dtheta, ddtheta;
  if (!projectOntoChart(model, step_length, exportPoint(track.layout, track.values, t), theta,
                        dtheta, ddtheta))
    return;
  layout.q.of(point) = theta;
  layout.v.of(point) = dtheta;
  layout.a.of(point) = ddtheta;
}

bool projectOntoChart(const dynamics::Model& model, double step_length,
                      const Eigen::VectorXd& chart, VecD& theta, VecD& dtheta, VecD& ddtheta) {
  const int nc = chartSize(model);
  const Eigen::VectorXd c = chart.head(nc), cdot = chart.segment(nc, nc), cddot = chart.tail(nc);
  const VecD start = theta;
  for (int it = 0;; ++it) {
    const Eigen::VectorXd f = constraintValue(model, step_length, theta, c);
    if (f.cwiseAbs().maxCoeff() < kTolerance) break;
    if (it == kMaxIterations || !f.allFinite()) {
      theta = start;
      return false;
    }
    theta -= constraintJacobian(model, theta, nc).partialPivLu().solve(f);
  }
  const auto lu = constraintJacobian(model, theta, nc).partialPivLu();
  if (!(lu.rcond() >= kMinConditioning)) {
    theta = start;
    return false;
  }
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(model.nLinks());
  rhs.tail(nc) = cdot;
  dtheta = lu.solve(rhs);
  // Second derivative of the same rows: A ddtheta + (Adot dtheta) = (0, cddot).
  rhs.tail(nc) = cddot;
  rhs.head(2) -= dynamics::pointBias<double>(model.tipWeights(), theta, dtheta);
  rhs.segment(2, 2) -= dynamics::pointBias<double>(model.hipWeights(), theta, dtheta);
  ddtheta = lu.solve(rhs);
  return true;
}

}  // namespace gaitopt::ocp
