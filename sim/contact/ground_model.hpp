#pragma once
/// @file ground_model.hpp
/// The interchangeable grounds a walk can run on, so a scene models no more than it needs
/// (Addi & Rodic 2010): rigid ground with impact maps and located events
/// (hybrid_walk.hpp); a compliant Hunt-Crossley ground integrated with a fixed explicit step
/// (impedance_contact.hpp); and velocity-level time stepping with a Lemke LCP per step
/// (lcp_contact_step.hpp); and DART, another engine with feet as bodies (dart_walk.hpp).
/// Each is registered once in sim/walk/ground_registry.cpp; a GroundModel holds the settings of
/// any of them. Friction always comes from the robot (Model::friction()).
#include <any>
#include <type_traits>
#include <typeindex>
#include <utility>

#include "sim/contact/impedance_contact.hpp"
#include "sim/walk/event_integrator.hpp"

namespace gaitopt::sim {

/// Rigid ground: impact maps (Mu 2.23-2.37), events located by bisection.
struct RigidGround {
  EventIntegratorOptions integrator;
};

/// Compliant ground: Hunt-Crossley normal force and a tangential spring-damper at each tip,
/// integrated by fixed-step RK4 on the free-base chain.
struct CompliantGround {
  ImpedanceGround contact;  ///< its `friction` is overwritten by the plant's
  double time_step = 1e-4;  ///< RK4 step [s]
};

/// Time-stepping rigid contact: one LCP (Stewart-Trinkle) per step of the free-base chain.
struct LcpGround {
  double time_step = 1e-3;  ///< [s]
};

/// The DART physics engine as the plant (dart_walk.hpp): its own contact solver and feet.
struct DartGround {
  double time_step = 1e-3;  ///< DART's step, and the controller's period [s]
};

/// The settings of one ground, of whichever type its entry in sim/walk/ground_registry.hpp
/// names: the structs above, or a ground's own, so a new ground needs no change here.
class GroundModel {
 public:
  /// Implicit: a ground's settings are a GroundModel wherever one is asked for.
  template <class G, class = std::enable_if_t<!std::is_same_v<std::decay_t<G>, GroundModel>>>
  GroundModel(G settings) : settings_(std::move(settings)) {}

  /// The settings when they are a G, else null.
  template <class G>
  const G* getIf() const {
    return std::any_cast<G>(&settings_);
  }
  template <class G>
  G* getIf() {
    return std::any_cast<G>(&settings_);
  }
  /// The type of the settings, which names the ground's entry.
  std::type_index type() const { return settings_.type(); }

 private:
  std::any settings_;
};

}  // namespace gaitopt::sim
