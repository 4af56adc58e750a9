#pragma once
// The five-link robot of Mu (2004) and its polynomial gait (configs/gaits/mu2004.yaml), built
// once per test program for the ground-model tests.
#include <string>

#include "dynamics/model_variation.hpp"
#include "dynamics/robot_files/robot_config.hpp"
#include "gaits/polynomial/gait_params.hpp"
#include "gaits/polynomial/hip_plan_search.hpp"
#include "gaits/polynomial/polynomial_gait.hpp"
#include "sim/controllers/tracking_controller.hpp"

namespace gaitopt::sim::test {

inline const dynamics::Model& fiveLinkRobot() {
  static const dynamics::Model model = dynamics::loadRobot(std::string(GAITOPT_SOURCE_DIR) +
                                                           "/configs/robots/mu2004_five_link.yaml");
  return model;
}

/// The robot with a heel long enough for the polynomial gait: its ZMP lies up to 0.197 m behind
/// the stance tip (gaits/export/metrics.cpp), far beyond the shipped 0.05 m heel (a foot rotation,
/// contact_rules.hpp). On a 0.30 m heel the CoP its walk asks for keeps 2.3 mm from the toe
/// (measured on rigid ground); the walks that use this gait as a reference for other properties
/// walk this plant.
inline const dynamics::Model& longHeelRobot() {
  static const dynamics::Model model = dynamics::withFoot(fiveLinkRobot(), {0.30, 0.15});
  return model;
}

/// The polynomial gait at 1 kHz, as the rigid walk test uses it.
inline const gaits::Trajectory& polynomialGait() {
  static const gaits::Trajectory gait = [] {
    const auto params =
        gaits::loadGait(std::string(GAITOPT_SOURCE_DIR) + "/configs/gaits/mu2004.yaml");
    const auto plan = gaits::searchHipPlan(fiveLinkRobot(), params).plan;
    return gaits::buildTrajectory(gaits::PolynomialGait(fiveLinkRobot(), params, plan),
                                  fiveLinkRobot(), 1000);
  }();
  return gait;
}

inline TrackingController computedTorque() {
  return TrackingController(fiveLinkRobot(), std::make_unique<PdLaw>(TrackingGains{}));
}

}  // namespace gaitopt::sim::test
