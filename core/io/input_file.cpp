#include "io/input_file.hpp"
#include "io/file_policy.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace tendril {

std::string read_input_file(const std::string& path, std::size_t max_bytes) {
  check_readable(path);  // a sandboxed scene reads beside itself or in its output folder only
  auto refuse = [&](const std::string& why) -> InputError { return InputError("cannot read " + path + ": " + why); };
  // O_NONBLOCK: opening a FIFO without a writer must not wait for one.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw refuse(std::strerror(errno));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0) throw refuse(std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw refuse("it is a directory, not a file");
  if (!S_ISREG(st.st_mode)) throw refuse("not a regular file (a FIFO, socket or device is refused)");
  if (std::size_t(st.st_size) > max_bytes)
    throw refuse("the file has " + std::to_string(st.st_size) + " bytes, more than the limit of " +
                 std::to_string(max_bytes));
  std::string text(std::size_t(st.st_size), '\0');
  std::size_t have = 0;
  // Reads to the end, not to st_size: a file that grows while it is read is
  // taken whole up to the limit.
  for (;;) {
    if (have == text.size()) {
      if (have > max_bytes) throw refuse("the file grew beyond the limit of " + std::to_string(max_bytes) + " bytes");
      text.resize(std::min(std::max<std::size_t>(2 * have, 4096), max_bytes + 1));
    }
    const ssize_t n = ::read(fd, text.data() + have, text.size() - have);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw refuse(std::strerror(errno));
    if (n == 0) break;
    have += std::size_t(n);
  }
  text.resize(have);
  return text;
}

}  // namespace tendril
