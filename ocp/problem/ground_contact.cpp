#include "ocp/problem/ground_contact.hpp"

#include "dynamics/ground.hpp"
#include "dynamics/point_acceleration_derivatives.hpp"

namespace gaitopt::ocp {
namespace {

using Row = Eigen::Matrix<double, 1, 5>;  // coefficients of (F_Bx, F_By, F_Ex, F_Ey, tau0)

}  // namespace

GroundContact::GroundContact(const dynamics::Model& model, const PointLayout& point,
                             const std::optional<dynamics::Foot>& zmp_foot, double step_length,
                             double mu, double min_normal)
    : model_(&model), point_(point) {
  const bool dsp = point.hasContactForce();
  std::vector<Row> rows{Row(0, 1, 0, 0, 0), Row(-1, mu, 0, 0, 0), Row(1, mu, 0, 0, 0)};
  if (dsp) {
    rows.push_back(Row(0, 0, 0, 1, 0));
    rows.push_back(Row(0, 0, -1, mu, 0));
    rows.push_back(Row(0, 0, 1, mu, 0));
  }
  if (zmp_foot) {
    const double heel = zmp_foot->heel;
    const double hi = (dsp ? step_length : 0.0) + zmp_foot->toe;
    // dynamics/centre_of_pressure.hpp in moment form, linear in (F, tau0):
    // M = step_length F_Ey - tau0; M + heel Fy >= 0 and hi Fy - M >= 0.
    rows.push_back(Row(0, heel, 0, step_length + heel, -1));
    rows.push_back(Row(0, hi, 0, hi - step_length, 1));
    // In the DSP only foot B carries the ankle torque: its own CoP x_B = -tau0 / F_By also
    // stays on it, -heel F_By <= -tau0 <= toe F_By (the hull alone allows far more tau0).
    if (dsp) {
      rows.push_back(Row(0, heel, 0, 0, -1));
      rows.push_back(Row(0, zmp_foot->toe, 0, 0, 1));
    }
  }
  rows_.resize(static_cast<Eigen::Index>(rows.size()), 5);
  for (size_t r = 0; r < rows.size(); ++r) rows_.row(static_cast<Eigen::Index>(r)) = rows[r];
  lower_ = Eigen::VectorXd::Zero(rows_.rows());
  lower_(0) = min_normal;           // F_By
  if (dsp) lower_(3) = min_normal;  // F_Ey
}

Eigen::Matrix<double, 5, 1> GroundContact::contactQuantities(const Eigen::VectorXd& v) const {
  const PointLayout& l = point_;
  const Vec2d f_e = l.hasContactForce() ? Vec2d(l.lambda.of(v)) : Vec2d::Zero();
  const Vec2d f_b = dynamics::stanceForce<double>(*model_, l.q.of(v), l.v.of(v), l.a.of(v), f_e);
  Eigen::Matrix<double, 5, 1> s;
  s << f_b, f_e, v(l.u[0]);
  return s;
}

void GroundContact::evaluate(const Eigen::VectorXd& v, Eigen::Ref<Eigen::VectorXd> f) const {
  f = rows_ * contactQuantities(v);
}

void GroundContact::jacobian(const Eigen::VectorXd& v, Eigen::Ref<Eigen::MatrixXd> jac) const {
  const PointLayout& l = point_;
  // ds/dv: F_B through m a_com(theta, dtheta, ddtheta) and -F_E; F_E and tau0 directly. The
  // acceleration's Jacobian spans the motion (q, v, a).
  Eigen::MatrixXd ds = Eigen::MatrixXd::Zero(5, v.size());
  ds.block(0, l.motion().start, 2, l.motion().size) =
      model_->totalMass() * dynamics::pointAccelerationJacobian(model_->totalComWeights(),
                                                                l.q.of(v), l.v.of(v), l.a.of(v));
  if (l.hasContactForce()) {
    ds.block(0, l.lambda.start, 2, 2) = -Eigen::Matrix2d::Identity();
    ds.block(2, l.lambda.start, 2, 2) = Eigen::Matrix2d::Identity();
  }
  ds(4, l.u[0]) = 1;
  jac = rows_ * ds;
}

void GroundContact::hessian(const Eigen::VectorXd& v, const Eigen::VectorXd& w,
                            Eigen::Ref<Eigen::MatrixXd> hess) const {
  const PointLayout& l = point_;
  hess.setZero();
  // Only F_B is nonlinear: weight of a_com = m * (rows^T w) restricted to F_B.
  const Eigen::Vector2d c = model_->totalMass() * (rows_.transpose() * w).head<2>();
  const Slice m = l.motion();
  hess.block(m.start, m.start, m.size, m.size) = dynamics::pointAccelerationHessian(
      model_->totalComWeights(), l.q.of(v), l.v.of(v), l.a.of(v), c);
}

}  // namespace gaitopt::ocp
