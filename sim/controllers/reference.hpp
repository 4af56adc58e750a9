#pragma once
/// @file reference.hpp
/// An exported gait (trajectory CSV, docs/design.md#the-export-contract) as the reference a
/// controller tracks: one step, SSP then optionally DSP, read on the step clock (0 at every SSP
/// start). Three choices make it survive timing errors (docs/design.md#the-verification-ladder,
/// rung 4):
///  - Past the planned touchdown the SSP reference does not freeze: it goes on at the touchdown
///    rates, its touchdown accelerations faded out over 20 ms (reference.cpp says why), with the
///    swing tip's downward speed raised to at least `strike_velocity`. A gait
///    designed to land at rest (Mu ch. 3: touchdown time goes as the square root of a height
///    error) would otherwise hover a lagging robot at its final posture while the feed-forward
///    still has rates. The extra swing-leg rate Delta is phased in over the `strike_window`
///    after the planned touchdown, Delta phi(t) with phidot = 3s^2 - 2s^3 (s from 0 to 1 over
///    the window): a step in the reference rates at touchdown made Mu's sliding-mode law
///    (Lambda = 100) jerk the swing leg and slip the stance tip, and a strike phased in before
///    it made the robot that was on time strike early, in a single impact that skipped the
///    double support.
///  - A phase starts from where the robot is: the robot's departure from the reference at the
///    phase start (angles and rates) is faded out by a cubic Hermite blend over `fade` seconds
///    (PhaseStart), as Westervelt et al. correct their virtual constraints after an impact. An
///    early or late touchdown thus starts the DSP reference at the robot, not at a jump. Only
///    the departure a timing error makes is faded (each angle within `fade_angle`, each rate
///    within `fade_rate`); beyond it is an error the controller corrects: on the impedance
///    ground a step ended with rates 17 rad/s off the plan, and fading those dragged the
///    reference 0.4 rad away for 0.15 s and the robot fell.
///  - The DSP (fully actuated in hip x, hip y and torso, Mu 2.21) starts where the plan's hip has
///    progressed as far as the robot's (dspClockAt): a late touchdown finds the hip ahead of the
///    plan's DSP start, and fading a posture 0.03 s behind back onto the plan's start within the
///    0.1 s DSP asked for 12 m/s^2 at the hip and saturated the stance ankle and knee.
#include <algorithm>
#include <optional>
#include <vector>

#include "dynamics/model.hpp"
#include "gaits/trajectory/trajectory.hpp"

namespace gaitopt::sim {

struct ReferenceOptions {
  /// Least downward speed of the swing tip past the planned touchdown [m/s] (>= 0).
  double strike_velocity = 0.1;
  /// Time over which a phase start's departure from the reference fades out [s] (> 0; the DSP
  /// uses at most its own duration).
  double fade = 0.15;
  double fade_angle = 0.05;  ///< largest angle departure faded [rad] (>= 0)
  double fade_rate = 1.0;    ///< largest rate departure faded [rad/s] (>= 0)
  /// Time after the planned touchdown over which the strike rates are phased in [s] (> 0).
  double strike_window = 0.1;
};

class Reference;

/// The robot's departure from the reference at the start of a phase, faded out over the phase:
/// offset(tau) = h00(s) d_theta + F h10(s) d_dtheta, s = tau / F, with the cubic Hermite basis
/// h00 = 2s^3 - 3s^2 + 1, h10 = s^3 - 2s^2 + s (zero value and slope at s = 1).
struct PhaseStart {
  double t0 = 0;           ///< step clock at the phase start [s]
  double fade = 0;         ///< F [s]; 0: no offset
  VecD d_theta, d_dtheta;  ///< robot minus reference at t0 [rad], [rad/s]
};

class Reference {
 public:
  /// Without a model the reference past touchdown keeps the touchdown rates as they are.
  /// @throws std::invalid_argument when the trajectory does not start with an SSP, or for
  ///         options out of range.
  explicit Reference(const gaits::Trajectory& step, ReferenceOptions options = {});
  /// With the robot's model, the swing tip past touchdown descends at >= strike_velocity.
  Reference(const gaits::Trajectory& step, const dynamics::Model& model,
            ReferenceOptions options = {});

  /// The reference knot of `phase` at step clock t: held at the start of a phase before it,
  /// extrapolated past the SSP end (see file doc), held at the DSP end after it.
  gaits::Knot at(gaits::Phase phase, double t) const;
  /// The same with the robot's departure at the phase start faded in (PhaseStart).
  gaits::Knot at(gaits::Phase phase, double t, const PhaseStart& start) const;
  /// The step clock at which the DSP starts for a robot touching down at angles theta: where
  /// the plan's hip x equals the robot's (the reference's model), kept within the DSP's first
  /// three quarters; the planned touchdown time without a model or DSP.
  double dspClockAt(const VecD& theta) const;
  /// The departure of (theta, dtheta) from the reference at clock t0 of `phase`.
  PhaseStart startFrom(gaits::Phase phase, double t0, const VecD& theta, const VecD& dtheta) const;

  double touchdownTime() const { return ssp_end_; }  ///< SSP duration [s]
  double endTime() const { return end_; }            ///< step duration [s]
  /// When a single support's start no longer shows in its reference (PhaseStart) [s].
  double fadeTime() const { return std::min(options_.fade, ssp_end_); }
  bool hasDsp() const { return dsp_.has_value(); }
  double stepLength() const { return ssp_.stepLength(); }
  /// The state the step starts from.
  const gaits::Knot& start() const { return ssp_.knots().front(); }

 private:
  gaits::Knot singleSupport(double t) const;

  gaits::Trajectory ssp_;
  std::optional<gaits::Trajectory> dsp_;
  double ssp_end_ = 0, end_ = 0;
  ReferenceOptions options_;
  VecD strike_change_;  ///< Delta: added swing-leg rates at and past touchdown [rad/s]
  std::optional<dynamics::ChainPoint> hip_;  ///< the model's hip weights, when given
  std::vector<double> dsp_hip_x_;            ///< plan's hip x at each DSP knot [m]
};

}  // namespace gaitopt::sim
