#pragma once
/// @file ground_registry.hpp
/// The grounds a walk can run on (sim/contact/ground_model.hpp), each registered once in
/// ground_registry.cpp with its name, a one-line description, the reader of its ground file
/// (configs/grounds/NAME.yaml, sim/contact/ground_config.hpp) and its walk. walk.hpp, the
/// ground-file reader, `--ground` (apps/study_commands/scenario_options.cpp) and the Python
/// module (python/bind_walk.cpp) take the names from here.
#include <functional>
#include <string>
#include <type_traits>
#include <typeindex>
#include <vector>

#include "sim/contact/ground_model.hpp"
#include "sim/walk/hybrid_walk.hpp"

namespace gaitopt::config {
class YamlReader;
}

namespace gaitopt::sim {

/// The arguments of walk.hpp's walk besides the ground.
struct WalkArguments {
  const dynamics::Model& plant;
  const Controller& controller;
  const Reference& ref;
  const WalkPlan& plan;
  const WalkLog& log;
  const VecD& theta0;
  const VecD& dtheta0;
};

struct GroundEntry {
  std::string name;
  std::string description;   ///< one line, for --help and the Python module
  std::type_index settings;  ///< the type a GroundModel of this ground holds
  /// The ground file's keys (`model` already read as this name).
  std::function<GroundModel(const config::YamlReader& file)> read;
  /// Its walk; `ground` holds settings of the entry's type.
  std::function<WalkResult(const GroundModel& ground, const WalkArguments& args)> walk;
  /// Its time step, the finest a walk's logged rows can be [s].
  std::function<double(const GroundModel& ground)> time_step;
};

/// The walk on a ground whose settings are a G, as walkLcp (sim/contact/lcp_walk.hpp).
template <class G>
using GroundWalk = WalkResult (*)(const dynamics::Model&, const Controller&, const Reference&,
                                  const G&, const WalkPlan&, const WalkLog&, const VecD&,
                                  const VecD&);

/// The entry of a ground with settings G, read from its file by `read`, walked by `walk` in steps
/// of `time_step`.
template <class G>
GroundEntry makeGroundEntry(std::string name, std::string description,
                            G (*read)(const config::YamlReader&), GroundWalk<G> walk,
                            std::type_identity_t<double (*)(const G&)> time_step) {
  return {std::move(name),
          std::move(description),
          typeid(G),
          [read](const config::YamlReader& file) -> GroundModel { return read(file); },
          [walk](const GroundModel& ground, const WalkArguments& a) {
            return walk(a.plant, a.controller, a.ref, *ground.getIf<G>(), a.plan, a.log, a.theta0,
                        a.dtheta0);
          },
          [time_step](const GroundModel& ground) { return time_step(*ground.getIf<G>()); }};
}

/// The ground `gaitopt simulate` and the Python module walk on unless told otherwise.
inline constexpr const char* kDefaultGround = "rigid";

/// Every ground, in registration order.
const std::vector<GroundEntry>& grounds();
std::vector<std::string> groundNames();
/// The ground called `name`, or null.
const GroundEntry* findGround(const std::string& name);
/// @throws std::invalid_argument naming the registered grounds when none is called `name`.
const GroundEntry& groundEntry(const std::string& name);
/// The entry whose settings `ground` holds. @throws std::invalid_argument for settings no
/// entry registers.
const GroundEntry& groundEntryOf(const GroundModel& ground);
std::string groundName(const GroundModel& ground);

}  // namespace gaitopt::sim
