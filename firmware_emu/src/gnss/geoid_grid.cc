#include "hil/firmware_emu/gnss/geoid_grid.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace hil::gnss {
namespace {

constexpr std::size_t kHeaderBytes = 40;

std::uint64_t BigEndian(const unsigned char* p, int n) {
  std::uint64_t v = 0;
  for (int i = 0; i < n; ++i) v = v << 8 | p[i];
  return v;
}

double DoubleAt(const unsigned char* p) { return std::bit_cast<double>(BigEndian(p, 8)); }

float FloatAt(const unsigned char* p) {
  return std::bit_cast<float>(static_cast<std::uint32_t>(BigEndian(p, 4)));
}

}  // namespace

GeoidGrid GeoidGrid::LoadGtx(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw std::runtime_error("cannot read the geoid grid " + path);
  const std::streamoff size = in.tellg();
  in.seekg(0);
  const auto bad = [&](const std::string& why) {
    return std::runtime_error("the geoid grid " + path + " is not a GTX grid: " + why);
  };
  unsigned char header[kHeaderBytes];
  if (size < static_cast<std::streamoff>(kHeaderBytes) ||
      !in.read(reinterpret_cast<char*>(header), kHeaderBytes))
    throw bad("shorter than its 40-byte header");
  GeoidGrid g;
  g.path_ = path;
  g.south_lat_deg_ = DoubleAt(&header[0]);
  g.west_lon_deg_ = DoubleAt(&header[8]);
  g.lat_step_deg_ = DoubleAt(&header[16]);
  g.lon_step_deg_ = DoubleAt(&header[24]);
  g.rows_ = static_cast<std::int32_t>(BigEndian(&header[32], 4));
  g.cols_ = static_cast<std::int32_t>(BigEndian(&header[36], 4));
  if (g.rows_ < 2 || g.cols_ < 2 || g.rows_ > 100000 || g.cols_ > 100000 ||
      !(g.lat_step_deg_ > 0) || !(g.lon_step_deg_ > 0))
    throw bad("its header gives no usable grid size");
  const std::size_t n = static_cast<std::size_t>(g.rows_) * static_cast<std::size_t>(g.cols_);
  if (static_cast<std::size_t>(size) != kHeaderBytes + 4 * n)
    throw bad(std::to_string(size) + " bytes where the header says " +
              std::to_string(kHeaderBytes + 4 * n));
  // the values in one read straight into place, then from big-endian (a byte-wise copy of the
  // file through a second buffer took tens of ms for 4 MB, on every run)
  g.n_m_.resize(n);
  if (!in.read(reinterpret_cast<char*>(g.n_m_.data()), static_cast<std::streamsize>(4 * n)))
    throw std::runtime_error("cannot read the geoid grid " + path);
  for (float& v : g.n_m_) {
    unsigned char b[4];
    std::memcpy(b, &v, 4);
    v = FloatAt(b);
  }
  return g;
}

GeoidGrid GeoidGrid::Resampled(double step_deg, bool round_to_m) const {
  const double ratio_lat = step_deg / lat_step_deg_, ratio_lon = step_deg / lon_step_deg_;
  const auto whole = [](double v) { return std::abs(v - std::round(v)) < 1e-9 && v >= 1; };
  if (!whole(ratio_lat) || !whole(ratio_lon) || std::fmod(360.0, step_deg) != 0 ||
      std::fmod(180.0, step_deg) != 0)
    throw std::invalid_argument("geoid grid step " + std::to_string(step_deg) +
                                " deg is not a multiple of the grid's nor a divisor of 180 deg");
  GeoidGrid g;
  g.path_ = path_;
  g.south_lat_deg_ = -90.0;
  g.west_lon_deg_ = -180.0;
  g.lat_step_deg_ = g.lon_step_deg_ = step_deg;
  g.rows_ = static_cast<int>(std::lround(180.0 / step_deg)) + 1;
  g.cols_ = static_cast<int>(std::lround(360.0 / step_deg));
  for (int r = 0; r < g.rows_; ++r) {
    for (int c = 0; c < g.cols_; ++c) {
      const double v = SeparationAt_m(-90.0 + r * step_deg, -180.0 + c * step_deg);
      g.n_m_.push_back(static_cast<float>(round_to_m ? std::round(v) : v));
    }
  }
  return g;
}

double GeoidGrid::Node_m(int row, int col) const {
  const int c = ((col % cols_) + cols_) % cols_;  // the grid wraps around in longitude
  const int r = std::clamp(row, 0, rows_ - 1);
  return n_m_[static_cast<std::size_t>(r) * static_cast<std::size_t>(cols_) +
              static_cast<std::size_t>(c)];
}

double GeoidGrid::SeparationAt_m(double lat_deg, double lon_deg) const {
  const double y =
      std::clamp((lat_deg - south_lat_deg_) / lat_step_deg_, 0.0, static_cast<double>(rows_ - 1));
  const double x =
      std::fmod(std::fmod(lon_deg - west_lon_deg_, 360.0) + 360.0, 360.0) / lon_step_deg_;
  const int r = std::min(static_cast<int>(y), rows_ - 2);
  const int c = static_cast<int>(x);
  const double fy = y - r, fx = x - c;
  const double south = (1 - fx) * Node_m(r, c) + fx * Node_m(r, c + 1);
  const double north = (1 - fx) * Node_m(r + 1, c) + fx * Node_m(r + 1, c + 1);
  return (1 - fy) * south + fy * north;
}

}  // namespace hil::gnss
