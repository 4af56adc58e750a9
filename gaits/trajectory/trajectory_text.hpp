#pragma once
/// @file trajectory_text.hpp
/// The cells of an export as text, formatted once for both trajectory.csv and trajectory.json:
/// the two files hold the same 60 columns of 1 kHz samples, and formatting the numbers was most
/// of the cost of writing a result folder. Numbers are the shortest decimal
/// that reads back as exactly the same double (io/number_text.hpp).
#include <string>
#include <string_view>
#include <vector>

#include "dynamics/model.hpp"
#include "gaits/trajectory/trajectory.hpp"

namespace gaitopt::gaits {

/// A row-major table of cells in columnNames order: "t", "phase" (SSP, DSP), then the numbers of
/// rowNumbers.
class TrajectoryText {
 public:
  /// @throws std::invalid_argument for no rows, rows of another link count than `model`, or a
  /// row without vertical ground force (rowNumbers).
  TrajectoryText(const std::vector<Knot>& rows, double step_length, const dynamics::Model& model);

  const std::string& robot() const { return robot_; }
  double stepLength() const { return step_length_; }
  const std::vector<std::string>& names() const { return names_; }
  size_t rows() const { return ends_.size() / names_.size(); }
  std::string_view cell(size_t row, size_t column) const {
    const size_t i = row * names_.size() + column;
    const size_t start = i == 0 ? 0 : ends_[i - 1] + 1;  // after the separator
    return std::string_view(chars_).substr(start, ends_[i] - start);
  }
  /// The rows as trajectory.csv's lines: the cells of a row joined by commas, each line ended
  /// by a newline.
  const std::string& csvLines() const { return chars_; }

 private:
  std::string robot_;
  double step_length_ = 0;
  std::vector<std::string> names_;
  std::string chars_;         ///< every cell and its separator, row by row
  std::vector<size_t> ends_;  ///< the position of each cell's separator in chars_
};

}  // namespace gaitopt::gaits
