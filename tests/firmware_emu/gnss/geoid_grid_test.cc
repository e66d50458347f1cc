// The EGM96 geoid grid reader (firmware_emu/src/gnss/geoid_grid.cc) against PROJ, an independent
// implementation evaluating the same grid (vectors/gnss/egm96_proj_points.txt), against NGA's own
// check values, and the u-blox 5 table against real receivers' GGA geoid separations.
#include "hil/firmware_emu/gnss/geoid_grid.h"

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "shared_vectors.h"

namespace hil::gnss {
namespace {

const GeoidGrid& Egm96() {
  static const GeoidGrid grid = GeoidGrid::LoadGtx(HIL_EGM96_GRID);
  return grid;
}

TEST(GeoidGridTest, ReadsProjsEgm96FifteenMinuteGrid) {
  const GeoidGrid& g = Egm96();
  EXPECT_EQ(g.rows(), 721);
  EXPECT_EQ(g.cols(), 1440);
  EXPECT_EQ(g.south_lat_deg(), -90.0);
  EXPECT_EQ(g.west_lon_deg(), -180.0);
  EXPECT_EQ(g.lat_step_deg(), 0.25);
  EXPECT_EQ(g.lon_step_deg(), 0.25);
}

TEST(GeoidGridTest, AtGridNodesTheStoredValue) {
  const GeoidGrid& g = Egm96();
  for (const auto& [row, col] : {std::pair{0, 0}, {360, 720}, {502, 922}, {720, 1439}, {100, 5}}) {
    const double lat = -90.0 + 0.25 * row, lon = -180.0 + 0.25 * col;
    EXPECT_EQ(g.SeparationAt_m(lat, lon), g.Node_m(row, col)) << lat << " " << lon;
    EXPECT_EQ(g.SeparationAt_m(lat, lon + 360.0), g.Node_m(row, col)) << "longitude wraps";
  }
}

TEST(GeoidGridTest, AgreesWithProjEverywhere) {
  std::ifstream in(std::string(std::getenv("HIL_SOURCE_DIR")) +
                   "/vectors/gnss/egm96_proj_points.txt");
  ASSERT_TRUE(in);
  int points = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ss(line);
    double lat = 0, lon = 0, n = 0;
    ss >> lat >> lon >> n;
    // PROJ prints 4 decimals
    EXPECT_NEAR(Egm96().SeparationAt_m(lat, lon), n, 0.6e-4) << line;
    ++points;
  }
  EXPECT_EQ(points, 20);
}

// NGA's sample output of its interpolation program on the same grid (the EGM96 distribution's
// README, OUTINTPT.DAT); NGA interpolates with a spline, PROJ and hil bilinearly: a few cm apart.
TEST(GeoidGridTest, AgreesWithNgasCheckValues) {
  const struct {
    double lat, lon, n;
  } nga[] = {{38.6281550, 269.7791550, -31.628}, {-14.6212170, 305.0211140, -2.969},
             {46.8743190, 102.4487290, -43.575}, {-23.6174460, 133.8747120, 15.871},
             {38.6254730, 359.9995000, 50.066},  {-0.4667440, 0.0023000, 17.329}};
  for (const auto& p : nga) EXPECT_NEAR(Egm96().SeparationAt_m(p.lat, p.lon), p.n, 0.06) << p.lat;
}

// First GGA with a fix of a real receiver's log: latitude, longitude, geoid separation.
struct RealGga {
  double lat = 0, lon = 0, n = 0;
};

RealGga FirstFix(const std::string& file) {
  std::ifstream in(test::GpsdVector(file));
  EXPECT_TRUE(in) << file;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("$GPGGA", 0) != 0) continue;
    std::vector<std::string> f;
    std::stringstream ss(line);
    for (std::string x; std::getline(ss, x, ',');) f.push_back(x);
    if (f.size() < 12 || f[6] == "0" || f[2].empty()) continue;
    const auto deg = [](const std::string& v, const std::string& h) {
      const double x = std::stod(v), d = std::floor(x / 100);
      return (h == "S" || h == "W" ? -1 : 1) * (d + (x - 100 * d) / 60);
    };
    return {deg(f[2], f[3]), deg(f[4], f[5]), std::stod(f[11])};
  }
  ADD_FAILURE() << "no fix in " << file;
  return {};
}

// A u-blox 5 prints EGM96 from a coarse table: 10° nodes in whole metres, interpolated bilinearly
// (the 15' grid itself is 2.4 to 4.4 m off these receivers' values).
TEST(GeoidGridTest, Ublox5TableReproducesRealReceivers) {
  HIL_SKIP_WITHOUT_GPSD_VECTORS();
  const GeoidGrid table = Egm96().Resampled(10.0, true);
  EXPECT_EQ(table.rows(), 19);
  EXPECT_EQ(table.cols(), 36);
  for (const char* file : {"nl402u.log", "nl551e.log", "ublox-lea-5h.log"}) {
    const RealGga real = FirstFix(file);
    EXPECT_NEAR(table.SeparationAt_m(real.lat, real.lon), real.n, 0.05) << file;
    EXPECT_GT(std::abs(Egm96().SeparationAt_m(real.lat, real.lon) - real.n), 2.0) << file;
  }
  // a node keeps the fine grid's value rounded: 40° N 60° E is −28.33 m in the 15' grid
  EXPECT_EQ(table.SeparationAt_m(40.0, 60.0), -28.0);
}

TEST(GeoidGridTest, UnreadableOrMalformedGridsAreNamed) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path();
  try {
    GeoidGrid::LoadGtx((dir / "no_such_grid.gtx").string());
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_grid.gtx"), std::string::npos) << e.what();
  }
  const std::string cut = (dir / ("hil_cut_grid_" + std::to_string(::getpid()) + ".gtx")).string();
  {
    std::ifstream full(HIL_EGM96_GRID, std::ios::binary);
    std::string head(1000, '\0');
    full.read(head.data(), 1000);
    std::ofstream(cut, std::ios::binary) << head;
  }
  try {
    GeoidGrid::LoadGtx(cut);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("1000 bytes where the header says 4153000"),
              std::string::npos)
        << e.what();
  }
  std::filesystem::remove(cut);
}

}  // namespace
}  // namespace hil::gnss
