// `hil dataset import`'s readers (RTKLIB .pos and time tags, IMU CSV, UBX), the outage plan, the
// lag and alignment estimates on a synthetic walk of known lag, and the outage scoring. The real
// walk (../shared/vectors/real_imu/walk_0827) is imported when present, else the test is skipped.
#include "hil/harness/datasets/dataset_import.h"

#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include <gtest/gtest.h>

#include "hil/harness/datasets/import_fields.h"
#include "hil/harness/datasets/outage_score.h"
#include "hil/harness/datasets/rtklib_pos.h"
#include "hil/harness/datasets/rtklib_timetag.h"
#include "hil/harness/datasets/ubx_nav_log.h"

namespace hil::harness {
namespace {

constexpr double kPi = std::numbers::pi;

struct TempDir {
  std::string path;
  TempDir() {
    char tmpl[] = "/tmp/dataset_import_XXXXXX";
    path = mkdtemp(tmpl);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
};

std::string Vectors() {
  const char* src = std::getenv("HIL_SOURCE_DIR");
  return std::string(src ? src : ".") + "/vectors/datasets/import/";
}

void WriteFile(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

std::string ErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(RtklibPos, ReadsCalendarTimesVelocitiesAndSigma) {
  const std::vector<RtklibPosEpoch> e = ReadRtklibPos(Vectors() + "small.pos");
  ASSERT_EQ(e.size(), 3u);
  EXPECT_EQ(e[0].week, 2381);
  EXPECT_NEAR(e[0].sow, 408639.749, 1e-9);  // Thursday 17:30:39.749 of GPS week 2381
  EXPECT_DOUBLE_EQ(e[0].lat_deg, 40.0966916);
  EXPECT_DOUBLE_EQ(e[0].lon_deg, -105.1471665);
  EXPECT_EQ(e[1].quality, 2);
  EXPECT_EQ(e[2].satellites, 9);
  EXPECT_DOUBLE_EQ(e[1].std_ned_m.y(), 0.06);
  ASSERT_TRUE(e[1].has_velocity);
  EXPECT_DOUBLE_EQ(e[1].v_ned_mps.x(), 1.0);
  EXPECT_DOUBLE_EQ(e[1].v_ned_mps.z(), 0.1);  // vu −0.1 up is 0.1 down
  EXPECT_DOUBLE_EQ(e[0].v_std_ned_mps.y(), 0.0494);
}

TEST(RtklibPos, ReadsWeekAndSecondsWithoutVelocities) {
  const std::vector<RtklibPosEpoch> e = ReadRtklibPos(Vectors() + "small_weektow.pos");
  ASSERT_EQ(e.size(), 2u);
  EXPECT_EQ(e[1].week, 2381);
  EXPECT_DOUBLE_EQ(e[1].sow, 408640.0);
  EXPECT_FALSE(e[1].has_velocity);
}

TEST(RtklibPos, BadInputNamesFileLineAndField) {
  const TempDir d;
  const std::string header =
      "%  GPST latitude(deg) longitude(deg) height(m) Q ns sdn(m) sde(m) sdu(m)\n";
  const std::string p = d.path + "/bad.pos";
  WriteFile(p, header + "2025/08/28 17:30:39.749 40.1 -105.1 1601.4 1 25 0.01 x 0.01\n");
  EXPECT_EQ(ErrorOf([&] { ReadRtklibPos(p); }), p + ":2: sde: 'x' is not a finite number");
  WriteFile(p, header + "2025/08/28 17:30:39.749 40.1 -105.1 1601.4 1 25 0.01 0.01\n");
  EXPECT_EQ(ErrorOf([&] { ReadRtklibPos(p); }), p + ":2: sdu: missing");
  WriteFile(p, header + "2025/08/28 17:30:39.749 40.1 -105.1 1 1 25 0.01 0.01 0.01\n" +
                   "2025/08/28 17:30:39.749 40.1 -105.1 1 1 25 0.01 0.01 0.01\n");
  EXPECT_EQ(ErrorOf([&] { ReadRtklibPos(p); }), p + ":3: GPST: time repeats or goes backwards");
  WriteFile(p, "%  UTC latitude(deg)\n2025/08/28 17:30:39.749 40.1\n");
  EXPECT_EQ(ErrorOf([&] { ReadRtklibPos(p); }), p + ":1: time system: 'UTC' (only GPST is read)");
  WriteFile(p, header + "2025/08/28 17:30:39.749 95 -105.1 1 1 25 0.01 0.01 0.01\n");
  EXPECT_EQ(ErrorOf([&] { ReadRtklibPos(p); }), p + ":2: latitude: outside ±90°");
}

// RTKLIB's time-tag layout: 60 bytes of text, u32 tick at opening, u32 seconds + double fraction
// (GPST), then (u32 tick, u32 or u64 file position) records
std::string TagBytes(const std::vector<std::pair<std::uint32_t, std::uint64_t>>& rec, int fpos,
                     const char* text = "TIMETAG RTKLIB EX 2.5.0") {
  std::string b(64, '\0');
  std::memcpy(b.data(), text, std::strlen(text));
  const std::uint32_t tick0 = 705026197, secs = 1756402240;
  const double frac = 0.961;
  std::memcpy(b.data() + 60, &tick0, 4);
  b.append(reinterpret_cast<const char*>(&secs), 4);
  b.append(reinterpret_cast<const char*>(&frac), 8);
  for (const auto& [tick, pos] : rec) {
    b.append(reinterpret_cast<const char*>(&tick), 4);
    if (fpos == 4) {
      const auto p32 = static_cast<std::uint32_t>(pos);
      b.append(reinterpret_cast<const char*>(&p32), 4);
    } else {
      b.append(reinterpret_cast<const char*>(&pos), 8);
    }
  }
  return b;
}

TEST(RtklibTimeTag, ReadsHeaderAndRecordsAndDatesBytes) {
  const TempDir d;
  const std::string p = d.path + "/x.tag";
  WriteFile(p, TagBytes({{113, 835}, {128, 943}, {144, 1067}}, 4));
  const RtklibTimeTag t = ReadRtklibTimeTag(p);
  EXPECT_EQ(t.header, "TIMETAG RTKLIB EX 2.5.0");
  EXPECT_EQ(t.open_tick_ms, 705026197u);
  EXPECT_DOUBLE_EQ(t.open_gpst_s, 1756402240.961);
  ASSERT_EQ(t.records.size(), 3u);
  EXPECT_NEAR(RtklibTimeTagTimeOf(t, 900), 1756402240.961 + 0.128, 1e-9);
  EXPECT_NEAR(RtklibTimeTagTimeOf(t, 835), 1756402240.961 + 0.113, 1e-9);
  EXPECT_THROW(RtklibTimeTagTimeOf(t, 2000), std::out_of_range);
  WriteFile(p, TagBytes({{113, 835}, {128, 1u << 20}}, 8));
  EXPECT_EQ(ReadRtklibTimeTag(p, 8).records[1].file_pos, 1u << 20);
}

TEST(RtklibTimeTag, BadFilesNameTheRecord) {
  const TempDir d;
  const std::string p = d.path + "/x.tag";
  WriteFile(p, TagBytes({{113, 835}}, 4, "NOT A TAG"));
  EXPECT_EQ(ErrorOf([&] { ReadRtklibTimeTag(p); }),
            p + ": header: does not start with 'TIMETAG RTKLIB'");
  WriteFile(p, TagBytes({{113, 835}, {100, 900}}, 4));
  EXPECT_EQ(ErrorOf([&] { ReadRtklibTimeTag(p); }), p + ":2: tick: goes backwards");
  WriteFile(p, TagBytes({{113, 835}}, 4) + "abc");
  EXPECT_EQ(ErrorOf([&] { ReadRtklibTimeTag(p); }),
            p + ":2: record: partial record (3 bytes) at the end");
}

TEST(ImuCsv, SkipsLinesCutAtTheLogsEndsAndConvertsUnits) {
  const ImuCsv c = ReadImuCsv(Vectors() + "imu_cut.csv", ImuCsvOptions{});
  ASSERT_EQ(c.samples.size(), 3u);
  EXPECT_EQ(c.cut_lines, 2);
  EXPECT_EQ(c.newlines, 4u);
  EXPECT_EQ(c.samples[0].line, 2);
  EXPECT_NEAR(c.samples[0].f_sensor_mps2.z(), 1.011 * 9.80665, 1e-12);
  EXPECT_NEAR(c.samples[1].w_sensor_radps.x(), 0.114 * kPi / 180, 1e-15);
  EXPECT_DOUBLE_EQ(c.samples[2].tick_s, 3326.357);
  EXPECT_EQ(c.samples[0].end_pos, 39u + 47u);  // the cut first line: 39 bytes with its newline
}

TEST(ImuCsv, ABadLineInsideTheLogIsAnError) {
  const TempDir d;
  const std::string p = d.path + "/bad.csv";
  WriteFile(p, "1,2,3,4,5,6,7\n1,2,3,4,5,6\n1,2,3,4,5,6,9\n");
  EXPECT_EQ(ErrorOf([&] { ReadImuCsv(p, {}); }),
            p + ":2: fields: too few (a cut line inside the log)");
  WriteFile(p, "1,2,3,4,5,6,7\n1,2,3,nan,5,6,8\n1,2,3,4,5,6,9\n");
  EXPECT_EQ(ErrorOf([&] { ReadImuCsv(p, {}); }), p + ":2: gyro x: 'nan' is not a finite number");
  WriteFile(p, "1,2,3,4,5,6,7\n1,2,3,4,5,6,7\n1,2,3,4,5,6,9\n");
  EXPECT_EQ(ErrorOf([&] { ReadImuCsv(p, {}); }), p + ":2: tick: does not increase");
}

std::string UbxFrame(std::uint8_t cls, std::uint8_t id, const std::string& payload) {
  std::string f = "\xB5\x62";
  f += static_cast<char>(cls);
  f += static_cast<char>(id);
  f += static_cast<char>(payload.size() & 0xFF);
  f += static_cast<char>(payload.size() >> 8);
  f += payload;
  std::uint8_t a = 0, b = 0;
  for (std::size_t i = 2; i < f.size(); ++i)
    a = static_cast<std::uint8_t>(a + f[i]), b = static_cast<std::uint8_t>(b + a);
  f += static_cast<char>(a);
  f += static_cast<char>(b);
  return f;
}

template <typename T>
void Put(std::string& p, std::size_t at, T v) {
  std::memcpy(p.data() + at, &v, sizeof v);
}

std::string NavPvt(std::uint32_t itow, std::uint8_t fix, std::uint8_t flags) {
  std::string p(92, '\0');
  Put<std::uint32_t>(p, 0, itow);
  Put<std::int32_t>(p, 16, -250000);  // nano: −0.25 ms
  p[20] = static_cast<char>(fix);
  p[21] = static_cast<char>(flags);
  Put<std::int32_t>(p, 24, -1051471665);
  Put<std::int32_t>(p, 28, 400966916);
  Put<std::int32_t>(p, 32, 1601435);
  Put<std::int32_t>(p, 36, 1580048);  // hMSL
  Put<std::uint32_t>(p, 40, 14);      // hAcc mm
  Put<std::uint32_t>(p, 44, 10);      // vAcc mm
  Put<std::int32_t>(p, 48, 1000);     // velN mm/s
  Put<std::int32_t>(p, 52, -500);
  Put<std::int32_t>(p, 56, 20);
  Put<std::uint32_t>(p, 68, 50);  // sAcc mm/s
  return p;
}

TEST(UbxNavLog, ReadsNavPvtAmongOtherMessagesAndCountsDamage) {
  const TempDir d;
  const std::string p = d.path + "/x.ubx";
  std::string bad = UbxFrame(0x01, 0x07, NavPvt(408640000, 3, 0x81));
  bad[10] ^= 0x55;
  WriteFile(p, "$GPGGA,junk\r\n" + UbxFrame(0x02, 0x15, std::string(16, 'r')) +
                   UbxFrame(0x01, 0x07, NavPvt(408639750, 3, 0x81)) + bad +
                   UbxFrame(0x01, 0x07, NavPvt(408640250, 1, 0x00)) +
                   UbxFrame(0x01, 0x07, NavPvt(408639750, 3, 0x01)) +  // iTOW repeated
                   UbxFrame(0x01, 0x07, NavPvt(408640500, 3, 0x41)).substr(0, 30));
  const UbxNavLog log = ReadUbxNavLog(p);
  EXPECT_EQ(log.bad_checksum, 1u);
  EXPECT_EQ(log.cut_frames, 1u);
  EXPECT_EQ(log.nav_pvt, 3u);
  EXPECT_EQ(log.not_fixed, 1u);
  EXPECT_EQ(log.duplicates, 1u);
  ASSERT_EQ(log.fixes.size(), 1u);
  const UbxNavFix& f = log.fixes[0];
  EXPECT_DOUBLE_EQ(f.sow, 408639.75);  // iTOW alone (nano is the UTC time's)
  EXPECT_DOUBLE_EQ(f.lat_deg, 40.0966916);
  EXPECT_DOUBLE_EQ(f.lon_deg, -105.1471665);
  EXPECT_DOUBLE_EQ(f.height_msl_m, 1580.048);
  EXPECT_NEAR(f.std_ned_m.x(), 0.014 / std::sqrt(2.0), 1e-12);
  EXPECT_DOUBLE_EQ(f.v_ned_mps.y(), -0.5);
  EXPECT_EQ(f.carrier_solution, 2);
  WriteFile(p, UbxFrame(0x01, 0x07, std::string(40, '\0')));
  EXPECT_EQ(ErrorOf([&] { ReadUbxNavLog(p); }),
            p + ": NAV-PVT: payload of 40 bytes at byte offset 0 (expected 92)");
}

TEST(UbxNavLog, JoinsPosLlhAndVelNedWithoutNavPvt) {
  const TempDir d;
  const std::string p = d.path + "/x.ubx";
  std::string pos(28, '\0'), vel(36, '\0');
  Put<std::uint32_t>(pos, 0, 1000);
  Put<std::int32_t>(pos, 8, 400000000);
  Put<std::uint32_t>(pos, 20, 2000);
  Put<std::uint32_t>(vel, 0, 1000);
  Put<std::int32_t>(vel, 4, 150);  // cm/s
  Put<std::uint32_t>(vel, 28, 20);
  WriteFile(p, UbxFrame(0x01, 0x02, pos) + UbxFrame(0x01, 0x12, vel));
  const UbxNavLog log = ReadUbxNavLog(p);
  ASSERT_EQ(log.fixes.size(), 1u);
  EXPECT_DOUBLE_EQ(log.fixes[0].lat_deg, 40.0);
  EXPECT_DOUBLE_EQ(log.fixes[0].v_ned_mps.x(), 1.5);
  EXPECT_DOUBLE_EQ(log.fixes[0].v_std_ned_mps.z(), 0.2);
}

TEST(OutageWindows, ListOrPeriodicWithinTheData) {
  OutagePlan p;
  p.every_s = 30, p.first_s = 20, p.length_s = 15;
  const std::vector<OutageWindow> w = PlanOutages(p, 1000, 1100);
  ASSERT_EQ(w.size(), 3u);  // 20, 50, 80 (ends at 95 < 100)
  EXPECT_DOUBLE_EQ(w[2].start_s, 1080);
  EXPECT_DOUBLE_EQ(w[2].end_s, 1095);
  EXPECT_TRUE(InOutage(w, 1080));
  EXPECT_FALSE(InOutage(w, 1095));
  p.every_s = 10;
  EXPECT_THROW(PlanOutages(p, 0, 100), std::invalid_argument);
  OutagePlan l;
  l.at_s = {10, 15};
  EXPECT_THROW(PlanOutages(l, 0, 100), std::invalid_argument);
}

// A synthetic walk of our own: 6 s at rest, then 1 m/s with the heading swinging ±40° (period
// 8 s); IMU at 100 Hz, level, sensor axes FLU (so --imu-axes x,-y,-z), gyro bias 0.2 °/s on z,
// logged with its tags 0.080 s late; RTKLIB-style reference at 4 Hz with velocities.
struct SyntheticWalk {
  static constexpr double kLag = 0.080, kStart = 1756402250.0, kYaw0 = 0.6;
  static constexpr double kLat = 40.0966916, kLon = -105.1471665, kH = 1601.4;
  static double Speed(double t) { return t < 6 ? 0 : std::min(1.0, (t - 6) / 2); }
  static double Yaw(double t) {
    return kYaw0 + (t < 6 ? 0 : 0.7 * std::sin(2 * kPi * (t - 6) / 8));
  }
  static double YawRate(double t) {
    return t < 6 ? 0 : 0.7 * 2 * kPi / 8 * std::cos(2 * kPi * (t - 6) / 8);
  }

  // files in `dir`: walk.pos, imu.csv, imu.csv.tag
  static void Write(const std::string& dir, double seconds) {
    const double g = NormalGravity(kLat, kH);
    std::string csv, pos =
                         "%  GPST latitude(deg) longitude(deg) height(m) Q ns sdn(m) sde(m) sdu(m) "
                         "sdne(m) sdeu(m) sdun(m) age(s) ratio vn(m/s) ve(m/s) vu(m/s) sdvn sdve "
                         "sdvu sdvne sdveu sdvun\n";
    std::vector<std::pair<std::uint32_t, std::uint64_t>> tags;
    double n = 0, e = 0;
    const double dt = 0.01;
    for (int k = 0; k * dt <= seconds; ++k) {
      const double t = k * dt, v = Speed(t), psi = Yaw(t);
      const double dv = t < 6 || t > 8 ? 0 : 0.5;
      const Eigen::Vector2d a_ne(dv * std::cos(psi) - v * YawRate(t) * std::sin(psi),
                                 dv * std::sin(psi) + v * YawRate(t) * std::cos(psi));
      // body FRD specific force of a level body: Rz(ψ)ᵀ (a − g)
      const double fx = std::cos(psi) * a_ne.x() + std::sin(psi) * a_ne.y();
      const double fy = -std::sin(psi) * a_ne.x() + std::cos(psi) * a_ne.y();
      char line[160];
      std::snprintf(line, sizeof line, "%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%d\n", fx / 9.80665,
                    -fy / 9.80665, g / 9.80665, 0.0, 0.0, -(YawRate(t) * 180 / kPi + 0.2),
                    5000 + 10 * k);
      csv += line;
      tags.emplace_back(static_cast<std::uint32_t>(std::lround((t + kLag) * 1000)), csv.size());
      if (k % 25 == 0) {
        const GpsWeekSow w = GpsFromGpstEpochSeconds(kStart + t);
        const double lat = kLat + n / 6369000.0 * 180 / kPi;
        const double lon = kLon + e / (6387000.0 * std::cos(kLat * kPi / 180)) * 180 / kPi;
        std::snprintf(line, sizeof line,
                      "%d %.3f %.9f %.9f %.4f 1 20 0.01 0.01 0.02 0 0 0 0 0 %.5f %.5f 0 0.05 0.05 "
                      "0.05 0 0 0\n",
                      w.week, w.sow, lat, lon, kH, v * std::cos(psi), v * std::sin(psi));
        pos += line;
      }
      n += v * std::cos(psi) * dt, e += v * std::sin(psi) * dt;
    }
    WriteFile(dir + "/walk.pos", pos);
    WriteFile(dir + "/imu.csv", csv);
    std::string tag(64, '\0');
    std::memcpy(tag.data(), "TIMETAG RTKLIB synthetic", 24);
    const auto secs = static_cast<std::uint32_t>(kStart);
    const double frac = 0;
    tag.append(reinterpret_cast<const char*>(&secs), 4)
        .append(reinterpret_cast<const char*>(&frac), 8);
    for (const auto& [tick, p] : tags) {
      const auto p32 = static_cast<std::uint32_t>(p);
      tag.append(reinterpret_cast<const char*>(&tick), 4)
          .append(reinterpret_cast<const char*>(&p32), 4);
    }
    WriteFile(dir + "/imu.csv.tag", tag);
  }
};

DatasetImportOptions SyntheticOptions(const std::string& dir) {
  DatasetImportOptions o;
  o.reference_pos = dir + "/walk.pos";
  o.imu_csv = dir + "/imu.csv";
  o.imu_axes = "x,-y,-z";
  o.outages.every_s = 20, o.outages.first_s = 15, o.outages.length_s = 10;
  o.have_outages = true;
  return o;
}

TEST(DatasetImport, FindsTheLagTheAttitudeAndTheBiasOfASyntheticWalk) {
  const TempDir d;
  SyntheticWalk::Write(d.path, 60);
  const DatasetImportResult r = ImportDataset(SyntheticOptions(d.path), d.path + "/out");
  ASSERT_TRUE(r.lag.has_value());
  EXPECT_NEAR(r.lag_s, SyntheticWalk::kLag, 0.003) << r.report;
  EXPECT_GT(r.lag->correlation, 0.99);
  const ImuAlignment& a = r.alignment;
  EXPECT_NEAR(a.yaw_rad, SyntheticWalk::kYaw0, 0.5 * kPi / 180) << r.report;
  EXPECT_NEAR(a.roll_rad, 0, 1e-4);
  EXPECT_NEAR(a.pitch_rad, 0, 1e-4);
  EXPECT_NEAR(a.gyro_bias_frd_radps.z(), 0.2 * kPi / 180, 1e-6);  // sensor −z is FRD z
  EXPECT_NEAR(a.mount_yaw_rad, 0, 1.0 * kPi / 180);
  EXPECT_LT(a.accel_bias_frd_mps2.norm(), 1e-5);
  ASSERT_EQ(r.windows.size(), 2u);  // 15-25 and 35-45 s after the start (55-65 would pass the end)
  EXPECT_EQ(r.gnss_lines + 80u, r.truth_lines);  // 2 × 10 s at 4 Hz dropped
  for (const char* f : {"IMU.txt", "GNSS.txt", "GNSS-POSVEL.txt", "truth.nav", "kf-gins.yaml",
                        "kf-gins-posvel.yaml", "outages.txt", "import_report.txt"})
    EXPECT_TRUE(std::filesystem::exists(d.path + "/out/" + f)) << f;
  const std::vector<OutageWindow> w = ReadOutageWindows(d.path + "/out/outages.txt");
  ASSERT_EQ(w.size(), 2u);
  EXPECT_NEAR(w[0].end_s - w[0].start_s, 10.0, 1e-9);
}

TEST(DatasetImport, AGivenOffsetIsUsedAndWrongAxesAreRefused) {
  const TempDir d;
  SyntheticWalk::Write(d.path, 30);
  DatasetImportOptions o = SyntheticOptions(d.path);
  o.imu_lag_s = 0.08;
  o.have_outages = false;
  const DatasetImportResult r = ImportDataset(o, d.path + "/out");
  EXPECT_FALSE(r.lag.has_value());
  EXPECT_DOUBLE_EQ(r.lag_s, 0.08);
  o.imu_axes = "x,y,z";  // sensor z up taken as down
  EXPECT_NE(ErrorOf([&] { ImportDataset(o, d.path + "/out2"); }).find("choose other axes"),
            std::string::npos);
  o.imu_axes = "x,x,z";
  EXPECT_THROW(ImportDataset(o, d.path + "/out3"), std::invalid_argument);
}

KfginsNavLine NavAt(double sow, double north_m, double up_m, double yaw_deg) {
  KfginsNavLine l;
  l.sow = sow;
  l.lat_deg = 40 + north_m / 6364000.0 * 180 / kPi;  // about the meridian radius at 40°
  l.lon_deg = -105;
  l.height_m = 1600 + up_m;
  l.rpy_deg.z() = yaw_deg;
  return l;
}

TEST(OutageScore, PerWindowMaximaRmsHeadingAndNees) {
  std::vector<KfginsNavLine> truth, est;
  std::vector<KfginsStdLine> stds;
  for (int k = 0; k <= 400; ++k) {  // 100 s at 4 Hz, the result at 8 Hz
    const double t = 1000 + 0.25 * k;
    truth.push_back(NavAt(t, 0, 0, 10));
  }
  for (int k = 0; k <= 800; ++k) {
    const double t = 1000 + 0.125 * k;
    const bool in1 = t >= 1020 && t < 1030, in2 = t >= 1060 && t < 1070;
    const double err = in1 ? (t - 1020) * 0.1 : in2 ? 2.0 : 0.01;  // window 1 grows to ~1 m
    est.push_back(NavAt(t, err, in2 ? 1.5 : 0, in2 ? 13 : 10));
    stds.push_back({t, Eigen::Vector3d::Constant(0.01), Eigen::Vector3d::Constant(1e3)});
  }
  const OutageScore s = ScoreOutages(truth, est, {{1020, 1030}, {1060, 1070}}, 0, &stds);
  ASSERT_EQ(s.windows.size(), 2u);
  EXPECT_EQ(s.windows[0].epochs, 40u);
  EXPECT_NEAR(s.windows[0].max_h_m, 0.975, 2e-3);
  EXPECT_NEAR(s.windows[1].max_h_m, 2.0, 2e-3);
  EXPECT_NEAR(s.windows[1].max_3d_m, 2.5, 2e-3);
  EXPECT_NEAR(s.windows[1].rms_3d_m, 2.5, 2e-3);
  EXPECT_NEAR(s.windows[1].heading_end_deg, 3.0, 1e-9);
  EXPECT_NEAR(s.rms_of_max_h_m, std::sqrt((0.975 * 0.975 + 4) / 2), 2e-3);
  EXPECT_NEAR(s.worst_max_3d_m, 2.5, 2e-3);
  EXPECT_EQ(s.gnss_epochs, 401u - 80u);
  EXPECT_NEAR(s.rmse_h_gnss_m, 0.01, 2e-4);
  ASSERT_TRUE(s.has_nees);
  EXPECT_GT(s.mean_nees_pos, 1.0);  // 1 cm σ, errors of 1 cm to 2.5 m
  const std::string j = OutageScoreJson(s);
  EXPECT_NE(j.find("\"rms_of_max_h_m\""), std::string::npos);
  EXPECT_NE(OutageScoreText(s).find("RMS of maxima horizontal"), std::string::npos);
}

// The real walk (rtklibexplorer/GNSS_IMU, BSD-3), read in place; skipped when ../shared is absent.
TEST(DatasetImport, RealWalk0827) {
  const char* src = std::getenv("HIL_SOURCE_DIR");
  const std::string dir = std::string(src ? src : ".") + "/../shared/vectors/real_imu/walk_0827";
  if (!std::filesystem::exists(dir + "/gnss_1730_sf.pos"))
    GTEST_SKIP() << dir << " absent: the real-walk import is not tested";
  const TempDir d;
  DatasetImportOptions o;
  o.reference_pos = dir + "/gnss_1730_sf.pos";
  o.imu_csv = dir + "/imu_1730.csv";
  o.imu_axes = "x,-y,-z";
  o.outages.every_s = 30, o.outages.first_s = 20, o.outages.length_s = 10;
  o.have_outages = true;
  const DatasetImportResult r = ImportDataset(o, d.path);
  EXPECT_LT(r.alignment.f_static_frd_mps2.z(), -9.5) << r.report;
  ASSERT_TRUE(r.lag.has_value());
  EXPECT_GT(r.lag->correlation, 0.5) << r.report;
  EXPECT_LT(std::abs(r.lag_s), 0.5) << r.report;
  EXPECT_GT(r.imu_lines, 20000u);
  EXPECT_GT(r.windows.size(), 2u);
}

}  // namespace
}  // namespace hil::harness
