// Third-party clients on the emulated NEO-5M's pty (label pty): gpsd identifies a u-blox and
// reports the fixes the emulator sent; ubxtool polls MON-VER, changes the rate and enables and
// disables messages, and the stream changes accordingly. Needs gpsd, gpsd-clients (gpspipe,
// ubxtool) and the hil binary; every wait is bounded and every process started here is killed.
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <netinet/in.h>
#include <nlohmann/json.hpp>
#include <sys/socket.h>

#include "hil/firmware_emu/gnss/gps_time.h"

namespace {

namespace fs = std::filesystem;

std::string Env(const char* name) {
  const char* v = std::getenv(name);
  return v ? v : "";
}

bool HaveTool(const std::string& tool) {
  return std::system(("command -v " + tool + " >/dev/null 2>&1").c_str()) == 0;
}

int FreePort() {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  a.sin_port = 0;
  bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a);
  socklen_t len = sizeof a;
  getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len);
  close(fd);
  return ntohs(a.sin_port);
}

// Starts `command` in the background under `timeout`, returns its pid (read from a pid file).
pid_t Spawn(const std::string& command, const fs::path& pid_file) {
  const std::string sh = "(" + command + ") & echo $! > " + pid_file.string();
  if (std::system(sh.c_str()) != 0) return -1;
  std::ifstream in(pid_file);
  pid_t pid = -1;
  in >> pid;
  return pid;
}

bool WaitFor(const std::function<bool()>& ok, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (ok()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return ok();
}

void Stop(pid_t pid) {
  if (pid > 0) kill(pid, SIGTERM);
}

std::string ReadAll(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

struct CapturedMessage {
  double t_s;
  std::string name;
  std::string bytes;
};

std::vector<CapturedMessage> ReadCapture(const fs::path& p) {
  std::vector<CapturedMessage> out;
  std::ifstream in(p);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ss(line);
    std::string dir, t, period, wall, name, hex;
    ss >> dir >> t >> period >> wall >> name >> hex;
    if (dir != "tx") continue;
    std::string bytes;
    for (std::size_t i = 0; i + 1 < hex.size(); i += 2)
      bytes += static_cast<char>(std::stoi(hex.substr(i, 2), nullptr, 16));
    out.push_back({std::stod(t) * 1e-9, name, bytes});
  }
  return out;
}

std::int32_t I4(const std::string& b, std::size_t off) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i)
    v = (v << 8) | static_cast<std::uint8_t>(b[off + static_cast<std::size_t>(i)]);
  return static_cast<std::int32_t>(v);
}

double NmeaDegrees(const std::string& field, const std::string& hemi) {
  const double v = std::stod(field);
  const double deg = std::floor(v / 100.0);
  const double d = deg + (v - deg * 100.0) / 60.0;
  return hemi == "S" || hemi == "W" ? -d : d;
}

class GnssPtyTest : public ::testing::Test {
 protected:
  void SetUp() override {
    for (const char* tool : {"gpsd", "gpspipe", "ubxtool", "timeout"}) {
      ASSERT_TRUE(HaveTool(tool))
          << tool << " is not installed (Debian packages gpsd, gpsd-clients; see ci/setup)";
    }
    hil_ = Env("HIL_BIN_DIR") + "/hil";
    ASSERT_TRUE(fs::exists(hil_)) << hil_;
    dir_ = fs::temp_directory_path() /
           ("hil_gnss_pty_" + std::to_string(getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    for (pid_t p : pids_) Stop(p);
    // leave the folder for inspection when a test failed
    if (!HasFailure()) fs::remove_all(dir_);
  }
  /// Starts `hil emulate` on a scenario of `duration_s` and waits for the link.
  void Emulate(int duration_s) {
    std::ofstream(dir_ / "scenario.yaml")
        << "name: gnss_pty\nstart_utc: \"2026-03-10T08:00:00Z\"\nduration_s: " << duration_s
        << "\nseed: 5\n"
        << "origin: {lat_deg: -33.4488897, lon_deg: -70.6692655, height_m: 570.0}\n"
        << "vehicle: {model: bicycle, wheelbase_m: 0.84}\npath: {type: line, heading_deg: 30.0, "
           "speed_kmh: 3.6}\n"
        << "gnss: {profile: neo-5m, baud: 9600, link: ttyGPS}\n";
    pids_.push_back(Spawn("timeout " + std::to_string(duration_s + 20) + " " + hil_ + " emulate " +
                              (dir_ / "scenario.yaml").string() + " --out " +
                              (dir_ / "run").string() + " > " + (dir_ / "emulate.out").string() +
                              " 2>&1",
                          dir_ / "hil.pid"));
    emulate_pid_ = pids_.back();
    link_ = dir_ / "run" / "ttyGPS";
    ASSERT_TRUE(WaitFor([&] { return fs::exists(link_); }, 10.0)) << "no link " << link_;
  }
  /// Waits for `hil emulate` to finish (it flushes its capture then).
  std::vector<CapturedMessage> WaitEndAndReadCapture(double seconds) {
    EXPECT_TRUE(WaitFor([&] { return kill(emulate_pid_, 0) != 0; }, seconds))
        << "hil emulate did not end";
    return ReadCapture(dir_ / "run" / "captures" / "ttyGPS.cap");
  }
  std::string Ubxtool(const std::string& args) {
    const fs::path out = dir_ / "ubxtool.out";
    std::system(("timeout 15 ubxtool -f " + link_.string() + " -s 9600 -P 12 " + args + " > " +
                 out.string() + " 2>&1")
                    .c_str());
    return ReadAll(out);
  }

  std::string hil_;
  fs::path dir_, link_;
  std::vector<pid_t> pids_;
  pid_t emulate_pid_ = -1;
};

TEST_F(GnssPtyTest, GpsdIdentifiesAUbloxAndReportsTheEmittedFixes) {
  Emulate(22);
  const int port = FreePort();
  pids_.push_back(Spawn("timeout 30 gpsd -N -n -S " + std::to_string(port) + " -F " +
                            (dir_ / "gpsd.sock").string() + " " + link_.string() + " > " +
                            (dir_ / "gpsd.log").string() + " 2>&1",
                        dir_ / "gpsd.pid"));
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  std::system(("timeout 17 gpspipe -w localhost:" + std::to_string(port) + " > " +
               (dir_ / "pipe.json").string() + " 2>/dev/null")
                  .c_str());
  const auto capture = WaitEndAndReadCapture(20);

  // what the emulator sent: NMEA GGA positions and UBX NAV-SOL ECEF positions
  std::vector<std::pair<double, double>> gga;
  std::vector<std::array<std::int32_t, 3>> sol;
  for (const auto& m : capture) {
    if (m.name == "NMEA-GGA") {
      std::vector<std::string> f;
      std::stringstream ss(m.bytes);
      std::string x;
      while (std::getline(ss, x, ',')) f.push_back(x);
      if (f.size() > 6 && f[6] != "0")
        gga.emplace_back(NmeaDegrees(f[2], f[3]), NmeaDegrees(f[4], f[5]));
    } else if (m.name == "UBX-NAV-SOL") {
      sol.push_back({I4(m.bytes, 6 + 12), I4(m.bytes, 6 + 16), I4(m.bytes, 6 + 20)});
    }
  }
  bool ublox = false;
  int tpv = 0, matched = 0;
  std::istringstream pipe(ReadAll(dir_ / "pipe.json"));
  std::string line;
  while (std::getline(pipe, line)) {
    const auto j = nlohmann::json::parse(line, nullptr, false);
    if (j.is_discarded() || !j.contains("class")) continue;
    if (j["class"] == "DEVICE" && j.value("driver", "") == "u-blox") {
      ublox = true;
      EXPECT_NE(j.value("subtype", "").find("SW 6.02 (36023),HW 00040005"), std::string::npos)
          << line;
    }
    if (j["class"] != "TPV" || j.value("mode", 0) < 2) continue;
    ++tpv;
    bool ok = false;
    if (j.contains(
            "ecefx")) {  // from NAV-SOL: ECEF printed in metres with 2 decimals = the cm sent
      const std::array<std::int32_t, 3> e{
          static_cast<std::int32_t>(std::lround(j["ecefx"].get<double>() * 100)),
          static_cast<std::int32_t>(std::lround(j["ecefy"].get<double>() * 100)),
          static_cast<std::int32_t>(std::lround(j["ecefz"].get<double>() * 100))};
      for (const auto& s : sol) ok = ok || s == e;
    } else {  // from NMEA: lat/lon to the sentence's 1e-5 minutes
      for (const auto& [lat, lon] : gga) {
        ok = ok || (std::abs(lat - j["lat"].get<double>()) < 1e-8 &&
                    std::abs(lon - j["lon"].get<double>()) < 1e-8);
      }
    }
    EXPECT_TRUE(ok) << "gpsd reported a fix the emulator did not send: " << line;
    matched += ok ? 1 : 0;
    EXPECT_LT(j["lat"].get<double>(), -33.0);  // southern and western hemispheres
    EXPECT_LT(j["lon"].get<double>(), -70.0);
  }
  EXPECT_TRUE(ublox) << "gpsd never identified a u-blox (see " << dir_ << "/pipe.json)";
  EXPECT_GE(tpv, 5);
  EXPECT_EQ(matched, tpv);
  EXPECT_FALSE(sol.empty()) << "gpsd did not switch the receiver to UBX";
}

TEST_F(GnssPtyTest, UbxtoolPollsAndConfiguresTheReceiver) {
  Emulate(16);
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  const std::string ver = Ubxtool("-p MON-VER -w 2.5");
  EXPECT_NE(ver.find("swVersion 6.02 (36023)"), std::string::npos) << ver;
  EXPECT_NE(ver.find("hwVersion 00040005"), std::string::npos) << ver;
  // measurement period 500 ms: accepted; 50 ms (20 Hz): refused by the NEO-5M profile, whose
  // fastest accepted rate is cfg_rate_max_hz = 10 (receiver_profile.h)
  const std::string rate = Ubxtool("-c 6,8,0xf4,1,1,0,1,0 -w 2");
  EXPECT_NE(rate.find("ACK to Class x06 (CFG) ID x08 (RATE)"), std::string::npos) << rate;
  const std::string fast = Ubxtool("-c 6,8,0x32,0,1,0,1,0 -w 2");
  EXPECT_NE(fast.find("NAK to Class x06 (CFG) ID x08 (RATE)"), std::string::npos) << fast;
  const std::string bin = Ubxtool("-e BINARY -w 2.5");
  EXPECT_NE(bin.find("UBX-NAV-SOL"), std::string::npos) << bin;
  // at 2 Hz with UBX and NMEA the 9600-baud link is overloaded: the ACKs may be queued late or
  // dropped like any message, so the effect is checked in the capture below
  Ubxtool("-d NMEA -w 2");
  const auto cap = WaitEndAndReadCapture(20);

  // the stream changed: RMC every second, then every 0.5 s; UBX after -e BINARY; no NMEA at the end
  std::vector<double> rmc;
  double first_sol = -1, last_nmea = -1, last_ubx = -1;
  for (const auto& m : cap) {
    if (m.name == "NMEA-RMC") rmc.push_back(m.t_s);
    if (m.name.rfind("NMEA-", 0) == 0) last_nmea = m.t_s;
    if (m.name == "UBX-NAV-SOL") {
      if (first_sol < 0) first_sol = m.t_s;
      last_ubx = m.t_s;
    }
  }
  ASSERT_GE(rmc.size(), 4u);
  bool one_hz = false, two_hz = false;
  for (std::size_t i = 1; i < rmc.size(); ++i) {
    const double dt = rmc[i] - rmc[i - 1];
    one_hz = one_hz || std::abs(dt - 1.0) < 0.05;
    two_hz = two_hz || std::abs(dt - 0.5) < 0.05;
  }
  EXPECT_TRUE(one_hz);
  EXPECT_TRUE(two_hz);
  EXPECT_GT(first_sol, 0);
  EXPECT_GT(last_ubx, last_nmea) << "NMEA continued after ubxtool -d NMEA";
}

// Issue 15.11: the default scenario started on the paper's 2013-06-10, which gpsd 3.22 takes for
// a GPS week-rollover victim: every TPV said 2033-01-24. gpsd attached to `hil emulate` (the
// README's example) must report the emulated UTC: the scenario's start plus the time since the
// emulation began.
TEST_F(GnssPtyTest, GpsdReportsTheEmulatedUtcOfTheDefaultScenario) {
  std::ifstream def(Env("HIL_SOURCE_DIR") + "/vectors/scenarios/default.yaml");
  std::string line, start_text;
  while (std::getline(def, line)) {
    if (line.rfind("start_utc: \"", 0) == 0) start_text = line.substr(12, line.rfind('"') - 12);
  }
  ASSERT_FALSE(start_text.empty()) << "default.yaml gives no start_utc";
  const hil::UnixTime start = hil::gnss::ParseIsoUtc(start_text);
  const auto t0 = std::chrono::steady_clock::now();
  pids_.push_back(Spawn("timeout 30 " + hil_ + " emulate --out " + (dir_ / "run").string() + " > " +
                            (dir_ / "emulate.out").string() + " 2>&1",
                        dir_ / "hil.pid"));
  link_ = dir_ / "run" / "ttyGPS";
  ASSERT_TRUE(WaitFor([&] { return fs::exists(link_); }, 10.0)) << "no link " << link_;
  const int port = FreePort();
  pids_.push_back(Spawn("timeout 20 gpsd -N -n -b -S " + std::to_string(port) + " -F " +
                            (dir_ / "gpsd.sock").string() + " " + link_.string() + " > " +
                            (dir_ / "gpsd.log").string() + " 2>&1",
                        dir_ / "gpsd.pid"));
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  std::system(("timeout 10 gpspipe -w localhost:" + std::to_string(port) + " > " +
               (dir_ / "pipe.json").string() + " 2>/dev/null")
                  .c_str());
  const double elapsed_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  int tpv = 0;
  std::istringstream pipe(ReadAll(dir_ / "pipe.json"));
  while (std::getline(pipe, line)) {
    const auto j = nlohmann::json::parse(line, nullptr, false);
    if (j.is_discarded() || j.value("class", "") != "TPV" || !j.contains("time")) continue;
    ++tpv;
    const double since_start_s =
        hil::ToSeconds(hil::gnss::ParseIsoUtc(j["time"].get<std::string>()) - start);
    EXPECT_GE(since_start_s, 0.0) << line;
    EXPECT_LE(since_start_s, elapsed_s + 1.0) << "emulated " << elapsed_s << " s: " << line;
    EXPECT_NEAR(since_start_s, std::round(since_start_s), 1e-3) << "1 Hz epochs: " << line;
  }
  EXPECT_GE(tpv, 5) << "see " << dir_ / "pipe.json";
}

}  // namespace
