#pragma once
/// @file controller_registry.hpp
/// The controllers a scenario (sim/scenario/scenario.hpp) may name, each registered once in
/// controller_registry.cpp with its name, a one-line description and the factory that builds it
/// from what the scenario has. `--controller` (apps/study_commands/scenario_options.cpp), the
/// Python module (python/bind_walk.cpp) and the scenario take the names from here.
#include <memory>
#include <string>
#include <vector>

#include "dynamics/model.hpp"
#include "dynamics/model_variation.hpp"
#include "sim/controllers/controller.hpp"
#include "sim/controllers/mu_sliding_mode.hpp"
#include "sim/controllers/reference.hpp"
#include "sim/controllers/tracking_law.hpp"

namespace gaitopt::sim {

/// What a controller is built from: the controller's model of the robot, the reference, and the
/// scenario's gains of every law at its bandwidth (sim/scenario/scenario.hpp scales them).
struct ControllerSetting {
  const dynamics::Model& model;
  const Reference& ref;
  TrackingGains gains;
  MuSlidingModeGains mu_gains;
  dynamics::ParameterErrors uncertainty_bound;  ///< what mu_sliding_mode knows of its error
  BoundSide bound_side;
};

struct ControllerEntry {
  std::string name;
  std::string description;  ///< one line, for --help and the Python module
  /// @throws std::invalid_argument when the controller cannot drive the model or the reference.
  std::unique_ptr<Controller> (*build)(const ControllerSetting& setting);
  /// Whether it drives a robot whose stance ankle is passive; the others set every joint
  /// acceleration through the torques (sim/scenario/scenario_settings.hpp checks it).
  bool passive_ankle = false;
};

/// The controller a scenario walks unless told otherwise.
inline constexpr const char* kDefaultController = "computed_torque";

/// Every controller, in registration order.
const std::vector<ControllerEntry>& controllers();
std::vector<std::string> controllerNames();
/// @throws std::invalid_argument naming the registered controllers when none is called `name`.
const ControllerEntry& controllerEntry(const std::string& name);

}  // namespace gaitopt::sim
