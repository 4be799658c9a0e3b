#include <doctest/doctest.h>

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/atomic_file.hpp"
#include "io/input_file.hpp"

using namespace tendril;
namespace fs = std::filesystem;

namespace {

// A fresh, empty folder per test case.
fs::path fresh_folder(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("tendril_test_atomic_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string contents(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t entries(const fs::path& dir) {
  return std::size_t(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

mode_t mode_of(const fs::path& p) {
  struct stat st {};
  REQUIRE(::stat(p.c_str(), &st) == 0);
  return st.st_mode & 07777;
}

}  // namespace

TEST_CASE("atomic file: written whole, replaces the old file, keeps its mode, leaves nothing behind") {
  const fs::path dir = fresh_folder("whole");
  const fs::path path = dir / "a.txt";
  write_file_atomically(path.string(), "first\n");
  CHECK(contents(path) == "first\n");
  const mode_t mask = ::umask(0);
  ::umask(mask);
  CHECK(mode_of(path) == (0666 & ~mask));  // as open(2) would have made it, not mkstemp's 0600

  ::chmod(path.c_str(), 0640);
  write_file_atomically(path.string(), std::string(100000, 'x'));
  CHECK(contents(path) == std::string(100000, 'x'));
  CHECK(mode_of(path) == 0640);
  CHECK(entries(dir) == 1);  // no temporary file left

  // Pieces: nothing visible until commit.
  {
    AtomicFile f(path.string());
    f.write("new ");
    f.write("text");
    CHECK(contents(path) == std::string(100000, 'x'));
    f.commit();
  }
  CHECK(contents(path) == "new text");
  CHECK(entries(dir) == 1);

  // Abandoned before commit (an exception in the writer): the old file stays.
  {
    AtomicFile f(path.string());
    f.write("half");
  }
  CHECK(contents(path) == "new text");
  CHECK(entries(dir) == 1);
}

TEST_CASE("atomic file: a symbolic link keeps pointing at the rewritten file") {
  const fs::path dir = fresh_folder("link");
  write_file_atomically((dir / "real.txt").string(), "old");
  fs::create_symlink("real.txt", dir / "link.txt");
  write_file_atomically((dir / "link.txt").string(), "new");
  CHECK(fs::is_symlink(dir / "link.txt"));
  CHECK(contents(dir / "real.txt") == "new");
}

TEST_CASE("atomic file: failures name the path and leave the old file intact") {
  const fs::path dir = fresh_folder("fail");
  CHECK_THROWS_WITH_AS(write_file_atomically((dir / "missing" / "x.txt").string(), "x"),
                       doctest::Contains("missing/x.txt: cannot create a file in"), OutputError);
  fs::create_directories(dir / "sub");
  CHECK_THROWS_WITH_AS(write_file_atomically((dir / "sub").string(), "x"), doctest::Contains("it is a directory"),
                       OutputError);

  // A file size limit (ulimit -f) stands in for a full disk: the write fails
  // part-way, the error says so, the previous file is intact and no temporary
  // file remains. (tests/faults/ also fills a real small tmpfs.)
  const fs::path path = dir / "model.xml";
  write_file_atomically(path.string(), "the good model");
  rlimit old {};
  REQUIRE(::getrlimit(RLIMIT_FSIZE, &old) == 0);
  const auto previous_handler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit small = old;
  small.rlim_cur = 4096;
  REQUIRE(::setrlimit(RLIMIT_FSIZE, &small) == 0);
  std::string message;
  try {
    write_file_atomically(path.string(), std::string(20000, 'y'));
  } catch (const OutputError& e) {
    message = e.what();
  }
  ::setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, previous_handler);
  CHECK(message.find("model.xml: writing failed after 4096 bytes: File too large") != std::string::npos);
  CHECK(message.find("the previous file, if any, is unchanged") != std::string::npos);
  CHECK(contents(path) == "the good model");
  CHECK(entries(dir) == 2);  // model.xml and sub/
}

TEST_CASE("atomic file: a signal's clean-up removes the temporary files of unfinished writes") {
  const fs::path dir = fresh_folder("signal");
  write_file_atomically((dir / "j.txt").string(), "old");
  AtomicFile f((dir / "j.txt").string());
  f.write("unfinished");
  CHECK(entries(dir) == 2);
  remove_unfinished_outputs();
  CHECK(entries(dir) == 1);
  CHECK(contents(dir / "j.txt") == "old");
}

TEST_CASE("input file: regular files only, up to a size") {
  const fs::path dir = fresh_folder("input");
  write_file_atomically((dir / "m.xml").string(), "0123456789");
  CHECK(read_input_file((dir / "m.xml").string()) == "0123456789");
  CHECK_THROWS_WITH_AS(read_input_file((dir / "m.xml").string(), 9), doctest::Contains("more than the limit of 9"),
                       InputError);
  CHECK_THROWS_WITH_AS(read_input_file(dir.string()), doctest::Contains("it is a directory"), InputError);
  CHECK_THROWS_WITH_AS(read_input_file("/dev/zero"), doctest::Contains("not a regular file"), InputError);
  // A FIFO without a writer: refused at once, not waited on.
  REQUIRE(::mkfifo((dir / "fifo").c_str(), 0600) == 0);
  CHECK_THROWS_WITH_AS(read_input_file((dir / "fifo").string()), doctest::Contains("not a regular file"), InputError);
  CHECK_THROWS_WITH_AS(read_input_file((dir / "none").string()), doctest::Contains("No such file"), InputError);
}
