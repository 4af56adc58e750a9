/// @file dynamics_bench.cpp
/// Micro-benchmarks of the dynamics kernels on the five-link robot of Mu (2004), at one fixed,
/// non-trivial state. The robot is loaded once, before any benchmark runs.
#include <cstdio>
#include <exception>
#include <string>
#include <utility>

#include <benchmark/benchmark.h>

#include "dynamics/dsp_dynamics.hpp"
#include "dynamics/impact/impact.hpp"
#include "dynamics/model.hpp"
#include "dynamics/residual_derivatives.hpp"
#include "dynamics/robot_files/robot_config.hpp"
#include "dynamics/ssp_dynamics.hpp"

namespace {

using namespace gaitopt;
using namespace gaitopt::dynamics;

/// The robot and the state every benchmark evaluates at.
struct Fixture {
  Model model;
  DynamicsPoint x;

  explicit Fixture(Model m) : model(std::move(m)) {
    x.theta.resize(5);
    x.theta << 0.3, 0.1, -0.05, 3.0, 2.7;
    x.dtheta.resize(5);
    x.dtheta << 0.5, -1.0, 0.2, 1.5, -2.0;
    x.ddtheta.resize(5);
    x.ddtheta << 1, 2, -1, 0.5, 3;
    x.tau.resize(5);
    x.tau << 5, -10, 20, 3, -4;
    x.lambda << 30, 150;
  }
};

/// The shared fixture; the first call (from main) loads the robot file.
const Fixture& fixture() {
  static const Fixture f(
      loadRobot(std::string(GAITOPT_SOURCE_DIR) + "/configs/robots/mu2004_five_link.yaml"));
  return f;
}

/// Times fn(model, x). The state is a local passed through DoNotOptimize on every iteration, so
/// the compiler can neither constant-fold the call nor hoist it out of the loop.
template <class Fn>
void timeAtState(benchmark::State& state, Fn fn) {
  const Fixture& f = fixture();
  DynamicsPoint x = f.x;
  for (auto _ : state) {
    benchmark::DoNotOptimize(x);
    benchmark::DoNotOptimize(fn(f.model, x));
  }
}

template <class Fn>
void add(const char* name, Fn fn) {
  benchmark::RegisterBenchmark(name, [fn](benchmark::State& s) { timeAtState(s, fn); });
}

void registerAll() {
  using X = const DynamicsPoint&;
  using M = const Model&;
  const Eigen::VectorXd ones_ssp = Eigen::VectorXd::Ones(5);
  const Eigen::VectorXd ones_dsp = Eigen::VectorXd::Ones(7);
  add("BM_MassMatrix", [](M m, X x) { return massMatrix<double>(m, x.theta); });
  add("BM_Coriolis", [](M m, X x) { return coriolis<double>(m, x.theta, x.dtheta); });
  add("BM_Gravity", [](M m, X x) { return gravityVector<double>(m, x.theta); });
  add("BM_SspForwardDynamics",
      [](M m, X x) { return sspForwardDynamics(m, x.theta, x.dtheta, x.tau); });
  add("BM_DspForwardDynamics",
      [](M m, X x) { return dspForwardDynamics(m, x.theta, x.dtheta, x.tau); });
  add("BM_SspResidual", [](M m, X x) { return residual(m, x, false); });
  add("BM_DspResidual", [](M m, X x) { return residual(m, x, true); });
  add("BM_SspResidualJacobian", [](M m, X x) { return residualJacobian(m, x, false); });
  add("BM_DspResidualJacobian", [](M m, X x) { return residualJacobian(m, x, true); });
  add("BM_SspResidualHessian",
      [ones_ssp](M m, X x) { return residualHessian(m, x, false, ones_ssp); });
  add("BM_DspResidualHessian",
      [ones_dsp](M m, X x) { return residualHessian(m, x, true, ones_dsp); });
  add("BM_DoubleImpact", [](M m, X x) { return doubleImpact(m, x.theta, x.dtheta); });
  add("BM_SingleImpact", [](M m, X x) { return singleImpact(m, x.theta, x.dtheta); });
  add("BM_ReducedDspModel", [](M m, X x) { return reducedDspModel(m, x.theta, x.dtheta); });
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (fixture().model.nLinks() != 5) {
      std::fprintf(stderr, "dynamics_bench: expected a five-link robot\n");
      return 1;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "dynamics_bench: cannot load the robot: %s\n", e.what());
    return 1;
  }
  registerAll();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
