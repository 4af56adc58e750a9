#pragma once
/// @file config_error.hpp
/// The error every input reader throws: it names the file, the key (and line when known), the
/// value found and what was expected, so a user can fix a hand-edited file without a debugger.
#include <stdexcept>
#include <string>

namespace gaitopt::config {

class ConfigError : public std::runtime_error {
 public:
  ConfigError(std::string file, std::string key, int line, std::string message);

  const std::string& file() const { return file_; }
  const std::string& key() const { return key_; }
  int line() const { return line_; }  ///< 1-based, 0 when unknown

 private:
  std::string file_;
  std::string key_;
  int line_;
};

}  // namespace gaitopt::config
