#pragma once
/// @file config_path.hpp
/// A file a config names (a robot, an initial guess, a library's OCP config, a study's gaits and
/// walk batteries) is read relative to the folder of the config that names it, so a folder of
/// configs can be copied or run from anywhere.
#include <string>

namespace gaitopt::config {

/// `path` as named in `config_file`: itself when absolute, else relative to the config's folder.
/// Not normalised: "a/link/../b" must stay the file system's, not a/b. `config_file` is the
/// file's path, not a reader's label (YamlReader::file() adds the --set overrides to it).
std::string besideConfig(const std::string& config_file, const std::string& path);

}  // namespace gaitopt::config
