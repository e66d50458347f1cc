// Estimate readers (output adapters), criteria with min thresholds, SVG charts, scenario includes.
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "hil/firmware_emu/gnss/gps_time.h"
#include "hil/harness/devices/scenario_file.h"
#include "hil/harness/dut/estimate_reader.h"
#include "hil/harness/report/report.h"
#include "hil/harness/report/svg_plot.h"
#include "hil/harness/scenario/scenario.h"
#include "hil/harness/scenario/yaml_reader.h"

namespace hil::harness {
namespace {

const UnixTime kStart = gnss::ParseIsoUtc("2013-06-10T08:00:00Z");

TEST(EstimateReaderTest, NavdJsonLines) {
  auto r = MakeEstimateReader(EstimatorOutput::kJsonStdout, kStart);
  const auto e = r->Line(
      R"({"tov_utc_s":1370851202.500000000,"lat_deg":35.5,"lon_deg":50.6,"height_m":1312.5,"vel_enu_mps":[0.1,0.2,0.0],)"
      R"("pos_std_enu_m":[0.3,0.3,0.6],"yaw_deg":30.0,"mode":"gnss_only","status":0})",
      WallTimeFromNs(42));
  ASSERT_TRUE(e);
  EXPECT_EQ(ToNs(e->t_validity), 2'500'000'000LL);
  EXPECT_DOUBLE_EQ(e->lat_deg, 35.5);
  ASSERT_TRUE(e->pos_std_enu_m);
  EXPECT_DOUBLE_EQ(e->pos_std_enu_m->z(), 0.6);
  EXPECT_EQ(e->wall_rx, WallTimeFromNs(42));
  EXPECT_FALSE(r->Line("navd: starting", WallTimeFromNs(1)));
  EXPECT_FALSE(r->Line(R"({"lat_deg":1})", WallTimeFromNs(1)));
}

// n2k_socketcan: the solutions come from the bus; navd's JSON lines on stdout are read for its
// health only, never as solutions, and are not "unparsed" output
TEST(EstimateReaderTest, N2kSocketcanTakesNoSolutionFromLines) {
  auto r = MakeEstimateReader(EstimatorOutput::kN2kSocketcan, kStart);
  EXPECT_FALSE(r->Line(
      R"({"tov_utc_s":1370851202.5,"lat_deg":35.5,"lon_deg":50.6,"height_m":1312.5,"status":0})",
      WallTimeFromNs(1)));
  EXPECT_FALSE(r->SolutionsInLines());
  EXPECT_TRUE(MakeEstimateReader(EstimatorOutput::kJsonStdout, kStart)->SolutionsInLines());
}

TEST(EstimateReaderTest, GpsdTpvObjects) {
  auto r = MakeEstimateReader(EstimatorOutput::kGpsdJson, kStart);
  const auto e = r->Line(
      R"({"class":"TPV","device":"/dev/pts/3","mode":3,"time":"2013-06-10T08:00:03.000Z","ept":0.005,)"
      R"("lat":35.47960960,"lon":50.59797650,"altHAE":1312.000,"track":90.0,"speed":2.0,"climb":0.0,)"
      R"("epx":1.96,"epy":3.92,"epv":5.88})",
      WallTimeFromNs(7));
  ASSERT_TRUE(e);
  EXPECT_EQ(ToNs(e->t_validity), 3'000'000'000LL);
  EXPECT_DOUBLE_EQ(e->height_m, 1312.0);
  ASSERT_TRUE(e->vel_enu_mps);
  EXPECT_NEAR(e->vel_enu_mps->x(), 2.0, 1e-12);
  EXPECT_NEAR(e->vel_enu_mps->y(), 0.0, 1e-12);
  EXPECT_NEAR(e->pos_std_enu_m->y(), 2.0, 1e-12);
  EXPECT_FALSE(r->Line(R"({"class":"SKY","satellites":[]})", WallTimeFromNs(1)));
  EXPECT_FALSE(
      r->Line(R"({"class":"TPV","mode":1,"time":"2013-06-10T08:00:03.000Z","lat":1,"lon":2})",
              WallTimeFromNs(1)))
      << "no fix: no solution";
}

std::string Nmea(const std::string& body) {
  unsigned x = 0;
  for (char c : body) x ^= static_cast<unsigned char>(c);
  char buf[8];
  std::snprintf(buf, sizeof buf, "*%02X", x);
  return "$" + body + buf;
}

TEST(EstimateReaderTest, NmeaGgaWithRmcVelocity) {
  auto r = MakeEstimateReader(EstimatorOutput::kNmeaStdout, kStart);
  EXPECT_FALSE(r->Line(Nmea("GPRMC,080004.00,A,3528.77658,N,05035.87859,E,1.944,90.00,100613,,,A"),
                       WallTimeFromNs(1)));
  EXPECT_FALSE(
      r->Line("$GPGGA,080004.00,3528.77658,N,05035.87859,E,1,08,1.01,1312.0,M,-20.1,M,,*00",
              WallTimeFromNs(2)))
      << "a wrong checksum is no solution";
  const auto e =
      r->Line(Nmea("GPGGA,080004.00,3528.77658,N,05035.87859,E,1,08,1.01,1312.0,M,-20.1,M,,"),
              WallTimeFromNs(2));
  ASSERT_TRUE(e);
  EXPECT_EQ(ToNs(e->t_validity), 4'000'000'000LL);
  EXPECT_NEAR(e->lat_deg, 35 + 28.77658 / 60, 1e-12);
  EXPECT_NEAR(e->lon_deg, 50 + 35.87859 / 60, 1e-12);
  EXPECT_NEAR(e->height_m, 1312.0 - 20.1, 1e-9) << "ellipsoidal = MSL + geoid separation";
  ASSERT_TRUE(e->vel_enu_mps);
  EXPECT_NEAR(e->vel_enu_mps->x(), 1.944 * 1852 / 3600, 1e-9);
  EXPECT_FALSE(r->Line(Nmea("GPGGA,080005.00,,,,,0,00,99.99,,,,,,"), WallTimeFromNs(3)))
      << "quality 0 is no solution";
}

TEST(CriteriaTest, MinimumThresholdsAndRunMetrics) {
  RunReport r;
  r.metrics.samples = 100;
  r.metrics.horizontal_rmse_m = 0.4;
  r.output_rate_hz = 9.5;
  OutageMetrics o;
  o.samples = 10;
  o.max_horizontal_error_m = 2.5;
  o.reconvergence_time_s = 3.0;
  r.outages = {o};
  Criterion rate{"rate", "output_rate_hz", std::nullopt, 10.0, std::nullopt, {}};
  Criterion outage{"outage", "outage_max_horizontal_error_m", 3.0, std::nullopt, std::nullopt, {}};
  Criterion reconv{"reconv", "reconvergence_time_s", 2.0, std::nullopt, std::nullopt, {}};
  Criterion latency{"latency", "latency_p99_ms", 100.0, std::nullopt, std::nullopt, {}};
  const auto res =
      EvaluateCriteria({rate, outage, reconv, latency}, RunMetricTable(r), MetricTable{});
  EXPECT_FALSE(res[0].pass) << "9.5 Hz is below the 10 Hz minimum";
  EXPECT_TRUE(res[1].pass);
  EXPECT_FALSE(res[2].pass);
  EXPECT_FALSE(res[3].pass) << "latency is not measured in virtual mode: the criterion cannot pass";
  EXPECT_FALSE(res[3].value);
}

TEST(SvgPlotTest, RendersSeriesBandsAndTicks) {
  PlotChart c;
  c.title = "error <m>";
  c.series.push_back({"a", "#ff0000", PlotSeries::Style::kLine, {0, 1, 2}, {0, 1, 4}, 0});
  c.series.push_back({"b", "#00ff00", PlotSeries::Style::kPoints, {0, 1}, {2, 3}, 0});
  c.bands.push_back({0.5, 1.5, "outage"});
  const std::string svg = RenderSvg(c);
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  EXPECT_NE(svg.find("<polyline"), std::string::npos);
  EXPECT_EQ(std::count(svg.begin(), svg.end(), '\n') > 10, true);
  EXPECT_NE(svg.find("error &lt;m&gt;"), std::string::npos) << "text is escaped";
  EXPECT_NE(svg.find("GNSS outage"), std::string::npos);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_NE(RenderSvg(PlotChart{}).find("no data"), std::string::npos);
  const auto t = NiceTicks(0.13, 9.7, 5);
  ASSERT_FALSE(t.empty());
  EXPECT_DOUBLE_EQ(t.front(), 2.0);
  EXPECT_DOUBLE_EQ(t[1] - t[0], 2.0);
}

class IncludeTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("hil_include_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_ / "lib" / "vehicles");
    Write("lib/vehicles/tractor.yaml",
          "vehicle: {model: bicycle, wheelbase_m: 2.7, speed_lag_s: 1.5}\n");
    Write("lib/vehicles/broken.yaml", "vehicle:\n  model: bicycle\n  wheelbase_m: 200\n");
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  void Write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
  }
  std::string Path(const std::string& name) const { return (dir_ / name).string(); }
  std::filesystem::path dir_;
};

TEST_F(IncludeTest, IncludedPiecesAreMergedAndTheScenarioWins) {
  Write("s.yaml",
        "name: s\ninclude: [lib/vehicles/tractor.yaml]\norigin: {lat_deg: 35, lon_deg: 50}\n");
  const Scenario s = LoadScenario(Path("s.yaml"));
  EXPECT_DOUBLE_EQ(s.truth.vehicle.wheelbase_m, 2.7);
  EXPECT_DOUBLE_EQ(s.truth.vehicle.speed_lag_s, 1.5);
  Write("own.yaml",
        "name: s\ninclude: lib/vehicles/tractor.yaml\nvehicle: {wheelbase_m: 1.1}\norigin: "
        "{lat_deg: 35, lon_deg: 50}\n");
  EXPECT_DOUBLE_EQ(LoadScenario(Path("own.yaml")).truth.vehicle.wheelbase_m, 1.1);
}

TEST_F(IncludeTest, ErrorsNameTheIncludedFile) {
  Write("s.yaml",
        "name: s\ninclude: [lib/vehicles/broken.yaml]\norigin: {lat_deg: 35, lon_deg: 50}\n");
  try {
    LoadScenario(Path("s.yaml"));
    FAIL();
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.file(), Path("lib/vehicles/broken.yaml"));
    EXPECT_EQ(e.line(), 3);
    EXPECT_EQ(e.field(), "vehicle.wheelbase_m");
  }
  Write("m.yaml", "name: s\ninclude: [lib/nothing.yaml]\norigin: {lat_deg: 35, lon_deg: 50}\n");
  try {
    LoadScenario(Path("m.yaml"));
    FAIL();
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.file(), Path("m.yaml"));
    EXPECT_EQ(e.line(), 2);
    EXPECT_NE(std::string(e.what()).find("cannot find included file 'lib/nothing.yaml'"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(IncludeTest, TheProjectLibraryIsSearched) {
  Write("s.yaml",
        "name: s\ninclude: [vehicles/small_robot.yaml]\norigin: {lat_deg: 35, lon_deg: 50}\n");
  EXPECT_DOUBLE_EQ(LoadScenario(Path("s.yaml")).truth.vehicle.wheelbase_m, 0.84);
}

}  // namespace
}  // namespace hil::harness

namespace hil::harness {
namespace {

TEST(EstimateReaderTest, Nmea2000GnssPositionFastPacketsFromCandumpLines) {
  // PGN 129029 payload: SID, date, time, lat, lon, altitude (+ 12 bytes of the rest, zero)
  const std::int64_t t_ns = ToNs(kStart) + 7'500'000'000LL;
  const auto days = static_cast<std::uint64_t>(t_ns / 86'400'000'000'000LL);
  const auto tod = static_cast<std::uint64_t>((t_ns % 86'400'000'000'000LL) / 100'000LL);
  std::string payload(1, '\x05');
  const auto put = [&](std::uint64_t v, int n) {
    for (int i = 0; i < n; ++i) payload += static_cast<char>((v >> (8 * i)) & 0xFF);
  };
  put(days, 2);
  put(tod, 4);
  put(static_cast<std::uint64_t>(static_cast<std::int64_t>(35.4796096e16)), 8);
  put(static_cast<std::uint64_t>(static_cast<std::int64_t>(50.5979765e16)), 8);
  put(static_cast<std::uint64_t>(static_cast<std::int64_t>(1312.25e6)), 8);
  payload += std::string(43 - payload.size(), '\0');
  // fast packet frames: [seq|0, len, 6 bytes], then [seq|k, 7 bytes]
  std::vector<std::string> frames;
  frames.push_back(std::string{static_cast<char>(3 << 5), static_cast<char>(payload.size())} +
                   payload.substr(0, 6));
  for (std::size_t i = 6, k = 1; i < payload.size(); i += 7, ++k) {
    std::string f(1, static_cast<char>((3 << 5) | static_cast<int>(k)));
    f += payload.substr(i, 7);
    f.resize(8, '\xFF');
    frames.push_back(f);
  }
  auto r = MakeEstimateReader(EstimatorOutput::kN2kCandump, kStart);
  std::optional<EstimateRecord> e;
  for (const auto& f : frames) {
    std::string line = "(1749542407.500000) vcan0 0DF80517#";
    for (unsigned char c : f) {
      char h[3];
      std::snprintf(h, sizeof h, "%02X", c);
      line += h;
    }
    EXPECT_FALSE(e) << "a solution only after the last frame";
    e = r->Line(line, WallTimeFromNs(9));
  }
  ASSERT_TRUE(e);
  EXPECT_EQ(ToNs(e->t_validity), 7'500'000'000LL);
  EXPECT_NEAR(e->lat_deg, 35.4796096, 1e-12);
  EXPECT_NEAR(e->lon_deg, 50.5979765, 1e-12);
  EXPECT_NEAR(e->height_m, 1312.25, 1e-9);
  EXPECT_FALSE(r->Line("(1749542407.500000) vcan0 09F80117#A0B3F2150AB5A61E", WallTimeFromNs(1)))
      << "129025 is not read";
}

}  // namespace
}  // namespace hil::harness
