#include "gaits/trajectory/trajectory_json.hpp"

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "io/output/checked_write.hpp"

namespace gaitopt::gaits {
namespace {

/// A JSON number from its shortest exact text, as nlohmann writes it (a float's ".0" kept so
/// readers see a float; null where JSON has no number), without building the document as a
/// tree: the export streams 60 columns of 1 kHz samples.
void appendJsonNumber(std::string& out, std::string_view text) {
  if (text == "nan" || text == "inf" || text == "-inf") {
    out += "null";
    return;
  }
  out += text;
  if (text.find_first_of(".e") == std::string_view::npos) out += ".0";
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

void writeTrajectoryJson(const TrajectoryText& text, const std::string& path) {
  const std::vector<std::string>& names = text.names();
  std::string out = nlohmann::ordered_json{
      {"robot", text.robot()},
      {"step_length", text.stepLength()},
      {"columns",
       names}}.dump();
  out.pop_back();                                // the closing brace: "data" follows
  out.reserve(text.rows() * names.size() * 20);  // about 20 characters a number
  out += ",\"data\":{";
  for (size_t c = 0; c < names.size(); ++c) {
    if (c > 0) out += ',';
    appendJsonColumn(out, names[c], text.rows(), [&](size_t k) {
      if (c != 1) return appendJsonNumber(out, text.cell(k, c));
      out += '"';  // the phase
      out += text.cell(k, c);
      out += '"';
    });
  }
  out += "}}\n";
  io::writeFileAtomically(path, out);
}

void writeTrajectoryJson(const std::vector<Knot>& rows, double step_length,
                         const dynamics::Model& model, const std::string& path) {
  writeTrajectoryJson(TrajectoryText(rows, step_length, model), path);
}

}  // namespace gaitopt::gaits
