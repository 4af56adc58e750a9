// The resumable row log (io/row_log.hpp): rows survive a reopen with their quoting, a torn last
// line is cut from the file, and a file of another kind is refused.
#include <gtest/gtest.h>

#include "config/config_error.hpp"
#include "io/io_test_dir.hpp"
#include "io/row_log.hpp"

namespace gaitopt::io::test {
namespace {

const Row kHeader = {"key", "value", "note"};

using RowLogTest = IoTest;

TEST_F(RowLogTest, RowsSurviveAReopenWithCommasAndQuotes) {
  const std::string file = path("log.csv");
  RowLog(file, kHeader).append({"a", "1.5", "x, \"quoted\""});
  const RowLog back(file, kHeader);
  ASSERT_EQ(back.rows().size(), 1u);
  EXPECT_EQ(back.rows().at("a"), (Row{"a", "1.5", "x, \"quoted\""}));
  EXPECT_EQ(slurp(file), "key,value,note\na,1.5,\"x, \"\"quoted\"\"\"\n");
}

TEST_F(RowLogTest, ALaterRowReplacesAnEarlierOneOfTheSameKey) {
  const std::string file = path("log.csv");
  {
    RowLog log(file, kHeader);
    log.append({"a", "1", ""});
    log.append({"a", "2", ""});
  }
  EXPECT_EQ(RowLog(file, kHeader).rows().at("a")[1], "2");
}

// A 2-D map keys a point by both coordinates: (1, 2) and (1, 3) are two rows, not one replaced.
TEST_F(RowLogTest, RowsKeyedByTwoFieldsKeepPointsOfOneRow) {
  const std::string file = path("map.csv");
  {
    RowLog log(file, kHeader, 2);
    log.append({"1", "2", "first"});
    log.append({"1", "3", "second"});
  }
  const RowLog back(file, kHeader, 2);
  ASSERT_EQ(back.rows().size(), 2u);
  EXPECT_EQ(back.rows().at("1,2")[2], "first");
  EXPECT_EQ(back.rows().at("1,3")[2], "second");
  EXPECT_THROW(RowLog(file, kHeader, 4), std::logic_error);
}

TEST_F(RowLogTest, ATornLastRowIsCutFromTheFile) {
  const std::string file = path("log.csv");
  put(file, "key,value,note\na,1,ok\nb,2,tor");  // killed in the middle of row b
  const RowLog log(file, kHeader);
  EXPECT_EQ(log.rows().size(), 1u);
  EXPECT_EQ(log.rows().count("b"), 0u);  // b is redone
  EXPECT_EQ(slurp(file), "key,value,note\na,1,ok\n");
}

TEST_F(RowLogTest, ATornHeaderIsWrittenAgain) {
  const std::string file = path("log.csv");
  put(file, "key,val");
  EXPECT_TRUE(RowLog(file, kHeader).rows().empty());
  EXPECT_EQ(slurp(file), "key,value,note\n");
}

TEST_F(RowLogTest, AnotherHeaderIsRefused) {
  const std::string file = path("log.csv");
  put(file, "key,value\na,1\n");
  EXPECT_THROW(RowLog(file, kHeader), config::ConfigError);
}

TEST_F(RowLogTest, ARowOfTheWrongWidthIsABug) {
  RowLog log(path("log.csv"), kHeader);
  EXPECT_THROW(log.append({"a", "1"}), std::logic_error);
}

}  // namespace
}  // namespace gaitopt::io::test
