#pragma once
/// @file fuzz_input.hpp
/// What the fuzz targets share. The loaders read a path, so each input is written to an
/// in-memory file (memfd) and the loader is given /proc/self/fd/N: no disk traffic, and nothing
/// is left behind by a crash. A loader passes when it returns or throws config::ConfigError, the
/// one exception its header documents; any other exception escapes to libFuzzer, which reports
/// it like a crash, a sanitizer report or a timeout.
#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "config/config_error.hpp"

namespace gaitopt::fuzz {

/// Replaces the content of this process's input file by `data`; returns the file's path.
inline std::string writeInput(const uint8_t* data, size_t size) {
  static const int fd = memfd_create("gaitopt-fuzz-input", 0);
  if (fd < 0 || ftruncate(fd, 0) != 0 || pwrite(fd, data, size, 0) != static_cast<ssize_t>(size)) {
    std::perror("fuzz harness: cannot write the input file");
    std::abort();
  }
  return "/proc/self/fd/" + std::to_string(fd);
}

/// Runs `load(path)` on the input; a ConfigError is a documented rejection, not a finding.
template <class Load>
int runLoader(const uint8_t* data, size_t size, Load load) {
  const std::string path = writeInput(data, size);
  try {
    load(path);
  } catch (const config::ConfigError&) {
  }
  return 0;
}

}  // namespace gaitopt::fuzz
