#include "core/io/text_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/io/file_kind.h"
#include "core/support/quoted_text.h"
#include "core/support/error.h"

namespace gps {
namespace {

// Closes the descriptor however the read ends.
struct FileDescriptor {
  int fd;
  ~FileDescriptor() {
    if (fd >= 0) ::close(fd);
  }
};

// Reads up to `count` bytes into `out`, fewer only at the end of the file.
size_t read_fully(int fd, char* out, size_t count, const std::string& name) {
  size_t done = 0;
  while (done < count) {
    const ssize_t n = ::read(fd, out + done, count - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw Error(name + ": cannot read (" + std::strerror(errno) + ")");
    if (n == 0) break;
    done += size_t(n);
  }
  return done;
}

}  // namespace

std::string read_text_file(const std::string& path, const HeadCheck& check_head) {
  const std::string name = escaped(path);
  // Non-blocking: opening a FIFO without a writer returns at once, and fstat then refuses it.
  const FileDescriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0) {
    if (errno == ENOENT) throw Error(name + ": no such file");
    if (errno == ELOOP) throw Error(name + ": a loop of symbolic links");
    throw Error(name + ": cannot open (" + std::strerror(errno) + ")");
  }
  struct stat status {};
  if (::fstat(file.fd, &status) != 0) throw Error(name + ": cannot read (" + std::strerror(errno) + ")");
  if (!S_ISREG(status.st_mode)) throw Error(name + ": is " + std::string(file_kind(status.st_mode)) + ", not a file");
  const size_t size = size_t(status.st_size);
  std::string data(std::min(size, kHeadBytes), '\0');
  data.resize(read_fully(file.fd, data.data(), data.size(), name));
  if (check_head) {
    try {
      check_head(data, size);
    } catch (const Error& e) {
      throw Error(name + ": " + e.what(), e.kind());
    }
  }
  if (data.size() < size && data.size() == kHeadBytes) {
    data.resize(size);
    data.resize(kHeadBytes + read_fully(file.fd, data.data() + kHeadBytes, size - kHeadBytes, name));
  }
  return data;
}

void drop_byte_order_mark(std::string& text) {
  if (text.starts_with(kUtf8ByteOrderMark)) text.erase(0, kUtf8ByteOrderMark.size());
}

}  // namespace gps
