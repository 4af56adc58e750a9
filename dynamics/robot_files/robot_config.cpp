#include "dynamics/robot_files/robot_config.hpp"

#include <numbers>
#include <stdexcept>

#include "config/yaml_reader.hpp"

namespace gaitopt::dynamics {
namespace {

using config::YamlReader;

Link readLink(const YamlReader& r) {
  r.allowOnly({"name", "mass", "inertia", "length", "com", "continues"});
  Link link;
  link.name = r.string("name");
  // Plausible ranges (a gram to ten tonnes, a millimetre to 100 m): beyond them the dynamics
  // overflow to NaN (mass 1e308) long before any result means anything.
  link.mass = r.number("mass", config::inRange(1e-3, 1e4, "[kg]"));
  link.inertia = r.number("inertia", config::inRange(1e-9, 1e6, "[kg m^2] (about the link CoM)"));
  link.length = r.number("length", config::inRange(1e-3, 100.0, "[m]"));
  link.com = r.number("com", config::inRange(0.0, link.length, "[m] (within the link length)"));
  link.continues = r.boolean("continues");
  return link;
}

Joint readJoint(const YamlReader& r) {
  r.allowOnly({"name", "actuated", "torque_limit", "velocity_limit"});
  Joint joint;
  joint.name = r.string("name");
  joint.actuated = r.boolean("actuated");
  if (joint.actuated) {
    joint.torque_limit = r.number("torque_limit", config::positive("[N m]"));
  } else if (r.has("torque_limit")) {
    r.fail("torque_limit", "an unactuated joint (actuated: false) takes no torque_limit");
  }
  // 100 rad/s bounds the range so that a value in deg/s is caught.
  joint.velocity_limit = r.number("velocity_limit", config::inRange(1e-6, 100.0, "[rad/s]"));
  return joint;
}

}  // namespace

Model loadRobot(const std::string& path, const std::vector<config::Override>& overrides) {
  const YamlReader root = YamlReader::fromFile(path, overrides);
  root.allowOnly({"name", "description", "gravity", "friction", "foot", "links", "joints"});
  const std::string name = root.string("name");
  root.stringOr("description", "");
  const double gravity = root.number("gravity", config::inRange(0.1, 100.0, "[m/s^2]"));
  const double friction = root.number("friction", config::inRange(1e-6, 10.0, "(Coulomb mu)"));
  const YamlReader foot_node = root.map("foot");
  foot_node.allowOnly({"heel", "toe"});
  const Foot foot{foot_node.number("heel", config::nonNegative("[m]")),
                  foot_node.number("toe", config::nonNegative("[m]"))};

  std::vector<Link> links;
  for (const auto& item : root.list("links")) links.push_back(readLink(item));
  std::vector<Joint> joints;
  for (const auto& item : root.list("joints")) joints.push_back(readJoint(item));
  try {
    return Model(name, std::move(links), std::move(joints), gravity, friction, foot);
  } catch (const std::invalid_argument& e) {
    root.fail("links", e.what());
  }
}

}  // namespace gaitopt::dynamics
