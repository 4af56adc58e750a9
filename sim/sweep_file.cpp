#include "sim/sweep_file.hpp"

#include <optional>

#include <fmt/format.h>

namespace gaitopt::sim {
namespace {

const io::Row kHeader = {"value",          "steps_completed", "steps_requested",
                         "fell",           "failure",         "max_tracking_error",
                         "max_multiplier", "mean_advance",    "wall_time_s"};

std::string number(double v) {
  return fmt::format("{:.12g}", v);
}

/// A row back from its fields, or nothing for a foreign one.
std::optional<SweepRow> parseRow(const io::Row& f) {
  try {
    return SweepRow{std::stod(f[0]),
                    std::stoi(f[1]),
                    std::stoi(f[2]),
                    f[3] == "1",
                    f[4],
                    std::stod(f[5]),
                    f[6].empty() ? -1 : std::stod(f[6]),
                    std::stod(f[7]),
                    std::stod(f[8])};
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace

std::string SweepFile::key(double value) {
  return fmt::format("{:.10g}", value);
}

SweepFile::SweepFile(std::string path) : log_(std::move(path), kHeader) {
  for (const auto& [text, fields] : log_.rows())
    if (const auto row = parseRow(fields)) rows_[key(row->value)] = *row;
}

void SweepFile::append(const SweepRow& row) {
  log_.append({key(row.value), std::to_string(row.steps_completed),
               std::to_string(row.steps_requested), row.fell ? "1" : "0", row.failure,
               number(row.max_tracking_error),
               row.max_multiplier < 0 ? std::string() : number(row.max_multiplier),
               number(row.mean_advance), number(row.wall_time_s)});
  const std::lock_guard lock(mutex_);  // counted only once it is on disk
  rows_[key(row.value)] = row;
}

}  // namespace gaitopt::sim
