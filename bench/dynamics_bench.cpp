/// @file dynamics_bench.cpp
/// Micro-benchmarks of the dynamics kernels on the five-link robot of Mu (2004), at one fixed,
/// non-trivial state. The robot is loaded once, before any benchmark runs.
#include <cstdio>
#include <exception>
#include <string>
#include <utility>

#include <benchmark/benchmark.h>

#include "dynamics/dsp_dynamics.hpp"
#include "dynamics/impact.hpp"
#include "dynamics/model.hpp"
#include "dynamics/residual_derivatives.hpp"
#include "dynamics/robot_config.hpp"
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

// Every loop copies its inputs into locals and passes them through DoNotOptimize on each
// iteration, so the compiler can neither constant-fold the call nor hoist it out of the loop.

void BM_MassMatrix(benchmark::State& state) {
  const Fixture& f = fixture();
  VecD theta = f.x.theta;
  for (auto _ : state) {
    benchmark::DoNotOptimize(theta);
    benchmark::DoNotOptimize(massMatrix<double>(f.model, theta));
  }
}
BENCHMARK(BM_MassMatrix);

void BM_Coriolis(benchmark::State& state) {
  const Fixture& f = fixture();
  VecD theta = f.x.theta, dtheta = f.x.dtheta;
  for (auto _ : state) {
    benchmark::DoNotOptimize(theta);
    benchmark::DoNotOptimize(dtheta);
    benchmark::DoNotOptimize(coriolis<double>(f.model, theta, dtheta));
  }
}
BENCHMARK(BM_Coriolis);

void BM_Gravity(benchmark::State& state) {
  const Fixture& f = fixture();
  VecD theta = f.x.theta;
  for (auto _ : state) {
    benchmark::DoNotOptimize(theta);
    benchmark::DoNotOptimize(gravityVector<double>(f.model, theta));
  }
}
BENCHMARK(BM_Gravity);

void BM_SspForwardDynamics(benchmark::State& state) {
  const Fixture& f = fixture();
  VecD theta = f.x.theta, dtheta = f.x.dtheta, tau = f.x.tau;
  for (auto _ : state) {
    benchmark::DoNotOptimize(theta);
    benchmark::DoNotOptimize(dtheta);
    benchmark::DoNotOptimize(tau);
    benchmark::DoNotOptimize(sspForwardDynamics(f.model, theta, dtheta, tau));
  }
}
BENCHMARK(BM_SspForwardDynamics);

void BM_DspForwardDynamics(benchmark::State& state) {
  const Fixture& f = fixture();
  VecD theta = f.x.theta, dtheta = f.x.dtheta, tau = f.x.tau;
  for (auto _ : state) {
    benchmark::DoNotOptimize(theta);
    benchmark::DoNotOptimize(dtheta);
    benchmark::DoNotOptimize(tau);
    benchmark::DoNotOptimize(dspForwardDynamics(f.model, theta, dtheta, tau));
  }
}
BENCHMARK(BM_DspForwardDynamics);

void BM_Residual(benchmark::State& state, bool dsp) {
  const Fixture& f = fixture();
  DynamicsPoint x = f.x;
  for (auto _ : state) {
    benchmark::DoNotOptimize(x);
    benchmark::DoNotOptimize(residual(f.model, x, dsp));
  }
}
BENCHMARK_CAPTURE(BM_Residual, ssp, false)->Name("BM_SspResidual");
BENCHMARK_CAPTURE(BM_Residual, dsp, true)->Name("BM_DspResidual");

void BM_ResidualJacobian(benchmark::State& state, bool dsp) {
  const Fixture& f = fixture();
  DynamicsPoint x = f.x;
  for (auto _ : state) {
    benchmark::DoNotOptimize(x);
    benchmark::DoNotOptimize(residualJacobian(f.model, x, dsp));
  }
}
BENCHMARK_CAPTURE(BM_ResidualJacobian, ssp, false)->Name("BM_SspResidualJacobian");
BENCHMARK_CAPTURE(BM_ResidualJacobian, dsp, true)->Name("BM_DspResidualJacobian");

void BM_ResidualHessian(benchmark::State& state, bool dsp) {
  const Fixture& f = fixture();
  DynamicsPoint x = f.x;
  const Eigen::VectorXd sigma = Eigen::VectorXd::Ones(residualRows(f.model, dsp));
  for (auto _ : state) {
    benchmark::DoNotOptimize(x);
    benchmark::DoNotOptimize(residualHessian(f.model, x, dsp, sigma));
  }
}
BENCHMARK_CAPTURE(BM_ResidualHessian, ssp, false)->Name("BM_SspResidualHessian");
BENCHMARK_CAPTURE(BM_ResidualHessian, dsp, true)->Name("BM_DspResidualHessian");

void BM_DoubleImpact(benchmark::State& state) {
  const Fixture& f = fixture();
  VecD theta = f.x.theta, dtheta = f.x.dtheta;
  for (auto _ : state) {
    benchmark::DoNotOptimize(theta);
    benchmark::DoNotOptimize(dtheta);
    benchmark::DoNotOptimize(doubleImpact(f.model, theta, dtheta));
  }
}
BENCHMARK(BM_DoubleImpact);

void BM_SingleImpact(benchmark::State& state) {
  const Fixture& f = fixture();
  VecD theta = f.x.theta, dtheta = f.x.dtheta;
  for (auto _ : state) {
    benchmark::DoNotOptimize(theta);
    benchmark::DoNotOptimize(dtheta);
    benchmark::DoNotOptimize(singleImpact(f.model, theta, dtheta));
  }
}
BENCHMARK(BM_SingleImpact);

void BM_ReducedDspModel(benchmark::State& state) {
  const Fixture& f = fixture();
  VecD theta = f.x.theta, dtheta = f.x.dtheta;
  for (auto _ : state) {
    benchmark::DoNotOptimize(theta);
    benchmark::DoNotOptimize(dtheta);
    benchmark::DoNotOptimize(reducedDspModel(f.model, theta, dtheta));
  }
}
BENCHMARK(BM_ReducedDspModel);

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
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
