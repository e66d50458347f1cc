#include "navd_pty_runner.h"

#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <termios.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <thread>

#include <sys/wait.h>

namespace hil::estimator::testing {
namespace {

namespace fs = std::filesystem;

bool HasOpen(pid_t pid, const std::string& path) {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator("/proc/" + std::to_string(pid) + "/fd", ec)) {
    if (fs::read_symlink(e.path(), ec) == path) return true;
  }
  return false;
}

void WaitUntilIdle(const std::string& out) {
  std::uintmax_t size = 0;
  for (int idle_ms = 0, waited_ms = 0; idle_ms < 1000 && waited_ms < 30000; waited_ms += 50) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    std::error_code ec;
    const std::uintmax_t now = fs::file_size(out, ec);
    idle_ms = (!ec && now == size) ? idle_ms + 50 : 0;
    if (!ec) size = now;
  }
}

}  // namespace

NavdRun RunNavdOnPty(const std::string& bytes, const std::string& protocol) {
  const char* bin = std::getenv("HIL_BIN_DIR");
  if (bin == nullptr) throw std::runtime_error("HIL_BIN_DIR is not set");
  const int far = posix_openpt(O_RDWR | O_NOCTTY);
  if (far < 0 || grantpt(far) != 0 || unlockpt(far) != 0) throw std::runtime_error("no pty");
  const std::string near = ptsname(far);
  // hold the near end open and raw, so that the pty neither hangs up nor edits the bytes
  const int hold = open(near.c_str(), O_RDWR | O_NOCTTY);
  termios tio{};
  tcgetattr(hold, &tio);
  cfmakeraw(&tio);
  tcsetattr(hold, TCSANOW, &tio);
  const fs::path dir = fs::temp_directory_path() / ("navd_gpsd_" + std::to_string(getpid()) + "_" +
                                                    protocol + std::to_string(far));
  fs::create_directories(dir);
  const std::string conf = dir / "navd.conf", out = dir / "out.jsonl";
  std::ofstream(conf) << "[input]\ngnss_device = " << near << "\ngnss_protocol = " << protocol
                      << "\ngnss_baud = 9600\nimu_device =\n[filter]\nmode = gnss_only\n[output]\n"
                      << "json = " << out << "\n";
  const pid_t pid = fork();
  if (pid == 0) {
    execl((std::string(bin) + "/navd").c_str(), "navd", "--config", conf.c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  for (int i = 0; i < 200 && !HasOpen(pid, near); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(25));
  for (std::size_t i = 0; i < bytes.size(); i += 256) {
    const std::size_t n = std::min<std::size_t>(256, bytes.size() - i);
    if (write(far, bytes.data() + i, n) != static_cast<ssize_t>(n)) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  WaitUntilIdle(out);
  kill(pid, SIGTERM);
  int status = 0;
  waitpid(pid, &status, 0);
  close(hold);
  close(far);
  NavdRun r;
  r.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(out);
  for (std::string line; std::getline(in, line);) r.json_lines.push_back(line);
  fs::remove_all(dir);
  return r;
}

}  // namespace hil::estimator::testing
