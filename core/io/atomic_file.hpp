#pragma once
// Every file tendril writes goes through here, so that a file is written whole
// or not at all. The text goes to a temporary file beside the target (same
// folder: the rename cannot cross file systems), every write is checked, the
// file is flushed, synced and renamed over the target, and the folder synced.
// On any failure (disk full, a file size limit, a read-only folder, a signal)
// the temporary file is removed, the previous file is left exactly as it was,
// and OutputError says which path failed and why.
//
// Writers: write_file_atomically(path, text) for a text built in memory;
// AtomicFile when the output comes in pieces. Nothing is visible at `path`
// until commit() returns.
#include <stdexcept>
#include <string>
#include <string_view>

namespace tendril {

struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class AtomicFile {
 public:
  // Creates the temporary file; throws OutputError when it cannot.
  explicit AtomicFile(std::string path);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  // Removes the temporary file unless commit() succeeded.
  ~AtomicFile();

  void write(std::string_view text);
  // Flushes, syncs and renames the file into place.
  void commit();

 private:
  [[noreturn]] void fail(const std::string& what);
  void discard() noexcept;

  std::string path_, temp_;
  int fd_ = -1;
  bool temp_exists_ = false;
  long long written_ = 0;
  int slot_ = -1;  // in the list of unfinished outputs a signal removes
};

void write_file_atomically(const std::string& path, std::string_view text);

// Called from a signal handler (async-signal-safe): removes the temporary
// files of the writes in progress, so an interrupted save leaves nothing but
// the previous file behind.
void remove_unfinished_outputs() noexcept;

// Installs handlers for SIGINT, SIGTERM and SIGHUP that remove unfinished
// outputs and then die of the same signal (the exit status still says which),
// and ignores SIGXFSZ so that a file size limit is an error, not a kill.
void clean_up_outputs_on_signals();

}  // namespace tendril
