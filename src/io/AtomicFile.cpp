#include "io/AtomicFile.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include "core/Text.h"

namespace tabletop {
namespace {

// The file a write to `path` really replaces: `path` itself, or the
// regular file a link there names; "" with `why` set when that is not a
// regular file.
std::string resolve(const std::string& path, std::string& why) {
  // A name with a control character or another unprintable one (a line
  // break, an escape, a direction mark) would show as other text in every
  // message and listing, and may reach gnuplot or ffmpeg: refused.
  if (const auto unprintable = unprintableProblem(path)) {
    why = "'" + shownText(path, 256) + "': expected a printable file name, got " + *unprintable;
    return "";
  }
  struct stat info {};
  if (::lstat(path.c_str(), &info) != 0) return path;  // a new file
  if (S_ISLNK(info.st_mode)) {
    std::error_code ec;
    const std::filesystem::path target = std::filesystem::canonical(path, ec);
    if (ec) {
      why = path + ": is a link to nothing that can be written";
      return "";
    }
    if (::stat(target.c_str(), &info) != 0 || !S_ISREG(info.st_mode)) {
      why = path + ": is a link to something other than a regular file; refused";
      return "";
    }
    return target.string();
  }
  if (!S_ISREG(info.st_mode)) {
    why = path + (S_ISDIR(info.st_mode) ? ": is a directory; expected a file name" : ": is not a regular file; refused");
    return "";
  }
  return path;
}

}  // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  target_ = resolve(path_, problem_);
  if (!problem_.empty()) return;
  std::vector<char> name(target_.begin(), target_.end());
  const std::string pattern = ".XXXXXX.part";
  name.insert(name.end(), pattern.begin(), pattern.end());
  name.push_back('\0');
  // mkstemps makes the file new (O_EXCL), readable by its owner only.
  const int fd = ::mkstemps(name.data(), 5);
  if (fd < 0) {
    problem_ = path_ + ": cannot write beside it: " + std::strerror(errno);
    return;
  }
  ::fchmod(fd, 0644);
  ::close(fd);
  temporary_ = name.data();
}

AtomicFile::~AtomicFile() {
  if (!committed_ && !temporary_.empty()) std::remove(temporary_.c_str());
}

std::string AtomicFile::commit() {
  if (!problem_.empty()) return problem_;
  // What is there now may have changed since the start (a device put in
  // its place): check again just before replacing it.
  std::string why;
  if (resolve(path_, why) != target_) {
    return why.empty() ? path_ + ": changed while it was written; not replaced" : why;
  }
  std::error_code ec;
  if (!std::filesystem::is_regular_file(temporary_, ec)) return path_ + ": nothing was written";
  std::filesystem::rename(temporary_, target_, ec);
  if (ec) return path_ + ": cannot rename into place: " + ec.message();
  committed_ = true;
  return "";
}

std::string AtomicFile::destinationProblem(const std::string& path) {
  std::string why;
  resolve(path, why);
  return why;
}

bool AtomicFile::sameFile(const std::string& a, const std::string& b) {
  // Two names of one existing file (a link, a hard link, "./F", "d/../F")
  // have one device and inode; names of files not made yet are compared
  // as absolute paths with the links of their folders followed.
  struct stat one {}, two {};
  if (::stat(a.c_str(), &one) == 0 && ::stat(b.c_str(), &two) == 0) {
    return one.st_dev == two.st_dev && one.st_ino == two.st_ino;
  }
  std::error_code ec1, ec2;
  const auto pa = std::filesystem::weakly_canonical(std::filesystem::absolute(a, ec1), ec1);
  const auto pb = std::filesystem::weakly_canonical(std::filesystem::absolute(b, ec2), ec2);
  return !ec1 && !ec2 && pa == pb;
}

std::string AtomicFile::write(const std::string& path, const std::string& content) {
  AtomicFile file(path);
  if (!file.problem().empty()) return file.problem();
  {
    std::ofstream out(file.temporaryPath(), std::ios::binary | std::ios::trunc);
    if (!out) return path + ": cannot open for writing";
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.close();
    if (!out) return path + ": cannot write (is the disk full?)";
  }
  return file.commit();
}

}  // namespace tabletop
