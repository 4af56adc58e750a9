// Checked writes: the errno text reaches the message; a failed write leaves no partial file.
#include "io/checked_write.hpp"

#include "io_test_dir.hpp"

namespace gaitopt::io::test {
namespace {

using CheckedWriteTest = IoTest;

TEST_F(CheckedWriteTest, WritesAndReplacesAtomically) {
  writeFileAtomically(path("a.json"), "{}\n");
  writeFileAtomically(path("a.json"), "[1]\n");
  EXPECT_EQ(slurp(path("a.json")), "[1]\n");
  EXPECT_FALSE(std::filesystem::exists(path("a.json.tmp")));
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

TEST_F(CheckedWriteTest, AppendGrowsAndTruncateCutsATornLine) {
  {
    AppendFile f(path("log.csv"));
    f.append("h\n");
    f.append("1\n2");
    f.truncate(4);
  }
  EXPECT_EQ(slurp(path("log.csv")), "h\n1\n");
}

}  // namespace
}  // namespace gaitopt::io::test
