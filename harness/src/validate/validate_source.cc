// Reading what `hil validate` checks: hil captures, raw logs, live serial devices.
#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <sys/stat.h>

#include "hil/firmware_emu/link/pty_port.h"
#include "hil/firmware_emu/wall_time.h"
#include "hil/harness/links/capture_format.h"
#include "hil/harness/validate/validate.h"

namespace hil::harness {
namespace {

// The device's bytes of a hil capture (any version, see capture_format.h), with emulated times
// and the line rate of its header.
ByteStream ByteStreamOfCapture(const std::string& text, const std::string& source) {
  ByteStream s;
  std::istringstream in(text);
  std::string line;
  std::size_t line_no = 0;
  CaptureHeader header;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty()) continue;
    if (line[0] == '#') {
      ParseCaptureHeaderLine(line, header);
      continue;
    }
    const auto rec = ParseCaptureLine(line);
    if (!rec)
      throw std::runtime_error(source + ":" + std::to_string(line_no) + ": not a capture line");
    if (rec->dir != CaptureDir::kTx)
      continue;  // host bytes, drops and frames are not the device's stream
    for (std::size_t i = 0; i < rec->bytes.size(); ++i) {
      s.bytes.push_back(rec->bytes[i]);
      s.t_ns.push_back(ToNs(rec->t_byte(i)));
    }
  }
  if (header.kind == "serial") s.line_baud = header.baud;
  s.description = "hil capture v" + std::to_string(header.version) + " (link " + header.link +
                  ", " + header.kind +
                  (header.kind == "serial" ? ", " + std::to_string(header.baud) + " baud" : "") +
                  "), device bytes";
  return s;
}

ByteStream ListenSerial(const std::string& source, double listen_s, int baud) {
  const int fd = open(source.c_str(), O_RDONLY | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw std::runtime_error("cannot open " + source + ": " + std::strerror(errno));
  termios tio{};
  if (tcgetattr(fd, &tio) == 0) {
    cfmakeraw(&tio);
    if (const unsigned b = link::BaudToSpeed(baud); b != 0) cfsetspeed(&tio, b);
    tcsetattr(fd, TCSANOW, &tio);
  }
  ByteStream s;
  const WallTime t0 = WallNow();
  const WallTime end = t0 + DurationFromSeconds(listen_s);
  char buf[1024];
  for (WallTime now = t0; now < end; now = WallNow()) {
    pollfd p{fd, POLLIN, 0};
    if (poll(&p, 1, static_cast<int>(std::max<std::int64_t>(1, (end - now).count() / 1000000))) <=
        0)
      continue;
    const ssize_t n = read(fd, buf, sizeof buf);
    if (n <= 0) continue;
    const Duration t = WallNow() - t0;
    for (ssize_t i = 0; i < n; ++i) {
      s.bytes.push_back(buf[i]);
      s.t_ns.push_back(t.count());
    }
  }
  close(fd);
  s.description = "serial device listened to for " + std::to_string(listen_s) + " s at " +
                  std::to_string(baud) + " baud";
  return s;
}

}  // namespace

ByteStream ReadByteSource(const std::string& source, double listen_s, int baud) {
  struct stat st {};
  if (stat(source.c_str(), &st) != 0)
    throw std::runtime_error("cannot read " + source + ": " + std::strerror(errno));
  if (S_ISCHR(st.st_mode)) return ListenSerial(source, listen_s, baud);
  if (S_ISDIR(st.st_mode))
    throw std::runtime_error(source + ": is a folder, not a capture, a log or a serial device");
  std::ifstream in(source, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + source);
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  if (text.rfind("# hil capture v", 0) == 0) return ByteStreamOfCapture(text, source);
  // a raw log: drop the leading comment block (gpsd logs carry their metadata there)
  std::size_t pos = 0;
  while (pos < text.size() && text[pos] == '#') {
    const std::size_t nl = text.find('\n', pos);
    pos = nl == std::string::npos ? text.size() : nl + 1;
  }
  ByteStream s;
  s.bytes = text.substr(pos);
  s.description = "raw byte log";
  return s;
}

}  // namespace hil::harness
