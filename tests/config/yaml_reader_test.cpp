// YamlReader: duplicate keys are errors naming the file, the key path and both lines, wherever
// the mapping sits (top level, nested, inside a list).
#include <fstream>
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "config/yaml_reader.hpp"

namespace gaitopt::config {
namespace {

/// Writes `text` to a file in the test's temporary folder and returns its path.
std::string writeYaml(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

/// The ConfigError message `read` throws, or "no error".
std::string errorOf(const std::function<void()>& read) {
  try {
    read();
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "no error";
}

TEST(YamlReader, DuplicateTopLevelKeyNamesFileKeyAndBothLines) {
  const std::string path = writeYaml("dup_top.yaml", "a: 1\nb: 2\na: 3\n");
  const std::string message = errorOf([&] { YamlReader::fromFile(path); });
  EXPECT_EQ(message, path +
                         ":3: key 'a': duplicate key, first given at line 1; each key may "
                         "appear once in a mapping");
}

TEST(YamlReader, DuplicateKeyInANestedFlowMapping) {
  const std::string path = writeYaml("dup_nested.yaml", "outer:\n  inner: {x: 1, x: 2}\n");
  const YamlReader root = YamlReader::fromFile(path);
  const std::string message = errorOf([&] { root.map("outer").map("inner"); });
  EXPECT_NE(message.find(path + ":2: key 'outer.inner.x': duplicate key, first given at line 2"),
            std::string::npos)
      << message;
}

TEST(YamlReader, DuplicateKeyInAListItem) {
  const std::string path = writeYaml("dup_list.yaml", "links:\n  - mass: 1\n    mass: 2\n");
  const YamlReader root = YamlReader::fromFile(path);
  const std::string message = errorOf([&] { root.list("links"); });
  EXPECT_NE(message.find(":3: key 'links[0].mass': duplicate key, first given at line 2"),
            std::string::npos)
      << message;
}

TEST(YamlReader, DistinctKeysAreAccepted) {
  const std::string path = writeYaml("distinct.yaml", "a: 1\nb: {a: 2}\n");
  const YamlReader root = YamlReader::fromFile(path);
  EXPECT_EQ(root.number("a", positive("[m]")), 1.0);
  EXPECT_EQ(root.map("b").number("a", positive("[m]")), 2.0);
}

}  // namespace
}  // namespace gaitopt::config
