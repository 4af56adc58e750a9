// The study's pieces without running a solve: a config's points (every combination, the last
// axis fastest, several keys set together, the previous point of a warm start), the CSV quoting,
// the per-axis summary (convergence counts, medians, MUMPS's share, spread within one gait) and
// the walk table with a column per plant; walks read from a battery file, which the robust-design
// studies share; and configs refused with the key and why.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <unistd.h>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "study/axis_summary.hpp"
#include "study/study_config.hpp"
#include "study/study_points.hpp"
#include "study/study_settings.hpp"
#include "study/study_solve.hpp"
#include "study/study_table.hpp"
#include "study/study_tools.hpp"
#include "study/walk_pivot.hpp"
#include "support/config_text.hpp"

namespace gaitopt::study {
namespace {

const std::string kOcp = std::string(GAITOPT_SOURCE_DIR) + "/configs/ocp/";

using test::configErrorOf;
using test::writeTempFile;

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(StudyPoints, EveryCombinationTheLastAxisFastestWithTheSetsFirst) {
  const StudyConfig c = loadStudyConfig(writeTempFile(
      "points.yaml", "name: p\ngaits: [" + kOcp + "mu2004_walk.yaml, " + kOcp +
                         "rabbit_kelly2017.yaml]\nset: {solver.tolerance: 1.0e-6, constraints: "
                         "{zmp_margin: 0}}\naxes:\n"
                         "  - {key: \"phases[0].segments\", values: [24, 30]}\n"
                         "  - name: solver\n"
                         "    values: [{solver.linear_solver: mumps, solver.mumps_pivot_order: 7},"
                         " {solver.linear_solver: ldl}]\n"
                         "    labels: [mumps-auto, ldl]\nwarm_start: previous\n"));
  const std::vector<StudyPoint> points = studyPoints(c);
  ASSERT_EQ(points.size(), 8u);
  EXPECT_EQ(points[0].folder, "mu2004_walk_segments=24_solver=mumps-auto");
  EXPECT_EQ(points[1].folder, "mu2004_walk_segments=24_solver=ldl");
  EXPECT_EQ(points[2].folder, "mu2004_walk_segments=30_solver=mumps-auto");
  EXPECT_EQ(points[4].gait, "rabbit_kelly2017");
  // The study's set, then the axes' values in order: two keys for the first solver.
  std::vector<std::string> texts;
  for (const auto& o : points[0].overrides) texts.push_back(o.text());
  EXPECT_EQ(texts, (std::vector<std::string>{"solver.tolerance=1.0e-6", "constraints.zmp_margin=0",
                                             "phases[0].segments=24", "solver.linear_solver=mumps",
                                             "solver.mumps_pivot_order=7"}));
  // The previous point on the last axis: none at its first value, nor across gaits.
  EXPECT_FALSE(points[0].previous);
  EXPECT_EQ(points[1].previous, 0u);
  EXPECT_FALSE(points[2].previous);
  EXPECT_EQ(points[3].previous, 2u);
  EXPECT_FALSE(points[4].previous);
}

// A gait entry names a variant of a config and sets its own values after the study's.
TEST(StudyPoints, AGaitEntryWithANameAndValuesOfItsOwn) {
  const std::vector<StudyPoint> points = studyPoints(loadStudyConfig(writeTempFile(
      "entry.yaml", "name: e\nset: {solver.tolerance: 1.0e-6}\ngaits:\n  - config: " + kOcp +
                        "mu2004_walk.yaml\n    name: wide\n    set: {constraints: "
                        "{friction_margin: 0.3}}\n  - " +
                        kOcp + "mu2004_walk.yaml\n")));
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[0].folder, "wide");
  ASSERT_EQ(points[0].overrides.size(), 2u);
  EXPECT_EQ(points[0].overrides[1].text(), "constraints.friction_margin=0.3");
  EXPECT_EQ(points[1].folder, "mu2004_walk");
  EXPECT_EQ(points[1].overrides.size(), 1u);
  // A list of mappings is read in order: a shared anchored mapping, then the entry's own values.
  const std::string list_yaml = fmt::format(R"(name: e
gaits:
  - config: {0}mu2004_walk.yaml
    set: [&shared {{solver.tolerance: 1.0e-6}}, {{constraints.friction_margin: 0.3}}]
  - config: {0}mu2004_walk.yaml
    name: b
    set: [*shared]
)",
                                            kOcp);
  const std::vector<StudyPoint> listed =
      studyPoints(loadStudyConfig(writeTempFile("entry_list.yaml", list_yaml)));
  ASSERT_EQ(listed.size(), 2u);
  const auto texts = [](const StudyPoint& p) {
    std::vector<std::string> t;
    for (const auto& o : p.overrides) t.push_back(o.text());
    return t;
  };
  EXPECT_EQ(texts(listed[0]), (std::vector<std::string>{"solver.tolerance=1.0e-6",
                                                        "constraints.friction_margin=0.3"}));
  EXPECT_EQ(texts(listed[1]), std::vector<std::string>{"solver.tolerance=1.0e-6"});
  // A value the config refuses names the entry.
  const std::string message = configErrorOf([&] {
    loadStudyConfig(writeTempFile(
        "entry_bad.yaml",
        "name: e\ngaits:\n  - config: " + kOcp + "mu2004_walk.yaml\n    set: {scheme: euler}\n"));
  });
  EXPECT_NE(message.find("scheme"), std::string::npos) << message;
}

// A study written elsewhere may name a shipped problem as the docs spell it (configs/...), as
// the CLI's --config does; a file beside the study of that name would come first.
TEST(StudyConfig, AGaitNamedByItsShippedPathIsFoundFromAnyFolder) {
  const StudyConfig c = loadStudyConfig(
      writeTempFile("shipped.yaml", "name: s\ngaits: [configs/ocp/rabbit_kelly2017.yaml]\n"));
  ASSERT_EQ(c.gaits.size(), 1u);
  EXPECT_TRUE(std::filesystem::is_regular_file(c.gaits[0].path)) << c.gaits[0].path;
  EXPECT_EQ(c.gaits[0].name, "rabbit_kelly2017");
}

// Paths in a study are read beside the study file also when a --set is given: the reader's
// label then names the overrides, and a "/" in one ("description=a/b") once moved the folder the
// gaits and a walk's robot were looked for in.
TEST(StudyConfig, PathsAreReadBesideTheFileWhateverTheOverridesSay) {
  namespace fs = std::filesystem;
  const fs::path folder = fs::path(::testing::TempDir()) / "beside";
  fs::create_directories(folder);
  const auto from = [&](const std::string& kind, const std::string& file) {
    return fs::relative(std::string(GAITOPT_SOURCE_DIR) + "/configs/" + kind + "/" + file, folder)
        .string();
  };
  const std::string path = (folder / "s.yaml").string();
  std::ofstream(path) << "name: s\ngaits: [" << from("ocp", "rabbit_kelly2017.yaml")
                      << "]\nwalks:\n  - name: w\n    options: {robot: "
                      << from("robots", "rabbit.yaml")
                      << "}\n    controllers: [computed_torque]\n"
                         "    plant: {option: mass-error, values: [0]}\n";
  const StudyConfig c = loadStudyConfig(path, {{"description", "a/b"}});
  ASSERT_EQ(c.gaits.size(), 1u);
  EXPECT_TRUE(fs::equivalent(c.gaits[0].path, kOcp + "rabbit_kelly2017.yaml")) << c.gaits[0].path;
  ASSERT_EQ(c.walks.size(), 1u);
  ASSERT_EQ(c.walks[0].options.size(), 1u);
  EXPECT_TRUE(fs::equivalent(c.walks[0].options[0].value,
                             std::string(GAITOPT_SOURCE_DIR) + "/configs/robots/rabbit.yaml"))
      << c.walks[0].options[0].value;
}

TEST(StudyConfig, RefusedWithTheKeyAndWhy) {
  const std::string gait = "gaits: [" + kOcp + "mu2004_walk.yaml]\n";
  for (const auto& [yaml, why] : std::vector<std::pair<std::string, std::string>>{
           {"axes: [{name: s, values: [{solver.linear_solver: ldl}]}]", "a label per value"},
           {"axes: [{key: constraints.zmp_margin, values: [0.01, 0.02], labels: [a]}]",
            "one label per value"},
           {"axes: [{key: constraints.zmp_margin, values: [banana]}]", "refuses 'banana'"},
           {"axes: [{key: constraints.no_such_key, values: [1]}]", "no_such_key"},
           {"warm_start: always", "expected one of none, previous"},
           {"axes: [{key: constraints.zmp_margin, values: [0.01, 0.01]}]", "'0.01' is given twice"},
           {"axes: [{name: s, values: [{solver.tolerance: 1e-4}, {solver.tolerance: 1e-5}], "
            "labels: [a, a]}]",
            "'a' is given twice"},
           {"stability: [{controllers: [computed_torque]}]", "sweeps"},
           {"walks: [{name: a b, controllers: [computed_torque], plant: {option: mass-error, "
            "values: [0]}}]",
            "letters, digits"},
           {"walks: [{name: w, controllers: [computed_torque], plant: {option: ground, values: "
            "[rigid]}}]",
            "expected one of mass-error"}}) {
    const std::string message = configErrorOf(
        [&] { loadStudyConfig(writeTempFile("bad.yaml", "name: b\n" + gait + yaml + "\n")); });
    EXPECT_NE(message.find(why), std::string::npos) << yaml << ": " << message;
  }
}

// Points are written under their gait's name: two gaits of one name would share folders, and
// the second read the first's result as its own ("2 of 2 solves converged", one solved).
TEST(StudyConfig, TwoGaitsOfOneNameAreRefused) {
  const std::string ocp = kOcp + "rabbit_kelly2017.yaml";
  const std::string gaits =
      std::string(GAITOPT_SOURCE_DIR) + "/configs/gaits/rabbit_kelly2017.yaml";
  const std::string robot = std::string(GAITOPT_SOURCE_DIR) + "/configs/robots/rabbit.yaml";
  for (const std::string& yaml :
       {"gaits: [" + ocp + ", " + ocp + "]\n",
        "gaits: [{config: " + ocp + ", set: {constraints.rate_limit: 6}}, {config: " + ocp +
            ", set: {constraints.rate_limit: 10}}]\n",
        "polynomial_gaits: [{gait: " + gaits + ", robot: " + robot + "}]\ngaits: [" + ocp +
            "]\n"}) {
    const std::string message =
        configErrorOf([&] { loadStudyConfig(writeTempFile("twice.yaml", "name: t\n" + yaml)); });
    EXPECT_NE(message.find("two gaits are named 'rabbit_kelly2017'"), std::string::npos)
        << yaml << ": " << message;
  }
  // Named apart, the two entries of one file are two gaits.
  const StudyConfig c = loadStudyConfig(writeTempFile(
      "apart.yaml",
      "name: t\ngaits: [{config: " + ocp + ", name: a}, {config: " + ocp + ", name: b}]\n"));
  EXPECT_EQ(c.gaits.size(), 2u);
}

// `walks_from` reads the walks of a battery file beside the study, which then counts among the
// files a rerun must find unchanged.
TEST(StudyConfig, WalksFromABatteryFile) {
  const std::string battery = writeTempFile(
      "battery.yaml",
      "walks:\n  - name: rigid\n    options: {ground: rigid, steps: 20}\n    controllers: "
      "[computed_torque, mu_sliding_mode]\n    plant: {option: mass-error, values: [-0.1, 0.1]}\n");
  const std::string gait = "gaits: [" + kOcp + "mu2004_walk.yaml]\n";
  const StudyConfig c = loadStudyConfig(
      writeTempFile("with_battery.yaml", "name: b\n" + gait + "walks_from: battery.yaml\n"));
  EXPECT_EQ(c.walks_file, battery);
  ASSERT_EQ(c.walks.size(), 1u);
  EXPECT_EQ(c.walks[0].name, "rigid");
  EXPECT_EQ(c.walks[0].controllers,
            (std::vector<std::string>{"computed_torque", "mu_sliding_mode"}));
  EXPECT_EQ(c.walks[0].plant_option, "mass-error");
  EXPECT_EQ(c.walks[0].plant_values, (std::vector<std::string>{"-0.1", "0.1"}));
  const std::vector<std::string> inputs = studyInputs(c);
  EXPECT_NE(std::find(inputs.begin(), inputs.end(), battery), inputs.end());
  // Both, or a battery with keys of a study, are refused.
  for (const auto& [battery_text, study, why] :
       std::vector<std::tuple<std::string, std::string, std::string>>{
           {"walks: []\n", "walks_from: both.yaml\nwalks: []\n", "not both"},
           {"name: x\nwalks: []\n", "walks_from: keyed.yaml\n", "'name': unknown key"}}) {
    const std::string name = study.substr(12, study.find('.') - 12) + ".yaml";
    writeTempFile(name, battery_text);
    const std::string message = configErrorOf(
        [&] { loadStudyConfig(writeTempFile("refused.yaml", "name: b\n" + gait + study)); });
    EXPECT_NE(message.find(why), std::string::npos) << study << ": " << message;
  }
}

// The robust-design studies compare their gaits on one battery of walks.
TEST(StudyConfig, TheRobustDesignStudiesWalkOneBattery) {
  const std::string studies = std::string(GAITOPT_SOURCE_DIR) + "/configs/studies/";
  const StudyConfig strike = loadStudyConfig(studies + "strike_cost.yaml");
  const StudyConfig candidates = loadStudyConfig(studies + "ensemble_candidates.yaml");
  const StudyConfig penalty = loadStudyConfig(studies + "sensitivity_penalty.yaml");
  EXPECT_EQ(strike.walks_file, candidates.walks_file);
  EXPECT_EQ(penalty.walks_file, candidates.walks_file);
  EXPECT_EQ(penalty.warm_start, StudyConfig::WarmStart::kPreviousOnly);
  ASSERT_EQ(strike.walks.size(), 6u);  // rigid masses, lengths, pushes, cases; LCP; DART
  EXPECT_EQ(strike.walks.back().name, "dart");
  EXPECT_EQ(strike.walks.front().plant_values.size(), 7u);  // masses x0.8 .. x1.2
}

// Every shipped study reads, with every gait's sets (a key its config lacks, or a study whose
// pins no longer apply to the config it names, is an error at load, not minutes into a run).
TEST(StudyConfig, EveryShippedStudyLoads) {
  int studies = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(GAITOPT_SOURCE_DIR) + "/configs/studies")) {
    if (entry.path().extension() != ".yaml") continue;
    ++studies;
    EXPECT_NO_THROW(loadStudyConfig(entry.path().string())) << entry.path().filename();
  }
  EXPECT_GE(studies, 14);
}

// A run refused as bad input (exit 2) or as unrealisable (exit 3) is refused again, so its
// status is kept and it is not restarted; a run killed or stopped by the machine (a full disk: exit
// 1) left no result for a reason that may be gone, so the next run of the study starts it again,
// and it is counted.
TEST(StudyTools, OnlyARefusedRunIsRememberedAKilledOneIsRedone) {
  const std::string dir =
      (std::filesystem::temp_directory_path() / fmt::format("gaitopt_study_tools_{}", ::getpid()))
          .string();
  std::filesystem::create_directories(dir);
  const auto standIn = [&](const std::string& name, const std::string& body) {
    const std::string path = dir + "/" + name;
    std::ofstream(path) << "#!/bin/sh\n" << body << "\n";
    std::filesystem::permissions(path, std::filesystem::perms::owner_all);
    return path;
  };
  StudyTools refused{standIn("refused", "exit 2"), {}};
  EXPECT_EQ(runTool(refused, {}, dir + "/a", "a"), 2);
  EXPECT_EQ(readFile(dir + "/a.exit"), "2");
  EXPECT_EQ(*refused.unfinished, 0);
  StudyTools killed{standIn("killed", "kill -9 $$"), {}};
  EXPECT_EQ(runTool(killed, {}, dir + "/b", "b"), 137);
  EXPECT_FALSE(std::filesystem::exists(dir + "/b.exit"));
  EXPECT_EQ(*killed.unfinished, 1);
  StudyTools full_disk{standIn("full_disk", "exit 1"), {}};
  EXPECT_EQ(runTool(full_disk, {}, dir + "/b", "b"), 1);  // started again
  EXPECT_EQ(*full_disk.unfinished, 1);
  EXPECT_EQ(runTool(full_disk, {}, dir + "/a", "a"), 2);         // the refusal is not repeated
  StudyTools unreachable{standIn("unreachable", "exit 3"), {}};  // a step the legs cannot span
  EXPECT_EQ(runTool(unreachable, {}, dir + "/c", "c"), 3);
  EXPECT_EQ(readFile(dir + "/c.exit"), "3");
  EXPECT_EQ(*unreachable.unfinished, 0);
  std::filesystem::remove_all(dir);
}

// A warm solve killed under a point (warm_start: previous) did not happen: the point is not
// marked as started (.start), so the next run of the study solves it from the warm start again
// (it was marked "guess" and never retried, while the study said to run it again).
TEST(StudySolve, AKilledWarmSolveIsTriedAgainByTheNextRun) {
  const std::string dir =
      (std::filesystem::temp_directory_path() / fmt::format("gaitopt_warm_{}", ::getpid()))
          .string();
  std::filesystem::create_directories(dir);
  const std::string script = dir + "/stand_in";
  // Writes a converged summary into --out, except that its first warm start is killed.
  std::ofstream(script) << "#!/bin/sh\nout=; warm=0\n"
                           "while [ $# -gt 0 ]; do case \"$1\" in --out) out=$2; shift;; "
                           "--warm-start) warm=1;; esac; shift; done\n"
                           "if [ $warm = 1 ] && [ ! -e \"$out.killed\" ]; then "
                           ": > \"$out.killed\"; kill -9 $$; fi\n"
                           "mkdir -p \"$out\" && echo '{\"cost\": 1}' > \"$out/summary.json\"\n";
  std::filesystem::permissions(script, std::filesystem::perms::owner_all);
  StudyConfig c;
  c.warm_start = StudyConfig::WarmStart::kPrevious;
  std::vector<StudyPoint> points(2);
  points[0].folder = "p0";
  points[1].folder = "p1";
  points[1].previous = 0;
  StudyTools t{script, {}};
  solvePoint(c, points, 0, dir, t);
  solvePoint(c, points, 1, dir, t);
  EXPECT_FALSE(std::filesystem::exists(gaitFolder(points[1], dir) + ".start"));
  EXPECT_EQ(*t.unfinished, 1);
  StudyTools rerun{script, {}};
  solvePoint(c, points, 1, dir, rerun);
  EXPECT_EQ(readFile(gaitFolder(points[1], dir) + ".start"), "guess");  // tried, not cheaper
  EXPECT_EQ(*rerun.unfinished, 0);
  std::filesystem::remove_all(dir);
}

TEST(StudyTable, CsvQuotesWhatWouldSplitAFieldAndMarkdownEscapesBars) {
  const Table t{{"a", "b"}, {{"x, y", "say \"hi\""}, {"p|q", "line\nbreak"}}};
  const std::string csv = ::testing::TempDir() + "t.csv", md = ::testing::TempDir() + "t.md";
  writeCsv(t, csv);
  writeMarkdown(t, md);
  EXPECT_EQ(readFile(csv), "a,b\n\"x, y\",\"say \"\"hi\"\"\"\np|q,\"line\nbreak\"\n");
  EXPECT_EQ(readFile(md), "| a | b |\n|---|---|\n| x, y | say \"hi\" |\n| p\\|q | line break |\n");
}

TEST(AxisSummary, CountsMediansMumpsShareAndTheSpreadWithinOneGait) {
  StudyConfig c;
  c.axes.push_back({"solver", {{}, {}}, {"mumps", "ldl"}});
  Table solves{{"gait", "solver", "converged", "iterations", "cost", "wall_time_s",
                "factorizations", "mumps_fallbacks"},
               {{"a", "mumps", "1", "10", "100", "1", "10", "0"},
                {"a", "ldl", "1", "20", "102", "3", "30", "3"},
                {"b", "mumps", "0", "500", "9999", "9", "500", "0"},
                {"b", "ldl", "1", "40", "5", "5", "40", "1"}}};
  const Table s = axisSummary(c, solves);
  ASSERT_EQ(s.rows.size(), 4u);
  // Gait a: both converged, 2 % apart; the medians of 10 and 20 iterations, 1 and 3 s.
  EXPECT_EQ(s.rows[0],
            (std::vector<std::string>{"gait", "a", "2 of 2", "15", "2", "7.5 %", "2.00 %"}));
  // Gait b's failed solve counts in the iterations but not in the spread.
  EXPECT_EQ(s.rows[1][2], "1 of 2");
  EXPECT_EQ(s.rows[1][6], "0.00 %");
  // Per solver: the spread is within one gait (a's 100 and b's 5 are not compared).
  EXPECT_EQ(s.rows[3],
            (std::vector<std::string>{"solver", "ldl", "2 of 2", "30", "4", "5.7 %", "0.00 %"}));
}

TEST(WalkPivot, AColumnPerPlantEachCellTheStepsAndWhereItFellOrWhyItWasRefused) {
  const Table walks{
      {"gait", "walk", "controller", "plant_option", "plant", "steps", "steps_requested",
       "failure"},
      {{"g", "rigid", "ct", "mass-error", "-0.1", "3", "20", "step 4: foot rotation: the CoP"},
       {"g", "rigid", "ct", "mass-error", "0", "20", "20", ""},
       {"g", "rigid", "smc", "mass-error", "0", "20", "20", ""},
       {"g", "rigid", "hzd", "mass-error", "0", "", "",
        "simulate exited 2: error: --controller hzd: HZD control needs ..."}}};
  const Table p = walkPivot(walks, 1);
  EXPECT_EQ(p.header, (std::vector<std::string>{"gait", "walk", "controller", "mass-error -0.1",
                                                "mass-error 0"}));
  ASSERT_EQ(p.rows.size(), 3u);
  EXPECT_EQ(p.rows[0], (std::vector<std::string>{"g", "rigid", "ct",
                                                 "3 of 20 (step 4: foot rotation)", "20 of 20"}));
  EXPECT_EQ(p.rows[1], (std::vector<std::string>{"g", "rigid", "smc", "", "20 of 20"}));
  // A refused walk says so, not " of ".
  EXPECT_EQ(p.rows[2], (std::vector<std::string>{"g", "rigid", "hzd", "", "simulate exited 2"}));
}

}  // namespace
}  // namespace gaitopt::study
