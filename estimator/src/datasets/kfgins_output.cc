#include "hil/estimator/datasets/kfgins_output.h"

#include <cerrno>
#include <charconv>
#include <cstring>

#include "hil/estimator/datasets/dataset_error.h"
#include "hil/estimator/datasets/fixed_decimal.h"

namespace hil::estimator::datasets {
namespace {

// a line being formatted in a fixed buffer
class LineBuffer {
 public:
  void Add(double v, int decimals) {
    if (p_ != buf_) *p_++ = ' ';
    // a value too long for the rest of the line is left out (never happens here)
    p_ = FormatFixed(p_, end_ - 2, v, decimals);
  }
  void Add(const Eigen::Vector3d& v, int decimals) {
    for (int i = 0; i < 3; ++i) Add(v[i], decimals);
  }
  void AddInt(int v) {
    if (p_ != buf_) *p_++ = ' ';
    p_ = std::to_chars(p_, end_ - 2, v).ptr;
  }
  void WriteTo(std::FILE* f) {
    *p_++ = '\n';
    std::fwrite(buf_, 1, static_cast<std::size_t>(p_ - buf_), f);
    p_ = buf_;
  }

 private:
  char buf_[512] = {};
  char* p_ = buf_;
  char* const end_ = buf_ + sizeof buf_;
};

std::FILE* Create(const std::string& dir, const char* name) {
  const std::string path = dir + "/" + name;
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw DatasetError(path, 0, std::string("cannot create: ") + std::strerror(errno));
  std::setvbuf(f, nullptr, _IOFBF, 1 << 18);  // one line per IMU epoch: written in large blocks
  return f;
}

}  // namespace

KfginsOutputWriter::KfginsOutputWriter(const std::string& dir) : dir_(dir) {
  nav_ = Create(dir, kNavFile);
  err_ = Create(dir, kImuErrFile);
  std_ = Create(dir, kStdFile);
}

KfginsOutputWriter::~KfginsOutputWriter() {
  for (std::FILE* f : {nav_, err_, std_})
    if (f) std::fclose(f);
}

void KfginsOutputWriter::Write(const KfginsEpoch& e) {
  LineBuffer b;
  b.AddInt(e.week);
  b.Add(e.sow, 6);
  b.Add(e.lat_deg, 11);
  b.Add(e.lon_deg, 11);
  b.Add(e.height_m, 6);
  b.Add(e.vel_ned_mps, 6);
  b.Add(e.rpy_deg, 8);
  b.WriteTo(nav_);
  b.Add(e.sow, 6);
  b.Add(e.gyro_bias_frd_deg_hr, 6);
  b.Add(e.accel_bias_frd_mgal, 6);
  b.WriteTo(err_);
  b.Add(e.sow, 6);
  b.Add(e.pos_std_ned_m, 6);
  b.Add(e.vel_std_ned_mps, 6);
  b.Add(e.att_std_deg, 8);
  b.Add(e.gyro_bias_std_deg_hr, 6);
  b.Add(e.accel_bias_std_mgal, 6);
  b.WriteTo(std_);
}

void KfginsOutputWriter::Close() {
  const char* names[] = {kNavFile, kImuErrFile, kStdFile};
  std::FILE* files[] = {nav_, err_, std_};
  nav_ = err_ = std_ = nullptr;
  int failed = -1;
  for (int i = 0; i < 3; ++i) {
    if (!files[i]) continue;
    const bool bad = std::ferror(files[i]) != 0;
    if ((std::fclose(files[i]) != 0 || bad) && failed < 0) failed = i;
  }
  if (failed >= 0) throw DatasetError(dir_ + "/" + names[failed], 0, "write error (disk full?)");
}

}  // namespace hil::estimator::datasets
