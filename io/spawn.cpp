#include "io/spawn.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <system_error>

extern char** environ;

namespace gaitopt::io {
namespace {

/// posix_spawn's file actions, released on every path out.
struct FileActions {
  posix_spawn_file_actions_t actions{};
  FileActions() { posix_spawn_file_actions_init(&actions); }
  ~FileActions() { posix_spawn_file_actions_destroy(&actions); }
  FileActions(const FileActions&) = delete;
  FileActions& operator=(const FileActions&) = delete;
};

/// Starts argv with the file actions `fa` and waits for it.
int spawnAndWait(const std::vector<std::string>& argv, const FileActions& fa) {
  if (argv.empty()) throw std::invalid_argument("runProgram: empty argument vector");
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int error = ::posix_spawn(&pid, args[0], &fa.actions, nullptr, args.data(), environ);
  if (error != 0)
    throw std::system_error(error, std::generic_category(), "cannot start " + argv[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) throw std::system_error(errno, std::generic_category(), "waitpid");
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return WEXITSTATUS(status);
}

}  // namespace

int runProgram(const std::vector<std::string>& argv, Output output) {
  if (output == Output::kNone) return runProgramInto(argv, "/dev/null");
  FileActions fa;
  if (output == Output::kErrors)
    posix_spawn_file_actions_addopen(&fa.actions, 1, "/dev/null", O_WRONLY, 0);
  return spawnAndWait(argv, fa);
}

int runProgramInto(const std::vector<std::string>& argv, const std::string& log) {
  FileActions fa;
  if (!log.empty()) {
    posix_spawn_file_actions_addopen(&fa.actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
    posix_spawn_file_actions_adddup2(&fa.actions, 1, 2);
  }
  return spawnAndWait(argv, fa);
}

}  // namespace gaitopt::io
