// Substitute (issue 40.4): every value pasted into a command template is data. Each value below
// goes through /bin/sh in each place a template can hold it (bare, inside '...' of an inner
// `sh -c`, inside "..."), and must arrive as one word, byte for byte, without running anything.
#include "hil/harness/dut/shell_substitute.h"

#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <sys/wait.h>

namespace hil::harness {
namespace {

namespace fs = std::filesystem;

// Runs `line` with /bin/sh and returns its stdout.
std::string Sh(const std::string& line) {
  FILE* p = popen(line.c_str(), "r");
  if (!p) return "<popen failed>";
  std::string out;
  std::array<char, 512> buf;
  std::size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) out.append(buf.data(), n);
  pclose(p);
  return out;
}

class SubstituteTest : public ::testing::Test {
 protected:
  void SetUp() override {
    marker_ = fs::temp_directory_path() / ("hil_pwned_" + std::to_string(getpid()));
    fs::remove(marker_);
  }
  void TearDown() override { fs::remove(marker_); }
  // values that would run a command, split, glob or end a quote if pasted as they are
  std::vector<std::string> Hostile() const {
    const std::string m = marker_.string();
    return {"$(touch " + m + ")",
            "`touch " + m + "`",
            "a; touch " + m,
            "a' ; touch " + m + "; echo '",
            "a\" ; touch " + m + "; echo \"",
            "/tmp/with space/run dir",
            "x\\$(touch " + m + ")",
            "*",
            "{run_dir}",
            "tab\there",
            "",
            "it's \"quoted\" \\ $HOME"};
  }
  fs::path marker_;
};

TEST_F(SubstituteTest, PlainValuesGoInAsTheyAre) {
  EXPECT_EQ(Substitute("{navd} --config {run_dir}/navd.conf",
                       {{"navd", "/opt/hil/bin/navd"}, {"run_dir", "/srv/runs/a-seed1"}}),
            "/opt/hil/bin/navd --config /srv/runs/a-seed1/navd.conf");
  EXPECT_EQ(Substitute("sh -c 'cat {ttyGPS}'", {{"ttyGPS", "/r/ttyGPS"}}), "sh -c 'cat /r/ttyGPS'");
  EXPECT_EQ(Substitute("{unknown} {seed}", {{"seed", "7"}}), "{unknown} 7");
}

TEST_F(SubstituteTest, EveryValueArrivesAsOneWordOutsideQuotes) {
  for (const std::string& v : Hostile()) {
    const std::string line = Substitute("printf '[%s]' {x}/tail", {{"x", v}});
    EXPECT_EQ(Sh(line), "[" + v + "/tail]") << line;
  }
  EXPECT_FALSE(fs::exists(marker_)) << "a value ran a command";
}

TEST_F(SubstituteTest, EveryValueArrivesAsOneWordInAnInnerShellsScript) {
  for (const std::string& v : Hostile()) {
    const std::string line = Substitute("sh -c 'printf \"[%s]\" {x}/tail'", {{"x", v}});
    EXPECT_EQ(Sh(line), "[" + v + "/tail]") << line;
  }
  EXPECT_FALSE(fs::exists(marker_)) << "a value ran a command";
}

TEST_F(SubstituteTest, EveryValueIsTextInsideDoubleQuotes) {
  for (const std::string& v : Hostile()) {
    const std::string line = Substitute("printf '[%s]' \"{x}/tail\"", {{"x", v}});
    EXPECT_EQ(Sh(line), "[" + v + "/tail]") << line;
  }
  EXPECT_FALSE(fs::exists(marker_)) << "a value ran a command";
}

TEST_F(SubstituteTest, AValueIsNotSubstitutedAgain) {
  EXPECT_EQ(Substitute("{a} {b}", {{"a", "{b}"}, {"b", "B"}}), "'{b}' B");
}

TEST_F(SubstituteTest, EscapedBracesAndQuotesOfTheTemplateKeepTheirMeaning) {
  // a backslash-escaped quote does not open a string: the value after it is outside quotes
  const std::string line = Substitute("printf '[%s]' \\'{x}", {{"x", "a b"}});
  EXPECT_EQ(Sh(line), "['a b]") << line;
}

}  // namespace
}  // namespace hil::harness
