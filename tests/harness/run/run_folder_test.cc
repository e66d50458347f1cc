// Which folder a run may write into: missing, empty or a previous run's (report.json or the
// lock file an interrupted run leaves); never the root or the home folder, never a folder of
// other files (issue 40: `--out /` was accepted and overwrote files).
#include "hil/harness/run/run_folder.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "hil/harness/run/folder_lock.h"

namespace hil::harness {
namespace {

namespace fs = std::filesystem;

class RunFolderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    top_ = fs::temp_directory_path() / ("hil_run_folder_" + std::to_string(getpid()));
    fs::remove_all(top_);
    fs::create_directories(top_);
  }
  void TearDown() override { fs::remove_all(top_); }
  std::string Dir(const std::string& name) { return (top_ / name).string(); }
  fs::path top_;
};

TEST_F(RunFolderTest, MissingEmptyAndPreviousRunFoldersAreAccepted) {
  EXPECT_FALSE(WhyNotARunFolder(Dir("new/deeper")));
  fs::create_directories(Dir("empty"));
  EXPECT_FALSE(WhyNotARunFolder(Dir("empty")));
  fs::create_directories(Dir("done"));
  std::ofstream(Dir("done/report.json")) << "{}";
  std::ofstream(Dir("done/junit.xml")) << "";
  EXPECT_FALSE(WhyNotARunFolder(Dir("done")));
  fs::create_directories(Dir("interrupted/captures"));
  std::ofstream(Dir("interrupted/") + kRunLockName) << "";
  EXPECT_FALSE(WhyNotARunFolder(Dir("interrupted")));
  EXPECT_NO_THROW(MakeRunFolder(Dir("new/deeper")));
  EXPECT_TRUE(fs::is_directory(Dir("new/deeper")));
}

TEST_F(RunFolderTest, AFolderOfOtherFilesIsRefused) {
  fs::create_directories(Dir("mine"));
  std::ofstream(Dir("mine/thesis.tex")) << "precious";
  const auto why = WhyNotARunFolder(Dir("mine"));
  ASSERT_TRUE(why);
  EXPECT_NE(why->find("neither empty nor a previous run's folder"), std::string::npos) << *why;
  try {
    MakeRunFolder(Dir("mine"));
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("refusing the output folder " + Dir("mine")),
              std::string::npos)
        << e.what();
  }
}

TEST_F(RunFolderTest, TheRootAndTheHomeFolderAreRefused) {
  for (const char* root : {"/", "//", "/.", "/tmp/.."}) {
    const auto why = WhyNotARunFolder(root);
    ASSERT_TRUE(why) << root;
    EXPECT_NE(why->find("root folder"), std::string::npos) << *why;
  }
  // a home folder that would otherwise pass (empty, or holding a report.json) is still refused
  fs::create_directories(Dir("home"));
  std::ofstream(Dir("home/report.json")) << "{}";
  const char* old = std::getenv("HOME");
  const std::string saved = old ? old : "";
  ASSERT_EQ(setenv("HOME", Dir("home").c_str(), 1), 0);
  const auto why = WhyNotARunFolder(Dir("home") + "/.");
  if (old)
    setenv("HOME", saved.c_str(), 1);
  else
    unsetenv("HOME");
  ASSERT_TRUE(why);
  EXPECT_NE(why->find("home folder"), std::string::npos) << *why;
}

}  // namespace
}  // namespace hil::harness
