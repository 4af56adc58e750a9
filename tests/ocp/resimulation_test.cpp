// The independent accuracy measure of a collocated gait (ocp/solve/resimulation.hpp) on RABBIT
// (configs/ocp/rabbit_kelly2017.yaml): the optimal torques re-simulated by RKF 7(8) must
// reproduce the solution's strike state with the error order of each scheme (Betts 2010,
// sec. 4.5; Kelly 2017, sec. 4): Hermite-Simpson globally O(h^4) and per segment O(h^5),
// trapezoidal far less accurate on the same mesh. bench/ocp_study measures the full curves.
#include <gtest/gtest.h>

#include <cmath>

#include <fmt/format.h>

#include "dynamics/robot_files/robot_config.hpp"
#include "ocp/guess/initial_guess.hpp"
#include "ocp/problem/gait_problem.hpp"
#include "ocp/solve/ipopt_adapter.hpp"
#include "ocp/solve/resimulation.hpp"

namespace gaitopt::ocp {
namespace {

struct ResimulatedSolve {
  GaitProblem problem;
  Eigen::VectorXd x;
};

class RabbitResimulation : public ::testing::Test {
 protected:
  void SetUp() override {
#ifndef NDEBUG
    GTEST_SKIP() << "three solves and re-simulations: optimised builds only";
#endif
  }
  static void SetUpTestSuite() {
    config_ = new OcpConfig(
        loadOcpConfig(std::string(GAITOPT_SOURCE_DIR) + "/configs/ocp/rabbit_kelly2017.yaml"));
    config_->solver.tolerance = 1e-9;  // solver error far below the discretisation error
    model_ = new dynamics::Model(dynamics::loadRobot(config_->robot_path));
    guess_ = new gaits::Trajectory(polynomialGuess(*model_, *config_));
  }
  static void TearDownTestSuite() {
    delete guess_;
    delete model_;
    delete config_;
  }
  static ResimulatedSolve solve(Scheme scheme, int segments) {
    OcpConfig c = *config_;
    c.scheme = scheme;
    c.phases.front().segments = segments;
    GaitProblem p = buildGaitProblem(*model_, c, *guess_);
    const SolveResult r = solveWithIpopt(p.nlp, c.solver);
    EXPECT_EQ(r.status, "Solve_Succeeded") << toString(scheme) << " " << segments;
    return {std::move(p), r.x};
  }
  static OcpConfig* config_;
  static dynamics::Model* model_;
  static gaits::Trajectory* guess_;
};
OcpConfig* RabbitResimulation::config_ = nullptr;
dynamics::Model* RabbitResimulation::model_ = nullptr;
gaits::Trajectory* RabbitResimulation::guess_ = nullptr;

TEST_F(RabbitResimulation, ErrorsFallWithTheSchemesOrder) {
  const ResimulatedSolve coarse = solve(Scheme::kHermiteSimpson, 8);
  const ResimulatedSolve fine = solve(Scheme::kHermiteSimpson, 16);
  const ResimulatedSolve trapezoidal = solve(Scheme::kTrapezoidal, 16);
  const StateError end8 = sspEndStateError(coarse.problem, *model_, coarse.x);
  const StateError end16 = sspEndStateError(fine.problem, *model_, fine.x);
  const StateError trap16 = sspEndStateError(trapezoidal.problem, *model_, trapezoidal.x);
  const StateError seg8 = sspSegmentError(coarse.problem, *model_, coarse.x);
  const StateError seg16 = sspSegmentError(fine.problem, *model_, fine.x);
  const double end_order = std::log2(end8.angle / end16.angle);
  const double rate_order = std::log2(end8.rate / end16.rate);
  const double segment_order = std::log2(seg8.angle / seg16.angle);
  RecordProperty("hs_end_angle_error_8_16_rad",
                 fmt::format("{:.2e} {:.2e}", end8.angle, end16.angle));
  RecordProperty("trapezoidal_end_angle_error_16_rad", fmt::format("{:.2e}", trap16.angle));
  RecordProperty("hs_end_order", fmt::format("{:.2f}", end_order));
  RecordProperty("hs_end_rate_order", fmt::format("{:.2f}", rate_order));
  RecordProperty("hs_segment_order", fmt::format("{:.2f}", segment_order));
  // Measured: end 7.9e-2 -> 5.7e-3 rad (order 3.8; rates 0.68 -> 0.051 rad/s, 3.7), segments
  // 1.7e-4 -> 6.9e-6 rad (4.6), trapezoidal 0.12 rad at 16 segments. A scheme of order 2, or
  // torques read with the wrong interpolation (piecewise constant: order 1), fails the first two.
  EXPECT_GE(end_order, 3.0);
  EXPECT_GE(segment_order, 4.0);
  EXPECT_GE(rate_order, 3.0);
  EXPECT_GT(trap16.angle, 5 * end16.angle);
}

TEST_F(RabbitResimulation, MeasuresAgainstTheSolutionsStrikeState) {
  // Moving the solution's last SSP angles by 0.05 rad (the re-simulation starts from the first
  // point and uses the torques only) must show up as an end error of about 0.05 rad.
  ResimulatedSolve s = solve(Scheme::kHermiteSimpson, 16);
  const double before = sspEndStateError(s.problem, *model_, s.x).angle;
  const PhaseLayout& l = s.problem.ssp.layout;
  const int last = l.points() - 1;
  for (int i = 0; i < model_->nLinks(); ++i) s.x(l.x(last, i)) += 0.05;
  const double after = sspEndStateError(s.problem, *model_, s.x).angle;
  EXPECT_LT(before, 0.01);
  EXPECT_NEAR(after, 0.05, before + 1e-9);
}

}  // namespace
}  // namespace gaitopt::ocp
