#include "apps/row_log.hpp"

#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "config/config_error.hpp"

namespace gaitopt::apps {
namespace {

/// Splits a line written by append(): quoted fields keep their commas.
Row splitRow(const std::string& line) {
  Row fields(1);
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

/// A field as CSV: quoted when it holds a comma, a quote or a line break.
std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string q = "\"";
  for (char c : text) q += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
  return q + '"';
}

std::string joinRow(const Row& row) {
  std::string line;
  for (std::size_t i = 0; i < row.size(); ++i) {
    if (i > 0) line += ',';
    line += csvField(row[i]);
  }
  return line;
}

}  // namespace

RowLog::RowLog(std::string path, Row header) : path_(std::move(path)), header_(std::move(header)) {
  const std::string header_line = joinRow(header_);
  bool torn = false;
  if (std::filesystem::exists(path_)) {
    std::ifstream in(path_);
    std::string line;
    if (!in || !std::getline(in, line) || line != header_line)
      throw config::ConfigError(path_, "", 1,
                                fmt::format("not a file of this kind and version (expected "
                                            "the header '{}'; remove it to start over)",
                                            header_line));
    while (std::getline(in, line)) {
      torn = in.eof();  // a last line without its newline was cut by a kill
      Row row = splitRow(line);
      if (!torn && row.size() == header_.size()) rows_[row.front()] = std::move(row);
    }
  }
  // Append only: finished rows are never rewritten, so no kill can lose them.
  const bool fresh = !std::filesystem::exists(path_);
  out_.open(path_, std::ios::app);
  if (!out_) throw std::runtime_error(fmt::format("{}: cannot write", path_));
  if (fresh) out_ << header_line << '\n';
  if (torn) out_ << '\n';  // the torn fragment stays a line of its own, ignored on reading
  out_.flush();
}

void RowLog::append(const Row& row) {
  if (row.size() != header_.size())
    throw std::logic_error(fmt::format("{}: a row of {} fields, the header has {}", path_,
                                       row.size(), header_.size()));
  const std::lock_guard lock(mutex_);
  rows_[row.front()] = row;
  out_ << joinRow(row) << std::endl;  // flushed: resumable
}

}  // namespace gaitopt::apps
