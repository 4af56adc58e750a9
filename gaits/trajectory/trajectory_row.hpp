#pragma once
/// @file trajectory_row.hpp
/// One row of an exported trajectory (trajectory_columns.hpp) read back into a Knot: the fields
/// of a trajectory.csv line, or a row object of summary.json's switch states (switch_states.hpp).
/// One parser for both, so a stored switch state gets the checks of a CSV row: every value a
/// finite number, the phase SSP or DSP, and q, dq and the physical joints equal to what the
/// angles give (Mu 2.41) to 1e-9.
#include <string>
#include <string_view>
#include <vector>

#include "dynamics/model.hpp"
#include "gaits/trajectory/physical_joints.hpp"
#include "gaits/trajectory/trajectory.hpp"

namespace gaitopt::gaits {

/// Where a row comes from, for error messages: the file, the line (0 in a JSON file) and the
/// prefix of the key (e.g. "step_end." for summary.json; empty for the CSV).
struct RowSource {
  std::string path;
  int line = 0;
  std::string key_prefix;
};

struct Row {
  Knot knot;
  double swing_x = 0;  ///< the swing tip's x [m]: at the end of the step, the step length
};

/// A field quoted for an error message, shortened so a corrupt line cannot flood the terminal.
std::string quotedField(std::string_view text);

/// The knot of one row given as its fields in the order of `names` (columnNames(model));
/// `joints` are physicalJoints(model). @throws config::ConfigError naming the source and the
/// column for a wrong field count, a non-numeric or non-finite value, an unknown phase, or a
/// derived column that disagrees with the angles.
Row parseRow(const RowSource& source, const std::vector<std::string>& names,
             std::vector<std::string_view> fields, const dynamics::Model& model,
             const std::vector<PhysicalJoint>& joints);

}  // namespace gaitopt::gaits
