#pragma once

#include <string>
#include <vector>

namespace tabletop {

/// A new private folder (mode 0700) under the system's temporary folder
/// (TMPDIR, else /tmp), removed with everything in it when the object goes:
/// where `render --video` puts frames nobody asked to keep. It is locked
/// (flock) from before it takes its name until it goes, so a folder of the
/// same prefix found unlocked is one a killed program left (a kill -9
/// cannot be caught): removeAbandoned() takes those away.
class TemporaryFolder {
 public:
  /// Throws std::runtime_error when the folder cannot be made.
  explicit TemporaryFolder(const std::string& prefix);
  ~TemporaryFolder();
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  const std::string& path() const { return path_; }

  /// Removes this user's folders named `prefix` + 6 characters that no
  /// living TemporaryFolder holds; returns their paths.
  static std::vector<std::string> removeAbandoned(const std::string& prefix);

 private:
  std::string path_;
  int lock_ = -1;  // the folder, opened and flock-ed
};

}  // namespace tabletop
