#include "sim/contact/ground_config.hpp"

#include "config/quantities.hpp"
#include "config/yaml_reader.hpp"

namespace gaitopt::sim {
namespace {

using config::inRange;
using config::nonNegative;
using config::positive;
using config::YamlReader;

/// Explicit or event-integrator steps between 0.1 us and 10 ms: beyond that no ground of a
/// walking robot is resolved [s].
double timeStep(const YamlReader& root) {
  return root.number("time_step", inRange(1e-7, 1e-2, "[s]"));
}

RigidGround rigid(const YamlReader& root) {
  root.allowOnly({"model", "time_step", "time_tolerance"});
  RigidGround g;
  g.integrator.step = timeStep(root);
  g.integrator.time_tolerance = root.number("time_tolerance", inRange(1e-14, 1e-3, "[s]"));
  return g;
}

CompliantGround impedance(const YamlReader& root) {
  root.allowOnly({"model", "stiffness", "damping", "exponent", "tangential_stiffness",
                  "tangential_damping", "time_step"});
  CompliantGround g{{}, timeStep(root)};
  g.contact.exponent = root.number("exponent", inRange(1.0, 3.0, "[-] (1 linear, 1.5 Hertz)"));
  g.contact.stiffness = root.number("stiffness", inRange(config::kStiffness));  // as its sweep
  g.contact.damping = root.number("damping", nonNegative("[N s/m^(exponent+1)]"));
  g.contact.tangential_stiffness = root.number("tangential_stiffness", positive("[N/m]"));
  g.contact.tangential_damping = root.number("tangential_damping", nonNegative("[N s/m]"));
  g.contact.friction = 0;  // the plant's, set by the walk (ground_model.hpp)
  return g;
}

LcpGround lcp(const YamlReader& root) {
  root.allowOnly({"model", "time_step"});
  return LcpGround{timeStep(root)};
}

DartGround dart(const YamlReader& root) {
  root.allowOnly({"model", "time_step"});
  return DartGround{timeStep(root)};
}

}  // namespace

GroundModel loadGround(const std::string& yaml_path) {
  const auto root = YamlReader::fromFile(yaml_path);
  const std::string model = root.choice("model", {"rigid", "impedance", "lcp", "dart"});
  if (model == "rigid") return rigid(root);
  if (model == "impedance") return impedance(root);
  if (model == "lcp") return lcp(root);
  return dart(root);
}

}  // namespace gaitopt::sim
