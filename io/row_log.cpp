#include "io/row_log.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "config/config_error.hpp"

namespace gaitopt::io {
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

/// The whole file ("" when it does not exist).
std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

RowLog::RowLog(std::string path, Row header, std::size_t key_fields)
    : path_(std::move(path)), header_(std::move(header)), key_fields_(key_fields), out_(path_) {
  if (key_fields_ < 1 || key_fields_ > header_.size())
    throw std::logic_error(
        fmt::format("{}: {} key fields of {}", path_, key_fields_, header_.size()));
  const std::string header_line = joinRow(header_);
  const std::string text = readAll(path_);
  if (text.empty()) {
    out_.append(header_line + '\n');
    return;
  }
  // A last line without its newline was cut by a kill or a full disk: it is dropped from the
  // file, so its point is redone and no reader (the plot scripts) ever sees a short row.
  const std::size_t complete = text.rfind('\n') + 1;  // 0 when no line is complete
  if (complete < text.size()) out_.truncate(static_cast<long>(complete));
  if (complete == 0) {  // not even the header was whole
    out_.append(header_line + '\n');
    return;
  }
  std::istringstream in(text.substr(0, complete));
  std::string line;
  if (!std::getline(in, line) || line != header_line)
    throw config::ConfigError(path_, "", 1,
                              fmt::format("not a file of this kind and version (expected "
                                          "the header '{}'; remove it to start over)",
                                          header_line));
  while (std::getline(in, line)) {
    Row row = splitRow(line);
    if (row.size() == header_.size()) rows_[keyOf(row)] = std::move(row);
  }
}

void RowLog::append(const Row& row) {
  if (row.size() != header_.size())
    throw std::logic_error(fmt::format("{}: a row of {} fields, the header has {}", path_,
                                       row.size(), header_.size()));
  const std::lock_guard lock(mutex_);
  out_.append(joinRow(row) + '\n');  // one write(2): on disk at once, resumable
  rows_[keyOf(row)] = row;
}

std::string RowLog::keyOf(const Row& row) const {
  std::string key = row.front();
  for (std::size_t i = 1; i < key_fields_; ++i) key += ',' + row[i];
  return key;
}

}  // namespace gaitopt::io
