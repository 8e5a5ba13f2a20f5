#include "io/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <system_error>

namespace slamsph {

void write_file_atomically(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  auto fail = [&](int err, const std::string& what) {
    ::unlink(tmp.c_str());
    throw std::system_error(err ? err : EIO, std::generic_category(), what);
  };
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw std::system_error(errno, std::generic_category(), "cannot create " + tmp);
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int err = errno;
      ::close(fd);
      fail(err, "cannot write " + path);
    }
    done += static_cast<std::size_t>(n);
  }
  // fsync: a crash right after the rename must not leave an empty file under the name.
  if (::fsync(fd) != 0 && errno != EINVAL) {
    const int err = errno;
    ::close(fd);
    fail(err, "cannot write " + path);
  }
  if (::close(fd) != 0) fail(errno, "cannot write " + path);
  if (std::rename(tmp.c_str(), path.c_str()) != 0)
    fail(errno, "cannot rename " + tmp + " to " + path);
}

}  // namespace slamsph
