// The safe output folder of docs/design.md#output-folders-and-failures: what may be replaced,
// inputs, paths, locks, leftovers.
#include "io/output/output_folder.hpp"

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <fstream>

#include <stdexcept>

#include "config/config_error.hpp"
#include "io/output/checked_write.hpp"
#include "io_test_dir.hpp"

namespace gaitopt::io::test {
namespace {

namespace fs = std::filesystem;
using OutputFolderTest = IoTest;

void fillWith(const std::string& dir, const std::string& text) {
  writeFile(dir + "/result.txt", text);
}

TEST_F(OutputFolderTest, NewFolderIsWrittenWithMarkerAndNoLeftovers) {
  const OutputFolder out(path("res"), {});
  out.write([](const std::string& d) { fillWith(d, "one"); });
  EXPECT_EQ(slurp(path("res/result.txt")), "one");
  EXPECT_TRUE(fs::exists(path("res") + "/" + kMarker));
  int entries = 0;
  for (const auto& e : fs::directory_iterator(dir_)) entries += e.path().filename() != "res";
  EXPECT_EQ(entries, 1) << "only OUT.lock while the folder is held";
}

TEST_F(OutputFolderTest, OwnResultIsReplacedButForeignFolderAndFileAreRefused) {
  OutputFolder(path("res"), {}).write([](const std::string& d) { fillWith(d, "one"); });
  OutputFolder(path("res"), {}).write([](const std::string& d) { fillWith(d, "two"); });
  EXPECT_EQ(slurp(path("res/result.txt")), "two");
  fs::create_directories(path("mine"));
  put(path("mine/thesis.tex"), "precious");
  EXPECT_THROW(OutputFolder(path("mine"), {}), config::ConfigError);
  EXPECT_EQ(slurp(path("mine/thesis.tex")), "precious");
  put(path("file"), "data");
  EXPECT_THROW(OutputFolder(path("file"), {}), config::ConfigError);
  EXPECT_EQ(slurp(path("file")), "data");
}

// A result is replaced whole, so what a user put into it since (notes beside a walk) would go
// with it; the marker lists what gaitopt wrote, and a command writing into a result (report's
// page) adds its file to the list.
TEST_F(OutputFolderTest, AResultHoldingAFileGaitoptDidNotWriteIsRefused) {
  OutputFolder(path("res"), {}).write([](const std::string& d) { fillWith(d, "one"); });
  put(path("res/notes.md"), "my notes");
  EXPECT_THROW(OutputFolder(path("res"), {}), config::ConfigError);
  EXPECT_EQ(slurp(path("res/notes.md")), "my notes");
  fs::remove(path("res/notes.md"));
  put(path("res/report.html"), "page");
  addWrittenFile(path("res"), "report.html");
  OutputFolder(path("res"), {}).write([](const std::string& d) { fillWith(d, "two"); });
  EXPECT_EQ(slurp(path("res/result.txt")), "two");
  EXPECT_FALSE(fs::exists(path("res/report.html")));
}

// simulate and impact-map draw their pictures into the result once it is in place; unlisted,
// they made the command's own next run refuse the folder.
TEST_F(OutputFolderTest, PicturesDrawnIntoAPlacedResultKeepItReplaceable) {
  {
    const OutputFolder out(path("walk"), {});
    out.write([](const std::string& d) { fillWith(d, "one"); });
    put(path("walk/overview.png"), "picture");
    fs::create_directories(path("walk/plots"));
    put(path("walk/plots/forces.png"), "picture");
    listAddedFiles(out.path());
  }
  OutputFolder(path("walk"), {}).write([](const std::string& d) { fillWith(d, "two"); });
  EXPECT_EQ(slurp(path("walk/result.txt")), "two");
  EXPECT_FALSE(fs::exists(path("walk/overview.png")));
}

// A walk written over an optimised gait took the gait with it: a result replaces only one of
// its own kind (or of none: a folder written before markers named kinds).
TEST_F(OutputFolderTest, AResultOfAnotherKindIsRefused) {
  OutputFolder(path("gait"), {}, "--out", "gait").write([](const std::string& d) {
    fillWith(d, "gait");
  });
  EXPECT_THROW(OutputFolder(path("gait"), {}, "--out", "walk"), config::ConfigError);
  EXPECT_EQ(slurp(path("gait/result.txt")), "gait");
  OutputFolder(path("gait"), {}, "--out", "gait").write([](const std::string& d) {
    fillWith(d, "again");
  });
  EXPECT_EQ(slurp(path("gait/result.txt")), "again");
}

TEST_F(OutputFolderTest, AnOutWhereNoFolderCanBeMadeIsABadOption) {
  if (!fs::is_directory("/proc/self")) GTEST_SKIP() << "no /proc";
  try {
    OutputFolder("/proc/gaitopt_no_folder", {});
    FAIL() << "no error";
  } catch (const config::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("--out: '/proc/gaitopt_no_folder' cannot be created"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(OutputFolderTest, InputsOfTheCommandAreRefusedByRealPath) {
  put(path("config.yaml"), "x");
  fs::create_directories(path("ref"));
  EXPECT_THROW(OutputFolder(path("config.yaml"), {path("config.yaml")}), config::ConfigError);
  // Another spelling of the same folder, and a folder holding an input.
  EXPECT_THROW(OutputFolder(path("ref/../ref/"), {path("ref")}), config::ConfigError);
  fs::create_symlink(path("ref"), path("link"));
  EXPECT_THROW(OutputFolder(path("ref"), {path("link")}), config::ConfigError);
  EXPECT_THROW(OutputFolder(dir_.string(), {path("config.yaml")}), config::ConfigError);
}

TEST_F(OutputFolderTest, PathsWithoutAFolderNameAreRefusedAndTrailingSlashNormalised) {
  for (const char* bad : {"", ".", "./", "..", "/", "a/.."})
    EXPECT_THROW(normaliseOutPath(bad, "--out"), config::ConfigError) << bad;
  EXPECT_EQ(normaliseOutPath("results/run1/", "--out"), "results/run1");
  EXPECT_EQ(normaliseOutPath("results//run1///", "--out"), "results/run1");
}

TEST_F(OutputFolderTest, APathBelowAFileIsRefusedNamingTheFile) {
  put(path("notes"), "x");
  try {
    OutputFolder((fs::path(path("notes")) / "sub" / "res").string(), {});
    FAIL() << "a folder below a file was accepted";
  } catch (const config::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("which is a file, not a folder"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(slurp(path("notes")), "x");
}

TEST_F(OutputFolderTest, SecondWriterIsRefusedWhileTheFirstHoldsTheLock) {
  const OutputFolder first(path("res"), {});
  EXPECT_THROW(OutputFolder(path("res"), {}), config::ConfigError);
}

TEST_F(OutputFolderTest, FailedFillKeepsThePreviousResult) {
  OutputFolder(path("res"), {}).write([](const std::string& d) { fillWith(d, "good"); });
  EXPECT_THROW(OutputFolder(path("res"), {}).write([](const std::string& d) {
    fillWith(d, "half");
    throw std::runtime_error("disk full");
  }),
               std::runtime_error);
  EXPECT_EQ(slurp(path("res/result.txt")), "good");
}

TEST_F(OutputFolderTest, LeftoversOfDeadRunsAreCleanedAndAnOrphanedOldResultRestored) {
  // pid 2^22 + 1 is above the kernel's pid_max: no process can have it.
  const std::string dead = "4194305";
  fs::create_directories(path("res.tmp-" + dead));
  fs::create_directories(path("res.old-" + dead));
  put(path("res.old-" + dead + "/result.txt"), "previous");
  put(path("res.old-" + dead + "/") + kMarker, "");
  fs::create_directories(path("res.tmp-1x"));  // not ours: not a pid
  const OutputFolder out(path("res"), {});
  EXPECT_EQ(slurp(path("res/result.txt")), "previous");
  EXPECT_FALSE(fs::exists(path("res.tmp-" + dead)));
  EXPECT_FALSE(fs::exists(path("res.old-" + dead)));
  EXPECT_TRUE(fs::exists(path("res.tmp-1x")));
}

// A run that has exited but is not yet reaped (a zombie, as a container's slow init leaves
// it) answers kill(pid, 0): its staging folder is a leftover all the same (one stayed for good).
TEST_F(OutputFolderTest, TheLeftoverOfAnExitedButUnreapedRunIsCleaned) {
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) ::_exit(0);
  const std::string zombie = path("res.tmp-" + std::to_string(child));
  fs::create_directories(zombie);
  put(zombie + "/" + kMarker, "");
  for (int wait_ms = 0; wait_ms < 2000 && ::kill(child, 0) == 0; wait_ms += 10) {
    std::ifstream stat("/proc/" + std::to_string(child) + "/stat");
    std::string line;
    std::getline(stat, line);
    if (line.find(") Z ") != std::string::npos) break;  // exited, not reaped
    ::usleep(10000);
  }
  { const OutputFolder out(path("res"), {}); }
  EXPECT_FALSE(fs::exists(zombie));
  ::waitpid(child, nullptr, 0);
}

// Issue 39: DIR.lock is gaitopt's own. A link or a user's file there is refused and kept; a lock
// a killed run left (tagged, or empty) is taken and removed at the end.
TEST_F(OutputFolderTest, LockFileThatIsNotGaitoptsIsRefusedAndKept) {
  put(path("notes"), "user data");
  fs::create_symlink(path("notes"), path("res.lock"));
  EXPECT_THROW(OutputFolder(path("res"), {}), config::ConfigError);
  EXPECT_TRUE(fs::is_symlink(path("res.lock")));
  fs::remove(path("res.lock"));
  put(path("res.lock"), "my own lock notes\n");
  EXPECT_THROW(OutputFolder(path("res"), {}), config::ConfigError);
  EXPECT_EQ(slurp(path("res.lock")), "my own lock notes\n");
  EXPECT_EQ(slurp(path("notes")), "user data");
  fs::remove(path("res.lock"));
  ASSERT_EQ(::mkfifo(path("res.lock").c_str(), 0644), 0);  // must not hang the open
  EXPECT_THROW(OutputFolder(path("res"), {}), config::ConfigError);
  fs::remove(path("res.lock"));
  for (const std::string& stale : {std::string(kLockTag) + "\n4194305\n", std::string()}) {
    put(path("res.lock"), stale);
    { const OutputFolder out(path("res"), {}); }
    EXPECT_FALSE(fs::exists(fs::symlink_status(path("res.lock")))) << stale;
  }
}

// Issue 39: a dead pid's OUT.tmp-PID / OUT.old-PID that gaitopt did not make (no marker, or a
// link) is neither removed nor restored as OUT.
TEST_F(OutputFolderTest, LeftoversThatGaitoptDidNotMakeAreKept) {
  const std::string dead = "4194305";
  fs::create_directories(path("res.tmp-" + dead));
  put(path("res.tmp-" + dead + "/thesis.tex"), "mine");
  fs::create_directories(path("users"));
  put(path("users/") + kMarker, "");
  fs::create_directory_symlink(path("users"), path("res.old-" + dead));
  const OutputFolder out(path("res"), {});
  EXPECT_EQ(slurp(path("res.tmp-" + dead + "/thesis.tex")), "mine");
  EXPECT_TRUE(fs::is_symlink(path("res.old-" + dead)));
  EXPECT_FALSE(fs::exists(fs::symlink_status(path("res"))));
  EXPECT_TRUE(fs::exists(path("users/") + kMarker));
}

TEST_F(OutputFolderTest, OutputInsideAnInputFolderIsRefused) {
  fs::create_directories(path("ref"));
  EXPECT_THROW(OutputFolder(path("ref/walk"), {path("ref")}), config::ConfigError);
  EXPECT_THROW(ResumableFolder(path("ref/sweep/"), {path("ref")}, "claim.json"),
               config::ConfigError);
  EXPECT_FALSE(fs::exists(path("ref/sweep")));
}

TEST_F(OutputFolderTest, ResumableFolderKeepsItsFilesAndRefusesForeignOnes) {
  {
    const ResumableFolder f(path("sweep"), {}, "claim.json");
    put(path("sweep/claim.json"), "{}");
    put(path("sweep/rows.csv"), "a\n");
  }
  const ResumableFolder again(path("sweep"), {}, "claim.json");
  EXPECT_EQ(slurp(path("sweep/rows.csv")), "a\n");
  fs::create_directories(path("home"));
  put(path("home/notes"), "x");
  EXPECT_THROW(ResumableFolder(path("home"), {}, "claim.json"), config::ConfigError);
}

// A stability sweep (resumable) with a walk written inside it: a walk's --out on the sweep
// replaced it whole, rows and nested walk with it.
TEST_F(OutputFolderTest, AResumableRunsFolderIsNotReplacedByAnotherResult) {
  {
    const ResumableFolder sweep(path("sweep"), {}, "claim.json");
    put(path("sweep/claim.json"), "{}");
    put(path("sweep/rows.csv"), "a\n");
  }
  OutputFolder(path("sweep/point"), {}).write([](const std::string& d) { fillWith(d, "p"); });
  EXPECT_THROW(OutputFolder(path("sweep"), {}), config::ConfigError);
  EXPECT_EQ(slurp(path("sweep/rows.csv")), "a\n");
  EXPECT_EQ(slurp(path("sweep/point/result.txt")), "p");
}

TEST_F(OutputFolderTest, ResumableRunRefusesAnotherCommandsResultAndLeavesItWhole) {
  OutputFolder(path("gait"), {}).write([](const std::string& d) { fillWith(d, "gait"); });
  EXPECT_THROW(ResumableFolder(path("gait"), {}, "claim.json"), config::ConfigError);
  EXPECT_EQ(slurp(path("gait/result.txt")), "gait");
  EXPECT_FALSE(fs::exists(path("gait/claim.json")));
  // A result that has only the marker (a run killed before it claimed the folder) is its own.
  fs::create_directories(path("bare"));
  writeMarker(path("bare"));
  EXPECT_NO_THROW(ResumableFolder(path("bare"), {}, "claim.json"));
}

TEST_F(OutputFolderTest, OutputInsideAResultIsRefusedUnlessTheResultIsResumable) {
  OutputFolder(path("gait"), {}).write([](const std::string& d) { fillWith(d, "gait"); });
  EXPECT_THROW(OutputFolder(path("gait/walk"), {}), config::ConfigError);
  EXPECT_THROW(ResumableFolder(path("gait/deep/sweep"), {}, "claim.json"), config::ConfigError);
  EXPECT_FALSE(fs::exists(path("gait/walk")));
  // A library's points live in its folder; one written before the marker said so is upgraded.
  fs::create_directories(path("lib"));
  writeMarker(path("lib"));
  put(path("lib/claim.json"), "{}");
  EXPECT_THROW(OutputFolder(path("lib/points/p"), {}), config::ConfigError);
  const ResumableFolder lib(path("lib"), {}, "claim.json");
  OutputFolder(path("lib/points/p"), {}).write([](const std::string& d) { fillWith(d, "p"); });
  EXPECT_EQ(slurp(path("lib/points/p/result.txt")), "p");
}

}  // namespace
}  // namespace gaitopt::io::test
