#include "hil/truth/spill_bytes.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

namespace hil::truth {

void SpillBytes::Fail(const char* what) const {
  throw std::runtime_error(std::string(owner_) + "'s temporary file: " + what + ": " +
                           std::strerror(errno));
}

SpillBytes::~SpillBytes() {
  if (fd_ >= 0) ::close(fd_);
}

SpillBytes::SpillBytes(SpillBytes&& other) noexcept
    : item_bytes_(other.item_bytes_), owner_(other.owner_), fd_(other.fd_) {
  other.fd_ = -1;
}

void SpillBytes::Write(std::size_t first, const void* data, std::size_t n) {
  if (n == 0) return;
  if (fd_ < 0) {
    std::FILE* f = std::tmpfile();  // unlinked at once: gone with the process
    if (!f) Fail("create");
    fd_ = ::dup(fileno(f));
    std::fclose(f);
    if (fd_ < 0) Fail("create");
  }
  const std::size_t bytes = n * item_bytes_;
  const auto offset = static_cast<off_t>(first * item_bytes_);
  if (::pwrite(fd_, data, bytes, offset) != static_cast<ssize_t>(bytes)) Fail("write");
}

void SpillBytes::Read(std::size_t first, void* data, std::size_t n) const {
  if (n == 0) return;
  const std::size_t bytes = n * item_bytes_;
  const auto offset = static_cast<off_t>(first * item_bytes_);
  if (fd_ < 0 || ::pread(fd_, data, bytes, offset) != static_cast<ssize_t>(bytes)) Fail("read");
}

}  // namespace hil::truth
