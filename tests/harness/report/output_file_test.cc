// Run outputs written whole or not at all (output_file.h): a write that fails part-way (here a
// file size limit, as a full disk) leaves the earlier file as it was and no temporary file.
#include "hil/harness/report/output_file.h"

#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <sys/resource.h>

namespace hil::harness {
namespace {

namespace fs = std::filesystem;

std::string Read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A file size limit of `bytes` while it lives (SIGXFSZ ignored: the write fails with EFBIG).
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    getrlimit(RLIMIT_FSIZE, &old_);
    old_handler_ = std::signal(SIGXFSZ, SIG_IGN);
    const rlimit r{bytes, old_.rlim_max};
    setrlimit(RLIMIT_FSIZE, &r);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &old_);
    std::signal(SIGXFSZ, old_handler_);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

 private:
  rlimit old_{};
  void (*old_handler_)(int) = nullptr;
};

class OutputFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("hil_output_file_" + std::to_string(getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string Path(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

TEST_F(OutputFileTest, AFailedWriteKeepsTheEarlierFileAndLeavesNoTemporary) {
  const std::string path = Path("report.json");
  WriteOutputFile(path, "{\"earlier\": true}\n");
  {
    const FileSizeLimit limit(4096);
    EXPECT_THROW(WriteOutputFile(path, std::string(100000, 'x')), OutputWriteError);
  }
  EXPECT_EQ(Read(path), "{\"earlier\": true}\n");
  EXPECT_FALSE(fs::exists(path + ".tmp"));
}

TEST_F(OutputFileTest, AStreamedFileAppearsOnlyWhenCommitted) {
  const std::string path = Path("truth.csv");
  WriteOutputFile(path, "earlier\n");
  std::string expected;
  {
    OutputFile out(path);
    for (int i = 0; i < 200000; ++i) {
      out.text() += std::to_string(i) + "\n";
      out.Pass();
    }
    expected = Read(path);  // before the commit: still the earlier file
    EXPECT_EQ(expected, "earlier\n");
    out.Commit();
  }
  const std::string text = Read(path);
  EXPECT_EQ(text.substr(0, 4), "0\n1\n");
  EXPECT_EQ(text.substr(text.size() - 7), "199999\n");
  EXPECT_FALSE(fs::exists(path + ".tmp"));
}

TEST_F(OutputFileTest, AStreamedFileThatCannotBeWrittenIsNotRenamed) {
  const std::string path = Path("estimate.csv");
  WriteOutputFile(path, "earlier\n");
  {
    const FileSizeLimit limit(OutputFile::kChunkBytes / 2);
    OutputFile out(path);
    out.text() = std::string(OutputFile::kChunkBytes, 'x');
    EXPECT_THROW(out.Pass(), OutputWriteError);
  }  // destroyed uncommitted: its temporary file goes
  EXPECT_EQ(Read(path), "earlier\n");
  EXPECT_FALSE(fs::exists(path + ".tmp"));
}

}  // namespace
}  // namespace hil::harness
