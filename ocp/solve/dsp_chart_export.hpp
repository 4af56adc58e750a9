#pragma once
/// @file dsp_chart_export.hpp
/// The dense export of a double support collocated in reduced coordinates (dsp_chart.hpp): the
/// chart c(t) follows the scheme's polynomials through the points' chart values (exportPoint,
/// so c, cdot and cddot are derivatives of one another), and theta(t) is the pinned chain at
/// c(t). E then stays at (step_length, 0) between the points too, to rounding, where the
/// polynomials of theta itself would leave it by O(h^4).
#include "dynamics/model.hpp"
#include "ocp/transcription/collocation.hpp"
#include "ocp/transcription/phase.hpp"
#include "ocp/transcription/point_layout.hpp"

namespace gaitopt::ocp {

/// The chart's values at a phase's points, laid out as a second-order phase of its own.
struct ChartTrack {
  PhaseLayout layout;      ///< nq = chartSize, no inputs; the phase's segments, mesh, duration
  Eigen::VectorXd values;  ///< (c, cdot, cddot) of every point, in the layout's order
};

/// The chart at the points of `phase` of the solution x.
ChartTrack chartTrack(const dynamics::Model& model, const Phase& phase, const Eigen::VectorXd& x);

/// Moves theta, dtheta, ddtheta of `point` (a point of `layout`, exported at phase time t by
/// exportPoint) onto the pinned chain at the chart's value at t. A chart value the chain cannot
/// reach (the iterate of a failed solve, whose points need not keep the tip pinned) leaves the
/// scheme's own point, so that a failed solve is still exported and its drift check says how far
/// off it is.
void placeOnChart(const dynamics::Model& model, double step_length, const ChartTrack& track,
                  double t, const PointLayout& layout, Eigen::VectorXd& point);

/// The chain's theta, dtheta, ddtheta with E at (step_length, 0) and at rest and chart values
/// `chart` = (c, cdot, cddot) (3 chartSize), by Newton's method from `theta` (which holds the
/// start on entry): [J_E; J_hip; upper-body rows] dtheta = (0, cdot) and the same matrix for
/// ddtheta with the bias terms. @return false, with theta, dtheta and ddtheta as they came in,
/// when Newton does not reach the chain or the chain is near the chart's singularity (a stretched
/// leg).
bool projectOntoChart(const dynamics::Model& model, double step_length,
                      const Eigen::VectorXd& chart, VecD& theta, VecD& dtheta, VecD& ddtheta);

}  // namespace gaitopt::ocp
