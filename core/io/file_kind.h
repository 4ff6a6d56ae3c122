#pragma once
// What a file that is not a regular one is, in words for a message.
#include <sys/stat.h>

namespace gps {

/// "a directory", "a FIFO (named pipe)", … for the type bits of `mode`; "a regular file" for one.
inline const char* file_kind(mode_t mode) {
  if (S_ISREG(mode)) return "a regular file";
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISLNK(mode)) return "a symbolic link";
  return "not a regular file";
}

}  // namespace gps
