#pragma once
/// @file study_table.hpp
/// The rows a study collects (one per solve, walk or sweep), written as CSV for scripts and as a
/// markdown table for people.
#include <string>
#include <vector>

namespace gaitopt::study {

struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

/// The index of the column `name` (header.size() when there is none).
std::size_t columnOf(const Table& table, const std::string& name);

/// RFC 4180 CSV: a field holding a comma, quote or line break is quoted, quotes doubled.
/// @throws io::WriteError.
void writeCsv(const Table& table, const std::string& path);

/// A markdown table; '|' inside a cell is escaped. @throws io::WriteError.
void writeMarkdown(const Table& table, const std::string& path);

}  // namespace gaitopt::study
