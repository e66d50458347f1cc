// navd end to end in EKF mode: MCU binary frames (IMU at 100 Hz, time pulses) and NMEA (GGA + RMC
// at 1 Hz) are written into two FIFOs named as navd's devices; navd must align, fuse, and write
// 10 Hz JSON lines in mode "ekf" that follow the vehicle.
#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include "hil/estimator/drivers/mcu_frame_decoder.h"
#include "hil/estimator/drivers/nmea_decoder.h"
#include "hil/estimator/geodesy.h"
#include "hil/estimator/outputs/nmea0183_writer.h"

namespace hil::estimator {
namespace {

void PutLe(std::string& s, std::uint64_t v, int n) {
  for (int i = 0; i < n; ++i) s.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
}

// the test's own encoder of the MCU frame protocol v1 (header, payload, CRC low byte first)
std::string Frame(std::uint8_t type, std::uint16_t seq, std::uint32_t tick,
                  const std::string& payload) {
  std::string body;
  body.push_back(1);
  body.push_back(static_cast<char>(type));
  body.push_back(static_cast<char>(payload.size()));
  PutLe(body, seq, 2);
  PutLe(body, tick, 4);
  body += payload;
  const std::uint16_t crc = drivers::Crc16CcittFalse(body);
  std::string f = "\xA5\x5A" + body;
  PutLe(f, crc, 2);
  return f;
}

std::string F32(float v) {
  std::uint32_t u;
  std::memcpy(&u, &v, 4);
  std::string s;
  PutLe(s, u, 4);
  return s;
}

TEST(NavdEkfE2eTest, FusesMcuImuAndNmeaIntoEkfSolutions) {
  const char* bin = std::getenv("HIL_BIN_DIR");
  ASSERT_NE(bin, nullptr);
  const auto dir =
      std::filesystem::temp_directory_path() / ("navd_e2e_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const std::string gnss = dir / "gnss", imu = dir / "imu", out = dir / "out.jsonl",
                    conf = dir / "navd.conf";
  ASSERT_EQ(mkfifo(gnss.c_str(), 0600), 0);
  ASSERT_EQ(mkfifo(imu.c_str(), 0600), 0);
  std::ofstream(conf)
      << "[input]\ngnss_device = " << gnss << "\nimu_device = " << imu
      << "\n[filter]\nmode = ekf\nnhc_std_mps = 0.05\nfusion_horizon_s = 0.2\n[output]\njson = "
      << out << "\nrate_hz = 10\ncan_log = " << (dir / "can.log").string()
      << "\nnmea_device = " << (dir / "nmea.txt").string() << "\n";
  const pid_t pid = fork();
  if (pid == 0) {
    execl((std::string(bin) + "/navd").c_str(), "navd", "--config", conf.c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  const int gfd = open(gnss.c_str(), O_WRONLY);
  const int ifd = open(imu.c_str(), O_WRONLY);
  ASSERT_GE(gfd, 0);
  ASSERT_GE(ifd, 0);

  // GIVEN a level vehicle driving east at 1 m/s for 40 s, a 1 MHz MCU tick and GPS week 1744
  const LocalTangentFrame frame({48.0, 11.0, 500.0});
  const std::int64_t week_ns = 1744LL * 604800LL * kNsPerSecond, tow0_ns = 86400LL * kNsPerSecond;
  std::string imu_bytes =
      Frame(4, 0, 0,
            std::string("\0\0\0\0", 4) + std::string("\x40\x42\x0F\x00", 4) +
                std::string("\x10\x27\0\0", 4) + F32(9.80665f / 8000) +
                F32(0.01f * 3.14159265f / 180) + F32(0.1f) + std::string("\x03\x00", 2));
  std::string gnss_bytes;
  std::uint16_t seq = 1;
  for (int k = 1; k <= 4000; ++k) {  // 100 Hz
    const std::uint32_t tick = static_cast<std::uint32_t>(k * 10000);
    if (k % 100 == 0) {
      std::string p;
      PutLe(p, 1744, 2);
      PutLe(p, static_cast<std::uint64_t>((tow0_ns + k * 10'000'000LL) / 1'000'000), 4);
      p.push_back(1);
      imu_bytes += Frame(3, seq++, tick, p);
      // the GNSS fix of this second, antenna at the body origin
      NavOutput fix;
      fix.valid = true;
      fix.position = frame.ToLla(Eigen::Vector3d(k * 0.01, 0, 0));
      fix.v_N_mps = Eigen::Vector3d(1, 0, 0);
      gnss_bytes += outputs::FormatNmea0183(
          fix, UnixNsFromGpsTime(GpsTimeFromNs(week_ns + tow0_ns + k * 10'000'000LL), 18));
    }
    std::string payload;
    for (int a : {0, 0, 8000})
      PutLe(payload, static_cast<std::uint16_t>(static_cast<std::int16_t>(a)), 2);
    for (int g = 0; g < 3; ++g) PutLe(payload, 0, 2);
    imu_bytes += Frame(1, seq++, tick, payload);
  }
  // WHEN both streams are written (interleaved about a second at a time, the fixes slightly ahead,
  // as a receiver's latency is below the fusion horizon)
  const std::size_t imu_chunk = imu_bytes.size() / 40 + 1, gnss_chunk = gnss_bytes.size() / 40 + 1;
  for (std::size_t i = 0; i < 40; ++i) {
    if (i * gnss_chunk < gnss_bytes.size()) {
      ASSERT_GT(write(gfd, gnss_bytes.data() + i * gnss_chunk,
                      std::min(gnss_chunk, gnss_bytes.size() - i * gnss_chunk)),
                0);
    }
    if (i * imu_chunk < imu_bytes.size()) {
      ASSERT_GT(write(ifd, imu_bytes.data() + i * imu_chunk,
                      std::min(imu_chunk, imu_bytes.size() - i * imu_chunk)),
                0);
    }
  }
  // navd has worked through the streams when its output stops growing (a slow machine or a
  // sanitizer build takes longer than the writes: wait for it rather than a fixed time)
  std::uintmax_t size = 0;
  for (int idle_ms = 0, waited_ms = 0; idle_ms < 1500 && waited_ms < 45000; waited_ms += 100) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    std::error_code ec;
    const std::uintmax_t now = std::filesystem::file_size(out, ec);
    idle_ms = (!ec && now == size && now > 0) ? idle_ms + 100 : 0;
    if (!ec) size = now;
  }
  kill(pid, SIGTERM);
  int status = 0;
  waitpid(pid, &status, 0);
  close(gfd);
  close(ifd);

  // THEN navd wrote ekf solutions at about 10 Hz that follow the vehicle east
  std::ifstream in(out);
  int lines = 0;
  double last_lon = 0, first_lon = 0;
  for (std::string line; std::getline(in, line);) {
    ASSERT_NE(line.find("\"mode\":\"ekf\""), std::string::npos) << line;
    const auto p = line.find("\"lon_deg\":");
    ASSERT_NE(p, std::string::npos);
    last_lon = std::stod(line.substr(p + 10));
    if (lines == 0) first_lon = last_lon;
    ++lines;
  }
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  EXPECT_GT(lines, 300);
  EXPECT_LT(lines, 420);
  const Eigen::Vector3d p_last = frame.ToLocal({48.0, last_lon, 500.0});
  EXPECT_NEAR(p_last.x(), 39.8, 0.5);  // the last solution ~0.2 s (fusion horizon) before the end
  EXPECT_GT(last_lon, first_lon);
  // and the same solutions as NMEA 2000 frames (candump -l) and NMEA 0183 sentences
  std::ifstream can_log(dir / "can.log");
  int rapid = 0, fast = 0;
  for (std::string line; std::getline(can_log, line);) {
    if (line.find(" can0 09F80180#") != std::string::npos) ++rapid;
    if (line.find(" can0 0DF80580#") != std::string::npos) ++fast;
  }
  EXPECT_GT(rapid, 300);
  EXPECT_EQ(fast % 7, 0);
  EXPECT_GT(fast, 7 * 30);
  std::ifstream nmea_out(dir / "nmea.txt");
  int gga = 0;
  for (std::string line; std::getline(nmea_out, line);) gga += line.rfind("$GNGGA,", 0) == 0;
  EXPECT_EQ(gga, lines);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace hil::estimator
