#include "sim/controllers/controller_registry.hpp"

#include "config/registry.hpp"
#include "sim/controllers/hzd_controller.hpp"
#include "sim/controllers/tracking_controller.hpp"

namespace gaitopt::sim {
namespace {

template <class Law, DspFeedForward Dsp = DspFeedForward::kModel>
std::unique_ptr<Controller> buildTracking(const ControllerSetting& s) {
  return std::make_unique<TrackingController>(s.model, std::make_unique<Law>(s.gains), Dsp);
}

template <DspFeedForward Dsp = DspFeedForward::kModel>
std::unique_ptr<Controller> buildMuSlidingMode(const ControllerSetting& s) {
  return std::make_unique<MuSlidingModeController>(s.model, s.mu_gains, s.uncertainty_bound,
                                                   s.bound_side, Dsp);
}

std::unique_ptr<Controller> buildHzd(const ControllerSetting& s) {
  return makeHzdController(s.model, s.ref, std::make_unique<PdLaw>(s.gains));
}

}  // namespace

// One entry per controller: adding one is its own files and an entry here.
const std::vector<ControllerEntry>& controllers() {
  static const std::vector<ControllerEntry> entries{
      {"computed_torque", "computed torque with PD tracking (Mu 2.43)", buildTracking<PdLaw>},
      {"computed_torque_plan_dsp",
       "computed torque; in double support the plan's torques fed forward and the model's "
       "computed torque for the correction only",
       buildTracking<PdLaw, DspFeedForward::kPlan>},
      {"sliding_mode", "computed torque with a boundary-layer sliding-mode law",
       buildTracking<SlidingModeLaw>},
      {"mu_sliding_mode", "Mu's integral sliding mode with a known uncertainty bound (Mu 4.1-4.17)",
       buildMuSlidingMode<>},
      {"mu_sliding_mode_plan_dsp",
       "Mu's integral sliding mode; in double support the plan's torques fed forward and the "
       "model's equivalent control for the correction only",
       buildMuSlidingMode<DspFeedForward::kPlan>},
      {"hzd", "output zeroing of virtual constraints for a passive ankle (Westervelt et al. 2003)",
       buildHzd, true},
  };
  return entries;
}

std::vector<std::string> controllerNames() {
  return config::registeredNames(controllers());
}

const ControllerEntry& controllerEntry(const std::string& name) {
  return config::registered(controllers(), name, "controller");
}

}  // namespace gaitopt::sim
