#pragma once

#include <string>

namespace tabletop {

/// A file written under a temporary name beside its destination (made new
/// and unique, "NAME.XXXXXX.part", on the same file system, so no link or
/// file placed there beforehand is written through) and renamed into place
/// only once it is complete. rename() is atomic: whatever stops the writer
/// (an error, a full disk, Ctrl-C, a kill) the destination holds either its
/// previous content or the complete new one. Only a regular file is ever
/// replaced: a destination that is a directory, a device, a pipe or a
/// socket (or a link to one) is refused; a link to a regular file is
/// written through, so the link stays. Every file tabletop writes (results,
/// traces, frames, videos, plots, tables) goes through here.
class AtomicFile {
 public:
  explicit AtomicFile(std::string path);
  /// Removes the temporary file unless it was committed.
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  const std::string& path() const { return path_; }
  /// Where the writer writes ("" when problem() is set).
  const std::string& temporaryPath() const { return temporary_; }
  /// "" or why the destination cannot be written.
  const std::string& problem() const { return problem_; }
  /// Renames the temporary into place; "" or what went wrong (then the
  /// temporary is removed and the destination untouched).
  std::string commit();

  /// "" when `path` may be written (a printable name, missing, or a
  /// regular file, or a link to one), else why not: the check commands
  /// make before they run.
  static std::string destinationProblem(const std::string& path);
  /// Whether `a` and `b` name one file, however spelt (links, "./", "..",
  /// hard links), so two outputs cannot overwrite each other.
  static bool sameFile(const std::string& a, const std::string& b);
  /// Writes `content` to `path` this way; "" or what went wrong.
  static std::string write(const std::string& path, const std::string& content);

 private:
  std::string path_;
  std::string target_;  ///< path_, or the regular file a link at path_ names
  std::string temporary_;
  std::string problem_;
  bool committed_ = false;
};

}  // namespace tabletop
