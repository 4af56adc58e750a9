#include "ocp/solve/solution_report.hpp"

#include <cmath>
#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>

#include "gaits/export/consistency.hpp"
#include "gaits/export/export_checks.hpp"
#include "gaits/export/export_contract.hpp"
#include "gaits/export/gait_export.hpp"
#include "gaits/export/gait_summary.hpp"
#include "gaits/export/metrics.hpp"
#include "io/output/checked_write.hpp"
#include "io/output/output_folder.hpp"

namespace gaitopt::ocp {
namespace {

/// The worst friction ratio, or why there is none (a tip pulling on the ground).
nlohmann::ordered_json frictionRatioJson(const gaits::ExportFigures& f) {
  if (std::isfinite(f.max_friction_ratio) && f.min_normal_force > 0) return f.max_friction_ratio;
  return "unbounded: a normal force <= 0";
}

nlohmann::ordered_json meshHistory(const std::vector<MeshRound>& history) {
  auto rounds = nlohmann::ordered_json::array();
  for (const auto& m : history)
    rounds.push_back({{"segments", m.segments},
                      {"status", m.status},
                      {"iterations", m.iterations},
                      {"cost", m.cost},
                      {"max_segment_error_Nms", m.max_segment_error},
                      {"wall_time_s", m.wall_time_s}});
  return rounds;
}

nlohmann::ordered_json solverJson(const SolverOptions& s) {
  return {{"tolerance", s.tolerance},
          {"constraint_tolerance", s.constraint_tolerance},
          {"max_iterations", s.max_iterations},
          {"hessian", s.hessian},
          {"jacobian", s.jacobian},
          {"linear_solver", s.linear_solver},
          {"mu_strategy", s.mu_strategy},
          {"mu_init", s.mu_init},
          {"bound_push", s.bound_push},
          {"bound_frac", s.bound_frac},
          {"bound_mult_init_method", s.bound_mult_init_method},
          {"constr_mult_init_max", s.constr_mult_init_max},
          {"min_refinement_steps", s.min_refinement_steps},
          {"mumps_pivot_order", s.mumps_pivot_order},
          {"nlp_scaling_method", s.nlp_scaling_method},
          {"print_level", s.print_level}};
}

/// Every solver setting the solution came from: the config's (defaults filled in), those of
/// the warm-started refinement rounds and continuation stages, and the refinement's resample
/// rate.
nlohmann::ordered_json solverSettings(const OcpConfig& config) {
  auto json = solverJson(config.solver);
  json["refinement_rounds"] = solverJson(warmStarted(config.solver));
  json["refinement_resample_hz"] = kRefinementResampleHz;
  if (config.continuation.enabled)
    json["continuation_stages"] = solverJson(warmStarted(config.solver));
  return json;
}

nlohmann::ordered_json pathParametersJson(const PathParameters& p) {
  return {{"friction_margin", p.friction_margin},
          {"impulse_friction_margin", p.impulse_friction_margin},
          {"zmp_margin", p.zmp_margin},
          {"min_normal_force", p.min_normal_force},
          {"strike_normal_velocity", {p.normal_velocity_min, p.normal_velocity_max}},
          {"cost",
           {{"torque_squared", p.cost.torque_squared},
            {"abs_work", p.cost.abs_work},
            {"cost_of_transport", p.cost.cost_of_transport}}}};
}

/// What the KKT solves of the whole solve (every stage and round) cost, as the solvers count it.
nlohmann::ordered_json linearSolverJson(const SolverOptions& options, const SolveProfile& p) {
  nlohmann::ordered_json json = {
      {"linear_solver", options.linear_solver},
      {"factorizations", p.factorizations},
      {"pivoting_factorizations", p.ldl.pivoting_factorizations},
      {"mumps_fallbacks", p.ldl.mumps_fallbacks},
      {"mumps_fallback_share",
       p.factorizations > 0 ? static_cast<double>(p.ldl.mumps_fallbacks) / p.factorizations : 0.0},
      {"fallbacks_by_reason",
       {{"zero_pivot", p.ldl.zero_pivot_fallbacks}, {"inexact_solve", p.ldl.inexact_fallbacks}}},
      {"delayed_pivots", p.ldl.delayed_pivots},
      {"inexact_refactorizations", p.ldl.inexact_refactorizations},
      {"inertia_corrections", p.inertia_corrections}};
  if (options.linear_solver == "ldl") json["solves"] = p.ldl.solves;  // MUMPS's are not counted
  return json;
}

/// The continuation's settings and the path it took, one entry per Ipopt solve.
nlohmann::ordered_json continuationJson(const ContinuationOptions& o,
                                        const std::vector<ContinuationStage>& path) {
  auto stages = nlohmann::ordered_json::array();
  for (const ContinuationStage& s : path)
    stages.push_back({{"progress", s.progress},
                      {"parameters", pathParametersJson(s.parameters)},
                      {"segments", s.segments},
                      {"start", s.start},
                      {"mu_init", s.mu_init},
                      {"status", s.status},
                      {"converged", s.success},
                      {"iterations", s.iterations},
                      {"cost", s.cost},
                      {"max_violation", s.max_violation},
                      {"wall_time_s", s.wall_time_s}});
  return {{"steps", o.steps},
          {"parameters", o.parameters},
          {"sequential", o.sequential},
          {"spacing", o.geometric ? "geometric" : "linear"},
          {"cost_start", o.cost_start},
          {"halvings", o.halvings},
          {"retries", o.retries},
          {"retry_mu_init", o.retry_mu_init},
          {"mesh", {{"segments", o.mesh_segments}, {"until", o.mesh_until}}},
          {"stages", stages}};
}

/// The location of a violation for summary.json; `name_key` says what the name names.
nlohmann::ordered_json violationJson(const Violation& v, const std::string& name_key) {
  if (v.name.empty()) return nullptr;
  using Json = nlohmann::ordered_json;
  const bool on_grid = v.node.index >= 0;
  return {{name_key, v.name},
          {"phase", v.phase},
          {"node_kind", on_grid ? Json(v.node.kind) : Json()},
          {"node", on_grid ? Json(v.node.index) : Json()},
          {v.part, on_grid ? v.node.entry : v.index},
          {"value", v.value},
          {"lower", v.lower},
          {"upper", v.upper},
          {"violation", v.amount}};
}

/// Peak torques below this are a passive gait's, whose residual has no torque scale [N m].
constexpr double kPassiveTorque = 1e-3;

/// A strike slower than this, normal and tangential, lands at rest (solver tolerance), and no
/// impact type applies [m/s].
constexpr double kAtRest = 1e-6;

/// |P_t| / P_n of an impulse, the share of its friction cone it uses (null without a push).
nlohmann::ordered_json coneRatio(const Vec2d& impulse) {
  if (!(impulse.y() > 0)) return nullptr;
  return std::abs(impulse.x()) / impulse.y();
}

/// The swing tip's strike: velocity, Mu's strike angle, the impulses and their cone ratios, the
/// impact type the state admits (Mu sec. 5.3) beside the one the config models.
nlohmann::ordered_json strikeJson(const StrikeReport& s, const OcpConfig& config) {
  const char* modelled = config.impact == ImpactModel::kDouble   ? "double"
                         : config.impact == ImpactModel::kSingle ? "single"
                                                                 : "impactless";
  return {{"tip_velocity", {s.tip_velocity.x(), s.tip_velocity.y()}},
          {"normal_velocity", s.normal_velocity},
          {"angle_rad", s.angle},
          {"impact_modelled", modelled},
          {"impulse_leading", {s.impulse_leading.x(), s.impulse_leading.y()}},
          {"impulse_trailing", {s.impulse_trailing.x(), s.impulse_trailing.y()}},
          {"impulse_leading_cone_ratio", coneRatio(s.impulse_leading)},
          {"impulse_trailing_cone_ratio", coneRatio(s.impulse_trailing)},
          // a grazing strike (tangential only) is still an impact: its tip stops
          {"impact_admitted", s.tip_velocity.norm() > kAtRest ? dynamics::toString(s.admitted)
                                                              : "none: the tip lands at rest"}};
}

/// The objective term by term (the solver's quadrature), and the share of the torque-squared
/// regulariser in it when another term is the primary one (a "small" regulariser was
/// 78 % of the least-cost-of-transport objective).
nlohmann::ordered_json costTermsJson(const Nlp& nlp, const Eigen::VectorXd& x,
                                     const CostWeights& weights) {
  nlohmann::ordered_json terms = nlohmann::ordered_json::object();
  double regulariser = 0, total = 0;
  for (const auto& term : nlp.costTerms()) {
    const double value = term->value(x);
    terms[term->name()] = value;
    total += value;
    if (term->name().ends_with("_torque_squared")) regulariser += value;
  }
  nlohmann::ordered_json out = {{"terms", terms}};
  if (weights.primary() != "torque_squared" && weights.torque_squared > 0)
    out["regulariser_share"] = total != 0 ? regulariser / total : 0.0;
  return out;
}

/// Why a solve failed and where: the error line (also in FAILED.txt) and summary.json's keys.
struct FailureReport {
  std::string message;
  nlohmann::ordered_json summary;
};

FailureReport failureReport(const GaitSolution& solution, const std::string& dir) {
  const SolveResult& r = solution.result;
  const Violation row = solution.problem.nlp.worstConstraint(r.x);
  const Violation bound = solution.problem.nlp.worstBound(r.x);
  const std::string message = fmt::format(
      "solver status {} after {} iterations; worst violated constraint: {}; worst variable "
      "bound: {}; {} (max violation {:.3g}) written to {}",
      r.status, r.iterations, describe(row), describe(bound), r.point, r.max_violation, dir);
  return {message,
          {{"point", r.point},
           {"worst_violation", violationJson(row, "constraint")},
           {"worst_bound_violation", violationJson(bound, "variable")}}};
}

/// The export's breaches of its contract (gaits/export/export_contract.hpp).
nlohmann::ordered_json breachesJson(const std::vector<gaits::ExportBreach>& breaches) {
  auto list = nlohmann::ordered_json::array();
  for (const auto& b : breaches)
    list.push_back(
        {{"check", b.check}, {"value", b.value}, {"bound", b.bound}, {"meaning", b.meaning}});
  return list;
}

}  // namespace

size_t writeGaitFiles(const std::string& dir, const gaits::Trajectory& traj,
                      const dynamics::Model& model, double rate_hz,
                      const nlohmann::ordered_json& summary, const FolderPictures& pictures) {
  const size_t samples = gaits::writeGaitExport(dir, traj, model, rate_hz, summary);
  if (pictures) pictures(dir);
  return samples;
}

nlohmann::ordered_json betweenNodeMetrics(const gaits::Trajectory& dense,
                                          const dynamics::Model& model, double rate_hz) {
  const double defect = gaits::maxDynamicsResidual(dense, model);
  const Eigen::VectorXd peak_torque = gaits::peakTorque(dense);
  const double peak = peak_torque.maxCoeff();
  const gaits::ExportFigures f = gaits::exportFigures(dense, model);
  using Json = nlohmann::ordered_json;
  Json metrics = {
      {"max_dynamics_defect", defect},
      // undefined for a passive gait (no torque to compare with)
      {"dynamics_defect_per_peak_torque", peak > kPassiveTorque ? Json(defect / peak) : Json()},
      {"max_tip_acceleration", gaits::maxTipAcceleration(dense, model)},
      {"min_normal_force", f.min_normal_force},
      {"max_friction_ratio", frictionRatioJson(f)},
      {"min_zmp_margin", gaits::minZmpMargin(dense, model)},
      {"min_foot_cop_margin", f.min_foot_cop_margin},
      {"min_swing_clearance", f.min_swing_clearance},
      {"max_dsp_tip_drift", f.max_dsp_tip_drift},
      {"max_rate_mismatch", f.max_rate_mismatch},
      {"max_acceleration_mismatch", f.max_acceleration_mismatch},
      {"max_joint_rate_use", f.max_joint_rate_use},
      {"max_torque_use", f.max_torque_use},
      // the summary's peak torques and posture at the solver's points, here the export's
      {"peak_torque",
       std::vector<double>(peak_torque.data(), peak_torque.data() + peak_torque.size())},
      {"posture_deg", gaits::postureJson(dense, model)},
      {"rate_hz", rate_hz},
      {"breaches", breachesJson(gaits::exportBreaches(f, model.friction(), rate_hz))}};
  if (const std::vector<std::string> unjudged = gaits::unjudgedChecks(rate_hz); !unjudged.empty())
    metrics["unjudged"] = {
        {"checks", unjudged},
        {"why", fmt::format("judged on exports at {:g} Hz or finer: at {:g} Hz the three-point "
                            "differences they compare with err by more than their bounds",
                            gaits::kDerivativeCheckRateHz, rate_hz)}};
  return metrics;
}

nlohmann::ordered_json solutionSummary(const GaitResultOptions& o, const dynamics::Model& model,
                                       const OcpConfig& config, const GaitSolution& solution,
                                       const nlohmann::ordered_json& failure,
                                       const gaits::Trajectory& dense) {
  const GaitProblem& problem = solution.problem;
  const SolveResult& r = solution.result;
  const gaits::Trajectory traj = reconstruct(problem, model, r.x);
  auto summary = gaits::gaitSummary(traj, model,
                                    {o.config_path, r.status, r.iterations, r.wall_time_s,
                                     r.callback_time_s, config.cost.primary()});
  summary["converged"] = r.success;
  if (!o.config_overrides.empty()) summary["config_overrides"] = o.config_overrides;
  if (!o.warm_start.empty()) summary["warm_start"] = o.warm_start;
  summary["cost"] = r.cost;  // the solver's objective (the scheme's own quadrature)
  summary["cost_terms"] = costTermsJson(problem.nlp, r.x, config.cost);
  summary["cost_quadrature"] = fmt::format(
      "the solver's objective: {} quadrature on the "
      "collocation points",
      toString(problem.ssp.layout.scheme));
  // The integrals over what a controller receives (trajectory.csv); the collocation points'
  // own trapezoid values under at_nodes.
  summary["at_nodes"] = {{"energy_J", summary["energy_J"]},
                         {"torque_squared", summary["torque_squared"]},
                         {"cost_of_transport", summary["cost_of_transport"]},
                         {"quadrature", "trapezoid on the collocation points"}};
  summary["energy_J"] = gaits::absoluteWork(dense);
  summary["torque_squared"] = gaits::torqueSquaredIntegral(dense);
  summary["cost_of_transport"] = gaits::costOfTransport(dense, model);
  summary["integral_quadrature"] = fmt::format("trapezoid on trajectory.csv ({:g} Hz)", o.rate_hz);
  if (const auto loss = problem.touchdown.energyLoss(model, r.x))
    summary["impact_energy_loss_J"] = *loss;
  summary["strike"] = strikeJson(problem.touchdown.strike(model, r.x), config);
  summary["max_violation"] = r.max_violation;
  if (!failure.is_null()) summary.update(failure);
  // The constraints hold at the collocation points; the dense export shows how far they are
  // missed between them.
  summary["between_nodes"] = betweenNodeMetrics(dense, model, o.rate_hz);
  summary["nlp"] = {
      {"variables", problem.nlp.variables()},
      {"constraints", problem.nlp.constraints()},
      {"segments", solution.history.back().segments},
      {"scheme", toString(problem.ssp.layout.scheme)},
      {"dsp_pin", problem.dsp && problem.dsp->reduced_coordinates ? "position (reduced coordinates)"
                                                                  : "acceleration"}};
  // A longer period or an ensemble (docs/design.md#the-problems-shape): the folder holds one step.
  if (problem.steps > 1 || problem.variants > 1)
    summary["nlp"]["shape"] = {{"steps", problem.steps},
                               {"variants", problem.variants},
                               {"exported", "the nominal's first step"}};
  summary["mesh_history"] = meshHistory(solution.history);
  if (config.continuation.enabled)
    summary["continuation"] = continuationJson(config.continuation, solution.continuation);
  summary["solver"] = solverSettings(config);
  summary["kkt"] = linearSolverJson(config.solver, solution.result.profile);
  return summary;
}

nlohmann::ordered_json writeGaitResult(const GaitResultOptions& o, const dynamics::Model& model,
                                       const OcpConfig& config, const GaitSolution& solution,
                                       const nlohmann::ordered_json& failure,
                                       const std::string& dir) {
  // Between the points the export follows the scheme's own polynomials.
  const gaits::Trajectory dense =
      reconstructDense(solution.problem, model, solution.result.x, o.rate_hz);
  const auto summary = solutionSummary(o, model, config, solution, failure, dense);
  writeGaitFiles(dir, dense, model, o.rate_hz, summary, o.pictures);
  return summary;
}

namespace {

/// FAILED.txt, so that a person browsing the folders cannot mistake it for a gait. The folder
/// is renamed into place only when complete, so a plain write suffices.
void writeFailedNote(const std::string& path, const std::string& message) {
  io::writeFile(path,
                "This folder holds a failed solve, not a gait: do not use it as a "
                "reference.\n" +
                    message + '\n');
}

}  // namespace

void removeFailedResult(const std::string& failed_dir) {
  if (std::filesystem::is_regular_file(failed_dir + "/FAILED.txt")) io::removeIfOurs(failed_dir);
}

std::string writeFailedResult(const GaitResultOptions& o, const dynamics::Model& model,
                              const OcpConfig& config, const GaitSolution& solution,
                              const std::string& failed_dir) {
  const FailureReport report = failureReport(solution, failed_dir);
  std::vector<std::string> inputs = ocpInputs(config);
  inputs.insert(inputs.end(), {o.config_path, o.warm_start});
  io::OutputFolder(failed_dir, inputs, "--out", "gait").write([&](const std::string& dir) {
    writeGaitResult(o, model, config, solution, report.summary, dir);
    writeFailedNote(dir + "/FAILED.txt", report.message);
  });
  return report.message;
}

}  // namespace gaitopt::ocp
