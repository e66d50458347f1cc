#pragma once
/// @file
/// The geoid height N (geoid above the WGS-84 ellipsoid, m) at a fix's latitude and longitude, so
/// that altitude above mean sea level = ellipsoidal height − N (GGA fields 9 and 11, NAV-POSLLH
/// hMSL), from a grid of EGM96 geoid heights.
///
/// A u-blox 5 does not carry the fine grid: its GGA geoid separations in three real captures
/// (gpsd's nl402u, nl551e and ublox-lea-5h logs: 43.6, 46.1, 46.0 m at 54.09° N 10.82° E,
/// 52.00° N 6.04° E, 51.93° N 4.58° E) are EGM96 on a 10° grid with values rounded to whole metres,
/// interpolated bilinearly (43.63, 46.08, 45.98 m), where the 15' grid gives 39.25, 43.71 and
/// 43.54 m. `Resampled(10, true)` makes that table from the fine grid.
///
/// The grid is NGA's EGM96 15-minute grid in the GTX format PROJ ships (Debian package proj-data,
/// /usr/share/proj/egm96_15.gtx): a 40-byte big-endian header (south latitude, west longitude,
/// latitude step, longitude step as doubles; rows, columns as 32-bit integers), then rows × columns
/// big-endian 32-bit floats, row by row from south to north, west to east. Values between nodes are
/// interpolated bilinearly (as PROJ does), wrapping around in longitude. Plain C++: the emulator
/// keeps its Eigen-only dependency rule; the grid is a data file.

#include <cstdint>
#include <string>
#include <vector>

namespace hil::gnss {

class GeoidGrid {
 public:
  /// Reads a GTX grid. @throws std::runtime_error naming the file when it cannot be read or is
  /// not a GTX grid of the size its header says.
  static GeoidGrid LoadGtx(const std::string& path);

  /// A coarser grid whose nodes (every `step_deg`, a multiple of this grid's steps, from −90° and
  /// −180°) take this grid's node values, rounded to whole metres when `round_to_m`.
  GeoidGrid Resampled(double step_deg, bool round_to_m) const;

  /// Geoid height N (m) at a WGS-84 latitude (−90…90°) and longitude (any, wrapped).
  double SeparationAt_m(double lat_deg, double lon_deg) const;

  /// The value stored at a grid node (row from the south, column from the west edge).
  double Node_m(int row, int col) const;

  double south_lat_deg() const { return south_lat_deg_; }
  double west_lon_deg() const { return west_lon_deg_; }
  double lat_step_deg() const { return lat_step_deg_; }
  double lon_step_deg() const { return lon_step_deg_; }
  int rows() const { return rows_; }
  int cols() const { return cols_; }
  const std::string& path() const { return path_; }

 private:
  GeoidGrid() = default;
  std::string path_;
  double south_lat_deg_ = 0, west_lon_deg_ = 0, lat_step_deg_ = 0, lon_step_deg_ = 0;
  int rows_ = 0, cols_ = 0;
  std::vector<float> n_m_;  ///< rows × cols, row-major from the south-west node
};

}  // namespace hil::gnss
