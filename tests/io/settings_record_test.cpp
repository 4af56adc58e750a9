// Settings records of resumable folders, strict JSON and terminal-safe text.
#include "io/settings_record.hpp"

#include "config/config_error.hpp"
#include "io/strict_json.hpp"
#include "io/terminal_text.hpp"
#include "io_test_dir.hpp"

namespace gaitopt::io::test {
namespace {

using SettingsTest = IoTest;

TEST_F(SettingsTest, SameSettingsResumeOtherSettingsAreRefusedNamingTheDifference) {
  const nlohmann::ordered_json a = {{"controller", "computed_torque"}, {"steps", 10}};
  claimSettings(path("s.json"), a);
  EXPECT_NO_THROW(claimSettings(path("s.json"), a));
  try {
    claimSettings(path("s.json"), {{"controller", "sliding_mode"}, {"steps", 10}});
    FAIL();
  } catch (const config::ConfigError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.key(), "controller");
    EXPECT_NE(what.find("controller: folder \"computed_torque\", this run \"sliding_mode\""),
              std::string::npos)
        << what;
    EXPECT_EQ(what.find("steps:"), std::string::npos) << what;
  }
}

TEST_F(SettingsTest, FingerprintFollowsContentNotName) {
  put(path("a"), "1,2,3\n");
  put(path("b"), "1,2,3\n");
  put(path("c"), "1,2,4\n");
  EXPECT_EQ(fileFingerprint(path("a")), fileFingerprint(path("b")));
  EXPECT_NE(fileFingerprint(path("a")), fileFingerprint(path("c")));
  put(path("empty"), "");
  EXPECT_EQ(fileFingerprint(path("empty")), "cbf29ce484222325");  // the FNV-1a offset basis
}

// The same gait solved again differs in its measured times, perhaps in how its config's path
// was typed and, after a change of the linear solver's inner workings, in its counts of
// factorizations or in the settings its solver record lists; a stability folder keyed by the
// whole summary.json refused to resume on it.
TEST_F(SettingsTest, ASummaryIsKeyedWithoutTheTimesARunMeasured) {
  put(path("a.json"),
      R"({"config": "a.yaml", "cost": 1.5, "wall_time_s": 0.1, "callback_time_s": 0.01,
          "stages": [{"cost": 1.5, "wall_time_s": 0.1}], "kkt": {"factorizations": 16}})");
  put(path("b.json"),
      R"({"config": "../b.yaml", "cost": 1.5, "wall_time_s": 0.2, "callback_time_s": 0.02,
          "stages": [{"cost": 1.5, "wall_time_s": 0.2}], "kkt": {"factorizations": 17},
          "solver": {"min_refinement_steps": 1}})");
  put(path("c.json"), R"({"config": "a.yaml", "cost": 1.6, "wall_time_s": 0.1,
          "callback_time_s": 0.01, "stages": [{"cost": 1.5, "wall_time_s": 0.1}]})");
  put(path("d.json"), R"({"config": "a.yaml", "cost": 1.5, "wall_time_s": 0.1,
          "callback_time_s": 0.01, "stages": [{"cost": 1.7, "wall_time_s": 0.1}]})");
  EXPECT_EQ(summaryFingerprint(path("a.json")), summaryFingerprint(path("b.json")));
  EXPECT_NE(summaryFingerprint(path("a.json")), summaryFingerprint(path("c.json")));
  EXPECT_NE(summaryFingerprint(path("a.json")), summaryFingerprint(path("d.json")));
}

TEST(StrictJson, DuplicateKeyIsRefusedAtAnyDepthButNotAcrossObjects) {
  EXPECT_THROW(parseStrictJson<nlohmann::json>(R"({"theta": [1], "theta": [2]})", "s.json"),
               config::ConfigError);
  EXPECT_THROW(parseStrictJson<nlohmann::json>(R"({"a": {"b": 1, "b": 1}})", "s.json"),
               config::ConfigError);
  EXPECT_NO_THROW(parseStrictJson<nlohmann::json>(R"({"a": {"b": 1}, "c": {"b": 2}})", "s.json"));
  EXPECT_NO_THROW(parseStrictJson<nlohmann::json>(R"([{"b": 1}, {"b": 2}])", "s.json"));
}

TEST(TerminalText, ControlBytesAreEscapedPrintableTextKept) {
  EXPECT_EQ(printable("t\x1b[2Jx\x07"), "t\\x1b[2Jx\\x07");
  EXPECT_EQ(printable("line\n\tok \xc2\xb0"), "line\n\tok \xc2\xb0");
  EXPECT_EQ(printable("\x7f"), "\\x7f");
}

TEST(TerminalText, ACountTakesItsNounInTheSingularOnlyForOne) {
  EXPECT_EQ(counted(1, "corner"), "1 corner");
  EXPECT_EQ(counted(0, "chart"), "0 charts");
  EXPECT_EQ(counted(20, "step"), "20 steps");
}

}  // namespace
}  // namespace gaitopt::io::test
