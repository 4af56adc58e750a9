#include "parallel/progress_bar.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include <fmt/format.h>

namespace gaitopt::parallel {
namespace {

using Clock = std::chrono::steady_clock;

/// How often a line goes to a file rather than a terminal [s].
constexpr double kLogInterval = 60;

std::string duration(double s) {
  const auto whole = static_cast<long>(std::lround(s));
  if (whole < 60) return fmt::format("{}s", whole);
  if (whole < 3600) return fmt::format("{}m{:02d}s", whole / 60, whole % 60);
  return fmt::format("{}h{:02d}m", whole / 3600, whole / 60 % 60);
}

struct ProgressState {
  Clock::time_point start = Clock::now();
  double last_line_s = -kLogInterval;
  std::size_t last_done = static_cast<std::size_t>(-1);
  std::size_t last_width = 0;  ///< of the line on the terminal, which blanks cover
};

}  // namespace

std::string progressText(const std::string& label, std::size_t done, std::size_t total,
                         double elapsed_s) {
  constexpr std::size_t kWidth = 30;
  const std::size_t all = std::max<std::size_t>(total, 1);
  const std::size_t filled = kWidth * std::min(done, all) / all;
  std::string text = fmt::format("{} [{}{}] {:3d}% {}/{}, {} elapsed", label,
                                 std::string(filled, '#'), std::string(kWidth - filled, '.'),
                                 100 * done / all, done, total, duration(elapsed_s));
  if (done > 0 && done < total)
    text += fmt::format(", about {} left", duration(elapsed_s * static_cast<double>(total - done) /
                                                    static_cast<double>(done)));
  return text;
}

ProgressFn progressBar(const std::string& label, bool quiet) {
  if (quiet) return {};
  const bool terminal = ::isatty(STDERR_FILENO) == 1;
  auto state = std::make_shared<ProgressState>();
  return [label, terminal, state](std::size_t done, std::size_t total) {
    const double elapsed = std::chrono::duration<double>(Clock::now() - state->start).count();
    const bool end = done == total;
    const bool due =
        terminal ? done != state->last_done : elapsed - state->last_line_s >= kLogInterval;
    if (!end && !due) return;
    if (end && state->last_done == done) return;  // the end is said once
    state->last_done = done;
    state->last_line_s = elapsed;
    const std::string text = progressText(label, done, total, elapsed);
    // The terminal's line is redrawn in place (blanks cover a longer previous one); a log gets
    // one line each time.
    if (terminal) {
      fmt::print(stderr, "\r{:<{}}{}", text, std::max(text.size(), state->last_width),
                 end ? "\n" : "");
      state->last_width = text.size();
    } else
      fmt::print(stderr, "{}\n", text);
    std::fflush(stderr);
  };
}

}  // namespace gaitopt::parallel
