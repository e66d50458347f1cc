// Golden test of navd's GNSS decoders against gpsd: each real u-blox 5 capture of gpsd's
// regression corpus (../shared/vectors/gpsd-ublox5, read in place) goes through navd's NMEA or
// UBX decoder and epoch assembler, in the protocol it carries, and every epoch is diffed field by
// field (time, lat, lon, altHAE, speed, track, mode) against gpsd's TPV reports in `<log>.chk`.
// Every epoch gpsd reports with a fix must be present with the same values within the
// resolution of the messages and of gpsd's printout; an epoch or field that differs must be
// explained by the log itself (the reason is derived from the decoded messages, not listed by
// time), and navd must report nothing where gpsd reports no fix.
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "hil/estimator/drivers/nmea_decoder.h"
#include "hil/estimator/drivers/nmea_epoch.h"
#include "hil/estimator/drivers/ubx_decoder.h"

#include "gpsd_chk.h"
#include "navd_pty_runner.h"

namespace hil::estimator::testing {

// names the log in GoogleTest's messages
void PrintTo(const GpsdLog& log, std::ostream* os) {
  *os << log.name << " (" << log.protocol << ")";
}

namespace {

constexpr std::int64_t kNsPerDay = 86400LL * 1'000'000'000LL;

/// One epoch as navd's decoders give it to the filter.
struct NavdEpoch {
  std::int64_t unix_ns = 0;
  int mode = 0;
  double lat_deg = 0, lon_deg = 0;
  std::optional<double> alt_hae_m, speed_mps, track_deg;
};

/// What the decoders saw besides the epochs, to explain a difference from the log itself.
struct Decoded {
  std::vector<NavdEpoch> epochs;
  std::set<std::int64_t> gga_tod_ns, rmc_tod_ns;  // NMEA: times of day of valid GGA / RMC
  std::map<std::int64_t, drivers::UbxMessage> sol_by_unix_ns;  // UBX: NAV-SOL by epoch
  std::uint64_t bad_checksums = 0;
};

Decoded DecodeNmea(const std::string& bytes) {
  Decoded d;
  drivers::NmeaEpochAssembler epochs;
  drivers::NmeaDecoder dec([&](const drivers::NmeaFix& f) {
    if (f.valid && f.utc_time_of_day_ns) {
      (f.kind == drivers::NmeaFix::Kind::kGga ? d.gga_tod_ns : d.rmc_tod_ns)
          .insert(*f.utc_time_of_day_ns);
    }
    const auto m = epochs.Add(f);
    if (!m) return;
    NavdEpoch e;
    e.unix_ns = m->tov_unix_ns;
    e.mode = 3;  // the assembler needs GGA's altitude: every NMEA measurement is 3-D
    e.lat_deg = m->lat_deg, e.lon_deg = m->lon_deg, e.alt_hae_m = m->height_m;
    e.speed_mps = m->speed_mps, e.track_deg = m->course_deg;
    d.epochs.push_back(e);
  });
  dec.Feed(bytes);
  d.bad_checksums = dec.stats().bad_checksum;
  return d;
}

Decoded DecodeUbx(const std::string& bytes) {
  Decoded d;
  drivers::UbxEpochAssembler epochs;
  std::vector<drivers::UbxMessage> sols;
  drivers::UbxDecoder dec([&](const drivers::UbxMessage& m) {
    if (m.cls == 0x01 && m.id == 0x06) sols.push_back(m);
    for (const GnssSample& g : epochs.Add(m)) {
      NavdEpoch e;
      e.unix_ns = UnixNsFromGpsTime(g.t, epochs.leap_seconds());
      e.mode = g.fix_dim;
      e.lat_deg = g.position.lat_deg, e.lon_deg = g.position.lon_deg;
      e.alt_hae_m = g.position.height_m;
      e.speed_mps = g.ground_speed_mps;
      if (g.has_velocity) {
        const double c = std::atan2(g.vel_enu_mps.x(), g.vel_enu_mps.y()) * 180 / std::numbers::pi;
        e.track_deg = c < 0 ? c + 360 : c;
      }
      d.epochs.push_back(e);
    }
  });
  dec.Feed(bytes);
  for (const auto& s : sols) {
    if (s.week < 0) continue;
    const GpsTime t = GpsTimeFromWeek(s.week, static_cast<std::int64_t>(s.itow_ms) * 1'000'000LL);
    d.sol_by_unix_ns[UnixNsFromGpsTime(t, epochs.leap_seconds())] = s;
  }
  d.bad_checksums = dec.stats().bad_checksum;
  return d;
}

/// Tolerances: the resolution of the messages and of gpsd's printout (lat/lon 9 decimals, altHAE
/// 4, speed 3, track 4).
struct Tolerance {
  std::int64_t time_ns;
  double latlon_deg, alt_m, speed_mps, track_deg;
};
// NMEA: gpsd and navd read the same digits; only gpsd's rounding to its printout remains.
constexpr Tolerance kNmeaTol{0, 5.1e-10, 5.1e-5, 5.1e-4, 5.1e-5};
// UBX: gpsd's time is iTOW (ms); navd adds fTOW (|fTOW| ≤ 0.5 ms). Both convert NAV-SOL's cm
// ECEF with their own geodesy: 1e-9° is 0.1 mm, far below the 1 cm input resolution.
constexpr Tolerance kUbxTol{500'000, 1e-9, 1e-4, 5.1e-4, 1e-3};

struct FieldStats {
  double max_dt_ms = 0, max_lat = 0, max_lon = 0, max_alt = 0, max_speed = 0, max_track = 0;
  int matched = 0, missing_explained = 0, gpsd_fix_epochs = 0, gpsd_no_fix_epochs = 0;
  std::vector<std::string> explained;
};

std::string Iso(std::int64_t unix_ns) {
  const std::int64_t s = unix_ns / 1'000'000'000LL, tod = s % 86400;
  char b[32];
  std::snprintf(b, sizeof b, "%02lld:%02lld:%02lld.%03lld", static_cast<long long>(tod / 3600),
                static_cast<long long>(tod / 60 % 60), static_cast<long long>(tod % 60),
                static_cast<long long>(unix_ns / 1'000'000 % 1000));
  return b;
}

/// Why navd has no epoch where gpsd has a fix ("" when the log does not explain it).
std::string WhyMissing(const Decoded& d, const GpsdEpoch& g, bool ubx) {
  if (ubx) {
    const auto it = d.sol_by_unix_ns.find(g.unix_ns);
    if (it == d.sol_by_unix_ns.end()) return "";
    const drivers::UbxMessage& s = it->second;
    if (!(s.flags & 0x01))
      return "NAV-SOL gpsFix " + std::to_string(s.gps_fix) +
             " with gpsFixOk clear: u-blox says the fix is not valid, navd drops it; gpsd "
             "reports it as mode " +
             std::to_string(g.mode);
    return "";
  }
  const std::int64_t tod = g.unix_ns % kNsPerDay;
  if (!d.gga_tod_ns.count(tod) && d.rmc_tod_ns.count(tod))
    return "RMC without GGA: navd needs GGA's altitude and quality for a measurement; gpsd "
           "reports the RMC's 2-D position";
  return "";
}

/// Why navd's epoch lacks gpsd's speed ("" when unexplained).
std::string WhyNoSpeed(const Decoded& d, const GpsdEpoch& g, bool ubx) {
  if (!ubx && !d.rmc_tod_ns.count(g.unix_ns % kNsPerDay))
    return "no RMC in this epoch (gpsd's speed comes from VTG, which navd does not read)";
  return "";
}

void CompareEpoch(const NavdEpoch& n, const GpsdEpoch& g, const Decoded& d, bool ubx,
                  const Tolerance& tol, FieldStats& st) {
  const std::string at = Iso(g.unix_ns);
  ++st.matched;
  st.max_dt_ms = std::max(st.max_dt_ms, std::fabs(n.unix_ns - g.unix_ns) * 1e-6);
  ASSERT_TRUE(g.lat_deg && g.lon_deg) << at;
  const double dlat = std::fabs(n.lat_deg - *g.lat_deg), dlon = std::fabs(n.lon_deg - *g.lon_deg);
  st.max_lat = std::max(st.max_lat, dlat), st.max_lon = std::max(st.max_lon, dlon);
  EXPECT_LE(dlat, tol.latlon_deg) << at << " lat";
  EXPECT_LE(dlon, tol.latlon_deg) << at << " lon";
  if (g.alt_hae_m) {
    ASSERT_TRUE(n.alt_hae_m) << at << " altHAE";
    const double da = std::fabs(*n.alt_hae_m - *g.alt_hae_m);
    st.max_alt = std::max(st.max_alt, da);
    EXPECT_LE(da, tol.alt_m) << at << " altHAE";
  }
  if (g.speed_mps && !n.speed_mps) {
    const std::string why = WhyNoSpeed(d, g, ubx);
    EXPECT_FALSE(why.empty()) << at << " speed: gpsd has " << *g.speed_mps << ", navd none";
    if (!why.empty()) st.explained.push_back(at + " speed: " + why);
  } else if (g.speed_mps) {
    const double ds = std::fabs(*n.speed_mps - *g.speed_mps);
    st.max_speed = std::max(st.max_speed, ds);
    EXPECT_LE(ds, tol.speed_mps) << at << " speed";
  }
  // track: present in both or in neither (an empty RMC course is no direction, not 0°)
  EXPECT_EQ(g.track_deg.has_value(), n.track_deg.has_value()) << at << " track";
  if (g.track_deg && n.track_deg) {
    double dt = std::fabs(*n.track_deg - *g.track_deg);
    dt = std::min(dt, 360 - dt);
    st.max_track = std::max(st.max_track, dt);
    EXPECT_LE(dt, tol.track_deg) << at << " track";
  }
  EXPECT_EQ(n.mode, g.mode) << at << " mode";
}

FieldStats CompareLog(const GpsdLog& log) {
  FieldStats st;
  const std::string dir = GpsdVectorsDir();
  const bool ubx = log.protocol == "ubx";
  const std::string bytes = ReadBytes(dir + "/" + log.name);
  const GpsdReport gpsd = ReadGpsdChk(dir + "/" + log.name + ".chk");
  const Decoded d = ubx ? DecodeUbx(bytes) : DecodeNmea(bytes);
  const Tolerance tol = ubx ? kUbxTol : kNmeaTol;
  EXPECT_EQ(d.bad_checksums, 0u) << log.name;
  std::set<std::size_t> used;
  for (const GpsdEpoch& g : gpsd.epochs) {
    const NavdEpoch* n = nullptr;
    for (std::size_t i = 0; i < d.epochs.size() && !n; ++i) {
      if (std::llabs(d.epochs[i].unix_ns - g.unix_ns) <= tol.time_ns) {
        n = &d.epochs[i];
        used.insert(i);
      }
    }
    if (g.mode < 2) {  // gpsd: no fix at this time; navd must not report one
      ++st.gpsd_no_fix_epochs;
      EXPECT_EQ(n, nullptr) << log.name << " " << Iso(g.unix_ns) << ": navd reports a fix";
      continue;
    }
    ++st.gpsd_fix_epochs;
    if (n == nullptr) {
      const std::string why = WhyMissing(d, g, ubx);
      EXPECT_FALSE(why.empty()) << log.name << " " << Iso(g.unix_ns) << ": gpsd mode " << g.mode
                                << ", navd has no epoch";
      if (!why.empty()) {
        st.explained.push_back(Iso(g.unix_ns) + " missing: " + why);
        ++st.missing_explained;
      }
      continue;
    }
    CompareEpoch(*n, g, d, ubx, tol, st);
  }
  // and navd reports nothing gpsd does not
  EXPECT_EQ(used.size(), d.epochs.size()) << log.name << ": navd epochs without a gpsd epoch";
  std::printf(
      "%-20s %-4s gpsd: %d fix epochs, %d no-fix epochs, %d timeless no-fix TPVs; navd: %zu "
      "epochs; matched %d of %d\n  max |diff|: time %.3f ms, lat %.2e deg, lon %.2e deg, altHAE "
      "%.2e m, speed %.2e m/s, track %.2e deg\n",
      log.name.c_str(), log.protocol.c_str(), st.gpsd_fix_epochs, st.gpsd_no_fix_epochs,
      gpsd.timeless_tpvs, d.epochs.size(), st.matched, st.gpsd_fix_epochs, st.max_dt_ms, st.max_lat,
      st.max_lon, st.max_alt, st.max_speed, st.max_track);
  for (const auto& e : st.explained) std::printf("  explained: %s\n", e.c_str());
  return st;
}

// Sentence level: every valid GGA of the NMEA logs decodes to gpsd's position and height.
TEST(GpsdNmeaSentenceTest, EveryValidGgaEqualsGpsdsPosition) {
  int compared = 0;
  for (const GpsdLog& log : GpsdLogs()) {
    if (log.protocol != "nmea") continue;
    const std::string dir = GpsdVectorsDir();
    const GpsdReport gpsd = ReadGpsdChk(dir + "/" + log.name + ".chk");
    std::map<std::int64_t, const GpsdEpoch*> by_tod;
    for (const GpsdEpoch& g : gpsd.epochs) by_tod[g.unix_ns % kNsPerDay] = &g;
    drivers::NmeaDecoder dec([&](const drivers::NmeaFix& f) {
      if (f.kind != drivers::NmeaFix::Kind::kGga || !f.valid) return;
      const auto it = by_tod.find(*f.utc_time_of_day_ns);
      ASSERT_NE(it, by_tod.end()) << log.name << ": GGA at " << Iso(*f.utc_time_of_day_ns)
                                  << " has no gpsd epoch";
      const GpsdEpoch& g = *it->second;
      EXPECT_NEAR(*f.lat_deg, *g.lat_deg, kNmeaTol.latlon_deg) << log.name;
      EXPECT_NEAR(*f.lon_deg, *g.lon_deg, kNmeaTol.latlon_deg) << log.name;
      EXPECT_NEAR(*f.msl_altitude_m + f.geoid_separation_m.value_or(0), *g.alt_hae_m,
                  kNmeaTol.alt_m)
          << log.name;
      ++compared;
    });
    dec.Feed(ReadBytes(dir + "/" + log.name));
  }
  std::printf("%d valid GGA sentences equal gpsd's positions\n", compared);
  EXPECT_GT(compared, 0);
}

class GpsdDecoderGoldenTest : public ::testing::TestWithParam<GpsdLog> {};

TEST_P(GpsdDecoderGoldenTest, EveryGpsdEpochIsDecodedWithTheSameValues) {
  const FieldStats st = CompareLog(GetParam());
  // every gpsd fix epoch is either matched or missing for a reason the log shows
  EXPECT_EQ(st.matched + st.missing_explained, st.gpsd_fix_epochs);
}

std::string LogTestName(const ::testing::TestParamInfo<GpsdLog>& p) {
  std::string n = p.param.name.substr(0, p.param.name.find('.'));
  for (char& c : n)
    if (c == '-') c = '_';
  return n;
}

INSTANTIATE_TEST_SUITE_P(Logs, GpsdDecoderGoldenTest, ::testing::ValuesIn(GpsdLogs()), LogTestName);

// End to end: the log through a pty into the real navd binary (GNSS-only mode, the log's
// protocol) gives one solution at each of gpsd's fix epochs, except those the log explains (the
// same derivation as above), with gpsd's position and speed, and none anywhere else.
struct NavdSolution {
  std::int64_t unix_ns = 0;
  nlohmann::json j;
};

std::vector<NavdSolution> ParseSolutions(const std::vector<std::string>& lines) {
  std::vector<NavdSolution> out;
  for (const std::string& line : lines) {
    NavdSolution s;
    s.j = nlohmann::json::parse(line, nullptr, false);
    const auto p = line.find("\"tov_utc_s\":");
    EXPECT_FALSE(s.j.is_discarded() || p == std::string::npos) << line;
    if (s.j.is_discarded() || p == std::string::npos) continue;
    long long sec = 0, nsec = 0;
    std::sscanf(line.c_str() + p + 12, "%lld.%lld", &sec, &nsec);
    s.unix_ns = sec * 1'000'000'000LL + nsec;
    out.push_back(s);
  }
  return out;
}

void CheckSolution(const NavdSolution& s, const GpsdEpoch& g, const Decoded& d, bool ubx) {
  const std::string at = Iso(g.unix_ns);
  // navd prints 10 decimals of a degree and 4 of a metre
  const double latlon_tol = (ubx ? kUbxTol : kNmeaTol).latlon_deg + 5e-11;
  EXPECT_NEAR(s.j["lat_deg"].get<double>(), *g.lat_deg, latlon_tol) << at;
  EXPECT_NEAR(s.j["lon_deg"].get<double>(), *g.lon_deg, latlon_tol) << at;
  if (g.alt_hae_m) {
    EXPECT_NEAR(s.j["height_m"].get<double>(), *g.alt_hae_m, 1.6e-4) << at;
  }
  if (g.speed_mps && !s.j.contains("speed_mps")) {
    EXPECT_FALSE(WhyNoSpeed(d, g, ubx).empty()) << at << ": navd reports no speed";
  } else if (g.speed_mps) {
    EXPECT_NEAR(s.j["speed_mps"].get<double>(), *g.speed_mps, 5.6e-4) << at;
  }
  // a velocity vector only where gpsd (the receiver) gave a direction
  EXPECT_EQ(s.j.contains("vel_enu_mps"), g.track_deg.has_value()) << at;
}

TEST_P(GpsdDecoderGoldenTest, NavdOnAPtyGivesSolutionsAtGpsdsEpochs) {
  const GpsdLog& log = GetParam();
  const bool ubx = log.protocol == "ubx";
  const std::string dir = GpsdVectorsDir();
  const std::string bytes = ReadBytes(dir + "/" + log.name);
  const GpsdReport gpsd = ReadGpsdChk(dir + "/" + log.name + ".chk");
  const Decoded d = ubx ? DecodeUbx(bytes) : DecodeNmea(bytes);
  const NavdRun run = RunNavdOnPty(bytes, log.protocol);
  EXPECT_EQ(run.exit_status, 0);
  const std::vector<NavdSolution> sol = ParseSolutions(run.json_lines);
  const std::int64_t tol_ns = (ubx ? kUbxTol : kNmeaTol).time_ns;
  int at_gpsd_epochs = 0, fix_epochs = 0, explained = 0;
  std::set<std::size_t> used;
  for (const GpsdEpoch& g : gpsd.epochs) {
    std::size_t k = sol.size();
    for (std::size_t i = 0; i < sol.size() && k == sol.size(); ++i)
      if (std::llabs(sol[i].unix_ns - g.unix_ns) <= tol_ns) k = i;
    if (g.mode < 2) {
      EXPECT_EQ(k, sol.size()) << Iso(g.unix_ns) << ": gpsd has no fix, navd a solution";
      continue;
    }
    ++fix_epochs;
    if (k == sol.size()) {
      const bool why = !WhyMissing(d, g, ubx).empty();
      EXPECT_TRUE(why) << Iso(g.unix_ns) << ": no navd solution";
      explained += why ? 1 : 0;
      continue;
    }
    used.insert(k);
    ++at_gpsd_epochs;
    CheckSolution(sol[k], g, d, ubx);
  }
  std::printf("%s through navd (%s): %zu solutions, %d at gpsd's %d fix epochs, %d explained\n",
              log.name.c_str(), log.protocol.c_str(), sol.size(), at_gpsd_epochs, fix_epochs,
              explained);
  EXPECT_EQ(used.size(), sol.size()) << "navd solutions at times gpsd reports no fix";
  EXPECT_EQ(at_gpsd_epochs + explained, fix_epochs);
}

}  // namespace
}  // namespace hil::estimator::testing
