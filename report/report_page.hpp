#pragma once
/// @file report_page.hpp
/// The one self-contained HTML page of `gaitopt report`: the page template
/// (report/report_template.html, compiled into the tool) with the result's data, frames and
/// pictures inlined, so it opens from disk with no network access. The content's text is user
/// text (folder, robot and file names, CSV cells) and enters the page only as escaped JSON data.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace gaitopt::report {

struct ReportContent {
  std::string title;
  std::string kind;                     ///< gait, walk, library or stability
  nlohmann::ordered_json summary;       ///< the folder's summary (scalars shown as a table)
  nlohmann::json frames;                ///< framesJson() of the animation, null for none
  std::string animation_note;           ///< what is animated, or why nothing is
  std::vector<std::string> link_names;  ///< legend of the stick figure
  /// The robot's foot behind and ahead of each tip [m], drawn under a tip on the ground (the
  /// stance tip, both in the double support); 0 and 0: point tips.
  double foot_heel = 0, foot_toe = 0;
  std::vector<std::string> charts;  ///< PNG files, inlined as data URIs
  std::vector<std::string> tables;  ///< CSV files shown as tables
};

/// RFC 4648 base64 of `bytes`.
std::string base64(const std::string& bytes);

/// The page's HTML. @throws std::runtime_error when a chart or table cannot be read.
std::string renderReportPage(const ReportContent& content);

}  // namespace gaitopt::report
