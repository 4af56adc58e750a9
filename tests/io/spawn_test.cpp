// Programs run from an argument vector: exit status, signals, and no shell expansion.
#include "io/spawn.hpp"

#include <system_error>
#include <tuple>

#include "io_test_dir.hpp"

namespace gaitopt::io::test {
namespace {

using SpawnTest = IoTest;

TEST_F(SpawnTest, ExitStatusAndSignalArePassedBack) {
  EXPECT_EQ(runProgram({"/bin/sh", "-c", "exit 7"}), 7);
  EXPECT_EQ(runProgram({"/bin/sh", "-c", "kill -9 $$"}), 128 + 9);
}

// The argument reaches the program byte for byte: "$(touch PWNED)" is not run.
TEST_F(SpawnTest, ArgumentsAreNotExpandedByAShell) {
  const std::string arg = path("x'$(touch PWNED)'y");
  EXPECT_EQ(runProgram({"/usr/bin/touch", arg}), 0);
  EXPECT_TRUE(std::filesystem::exists(arg));
  EXPECT_FALSE(std::filesystem::exists(path("PWNED")));
  EXPECT_FALSE(std::filesystem::exists("PWNED"));
}

// kErrors keeps the program's stderr and drops its stdout; kNone drops both. The capture
// redirects this process's descriptors, which the child inherits.
TEST_F(SpawnTest, OutputChoosesTheStreamsThatReachOurs) {
  const std::vector<std::string> both = {"/bin/sh", "-c", "echo listed; echo warned >&2"};
  for (const auto& [output, out, err] :
       {std::tuple{Output::kAll, "listed\n", "warned\n"},
        std::tuple{Output::kErrors, "", "warned\n"}, std::tuple{Output::kNone, "", ""}}) {
    testing::internal::CaptureStdout();
    testing::internal::CaptureStderr();
    EXPECT_EQ(runProgram(both, output), 0);
    EXPECT_EQ(testing::internal::GetCapturedStderr(), err);
    EXPECT_EQ(testing::internal::GetCapturedStdout(), out);
  }
}

TEST_F(SpawnTest, MissingProgramIsAnError) {
  EXPECT_THROW(runProgram({path("no-such-program")}), std::system_error);
}

}  // namespace
}  // namespace gaitopt::io::test
