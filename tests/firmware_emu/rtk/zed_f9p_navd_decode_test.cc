// navd's UBX decoder (estimator/drivers/ubx_decoder.h) on the emulated ZED-F9P's own output: the
// golden capture vectors/gnss/zed_f9p_first_seconds.golden (UBX and NMEA 4.10 on one UART, as
// navd reads it) framed by the UBX decoder with the NMEA decoder behind it. Checked: every NAV-PVT
// decoded field by field against the golden's fields (read there by the byte layout of the
// interface description, zed_f9p_golden_test.cc), every NMEA sentence passed to the NMEA decoder,
// the other UBX messages counted as unsupported, and no byte counted as garbage anywhere. Then
// navd's samples from the NAV-PVTs against gpsd's gpsdecode (3.22, gpsd-clients) over the same
// frames: time, mode, lat/lon/height, speed, track and accuracies per epoch (skips without it).
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "hil/estimator/drivers/nmea_decoder.h"
#include "hil/estimator/drivers/ubx_decoder.h"
#include "hil/estimator/drivers/ubx_nav_pvt_sample.h"

#include "golden_file.h"
#include "gpsdecode_tpv.h"

namespace hil::rtk {
namespace {

namespace drv = hil::estimator::drivers;

constexpr int kLeap_s = 18;  // GPS − UTC in 2026

struct Capture {
  std::string line_bytes;                                    ///< the UART's bytes in order
  std::string pvt_bytes;                                     ///< the NAV-PVT frames alone
  std::vector<std::map<std::string, long long>> pvt_fields;  ///< the golden's decoded fields
  int nmea = 0, other_ubx = 0;
};

std::string FromHex(const std::string& h) {
  std::string b;
  for (std::size_t i = 0; i + 1 < h.size(); i += 2)
    b.push_back(static_cast<char>(std::stoi(h.substr(i, 2), nullptr, 16)));
  return b;
}

Capture ReadGolden() {
  Capture c;
  std::istringstream in(
      hil::test::ReadFile(hil::test::SourceDir() + "/vectors/gnss/zed_f9p_first_seconds.golden"));
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream f(line);
    if (line.rfind("  ", 0) == 0) {  // the fields of the NAV-PVT above
      std::map<std::string, long long> m;
      for (std::string kv; f >> kv;) {
        const auto eq = kv.find('=');
        m[kv.substr(0, eq)] = std::stoll(kv.substr(eq + 1));
      }
      c.pvt_fields.push_back(m);
      continue;
    }
    std::string t_ms, name, body;
    f >> t_ms >> name;
    std::getline(f >> std::ws, body);
    if (name.rfind("UBX-", 0) == 0) {
      c.line_bytes += FromHex(body);
      if (name == "UBX-NAV-PVT") {
        c.pvt_bytes += FromHex(body);
      } else {
        ++c.other_ubx;
      }
    } else {
      c.line_bytes += body + "\r\n";
      ++c.nmea;
    }
  }
  return c;
}

struct Decoded {
  std::vector<drv::UbxMessage> pvt;
  drv::UbxDecoderStats ubx;
  drv::NmeaDecoderStats nmea;
};

Decoded DecodeLine(const std::string& bytes) {
  Decoded d;
  drv::NmeaDecoder nmea([](const drv::NmeaFix&) {});
  drv::UbxDecoder ubx([&d](const drv::UbxMessage& m) {
    if (m.cls == 0x01 && m.id == 0x07) d.pvt.push_back(m);
  });
  ubx.SetOtherBytesSink([&nmea](std::string_view b) { nmea.Feed(b); });
  for (std::size_t i = 0; i < bytes.size(); i += 37)
    ubx.Feed(std::string_view(bytes).substr(i, 37));
  d.ubx = ubx.stats();
  d.nmea = nmea.stats();
  return d;
}

TEST(ZedF9pNavdDecode, NavPvtFieldByFieldFromTheMixedLine) {
  const Capture c = ReadGolden();
  ASSERT_EQ(c.pvt_fields.size(), 14U) << "one NAV-PVT per second over 14 s";
  const Decoded d = DecodeLine(c.line_bytes);
  ASSERT_EQ(d.pvt.size(), c.pvt_fields.size());
  for (std::size_t i = 0; i < d.pvt.size(); ++i) {
    const drv::UbxMessage& m = d.pvt[i];
    const auto& g = c.pvt_fields[i];
    EXPECT_EQ(m.itow_ms, g.at("iTOW"));
    EXPECT_EQ(m.gps_fix, g.at("fixType"));
    EXPECT_EQ(drv::PvtGnssFixOk(m), g.at("gnssFixOK") == 1);
    EXPECT_EQ(drv::PvtDiffSoln(m), g.at("diffSoln") == 1);
    EXPECT_EQ(drv::PvtCarrSoln(m), g.at("carrSoln"));
    EXPECT_EQ(m.num_sv, g.at("numSV"));
    EXPECT_EQ(std::llround(m.lon_deg * 1e7), g.at("lon"));
    EXPECT_EQ(std::llround(m.lat_deg * 1e7), g.at("lat"));
    EXPECT_EQ(std::llround(m.height_m * 1e3), g.at("height"));
    EXPECT_EQ(std::llround(m.h_acc_m * 1e3), g.at("hAcc"));
    EXPECT_EQ(std::llround(m.v_acc_m * 1e3), g.at("vAcc"));
    EXPECT_EQ(std::llround(m.head_mot_deg * 1e5), g.at("headMot"));
    EXPECT_EQ((m.flags3 >> 1) & 0xF, g.at("lastCorrectionAge"));
  }
  // the capture holds standalone, float and fixed epochs: each maps to its GGA-style quality
  std::map<int, int> quality;
  for (const auto& m : d.pvt) ++quality[drv::NavPvtFixQuality(m)];
  EXPECT_GT(quality[1], 0);
  EXPECT_GT(quality[5], 0);
  EXPECT_GT(quality[4], 0);
  EXPECT_EQ(d.ubx.garbage_bytes, 0U);
  EXPECT_EQ(d.ubx.bad_checksum, 0U);
  EXPECT_EQ(d.ubx.unsupported, static_cast<std::uint64_t>(c.other_ubx));
  EXPECT_EQ(d.nmea.garbage_bytes, 0U);
  EXPECT_EQ(d.nmea.malformed, 0U);
  EXPECT_EQ(d.nmea.bad_checksum, 0U);
  EXPECT_EQ(d.nmea.sentences_ok + d.nmea.unsupported, static_cast<std::uint64_t>(c.nmea));
}

// gpsd stamps a TPV with the UTC time of the NAV-PVT (2026-06-10T08:00:SS.sssZ)
double UtcSecondOfMinute(const nlohmann::json& tpv) {
  const std::string t = tpv.value("time", "");
  return t.size() < 23 ? -1.0 : std::stod(t.substr(17, 6));
}

TEST(ZedF9pNavdDecode, NavPvtSamplesAgreeWithGpsdecode) {
  if (!test::GpsdecodeInstalled()) GTEST_SKIP() << "gpsdecode not installed";
  const Capture c = ReadGolden();
  std::map<long long, nlohmann::json> tpv_by_ms;
  for (const auto& j : test::GpsdecodeTpv(c.pvt_bytes, "navd_pvt"))
    tpv_by_ms[std::llround(UtcSecondOfMinute(j) * 1000)] = j;
  int compared = 0;
  for (const drv::UbxMessage& m : DecodeLine(c.pvt_bytes).pvt) {
    const auto g = drv::NavPvtToGnssSample(m, kLeap_s, {});
    if (!g) continue;  // no fix yet (the first second)
    const std::int64_t unix_ns = estimator::UnixNsFromGpsTime(g->t, kLeap_s);
    const long long ms_of_minute = (unix_ns / 1'000'000) % 60'000;
    ASSERT_TRUE(tpv_by_ms.count(ms_of_minute)) << "no gpsd TPV at " << ms_of_minute << " ms";
    const nlohmann::json& j = tpv_by_ms[ms_of_minute];
    EXPECT_EQ(j.value("mode", -1), g->fix_dim);
    EXPECT_NEAR(j["lat"].get<double>(), g->position.lat_deg, 1e-9);
    EXPECT_NEAR(j["lon"].get<double>(), g->position.lon_deg, 1e-9);
    EXPECT_NEAR(j["altHAE"].get<double>(), g->position.height_m, 1e-3);
    // gpsd 3.22's TPV: speed is gSpeed, track headMot, eph hAcc, epv vAcc
    EXPECT_NEAR(j["speed"].get<double>(), g->ground_speed_mps.value_or(-1), 1e-3);
    EXPECT_NEAR(j["speed"].get<double>(), g->vel_enu_mps.head<2>().norm(), 2e-3);
    EXPECT_NEAR(j["track"].get<double>(), m.head_mot_deg, 1e-4);
    EXPECT_NEAR(j["eph"].get<double>(), m.h_acc_m, 1e-3);
    EXPECT_NEAR(j["epv"].get<double>(), m.v_acc_m, 1e-3);
    ++compared;
  }
  EXPECT_EQ(compared, 13) << "every NAV-PVT with a fix (1 s … 13 s)";
}

}  // namespace
}  // namespace hil::rtk
