// Includes read only regular files inside the scenario's folder tree or a scenario library: a
// folder is called a folder, an absolute path, '..' or a symbolic link out of the tree is refused
// without a word of the file's content, and a FIFO (as the scenario or an include) is refused
// at once instead of blocking the load.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <sys/stat.h>

#include "hil/harness/devices/scenario_file.h"
#include "hil/harness/scenario/scenario.h"
#include "hil/harness/scenario/yaml_reader.h"

namespace hil::harness {
namespace {

namespace fs = std::filesystem;

constexpr const char* kMinimal =
    "name: t\n"
    "origin: {lat_deg: 35.0, lon_deg: 50.0}\n";

class YamlIncludesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    top_ = fs::temp_directory_path() / ("hil_includes_" + std::to_string(getpid()));
    fs::remove_all(top_);
    fs::create_directories(top_ / "scen/parts");
    fs::create_directories(top_ / "outside");
    std::ofstream(top_ / "outside/secret.yaml") << "gnss: {baud: 38400}\nsecret_line_42: 1\n";
    std::ofstream(top_ / "scen/parts/rig.yaml") << "gnss: {baud: 38400}\n";
  }
  void TearDown() override { fs::remove_all(top_); }

  std::string Scenario(const std::string& include) {
    const std::string path = (top_ / "scen/s.yaml").string();
    std::ofstream(path) << kMinimal << "include: " << include << "\n";
    return path;
  }
  std::string ErrorOf(const std::string& include) {
    try {
      LoadScenario(Scenario(include));
    } catch (const ScenarioError& e) {
      return e.what();
    }
    return "(loaded)";
  }
  fs::path top_;
};

TEST_F(YamlIncludesTest, AnIncludeInsideTheTreeLoads) {
  EXPECT_EQ(LoadScenario(Scenario("parts/rig.yaml")).gnss.baud, 38400);
  fs::create_symlink(top_ / "scen/parts/rig.yaml", top_ / "scen/link.yaml");
  EXPECT_EQ(LoadScenario(Scenario("link.yaml")).gnss.baud, 38400);  // a link inside the tree
  EXPECT_EQ(LoadScenario(Scenario("parts/../parts/rig.yaml")).gnss.baud, 38400);
}

TEST_F(YamlIncludesTest, AFolderIsCalledAFolder) {
  const std::string e = ErrorOf("parts");
  EXPECT_NE(e.find("'parts' is a folder"), std::string::npos) << e;
}

TEST_F(YamlIncludesTest, LeavingTheTreeIsRefusedWithoutEchoingTheFile) {
  fs::create_symlink(top_ / "outside/secret.yaml", top_ / "scen/parts/escape.yaml");
  for (const std::string& inc :
       {(top_ / "outside/secret.yaml").string(), std::string("../outside/secret.yaml"),
        std::string("parts/escape.yaml")}) {
    const std::string e = ErrorOf(inc);
    EXPECT_NE(e.find("s.yaml:3: include:"), std::string::npos) << e;
    EXPECT_NE(e.find("may not leave them"), std::string::npos) << e;
    EXPECT_EQ(e.find("secret_line_42"), std::string::npos) << e;
  }
  // /etc/passwd's first line is never printed
  const std::string e = ErrorOf("/etc/passwd");
  EXPECT_NE(e.find("may not leave them"), std::string::npos) << e;
  EXPECT_EQ(e.find("root:"), std::string::npos) << e;
}

TEST_F(YamlIncludesTest, ALibraryFolderTheUserNamesIsAllowed) {
  ASSERT_EQ(setenv("HIL_SCENARIO_LIB", (top_ / "outside").c_str(), 1), 0);
  const std::string e = ErrorOf("secret.yaml");  // found and read: its unknown key is the error
  unsetenv("HIL_SCENARIO_LIB");
  EXPECT_NE(e.find("secret.yaml:2: secret_line_42: unknown key"), std::string::npos) << e;
}

TEST_F(YamlIncludesTest, AFifoIsRefusedAtOnce) {
  ASSERT_EQ(mkfifo((top_ / "scen/fifo.yaml").c_str(), 0600), 0);
  const std::string e = ErrorOf("fifo.yaml");
  EXPECT_NE(e.find("not a regular file"), std::string::npos) << e;
  try {
    LoadScenario((top_ / "scen/fifo.yaml").string());  // blocked forever before
    FAIL();
  } catch (const ScenarioError& err) {
    EXPECT_NE(std::string(err.what()).find("not a regular file"), std::string::npos) << err.what();
  }
}

}  // namespace
}  // namespace hil::harness
