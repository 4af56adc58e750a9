#include "dynamics/model_variation.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace gaitopt::dynamics {
namespace {

double factor(double error, const char* name) {
  if (!(std::isfinite(error) && error > -1))
    throw std::invalid_argument(
        fmt::format("parameter error {}: {} must be finite and > -1", name, error));
  return 1 + error;
}

}  // namespace

ParameterErrors muUncertaintyCase(int mu_case) {
  switch (mu_case) {  // Mu (2004) sec. 4.3
    case 1:
      return {};
    case 2:
      return {0.4, 0.4, 0.1, 0.1};
    case 3:
      return {1.0, 1.0, 0.4, 0.4};
    default:
      throw std::invalid_argument(fmt::format("uncertainty case {}: expected 1, 2 or 3", mu_case));
  }
}

Model perturbedModel(const Model& nominal, const ParameterErrors& e) {
  const double fm = factor(e.mass, "mass"), fi = factor(e.inertia, "inertia");
  const double fl = factor(e.length, "length"), fd = factor(e.com, "com");
  std::vector<Link> links = nominal.links();
  for (Link& l : links) {
    l.mass *= fm;
    l.inertia *= fi;
    l.length *= fl;
    l.com *= fd;
  }
  return {nominal.name(),     links,          nominal.joints(), nominal.gravity(),
          nominal.friction(), nominal.foot(), nominal.slope()};
}

Model withFriction(const Model& nominal, double friction) {
  if (!(std::isfinite(friction) && friction >= 0))
    throw std::invalid_argument(fmt::format("friction {} must be finite and >= 0", friction));
  return {nominal.name(), nominal.links(), nominal.joints(), nominal.gravity(),
          friction,       nominal.foot(),  nominal.slope()};
}

Model withFoot(const Model& nominal, const Foot& foot) {
  if (!(std::isfinite(foot.heel) && std::isfinite(foot.toe) && foot.heel >= 0 && foot.toe >= 0))
    throw std::invalid_argument(
        fmt::format("foot heel {} and toe {} must be finite and >= 0", foot.heel, foot.toe));
  return {nominal.name(), nominal.links(), nominal.joints(), nominal.gravity(), nominal.friction(),
          foot,           nominal.slope()};
}

Model withSlope(const Model& nominal, double slope) {
  return {nominal.name(),
          nominal.links(),
          nominal.joints(),
          nominal.gravity(),
          nominal.friction(),
          nominal.foot(),
          slope};
}

}  // namespace gaitopt::dynamics
