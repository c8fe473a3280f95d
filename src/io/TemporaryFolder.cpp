#include "io/TemporaryFolder.h"

#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace tabletop {
namespace {

// Made under this prefix first, locked, then renamed to its own name, so
// no folder under the own name is ever unlocked while its maker lives.
constexpr const char* kMaking = ".making-";
constexpr int kTries = 100;  // names taken by others before giving up

std::filesystem::path base() {
  std::error_code ec;
  const std::filesystem::path dir = std::filesystem::temp_directory_path(ec);
  return ec ? std::filesystem::path("/tmp") : dir;
}

// Renames `from` to `to` unless `to` exists (a file system without
// RENAME_NOREPLACE checks first, which leaves a moment's race).
bool renameNew(const std::string& from, const std::string& to) {
  if (::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0) return true;
  if (errno != EINVAL && errno != ENOSYS) return false;
  struct stat info {};
  return ::lstat(to.c_str(), &info) != 0 && errno == ENOENT && ::rename(from.c_str(), to.c_str()) == 0;
}

}  // namespace

TemporaryFolder::TemporaryFolder(const std::string& prefix) {
  const std::filesystem::path dir = base();
  for (int attempt = 0; attempt < kTries && path_.empty(); ++attempt) {
    std::string pattern = (dir / (kMaking + prefix + "XXXXXX")).string();
    if (!mkdtemp(pattern.data())) {
      throw std::runtime_error("cannot make a temporary folder in " + dir.string() + ": " + std::strerror(errno));
    }
    const int fd = ::open(pattern.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    const std::string final = (dir / (prefix + pattern.substr(pattern.size() - 6))).string();
    if (fd >= 0 && ::flock(fd, LOCK_EX | LOCK_NB) == 0 && renameNew(pattern, final)) {
      path_ = final;
      lock_ = fd;
      break;
    }
    if (fd >= 0) ::close(fd);
    ::rmdir(pattern.c_str());
  }
  if (path_.empty()) throw std::runtime_error("cannot make a temporary folder in " + dir.string());
}

TemporaryFolder::~TemporaryFolder() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
  ::close(lock_);
}

std::vector<std::string> TemporaryFolder::removeAbandoned(const std::string& prefix) {
  std::vector<std::string> removed;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(base(), ec)) {
    const std::string name = entry.path().filename().string();
    if (name.size() != prefix.size() + 6 || name.compare(0, prefix.size(), prefix) != 0) continue;
    // Only this user's own folders, not a link to one.
    struct stat info {};
    if (::lstat(entry.path().c_str(), &info) != 0 || !S_ISDIR(info.st_mode) || info.st_uid != ::geteuid()) continue;
    const int fd = ::open(entry.path().c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC | O_NOFOLLOW);
    if (fd < 0) continue;
    if (::flock(fd, LOCK_EX | LOCK_NB) == 0) {
      std::error_code gone;
      std::filesystem::remove_all(entry.path(), gone);
      if (!gone) removed.push_back(entry.path().string());
    }
    ::close(fd);
  }
  return removed;
}

}  // namespace tabletop
