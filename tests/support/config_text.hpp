#pragma once
/// @file config_text.hpp
/// Config files written from text in the test's temporary folder, and the message of the
/// config::ConfigError reading one throws: the two halves of every test of a reader's errors.
#include <fstream>
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "config/config_error.hpp"

namespace gaitopt::test {

/// Writes `text` to the file `name` in the test's temporary folder and returns its path.
inline std::string writeTempFile(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

/// The ConfigError message `read` throws, or "no error".
inline std::string configErrorOf(const std::function<void()>& read) {
  try {
    read();
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace gaitopt::test
