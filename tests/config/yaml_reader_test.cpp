// YamlReader: duplicate keys are errors naming the file, the key path and both lines, wherever
// the mapping sits (top level, nested, inside a list); --set overrides replace values before the
// checks, and a path that does not fit the document is an error naming --set.
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "config/yaml_reader.hpp"
#include "support/config_text.hpp"

namespace gaitopt::config {
namespace {

using test::configErrorOf;
using test::writeTempFile;

TEST(YamlReader, DuplicateTopLevelKeyNamesFileKeyAndBothLines) {
  const std::string path = writeTempFile("dup_top.yaml", "a: 1\nb: 2\na: 3\n");
  const std::string message = configErrorOf([&] { YamlReader::fromFile(path); });
  EXPECT_EQ(message, path +
                         ":3: key 'a': duplicate key, first given at line 1; each key may "
                         "appear once in a mapping");
}

TEST(YamlReader, DuplicateKeyInANestedFlowMapping) {
  const std::string path = writeTempFile("dup_nested.yaml", "outer:\n  inner: {x: 1, x: 2}\n");
  const YamlReader root = YamlReader::fromFile(path);
  const std::string message = configErrorOf([&] { root.map("outer").map("inner"); });
  EXPECT_NE(message.find(path + ":2: key 'outer.inner.x': duplicate key, first given at line 2"),
            std::string::npos)
      << message;
}

TEST(YamlReader, DuplicateKeyInAListItem) {
  const std::string path = writeTempFile("dup_list.yaml", "links:\n  - mass: 1\n    mass: 2\n");
  const YamlReader root = YamlReader::fromFile(path);
  const std::string message = configErrorOf([&] { root.list("links"); });
  EXPECT_NE(message.find(":3: key 'links[0].mass': duplicate key, first given at line 2"),
            std::string::npos)
      << message;
}

TEST(YamlReader, DistinctKeysAreAccepted) {
  const std::string path = writeTempFile("distinct.yaml", "a: 1\nb: {a: 2}\n");
  const YamlReader root = YamlReader::fromFile(path);
  EXPECT_EQ(root.number("a", positive("[m]")), 1.0);
  EXPECT_EQ(root.map("b").number("a", positive("[m]")), 2.0);
}

}  // namespace
}  // namespace gaitopt::config

namespace gaitopt::config {
namespace {

YamlReader withSets(const std::string& path, const std::vector<std::string>& sets) {
  std::vector<Override> overrides;
  for (const auto& text : sets) overrides.push_back(parseOverride(text));
  return YamlReader::fromFile(path, overrides);
}

TEST(YamlReaderOverrides, ReplaceNestedListAndNewValuesBeforeTheChecks) {
  const std::string path =
      writeTempFile("sets.yaml", "a: 1\nm: {x: 2}\nl:\n  - {n: 3}\n  - {n: 4}\nv: [1, 2]\n");
  const YamlReader r = withSets(path, {"a=5", "m.x=6", "l[1].n=7", "m.y=8", "v=[9]", "new.k=1"});
  const auto any = inRange(-100, 100, "");
  EXPECT_EQ(r.number("a", any), 5);
  EXPECT_EQ(r.map("m").number("x", any), 6);
  EXPECT_EQ(r.map("m").number("y", any), 8);  // a key the file did not have
  EXPECT_EQ(r.list("l")[0].number("n", any), 3);
  EXPECT_EQ(r.list("l")[1].number("n", any), 7);
  EXPECT_EQ(r.numbers("v", any), std::vector<double>{9});  // a list replaced whole
  EXPECT_EQ(r.map("new").number("k", any), 1);
  // A value set is checked as one in the file, and the error names the --set.
  const std::string message = configErrorOf([&] { r.number("a", inRange(0, 1, "[m]")); });
  EXPECT_NE(message.find("(--set a=5, --set m.x=6"), std::string::npos) << message;
  EXPECT_NE(message.find("expected a number in [0, 1] [m], got 5"), std::string::npos) << message;
}

TEST(YamlReaderOverrides, NullRemovesAKeySoItsDefaultApplies) {
  const std::string path = writeTempFile("sets_null.yaml", "a: 1\nm: {x: 2, y: 3}\nl: [1, 2]\n");
  const YamlReader r = withSets(path, {"a=null", "m.y=~", "absent.k=null"});
  EXPECT_FALSE(r.has("a"));
  EXPECT_EQ(r.numberOr("a", 42, inRange(-100, 100, "")), 42);
  EXPECT_TRUE(r.map("m").has("x"));
  EXPECT_FALSE(r.map("m").has("y"));
  EXPECT_FALSE(r.map("absent").has("k"));  // removing what is not there changes nothing
  // A list item is not removed (that would renumber the rest): it becomes null.
  EXPECT_EQ(configErrorOf([&] {
              withSets(path, {"l[0]=null"}).numbers("l", inRange(0, 9, ""));
            }).find("l[0]") != std::string::npos,
            true);
}

// The items of a list as one line of YAML each, as a study passes them on as --set values.
TEST(YamlReader, YamlTextsOfAListAndOfOneValue) {
  const std::string path =
      writeTempFile("texts.yaml", "v: [1, word, [0.05, 0.06], {a: 1, b: [2]}]\nm: {x: 2}\n");
  const YamlReader r = YamlReader::fromFile(path);
  EXPECT_EQ(r.yamlTexts("v"),
            (std::vector<std::string>{"1", "word", "[0.05, 0.06]", "{a: 1, b: [2]}"}));
  EXPECT_EQ(r.yamlText("m"), "{x: 2}");
  EXPECT_NE(configErrorOf([&] { r.yamlTexts("m"); }).find("expected a non-empty list"),
            std::string::npos);
}

// A mapping whose keys are paths (a library's grid): --set reaches such a key whole, whether the
// file holds it or not, and a path into a list the mapping does not have is such a key.
TEST(YamlReaderOverrides, AKeyThatIsItselfAPathIsSetWhole) {
  const std::string path =
      writeTempFile("sets_literal.yaml", "grid:\n  constraints.friction_margin: [0.1]\n");
  const YamlReader r = withSets(
      path, {"grid.constraints.friction_margin=[0.2]", "grid.phases[0].segments=[24, 30]"});
  const auto any = inRange(-100, 100, "");
  const YamlReader grid = r.map("grid");
  EXPECT_EQ(grid.keys(),
            (std::vector<std::string>{"constraints.friction_margin", "phases[0].segments"}));
  EXPECT_EQ(grid.numbers("constraints.friction_margin", any), std::vector<double>{0.2});
  EXPECT_EQ(grid.numbers("phases[0].segments", any), (std::vector<double>{24, 30}));
  EXPECT_FALSE(withSets(path, {"grid.constraints.friction_margin=null"})
                   .map("grid")
                   .has("constraints.friction_margin"));
}

TEST(YamlReaderOverrides, PathsThatDoNotFitAreErrorsNamingSet) {
  const std::string path = writeTempFile("sets_bad.yaml", "a: 1\nl:\n  - {n: 3}\n");
  for (const auto& [set, why] :
       std::vector<std::pair<std::string, std::string>>{{"l[1].n=2", "no list item [1]"},
                                                        {"a.b=2", "runs through a value"},
                                                        {"l[x].n=2", "expected a list index"},
                                                        {"a", "expected KEY=VALUE"},
                                                        {"=2", "expected KEY=VALUE"},
                                                        {".a=2", "expected a key path"},
                                                        {"a=[1", "not valid YAML"}}) {
    const std::string message = configErrorOf([&] { withSets(path, {set}); });
    EXPECT_EQ(message.rfind("--set", 0), 0u) << set << ": " << message;
    EXPECT_NE(message.find(why), std::string::npos) << set << ": " << message;
  }
}

}  // namespace
}  // namespace gaitopt::config
