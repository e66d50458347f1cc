// The geoid grids a receiver's spec names (`gnss.geoid`, scenario.h): EGM96 from PROJ's grid and
// the u-blox 5's coarse table made from it, each read once per process.
#include <cstdlib>
#include <memory>

#include "hil/harness/scenario/scenario.h"

namespace hil::harness {

std::shared_ptr<const gnss::GeoidGrid> Egm96Geoid() {
  // one grid per process (4 MB), read on first use; $HIL_EGM96_GRID overrides the built-in path
  static const std::shared_ptr<const gnss::GeoidGrid> grid = [] {
    const char* env = std::getenv("HIL_EGM96_GRID");
    return std::make_shared<const gnss::GeoidGrid>(
        gnss::GeoidGrid::LoadGtx(env && *env ? env : HIL_EGM96_GRID));
  }();
  return grid;
}

std::shared_ptr<const gnss::GeoidGrid> Ublox5Geoid() {
  static const std::shared_ptr<const gnss::GeoidGrid> grid =
      std::make_shared<const gnss::GeoidGrid>(Egm96Geoid()->Resampled(10.0, true));
  return grid;
}

}  // namespace hil::harness
