#pragma once
/// @file ocp_config.hpp
/// configs/ocp/*.yaml: which robot, which phases, the mesh and scheme, the cost, the constraint
/// switches and the solver options (docs/design.md#configs). Paths are relative to the file.
#include <optional>
#include <string>
#include <vector>

#include "config/overrides.hpp"
#include "dynamics/model.hpp"
#include "ocp/problem/clearance_profile.hpp"
#include "ocp/shape/shape_config.hpp"
#include "ocp/solve/continuation_options.hpp"
#include "ocp/solve/ipopt_adapter.hpp"
#include "ocp/transcription/collocation.hpp"
#include "ocp/transcription/nlp.hpp"

namespace gaitopt::ocp {

struct PhaseConfig {
  std::string name;         ///< "SSP", then optionally "DSP"
  double duration = 0;      ///< fixed T, or the initial T when free
  double duration_min = 0;  ///< bounds of a free T; both 0 when fixed [s]
  double duration_max = 0;
  int segments = 0;
  std::vector<double> mesh;  ///< segment boundaries as fractions of T; empty: equal segments
  /// Fraction of T spanned by the first segment, each later one at most 1.5 times the one before
  /// and the rest equal (a mesh finer after an impact that follows the segment count); 0: equal
  /// segments. Not with `mesh`.
  double first_segment = 0;

  bool freeDuration() const { return duration_max > 0; }
  /// The segment boundaries the phase is built on: `mesh` if given, else the graded one of
  /// `first_segment` (on 2 segments or more), else empty (equal segments).
  std::vector<double> fractions() const;
  /// Equal segments from now on (a mesh continuation or a refinement replaces the mesh).
  void clearMesh() {
    mesh.clear();
    first_segment = 0;
  }
};

/// Weights of the running-cost terms; those at 0 are left out. Cost of transport is the
/// absolute work per weight and distance, W / (m g d) (dimensionless).
struct CostWeights {
  double torque_squared = 0;  ///< integral of sum_j tau_j^2 [N^2 m^2 s]
  double abs_work = 0;        ///< integral of sum_j |tau_j dq_j| [J]
  double cost_of_transport = 0;

  bool needsWorkSlacks() const { return abs_work > 0 || cost_of_transport > 0; }
  /// The main term, for summaries: cost_of_transport, else abs_work, else torque_squared.
  std::string primary() const;
};

/// Mesh refinement (Betts 2010, ch. 4.7): re-solve with the segments whose collocation error
/// exceeds `tolerance` split, until none does or `max_rounds` re-solves were made.
struct MeshRefinement {
  double tolerance = 0;  ///< per-segment dynamics defect integral [N m s]; 0: off
  int max_rounds = 4;
};

/// Touchdown: rigid single impact (B lifts off; SSP-only steps), rigid double impact (both tips
/// stay; leads into a DSP), or impactless (zero swing-tip velocity at touchdown, Mu ch. 3).
enum class ImpactModel { kSingle, kDouble, kImpactless };

/// A designed strike (docs/design.md#the-optimal-control-problem): the swing tip hits the ground
/// with a downward normal velocity v_n = -ydot_e^- in [normal_min, normal_max] [m/s] and,
/// optionally, at a strike angle alpha = cot^-1(xdot_e^- / ydot_e^-) in [angle_min, angle_max]
/// [rad] (Mu ch. 5: the angle between the tip velocity and the -x axis, 0..pi, pi/2 straight down,
/// > pi/2 moving forward; Xdot_e^- = -V_e (cos alpha, sin alpha)). Mu's Fig. 5.7 puts the flat part
/// of the single-impact sector, |mu_S| < 0.5, at 50 deg < alpha < 140 deg for S_L < 1.35 m. A tip
/// that lands at rest makes touchdown time go as the square root of a height error.
struct StrikeDesign {
  bool enabled = false;
  double normal_min = 0, normal_max = 0;  ///< [m/s], 0 <= min <= max
  bool angle = false;                     ///< whether the angle is bounded
  double angle_min = 0, angle_max = 0;    ///< [rad], 0 <= min <= max <= pi
};

/// The `initial_guess` value that asks for the straight-leg guess instead of a gait file.
inline constexpr const char* kStraightLegGuess = "straight_leg";

struct OcpConfig {
  std::string name;
  std::string robot_path;
  /// Polynomial gait file used as the initial guess; empty for `initial_guess: straight_leg`
  /// (straight_leg_guess.hpp, robots with one link per leg).
  std::string guess_gait_path;
  double step_length = 0;  ///< tips apart at touchdown [m]
  /// Ground inclination gamma [rad], > 0 uphill (dynamics/model.hpp); problemModel() applies it.
  /// The guess gait file's own `slope` is ignored: the guess is built on problemModel().
  double slope = 0;
  std::vector<PhaseConfig> phases;
  double step_duration = 0;  ///< with free durations: SSP + DSP = step_duration (0: free) [s]
  Scheme scheme = Scheme::kHermiteSimpson;
  ImpactModel impact = ImpactModel::kSingle;
  CostWeights cost;
  MeshRefinement refinement;
  // Constraint switches and bounds.
  bool torque_limits = true;  ///< |tau_j| <= robot torque limit; unactuated joints at 0
  bool knee_limits = true;    ///< knees never hyperextend (stance q1 >= 0, swing <= 0)
  /// With knee_limits: each knee's flexion |q| at most this, stance leg (links 0, 1) and swing
  /// leg (links n-2, n-1) as gaits/export/metrics.hpp's posture reads them [rad] (inf: off)
  double max_stance_knee_flexion = kInf, max_swing_knee_flexion = kInf;
  /// With knee_limits: in the double support the trailing knee (links 0, 1) flexed at least
  /// this [rad] (0: off). A straight trailing knee makes the hip's position from that leg, the
  /// double support's reduced coordinates (Mu 2.13), singular, and the closed loop's
  /// double-support laws invert them (sim/controllers/computed_torque.cpp).
  double min_trailing_knee_flexion = 0;
  double angle_range = 0;  ///< |theta - upright| bound per link [rad] (0: off)
  double rate_limit = 0;   ///< |dtheta| bound [rad/s] (0: off)
  /// |ddtheta_{p+1} - ddtheta_p| <= J (t_{p+1} - t_p) between consecutive points [rad/s^3]
  /// (jerk_limit.hpp; 0: off)
  double jerk_limit = 0;
  /// |u_{p+1} - u_p| <= R (t_{p+1} - t_p) between consecutive points [N m/s]
  /// (torque_rate_limit.hpp; 0: off)
  double torque_rate_limit = 0;
  /// |jerk_right - jerk_left| <= J where two segments of a phase meet, the jerk being the slope
  /// of the scheme's acceleration polynomial [rad/s^3] (jerk_jump.hpp; 0: off)
  double jerk_jump_limit = 0;
  /// The single support's contact rows also at the interior ends of this many equal
  /// sub-intervals of every segment (interior_contact.hpp; 0: at the points only)
  int interior_contact = 0;
  /// |dq_j| <= the robot's velocity_limit per joint, dq = M dtheta (Mu 2.41)
  bool joint_velocity_limits = false;
  bool swing_descends = true;  ///< swing tip vertical velocity <= 0 at strike
  StrikeDesign touchdown;      ///< the designed strike (config key `touchdown`), rigid impacts
  bool trailing_lifts = true;  ///< old stance tip vertical velocity >= 0 after a single impact
  /// The DSP collocated in Mu's reduced coordinates (hip position and upper body, 2.19-2.21),
  /// its leading tip pinned at position and velocity level at every point (dsp_chart.hpp);
  /// false: theta collocated, the tip pinned at acceleration level at every point.
  bool dsp_reduced_coordinates = false;
  bool ground_contact = true;  ///< unilateral forces and friction cones at the tips in contact
  /// With ground_contact: the rigid impact's impulses inside their friction cones and pushing
  /// up (Mu 2.31 double, 2.37b single impact).
  bool impact_friction = true;
  bool zmp = true;             ///< ZMP inside the support (only if the ankle is actuated)
  ClearanceProfile clearance;  ///< swing tip height >= h(t / T_SSP) in the SSP
  /// Friction cones narrowed to |F_t| <= (mu - friction_margin) F_n, forces and impulses, so a
  /// tracking error does not make the optimum slip (dimensionless, < the robot's mu).
  double friction_margin = 0;
  /// The impact impulses' own margin, |P_t| <= (mu - m) P_n, when it differs from
  /// friction_margin (unset: friction_margin). The impulse cone is scale-free: it binds a strike
  /// of 1 mm/s as hard as one of 1 m/s, and a margin on it prices every designed strike
  /// (docs/optimal_gaits.md#what-the-strike-costs).
  std::optional<double> impulse_friction_margin;
  /// With zmp: the ZMP (and in the DSP foot B's own CoP) kept this far inside [-heel, toe], so a
  /// tracking error does not rotate the foot about its edge [m], < half the foot.
  double zmp_margin = 0;
  /// Every tip in contact keeps at least this normal force at every point (SSP stance tip, both
  /// DSP tips) [N], so the optimum does not unload a foot to zero where a tracking error then
  /// lifts it off.
  double min_normal_force = 0;
  SolverOptions solver;

  // The problem's shape: steps per period and model variants (ocp/shape/shape_config.hpp).
  ShapeConfig shape;

  /// Reach this problem from the torque-squared problem on its mesh (continuation.hpp); off
  /// unless the config has a `continuation:` section.
  ContinuationOptions continuation;
};

/// The problem of the config file `path`, with `overrides` (`--set KEY=VALUE`) in place of the
/// file's values and checked like them. @throws config::ConfigError naming file, key and
/// expectation.
OcpConfig loadOcpConfig(const std::string& path,
                        const std::vector<config::Override>& overrides = {});

/// The files a problem reads besides its config file (the robot, and the guess gait when it has
/// one), as the config names them: an output folder may not be, hold or lie inside one.
std::vector<std::string> ocpInputs(const OcpConfig& config);

/// The model the gait problem is posed on: the config's robot on its slope,
/// dynamics::withSlope(loadRobot(config.robot_path), config.slope).
/// @throws config::ConfigError for a bad robot file.
dynamics::Model problemModel(const OcpConfig& config);

/// The friction coefficient of the optimiser's cones: the robot's, less the configured margin.
/// @throws std::invalid_argument when the margin leaves no cone.
double frictionBound(const dynamics::Model& model, const OcpConfig& config);
/// mu - the impulses' margin (OcpConfig::impulse_friction_margin, else friction_margin): the
/// impact impulses' cone. @throws std::invalid_argument when it leaves no cone.
double impulseFrictionBound(const dynamics::Model& model, const OcpConfig& config);

/// The foot the optimiser keeps the ZMP and CoP on: the robot's, shortened by zmp_margin at the
/// heel and at the toe. @throws std::invalid_argument when the margin leaves no foot.
dynamics::Foot marginFoot(const dynamics::Model& model, const OcpConfig& config);

/// The shortest step the solve may return [s]: step_duration, else the phases' durations, free
/// ones at their lower bounds. What an export rate is checked against before the solve.
double shortestStep(const OcpConfig& config);

/// A step the two legs cannot span, even stretched, is bad input, not a question for Ipopt
/// (which would spend its iteration limit on it). @throws std::domain_error naming `path` and
/// the key.
void requireReachable(const dynamics::Model& model, const OcpConfig& config,
                      const std::string& path);

}  // namespace gaitopt::ocp
