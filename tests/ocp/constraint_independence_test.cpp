// The rows that hold the swing tip to the ground are linearly independent at an optimum: Ipopt's
// Newton matrix is nonsingular only when the gradients of the equalities and of the inequalities
// at their bounds are (LICQ). The clearance bound y_E >= h(s) was once imposed at the touchdown
// point too, where touchdown_position already holds y_E = 0: the same gradient twice, which made
// the robust problem's matrices singular to working precision (results/inertia_audit.md).
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "support/solved_config.hpp"

namespace gaitopt::ocp {
namespace {

/// The first row of set `name` in the NLP's constraint vector. @throws if absent.
int firstRowOf(const Nlp& nlp, const std::string& name) {
  int row = 0;
  for (const auto& set : nlp.constraintSets()) {
    if (set->name() == name) return row;
    row += set->rows();
  }
  throw std::out_of_range("no constraint set " + name);
}

const ConstraintSet& setNamed(const Nlp& nlp, const std::string& name) {
  for (const auto& set : nlp.constraintSets())
    if (set->name() == name) return *set;
  throw std::out_of_range("no constraint set " + name);
}

TEST(ConstraintIndependence, TheTipRowsAtTheDefaultOptimumHaveFullRank) {
  const test::SolvedConfig s(loadOcpConfig(test::shippedOcpConfig("mu2004_walk")));
  ASSERT_TRUE(s.result.success) << s.result.status;
  const Nlp& nlp = s.problem.nlp;
  const Eigen::VectorXd& x = s.result.x;
  const Eigen::VectorXd g = nlp.constraintValues(x), lower = nlp.constraintLower();
  Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(nlp.constraints(), nlp.variables());
  for (const auto& t : nlp.jacobianTriplets(x)) jacobian(t.row(), t.col()) += t.value();

  // touchdown_position's rows, and the clearance rows at their bound (lift-off, where h = 0).
  std::vector<int> rows;
  const int touchdown = firstRowOf(nlp, "touchdown_position");
  for (int r = 0; r < setNamed(nlp, "touchdown_position").rows(); ++r)
    rows.push_back(touchdown + r);
  const int clearance = firstRowOf(nlp, "ssp_clearance");
  int active = 0;
  for (int r = 0; r < setNamed(nlp, "ssp_clearance").rows(); ++r)
    if (g(clearance + r) - lower(clearance + r) < 1e-7) {
      rows.push_back(clearance + r);
      ++active;
    }
  ASSERT_GE(active, 1) << "the tip is on the ground at lift-off, so a clearance row is active";

  Eigen::MatrixXd stacked(static_cast<Eigen::Index>(rows.size()), nlp.variables());
  for (size_t k = 0; k < rows.size(); ++k)
    stacked.row(static_cast<Eigen::Index>(k)) = jacobian.row(rows[k]).normalized();
  const Eigen::VectorXd sigma = Eigen::JacobiSVD<Eigen::MatrixXd>(stacked).singularValues();
  // Row-normalised gradients of distinct points of the path: far from dependent, not merely
  // above rounding (the duplicated row gave exactly 0).
  EXPECT_GT(sigma.minCoeff(), 1e-3) << "active tip rows: " << rows.size();
}

}  // namespace
}  // namespace gaitopt::ocp
