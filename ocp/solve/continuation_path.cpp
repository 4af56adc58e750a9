#include "ocp/solve/continuation_path.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace gaitopt::ocp {
namespace {

/// From `from` to `to` at progress p in (0, 1).
double between(double from, double to, double p, bool geometric) {
  if (geometric && from > 0 && to > 0) return from * std::pow(to / from, p);
  return from + p * (to - from);
}

bool continued(const OcpConfig& c, const std::string& group) {
  const auto& groups = c.continuation.parameters;
  return std::find(groups.begin(), groups.end(), group) != groups.end();
}

/// The easy problem: the configured one with the bounds and weights of the file's comment.
OcpConfig easiest(OcpConfig c) {
  if (continued(c, "margins")) {
    c.friction_margin = 0;
    if (c.impulse_friction_margin) c.impulse_friction_margin = 0;
    c.zmp_margin = 0;
    c.min_normal_force = 0;
  }
  if (continued(c, "strike")) c.touchdown.normal_min = 0;
  if (continued(c, "cost")) {
    c.cost.abs_work *= c.continuation.cost_start;
    c.cost.cost_of_transport *= c.continuation.cost_start;
  }
  return c;
}

/// Whether the path moves a group's parameters at all.
bool moves(const OcpConfig& c, const std::string& group) {
  if (!continued(c, group)) return false;
  if (group == "margins")
    return c.friction_margin > 0 || c.impulse_friction_margin.value_or(0) > 0 || c.zmp_margin > 0 ||
           c.min_normal_force > 0;
  if (group == "strike") return c.touchdown.normal_min > 0;
  return c.cost.abs_work > 0 || c.cost.cost_of_transport > 0;
}

/// A group's own progress at path progress p: in a sequential continuation the groups that move
/// share the path in equal windows one after another, else each moves over the whole path.
double groupProgress(const OcpConfig& target, const std::string& group, double p) {
  if (!target.continuation.sequential) return p;
  std::vector<std::string> windows;
  for (const std::string& g : target.continuation.parameters)
    if (moves(target, g)) windows.push_back(g);
  const auto it = std::find(windows.begin(), windows.end(), group);
  if (it == windows.end()) return p;
  const double width = 1.0 / static_cast<double>(windows.size());
  const double start = width * static_cast<double>(it - windows.begin());
  return std::clamp((p - start) / width, 0.0, 1.0);
}

}  // namespace

OcpConfig configAt(const OcpConfig& target, double progress) {
  const double p = std::clamp(progress, 0.0, 1.0);
  if (p == 1) return target;
  const OcpConfig easy = easiest(target);
  if (p == 0) return easy;
  const bool g = target.continuation.geometric;
  const auto at = [&](double from, double to, const char* group) {
    return between(from, to, groupProgress(target, group, p), g);
  };
  OcpConfig c = target;
  c.friction_margin = at(easy.friction_margin, target.friction_margin, "margins");
  if (target.impulse_friction_margin)
    c.impulse_friction_margin =
        at(*easy.impulse_friction_margin, *target.impulse_friction_margin, "margins");
  c.zmp_margin = at(easy.zmp_margin, target.zmp_margin, "margins");
  c.min_normal_force = at(easy.min_normal_force, target.min_normal_force, "margins");
  c.touchdown.normal_min = at(easy.touchdown.normal_min, target.touchdown.normal_min, "strike");
  c.cost.abs_work = at(easy.cost.abs_work, target.cost.abs_work, "cost");
  c.cost.cost_of_transport = at(easy.cost.cost_of_transport, target.cost.cost_of_transport, "cost");
  return c;
}

PathParameters pathParameters(const OcpConfig& c) {
  return {c.friction_margin,
          c.impulse_friction_margin.value_or(c.friction_margin),
          c.zmp_margin,
          c.min_normal_force,
          c.touchdown.normal_min,
          c.touchdown.normal_max,
          c.cost};
}

bool pathMoves(const OcpConfig& target) {
  return moves(target, "margins") || moves(target, "strike") || moves(target, "cost");
}

OcpConfig onSegments(OcpConfig config, const std::vector<int>& segments) {
  for (size_t i = 0; i < config.phases.size() && i < segments.size(); ++i) {
    config.phases[i].segments = segments[i];
    config.phases[i].clearMesh();
  }
  return config;
}

}  // namespace gaitopt::ocp
