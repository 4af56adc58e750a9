/// @file ocp_study_guesses.cpp
/// What the initial guess buys. Three kinds of start for the same problem:
/// - "polynomial": the polynomial gait of Mu ch. 3 (ocp::polynomialGuess), the project's design;
/// - "naive": Kelly's (2017, sec. 5.3) default, the straight line in time from the polynomial
///   step's start state to its end state, with the rates of that line, no accelerations, no
///   torques and no contact forces;
/// - "perturbed": the optimum with every angle of every collocation point moved by uniform noise
///   in [-a, a] (fixed seeds 1..N), which probes how large a basin the exact-Newton solve has.
/// One row per attempt; an attempt converges when Ipopt reports Solve_Succeeded, and the cost
/// gap tells whether it found the same local optimum.
#include <cmath>
#include <random>

#include <fmt/format.h>

#include "bench/ocp_study.hpp"
#include "ocp/problem/gait_problem.hpp"
#include "ocp/solve/ipopt_adapter.hpp"

namespace gaitopt::bench {

namespace {

/// Angle noise bounds a [rad] of the perturbed guesses (0.5: to find where the solve fails).
constexpr double kNoiseLevels[] = {0.02, 0.05, 0.1, 0.2, 0.5};

/// The straight line from the first knot's state to the last one's, on `poly`'s time grid and
/// phases (so the touchdown switch stays where the problem expects it).
gaits::Trajectory naiveGuess(const gaits::Trajectory& poly) {
  const gaits::Knot& first = poly.knots().front();
  const gaits::Knot& last = poly.knots().back();
  const Eigen::VectorXd rate = (last.theta - first.theta) / poly.duration();
  std::vector<gaits::Knot> knots;
  for (const gaits::Knot& k : poly.knots()) {
    const double s = (k.t - first.t) / poly.duration();
    knots.push_back({.t = k.t,
                     .phase = k.phase,
                     .theta = (1 - s) * first.theta + s * last.theta,
                     .dtheta = rate,
                     .ddtheta = Eigen::VectorXd::Zero(rate.size()),
                     .tau = Eigen::VectorXd::Zero(k.tau.size())});
  }
  return {poly.robot(), poly.stepLength(), std::move(knots)};
}

/// `optimum` with uniform noise in [-noise, noise] added to every angle of every knot.
gaits::Trajectory perturbedGuess(const gaits::Trajectory& optimum, double noise, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-noise, noise);
  std::vector<gaits::Knot> knots = optimum.knots();
  for (gaits::Knot& k : knots)
    for (Eigen::Index i = 0; i < k.theta.size(); ++i) k.theta(i) += uniform(rng);
  return {optimum.robot(), optimum.stepLength(), std::move(knots)};
}

struct Attempt {
  std::string guess;
  double noise = 0;
  unsigned seed = 0;
};

ocp::SolveResult attempt(const StudyCase& c, const Attempt& a, const gaits::Trajectory& guess,
                         double optimal_cost, std::ostream& csv) {
  const ocp::SolveResult r =
      ocp::solveWithIpopt(ocp::buildGaitProblem(c.model, c.config, guess).nlp, c.config.solver);
  const double gap = optimal_cost > 0 ? std::abs(r.cost - optimal_cost) / optimal_cost : 0;
  csv << fmt::format("{},{},{},{},{},{},{},{:.10g},{:.6g},{:.3g}\n", c.robot, a.guess, a.noise,
                     a.seed, r.status, r.success ? 1 : 0, r.iterations, r.cost, r.wall_time_s, gap);
  csv.flush();
  return r;
}

}  // namespace

void guessStudy(const std::vector<StudyCase>& cases, int seeds, std::ostream& csv) {
  csv << "robot,guess,noise_rad,seed,status,converged,iterations,cost,wall_s,cost_gap\n";
  for (const StudyCase& c : cases) {
    // The reference optimum: from the polynomial guess, at the config's mesh and tolerance.
    const ocp::SolveResult best = attempt(c, {"polynomial"}, c.guess, 0, csv);
    attempt(c, {"naive"}, naiveGuess(c.guess), best.cost, csv);
    const gaits::Trajectory optimum =
        ocp::reconstruct(ocp::buildGaitProblem(c.model, c.config, c.guess), c.model, best.x);
    for (const double noise : kNoiseLevels)
      for (int seed = 1; seed <= seeds; ++seed) {
        const auto s = static_cast<unsigned>(seed);
        attempt(c, {"perturbed", noise, s}, perturbedGuess(optimum, noise, s), best.cost, csv);
      }
  }
}

}  // namespace gaitopt::bench
