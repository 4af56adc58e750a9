// Files named by their shipped path (io/data_dir.hpp): the user's own under the working
// directory first, else the shipped one, else none.
#include "io/data_dir.hpp"

#include <filesystem>
#include <string>

#include "io_test_dir.hpp"

namespace gaitopt::io::test {
namespace {

class LocalOrShipped : public IoTest {
 protected:
  void SetUp() override {
    IoTest::SetUp();
    previous_ = std::filesystem::current_path();
    std::filesystem::current_path(dir_);  // a working directory without configs/
  }
  void TearDown() override {
    std::filesystem::current_path(previous_);
    IoTest::TearDown();
  }
  std::filesystem::path previous_;
};

constexpr const char* kRobot = "configs/robots/mu2004_five_link.yaml";

TEST_F(LocalOrShipped, TheShippedFileWhenTheWorkingDirectoryHasNone) {
  EXPECT_EQ(localOrShipped(kRobot), dataFile(kRobot));
  EXPECT_TRUE(std::filesystem::is_regular_file(localOrShipped(kRobot)));
}

TEST_F(LocalOrShipped, TheUsersOwnFileFirst) {
  std::filesystem::create_directories("configs/robots");
  put(kRobot, "name: mine\n");
  EXPECT_EQ(localOrShipped(kRobot), kRobot);
}

TEST_F(LocalOrShipped, NothingWhenNeitherExists) {
  EXPECT_EQ(localOrShipped(std::string(kRobot) + ".missing"), "");
}

}  // namespace
}  // namespace gaitopt::io::test
