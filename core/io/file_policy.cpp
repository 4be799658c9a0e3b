#include "io/file_policy.hpp"

namespace tendril {

namespace {

thread_local const FilePolicy* t_policy = nullptr;

namespace fs = std::filesystem;

// The path with every symbolic link and ".." that exists resolved.
fs::path resolved(const fs::path& p) {
  std::error_code ec;
  fs::path r = fs::weakly_canonical(fs::absolute(p, ec), ec);
  return ec ? fs::absolute(p).lexically_normal() : r;
}

bool inside(const fs::path& path, const fs::path& folder) {
  const fs::path f = resolved(folder);
  auto [fe, pe] = std::mismatch(f.begin(), f.end(), path.begin(), path.end());
  return fe == f.end();
}

void check(const std::string& path, bool writing) {
  if (!t_policy) return;
  const fs::path p = resolved(path);
  for (const fs::path& f : t_policy->writable)
    if (inside(p, f)) return;
  if (!writing)
    for (const fs::path& f : t_policy->readable)
      if (inside(p, f)) return;
  std::string allowed;
  for (const fs::path& f : t_policy->writable) allowed += (allowed.empty() ? "" : ", ") + resolved(f).string();
  if (!writing)
    for (const fs::path& f : t_policy->readable) allowed += ", " + resolved(f).string();
  throw FileRefused(std::string("--sandbox: ") + (writing ? "writing " : "reading ") + path + " is refused; a sandboxed scene " +
                    (writing ? "writes only in " : "reads only in ") + allowed + " (tendril.out(name))");
}

}  // namespace

ScopedFilePolicy::ScopedFilePolicy(FilePolicy policy) : previous_(t_policy), policy_(std::move(policy)) {
  t_policy = &policy_;
}

ScopedFilePolicy::~ScopedFilePolicy() { t_policy = previous_; }

void check_writable(const std::string& path) { check(path, true); }
void check_readable(const std::string& path) { check(path, false); }

}  // namespace tendril
