#include "apps/study_commands/report_command.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "apps/command_runner.hpp"
#include "apps/shipped_file.hpp"
#include "config/config_error.hpp"
#include "io/output/checked_write.hpp"
#include "io/output/output_folder.hpp"
#include "io/terminal_text.hpp"
#include "report/plot_script.hpp"
#include "report/report_folder.hpp"

namespace gaitopt::apps {

void runReport(const ReportOptions& o) {
  // The page is the one file this command writes: never over an input (summary.json, a CSV).
  if (!o.out.empty() && !o.out.ends_with(".html"))
    throw config::ConfigError(o.out, "--out", 0, "expected a .html file for the page");
  if (std::filesystem::is_directory(o.out))
    throw config::ConfigError(o.out, "--out", 0, "is a folder: expected a .html file");
  const report::ReportContent content = report::collectReport(o.dir, o.robot_path);
  const std::string out = o.out.empty() ? o.dir + "/report.html" : o.out;
  io::writeFileAtomically(out, report::renderReportPage(content));
  if (o.out.empty()) io::addWrittenFile(o.dir, "report.html");
  fmt::print("report: wrote {} ({} result, {})\n", out, content.kind,
             io::counted(content.charts.size(), "chart"));
  if (o.gif && content.kind == "walk" &&
      report::runPlotScript("walk_gif.py", {o.dir}, io::Output::kErrors)) {
    io::addWrittenFile(o.dir, "walk.gif");
    fmt::print("report: wrote {}/walk.gif\n", o.dir);
  }
}

void registerReportCommand(CLI::App& app) {
  auto options = std::make_shared<ReportOptions>();
  CLI::App* cmd = app.add_subcommand(
      "report", "One self-contained HTML page of a result folder: animated stick figure, charts");
  cmd->add_option("DIR", options->dir, "Result folder (gait, walk, library or stability)")
      ->required();
  cmd->add_option("--robot", options->robot_path,
                  "Robot file of a gait (default configs/robots/<summary's robot>.yaml)")
      ->transform(orShippedFile())
      ->option_text("FILE");
  cmd->add_option("--out", options->out, "The page (default DIR/report.html)")->option_text("FILE");
  cmd->add_flag("!--no-gif", options->gif,
                "Do not draw DIR/walk.gif, a walk folder's animation, written beside its walk.csv "
                "whatever --out says");
  cmd->footer(
      "The page opens from disk with no network access; URL hash #t=SECONDS shows that time.\n"
      "Exit codes: 0 ok, 2 DIR is not a result folder, a file in it is malformed or its gait\n"
      "is of another robot than the one used, 1 I/O.");
  cmd->callback([options] { runSubcommand([&] { runReport(*options); }); });
}

}  // namespace gaitopt::apps
