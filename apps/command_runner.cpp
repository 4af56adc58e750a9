#include "apps/command_runner.hpp"

#include <exception>
#include <stdexcept>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "config/config_error.hpp"
#include "io/terminal_text.hpp"

namespace gaitopt::apps {
namespace {

int report(const char* message, ExitCode code) {
  fmt::print(stderr, "error: {}\n", io::printable(message));
  return code;
}

}  // namespace

int runReportingErrors(const std::function<void()>& body) {
  try {
    body();
    return kExitOk;
  } catch (const CommandError& e) {
    return report(e.what(), e.code());
  } catch (const config::ConfigError& e) {
    return report(e.what(), kExitInputError);
  } catch (const std::domain_error& e) {
    return report(e.what(), kExitInfeasible);
  } catch (const std::exception& e) {
    return report(e.what(), kExitFailure);
  } catch (...) {
    return report("unknown failure (non-standard exception)", kExitFailure);
  }
}

void runSubcommand(const std::function<void()>& body) {
  const int code = runReportingErrors(body);
  if (code != kExitOk) throw CLI::RuntimeError(code);
}

}  // namespace gaitopt::apps
