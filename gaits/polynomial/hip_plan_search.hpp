#pragma once
/// @file hip_plan_search.hpp
/// Chooses the free hip parameters (V_h1, V_h2 and S_D0, those the gait file leaves as
/// "optimize", and S_S0 and H_h when the file frees them) to maximise the DSP stability margin
/// of Mu (2004) sec. 3.2.3: the minimum over the DSP of the distance from the ZMP to the nearer
/// end of the segment between the tips. Mu checks the ZMP only there and assumes the ankle
/// carries what the single support asks; with `objective: zmp` the search maximises the least of
/// that margin and the single support's: the ZMP's distance inside the stance foot.
///
/// Method: NLopt's Subplex (LN_SBPLX), a derivative-free subspace Nelder-Mead. The objective is a
/// minimum over time samples, so it has kinks where the worst sample changes; gradient methods
/// stall there, while Subplex only compares values. Three bounded variables need a few hundred
/// evaluations. Parameters at which a leg cannot reach are rejected with a penalty that grows
/// with the number of unreachable samples, which steers the search back to feasible gaits.
#include <string>

#include "dynamics/model.hpp"
#include "gaits/polynomial/gait_params.hpp"
#include "gaits/polynomial/polynomial_gait.hpp"

#include <nlohmann/json.hpp>

namespace gaitopt::gaits {

struct HipPlanSearch {
  HipPlan plan;
  double margin = 0;      ///< the objective's margin at the plan [m]
  double dsp_margin = 0;  ///< DSP stability margin at the plan [m]
  double ssp_margin = 0;  ///< least SSP ZMP distance inside the stance foot (< 0: outside) [m]
  int evaluations = 0;    ///< objective evaluations
  std::string algorithm;  ///< "LN_SBPLX", or "fixed" when nothing was free
};

/// DSP stability margin of a gait, sampled at `samples` instants of the DSP [m]: min over t of
/// min(x_zmp, step_length - x_zmp). @throws std::domain_error if a leg cannot reach.
double dspStabilityMargin(const PolynomialGait& gait, const dynamics::Model& model, int samples);

/// Least distance of the SSP ZMP inside the stance foot [-heel, toe], sampled at `samples`
/// instants of the SSP [m]; negative when it leaves the foot. @throws std::domain_error if a leg
/// cannot reach.
double sspZmpMargin(const PolynomialGait& gait, const dynamics::Model& model, int samples);

/// @throws std::domain_error when no plan keeps the legs within reach (the message names the
///         time and the reachable range) or the objective's ZMP where it must be.
HipPlanSearch searchHipPlan(const dynamics::Model& model, const GaitParams& params);

/// searchHipPlan for the gait of file `gait_path`.
/// @throws std::domain_error naming the file, the gait, its step length and the robot when the
///         gait cannot be realised.
HipPlanSearch designHipPlan(const dynamics::Model& model, const GaitParams& params,
                            const std::string& gait_path);

/// summary.json's record of a designed gait: "gait" (its parameters) and "hip_plan" (the plan
/// and how it was found).
nlohmann::ordered_json designJson(const GaitParams& params, const HipPlanSearch& search);

}  // namespace gaitopt::gaits
