#pragma once
/// @file ground_model.hpp
/// The interchangeable grounds a walk can run on, so a scene models no more than it needs
/// (Addi & Rodic 2010): rigid ground with impact maps and located events
/// (hybrid_walk.hpp); a compliant Hunt-Crossley ground integrated with a fixed explicit step
/// (impedance_contact.hpp); and velocity-level time stepping with a Lemke LCP per step
/// (lcp_contact_step.hpp); and DART, another engine with feet as bodies (dart_walk.hpp).
/// Friction always comes from the robot (Model::friction()).
#include <string>
#include <variant>

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

using GroundModel = std::variant<RigidGround, CompliantGround, LcpGround, DartGround>;

/// "rigid", "impedance", "lcp" or "dart".
std::string groundName(const GroundModel& ground);

}  // namespace gaitopt::sim
