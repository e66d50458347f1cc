#include "hil/estimator/datasets/text_line_reader.h"

#include <gtest/gtest.h>

#include "datasets/kfgins_test_files.h"

namespace hil::estimator::datasets {
namespace {

TEST(TextLineReader, SkipsBlankAndCommentLinesAndCountsLines) {
  const testing::ScopedTempDir tmp;
  const std::string& dir = tmp.path;
  TextLineReader r(testing::WriteFile(dir, "a.txt", "# header\n\n  1 2,3\r\n% matlab\n4\t5\n"));
  std::string_view line;
  double v[4];
  ASSERT_TRUE(r.Next(line));
  EXPECT_EQ(r.line_number(), 3);
  ASSERT_EQ(r.ParseNumbers(line, v, 4), 3);
  EXPECT_DOUBLE_EQ(v[2], 3.0);
  ASSERT_TRUE(r.Next(line));
  EXPECT_EQ(r.line_number(), 5);
  EXPECT_EQ(r.ParseNumbers(line, v, 4), 2);
  EXPECT_FALSE(r.Next(line));
}

TEST(TextLineReader, NamesFileLineAndFieldOfABadNumber) {
  const testing::ScopedTempDir tmp;
  const std::string& dir = tmp.path;
  const std::string path = testing::WriteFile(dir, "b.txt", "1 2\n1 nan\n1 x2\n");
  TextLineReader r(path);
  std::string_view line;
  double v[2];
  const char* names[] = {"sow", "gyro"};
  ASSERT_TRUE(r.Next(line));
  EXPECT_EQ(r.ParseNumbers(line, v, 2, names), 2);
  ASSERT_TRUE(r.Next(line));
  try {
    r.ParseNumbers(line, v, 2, names);
    FAIL() << "NaN accepted";
  } catch (const DatasetError& e) {
    EXPECT_EQ(std::string(e.what()), path + ":2: gyro: not finite: 'nan'");
  }
  ASSERT_TRUE(r.Next(line));
  EXPECT_THROW(r.ParseNumbers(line, v, 2, names), DatasetError);
}

TEST(TextLineReader, MissingFileIsAnError) {
  try {
    TextLineReader r("/nonexistent/imu.txt");
    FAIL();
  } catch (const DatasetError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/imu.txt: cannot open"), std::string::npos);
  }
}

}  // namespace
}  // namespace hil::estimator::datasets
