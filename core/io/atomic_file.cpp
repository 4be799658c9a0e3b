#include "io/atomic_file.hpp"
#include "io/file_policy.hpp"

#include <fcntl.h>
#include <pthread.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>

namespace tendril {

namespace {

// The temporary files of the writes in progress, for remove_unfinished_outputs.
// A fixed table of C strings: a signal handler may read it, not allocate.
struct Unfinished {
  std::atomic<int> state{0};  // 0 free, 1 being filled, 2 armed
  char path[4096];
};
Unfinished g_unfinished[16];

int claim_slot(const std::string& temp) {
  if (temp.size() >= sizeof(Unfinished::path)) return -1;
  for (int i = 0; i < int(std::size(g_unfinished)); ++i) {
    int free = 0;
    if (!g_unfinished[i].state.compare_exchange_strong(free, 1)) continue;
    std::memcpy(g_unfinished[i].path, temp.c_str(), temp.size() + 1);
    g_unfinished[i].state.store(2);
    return i;
  }
  return -1;  // more writes at once than slots: only the signal clean-up misses them
}

void release_slot(int slot) {
  if (slot >= 0) g_unfinished[slot].state.store(0);
}

// The mode a new file gets from open(2): 0666 less the umask, read once.
mode_t new_file_mode() {
  static const mode_t mode = [] {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    return mode_t(0666 & ~mask);
  }();
  return mode;
}

std::string folder_of(const std::string& path) {
  const std::string parent = std::filesystem::path(path).parent_path().string();
  return parent.empty() ? "." : parent;
}

// Installed with SA_RESETHAND: the raised signal kills with the default action.
void on_signal(int sig) {
  remove_unfinished_outputs();
  ::raise(sig);
}

}  // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  check_writable(path_);  // a sandboxed scene writes in its output folder only
  // Writing through a symbolic link replaces the file it points to, not the link.
  std::error_code ec;
  if (std::filesystem::is_symlink(path_, ec)) {
    const auto target = std::filesystem::weakly_canonical(path_, ec);
    if (!ec) path_ = target.string();
  }
  struct stat old {};
  const bool exists = ::stat(path_.c_str(), &old) == 0;
  if (exists && S_ISDIR(old.st_mode)) throw OutputError("cannot write " + path_ + ": it is a directory");
  const std::string name = std::filesystem::path(path_).filename().string();
  temp_ = folder_of(path_) + "/." + name + ".tmp-XXXXXX";
  // The signals that clean up are held until the new file is in the table,
  // so that none arrives between its creation and its registration.
  sigset_t cleaning, before;
  sigemptyset(&cleaning);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&cleaning, sig);
  pthread_sigmask(SIG_BLOCK, &cleaning, &before);
  fd_ = ::mkostemp(temp_.data(), O_CLOEXEC);
  const int error = errno;
  if (fd_ >= 0) slot_ = claim_slot(temp_);
  pthread_sigmask(SIG_SETMASK, &before, nullptr);
  if (fd_ < 0) {
    const std::string reason = std::strerror(error);
    throw OutputError("cannot write " + path_ + ": cannot create a file in " + folder_of(path_) + ": " + reason);
  }
  temp_exists_ = true;
  if (::fchmod(fd_, exists ? (old.st_mode & 07777) : new_file_mode()) != 0) fail("cannot set its permissions");
}

AtomicFile::~AtomicFile() { discard(); }

void AtomicFile::discard() noexcept {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  if (temp_exists_) ::unlink(temp_.c_str());
  temp_exists_ = false;
  release_slot(slot_);
  slot_ = -1;
}

void AtomicFile::fail(const std::string& what) {
  const std::string reason = std::strerror(errno);
  discard();
  throw OutputError("cannot write " + path_ + ": " + what + ": " + reason + " (the previous file, if any, is unchanged)");
}

void AtomicFile::write(std::string_view text) {
  if (fd_ < 0) throw OutputError("cannot write " + path_ + ": the file is already closed");
  while (!text.empty()) {
    const ssize_t n = ::write(fd_, text.data(), text.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n == 0) errno = EIO;
      fail("writing failed after " + std::to_string(written_) + " bytes");
    }
    written_ += n;
    text.remove_prefix(std::size_t(n));
  }
}

void AtomicFile::commit() {
  if (fd_ < 0) throw OutputError("cannot write " + path_ + ": the file is already closed");
  struct stat st {};
  if (::fstat(fd_, &st) != 0) fail("cannot check the written file");
  if (st.st_size != written_) {
    errno = EIO;
    fail("the file holds " + std::to_string(st.st_size) + " of " + std::to_string(written_) + " bytes");
  }
  if (::fsync(fd_) != 0) fail("syncing failed");
  const int fd = fd_;
  fd_ = -1;  // closed once, whatever close returns
  if (::close(fd) != 0) fail("closing failed");
  if (::rename(temp_.c_str(), path_.c_str()) != 0) fail("cannot move the new file into place");
  temp_exists_ = false;
  discard();
  // The rename itself lasts only once the folder is synced (not every file system can).
  const int dir = ::open(folder_of(path_).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
}

void write_file_atomically(const std::string& path, std::string_view text) {
  AtomicFile file(path);
  file.write(text);
  file.commit();
}

void remove_unfinished_outputs() noexcept {
  for (Unfinished& u : g_unfinished)
    if (u.state.load() == 2) ::unlink(u.path);
}

void clean_up_outputs_on_signals() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  action.sa_flags = SA_RESETHAND;
  sigemptyset(&action.sa_mask);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction old {};
    // A signal the caller chose to ignore (nohup, a background job) stays ignored.
    if (::sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
    ::sigaction(sig, &action, nullptr);
  }
  std::signal(SIGXFSZ, SIG_IGN);
}

}  // namespace tendril
