// Locating violations of the gait problem for reports of failed solves: a disturbed variable or
// constraint row is found by name, phase, node and row, where the disturbance was put.
#include <gtest/gtest.h>

#include "dynamics/robot_files/robot_config.hpp"
#include "ocp/guess/initial_guess.hpp"
#include "ocp/problem/gait_problem.hpp"

namespace gaitopt::ocp {
namespace {

class RabbitViolations : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    config_ = new OcpConfig(
        loadOcpConfig(std::string(GAITOPT_SOURCE_DIR) + "/configs/ocp/rabbit_kelly2017.yaml"));
    config_->phases.front().segments = 4;
    model_ = new dynamics::Model(dynamics::loadRobot(config_->robot_path));
    problem_ =
        new GaitProblem(buildGaitProblem(*model_, *config_, polynomialGuess(*model_, *config_)));
  }
  static void TearDownTestSuite() {
    delete problem_;
    delete model_;
    delete config_;
  }
  static OcpConfig* config_;
  static dynamics::Model* model_;
  static GaitProblem* problem_;
};
OcpConfig* RabbitViolations::config_ = nullptr;
dynamics::Model* RabbitViolations::model_ = nullptr;
GaitProblem* RabbitViolations::problem_ = nullptr;

TEST_F(RabbitViolations, AVariableBeyondItsBoundIsNamedByBlockPointAndElement) {
  const PhaseLayout& l = problem_->ssp.layout;
  Eigen::VectorXd x = problem_->nlp.initialGuess();
  const int point = 5, element = 2;  // theta3 (torso) at point 5
  const int i = l.pointOffset(point) + element;
  x(i) = problem_->nlp.upperBounds()(i) + 1e4;  // beyond any violation of the guess
  const Violation v = problem_->nlp.worstBound(x);
  EXPECT_EQ(v.name, "ssp_points");
  EXPECT_EQ(v.phase, "ssp");
  EXPECT_STREQ(v.node.kind, "point");
  EXPECT_EQ(v.node.index, point);
  EXPECT_STREQ(v.part, "element");
  EXPECT_EQ(v.node.entry, element);
  EXPECT_EQ(v.index, point * l.pointSize() + element);
  EXPECT_NEAR(v.amount, 1e4, 1e-9);
  EXPECT_EQ(describe(v).rfind("ssp_points (ssp, point 5, element 2): ", 0), 0u) << describe(v);
}

TEST_F(RabbitViolations, AConstraintRowIsNamedBySetPhaseNodeAndRow) {
  const PhaseLayout& l = problem_->ssp.layout;
  Eigen::VectorXd x = problem_->nlp.initialGuess();
  // A huge stance-shank acceleration at point 6 breaks the dynamics there (D a, D ~ 1 kg m^2)
  // far more than the defects of the segments around it (h T a / 6 ~ 0.03 a).
  x(l.xdot(6, l.nq)) += 1e6;
  const Violation v = problem_->nlp.worstConstraint(x);
  EXPECT_EQ(v.name, "ssp_dynamics");
  EXPECT_EQ(v.phase, "ssp");
  EXPECT_STREQ(v.node.kind, "point");
  EXPECT_EQ(v.node.index, 6);
  EXPECT_STREQ(v.part, "row");
  EXPECT_EQ(v.index, 6 * model_->nLinks() + v.node.entry);  // n dynamics rows per point
  EXPECT_GT(v.amount, 1e5);
}

TEST_F(RabbitViolations, ADefectIsNamedBySegment) {
  const PhaseLayout& l = problem_->ssp.layout;
  Eigen::VectorXd x = problem_->nlp.initialGuess();
  // Moving the angle of link 1 by 1e3 rad at the midpoint of segment 2 (point 5) moves the
  // Hermite defect of that segment by as much; the dynamics see it through sines and cosines
  // only.
  x(l.x(5, 0)) += 1e3;
  const Violation v = problem_->nlp.worstConstraint(x);
  EXPECT_EQ(v.name, "ssp_defects");
  EXPECT_EQ(v.phase, "ssp");
  EXPECT_STREQ(v.node.kind, "segment");
  EXPECT_EQ(v.node.index, 2);
  EXPECT_EQ(v.node.entry, l.nx);  // the Hermite row of theta1: after the nx Simpson rows
}

TEST_F(RabbitViolations, AnImpactVariableIsNamedByItsElementOffTheGrid) {
  ASSERT_TRUE(problem_->touchdown.impact().has_value());  // RABBIT: a rigid single impact
  const ImpactLayout& impact = *problem_->touchdown.impact();
  Eigen::VectorXd x = problem_->nlp.initialGuess();
  // trailing_lifts: the old stance tip's vertical velocity after the strike is >= 0.
  const int i = impact.inDecision(impact.base_velocity)[1];
  x(i) = -1e4;
  const Violation v = problem_->nlp.worstBound(x);
  EXPECT_EQ(v.name, "impact");
  EXPECT_EQ(v.phase, kLinkPhase);
  EXPECT_STREQ(v.node.kind, "");
  EXPECT_EQ(v.node.index, -1);
  EXPECT_EQ(v.index, impact.base_velocity[1]);
  EXPECT_NEAR(v.amount, 1e4, 1e-9);
  EXPECT_EQ(describe(v).rfind("impact (link, element 1): ", 0), 0u) << describe(v);
}

}  // namespace
}  // namespace gaitopt::ocp
