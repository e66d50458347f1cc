#pragma once
/// @file
/// One hil at a time in a run or campaign folder (issue 40.3: two runs into one --out read each
/// other's ptys; two `campaign --local` into one folder ran everything twice). The folder's lock
/// file (flock, so the kernel releases it when its last holder ends, however) holds the pid and
/// command line of who took it; a second taker is refused with both named.

#include <stdexcept>
#include <string>

namespace hil::harness {

/// The folder is locked by another process (bad input: exit 2).
class FolderBusyError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class FolderLock {
 public:
  /// Locks `dir`/`lock_name` (created). Exclusive: alone in the folder, and writes this process's
  /// pid and command line into the file; shared: beside other shared holders only.
  /// @throws FolderBusyError naming the holder; std::runtime_error when the file cannot be made.
  FolderLock(const std::string& dir, const std::string& lock_name, bool exclusive = true);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;
  /// The lock file's descriptor: a process that keeps a copy keeps the lock (group_reaper.h).
  int fd() const { return fd_; }

 private:
  int fd_ = -1;
};

/// This process's command line, its arguments separated by spaces ("" when /proc cannot tell).
std::string OwnCommandLine();

/// The name of a run folder's lock file, and of a campaign folder's.
inline constexpr const char* kRunLockName = ".hil-run.lock";
inline constexpr const char* kCampaignLockName = ".hil-campaign.lock";

}  // namespace hil::harness
