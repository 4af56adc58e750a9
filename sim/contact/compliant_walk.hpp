#pragma once
/// @file compliant_walk.hpp
/// Walking on a compliant ground (Addi & Rodic 2010 sec. 4, the impedance alternative to rigid
/// contact): the free-base chain integrated by fixed-step explicit RK4 with a Hunt-Crossley
/// normal force and a tangential spring-damper with a Coulomb limit at both tips
/// (impedance_contact.hpp). Phases, relabelling and failures: free_base_walk.hpp. An explicit
/// step too long for the ground's stiffness makes the state blow up, which the walk reports as
/// "diverged".
#include "sim/contact/ground_model.hpp"
#include "sim/walk/free_base_walk.hpp"

namespace gaitopt::sim {

/// One RK4 step of length ground.time_step: every stage evaluates the contact forces with the
/// anchors of `s` (the last accepted state); the new anchors and the reported forces come from
/// the contact law at the accepted end state. ground.contact.friction is replaced by the
/// plant's. failure = "diverged: ..." when the step created more than kMaxCreatedEnergy
/// (free_base_walk.hpp divergedStep).
ContactStep compliantContactStep(const dynamics::Model& plant, const CompliantGround& ground,
                                 const FreeBaseState& s, const TorqueFeedback& torque);

/// The walk of free_base_walk.hpp on this ground (impact = "compliant").
/// @throws std::invalid_argument when the ground parameters are out of range.
WalkResult walkCompliant(const dynamics::Model& plant, const Controller& controller,
                         const Reference& ref, const CompliantGround& ground, const WalkPlan& plan,
                         const WalkLog& log = {}, const VecD& theta0 = {},
                         const VecD& dtheta0 = {});

}  // namespace gaitopt::sim
