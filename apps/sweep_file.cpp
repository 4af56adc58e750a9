#include "apps/sweep_file.hpp"

#include <filesystem>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

namespace gaitopt::apps {
namespace {

constexpr const char* kHeader =
    "value,steps_completed,steps_requested,fell,failure,max_tracking_error,max_multiplier,"
    "mean_advance,wall_time_s";
constexpr std::size_t kFields = 9;

/// Splits a line written by append(): the failure field is quoted, commas inside it kept.
std::vector<std::string> splitRow(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (c == '"' && quoted && i + 1 < line.size() && line[i + 1] == '"') {
      fields.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

/// A complete row, or nothing for a torn or foreign line.
std::optional<SweepRow> parseRow(const std::string& line) {
  const auto f = splitRow(line);
  if (f.size() != kFields) return std::nullopt;
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

std::string quoted(const std::string& text) {
  std::string q = "\"";
  for (char c : text) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + '"';
}

}  // namespace

std::string SweepFile::key(double value) {
  return fmt::format("{:.10g}", value);
}

SweepFile::SweepFile(std::string path) : path_(std::move(path)) {
  bool torn = false;
  if (std::filesystem::exists(path_)) {
    std::ifstream in(path_);
    std::string line;
    if (!in || !std::getline(in, line) || line != kHeader)
      throw std::runtime_error(
          fmt::format("{}: not a sweep file of this version (remove it to start over)", path_));
    while (std::getline(in, line)) {
      torn = in.eof();  // a last line without its newline was cut by a kill
      if (const auto row = parseRow(line); row && !torn) rows_[key(row->value)] = *row;
    }
  }
  // Append only: the finished rows are never rewritten, so no kill can lose them.
  const bool fresh = !std::filesystem::exists(path_);
  out_.open(path_, std::ios::app);
  if (!out_) throw std::runtime_error(fmt::format("{}: cannot write", path_));
  out_.precision(12);
  if (fresh) out_ << kHeader << '\n';
  if (torn) out_ << '\n';  // the torn fragment stays a line of its own, ignored on reading
  out_.flush();
}

void SweepFile::append(const SweepRow& row) {
  const std::lock_guard lock(mutex_);
  rows_[key(row.value)] = row;
  out_ << row.value << ',' << row.steps_completed << ',' << row.steps_requested << ','
       << (row.fell ? 1 : 0) << ',' << quoted(row.failure) << ',' << row.max_tracking_error << ','
       << (row.max_multiplier < 0 ? std::string() : fmt::format("{:.12g}", row.max_multiplier))
       << ',' << row.mean_advance << ',' << row.wall_time_s << std::endl;  // flushed: resumable
}

}  // namespace gaitopt::apps
