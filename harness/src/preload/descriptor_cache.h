#pragma once
// The preload library's per-process cache of which of hil's links a descriptor is (README.md,
// "Descriptor cache"): a wait that blocks tells its descriptors apart by their terminal device
// (st_rdev), one fstat each; the cache keeps each answer until the descriptor's number is closed
// or replaced through one of the interposed calls (close, dup2, dup3, close_range, closefrom,
// fclose, freopen, pclose, fcloseall, closedir, daemon), so a descriptor is looked up once per
// opening instead of once per wait. No allocation, no lock: a generation per descriptor number,
// bumped before and after each close or replacement, makes an answer found by a lookup that
// raced with one of them count for nothing.

namespace hil::preload {

/// Descriptors below this are cached (our choice: 1024, FD_SETSIZE and the usual soft limit of
/// open files; 16 KB of table). A higher one is looked up at every wait, as without the cache.
inline constexpr int kCachedDescriptors = 1024;

/// The index of `fd`'s link in Shared::link_rdev, or -1 for any other descriptor (one that is
/// not a terminal of hil's, or cannot be looked at). From the cache, else one fstat (counted in
/// Shared::descriptor_lookups) whose answer is kept; nothing is kept before hil has published its
/// links or when the fstat failed (a closed number is opened again by calls the library does not
/// see). `HIL_LOCKSTEP_FD_CACHE=0` in the environment turns the cache off (every lookup an fstat).
int LinkIndexOf(int fd);
/// Descriptor `fd` is being closed or replaced: what the cache knows of its number is dropped.
/// Called before and after the real call.
void ForgetLink(int fd);
/// The same for the numbers `first` to `last` (both included).
void ForgetLinks(unsigned first, unsigned last);

}  // namespace hil::preload
