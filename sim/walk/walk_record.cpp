#include "sim/walk/walk_record.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "dynamics/kinematics.hpp"
#include "io/output/checked_write.hpp"

namespace gaitopt::sim {
namespace {

/// The CSV is built in memory and written by one checked write (io/output/checked_write.hpp).
std::ostringstream openCsv() {
  std::ostringstream out;
  out.precision(10);
  return out;
}

void writeNames(std::ostringstream& out, const char* prefix, int first, int count) {
  for (int i = 0; i < count; ++i) out << ',' << prefix << first + i;
}

void writeValues(std::ostringstream& out, const VecD& v) {
  for (Eigen::Index i = 0; i < v.size(); ++i) out << ',' << v(i);
}

/// A CSV field, quoted when it holds a comma or a quote.
std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + '"';
}

}  // namespace

WalkRecorder::WalkRecorder(const dynamics::Model& plant, double rate_hz)
    : plant_(&plant), period_(1 / rate_hz) {}

WalkLog WalkRecorder::log() {
  return [this](const WalkSample& s) {
    const bool new_phase =
        samples_.empty() || samples_.back().step != s.step || samples_.back().phase != s.phase;
    if (new_phase && pending_) samples_.push_back(*pending_);  // the last state of the phase
    if (new_phase || s.t - samples_.back().t >= period_ * (1 - 1e-9)) {
      samples_.push_back(s);
      pending_.reset();
    } else {
      pending_ = s;
    }
  };
}

void WalkRecorder::finish() {
  if (pending_) samples_.push_back(*pending_);
  pending_.reset();
}

void WalkRecorder::writeWalkCsv(const std::string& path) const {
  std::ostringstream out = openCsv();
  const int n = plant_->nLinks();
  out << "t,step,phase,stance_x,stance_y";
  writeNames(out, "theta", 1, n);
  writeNames(out, "theta_ref", 1, n);
  writeNames(out, "tau", 0, n);
  writeNames(out, "tau_ref", 0, n);
  out << ",fb_x,fb_y,fe_x,fe_y,hip_x,hip_y\n";
  for (const auto& s : samples_) {
    const Vec2d hip = dynamics::hip<double>(*plant_, s.theta) + Vec2d(s.stance_x, s.stance_y);
    out << s.t << ',' << s.step + 1 << ',' << gaits::toString(s.phase) << ',' << s.stance_x << ','
        << s.stance_y;
    for (const VecD& v : {s.theta, s.theta_ref, s.tau, s.tau_ref}) writeValues(out, v);
    out << ',' << s.force_stance(0) << ',' << s.force_stance(1) << ',' << s.force_swing(0) << ','
        << s.force_swing(1) << ',' << hip(0) << ',' << hip(1) << '\n';
  }
  io::writeFile(path, out.str());
}

void WalkRecorder::writeStickCsv(const std::string& path, double frame_interval) const {
  std::ostringstream out = openCsv();
  out << "t,step,link,x0,y0,x1,y1,phase\n";
  double next = -1;
  for (const auto& s : samples_) {
    if (s.t < next && &s != &samples_.back()) continue;
    next = s.t + frame_interval;
    const Vec2d base(s.stance_x, s.stance_y);
    for (int i = 0; i < plant_->nLinks(); ++i) {
      const auto [p0, p1] = dynamics::linkEnds(*plant_, s.theta, i);
      const Vec2d a = base + p0, b = base + p1;
      out << s.t << ',' << s.step + 1 << ',' << i + 1 << ',' << a(0) << ',' << a(1) << ',' << b(0)
          << ',' << b(1) << ',' << gaits::toString(s.phase) << '\n';
    }
  }
  io::writeFile(path, out.str());
}

void writeStepsCsv(const WalkResult& walk, const std::string& path) {
  std::ostringstream out = openCsv();
  out << "step,ok,impact,ssp_duration,dsp_duration,advance,max_tracking_error,slip,"
         "min_cop_margin,max_friction_ratio,max_foot_tilt,failure,"
         "max_tip_penetration_m\n";
  for (std::size_t k = 0; k < walk.steps.size(); ++k) {
    const auto& s = walk.steps[k];
    out << k + 1 << ',' << (s.ok ? 1 : 0) << ',' << s.impact << ',' << s.ssp_duration << ','
        << s.dsp_duration << ',' << s.advance << ',' << s.max_tracking_error << ',' << s.slip << ','
        << s.min_cop_margin << ',' << s.max_friction_ratio << ',' << s.max_foot_tilt << ','
        << csvField(s.failure) << ',';
    if (!std::isnan(s.max_tip_penetration)) out << s.max_tip_penetration;  // else empty
    out << '\n';
  }
  io::writeFile(path, out.str());
}

}  // namespace gaitopt::sim
