// The GNSS receivers' row of the device table: section `gnss`, one Neo5mDevice per receiver on
// its own pty (ttyGPS, ttyGPS1, ...), navd's gnss_device and, for multi_gnss, every receiver's
// link and antenna.
#include <filesystem>

#include "hil/firmware_emu/gnss/neo5m_device.h"
#include "hil/harness/scenario/navd_gnss_source.h"

#include "gnss_receiver.h"

namespace hil::harness {
namespace {

constexpr std::uint64_t kGnssCommonOffset = 0x5151;  // the error part shared by all receivers
constexpr std::uint64_t kReceiverStride = 7919;      // each receiver's own part

// The scenario's global fault timeline: outages, data gaps and glitches reach every receiver.
void AddTimelineFaults(const FaultTimeline& timeline, std::vector<gnss::GnssFault>& faults) {
  for (const Fault& f : timeline.faults) {
    gnss::GnssFault g;
    g.start = f.start;
    g.end = f.end;
    if (f.kind == FaultKind::kGnssOutage) {
      g.kind = gnss::GnssFault::Kind::kOutage;
    } else if (f.kind == FaultKind::kGnssDataGap) {
      g.kind = gnss::GnssFault::Kind::kDataGap;
    } else if (f.kind == FaultKind::kGnssGlitch) {
      g.kind = gnss::GnssFault::Kind::kStep;
      g.offset_N_m =
          Eigen::Vector3d(f.Param("east_m", 0), f.Param("north_m", 0), f.Param("up_m", 0));
    } else if (f.kind == FaultKind::kGnssOverload) {
      g.kind = gnss::GnssFault::Kind::kOverload;
    } else {
      continue;
    }
    faults.push_back(g);
  }
}

// One Neo5mDevice per receiver of the gnss section, each on its own pty (ttyGPS, ttyGPS1, ...).
void BuildGnssReceivers(const Scenario& s, std::uint64_t seed, const std::string& dir,
                        DeviceBuild& set) {
  for (std::size_t i = 0; i < s.gnss.receivers.size(); ++i) {
    const GnssReceiverSpec& rx = s.gnss.receivers[i];
    gnss::Neo5mConfig cfg;
    cfg.name = "gps" + std::to_string(i);
    cfg.profile = s.gnss.profile;
    cfg.baud = s.gnss.baud;
    cfg.rate_hz = s.gnss.rate_hz;
    cfg.output_lag = DurationFromSeconds(s.gnss.output_lag_s);
    cfg.start_utc = s.start_utc;
    cfg.model = s.gnss.model;
    cfg.model->p_BA_B_m = rx.p_BA_B_m;
    cfg.start = s.gnss.start;
    cfg.faults = s.gnss.faults;
    AddTimelineFaults(s.faults, cfg.faults);
    cfg.common_seed = seed + kGnssCommonOffset;
    cfg.shading = s.gnss.shading;
    cfg.rtk_rough = s.gnss.rtk_rough;
    auto dev = std::make_unique<gnss::Neo5mDevice>(cfg, seed + kReceiverStride * i);
    const gnss::Neo5mDevice* raw = dev.get();
    set.fix_sources.push_back([raw] { return &raw->last_fix(); });
    AddSerialDevice(std::move(dev), rx.link, s.gnss.tx_buffer_bytes, dir, set);
  }
}

// [input] gnss_device and gnss_baud (unless navd reads the ZED-F9P rover: its row writes them);
// multi_gnss: every receiver's antenna relative to the body
// origin ([filter] antenna_N_m) and link ([input] gnss_device_N), after [filter]'s keys.
void WriteGnssReceiversNavd(NavdConfSlot slot, const Scenario& s, const std::string& gnss_device,
                            std::ostream& out) {
  if (slot == NavdConfSlot::kInput && !NavdReadsRover(s))
    out << "gnss_device = " << gnss_device << "\ngnss_baud = " << s.gnss.baud << "\n";
  if (slot != NavdConfSlot::kSections || s.estimator.navd_mode != NavdMode::kMultiGnss) return;
  const std::filesystem::path dir = std::filesystem::path(gnss_device).parent_path();
  for (std::size_t i = 0; i < s.gnss.receivers.size(); ++i) {
    const Eigen::Vector3d& a = s.gnss.receivers[i].p_BA_B_m;
    out << "antenna_" << i << "_m = " << a.x() << ", " << a.y() << ", " << a.z() << "\n";
  }
  out << "\n[input]\n";
  for (std::size_t i = 1; i < s.gnss.receivers.size(); ++i) {
    out << "gnss_device_" << i << " = " << (dir / s.gnss.receivers[i].link).string() << "\n";
  }
}

std::vector<std::string> GnssReceiverLinks(const Scenario& s) {
  std::vector<std::string> links;
  for (const GnssReceiverSpec& r : s.gnss.receivers) links.push_back(r.link);
  return links;
}

constexpr std::string_view kGnssReceiverSections[] = {"gnss", "obstructions"};
constexpr std::string_view kGnssReceiverNavdKeys[] = {"input.gnss_device", "input.gnss_baud",
                                                      "input.gnss_device_N", "filter.antenna_N_m"};

// navd reads the first receiver, and every receiver in multi_gnss, except in its UWB and
// odometry modes and when it reads the ZED-F9P rover instead (navd_gnss_source.h).
std::vector<std::string> GnssReceiverNavdLinks(const Scenario& s) {
  const NavdMode m = s.estimator.navd_mode;
  if (m == NavdMode::kUwb || m == NavdMode::kGyroOdometry || NavdReadsRover(s)) return {};
  if (m != NavdMode::kMultiGnss) return {s.gnss.link};
  std::vector<std::string> links{s.gnss.link};
  for (const GnssReceiverSpec& r : s.gnss.receivers) links.push_back(r.link);
  return links;
}

// The header's line: profile, rate, baud, receivers, the first antenna's lever arm.
std::string GnssReceiverProfile(const Scenario& s) {
  const Eigen::Vector3d& a = s.gnss.model.p_BA_B_m;
  return ProfileText(
      "profile %s, %g Hz, %d Bd, %zu receiver(s); antenna at (%.2f, %.2f, %.2f) m "
      "in the body frame (forward, left, up)",
      s.gnss.profile.c_str(), s.gnss.rate_hz, s.gnss.baud, s.gnss.receivers.size(), a.x(), a.y(),
      a.z());
}

}  // namespace

extern const DeviceKind kGnssReceiverKind;
const DeviceKind kGnssReceiverKind{.name = "gnss_receiver",
                                   .sections = kGnssReceiverSections,
                                   .spec = "gnss: (NEO-5M or RTK profile; one or more receivers)",
                                   .read = ReadGnssReceiverSpec,
                                   .seed_stream = 1,
                                   .build = BuildGnssReceivers,
                                   .navd_keys = kGnssReceiverNavdKeys,
                                   .write_navd = WriteGnssReceiversNavd,
                                   .links = GnssReceiverLinks,
                                   .navd_links = GnssReceiverNavdLinks,
                                   .report_section = "link_integrity",
                                   .link_role = "gnss",
                                   .profile = GnssReceiverProfile};

}  // namespace hil::harness
