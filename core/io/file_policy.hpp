#pragma once
// Where the files a sandboxed scene names may be (tendril run --sandbox):
// writes inside its output folder only, reads there or beside the scene.
// The policy is set for the thread that runs the scene while it runs; every
// file tendril writes (AtomicFile) or reads as data (read_input_file), and
// the sandbox's io.open, asks it first. Without a policy every path is allowed.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace tendril {

struct FileRefused : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct FilePolicy {
  std::vector<std::filesystem::path> writable;  // folders (and what is below them)
  std::vector<std::filesystem::path> readable;  // in addition to the writable ones
};

// Installs `policy` for this thread until the guard is destroyed.
class ScopedFilePolicy {
 public:
  explicit ScopedFilePolicy(FilePolicy policy);
  ScopedFilePolicy(const ScopedFilePolicy&) = delete;
  ScopedFilePolicy& operator=(const ScopedFilePolicy&) = delete;
  ~ScopedFilePolicy();

 private:
  const FilePolicy* previous_;
  FilePolicy policy_;
};

// Throw FileRefused naming `path` and the folders allowed when the thread's
// policy does not allow it. Symbolic links and ".." are resolved first.
void check_writable(const std::string& path);
void check_readable(const std::string& path);

}  // namespace tendril
