#pragma once
/// @file settings_record.hpp
/// What defines the rows of a resumable folder (a stability sweep's reference, controller,
/// steps, ...; a library's grid and problem), recorded in the folder by the first run, so a
/// rerun under other settings is refused instead of mixing rows of two experiments.
#include <string>

#include <nlohmann/json.hpp>

namespace gaitopt::io {

/// Writes `settings` to `path` when it does not exist; otherwise compares them with the
/// recorded ones. @throws config::ConfigError (exit 2) naming every key that differs, with
/// both values; WriteError when it cannot be written.
void claimSettings(const std::string& path, const nlohmann::ordered_json& settings);

/// A fingerprint of a file's bytes (64-bit FNV-1a, 16 hex digits), so a settings record names
/// an input by content, not by a path that differs between machines. @throws
/// config::ConfigError when it cannot be read.
std::string fileFingerprint(const std::string& path);

/// fileFingerprint of a text's bytes.
std::string textFingerprint(const std::string& text);

/// A fingerprint of what a result's summary.json says of the result: the file without the
/// times the run measured ("wall_time_s", "callback_time_s" at any depth), the config's path
/// as typed ("config"), the linear solver's counts of its own work ("kkt") and the solver's
/// settings ("solver"), which differ from run to run, or from one version of the solver to the
/// next, of the same result (a setting added to the record is not a new result; one that moves
/// the result moves its trajectory's bytes, which a stability folder keys beside this). @throws
/// config::ConfigError when it cannot be read or is not JSON.
std::string summaryFingerprint(const std::string& path);

}  // namespace gaitopt::io
