// Calls that can meet another program's wait without a write the kernel counts in the process's
// /proc/self/io `syscw` (README.md): shutdown (the reader sees its end), send, sendto and sendmsg
// on a socket (close and the other closes: interposed_closes.cc). Each is the real call; the thread
// notes that it touched something, so that when it next waits the other programs' threads look at
// their descriptors again.
#include <sys/socket.h>

#include "preload_state.h"

namespace pl = hil::preload;

extern "C" {

int shutdown(int fd, int how) {
  pl::NoteTouched();
  return pl::Real().shutdown(fd, how);
}

ssize_t send(int fd, const void* buf, size_t n, int flags) {
  pl::NoteTouched();
  return pl::Real().send(fd, buf, n, flags);
}

ssize_t sendto(int fd, const void* buf, size_t n, int flags, const sockaddr* to, socklen_t len) {
  pl::NoteTouched();
  return pl::Real().sendto(fd, buf, n, flags, to, len);
}

ssize_t sendmsg(int fd, const msghdr* msg, int flags) {
  pl::NoteTouched();
  return pl::Real().sendmsg(fd, msg, flags);
}

}  // extern "C"
