#include "sim/contact/ground_config.hpp"

#include "config/quantities.hpp"
#include "config/yaml_reader.hpp"
#include "sim/walk/ground_registry.hpp"

namespace gaitopt::sim {

using config::inRange;
using config::nonNegative;
using config::positive;
using config::YamlReader;

double groundTimeStep(const YamlReader& root) {
  return root.number("time_step", inRange(1e-7, 1e-2, "[s]"));
}

RigidGround readRigidGround(const YamlReader& root) {
  root.allowOnly({"model", "time_step", "time_tolerance"});
  RigidGround g;
  g.integrator.step = groundTimeStep(root);
  g.integrator.time_tolerance = root.number("time_tolerance", inRange(1e-14, 1e-3, "[s]"));
  return g;
}

CompliantGround readImpedanceGround(const YamlReader& root) {
  root.allowOnly({"model", "stiffness", "damping", "exponent", "tangential_stiffness",
                  "tangential_damping", "pad_thickness", "time_step"});
  CompliantGround g{{}, groundTimeStep(root)};
  g.contact.exponent = root.number("exponent", inRange(1.0, 3.0, "[-] (1 linear, 1.5 Hertz)"));
  g.contact.stiffness = root.number("stiffness", inRange(config::kStiffness));  // as its sweep
  g.contact.damping = root.number("damping", nonNegative("[N s/m^(exponent+1)]"));
  g.contact.tangential_stiffness = root.number("tangential_stiffness", positive("[N/m]"));
  g.contact.tangential_damping = root.number("tangential_damping", nonNegative("[N s/m]"));
  // The pad ground is this model with a thickness (Addi & Rodic 60); the impedance ground has none.
  if (root.string("model") == "pad")
    g.contact.pad_thickness = root.number("pad_thickness", inRange(1e-4, 0.1, "[m]"));
  else if (root.has("pad_thickness"))
    root.fail("pad_thickness", "a pad's thickness belongs to `model: pad`");
  g.contact.friction = 0;  // the plant's, set by the walk (ground_model.hpp)
  return g;
}

LcpGround readLcpGround(const YamlReader& root) {
  root.allowOnly({"model", "time_step"});
  return LcpGround{groundTimeStep(root)};
}

DartGround readDartGround(const YamlReader& root) {
  root.allowOnly({"model", "time_step"});
  return DartGround{groundTimeStep(root)};
}

GroundModel loadGround(const std::string& yaml_path,
                       const std::vector<config::Override>& overrides) {
  const auto root = YamlReader::fromFile(yaml_path, overrides);
  return groundEntry(root.choice("model", groundNames())).read(root);
}

}  // namespace gaitopt::sim
