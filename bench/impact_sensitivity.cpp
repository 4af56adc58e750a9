/// @file impact_sensitivity.cpp
/// How far the chapter-5 figures of Mu (2004) move with the link inertias, the one robot
/// parameter the thesis' Table 3.1 lost (only 0.033 kg m^2 survives, read as every link's): the
/// end of the single-impact region along sigma 15 deg, alpha 90 deg (Fig. 5.3a, about S_L 1.4 m
/// in the thesis), the approach angle from which the impact is double at S_L 1.8 m and sigma 1 to
/// 15 deg (Fig. 5.3d, 40 deg in the thesis), and the largest |mu_S| of a single impact with alpha
/// 55..135 deg and S_L <= 1.35 m (Fig. 5.7, under about 0.5 in the thesis). "Double from 40"
/// is read off Fig. 5.3(d) for every sigma under 20 deg; here at sigma 5 and 15 deg. Each pair of
/// mirrored links (shanks, thighs) and the torso is set to 0.01 .. 0.1 kg m^2 alone, then every
/// link at once, then the links as uniform rods (I = m l^2 / 12). Usage: impact_sensitivity OUT_DIR
/// (writes sensitivity.csv and sensitivity.md)
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "dynamics/robot_files/robot_config.hpp"
#include "gaits/impact/impact_point.hpp"

namespace {

using namespace gaitopt;

constexpr double kDeg = M_PI / 180;

/// The thesis' figures, in the order of Figures below.
constexpr double kThesisEdge = 1.4, kThesisDoubleFrom = 40, kThesisMaxMuS = 0.5;

dynamics::Model withInertias(const dynamics::Model& m, const std::vector<double>& inertia) {
  std::vector<dynamics::Link> links = m.links();
  for (std::size_t i = 0; i < links.size(); ++i) links[i].inertia = inertia[i];
  return {m.name(), links, m.joints(), m.gravity(), m.friction(), m.foot()};
}

dynamics::ImpactType typeAt(const dynamics::Model& m, double step, double sigma_deg,
                            double alpha_deg) {
  return gaits::evaluateImpactPoint(m, {step, sigma_deg * kDeg, alpha_deg * kDeg, 1.0}).type;
}

/// Mu's S_L where the single region ends along sigma 15, alpha 90, by bisection to 0.1 mm.
double singleEdge(const dynamics::Model& m) {
  double lo = 0.3, hi = 0.95;  // tip distances: single at lo, not at hi
  while (hi - lo > 5e-5)
    (typeAt(m, (lo + hi) / 2, 15, 90) == dynamics::ImpactType::kSingle ? lo : hi) = (lo + hi) / 2;
  return lo + hi;  // S_L = 2 x the tip distance
}

/// The least alpha [deg, 1 deg steps] from which the impact at S_L 1.8 m and knee bias `sigma`
/// is double up to 150 deg; NaN when it is not double at 150 deg.
double doubleFrom(const dynamics::Model& m, double sigma) {
  if (typeAt(m, 0.9, sigma, 150) != dynamics::ImpactType::kDouble) return std::nan("");
  double alpha = 150;
  while (alpha > 5 && typeAt(m, 0.9, sigma, alpha - 1) == dynamics::ImpactType::kDouble) alpha -= 1;
  return alpha;
}

std::string degrees(double alpha) {
  return std::isnan(alpha) ? "none" : fmt::format("{:.0f}", alpha);
}

/// The largest |mu_S| of a single impact, alpha 55..135 deg, S_L 0.1 .. 1.35 m.
double maxMuS(const dynamics::Model& m) {
  double worst = 0;
  for (double sigma : {1.0, 20.0, 40.0, 60.0})
    for (double step = 0.05; step <= 0.675 + 1e-9; step += 0.025)
      for (double alpha = 55; alpha <= 135 + 1e-9; alpha += 5) {
        const auto p = gaits::evaluateImpactPoint(m, {step, sigma * kDeg, alpha * kDeg, 1.0});
        if (p.type == dynamics::ImpactType::kSingle) worst = std::max(worst, std::abs(p.mu_s));
      }
  return worst;
}

struct Variant {
  std::string name;
  std::vector<double> inertia;
};

std::vector<Variant> variants(const dynamics::Model& m) {
  const std::vector<double> shipped = [&] {
    std::vector<double> v;
    for (const auto& l : m.links()) v.push_back(l.inertia);
    return v;
  }();
  std::vector<Variant> out{{"shipped (0.033 each)", shipped}};
  const std::vector<std::pair<std::string, std::vector<int>>> groups = {
      {"shanks", {0, 4}}, {"thighs", {1, 3}}, {"torso", {2}}, {"every link", {0, 1, 2, 3, 4}}};
  for (const auto& [name, links] : groups)
    for (double value : {0.01, 0.02, 0.05, 0.07, 0.1}) {
      std::vector<double> v = shipped;
      for (int i : links) v[static_cast<std::size_t>(i)] = value;
      out.push_back({fmt::format("{} {}", name, value), v});
    }
  std::vector<double> rods;
  for (const auto& l : m.links()) rods.push_back(l.mass * l.length * l.length / 12);
  out.push_back({"uniform rods", rods});
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    fmt::print(stderr, "usage: impact_sensitivity OUT_DIR\n");
    return 2;
  }
  const std::string out = argv[1];
  const dynamics::Model robot = dynamics::loadRobot(std::string(GAITOPT_SOURCE_DIR) +
                                                    "/configs/robots/mu2004_five_link.yaml");
  std::ofstream csv(out + "/sensitivity.csv"), md(out + "/sensitivity.md");
  csv << "inertias,single_edge_SL_m,double_from_deg_sigma5,double_from_deg_sigma15,"
         "max_abs_mu_S\n";
  md << "| link inertias [kg m^2] | single region ends at S_L [m] | double from alpha [deg], "
        "sigma 5 / 15 deg | largest \\|mu_S\\| |\n|---|---:|---:|---:|\n";
  md << fmt::format("| thesis (Figs. 5.3a, 5.3d, 5.7) | about {} | {} / {} | about {} |\n",
                    kThesisEdge, kThesisDoubleFrom, kThesisDoubleFrom, kThesisMaxMuS);
  for (const Variant& v : variants(robot)) {
    const dynamics::Model m = withInertias(robot, v.inertia);
    const double edge = singleEdge(m), mu_s = maxMuS(m);
    const double from5 = doubleFrom(m, 5), from15 = doubleFrom(m, 15);
    csv << fmt::format("{},{:.4f},{:.0f},{:.0f},{:.4f}\n", v.name, edge, from5, from15, mu_s);
    md << fmt::format("| {} | {:.3f} | {} / {} | {:.2f} |\n", v.name, edge, degrees(from5),
                      degrees(from15), mu_s);
  }
  fmt::print("impact_sensitivity: wrote {}/sensitivity.{{csv,md}}\n", out);
  return 0;
}
