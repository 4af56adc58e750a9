#include "sim/studies/sweep_file.hpp"

#include <cmath>
#include <optional>

#include <fmt/format.h>

namespace gaitopt::sim {
namespace {

const io::Row kOutcome = {"steps_completed",    "steps_requested", "fell",         "failure",
                          "max_tracking_error", "max_multiplier",  "mean_advance", "wall_time_s"};

std::string number(double v) {
  return fmt::format("{:.12g}", v);
}

io::Row header(std::vector<std::string> coordinates) {
  coordinates.insert(coordinates.end(), kOutcome.begin(), kOutcome.end());
  return coordinates;
}

/// A row back from its fields (`m` leading coordinates), or nothing for a foreign one.
std::optional<SweepRow> parseRow(const io::Row& f, std::size_t m) {
  try {
    SweepRow r{std::stod(f[0]),
               std::stoi(f[m]),
               std::stoi(f[m + 1]),
               f[m + 2] == "1",
               f[m + 3],
               std::stod(f[m + 4]),
               f[m + 5].empty() ? -1 : std::stod(f[m + 5]),
               std::stod(f[m + 6]),
               std::stod(f[m + 7])};
    if (m == 2) r.value_b = std::stod(f[1]);
    // A row edited or damaged by hand is walked again rather than believed: finite figures, a
    // count within the walk, and "fell" saying what the count says.
    const bool finite = std::isfinite(r.value) && std::isfinite(r.value_b) &&
                        std::isfinite(r.max_tracking_error) && std::isfinite(r.mean_advance) &&
                        std::isfinite(r.wall_time_s) && std::isfinite(r.max_multiplier);
    const bool counted =
        r.steps_requested > 0 && r.steps_completed >= 0 && r.steps_completed <= r.steps_requested &&
        (f[m + 2] == "0" || f[m + 2] == "1") && r.fell == (r.steps_completed < r.steps_requested);
    if (!finite || !counted) return std::nullopt;
    return r;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace

std::string SweepFile::key(double value) {
  return fmt::format("{:.10g}", value);
}

std::string SweepFile::key(double a, double b) {
  return key(a) + ',' + key(b);
}

std::string SweepFile::keyOf(const SweepRow& row) const {
  return map_ ? key(row.value, row.value_b) : key(row.value);
}

SweepFile::SweepFile(std::string path, std::vector<std::string> coordinates)
    : map_(coordinates.size() == 2),
      log_(std::move(path), header(coordinates), coordinates.size()) {
  for (const auto& [text, fields] : log_.rows())
    if (const auto row = parseRow(fields, coordinates.size())) rows_[keyOf(*row)] = *row;
}

void SweepFile::addAt(double a, double b, std::map<std::string, SweepRow>& on_grid) const {
  const std::string k = map_ ? key(a, b) : key(a);
  const auto it = rows_.find(k);
  if (it == rows_.end()) return;
  SweepRow row = it->second;
  row.value = a;
  if (map_) row.value_b = b;
  on_grid.emplace(k, row);
}

std::map<std::string, SweepRow> SweepFile::rowsAt(const std::vector<double>& values) const {
  std::map<std::string, SweepRow> on_grid;
  for (const double v : values) addAt(v, 0, on_grid);
  return on_grid;
}

std::map<std::string, SweepRow> SweepFile::rowsAt(const std::vector<double>& a,
                                                  const std::vector<double>& b) const {
  std::map<std::string, SweepRow> on_grid;
  for (const double va : a)
    for (const double vb : b) addAt(va, vb, on_grid);
  return on_grid;
}

void SweepFile::append(const SweepRow& row) {
  io::Row fields{key(row.value)};
  if (map_) fields.push_back(key(row.value_b));
  fields.insert(fields.end(),
                {std::to_string(row.steps_completed), std::to_string(row.steps_requested),
                 row.fell ? "1" : "0", row.failure, number(row.max_tracking_error),
                 row.max_multiplier < 0 ? std::string() : number(row.max_multiplier),
                 number(row.mean_advance), number(row.wall_time_s)});
  log_.append(fields);
  const std::lock_guard lock(mutex_);  // counted only once it is on disk
  rows_[keyOf(row)] = row;
}

}  // namespace gaitopt::sim
