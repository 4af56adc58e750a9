#include "report/report_frames.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include "config/config_error.hpp"
#include "dynamics/kinematics.hpp"

namespace gaitopt::report {
namespace {

const std::vector<std::string> kStickColumns = {"t",  "step", "link", "x0",
                                                "y0", "x1",   "y1",   "phase"};

std::vector<std::string> splitCsvLine(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  std::string field;
  while (std::getline(in, field, ',')) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

double parseNumber(const std::string& text, const std::string& path, const std::string& column,
                   int line) {
  std::size_t used = 0;
  double value = NAN;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !std::isfinite(value))
    throw config::ConfigError(path, column, line, "expected a finite number, got '" + text + "'");
  return value;
}

}  // namespace

std::vector<StickFrame> gaitFrames(const dynamics::Model& model, const gaits::Trajectory& step,
                                   double rate_hz) {
  std::vector<StickFrame> frames;
  const gaits::Trajectory sampled = step.resample(rate_hz);
  for (const gaits::Knot& k : sampled.knots()) {
    StickFrame f{k.t, 1, k.phase, {}};
    for (int i = 0; i < model.nLinks(); ++i) {
      const auto [p0, p1] = dynamics::linkEnds(model, k.theta, i);
      f.links.push_back({p0(0), p0(1), p1(0), p1(1)});
    }
    frames.push_back(std::move(f));
  }
  return frames;
}

std::vector<StickFrame> readStickCsv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw config::ConfigError(path, "", 0, "cannot read the walk's stick diagram");
  std::string line;
  std::getline(in, line);
  if (splitCsvLine(line) != kStickColumns)
    throw config::ConfigError(path, "", 1, "expected the header t,step,link,x0,y0,x1,y1,phase");
  std::vector<StickFrame> frames;
  for (int number = 2; std::getline(in, line); ++number) {
    const auto fields = splitCsvLine(line);
    if (fields.size() != kStickColumns.size())
      throw config::ConfigError(path, "", number, "expected 8 fields");
    std::array<double, 7> v{};
    for (std::size_t c = 0; c < v.size(); ++c)
      v[c] = parseNumber(fields[c], path, kStickColumns[c], number);
    gaits::Phase phase{};
    try {
      phase = gaits::phaseFromString(fields[7]);
    } catch (const std::invalid_argument&) {
      throw config::ConfigError(path, "phase", number, "expected SSP or DSP");
    }
    // A frame is the run of rows with one time; link numbers count 1, 2, ... within it.
    if (v[2] == 1) frames.push_back({v[0], static_cast<int>(v[1]), phase, {}});
    if (frames.empty() || frames.back().t != v[0] ||
        v[2] != static_cast<double>(frames.back().links.size() + 1))
      throw config::ConfigError(path, "link", number, "links of a frame must count 1, 2, ...");
    frames.back().links.push_back({v[3], v[4], v[5], v[6]});
  }
  if (frames.empty()) throw config::ConfigError(path, "", 2, "no frames");
  for (const StickFrame& f : frames)
    if (f.links.size() != frames.front().links.size())
      throw config::ConfigError(path, "link", 0, "frames with different numbers of links");
  return frames;
}

nlohmann::json framesJson(const std::vector<StickFrame>& frames) {
  // 0.1 mm and 0.1 ms are below a pixel and a frame; rounding keeps the page small.
  const auto rounded = [](double x) { return std::round(x * 1e4) / 1e4; };
  nlohmann::json t = nlohmann::json::array(), step = t, phase = t, links = t;
  for (const StickFrame& f : frames) {
    t.push_back(rounded(f.t));
    step.push_back(f.step);
    phase.push_back(gaits::toString(f.phase));
    nlohmann::json segments = nlohmann::json::array();
    for (const auto& l : f.links)
      segments.push_back({rounded(l[0]), rounded(l[1]), rounded(l[2]), rounded(l[3])});
    links.push_back(std::move(segments));
  }
  return {{"t", t}, {"step", step}, {"phase", phase}, {"links", links}};
}

}  // namespace gaitopt::report
