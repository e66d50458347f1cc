// Wrong fixes of the ZED-F9P rover (issue 44, Build item 2): with a wrong-fix rate of 1 every fix
// is off by a whole-cycle combination (decimetres) while carrSoln says fixed, until its hold ends;
// then float, and a new fix after the convergence time. With the default rate 0 no fix is wrong.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hil/firmware_emu/gnss/geodesy.h"

#include "zed_f9p_fixture.h"

namespace hil::rtk {
namespace {

using gnss::ubx::CarrSoln;

struct EpochState {
  double t_s;
  CarrSoln carr;
  double error_m;  // 3-D, against the still antenna
};

std::vector<EpochState> RunRover(const ZedF9pConfig& c, double seconds) {
  ZedF9pDevice dev(c, 3);
  const Eigen::Vector3d truth_E =
      gnss::EcefFromGeodetic(test::kRoverLat_deg, test::kRoverLon_deg, test::kRoverHeight_m);
  std::vector<EpochState> out;
  DeviceOutput sink;
  std::uint64_t epochs = 0;
  while (dev.next_event_time() < TimeFromSeconds(seconds)) {
    const Time t = dev.next_event_time();
    dev.OnEvent(test::StillTruth(t), sink);
    sink.clear();
    if (dev.rover_statistics().epochs == epochs) continue;  // a radio event
    epochs = dev.rover_statistics().epochs;
    const gnss::GnssFix& f = dev.last_fix();
    out.push_back({ToSeconds(t - Time{}), dev.last_epoch().carr_soln,
                   (gnss::EcefFromGeodetic(f.lat_deg, f.lon_deg, f.height_m) - truth_E).norm()});
  }
  return out;
}

TEST(ZedF9pWrongFix, EveryFixWrongUntilCaughtThenFloatAndANewFix) {
  ZedF9pConfig c = test::RoverWithRadio();
  c.rtk.wrong_fix = {1.0, 10.0, 2, 1};
  const std::vector<EpochState> run = RunRover(c, 60);
  int fixed = 0, refixes = 0;
  bool caught = false;
  double smallest_m = 1e9, largest_m = 0;
  for (std::size_t k = 1; k < run.size(); ++k) {
    if (run[k].carr != CarrSoln::kFixed) {
      caught = caught || run[k - 1].carr == CarrSoln::kFixed;
      continue;
    }
    ++fixed;
    refixes += run[k - 1].carr == CarrSoln::kFloat && caught ? 1 : 0;
    // a wrong fix is decimetres off while the fixed error is about a centimetre
    EXPECT_GT(run[k].error_m, 0.05) << "at " << run[k].t_s << " s";
    smallest_m = std::min(smallest_m, run[k].error_m);
    largest_m = std::max(largest_m, run[k].error_m);
  }
  RecordProperty("wrong_fix_error_min_mm", std::to_string(smallest_m * 1000));
  RecordProperty("wrong_fix_error_max_mm", std::to_string(largest_m * 1000));
  RecordProperty("fixed_epochs", fixed);
  RecordProperty("refixes", refixes);
  EXPECT_GT(fixed, 10);
  EXPECT_TRUE(caught) << "a wrong fix ends (hold 5–15 s) and the rover falls back to float";
  EXPECT_GE(refixes, 1) << "and fixes again after its convergence";
}

TEST(ZedF9pWrongFix, NoneAtTheDefaultRate) {
  const std::vector<EpochState> run = RunRover(test::RoverWithRadio(), 60);
  int fixed = 0;
  for (const EpochState& e : run) {
    if (e.carr != CarrSoln::kFixed) continue;
    ++fixed;
    EXPECT_LT(e.error_m, 0.06) << "at " << e.t_s << " s";
  }
  EXPECT_EQ(fixed, 48);  // fixed from 12 s to 59 s
}

}  // namespace
}  // namespace hil::rtk
