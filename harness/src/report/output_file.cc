#include "hil/harness/report/output_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <utility>

namespace hil::harness {
namespace {

// Writes all of `text` to `fd`; the errno of the first failure (0 when all went out).
int WriteAll(int fd, std::string_view text) {
  while (!text.empty()) {
    const ssize_t n = write(fd, text.data(), text.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return n < 0 ? errno : ENOSPC;
    text.remove_prefix(static_cast<std::size_t>(n));
  }
  return 0;
}

}  // namespace

std::string WriteFailureText(const std::string& path, int err) {
  return "cannot write " + path + ": " + std::strerror(err);
}

void WriteOutputFile(const std::string& path, std::string_view text) {
  const std::string tmp = path + ".tmp";
  const int fd = open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw OutputWriteError(WriteFailureText(path, errno));
  int err = WriteAll(fd, text);
  // the data on the disk before the rename: a delayed failure (EIO, a full disk seen late) shows
  // here, and a crash right after the rename leaves the new file, not an empty one
  if (err == 0 && fdatasync(fd) != 0) err = errno;
  if (close(fd) != 0 && err == 0) err = errno;
  if (err == 0 && std::rename(tmp.c_str(), path.c_str()) != 0) err = errno;
  if (err != 0) {
    unlink(tmp.c_str());
    throw OutputWriteError(WriteFailureText(path, err));
  }
}

OutputFile::OutputFile(std::string path) : path_(std::move(path)), tmp_(path_ + ".tmp") {
  fd_ = open(tmp_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) throw OutputWriteError(WriteFailureText(path_, errno));
  text_.reserve(kChunkBytes + kChunkBytes / 4);
}

OutputFile::~OutputFile() {
  if (fd_ < 0) return;
  close(fd_);
  unlink(tmp_.c_str());
}

void OutputFile::WriteOut() {
  const int err = WriteAll(fd_, text_);
  text_.clear();
  if (err != 0) throw OutputWriteError(WriteFailureText(path_, err));
}

void OutputFile::Pass() {
  if (text_.size() >= kChunkBytes) WriteOut();
}

void OutputFile::Commit() {
  WriteOut();
  int err = fdatasync(fd_) != 0 ? errno : 0;
  if (close(fd_) != 0 && err == 0) err = errno;
  fd_ = -1;
  if (err == 0 && std::rename(tmp_.c_str(), path_.c_str()) != 0) err = errno;
  if (err != 0) {
    unlink(tmp_.c_str());
    throw OutputWriteError(WriteFailureText(path_, err));
  }
}

}  // namespace hil::harness
