#pragma once
/// @file dsp_chart.hpp
/// The double support in Mu's reduced coordinates (2.19-2.21), config
/// constraints.dsp_reduced_coordinates. With both tips on the ground a chain with kneed legs has
/// n - 2 degrees of freedom, and c = (hip x, hip y, the angles of the links between the legs) is
/// a chart of them: each leg's two angles follow from its hip and tip (3.24). The phase keeps
/// theta, dtheta, ddtheta at its points, for every other constraint and the cost, but
///  - collocates c instead of theta: the Hermite-Simpson (or trapezoidal) defects of
///    collocation.hpp on (c, cdot) with the rates (cdot, cddot), all functions of the point's
///    (theta, dtheta, ddtheta) (chartValue);
///  - holds E at (step_length, 0) and at rest at every point after the first (PinnedTip; the
///    first is the touchdown's), with E's acceleration zero at every point (BipedDynamics).
/// Per point theta then has n - 2 free entries, and the chart's defects hold them: the rows
/// count as before (per Hermite-Simpson segment 20 defect rows of theta out; 12 of c and 8 pin
/// rows in) and E lies on the ground at every point to the solver's tolerance. The position
/// pin without the chart (pin rows on top of theta's defects) was over-determined: to keep it,
/// the knots' accelerations had to leave the pinned motion (E accelerating by 12 m/s^2, 11 N m
/// in the torques); Posa-Kuindersma-Tedrake's projection terms moved the export's accelerations
/// by 11 rad/s^2 between the points.
#include "dynamics/floating_base.hpp"  // VecX: more entries than links
#include "dynamics/kinematics.hpp"
#include "ocp/transcription/nlp.hpp"
#include "ocp/transcription/phase.hpp"

namespace gaitopt::ocp {

/// Chart coordinates of the double support: hip x, hip y, then one per link between the legs.
/// @throws std::invalid_argument unless the legs have two links each (the chart needs knees).
int chartSize(const dynamics::Model& model);

/// The chart of a DSP point y = (theta, dtheta, ddtheta) (3 n): (c, cdot, cddot) (3 chartSize)
/// [m, rad and their rates]. The hip is sum_j w_j u_j(theta_j) (Mu 2.13), so every entry
/// depends on one link's angle, rate and acceleration: its derivatives are written out (they
/// were most of the double support's callback time under autodiff). Affine in ddtheta.
Eigen::VectorXd chartValue(const dynamics::Model& model, const Eigen::VectorXd& y);
/// d chart / dy, 3 chartSize x 3 n.
Eigen::MatrixXd chartJacobian(const dynamics::Model& model, const Eigen::VectorXd& y);
/// sum_r weights_r d2 chart_r / dy2, 3 n x 3 n, symmetric; nonzero only in each link's
/// (theta, theta), (theta, dtheta), (theta, ddtheta) and (dtheta, dtheta) entries.
Eigen::MatrixXd chartHessian(const dynamics::Model& model, const Eigen::VectorXd& y,
                             const Eigen::VectorXd& weights);

/// y = (theta (n), dtheta (n)) of a DSP point: E at (step_length, 0) and at rest, Mu (2.9) and
/// its time derivative, 4 rows [m, m/s]. Affine in dtheta.
struct PinnedTip {
  const dynamics::Model* model;
  double step_length;
  template <class S>
  dynamics::VecX<S> operator()(const dynamics::VecX<S>& y) const {
    const int n = model->nLinks();
    const Vec<S> theta = y.head(n), dtheta = y.tail(n);
    dynamics::VecX<S> g(4);
    g.head(2) = dynamics::swingTip<S>(*model, theta);
    g(0) -= step_length;
    g.tail(2) = dynamics::pointVelocity<S>(model->tipWeights(), theta, dtheta);
    return g;
  }
};

/// The collocation defects of the chart (c, cdot) with rates (cdot, cddot), in place of
/// CollocationDefects on (theta, dtheta): per segment 2 nc rows (trapezoidal) or 4 nc
/// (Hermite-Simpson: Simpson's rows, then Hermite's), each a weighted sum of the chart at the
/// segment's points.
class ChartDefects : public ConstraintSet {
 public:
  /// One term of a row: coefficient * (T if scaled) * entry `entry` of the chart at `point`.
  struct Term {
    int row, point, entry;
    double coefficient;
    bool scaled;  ///< a rate term, proportional to the phase duration
  };
  ChartDefects(std::string name, const dynamics::Model& model, const Phase& phase);
  void values(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> g) const override;
  void jacobian(const Eigen::VectorXd& x, Triplets& out) const override;
  void hessian(const Eigen::VectorXd& x, const Eigen::VectorXd& lambda,
               Triplets& out) const override;
  GridNode nodeOf(int row) const override {
    return {"segment", row / per_segment_, row % per_segment_};
  }

 private:
  /// The terms of one point, its (theta, dtheta, ddtheta) at x and their columns in x.
  struct PointTerms {
    std::vector<Term>::const_iterator first, last;
    Eigen::VectorXd motion;
    std::vector<int> columns;
  };
  /// Calls fn(const PointTerms&) for each point the terms touch, in order.
  template <class Fn>
  void forEachPoint(const Eigen::VectorXd& x, Fn fn) const;
  /// The terms' factor at x: coefficient, times T for a rate term.
  double factor(const Term& t, double duration) const {
    return t.coefficient * (t.scaled ? duration : 1.0);
  }

  Phase phase_;
  const dynamics::Model* model_;
  int nc_;
  int per_segment_;
  std::vector<Term> terms_;  ///< sorted by point
};

/// The DSP of `phase` in reduced coordinates: ChartDefects and a PinnedTip at every point after
/// the first (the DSP's dynamics, with E's acceleration rows, come from BipedDynamics).
void addReducedDsp(Nlp& nlp, const dynamics::Model& model, const Phase& phase, double step_length);

}  // namespace gaitopt::ocp
