#include "apps/command_runner.hpp"

#include <exception>
#include <stdexcept>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "config/config_error.hpp"
#include "io/terminal_text.hpp"

namespace gaitopt::apps {
namespace {

int report(const char* message, io::ExitCode code) {
  fmt::print(stderr, "error: {}\n", io::printable(message));
  return code;
}

}  // namespace

int runReportingErrors(const std::function<void()>& body) {
  try {
    body();
    return io::kExitOk;
  } catch (const io::CommandError& e) {
    if (*e.what() == '\0') return e.code();  // reported already
    return report(e.what(), e.code());
  } catch (const config::ConfigError& e) {
    return report(e.what(), io::kExitInputError);
  } catch (const std::domain_error& e) {
    return report(e.what(), io::kExitInfeasible);
  } catch (const std::exception& e) {
    return report(e.what(), io::kExitFailure);
  } catch (...) {
    return report("unknown failure (non-standard exception)", io::kExitFailure);
  }
}

void runSubcommand(const std::function<void()>& body) {
  const int code = runReportingErrors(body);
  if (code != io::kExitOk) throw CLI::RuntimeError(code);
}

}  // namespace gaitopt::apps
