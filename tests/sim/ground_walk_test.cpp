// The polynomial gait of Mu (2004) under computed torque on the three grounds: it walks ten
// steps on the compliant and the LCP ground with the rigid walk's step times, step lengths and
// hip path to within stated tolerances; and an RK4 step too long for a stiff ground is reported
// as "diverged", not a crash or a hang.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <iterator>
#include <vector>

#include <fmt/format.h>

#include "dynamics/kinematics.hpp"
#include "five_link_gait.hpp"
#include "sim/contact/ground_config.hpp"
#include "sim/walk/walk.hpp"

namespace gaitopt::sim {
namespace {

GroundModel shippedGround(const std::string& name) {
  return loadGround(std::string(GAITOPT_SOURCE_DIR) + "/configs/grounds/" + name + ".yaml");
}

/// A walk with its hip path (world x, y) and the CPU time it took.
struct LoggedWalk {
  WalkResult result;
  std::vector<Vec2d> hip;
  double cpu_per_simulated_second = 0;
};

LoggedWalk walkOn(const GroundModel& ground, int steps) {
  const Reference ref(test::polynomialGait());
  const dynamics::Model& plant = test::longHeelRobot();  // the gait's ZMP needs a 0.2 m heel
  LoggedWalk w;
  const auto log = [&](const WalkSample& s) {
    w.hip.push_back(Vec2d(s.stance_x, s.stance_y) + dynamics::hip<double>(plant, s.theta));
  };
  const auto start = std::chrono::steady_clock::now();
  w.result = walk(plant, test::computedTorque(), ref, ground, {steps, {}, {}}, log);
  const double cpu =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  double simulated = 0;
  for (const auto& s : w.result.steps) simulated += s.ssp_duration + s.dsp_duration;
  w.cpu_per_simulated_second = cpu / simulated;
  return w;
}

#ifdef NDEBUG  // for the ten-step walks, Release only
/// Largest |hip y - rigid hip y at the same hip x| [m]: the path, whatever the timing.
double hipPathDistance(std::vector<Vec2d> rigid, const std::vector<Vec2d>& other) {
  std::sort(rigid.begin(), rigid.end(), [](const Vec2d& a, const Vec2d& b) { return a(0) < b(0); });
  double worst = 0;
  for (const Vec2d& p : other) {
    const auto hi = std::lower_bound(rigid.begin(), rigid.end(), p(0),
                                     [](const Vec2d& a, double x) { return a(0) < x; });
    if (hi == rigid.begin() || hi == rigid.end()) continue;  // outside the rigid walk's path
    const Vec2d& lo = *(hi - 1);
    const double y = lo(1) + (p(0) - lo(0)) / ((*hi)(0) - lo(0)) * ((*hi)(1) - lo(1));
    worst = std::max(worst, std::abs(p(1) - y));
  }
  return worst;
}
#endif

/// Tolerances against the rigid walk, per ground.
struct Agreement {
  const char* ground;
  double touchdown;  ///< |ssp duration - rigid| [s]
  double advance;    ///< |step length - rigid| [m]
  double hip_path;   ///< hipPathDistance [m]
};

TEST(GroundWalk, PolynomialGaitWalksTenStepsOnEveryGroundAsOnRigidGround) {
#ifdef NDEBUG
  constexpr int kSteps = 10;
  const LoggedWalk rigid = walkOn(shippedGround("rigid"), kSteps);
  ASSERT_EQ(rigid.result.steps_completed, kSteps) << rigid.result.failure;
  RecordProperty("rigid_cpu_per_simulated_s",
                 fmt::format("{:.3f}", rigid.cpu_per_simulated_second));
  // Compliant: the tips sink by ~1 mm under the robot's weight and the gait sets its swing tip
  // down with zero vertical speed (Mu ch. 3), so E meets the sunk ground ~21 ms early; 25 ms.
  // LCP: touchdown is found to within the 1 ms step, torques are held over it; 2 ms.
  // Hip paths: compliant within 2 mm of the rigid one (the sinking plus the tracking error the
  // early touchdown causes), LCP within 0.5 mm. Step lengths within 1 mm on the LCP ground and
  // 2.5 mm on the impedance ground: the rigid walk starts each phase's reference from the robot
  // (reference.hpp), the compliant one does not (its tips bounce at touchdown).
  for (const Agreement& a :
       {Agreement{"impedance", 0.025, 2.5e-3, 2e-3}, Agreement{"lcp", 0.002, 1e-3, 5e-4}}) {
    const LoggedWalk w = walkOn(shippedGround(a.ground), kSteps);
    ASSERT_EQ(w.result.steps_completed, kSteps) << a.ground << ": " << w.result.failure;
    double touchdown = 0, advance = 0, dsp = 0;
    for (int k = 0; k < kSteps; ++k) {
      const auto &s = w.result.steps[k], &r = rigid.result.steps[k];
      touchdown = std::max(touchdown, std::abs(s.ssp_duration - r.ssp_duration));
      dsp = std::max(dsp, std::abs(s.dsp_duration - r.dsp_duration));
      advance = std::max(advance, std::abs(s.advance - r.advance));
    }
    const double path = hipPathDistance(rigid.hip, w.hip);
    const std::string g = a.ground;
    RecordProperty(g + "_touchdown_difference_s", fmt::format("{:.2e}", touchdown));
    RecordProperty(g + "_dsp_difference_s", fmt::format("{:.2e}", dsp));
    RecordProperty(g + "_advance_difference_m", fmt::format("{:.2e}", advance));
    RecordProperty(g + "_hip_path_distance_m", fmt::format("{:.2e}", path));
    RecordProperty(g + "_tracking_error_rad", fmt::format("{:.2e}", w.result.max_tracking_error));
    RecordProperty(g + "_cpu_per_simulated_s", fmt::format("{:.3f}", w.cpu_per_simulated_second));
    EXPECT_LT(touchdown, a.touchdown) << g;
    EXPECT_LT(dsp, a.touchdown) << g;  // the DSP ends with the reference on every ground
    EXPECT_LT(advance, a.advance) << g;
    EXPECT_LT(path, a.hip_path) << g;
    EXPECT_EQ(w.result.steps.front().impact, g == "lcp" ? "lcp" : "compliant");
  }
#else
  GTEST_SKIP() << "ten-step walks on three grounds: optimised builds only";
#endif
}

TEST(GroundWalk, ACompliantWalkStartsWithTheStanceTipCarryingItsLoad) {
  // Pressed in to the static depth k delta^n = F of the reference's first stance force, the
  // ground carries that force from the first sample (at zero depth it carried next to nothing,
  // and any ankle torque put the centre of pressure off the foot at once).
  const Reference ref(test::polynomialGait());
  const double planned = ref.start().force_stance(1);
  ASSERT_GT(planned, 100.0);
  std::vector<double> normal;
  const auto log = [&](const WalkSample& s) { normal.push_back(s.force_stance(1)); };
  walk(test::longHeelRobot(), test::computedTorque(), ref, shippedGround("impedance"), {1, {}, {}},
       log);
  ASSERT_GE(normal.size(), 2U);
  EXPECT_NEAR(normal.front(), planned, 0.05 * planned);
}

TEST(GroundWalk, TheTimeStepThatLandsTheSwingTipIsJudgedUnderTheDoubleSupportLaw) {
  // The time step that lands E ends the single support: the next one applies the DSP law, so
  // that law's torque is the one judged (centre of pressure) and logged at the landing state.
  // Judged under the SSP law there, the torque answering the touchdown's velocity jump, which no
  // time step applies, put a stance foot's centre of pressure 3.5 cm beyond its toe: a fall of
  // the ensemble optimum on the LCP ground that its walk never made.
  const Reference ref(test::polynomialGait());
  for (const char* name : {"lcp", "impedance"}) {
    std::vector<WalkSample> samples;
    const auto log = [&](const WalkSample& s) { samples.push_back(s); };
    walk(test::longHeelRobot(), test::computedTorque(), ref, shippedGround(name), {1, {}, {}}, log);
    // The swing tip leaves the ground (on the impedance ground it starts pressed in), then lands.
    const auto airborne = std::find_if(samples.begin(), samples.end(),
                                       [](const WalkSample& s) { return s.force_swing(1) <= 0; });
    const auto landing = std::find_if(airborne, samples.end(),
                                      [](const WalkSample& s) { return s.force_swing(1) > 0; });
    ASSERT_NE(landing, samples.end()) << name << ": the swing tip never landed";
    EXPECT_EQ(landing->phase, gaits::Phase::kDsp) << name << " at " << landing->t << " s";
    EXPECT_EQ(std::prev(landing)->phase, gaits::Phase::kSsp) << name;
  }
}

TEST(GroundWalk, TheLoggedTorqueIsTheOneAppliedWithTheAnkleClippedToTheFoot) {
  // The polynomial gait asks the ankle for a centre of pressure up to 0.197 m behind the stance
  // tip; on the shipped 5 cm heel the ankle saturates (--cop-limit saturate). The log holds the
  // torque the plant receives, as on rigid ground: it held the request, whose CoP -tau0 / F_By
  // lay up to 0.2 m off the foot on the impedance ground (the margins gait, sliding mode).
  const Reference ref(test::polynomialGait());
  const dynamics::Model& plant = test::fiveLinkRobot();
  const dynamics::Foot& foot = plant.foot();
  for (const char* name : {"impedance", "pad"}) {
    double beyond = 0;  // the farthest logged CoP beyond the heel or the toe [m]
    int loaded = 0;
    const auto log = [&](const WalkSample& s) {
      if (s.force_stance(1) <= 0) return;
      ++loaded;
      const double cop = -s.tau(0) / s.force_stance(1);
      beyond = std::max({beyond, -foot.heel - cop, cop - foot.toe});
    };
    const WalkResult w =
        walk(plant, test::computedTorque(), ref, shippedGround(name), {1, {}, {}}, log);
    RecordProperty(std::string(name) + "_cop_saturated_time_s",
                   fmt::format("{:.3g}", w.cop_saturated_time));
    ASSERT_GT(loaded, 100) << name;
    EXPECT_GT(w.cop_saturated_time, 0.0) << name;  // the request did leave the foot
    EXPECT_LT(w.min_cop_margin, 0.0) << name;
    EXPECT_LE(beyond, 1e-12) << name;
  }
}

TEST(GroundWalk, TooLongRk4StepOnAStiffGroundIsReportedAsDiverged) {
  auto ground = *shippedGround("impedance").getIf<CompliantGround>();
  ground.contact.stiffness *= 100;  // 1e9 N/m^1.5, the same restitution (damping ratio c / k)
  ground.contact.damping *= 100;
  ground.time_step = 1e-3;
  const WalkResult w = walkOn(ground, 3).result;
  EXPECT_TRUE(w.fell);
  EXPECT_EQ(w.steps_completed, 0);
  EXPECT_NE(w.failure.find("diverged"), std::string::npos) << w.failure;
}

}  // namespace
}  // namespace gaitopt::sim
