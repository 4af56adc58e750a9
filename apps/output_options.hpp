#pragma once
/// @file output_options.hpp
/// The options shared by every command that writes a result folder.
#include <string>

#include <CLI/CLI.hpp>

#include "apps/option_checks.hpp"

namespace gaitopt::apps {

struct OutputOptions {
  std::string out_dir;
  double rate_hz = 1000;  ///< sample rate of the result's rows [Hz]
  bool plots = true;
};

/// Adds --out DIR (required), --rate HZ and --no-plots to `cmd`; `rows` names the file --rate
/// samples.
inline void addOutputOptions(CLI::App* cmd, OutputOptions& o,
                             const std::string& rows = "trajectory.csv") {
  cmd->add_option("--out", o.out_dir, "Result folder (created)")->required()->option_text("DIR");
  cmd->add_option("--rate", o.rate_hz, "Sample rate of " + rows + " [Hz]")
      ->check(CLI::Number)
      ->check(quantityRange(config::kSampleRate))
      ->default_val(1000);
  cmd->add_flag("!--no-plots", o.plots, "Skip the pictures");
}

}  // namespace gaitopt::apps
