#include "study/study_points.hpp"

namespace gaitopt::study {
namespace {

/// The point of `gait` whose value index on each axis is `index`.
StudyPoint pointAt(const StudyConfig& c, const StudyGait& gait,
                   const std::vector<std::size_t>& index) {
  StudyPoint p{gait.name, gait.path, "", {}, gait.sets, {}, {}};
  p.folder = p.gait;
  for (std::size_t a = 0; a < c.axes.size(); ++a) {
    const StudyAxis& axis = c.axes[a];
    p.labels.push_back(axis.labels[index[a]]);
    const auto& sets = axis.values[index[a]];
    p.overrides.insert(p.overrides.end(), sets.begin(), sets.end());
    p.folder += "_" + axis.name + "=" + axis.labels[index[a]];
  }
  return p;
}

/// The next combination, the last axis fastest; false after the last one.
bool advance(const StudyConfig& c, std::vector<std::size_t>& index) {
  for (std::size_t a = c.axes.size(); a-- > 0;) {
    if (++index[a] < c.axes[a].values.size()) return true;
    index[a] = 0;
  }
  return false;
}

}  // namespace

std::vector<StudyPoint> studyPoints(const StudyConfig& c) {
  std::vector<StudyPoint> points;
  for (const PolynomialGait& poly : c.polynomial_gaits) {
    const std::string name = gaitName(poly);
    // Axis columns stay empty: the axes set OCP config values.
    points.push_back(
        {name, poly.gait, poly.robot, std::vector<std::string>(c.axes.size()), {}, name, {}});
  }
  for (const StudyGait& gait : c.gaits) {
    std::vector<std::size_t> index(c.axes.size(), 0);
    do {
      points.push_back(pointAt(c, gait, index));
      if (!c.axes.empty() && index.back() > 0) points.back().previous = points.size() - 2;
    } while (advance(c, index));
  }
  return points;
}

}  // namespace gaitopt::study
