#include "parallel/progress_bar.hpp"

#include <algorithm>
#include <cstdio>

#include <fmt/format.h>

namespace gaitopt::parallel {

ProgressFn progressBar(const std::string& label, bool quiet) {
  if (quiet) return {};
  return [label](std::size_t done, std::size_t total) {
    constexpr std::size_t kWidth = 30;
    const std::size_t all = std::max<std::size_t>(total, 1);
    const std::size_t filled = kWidth * done / all;
    fmt::print(stderr, "\r{} [{}{}] {:3d}% {}/{}", label, std::string(filled, '#'),
               std::string(kWidth - filled, '.'), 100 * done / all, done, total);
    if (done == total) fmt::print(stderr, "\n");
    std::fflush(stderr);
  };
}

}  // namespace gaitopt::parallel
