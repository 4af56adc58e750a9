// Checked writes: the errno text reaches the message; a failed write leaves no partial file.
#include "io/output/checked_write.hpp"

#include <sys/resource.h>

#include <csignal>

#include "io_test_dir.hpp"

namespace gaitopt::io::test {
namespace {

using CheckedWriteTest = IoTest;

TEST_F(CheckedWriteTest, WritesAndReplacesAtomically) {
  writeFileAtomically(path("a.json"), "{}\n");
  writeFileAtomically(path("a.json"), "[1]\n");
  EXPECT_EQ(slurp(path("a.json")), "[1]\n");
  // No temporary is left next to it.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir_), {}), 1);
}

// Issue 39: a link planted at a file gaitopt writes, or at the temporary names it may use, is
// never written through; the user's file keeps its bytes.
TEST_F(CheckedWriteTest, LinksAreNeverWrittenThrough) {
  put(path("notes"), "user data");
  namespace fs = std::filesystem;
  fs::create_symlink(path("notes"), path("a.json.tmp"));
  fs::create_symlink(path("notes"), path("a.json.tmp-" + std::to_string(::getpid()) + "-0"));
  writeFileAtomically(path("a.json"), "{}\n");
  EXPECT_EQ(slurp(path("a.json")), "{}\n");
  EXPECT_TRUE(fs::is_symlink(path("a.json.tmp")));
  fs::create_symlink(path("notes"), path("b.csv"));
  EXPECT_THROW(writeFile(path("b.csv"), "x"), WriteError);
  EXPECT_THROW(AppendFile{path("b.csv")}, WriteError);
  EXPECT_EQ(slurp(path("notes")), "user data");
  // A link at the target itself is replaced by the rename, its target left alone.
  writeFileAtomically(path("b.csv"), "rows\n");
  EXPECT_FALSE(fs::is_symlink(path("b.csv")));
  EXPECT_EQ(slurp(path("notes")), "user data");
}

// /dev/full fails every write with ENOSPC: the full-disk case without a full disk.
TEST_F(CheckedWriteTest, FullDeviceReportsNoSpaceLeft) {
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  try {
    AppendFile f("/dev/full");
    f.append("row\n");
    FAIL() << "a write to /dev/full succeeded";
  } catch (const WriteError& e) {
    EXPECT_NE(std::string(e.what()).find("/dev/full: cannot write: No space left on device"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(CheckedWriteTest, MissingFolderNamesFileAndReason) {
  try {
    writeFile(path("no/such/file"), "x");
    FAIL();
  } catch (const WriteError& e) {
    EXPECT_NE(std::string(e.what()).find("No such file or directory"), std::string::npos);
  }
}

TEST_F(CheckedWriteTest, AnAtomicWriteNamesTheFileNotItsTemporary) {
  const std::string file = (std::filesystem::path(path("gone")) / "page.html").string();
  try {
    writeFileAtomically(file, "x");
    FAIL();
  } catch (const WriteError& e) {
    EXPECT_EQ(std::string(e.what()), file + ": cannot write: No such file or directory");
  }
}

TEST_F(CheckedWriteTest, AppendGrowsAndTruncateCutsATornLine) {
  {
    AppendFile f(path("log.csv"));
    f.append("h\n");
    f.append("1\n2");
    f.truncate(4);
  }
  EXPECT_EQ(slurp(path("log.csv")), "h\n1\n");
}

// A disk that fills in the middle of a row (here a file-size limit of 12 bytes, which lets the
// write through up to it and then fails with EFBIG): the file keeps its whole rows, with no
// torn one for a reader to meet before a resume cuts it.
TEST_F(CheckedWriteTest, AWriteCutShortLeavesTheRowsItHad) {
  rlimit before{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &before), 0);
  const auto sigxfsz = std::signal(SIGXFSZ, SIG_IGN);  // the write then fails with EFBIG
  AppendFile f(path("rows.csv"));
  f.append("h\n1\n");
  rlimit limit = before;
  limit.rlim_cur = 12;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &limit), 0);
  EXPECT_THROW(f.append("2,a long row past the limit\n"), WriteError);
  ::setrlimit(RLIMIT_FSIZE, &before);
  std::signal(SIGXFSZ, sigxfsz);
  EXPECT_EQ(slurp(path("rows.csv")), "h\n1\n");
}

}  // namespace
}  // namespace gaitopt::io::test
