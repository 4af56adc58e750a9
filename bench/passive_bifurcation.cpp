/// @file passive_bifurcation.cpp
/// The period-doubling route to chaos of Garcia, Chatterjee, Ruina and Coleman's simplest walker
/// (J. Biomech. Eng. 120, 1998; configs/robots/simplest_walker.yaml) as the slope grows, found
/// with the toolkit's own dynamics, impact map and relabelling (sim/studies/passive_walk.hpp):
/// the period-1 gait by continuation in the slope (fixed point, step time, inter-leg angle,
/// multipliers), the slopes where it and the period-2 gait double their period (bisection on
/// the multiplier crossing -1), the period-2 and period-4 gaits beyond them, and the orbit
/// diagram (the steps of a long passive walk at each slope, after its transient).
/// Usage: passive_bifurcation OUT_DIR   (writes branch.csv, orbit.csv, bifurcation.md; about a
/// minute)
#include <cmath>
#include <fstream>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "dynamics/robot_files/robot_config.hpp"
#include "sim/studies/passive_walk.hpp"

namespace {

using namespace gaitopt;

/// Garcia et al.'s stable period-1 gait at slope 0.009: stance angle 0.2003, its rate -0.1998
/// (their angles: from the slope normal, positive backwards).
constexpr double kGarciaSlope = 0.009;
constexpr double kGarciaStance = 0.2003, kGarciaStanceRate = -0.1998;
/// Their abstract: the period-1 gait is stable for 0 < slope < 0.015.
constexpr double kPublishedDoubling = 0.015;

const dynamics::Model& walker() {
  static const dynamics::Model m =
      dynamics::loadRobot(std::string(GAITOPT_SOURCE_DIR) + "/configs/robots/simplest_walker.yaml");
  return m;
}

/// A start near their gait in the toolkit's absolute angles (from the slope normal, positive
/// forwards; the swing leg from the hip), the swing leg turning with the stance leg.
Eigen::VectorXd garciaStart() {
  Eigen::VectorXd x(4);
  x << -kGarciaStance, std::numbers::pi + kGarciaStance, -kGarciaStanceRate, -kGarciaStanceRate;
  return x;
}

sim::PassiveGait solveAt(double gamma, const Eigen::VectorXd& guess, int period) {
  return sim::findPassiveGait(sim::downhill(walker(), gamma), guess, period);
}

/// The slope in (lo, hi) where the gait's most negative multiplier crosses -1, to 1e-7 rad.
double doublingSlope(double lo, double hi, Eigen::VectorXd x, int period) {
  while (hi - lo > 1e-7) {
    const double mid = (lo + hi) / 2;
    const sim::PassiveGait g = solveAt(mid, x, period);
    if (g.ok && g.most_negative_multiplier > -1) {
      lo = mid;
      x = g.start;
    } else {
      hi = mid;
    }
  }
  return (lo + hi) / 2;
}

/// The gait of twice the period just past a doubling.
sim::PassiveGait doubled(const sim::PassiveGait& g, double gamma) {
  return sim::findDoubledGait(sim::downhill(walker(), gamma), solveAt(gamma, g.start, g.period));
}

struct Branch {
  std::vector<double> slopes;
  std::vector<sim::PassiveGait> gaits;
};

/// Continuation of the gait of `period` from `x` over `slopes`, each solve started from the last.
Branch follow(const std::vector<double>& slopes, Eigen::VectorXd x, int period) {
  Branch b;
  for (double gamma : slopes) {
    const sim::PassiveGait g = solveAt(gamma, x, period);
    if (!g.ok || (period > 1 && !sim::hasDistinctHalves(g))) break;
    b.slopes.push_back(gamma);
    b.gaits.push_back(g);
    x = g.start;
  }
  return b;
}

std::vector<double> range(double from, double to, double step) {
  std::vector<double> v;
  for (int k = 0; from + k * step <= to + 1e-12; ++k) v.push_back(from + k * step);
  return v;
}

void writeBranch(std::ofstream& csv, const Branch& b) {
  for (std::size_t i = 0; i < b.gaits.size(); ++i) {
    const sim::PassiveGait& g = b.gaits[i];
    for (std::size_t s = 0; s < g.durations.size(); ++s)
      csv << fmt::format("{},{:.6f},{},{:.9f},{:.9f},{:.6f},{:.6f}\n", g.period, b.slopes[i], s,
                         g.durations[s], g.interleg_angles[s], g.max_multiplier,
                         g.most_negative_multiplier);
  }
}

/// A long passive walk at each slope from the period-1 gait nudged: the step times and angles of
/// its last `record` steps after `transient` (the attractor, or where it fell).
void writeOrbit(const std::string& path, const Branch& period1) {
  constexpr int kTransient = 200, kRecorded = 32;
  std::ofstream csv(path);
  csv << "slope,step,duration_s,interleg_angle_rad\n";
  for (double gamma : range(0.0130, 0.0192, 0.0001)) {
    std::size_t nearest = 0;
    for (std::size_t i = 0; i < period1.slopes.size(); ++i)
      if (std::abs(period1.slopes[i] - gamma) < std::abs(period1.slopes[nearest] - gamma))
        nearest = i;
    const dynamics::Model model = sim::downhill(walker(), gamma);
    Eigen::VectorXd walk = period1.gaits[nearest].start;
    walk.tail(2) *= 1.001;  // off the period-1 gait, which is unstable past the doubling
    for (int step = 0; step < kTransient + kRecorded; ++step) {
      const sim::PassiveStep s = sim::passiveStep(model, walk);
      if (!s.ok) break;
      if (step >= kTransient)
        csv << fmt::format("{:.4f},{},{:.9f},{:.9f}\n", gamma, step, s.duration, s.interleg_angle);
      walk = s.next;
    }
  }
}

/// Stance angle ~ c slope^p over the smallest slopes: Garcia et al.'s scaling law is p = 1/3.
double stanceExponent(const Branch& b) {
  const double a = std::abs(b.gaits[0].start(0)), z = std::abs(b.gaits[1].start(0));
  return std::log(z / a) / std::log(b.slopes[1] / b.slopes[0]);
}

/// The last gait of the branch whose multipliers all lie above -1: a doubling lies within one
/// slope step after it.
std::size_t lastBeforeDoubling(const Branch& b) {
  std::size_t last = 0;
  for (std::size_t i = 0; i < b.gaits.size(); ++i)
    if (b.gaits[i].most_negative_multiplier > -1) last = i;
  return last;
}

struct Doubling {
  double slope = 0;
  sim::PassiveGait before;  ///< the gait just below the doubling slope
};

/// Where the gaits of `b` double their period, between the branch's slopes around it.
Doubling findDoubling(const Branch& b, double slope_step) {
  const std::size_t i = lastBeforeDoubling(b);
  const double slope =
      doublingSlope(b.slopes[i], b.slopes[i] + slope_step, b.gaits[i].start, b.gaits[i].period);
  return {slope, solveAt(slope - 1e-6, b.gaits[i].start, b.gaits[i].period)};
}

std::string durations(const sim::PassiveGait& g) {
  std::string text;
  for (double d : g.durations) text += fmt::format("{}{:.4f}", text.empty() ? "" : ", ", d);
  return text;
}

void writeSummary(const std::string& path, const sim::PassiveGait& garcia, double exponent,
                  const Doubling& first, const Doubling& second, const sim::PassiveGait& period4) {
  std::ofstream md(path);
  md << "| quantity | published (Garcia et al. 1998) | here |\n|---|---:|---:|\n";
  md << fmt::format("| stance angle of the period-1 gait at slope {} [rad] | {} | {:.4f} |\n",
                    kGarciaSlope, kGarciaStance, -garcia.start(0));
  md << fmt::format("| its rate [sqrt(g/l)] | {} | {:.4f} |\n", kGarciaStanceRate,
                    -garcia.start(2));
  md << fmt::format("| largest multiplier there | stable (< 1) | {:.4f} |\n",
                    garcia.max_multiplier);
  md << fmt::format("| exponent p of stance angle ~ slope^p (slopes 1e-4, 2e-4) | 1/3 | {:.4f} |\n",
                    exponent);
  md << fmt::format("| slope where the period-1 gait doubles [rad] | {} | {:.6f} ({:+.2f} %) |\n",
                    kPublishedDoubling, first.slope, 100 * (first.slope / kPublishedDoubling - 1));
  md << fmt::format("| slope where the period-2 gait doubles [rad] | - | {:.6f} |\n", second.slope);
  md << fmt::format("| period-4 gait at slope {:.5f}: step times [sqrt(l/g)] | - | {} |\n",
                    second.slope + 2e-5, period4.ok ? durations(period4) : period4.failure);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    fmt::print(stderr, "usage: passive_bifurcation OUT_DIR\n");
    return 2;
  }
  const std::string out = argv[1];
  const sim::PassiveGait at_garcia = solveAt(kGarciaSlope, garciaStart(), 1);
  // Down to the smallest slopes for the scaling law, then up past the doublings.
  const Branch tiny = follow({kGarciaSlope, 1e-3, 2e-4, 1e-4}, at_garcia.start, 1);
  const Branch period1 = follow(range(0.0010, 0.0190, 0.0005), tiny.gaits[1].start, 1);
  const Doubling first = findDoubling(period1, 0.0005);
  const Branch period2 = follow(range(first.slope + 2e-5, 0.0190, 1e-4),
                                doubled(first.before, first.slope + 2e-5).start, 2);
  const Doubling second = findDoubling(period2, 1e-4);
  const sim::PassiveGait period4 = doubled(second.before, second.slope + 2e-5);
  std::ofstream csv(out + "/branch.csv");
  csv << "period,slope,step,duration_s,interleg_angle_rad,max_multiplier,most_negative_"
         "multiplier\n";
  writeBranch(csv, period1);
  writeBranch(csv, period2);
  writeSummary(out + "/bifurcation.md", at_garcia,
               stanceExponent({{1e-4, 2e-4}, {tiny.gaits[3], tiny.gaits[2]}}), first, second,
               period4);
  writeOrbit(out + "/orbit.csv", period1);
  fmt::print("passive_bifurcation: first doubling at slope {:.6f} (published {}); wrote {}\n",
             first.slope, kPublishedDoubling, out);
  return 0;
}
