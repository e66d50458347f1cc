#include "hil/harness/run/folder_lock.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include <sys/file.h>

namespace hil::harness {
namespace {

std::string ReadLockHolder(int fd) {
  char buf[4096];
  const ssize_t n = pread(fd, buf, sizeof buf - 1, 0);
  if (n <= 0) return "";
  std::string s(buf, static_cast<std::size_t>(n));
  while (!s.empty() && (s.back() == '\n' || s.back() == '\0')) s.pop_back();
  const std::size_t space = s.find(' ');
  if (space == std::string::npos) return "pid " + s;
  return "pid " + s.substr(0, space) + ": " + s.substr(space + 1);
}

}  // namespace

std::string OwnCommandLine() {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  std::string s = ss.str();
  while (!s.empty() && s.back() == '\0') s.pop_back();
  for (char& c : s) {
    if (c == '\0' || c == '\n') c = ' ';
  }
  return s;
}

FolderLock::FolderLock(const std::string& dir, const std::string& lock_name, bool exclusive) {
  const std::string path = dir + "/" + lock_name;
  fd_ = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
  if (fd_ < 0)
    throw std::runtime_error("cannot make the lock file " + path + ": " + std::strerror(errno));
  int rc;
  while ((rc = flock(fd_, (exclusive ? LOCK_EX : LOCK_SH) | LOCK_NB)) != 0 && errno == EINTR) {
  }
  if (rc != 0) {
    const int err = errno;
    const std::string holder = ReadLockHolder(fd_);
    close(fd_);
    fd_ = -1;
    if (err != EWOULDBLOCK)
      throw std::runtime_error("cannot lock " + path + ": " + std::strerror(err));
    throw FolderBusyError(
        dir + " is in use by another hil (" +
        (holder.empty() ? std::string("a campaign shard") : holder) +
        "; a run's folder stays locked until every process it started has ended): wait for it, "
        "or give another folder");
  }
  if (!exclusive) return;
  const std::string me = std::to_string(getpid()) + " " + OwnCommandLine() + "\n";
  // the lock holds without its note if this fails; a refused taker then names no pid
  [[maybe_unused]] const bool noted =
      ftruncate(fd_, 0) == 0 && pwrite(fd_, me.data(), me.size(), 0) > 0;
}

FolderLock::~FolderLock() {
  if (fd_ >= 0) close(fd_);
}

}  // namespace hil::harness
