#include "gaits/trajectory_json.hpp"

#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "gaits/trajectory_columns.hpp"
#include "io/checked_write.hpp"
#include "io/number_text.hpp"

namespace gaitopt::gaits {
namespace {

/// A JSON number as nlohmann writes it (the shortest text that reads back exactly, a float's
/// ".0" kept so readers see a float; null where JSON has no number) but without building the
/// document as a tree: the export streams 60 columns of 1 kHz samples.
void appendJsonNumber(std::string& out, double value) {
  if (!std::isfinite(value)) {
    out += "null";
    return;
  }
  const auto start = out.size();
  io::appendShortest(out, value);
  if (out.find_first_of(".e", start) == std::string::npos) out += ".0";
}

/// `"name":[v0,v1,...]` for one column; `append(k)` writes row k's entry.
template <class Append>
void appendJsonColumn(std::string& out, const std::string& name, size_t rows, Append append) {
  out += nlohmann::json(name).dump();
  out += ":[";
  for (size_t k = 0; k < rows; ++k) {
    if (k > 0) out += ',';
    append(k);
  }
  out += ']';
}

}  // namespace

void writeTrajectoryJson(const std::vector<Knot>& rows, double step_length,
                         const dynamics::Model& model, const std::string& path) {
  const std::vector<std::string> names = columnNames(model);
  const std::vector<PhysicalJoint> joints = physicalJoints(model);
  std::vector<Eigen::VectorXd> numbers;
  numbers.reserve(rows.size());
  for (const Knot& knot : rows) numbers.push_back(rowNumbers(knot, model, joints, step_length));

  std::string out = nlohmann::ordered_json{
      {"robot", model.name()},
      {"step_length", step_length},
      {"columns",
       names}}.dump();
  out.pop_back();                                // the closing brace: "data" follows
  out.reserve(rows.size() * names.size() * 20);  // about 20 characters a number
  out += ",\"data\":{";
  appendJsonColumn(out, names[0], rows.size(), [&](size_t k) { appendJsonNumber(out, rows[k].t); });
  out += ',';
  appendJsonColumn(out, names[1], rows.size(), [&](size_t k) {
    out += '"';
    out += toString(rows[k].phase);
    out += '"';
  });
  for (size_t c = 2; c < names.size(); ++c) {
    out += ',';
    const auto i = static_cast<Eigen::Index>(c - 2);
    appendJsonColumn(out, names[c], rows.size(),
                     [&](size_t k) { appendJsonNumber(out, numbers[k](i)); });
  }
  out += "}}\n";
  io::writeFileAtomically(path, out);
}

}  // namespace gaitopt::gaits
