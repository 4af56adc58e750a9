#include "ocp/problem/interior_contact.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "ocp/transcription/collocation_interpolation.hpp"

namespace gaitopt::ocp {

namespace {

/// The interior ends of `sub_intervals` equal sub-intervals but the midpoint.
std::vector<double> sampleTimes(int sub_intervals) {
  if (sub_intervals < 4 || sub_intervals % 2 != 0)
    throw std::invalid_argument("constraints.interior_contact: expected an even number >= 4");
  std::vector<double> s;
  for (int i = 1; i < sub_intervals; ++i)
    if (2 * i != sub_intervals) s.push_back(static_cast<double>(i) / sub_intervals);
  return s;
}

int rowCount(const Phase& phase, const GroundContact& contact, int sub_intervals) {
  if (phase.doubleSupport())
    throw std::invalid_argument("interior contact rows: single support only");
  if (phase.layout.scheme != Scheme::kHermiteSimpson || phase.layout.freeDuration())
    throw std::invalid_argument(
        "constraints.interior_contact: needs hermite_simpson and fixed phase durations");
  return phase.layout.segments * static_cast<int>(sampleTimes(sub_intervals).size()) *
         contact.rows();
}

}  // namespace

InteriorContact::InteriorContact(std::string name, const Phase& phase,
                                 std::shared_ptr<const GroundContact> contact, int sub_intervals)
    : ConstraintSet(std::move(name), rowCount(phase, *contact, sub_intervals), phase.name()),
      phase_(phase),
      contact_(std::move(contact)),
      samples_(sampleTimes(sub_intervals)) {}

std::vector<int> InteriorContact::localVariables(int k) const {
  const PhaseLayout& l = phase_.layout;
  const PointLayout& p = phase_.point;
  std::vector<int> local = p.q.indices(l.pointOffset(2 * k));
  for (int i : p.v.indices(l.pointOffset(2 * k))) local.push_back(i);
  for (int j = 0; j < 3; ++j)
    for (int i : p.a.indices(l.pointOffset(2 * k + j))) local.push_back(i);
  for (int j = 0; j < 3; ++j) local.push_back(l.pointOffset(2 * k + j) + p.u[0]);
  return local;
}

Eigen::MatrixXd InteriorContact::sampleMap(int k, double s) const {
  const PointLayout& p = phase_.point;
  const int n = p.n;
  const double h = phase_.layout.duration * phase_.layout.segmentFraction(k);
  const SegmentBasis b = lagrangeBasis(Scheme::kHermiteSimpson, s);
  const SegmentBasis c = lagrangeBasisIntegral(Scheme::kHermiteSimpson, s);
  const SegmentBasis d = lagrangeDoubleIntegral(Scheme::kHermiteSimpson, s);
  Eigen::MatrixXd map = Eigen::MatrixXd::Zero(p.size(), 5 * n + 3);
  for (int i = 0; i < n; ++i) {
    map(p.q[i], i) = 1;
    map(p.q[i], n + i) = h * s;
    map(p.v[i], n + i) = 1;
    for (size_t j = 0; j < 3; ++j) {
      const int a = (2 + static_cast<int>(j)) * n + i;
      map(p.q[i], a) = h * h * d[j];
      map(p.v[i], a) = h * c[j];
      map(p.a[i], a) = b[j];
    }
  }
  for (size_t j = 0; j < 3; ++j) map(p.u[0], 5 * n + static_cast<int>(j)) = b[j];
  return map;
}

Eigen::VectorXd InteriorContact::lowerBounds() const {
  return contact_->lowerBounds().replicate(rows() / contact_->rows(), 1);
}

Eigen::VectorXd InteriorContact::upperBounds() const {
  return contact_->upperBounds().replicate(rows() / contact_->rows(), 1);
}

void InteriorContact::values(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> g) const {
  const int m = contact_->rows();
  int row = 0;
  for (int k = 0; k < phase_.layout.segments; ++k) {
    const Eigen::VectorXd local = gather(x, localVariables(k));
    for (double s : samples_) {
      contact_->evaluate(sampleMap(k, s) * local, g.segment(row, m));
      row += m;
    }
  }
}

// Every row against every variable the sample reads: the rows' dense pattern (F_B spans the
// motion, the ZMP rows tau_0), zeros included.
void InteriorContact::jacobian(const Eigen::VectorXd& x, Triplets& out) const {
  const int m = contact_->rows();
  Eigen::MatrixXd jac(m, phase_.point.size());
  int row = 0;
  for (int k = 0; k < phase_.layout.segments; ++k) {
    const std::vector<int> vars = localVariables(k);
    const Eigen::VectorXd local = gather(x, vars);
    for (double s : samples_) {
      const Eigen::MatrixXd map = sampleMap(k, s);
      contact_->jacobian(map * local, jac);
      const Eigen::MatrixXd chained = jac * map;
      for (int r = 0; r < m; ++r)
        for (size_t c = 0; c < vars.size(); ++c)
          out.emplace_back(row + r, vars[c], chained(r, static_cast<Eigen::Index>(c)));
      row += m;
    }
  }
}

// map^T H map on the motion variables (the rows are linear in tau_0): the lower triangle of the
// 5 n x 5 n block, zeros included.
void InteriorContact::hessian(const Eigen::VectorXd& x, const Eigen::VectorXd& lambda,
                              Triplets& out) const {
  const int m = contact_->rows(), motion = 5 * phase_.point.n;
  Eigen::MatrixXd hess(phase_.point.size(), phase_.point.size());
  int row = 0;
  for (int k = 0; k < phase_.layout.segments; ++k) {
    const std::vector<int> vars = localVariables(k);
    const Eigen::VectorXd local = gather(x, vars);
    Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(motion, motion);
    for (double s : samples_) {
      const Eigen::MatrixXd map = sampleMap(k, s);
      contact_->hessian(map * local, lambda.segment(row, m), hess);
      sum += map.leftCols(motion).transpose() * hess * map.leftCols(motion);
      row += m;
    }
    for (int c = 0; c < motion; ++c)
      for (int r = c; r < motion; ++r)
        out.emplace_back(std::max(vars[r], vars[c]), std::min(vars[r], vars[c]), sum(r, c));
  }
}

}  // namespace gaitopt::ocp
