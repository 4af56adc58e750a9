#include "gaits/polynomial/hip_plan_search.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>
#include <nlopt.hpp>

#include "dynamics/ground.hpp"

namespace gaitopt::gaits {
namespace {

constexpr int kMarginSamples = 41;  // DSP samples in the objective
constexpr int kReachSamples = 61;   // SSP samples checked for reachability
constexpr double kPenalty = 10.0;   // above any margin: half a step is at most 2.5 m

/// One free parameter: where it lives in HipPlan and its search box.
struct FreeParam {
  double HipPlan::*field;
  double lo, hi, start;
};

struct SearchContext {
  const dynamics::Model* model;
  const GaitParams* params;
  HipPlan base;
  std::vector<FreeParam> free;
  int evaluations = 0;

  HipPlan planAt(const double* x) const {
    HipPlan p = base;
    for (size_t i = 0; i < free.size(); ++i) p.*(free[i].field) = x[i];
    return p;
  }
};

/// Number of SSP samples at which a leg cannot reach (0 for a feasible swing).
int unreachableSamples(const PolynomialGait& gait) {
  int bad = 0;
  for (int k = 0; k <= kReachSamples; ++k)
    if (!gait.reachable(gait.params().ssp_duration * k / kReachSamples, Phase::kSsp)) ++bad;
  return bad;
}

/// The objective's margin: the DSP's, or the least of it and the SSP's.
double objectiveMargin(const PolynomialGait& gait, const dynamics::Model& model) {
  const double dsp = dspStabilityMargin(gait, model, kMarginSamples);
  if (gait.params().hip_objective == HipObjective::kDspZmp) return dsp;
  return std::min(dsp, sspZmpMargin(gait, model, kReachSamples));
}

double negativeMargin(unsigned, const double* x, double*, void* data) {
  auto* ctx = static_cast<SearchContext*>(data);
  ++ctx->evaluations;
  const PolynomialGait gait(*ctx->model, *ctx->params, ctx->planAt(x));
  const int bad = unreachableSamples(gait);
  if (bad > 0) return kPenalty + bad;  // worse than any reachable gait
  try {
    return -objectiveMargin(gait, *ctx->model);
  } catch (const std::domain_error&) {
    return kPenalty + kReachSamples;
  }
}

/// The stance leg's length (shank and thigh) [m].
double legLength(const dynamics::Model& model) {
  return model.link(0).length + model.link(1).length;
}

std::vector<FreeParam> freeParams(const dynamics::Model& model, const GaitParams& p,
                                  HipPlan& base) {
  const double v = p.speed();
  std::vector<FreeParam> free;
  auto choose = [&](const std::optional<double>& given, double HipPlan::*field, double lo,
                    double hi, double start) {
    if (given)
      base.*field = *given;
    else
      free.push_back({field, lo, hi, start});
  };
  choose(p.hip_velocity_start, &HipPlan::velocity_start, 0.1 * v, 3 * v, v);
  choose(p.hip_velocity_touchdown, &HipPlan::velocity_touchdown, 0.1 * v, 3 * v, v);
  // S_S0 from a tenth of a step ahead of the stance tip to a step behind it; H_h from 80 to 98 %
  // of the leg (stretched at 100 %).
  const double length = p.step_length;
  choose(p.hip_start_free ? std::nullopt : std::optional<double>(p.hip_start), &HipPlan::start,
         -0.1 * length, length, p.hip_start);
  choose(p.hip_height_free ? std::nullopt : std::optional<double>(p.hip_height), &HipPlan::height,
         0.8 * legLength(model), 0.98 * legLength(model), p.hip_height);
  // S_D0 lies between the hip's start and end positions of the step (3.16, 3.17), over every
  // start the search may take.
  const double first = -(p.hip_start_free ? length : p.hip_start);
  const double last = p.step_length - (p.hip_start_free ? -0.1 * length : p.hip_start);
  choose(p.hip_dsp_start, &HipPlan::dsp_start, first + 0.05 * (last - first),
         last - 0.01 * (last - first), first + p.ssp_duration / p.duration() * (last - first));
  return free;
}

}  // namespace

double sspZmpMargin(const PolynomialGait& gait, const dynamics::Model& model, int samples) {
  const auto& p = gait.params();
  const dynamics::Foot& foot = model.foot();
  double margin = std::numeric_limits<double>::infinity();
  for (int k = 0; k <= samples; ++k) {
    const GaitKinematics g = gait.kinematics(p.ssp_duration * k / samples, Phase::kSsp);
    const double zmp = dynamics::zeroMomentPoint(model, g.theta, g.dtheta, g.ddtheta);
    margin = std::min({margin, zmp + foot.heel, foot.toe - zmp});
  }
  return margin;
}

double dspStabilityMargin(const PolynomialGait& gait, const dynamics::Model& model, int samples) {
  const auto& p = gait.params();
  double margin = std::numeric_limits<double>::infinity();
  for (int k = 0; k <= samples; ++k) {
    const double t = p.ssp_duration + p.dsp_duration * k / samples;
    const GaitKinematics g = gait.kinematics(t, Phase::kDsp);
    const double zmp = dynamics::zeroMomentPoint(model, g.theta, g.dtheta, g.ddtheta);
    margin = std::min({margin, zmp, p.step_length - zmp});
  }
  return margin;
}

namespace {

/// The search's outcome at `plan`, with both margins.
HipPlanSearch result(const dynamics::Model& model, const GaitParams& params, const HipPlan& plan,
                     int evaluations, const std::string& algorithm) {
  const PolynomialGait gait(model, params, plan);
  const double dsp = dspStabilityMargin(gait, model, kMarginSamples);
  const double ssp = sspZmpMargin(gait, model, kReachSamples);
  const double margin = params.hip_objective == HipObjective::kZmp ? std::min(dsp, ssp) : dsp;
  return {plan, margin, dsp, ssp, evaluations, algorithm};
}

}  // namespace

HipPlanSearch searchHipPlan(const dynamics::Model& model, const GaitParams& params) {
  requireKneedLegs(model);  // before NLopt, which would swallow the message
  SearchContext ctx{&model, &params, {}, {}};
  ctx.free = freeParams(model, params, ctx.base);
  if (ctx.free.empty()) return result(model, params, ctx.base, 1, "fixed");
  const auto dim = static_cast<unsigned>(ctx.free.size());
  nlopt::opt opt(nlopt::LN_SBPLX, dim);
  std::vector<double> lo, hi, x;
  for (const auto& f : ctx.free) {
    lo.push_back(f.lo);
    hi.push_back(f.hi);
    x.push_back(f.start);
  }
  opt.set_lower_bounds(lo);
  opt.set_upper_bounds(hi);
  opt.set_min_objective(negativeMargin, &ctx);
  opt.set_xtol_abs(1e-6);
  opt.set_ftol_abs(1e-9);
  opt.set_maxeval(3000);
  double value = 0;
  opt.optimize(x, value);
  const HipPlan best = ctx.planAt(x.data());
  if (value >= kPenalty) {
    // No reachable plan: let the gait itself say where and by how much a leg falls short.
    const PolynomialGait gait(model, params, best);
    for (int k = 0; k <= kReachSamples; ++k)
      gait.kinematics(params.ssp_duration * k / kReachSamples, Phase::kSsp);
    dspStabilityMargin(gait, model, kMarginSamples);
  }
  if (value > 0)
    throw std::domain_error(
        fmt::format("gait '{}': no hip plan keeps the {} (best margin {:.4f} m)", params.name,
                    params.hip_objective == HipObjective::kZmp
                        ? "SSP ZMP inside the stance foot and the DSP ZMP between the tips"
                        : "DSP ZMP between the tips",
                    -value));
  return result(model, params, best, ctx.evaluations, "LN_SBPLX");
}

nlohmann::ordered_json designJson(const GaitParams& p, const HipPlanSearch& search) {
  return {{"gait",
           {{"name", p.name},
            {"ssp_duration", p.ssp_duration},
            {"dsp_duration", p.dsp_duration},
            {"apex_x", p.apex_x},
            {"apex_height", p.apex_height},
            {"hip_height", p.hip_height},
            {"hip_bob", p.hip_bob},
            {"hip_start", p.hip_start},
            {"torso_angle", p.torso_angle}}},
          {"hip_plan",
           {{"objective", p.hip_objective == HipObjective::kZmp ? "zmp" : "dsp_zmp"},
            {"velocity_start", search.plan.velocity_start},
            {"velocity_touchdown", search.plan.velocity_touchdown},
            {"dsp_start", search.plan.dsp_start},
            {"start", search.plan.start},
            {"height", search.plan.height},
            {"dsp_stability_margin", search.dsp_margin},
            {"ssp_zmp_margin", search.ssp_margin},
            {"algorithm", search.algorithm},
            {"evaluations", search.evaluations}}}};
}

HipPlanSearch designHipPlan(const dynamics::Model& model, const GaitParams& params,
                            const std::string& gait_path) {
  try {
    return searchHipPlan(model, params);
  } catch (const std::domain_error& e) {
    throw std::domain_error(
        fmt::format("{}: gait '{}' (step_length {:g} m) cannot be realised by "
                    "robot '{}': {}",
                    gait_path, params.name, params.step_length, model.name(), e.what()));
  }
}

}  // namespace gaitopt::gaits
