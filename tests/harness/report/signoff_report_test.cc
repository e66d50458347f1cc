// The sign-off report (report.html): one self-contained file whose header says what was tested,
// whose verdict gives each criterion's meaning, and where values outside their band stand out.
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>

#include "hil/harness/report/report_html.h"
#include "hil/harness/report/signoff_sections.h"

namespace hil::harness {
namespace {

std::string ReadAll(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t Count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

class SignoffReportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("signoff_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
    report_.scenario = "field_9m";
    report_.scenario_file = "/fields/field_9m.yaml";
    report_.seed = 42;
    report_.mode = "virtual";
    report_.metrics.samples = report_.baselines.samples = 20;
    report_.metrics.horizontal_rmse_m = 0.5;
    report_.baselines.horizontal_rmse_m = 1.0;
    report_.metrics.nees_horizontal_mean = 40.0;  // over-confident
    report_.metrics.heading_rmse_deg = 6.5;
    report_.criteria.push_back({"default nees_horizontal: nees_horizontal_mean <= 4", 4.0, 40.0,
                                false, "nees_horizontal"});
    report_.criteria.push_back({"horizontal_rmse_m <= 1", 1.0, 0.5, true, ""});
    for (int i = 0; i < 20; ++i) {
      ErrorSample s;
      s.t = TimeFromSeconds(i);
      s.truth_enu_m = {0.4 * i, 0, 0};
      s.est_enu_m = {0.4 * i, 0.3, 0};
      s.err_enu_m = s.est_enu_m - s.truth_enu_m;
      s.nees_horizontal = 40.0;
      series_.estimate_errors.push_back(s);
      series_.truth_t_s.push_back(i);
      series_.truth_en_m.emplace_back(0.4 * i, 0);
    }
    header_.scenario_sha256 = std::string(64, 'a');
    header_.origin_lat_deg = 52.2;
    header_.origin_lon_deg = 5.1;
    header_.origin_height_m = 47.25;
    header_.run_started_utc = "2026-12-06 12:00:00 UTC";
    header_.scenario_start_utc = "2026-06-10 08:00:00 UTC";
    header_.devices = {{"gnss_receiver", "ttyGPS", "profile neo-5m, 1 Hz, 9600 Bd"},
                       {"mcu", "ttyIMU", "IMU profile razor-v13, IMU 10 Hz"}};
    header_.hil_version = "0.1.0";
    header_.hil_commit = "0123456789ab";
    header_.estimator_build = "navd 0.1.0 from the same build as hil";
    header_.cpu_model = "Test CPU 3000";
    header_.kernel = "6.1.0-test";
    header_.cpus_online = 2;
    header_.stepping = "virtual";
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::string Html() {
    WriteReportHtml(report_, series_, header_, dir_.string());
    return ReadAll(dir_ / "report.html");
  }

  std::filesystem::path dir_;
  RunReport report_;
  ReportSeries series_;
  RunHeader header_;
};

TEST_F(SignoffReportTest, HeaderSaysWhatWasTested) {
  const std::string h = Html();
  for (const std::string& field :
       {std::string("field_9m"), std::string("/fields/field_9m.yaml"), std::string(64, 'a'),
        std::string("52.2000000"), std::string("5.1000000"),
        std::string("47.25 m above the WGS-84 ellipsoid"), std::string("2026-12-06 12:00:00 UTC"),
        std::string("2026-06-10 08:00:00 UTC"), std::string("gnss_receiver"),
        std::string("profile neo-5m, 1 Hz, 9600 Bd"), std::string("IMU profile razor-v13"),
        std::string("version 0.1.0"), std::string("0123456789ab"),
        std::string("navd 0.1.0 from the same build"), std::string("Test CPU 3000"),
        std::string("6.1.0-test"), std::string("<th>mode</th><td>virtual, speed 1.00x")}) {
    EXPECT_NE(h.find(field), std::string::npos) << field;
  }
  EXPECT_NE(h.find("<th>seed</th><td>42</td>"), std::string::npos);
}

TEST_F(SignoffReportTest, SelfContainedWithInlineCharts) {
  const std::string h = Html();
  EXPECT_EQ(h.find("<img"), std::string::npos);
  EXPECT_EQ(h.find("<script"), std::string::npos);
  EXPECT_EQ(h.find("<link"), std::string::npos);
  EXPECT_EQ(h.find("src=\"http"), std::string::npos);
  EXPECT_EQ(h.find("url(http"), std::string::npos);
  // map, zoom, cross-track, error against time, NEES, CDF: inline, each with its own clip path
  EXPECT_EQ(Count(h, "<svg xmlns"), 6U);
  for (const char* id : {"map", "zoom", "xte", "error_time", "nees", "cdf"})
    EXPECT_EQ(Count(h, std::string("clipPath id=\"") + id + "\""), 1U) << id;
}

TEST_F(SignoffReportTest, VirtualModeSaysTheLatencyChartDoesNotApply) {
  const std::string h = Html();
  EXPECT_NE(h.find("the latency chart does not apply"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir_ / "plots/latency_histogram.svg"));
  for (const double ms : {1.0, 2.0, 2.5}) series_.latency_ms.Add(ms);
  report_.mode = "scaled x5";
  header_.stepping = "lockstep";  // no per-byte schedule: says so
  const std::string lockstep = Html();
  EXPECT_EQ(lockstep.find("does not apply"), std::string::npos);
  EXPECT_NE(lockstep.find("Lockstep: the links carry the virtual run's bytes"), std::string::npos);
  report_.mode = "realtime";
  header_.stepping = "free_running";
  header_.links = {{"ttyGPS", 100, "bytes", 10.0, 50.0, 80.0, 3}};
  const std::string rt = Html();
  EXPECT_EQ(rt.find("does not apply"), std::string::npos);
  EXPECT_NE(rt.find("clipPath id=\"latency\""), std::string::npos);
  EXPECT_NE(
      rt.find("<td>ttyGPS</td><td>100 bytes</td><td>10 / 50 / 80</td><td class=\"flagged\">3"),
      std::string::npos);
}

TEST_F(SignoffReportTest, CriteriaSayWhatTheyMean) {
  const std::string h = Html();
  EXPECT_NE(h.find("mean horizontal NEES (2 DOF, 2 when consistent) at most this"),
            std::string::npos);
  EXPECT_NE(h.find("root mean square of the horizontal error against truth"), std::string::npos);
  EXPECT_NE(h.find("class=\"verdict fail\">FAIL"), std::string::npos);
}

TEST_F(SignoffReportTest, NeesFortyAndHeadingSixAndAHalfStandOut) {
  const std::vector<ReviewFlag> flags = ReviewFlags(report_);
  ASSERT_EQ(flags.size(), 2U);
  EXPECT_EQ(flags[0].metric, "nees_horizontal_mean");
  EXPECT_TRUE(flags[0].severe);
  EXPECT_EQ(flags[1].metric, "heading_rmse_deg");
  const std::string h = Html();
  EXPECT_NE(h.find("<td>nees_horizontal_mean</td><td class=\"flagged\">40</td>"),
            std::string::npos);
  EXPECT_NE(h.find("<td>heading_rmse_deg</td><td class=\"flagged\">6.5</td>"), std::string::npos);
  // the accuracy table marks the same cells
  EXPECT_NE(h.find("<td>heading_rmse_deg</td><td class=\"flagged\">6.500</td>"), std::string::npos);
  // and the verdict at a glance says there are two to review, linking to them (a PASS with a
  // red NEES further down read as clean at a glance)
  const std::size_t verdict = h.find("Verdict at a glance"), review = h.find("id=\"review\"");
  const std::size_t link = h.find("<a class=\"review\" href=\"#review\">2 value(s) outside");
  ASSERT_NE(link, std::string::npos);
  EXPECT_LT(verdict, link);
  EXPECT_LT(link, review);
}

// A tractor on ISO 11783-7: the closed-loop section shows its steering ECU (the report showed
// only the controller's counters; frames lost, refusals, the exit reason were in report.json).
TEST_F(SignoffReportTest, ClosedLoopShowsTheSteeringEcu) {
  ClosedLoopReport c;
  SteeringEcuReport e;
  e.transport = "slcan";
  e.frames_from_controller = 120;
  e.frames_lost = 3;
  e.commands_accepted = 110;
  e.out_of_range = 2;
  e.engagements = 1;
  e.watchdog_trips = 1;
  e.exit_reason_code = 1;
  e.exit_reason = "remote_command_timeout";
  e.commanded_steer_rms_error_deg = 0.42;
  c.steering_ecu = e;
  report_.closed_loop = c;
  const std::string h = Html();
  EXPECT_NE(h.find("<h3>Steering ECU (ISO 11783-7 over slcan)</h3>"), std::string::npos) << h;
  EXPECT_NE(h.find("<td>120 / 3</td>"), std::string::npos);
  EXPECT_NE(h.find("<td>110 / 0, 0, 2</td>"), std::string::npos);
  EXPECT_NE(h.find("<td class=\"flagged-note\">remote_command_timeout</td>"), std::string::npos);
  EXPECT_NE(h.find("<td>0.420 deg</td>"), std::string::npos);
}

TEST_F(SignoffReportTest, ValuesInsideTheirBandAreNotFlagged) {
  report_.metrics.nees_horizontal_mean = 2.1;
  report_.metrics.heading_rmse_deg = 3.0;
  EXPECT_TRUE(ReviewFlags(report_).empty());
  report_.metrics.nees_horizontal_mean = 0.3;  // conservative: noted, not severe
  report_.metrics.horizontal_rmse_m = 1.3;     // worse than the raw fixes' 1.0 by > 1.2 x
  const std::vector<ReviewFlag> flags = ReviewFlags(report_);
  ASSERT_EQ(flags.size(), 2U);
  EXPECT_FALSE(flags[0].severe);
  EXPECT_EQ(flags[1].metric, "horizontal_rmse_m");
  EXPECT_TRUE(flags[1].severe);
}

}  // namespace
}  // namespace hil::harness
