#include "study/study_table.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "io/output/checked_write.hpp"

namespace gaitopt::study {
namespace {

std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string markdownCell(const std::string& text) {
  std::string cell;
  for (char c : text) cell += c == '|' ? std::string("\\|") : std::string(1, c == '\n' ? ' ' : c);
  return cell;
}

template <class Format>
std::string joined(const std::vector<std::string>& fields, Format format,
                   const std::string& separator) {
  std::vector<std::string> out;
  for (const std::string& f : fields) out.push_back(format(f));
  return fmt::format("{}", fmt::join(out, separator));
}

}  // namespace

std::size_t columnOf(const Table& table, const std::string& name) {
  return static_cast<std::size_t>(std::find(table.header.begin(), table.header.end(), name) -
                                  table.header.begin());
}

void writeCsv(const Table& table, const std::string& path) {
  std::string text = joined(table.header, csvField, ",") + "\n";
  for (const auto& row : table.rows) text += joined(row, csvField, ",") + "\n";
  io::writeFileAtomically(path, text);
}

void writeMarkdown(const Table& table, const std::string& path) {
  std::string text = "| " + joined(table.header, markdownCell, " | ") + " |\n|";
  for (std::size_t i = 0; i < table.header.size(); ++i) text += "---|";
  text += "\n";
  for (const auto& row : table.rows) text += "| " + joined(row, markdownCell, " | ") + " |\n";
  io::writeFileAtomically(path, text);
}

}  // namespace gaitopt::study
