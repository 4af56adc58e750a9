#include "gaits/trajectory/trajectory_text.hpp"

#include <future>
#include <span>
#include <stdexcept>

#include <fmt/format.h>

#include "gaits/trajectory/physical_joints.hpp"
#include "gaits/trajectory/trajectory_columns.hpp"
#include "io/number_text.hpp"

namespace gaitopt::gaits {
namespace {

void requireRows(const std::vector<Knot>& rows, const dynamics::Model& model) {
  if (rows.empty()) throw std::invalid_argument("cannot write an empty trajectory");
  if (rows.front().theta.size() != model.nLinks())
    throw std::invalid_argument(fmt::format("trajectory has {} links but robot '{}' has {}",
                                            rows.front().theta.size(), model.name(),
                                            model.nLinks()));
}

/// Some rows as text: every cell and its separator, and each separator's position.
struct TextBlock {
  std::string chars;
  std::vector<size_t> ends;

  void endCell(bool last) {
    ends.push_back(chars.size());
    chars += last ? '\n' : ',';
  }
};

TextBlock formatRows(std::span<const Knot> rows, double step_length, const dynamics::Model& model,
                     size_t columns) {
  const std::vector<PhysicalJoint> joints = physicalJoints(model);
  TextBlock block;
  block.ends.reserve(rows.size() * columns);
  block.chars.reserve(rows.size() * columns * 20);  // about 20 characters a number
  for (const Knot& knot : rows) {
    io::appendShortest(block.chars, knot.t);
    block.endCell(false);
    block.chars += toString(knot.phase);
    block.endCell(false);
    const Eigen::VectorXd values = rowNumbers(knot, model, joints, step_length);
    for (Eigen::Index i = 0; i < values.size(); ++i) {
      io::appendShortest(block.chars, values(i));
      block.endCell(i + 1 == values.size());
    }
  }
  return block;
}

}  // namespace

TrajectoryText::TrajectoryText(const std::vector<Knot>& rows, double step_length,
                               const dynamics::Model& model)
    : robot_(model.name()), step_length_(step_length), names_(columnNames(model)) {
  requireRows(rows, model);
  // The halves are formatted at once on two cores: formatting is most of a write.
  const std::span<const Knot> all(rows);
  const size_t half = rows.size() / 2;
  auto first = std::async(std::launch::async, [&] {
    return formatRows(all.first(half), step_length, model, names_.size());
  });
  TextBlock second = formatRows(all.subspan(half), step_length, model, names_.size());
  TextBlock block = first.get();
  const size_t offset = block.chars.size();
  chars_ = std::move(block.chars);
  chars_ += second.chars;
  ends_ = std::move(block.ends);
  for (const size_t end : second.ends) ends_.push_back(offset + end);
}

}  // namespace gaitopt::gaits
