#include "sim/walk/ground_registry.hpp"

#include <algorithm>
#include <stdexcept>

#include "config/registry.hpp"
#include "sim/contact/compliant_walk.hpp"
#include "sim/contact/dart_walk.hpp"
#include "sim/contact/ground_config.hpp"
#include "sim/contact/lcp_walk.hpp"

namespace gaitopt::sim {

// One entry per ground: adding one is its own files, its configs/grounds/NAME.yaml and an entry
// here.
const std::vector<GroundEntry>& grounds() {
  static const std::vector<GroundEntry> entries{
      makeGroundEntry("rigid", "impact maps and located events (Mu 2.23-2.37)", readRigidGround,
                      walkRigid, [](const RigidGround& g) { return g.integrator.step; }),
      makeGroundEntry("impedance", "compliant Hunt-Crossley contact, fixed-step RK4",
                      readImpedanceGround, walkCompliant,
                      [](const CompliantGround& g) { return g.time_step; }),
      makeGroundEntry(
          "pad", "Addi & Rodic's stiffening pad, damped while compressed, fixed-step RK4",
          readImpedanceGround, walkCompliant, [](const CompliantGround& g) { return g.time_step; }),
      makeGroundEntry("lcp", "time stepping, one Lemke LCP per step (Stewart & Trinkle 1996)",
                      readLcpGround, walkLcp, [](const LcpGround& g) { return g.time_step; }),
      makeGroundEntry("dart", "the DART physics engine, feet as bodies", readDartGround, walkDart,
                      [](const DartGround& g) { return g.time_step; }),
  };
  return entries;
}

std::vector<std::string> groundNames() {
  return config::registeredNames(grounds());
}

const GroundEntry* findGround(const std::string& name) {
  return config::findRegistered(grounds(), name);
}

const GroundEntry& groundEntry(const std::string& name) {
  return config::registered(grounds(), name, "ground");
}

const GroundEntry& groundEntryOf(const GroundModel& ground) {
  // The pad is the compliant ground with a thickness: one settings type serves both.
  if (const auto* c = ground.getIf<CompliantGround>(); c && c->contact.pad_thickness > 0)
    return groundEntry("pad");
  const auto& all = grounds();
  const auto it = std::find_if(all.begin(), all.end(),
                               [&](const GroundEntry& e) { return e.settings == ground.type(); });
  if (it == all.end())
    throw std::invalid_argument(std::string("no registered ground has settings of type ") +
                                ground.type().name());
  return *it;
}

std::string groundName(const GroundModel& ground) {
  return groundEntryOf(ground).name;
}

}  // namespace gaitopt::sim
