#include "hil/harness/links/capture_format.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstring>
#include <sstream>
#include <stdexcept>

#include "hil/firmware_emu/link/candump_log.h"

namespace hil::harness {
namespace {

constexpr std::string_view kDirNames[] = {"tx", "rx", "drop", "ftx", "frx"};

std::optional<std::int64_t> ToInt(std::string_view s) {
  std::int64_t v = 0;
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc{} || p != s.data() + s.size()) return std::nullopt;
  return v;
}

std::vector<std::string_view> Fields(std::string_view line) {
  std::vector<std::string_view> f;
  while (!line.empty()) {
    const std::size_t a = line.find_first_not_of(' ');
    if (a == std::string_view::npos) break;
    line.remove_prefix(a);
    const std::size_t b = line.find(' ');
    f.push_back(line.substr(0, b));
    line = b == std::string_view::npos ? std::string_view{} : line.substr(b);
  }
  return f;
}

}  // namespace

std::string_view CaptureDirName(CaptureDir d) { return kDirNames[static_cast<int>(d)]; }

namespace {

// Appends the lowercase hex digits of `bytes` to `o`.
void AppendCaptureHex(std::string& o, std::string_view bytes) {
  static constexpr char kHex[] = "0123456789abcdef";
  const std::size_t at = o.size();
  o.resize(at + bytes.size() * 2);
  char* w = o.data() + at;
  for (const unsigned char c : bytes) {
    *w++ = kHex[c >> 4];
    *w++ = kHex[c & 15];
  }
}

// Appends a decimal integer and a space to `o` (std::to_string's digits).
void AppendCaptureInt(std::string& o, std::int64_t v) {
  char buf[24];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  o.append(buf, res.ptr);
  o += ' ';
}

}  // namespace

std::string ToHex(std::string_view bytes) {
  std::string o;
  AppendCaptureHex(o, bytes);
  return o;
}

std::optional<std::string> FromHex(std::string_view hex) {
  if (hex.size() % 2 != 0) return std::nullopt;
  const auto nib = [](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
  };
  std::string out(hex.size() / 2, '\0');
  for (std::size_t i = 0; i < out.size(); ++i) {
    const int hi = nib(hex[2 * i]), lo = nib(hex[2 * i + 1]);
    if (hi < 0 || lo < 0) return std::nullopt;
    out[i] = static_cast<char>(hi << 4 | lo);
  }
  return out;
}

std::string FormatCaptureLine(const CaptureRecord& r) {
  std::string o;
  o.reserve(80 + r.name.size() + 2 * r.bytes.size() + 12 * r.wall_offsets_ns.size());
  o += CaptureDirName(r.dir);
  o += ' ';
  AppendCaptureInt(o, r.t_emu_ns);
  AppendCaptureInt(o, r.byte_period_ns);
  AppendCaptureInt(o, ToNs(r.t_wall));
  o += r.name.empty() ? std::string_view("-") : std::string_view(r.name);
  o += ' ';
  if (r.is_frame()) {
    o += link::FormatCanFrameText(r.frame);
  } else if (r.bytes.empty()) {
    o += '-';
  } else {
    AppendCaptureHex(o, r.bytes);
  }
  if (!r.wall_offsets_ns.empty()) {
    o += ' ';
    for (std::size_t k = 0; k < r.wall_offsets_ns.size(); ++k) {
      if (k) o += ',';
      o += std::to_string(r.wall_offsets_ns[k]);
    }
  }
  return o;
}

std::optional<CaptureRecord> ParseCaptureLine(std::string_view line) {
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.remove_suffix(1);
  if (line.empty() || line.front() == '#') return std::nullopt;
  const auto f = Fields(line);
  if (f.size() != 6 && f.size() != 7) return std::nullopt;
  CaptureRecord r;
  bool known = false;
  for (int d = 0; d < 5; ++d) {
    if (f[0] == kDirNames[d]) {
      r.dir = static_cast<CaptureDir>(d);
      known = true;
    }
  }
  const auto t = ToInt(f[1]), period = ToInt(f[2]), wall = ToInt(f[3]);
  if (!known || !t || !period || !wall) return std::nullopt;
  r.t_emu_ns = *t;
  r.byte_period_ns = *period;
  r.t_wall = WallTimeFromNs(*wall);
  r.name = std::string(f[4]);
  if (r.is_frame()) {
    const auto frame = link::ParseCanFrameText(f[5]);
    if (!frame) return std::nullopt;
    r.frame = *frame;
  } else if (f[5] != "-") {
    auto bytes = FromHex(f[5]);
    if (!bytes) return std::nullopt;
    r.bytes = std::move(*bytes);
  }
  if (f.size() == 7) {
    std::string_view rest = f[6];
    while (!rest.empty()) {
      const std::size_t comma = rest.find(',');
      const auto v = ToInt(rest.substr(0, comma));
      if (!v) return std::nullopt;
      r.wall_offsets_ns.push_back(*v);
      rest = comma == std::string_view::npos ? std::string_view{} : rest.substr(comma + 1);
    }
    if (!r.is_frame() && r.wall_offsets_ns.size() != r.bytes.size()) return std::nullopt;
  }
  return r;
}

CaptureWriter::CaptureWriter(const std::string& path, const CaptureHeader& h) : path_(path) {
  fd_ = open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw std::runtime_error("cannot write the capture " + path + ": " + std::strerror(errno));
  std::ostringstream out;
  out << "# hil capture v2\n# link " << h.link << ' ' << h.kind << ' ';
  if (h.kind == "can")
    out << h.iface;
  else
    out << h.baud;
  out << "\n";
  if (h.start_utc) out << "# start_unix_ns " << ToNs(*h.start_utc) << "\n";
  out << "# columns: dir t_emu_ns byte_period_ns t_wall_ns name data [wall_offsets_ns]"
         " (format: vectors/captures/README.md)\n";
  buf_ = out.str();
  Flush();
}

void CaptureWriter::ReportFailuresTo(RunDiagnostics* diagnostics) {
  diagnostics_ = diagnostics;
  if (failed_ && diagnostics_) diagnostics_->NoteWriteFailure(path_);
}

void CaptureWriter::Write(const CaptureRecord& r) {
  // buffered (no write per record: a 100 Hz link would cost a system call per message)
  if (failed_) return;
  buf_ += FormatCaptureLine(r);
  buf_ += '\n';
  if (buf_.size() >= kBufferBytes) Flush();
}

void CaptureWriter::Flush() {
  std::size_t done = 0;
  while (!failed_ && done < buf_.size()) {
    const ssize_t n = write(fd_, buf_.data() + done, buf_.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      Cut(done, n < 0 ? errno : ENOSPC);
      break;
    }
    done += static_cast<std::size_t>(n);
  }
  if (!failed_) size_ += static_cast<std::int64_t>(done);
  buf_.clear();
}

void CaptureWriter::Cut(std::size_t written, int err) {
  failed_ = true;
  if (diagnostics_) diagnostics_->NoteWriteFailure(path_);
  // keep the whole lines that reached the file, drop the part of a line after them
  const std::size_t nl = written == 0 ? std::string::npos : buf_.rfind('\n', written - 1);
  size_ += nl == std::string::npos ? 0 : static_cast<std::int64_t>(nl + 1);
  if (ftruncate(fd_, size_) != 0) return;
  const std::string mark =
      std::string("# cut: ") + std::strerror(err) + "; the records after this line are lost\n";
  const ssize_t n = pwrite(fd_, mark.data(), mark.size(), size_);
  if (n == static_cast<ssize_t>(mark.size())) {
    size_ += n;
  } else if (n > 0) {
    [[maybe_unused]] const int r = ftruncate(fd_, size_);  // a partial mark is no record either
  }
}

CaptureWriter::~CaptureWriter() {
  Flush();
  if (fd_ >= 0) close(fd_);
}

bool ParseCaptureHeaderLine(std::string_view line, CaptureHeader& hdr) {
  if (line.empty() || line.front() != '#') return false;
  std::istringstream h{std::string(line.substr(1))};
  std::string word;
  h >> word;
  if (word == "hil") {
    std::string cap, v;
    h >> cap >> v;  // "capture v2" or "capture v1:" followed by "link NAME, baud N"
    if (cap != "capture" || v.size() < 2 || v[0] != 'v') return false;
    hdr.version = v[1] - '0';
    if (hdr.version == 1) {
      std::string link_word, name, baud_word;
      h >> link_word >> name >> baud_word >> hdr.baud;
      if (!name.empty() && name.back() == ',') name.pop_back();
      hdr.link = name;
      hdr.kind = "serial";
    }
  } else if (word == "link") {
    h >> hdr.link >> hdr.kind;
    if (hdr.kind == "can")
      h >> hdr.iface;
    else
      h >> hdr.baud;
  } else if (word == "start_unix_ns") {
    std::int64_t ns = 0;
    if (h >> ns) hdr.start_utc = UnixTimeFromNs(ns);
  } else {
    return false;
  }
  return true;
}

Capture ReadCapture(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read the capture " + path);
  Capture c;
  c.header.version = 0;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    if (line.front() == '#') {
      ParseCaptureHeaderLine(line, c.header);
      continue;
    }
    if (auto r = ParseCaptureLine(line))
      c.records.push_back(std::move(*r));
    else
      ++c.unreadable_lines;
  }
  if (c.header.version == 0)
    throw std::runtime_error(path + " is not a hil capture (no '# hil capture' header)");
  return c;
}

}  // namespace hil::harness
