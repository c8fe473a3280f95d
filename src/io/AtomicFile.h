#pragma once

#include <string>

namespace tabletop {

/// A file written under a temporary name beside its destination
/// ("NAME.part", so on the same file system) and renamed into place only
/// once it is complete. rename() is atomic: whatever stops the writer (an
/// error, a full disk, Ctrl-C, a kill) the destination holds either its
/// previous content or the complete new one. Every file tabletop writes
/// (results, frames, videos, plots, tables) goes through here.
class AtomicFile {
 public:
  explicit AtomicFile(std::string path);
  /// Removes the temporary file unless it was committed.
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  const std::string& path() const { return path_; }
  /// Where the writer writes.
  const std::string& temporaryPath() const { return temporary_; }
  /// Renames the temporary into place; "" or what went wrong (then the
  /// temporary is removed and the destination untouched).
  std::string commit();

  /// Writes `content` to `path` this way; "" or what went wrong.
  static std::string write(const std::string& path, const std::string& content);

 private:
  std::string path_;
  std::string temporary_;
  bool committed_ = false;
};

}  // namespace tabletop
