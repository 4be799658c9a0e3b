#include "io/huge_pages.hpp"

#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>

namespace tendril {

namespace {

bool contains(const char* text, const char* part) { return text && std::strstr(text, part); }

}  // namespace

void restart_with_huge_pages(char** argv) {
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if (contains(tunables, "glibc.malloc.hugetlb")) return;
  if (const char* wish = std::getenv("TENDRIL_HUGE_PAGES"); wish && std::strcmp(wish, "0") == 0) return;
  if (contains(std::getenv("LD_PRELOAD"), "vgpreload")) return;
  const std::optional<std::string> before = tunables ? std::optional<std::string>(tunables) : std::nullopt;
  const std::string value = before && !before->empty() ? *before + ":" + kMemoryTunables : kMemoryTunables;
  if (setenv("GLIBC_TUNABLES", value.c_str(), 1) != 0) return;
  execv("/proc/self/exe", argv);
  // Still here: the exec failed (no /proc, say); go on as started.
  if (before) setenv("GLIBC_TUNABLES", before->c_str(), 1);
  else unsetenv("GLIBC_TUNABLES");
}

bool started_with_huge_pages() { return contains(std::getenv("GLIBC_TUNABLES"), kMemoryTunables); }

}  // namespace tendril
