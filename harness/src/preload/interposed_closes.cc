// Calls that close or replace a descriptor (README.md, "Descriptor cache"): close, dup2, dup3,
// close_range, closefrom, fclose, freopen, freopen64, pclose, fcloseall, closedir and daemon.
// Each is the real call, with the descriptor cache's entries of the numbers it closes dropped
// before and after it (descriptor_cache.h), and the thread noting that it touched something:
// a reader of what it closed sees an end, so when this thread next waits the other programs'
// threads look at their descriptors again (as after a write).
#include <dirent.h>
#include <stdio.h>
#include <unistd.h>

#include <climits>

#include <sys/syscall.h>

#include "descriptor_cache.h"
#include "preload_state.h"

namespace {

namespace pl = hil::preload;

// Before and after the real call that closes or replaces `fd`.
void Closing(int fd) {
  pl::NoteTouched();
  pl::ForgetLink(fd);
  pl::ForgetDescriptor(fd);
}

void ClosingRange(unsigned first, unsigned last) {
  pl::NoteTouched();
  pl::ForgetLinks(first, last);
  pl::ForgetDescriptors(first, last);
}

int FilenoOf(FILE* f) { return f ? fileno(f) : -1; }

}  // namespace

extern "C" {

int close(int fd) {
  Closing(fd);
  const int r = pl::Real().close(fd);
  pl::ForgetLink(fd);
  return r;
}

int dup2(int old_fd, int new_fd) {
  Closing(new_fd);
  const int r = pl::Real().dup2(old_fd, new_fd);
  pl::ForgetLink(new_fd);
  return r;
}

int dup3(int old_fd, int new_fd, int flags) {
  Closing(new_fd);
  const int r = pl::Real().dup3(old_fd, new_fd, flags);
  pl::ForgetLink(new_fd);
  return r;
}

int close_range(unsigned first, unsigned last, int flags) {
  ClosingRange(first, last);
  const int r = pl::Real().close_range
                    ? pl::Real().close_range(first, last, flags)
                    : static_cast<int>(syscall(SYS_close_range, first, last, flags));
  pl::ForgetLinks(first, last);
  return r;
}

void closefrom(int first) {
  const unsigned from = first < 0 ? 0u : static_cast<unsigned>(first);
  ClosingRange(from, UINT_MAX);
  if (pl::Real().closefrom) {
    pl::Real().closefrom(first);
  } else {
    syscall(SYS_close_range, from, UINT_MAX, 0);
  }
  pl::ForgetLinks(from, UINT_MAX);
}

int fclose(FILE* f) {
  const int fd = FilenoOf(f);
  Closing(fd);
  const int r = pl::Real().fclose(f);
  pl::ForgetLink(fd);
  return r;
}

FILE* freopen(const char* path, const char* mode, FILE* f) {
  const int fd = FilenoOf(f);
  Closing(fd);
  FILE* r = pl::Real().freopen(path, mode, f);
  pl::ForgetLink(fd);
  return r;
}

FILE* freopen64(const char* path, const char* mode, FILE* f) {
  const int fd = FilenoOf(f);
  Closing(fd);
  FILE* r = pl::Real().freopen64(path, mode, f);
  pl::ForgetLink(fd);
  return r;
}

int pclose(FILE* f) {
  const int fd = FilenoOf(f);
  Closing(fd);
  const int r = pl::Real().pclose(f);
  pl::ForgetLink(fd);
  return r;
}

int fcloseall() {
  ClosingRange(0, UINT_MAX);
  const int r = pl::Real().fcloseall();
  pl::ForgetLinks(0, UINT_MAX);
  return r;
}

int closedir(DIR* d) {
  const int fd = dirfd(d);
  Closing(fd);
  const int r = pl::Real().closedir(d);
  pl::ForgetLink(fd);
  return r;
}

// the child it leaves running has /dev/null on descriptors 0 to 2 (unless `noclose`)
int daemon(int nochdir, int noclose) {
  ClosingRange(0, 2);
  const int r = pl::Real().daemon(nochdir, noclose);
  pl::ForgetLinks(0, 2);
  return r;
}

}  // extern "C"
