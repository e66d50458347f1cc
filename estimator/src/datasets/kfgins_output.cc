#include "hil/estimator/datasets/kfgins_output.h"

#include <cerrno>
#include <charconv>
#include <cstring>

#include "hil/estimator/datasets/dataset_error.h"
#include "hil/estimator/datasets/fixed_decimal.h"

namespace hil::estimator::datasets {
namespace {

constexpr std::size_t kBlockBytes = 1 << 18;
constexpr std::size_t kLineBytes = 1024;  // more than any line (at most 22 numbers)

// a line being formatted at its place in a file's block
class LineBuffer {
 public:
  explicit LineBuffer(char* start) : start_(start), p_(start), end_(start + kLineBytes) {}
  void Add(double v, int decimals) {
    if (p_ != start_) *p_++ = ' ';
    // a value too long for the rest of the line is left out (never happens here)
    p_ = FormatFixed(p_, end_ - 2, v, decimals);
  }
  void Add(const Eigen::Vector3d& v, int decimals) {
    for (int i = 0; i < 3; ++i) Add(v[i], decimals);
  }
  void AddText(const char* text, std::size_t length) {
    if (static_cast<std::size_t>(end_ - 2 - p_) < length + 1) return;  // as Add: left out
    if (p_ != start_) *p_++ = ' ';
    std::memcpy(p_, text, length);
    p_ += length;
  }
  void AddInt(int v) {
    if (p_ != start_) *p_++ = ' ';
    p_ = std::to_chars(p_, end_ - 2, v).ptr;
  }
  std::size_t End() {
    *p_++ = '\n';
    return static_cast<std::size_t>(p_ - start_);
  }

 private:
  char* const start_;
  char* p_;
  char* const end_;
};

std::FILE* Create(const std::string& dir, const char* name) {
  const std::string path = dir + "/" + name;
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw DatasetError(path, 0, std::string("cannot create: ") + std::strerror(errno));
  std::setvbuf(f, nullptr, _IONBF, 0);  // the writer's blocks go out whole
  return f;
}

}  // namespace

char* KfginsOutputWriter::Block::Line() {
  if (bytes.size() - used < kLineBytes) Flush();
  return bytes.data() + used;
}

void KfginsOutputWriter::Block::Flush() {
  if (used > 0 && file) std::fwrite(bytes.data(), 1, used, file);
  used = 0;
}

KfginsOutputWriter::KfginsOutputWriter(const std::string& dir) : dir_(dir) {
  for (Block* b : {&nav_, &err_, &std_}) b->bytes.resize(kBlockBytes);
  nav_.file = Create(dir, kNavFile);
  err_.file = Create(dir, kImuErrFile);
  std_.file = Create(dir, kStdFile);
}

KfginsOutputWriter::~KfginsOutputWriter() {
  for (Block* b : {&nav_, &err_, &std_}) {
    if (!b->file) continue;
    b->Flush();
    std::fclose(b->file);
  }
}

void KfginsOutputWriter::Write(const KfginsEpoch& e) {
  char sow[512];  // formatted once for the three files (room for any double)
  const auto sow_length =
      static_cast<std::size_t>(FormatFixed(sow, sow + sizeof sow, e.sow, 6) - sow);
  LineBuffer n(nav_.Line());
  n.AddInt(e.week);
  n.AddText(sow, sow_length);
  n.Add(e.lat_deg, 11);
  n.Add(e.lon_deg, 11);
  n.Add(e.height_m, 6);
  n.Add(e.vel_ned_mps, 6);
  n.Add(e.rpy_deg, 8);
  nav_.used += n.End();
  LineBuffer b(err_.Line());
  b.AddText(sow, sow_length);
  b.Add(e.gyro_bias_frd_deg_hr, 6);
  b.Add(e.accel_bias_frd_mgal, 6);
  err_.used += b.End();
  LineBuffer s(std_.Line());
  s.AddText(sow, sow_length);
  s.Add(e.pos_std_ned_m, 6);
  s.Add(e.vel_std_ned_mps, 6);
  s.Add(e.att_std_deg, 8);
  s.Add(e.gyro_bias_std_deg_hr, 6);
  s.Add(e.accel_bias_std_mgal, 6);
  std_.used += s.End();
}

void KfginsOutputWriter::Close() {
  const char* names[] = {kNavFile, kImuErrFile, kStdFile};
  Block* blocks[] = {&nav_, &err_, &std_};
  int failed = -1;
  for (int i = 0; i < 3; ++i) {
    Block& b = *blocks[i];
    if (!b.file) continue;
    b.Flush();
    const bool bad = std::ferror(b.file) != 0;
    if ((std::fclose(b.file) != 0 || bad) && failed < 0) failed = i;
    b.file = nullptr;
  }
  if (failed >= 0) throw DatasetError(dir_ + "/" + names[failed], 0, "write error (disk full?)");
}

}  // namespace hil::estimator::datasets
