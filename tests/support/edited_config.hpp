#pragma once
/// @file edited_config.hpp
/// A shipped OCP config loaded with one piece of its text replaced, for tests of config errors:
/// the error message, or "" when the edited file loads.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include "config/config_error.hpp"
#include "ocp/problem/ocp_config.hpp"

namespace gaitopt::test {

/// The message of loading `config` (a configs/ocp/ file) with `from` replaced by `to`; the
/// edited copy is written to gaitopt_edited_<pid>.yaml in the temporary folder, with the robot
/// and guess paths made absolute.
inline std::string loadEditedOcpConfig(const std::string& config, const std::string& from,
                                       const std::string& to) {
  const auto path =
      std::filesystem::temp_directory_path() / fmt::format("gaitopt_edited_{}.yaml", ::getpid());
  {
    std::ifstream in(config);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (const std::string key : {"robot: ", "initial_guess: "}) {  // relative to the config
      const auto at = text.find(key);
      text.insert(at + key.size(), std::string(GAITOPT_SOURCE_DIR) + "/configs/ocp/");
    }
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    std::ofstream(path) << text;
  }
  std::string message;
  try {
    ocp::loadOcpConfig(path.string());
  } catch (const config::ConfigError& e) {
    message = e.what();
  }
  std::filesystem::remove(path);
  return message;
}

}  // namespace gaitopt::test
